#pragma once
// Ray-primitive intersection kernels: the slides' methods and the robust ones, side by side.
// Each kernel is one template over the scalar (float or double) and over a Steps recorder:
// NoSteps compiles to nothing; StepLog keeps the intermediate quantities a student computes by
// hand (normal, determinant, discriminant, barycentric coordinates) for `raystep-cli intersect`.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace raystep {

template <typename T>
using TVec3 = glm::vec<3, T, glm::defaultp>;

/// gamma(n) = n u / (1 - n u), u the unit roundoff: bounds the relative error of n roundings
/// (Higham; pbrt 3.9). Used for conservative error bounds, never as a tolerance.
template <typename T>
constexpr T gamma(int n) {
    constexpr T u = std::numeric_limits<T>::epsilon() * T(0.5);
    return (T(n) * u) / (T(1) - T(n) * u);
}

/// Steps recorder that records nothing (the renderer's choice: zero cost).
struct NoSteps {
    template <typename V>
    void operator()(const char*, const V&) {}
};

/// Steps recorder that keeps every named quantity, in the order the kernel computed it.
struct StepLog {
    struct Step {
        const char* name;
        int size;  // 1 (scalar) or 3 (vector)
        double v[3];
    };
    std::vector<Step> steps;
    template <typename T>
    void operator()(const char* name, T value) {
        if constexpr (std::is_arithmetic_v<T>)
            steps.push_back({name, 1, {double(value), 0.0, 0.0}});
        else
            steps.push_back({name, 3, {double(value.x), double(value.y), double(value.z)}});
    }
};

/// Result of a ray-triangle test: distance and barycentric coordinates of the hit
/// (the point is (1-u-v) a + u b + v c).
template <typename T>
struct TriangleHit {
    T t;
    T u;
    T v;
};

// ---------------------------------------------------------------------------------------------
// Ray-sphere

namespace detail {
/// The smaller of the roots t0 <= t1 that lies in (tMin, tMax): from outside the near side, from
/// inside the far side.
template <typename T>
std::optional<T> nearestRoot(T t0, T t1, T tMin, T tMax) {
    if (t0 > tMin && t0 < tMax) return t0;
    if (t1 > tMin && t1 < tMax) return t1;
    return std::nullopt;
}
}  // namespace detail

/// The slides' textbook quadratic: a t^2 + b t + c = 0 with a = d.d, b = 2 d.(o-c),
/// c = |o-c|^2 - r^2, t = (-b -+ sqrt(b^2 - 4ac)) / 2a. Loses digits to cancellation when the
/// sphere is far or small (b^2 ~ 4ac) and in the root near zero.
template <typename T, typename Steps = NoSteps>
std::optional<T> intersectSphereTextbook(const TVec3<T>& o, const TVec3<T>& d,
                                         const TVec3<T>& center, T radius, T tMin, T tMax,
                                         Steps&& steps = {}) {
    const TVec3<T> f = o - center;
    const T a = glm::dot(d, d);
    const T b = T(2) * glm::dot(f, d);
    const T c = glm::dot(f, f) - radius * radius;
    const T disc = b * b - T(4) * a * c;
    steps("a", a);
    steps("b", b);
    steps("c", c);
    steps("discriminant", disc);
    if (!(a > T(0)) || disc < T(0)) return std::nullopt;
    const T sq = std::sqrt(disc);
    const T t0 = (-b - sq) / (T(2) * a);
    const T t1 = (-b + sq) / (T(2) * a);
    steps("t0", t0);
    steps("t1", t1);
    return detail::nearestRoot(t0, t1, tMin, tMax);
}

