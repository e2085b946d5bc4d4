#pragma once
// The local model and the directions of secondary rays, as pure functions (tested by hand).
#include "raystep/base/math.h"

#include <optional>

namespace raystep {

/// The Phong terms of one light at one point.
struct PhongTerms {
    Color diffuse{0.0};   // I_light * kd * cos(a), a between normal and light
    Color specular{0.0};  // I_light * ks * cos^n(b), b between mirrored light and viewer
};

/// n: unit normal on the viewer's side; toLight, toViewer: unit vectors from the point.
PhongTerms phong(const Vec3& n, const Vec3& toLight, const Vec3& toViewer, const Color& lightI,
                 const Color& kd, const Color& ks, double shininess);

/// Snell's law: the refracted unit direction of unit `d` through a surface with unit normal `n`
/// facing against d (dot(d, n) < 0), for eta = n_from / n_to. nullopt on total internal reflection.
std::optional<Vec3> refract(const Vec3& d, const Vec3& n, double eta);

/// Direction with density cos(theta)/pi around unit normal n, from two uniforms in [0, 1).
Vec3 cosineSampleHemisphere(const Vec3& n, double u1, double u2);

}  // namespace raystep
