#pragma once
// Rays and the lecture's kinds of ray.
#include "raystep/base/math.h"

#include <array>
#include <string_view>

namespace raystep {

/// The kinds of ray on the slides, plus the diffuse bounce rays of colour bleeding.
enum class RayKind : std::uint8_t { Primary, Shadow, Reflection, Refraction, Diffuse };
constexpr int kRayKindCount = 5;
constexpr std::array<std::string_view, kRayKindCount> kRayKindNames = {
    "primary", "shadow", "reflection", "refraction", "diffuse"};

/// r(t) = origin + t * dir, valid for tMin < t < tMax.
struct Ray {
    Vec3 origin{0.0};
    Vec3 dir{0.0, 0.0, -1.0};
    double tMin = 0.0;
    double tMax = kInfinity;
    Vec3 at(double t) const { return origin + t * dir; }
};

}  // namespace raystep