/// The numerically stable form (Haines et al., Ray Tracing Gems ch. 7): the discriminant from
/// the ray's closest approach |f - (f.d / d.d) d| (no b^2 - 4ac cancellation), and the roots as
/// q = -(b' + sign(b') sqrt(disc)), t0 = q / a, t1 = c / q (no -b + sqrt cancellation).
template <typename T, typename Steps = NoSteps>
std::optional<T> intersectSphereStable(const TVec3<T>& o, const TVec3<T>& d, const TVec3<T>& center,
                                       T radius, T tMin, T tMax, Steps&& steps = {}) {
    const TVec3<T> f = o - center;
    const T a = glm::dot(d, d);
    const T b = glm::dot(f, d);  // half of the textbook b
    const TVec3<T> closest = f - (b / a) * d;
    const T r2 = radius * radius;
    const T c = glm::dot(f, f) - r2;
    const T disc = a * (r2 - glm::dot(closest, closest));  // = b^2 - a c, without cancellation
    steps("a", a);
    steps("b/2", b);
    steps("c", c);
    steps("closest approach", closest);
    steps("discriminant/4", disc);
    if (!(a > T(0)) || disc < T(0)) return std::nullopt;
    const T q = -(b + std::copysign(std::sqrt(disc), b));
    T t0 = q / a;
    T t1 = (q != T(0)) ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    steps("t0", t0);
    steps("t1", t1);
    return detail::nearestRoot(t0, t1, tMin, tMax);
}

// ---------------------------------------------------------------------------------------------
// Ray-triangle

/// The slides' method: intersect the supporting plane n.x = n.a first, then decide inside or
/// outside with barycentric coordinates from signed areas:
/// u = n.((p-a) x (c-a)) / |n|^2, v = n.((b-a) x (p-a)) / |n|^2.
template <typename T, typename Steps = NoSteps>
std::optional<TriangleHit<T>> intersectTrianglePlane(const TVec3<T>& o, const TVec3<T>& d,
                                                     const TVec3<T>& a, const TVec3<T>& b,
                                                     const TVec3<T>& c, T tMin, T tMax,
                                                     Steps&& steps = {}) {
    const TVec3<T> n = glm::cross(b - a, c - a);
    const T planeD = glm::dot(n, a);
    const T denom = glm::dot(n, d);
    steps("normal", n);
    steps("plane d", planeD);
    steps("n.dir", denom);
    if (denom == T(0) || !std::isfinite(denom)) return std::nullopt;  // parallel to the plane
    const T t = (planeD - glm::dot(n, o)) / denom;
    steps("t", t);
    if (!(t > tMin && t < tMax)) return std::nullopt;
    const TVec3<T> p = o + t * d;
    const T n2 = glm::dot(n, n);
    const T u = glm::dot(n, glm::cross(p - a, c - a)) / n2;
    const T v = glm::dot(n, glm::cross(b - a, p - a)) / n2;
    steps("point", p);
    steps("u", u);
    steps("v", v);
    if (u < T(0) || v < T(0) || u + v > T(1)) return std::nullopt;
    return TriangleHit<T>{t, u, v};
}

/// A ray against the plane of the points p with p.n = k (the slides' plane, with the sign that
/// agrees with that equation): t = (k - o.n) / (d.n); nullopt when the ray is parallel to it or
/// t is outside (tMin, tMax). The course's hand computations (app/course) ask for its steps.
template <typename T, typename Steps = NoSteps>
std::optional<T> intersectPlane(const TVec3<T>& o, const TVec3<T>& d, const TVec3<T>& n, T k,
                                T tMin, T tMax, Steps&& steps = {}) {
    const T denom = glm::dot(n, d);
    steps("n.dir", denom);
    if (denom == T(0) || !std::isfinite(denom)) return std::nullopt;  // parallel to the plane
    const T t = (k - glm::dot(n, o)) / denom;
    steps("t", t);
    if (!(t > tMin && t < tMax)) return std::nullopt;
    return t;
}

