#pragma once
// Ray-primitive intersection kernels (the slides' ray-sphere and ray-triangle tests).
// Templated on the scalar so the same kernel runs in float and double.
#include <glm/glm.hpp>

#include <cmath>
#include <optional>

namespace raystep {

template <typename T>
using TVec3 = glm::vec<3, T, glm::defaultp>;

/// Result of a ray-triangle test: distance and barycentric coordinates of the hit
/// (the point is (1-u-v) a + u b + v c).
template <typename T>
struct TriangleHit {
    T t;
    T u;
    T v;
};

/// Moller-Trumbore: solves o + t d = a + u (b-a) + v (c-a) by Cramer's rule.
/// Returns the hit when tMin < t < tMax and the point lies inside the triangle (edges included).
template <typename T>
std::optional<TriangleHit<T>> intersectTriangleMT(const TVec3<T>& o, const TVec3<T>& d,
                                                  const TVec3<T>& a, const TVec3<T>& b,
                                                  const TVec3<T>& c, T tMin, T tMax) {
    const TVec3<T> e1 = b - a;
    const TVec3<T> e2 = c - a;
    const TVec3<T> p = glm::cross(d, e2);
    const T det = glm::dot(e1, p);
    // det == 0: the ray is parallel to the triangle's plane (or the triangle is degenerate).
    if (det == T(0) || !std::isfinite(det)) return std::nullopt;
    const T invDet = T(1) / det;
    const TVec3<T> s = o - a;
    const T u = glm::dot(s, p) * invDet;
    if (u < T(0) || u > T(1)) return std::nullopt;
    const TVec3<T> q = glm::cross(s, e1);
    const T v = glm::dot(d, q) * invDet;
    if (v < T(0) || u + v > T(1)) return std::nullopt;
    const T t = glm::dot(e2, q) * invDet;
    if (!(t > tMin && t < tMax)) return std::nullopt;
    return TriangleHit<T>{t, u, v};
}

/// Ray-sphere: the nearest root of |o + t d - c|^2 = r^2 inside (tMin, tMax).
/// The roots are formed without cancellation (q = -(b + sign(b) sqrt(disc)), t0 = q/a, t1 = c/q)
/// and the discriminant from |f - (f.d) d / |d|^2| (Ray Tracing Gems, ch. 7), so far and
/// grazing spheres keep their digits.
template <typename T>
std::optional<T> intersectSphere(const TVec3<T>& o, const TVec3<T>& d, const TVec3<T>& center,
                                 T radius, T tMin, T tMax) {
    const TVec3<T> f = o - center;
    const T a = glm::dot(d, d);
    if (!(a > T(0))) return std::nullopt;
    const T b = glm::dot(f, d);  // half of the textbook b
    const TVec3<T> perp = f - (b / a) * d;
    const T r2 = radius * radius;
    const T disc = a * (r2 - glm::dot(perp, perp));  // (b^2 - a c) without cancellation
    if (disc < T(0)) return std::nullopt;
    const T sq = std::sqrt(disc);
    const T q = -(b + std::copysign(sq, b));
    const T c = glm::dot(f, f) - r2;
    T t0 = q / a;
    T t1 = (q != T(0)) ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > tMin && t0 < tMax) return t0;
    if (t1 > tMin && t1 < tMax) return t1;
    return std::nullopt;
}

}  // namespace raystep
