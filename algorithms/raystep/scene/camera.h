#pragma once
// Pinhole camera: the slides' "project the pixels onto the scene".
#include "raystep/base/math.h"
#include "raystep/base/ray.h"

namespace raystep {

struct Camera {
    Vec3 eye{0.0, 0.0, 5.0};
    Vec3 lookAt{0.0};
    Vec3 up{0.0, 1.0, 0.0};
    double fovDeg = 45.0;  // vertical field of view

    /// Primary ray through image position (x, y) in pixel units: (0,0) is the top-left corner
    /// of the image, (width, height) the bottom-right one; pixel centres are at +0.5.
    Ray generateRay(double x, double y, int width, int height) const;
};

}  // namespace raystep