/// Moller-Trumbore: solves o + t d = a + u (b-a) + v (c-a) by Cramer's rule, no plane stored.
template <typename T, typename Steps = NoSteps>
std::optional<TriangleHit<T>> intersectTriangleMT(const TVec3<T>& o, const TVec3<T>& d,
                                                  const TVec3<T>& a, const TVec3<T>& b,
                                                  const TVec3<T>& c, T tMin, T tMax,
                                                  Steps&& steps = {}) {
    const TVec3<T> e1 = b - a;
    const TVec3<T> e2 = c - a;
    const TVec3<T> p = glm::cross(d, e2);
    const T det = glm::dot(e1, p);
    steps("normal", glm::cross(e1, e2));
    steps("determinant", det);
    if (det == T(0) || !std::isfinite(det)) return std::nullopt;  // parallel or degenerate
    const T invDet = T(1) / det;
    const TVec3<T> s = o - a;
    const T u = glm::dot(s, p) * invDet;
    steps("u", u);
    if (u < T(0) || u > T(1)) return std::nullopt;
    const TVec3<T> q = glm::cross(s, e1);
    const T v = glm::dot(d, q) * invDet;
    steps("v", v);
    if (v < T(0) || u + v > T(1)) return std::nullopt;
    const T t = glm::dot(e2, q) * invDet;
    steps("t", t);
    if (!(t > tMin && t < tMax)) return std::nullopt;
    return TriangleHit<T>{t, u, v};
}

namespace detail {
template <typename T>
using Wider = std::conditional_t<std::is_same_v<T, float>, double, long double>;

template <typename T>
int maxDimension(const TVec3<T>& v) {
    return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}

/// The sheared triangle of the watertight test, computed in W from inputs in T.
template <typename W>
struct Sheared {
    W ax, ay, az, bx, by, bz, cx, cy, cz;  // vertices with the ray along +z from the origin
    W U, V, Wc;                            // 2D edge functions: weights of a, b, c
};

template <typename W, typename T>
Sheared<W> shear(const TVec3<T>& o, const TVec3<T>& d, const TVec3<T>& a, const TVec3<T>& b,
                 const TVec3<T>& c, int kx, int ky, int kz) {
    const W sx = W(d[kx]) / W(d[kz]), sy = W(d[ky]) / W(d[kz]), sz = W(1) / W(d[kz]);
    const auto project = [&](const TVec3<T>& p, W& x, W& y, W& z) {
        const W px = W(p[kx]) - W(o[kx]), py = W(p[ky]) - W(o[ky]), pz = W(p[kz]) - W(o[kz]);
        x = px - sx * pz;
        y = py - sy * pz;
        z = sz * pz;
    };
    Sheared<W> s;
    project(a, s.ax, s.ay, s.az);
    project(b, s.bx, s.by, s.bz);
    project(c, s.cx, s.cy, s.cz);
    s.U = s.cx * s.by - s.cy * s.bx;
    s.V = s.ax * s.cy - s.ay * s.cx;
    s.Wc = s.bx * s.ay - s.by * s.ax;
    return s;
}

/// t = (U az + V bz + W cz) / det, and pbrt-v3's conservative bound on its rounding error (3.9.6),
/// with the shear's own term: pbrt bounds the error of x = px - sx pz by gamma(5) (maxX + maxZ),
/// as if |sx pz| could always reach maxZ; it is |d[kx]| |z| (sx = d[kx] / d[kz], z = pz / d[kz]).
/// pbrt's term made the bound grow with the distance squared (a unit triangle 1e18 straight ahead
/// failed t > bound); this one is as large only for an oblique ray, and is still conservative for
/// directions longer than 1, which pbrt's was not.
template <typename W>
std::pair<W, W> distanceWithBound(const Sheared<W>& s, W dx, W dy) {
    const W det = s.U + s.V + s.Wc;
    const W invDet = W(1) / det;
    const W t = (s.U * s.az + s.V * s.bz + s.Wc * s.cz) * invDet;
    const W maxX = std::max({std::abs(s.ax), std::abs(s.bx), std::abs(s.cx)});
    const W maxY = std::max({std::abs(s.ay), std::abs(s.by), std::abs(s.cy)});
    const W maxZ = std::max({std::abs(s.az), std::abs(s.bz), std::abs(s.cz)});
    // |sx pz| <= |d[kx]| maxZ up to the roundings of sx, z and 1 / d[kz].
    constexpr W shear = gamma<W>(7) * (W(1) + gamma<W>(4));
    const W deltaX = gamma<W>(5) * maxX + shear * (std::abs(dx) * maxZ);
    const W deltaY = gamma<W>(5) * maxY + shear * (std::abs(dy) * maxZ);
    const W deltaZ = gamma<W>(3) * maxZ;
    const W deltaE = W(2) * (gamma<W>(2) * maxX * maxY + deltaY * maxX + deltaX * maxY);
    const W maxE = std::max({std::abs(s.U), std::abs(s.V), std::abs(s.Wc)});
    const W deltaT =
        W(3) * (gamma<W>(3) * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) * std::abs(invDet);
    return {t, deltaT};
}
}  // namespace detail

