#pragma once
// Independent references for the intersection kernels: exact rational arithmetic for triangles
// (Cramer's rule in boost::multiprecision::cpp_rational) and 50 significant digits for spheres
// (which need a square root). Shared by the tests and the accuracy measurements in bench/.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>
#include <glm/glm.hpp>

namespace raystep::exact {

using Rational = boost::multiprecision::cpp_rational;
using Big = boost::multiprecision::cpp_bin_float_50;

struct Reference {
    bool hit = false;
    double t = 0.0;  // the exact t rounded once to double
    double u = 0.0, v = 0.0;
};

struct R3 {
    Rational x, y, z;
};
inline R3 r3(const glm::dvec3& v) {
    return {Rational(v.x), Rational(v.y), Rational(v.z)};
}
inline R3 sub(const R3& a, const R3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Rational dot(const R3& a, const R3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline R3 cross(const R3& a, const R3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// o + t d = a + u (b - a) + v (c - a), solved exactly; the triangle is closed (edges count).
/// A ray in the triangle's plane (det = 0) counts as a miss, as for every kernel; t must be > 0.
inline Reference triangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a,
                          const glm::dvec3& b, const glm::dvec3& c) {
    const R3 O = r3(o), D = r3(d), A = r3(a);
    const R3 e1 = sub(r3(b), A), e2 = sub(r3(c), A);
    const R3 p = cross(D, e2);
    const Rational det = dot(e1, p);
    if (det == 0) return {};
    const R3 s = sub(O, A);
    const Rational u = dot(s, p) / det;
    const R3 q = cross(s, e1);
    const Rational v = dot(D, q) / det;
    const Rational t = dot(e2, q) / det;
    if (u < 0 || v < 0 || u + v > 1 || t <= 0) return {};
    return {true, t.convert_to<double>(), u.convert_to<double>(), v.convert_to<double>()};
}

/// The nearer positive root of |o + t d - c|^2 = r^2, in 50 significant digits.
inline Reference sphere(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c, double r) {
    const Big fx = Big(o.x) - Big(c.x), fy = Big(o.y) - Big(c.y), fz = Big(o.z) - Big(c.z);
    const Big a = Big(d.x) * Big(d.x) + Big(d.y) * Big(d.y) + Big(d.z) * Big(d.z);
    const Big b = fx * Big(d.x) + fy * Big(d.y) + fz * Big(d.z);
    const Big cc = fx * fx + fy * fy + fz * fz - Big(r) * Big(r);
    const Big disc = b * b - a * cc;
    if (disc < 0) return {};
    const Big sq = sqrt(disc);
    const Big t0 = (-b - sq) / a, t1 = (-b + sq) / a;
    if (t0 > 0) return {true, t0.convert_to<double>()};
    if (t1 > 0) return {true, t1.convert_to<double>()};
    return {};
}

}  // namespace raystep::exact
