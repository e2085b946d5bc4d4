#pragma once
// Pinhole camera: the slides' "project the pixels onto the scene".
#include "raystep/base/math.h"
#include "raystep/base/ray.h"

#include <optional>

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

/// A camera's frame for one image size, computed once (a render's every ray): the rays of
/// Camera::generateRay, bit for bit.
struct CameraRays {
    CameraRays(const Camera& camera, int width, int height);
    Ray operator()(double x, double y) const;
    int width, height;

  private:
    Vec3 eye_, forward_, right_, up_;
    double halfWidth_, halfHeight_;
};

/// Whether the camera has a view: eye apart from lookAt, up not along the view, fov in (0, 180).
bool cameraUsable(const Camera& camera);

/// Where the direction `dir` from the eye crosses a width x height image (generateRay's inverse,
/// in pixel units; it may fall outside the image); nullopt if it points beside or behind the eye.
std::optional<glm::dvec2> imagePosition(const Camera& camera, const Vec3& dir, int width,
                                        int height);

}  // namespace raystep