/// Watertight ray-triangle (Woop, Benthin, Wald 2013): shear and scale so the ray runs along +z
/// from the origin, then the 2D edge functions U, V, W of the projected triangle decide. Two
/// triangles sharing an edge compute that edge's function from the same numbers, so a ray through
/// the edge (or a shared vertex) can never miss both. Exact zeros are recomputed in a wider type.
/// A hit must also have t larger than its own rounding error (pbrt-v3), so a ray starting exactly
/// on the triangle cannot find it again; when the bound is inconclusive the wider type decides.
template <typename T, typename Steps = NoSteps>
std::optional<TriangleHit<T>> intersectTriangleWatertight(const TVec3<T>& o, const TVec3<T>& d,
                                                          const TVec3<T>& a, const TVec3<T>& b,
                                                          const TVec3<T>& c, T tMin, T tMax,
                                                          Steps&& steps = {}) {
    using Wd = detail::Wider<T>;
    // The axis where the direction is largest becomes z; swapping x and y keeps the winding.
    const int kz = detail::maxDimension(glm::abs(d));
    if (d[kz] == T(0)) return std::nullopt;  // zero direction (or NaN)
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    if (d[kz] < T(0)) std::swap(kx, ky);
    detail::Sheared<T> s = detail::shear<T>(o, d, a, b, c, kx, ky, kz);
    if (s.U == T(0) || s.V == T(0) || s.Wc == T(0)) {
        // On an edge in this precision: decide the signs in a wider type (the paper's fallback).
        s.U = T(Wd(s.cx) * Wd(s.by) - Wd(s.cy) * Wd(s.bx));
        s.V = T(Wd(s.ax) * Wd(s.cy) - Wd(s.ay) * Wd(s.cx));
        s.Wc = T(Wd(s.bx) * Wd(s.ay) - Wd(s.by) * Wd(s.ax));
    }
    steps("sheared a", TVec3<T>(s.ax, s.ay, s.az));
    steps("sheared b", TVec3<T>(s.bx, s.by, s.bz));
    steps("sheared c", TVec3<T>(s.cx, s.cy, s.cz));
    steps("U (weight of a)", s.U);
    steps("V (weight of b)", s.V);
    steps("W (weight of c)", s.Wc);
    if ((s.U < T(0) || s.V < T(0) || s.Wc < T(0)) && (s.U > T(0) || s.V > T(0) || s.Wc > T(0)))
        return std::nullopt;  // signs differ: the ray passes outside
    const T det = s.U + s.V + s.Wc;
    steps("determinant", det);
    if (det == T(0) || !std::isfinite(det)) return std::nullopt;  // seen edge-on
    const auto [t, deltaT] = detail::distanceWithBound(s, d[kx], d[ky]);
    steps("t", t);
    steps("t error bound", deltaT);
    if (!(t > tMin && t < tMax)) return std::nullopt;
    if (!(t > deltaT)) {
        const auto [tw, deltaTw] = detail::distanceWithBound(
            detail::shear<Wd>(o, d, a, b, c, kx, ky, kz), Wd(d[kx]), Wd(d[ky]));
        if (!(tw > deltaTw)) return std::nullopt;  // t may truly be 0 or less: no hit
    }
    const T invDet = T(1) / det;
    return TriangleHit<T>{t, s.V * invDet, s.Wc * invDet};
}

// ---------------------------------------------------------------------------------------------
// Ray-box

