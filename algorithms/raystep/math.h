#pragma once
// Vector types and the few helpers the whole core shares.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace raystep {

using Vec3 = glm::dvec3;
using Color = glm::dvec3;  // linear RGB radiance

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

inline double maxComponent(const Vec3& v) {
    return std::max({v.x, v.y, v.z});
}
inline double maxAbsComponent(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}
inline bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool isBlack(const Color& c) {
    return c.x <= 0.0 && c.y <= 0.0 && c.z <= 0.0;
}

/// Mirror direction d about the normal n (both need not face each other): d - 2 (d.n) n.
inline Vec3 reflect(const Vec3& d, const Vec3& n) {
    return d - 2.0 * glm::dot(d, n) * n;
}

/// Axis-aligned bounding box in 3D.
struct Bounds3 {
    Vec3 lo{kInfinity};
    Vec3 hi{-kInfinity};
    void extend(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Bounds3& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    Vec3 diagonal() const { return hi - lo; }
};

}  // namespace raystep