/// Slab test of a ray against the box [lo, hi]: (tNear, tFar) of the overlap with (tMin, tMax),
/// or nullopt. A direction component of +0 or -0 is handled by the origin's position in that slab
/// (no 0 * inf = NaN); tFar is widened by 1 + 2 gamma(3) (Ize 2013) so rounding can never drop a
/// box the ray truly touches.
template <typename T>
std::optional<std::pair<T, T>> intersectBox(const TVec3<T>& o, const TVec3<T>& d,
                                            const TVec3<T>& lo, const TVec3<T>& hi, T tMin,
                                            T tMax) {
    T tNear = tMin, tFar = tMax;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == T(0)) {
            if (o[i] < lo[i] || o[i] > hi[i]) return std::nullopt;
            continue;  // parallel to this slab and inside it: no constraint
        }
        const T inv = T(1) / d[i];
        T t0 = (lo[i] - o[i]) * inv;
        T t1 = (hi[i] - o[i]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        t1 *= T(1) + T(2) * gamma<T>(3);
        tNear = t0 > tNear ? t0 : tNear;
        tFar = t1 < tFar ? t1 : tFar;
        if (tNear > tFar) return std::nullopt;
    }
    return std::make_pair(tNear, tFar);
}

// ---------------------------------------------------------------------------------------------
// Hit points with error bounds, and where secondary rays start (pbrt-v3 3.9)

/// A point and a conservative bound on the absolute error of each coordinate.
template <typename T>
struct PointWithError {
    TVec3<T> p;
    TVec3<T> error;
};

/// The hit point from barycentrics, b0 a + b1 b + b2 c: more accurate than o + t d, with the bound
/// gamma(7) (|b0 a| + |b1 b| + |b2 c|).
template <typename T>
PointWithError<T> trianglePoint(const TVec3<T>& a, const TVec3<T>& b, const TVec3<T>& c, T u, T v) {
    const T w = T(1) - u - v;
    const TVec3<T> p = w * a + u * b + v * c;
    const TVec3<T> absSum = glm::abs(w * a) + glm::abs(u * b) + glm::abs(v * c);
    return {p, gamma<T>(7) * absSum};
}

/// The hit point o + t d projected back onto the sphere (which removes the error along the
/// normal that t carries), with pbrt's gamma(5) bound widened for the centre's translation.
template <typename T>
PointWithError<T> spherePoint(const TVec3<T>& o, const TVec3<T>& d, T t, const TVec3<T>& center,
                              T radius) {
    TVec3<T> local = (o + t * d) - center;
    const T len = glm::length(local);
    // A t far off (the textbook formula at 1e8) can put the "hit" at the centre: no direction.
    if (len > T(0)) local *= radius / len;
    const TVec3<T> p = center + local;
    return {p, gamma<T>(5) * glm::abs(local) + gamma<T>(2) * (glm::abs(center) + glm::abs(p))};
}

/// Origin for a ray leaving point p (with its error box) in direction w: pushed along the normal
/// just past the error box, to the side w goes, then rounded one ulp further away, so the new ray
/// cannot hit the surface it leaves however large or small the scene.
template <typename T>
TVec3<T> offsetRayOrigin(const PointWithError<T>& pe, const TVec3<T>& n, const TVec3<T>& w) {
    const T dist = glm::dot(glm::abs(n), pe.error);
    TVec3<T> offset = dist * n;
    if (glm::dot(w, n) < T(0)) offset = -offset;
    TVec3<T> po = pe.p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > T(0))
            po[i] = std::nextafter(po[i], std::numeric_limits<T>::infinity());
        else if (offset[i] < T(0))
            po[i] = std::nextafter(po[i], -std::numeric_limits<T>::infinity());
    }
    return po;
}

/// The textbook alternative: a fixed distance along the normal (here 1e-4). Too small for large
/// scenes (acne: the surface shadows itself), too large for tiny ones (light leaks, detached
/// shadows). Kept to show why.
constexpr double kFixedRayEpsilon = 1e-4;

}  // namespace raystep
