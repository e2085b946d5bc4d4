// Intersection kernels at the extremes. Every expected answer comes from exact rational
// arithmetic or 50-digit floats (tests/support/exact.h), never from the code under test.
#include "raystep/geometry/kernels.h"
#include "raystep/base/math.h"
#include "raystep/base/rng.h"

#include "exact.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace raystep {
namespace {

using exact::Rational;
using exact::Reference;
using D3 = glm::dvec3;
constexpr auto exactTriangle = exact::triangle;
constexpr auto exactSphere = exact::sphere;

// --------------------------------------------------------------------------------------------
// Named cases

struct TriangleCase {
    std::string name;
    D3 o, d, a, b, c;
};
struct SphereCase {
    std::string name;
    D3 o, d, center;
    double radius;
};

std::vector<TriangleCase> triangleCases() {
    const D3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    const D3 far(1e6, 1e6, 1e6);
    const double tiny = 1e-9;
    const double n = std::ldexp(1.0, -20);  // the needle's height: exact in float too
    return {
        {"DownTheZAxis", {0.25, 0.5, 1}, {0, 0, -1}, a, b, c},
        {"NegativeZeroComponents", {0.25, 0.5, 1}, {-0.0, -0.0, -1}, a, b, c},
        {"AlongPlusX", {-1, 0.25, 0.25}, {1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}},
        {"AlongMinusXNegZero", {2, 0.25, 0.25}, {-1, -0.0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}},
        {"AlongPlusY", {0.25, -3, 0.25}, {0, 1, -0.0}, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
        {"Oblique", {-1, -2, 3}, {1.25, 2.5, -3}, a, b, c},
        {"MissBeyondHypotenuse", {0.6, 0.6, 1}, {0, 0, -1}, a, b, c},
        {"MissBehindOrigin", {0.25, 0.25, -1}, {0, 0, -1}, a, b, c},
        {"RayInTrianglePlane", {-1, 0.25, 0}, {1, 0, 0}, a, b, c},
        {"ZeroAreaTriangle", {0.5, 0, 1}, {0, 0, -1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}},
        {"NeedleTriangleInside", {0.75, std::ldexp(1.0, -22), 1}, {0, 0, -1}, a, b, {1, n, 0}},
        {"NeedleTriangleJustOutside", {0.75, n, 1}, {0, 0, -1}, a, b, {1, n, 0}},
        {"TinyGeometry1e-9",
         {0.25 * tiny, 0.5 * tiny, tiny},
         {0, 0, -1},
         a * tiny,
         b * tiny,
         c * tiny},
        {"FarOffset1e6", far + D3(0.25, 0.5, 1), {0, 0, -1}, far + a, far + b, far + c},
        {"FarOffsetOblique1e6", far + D3(-1, -2, 3), {1.25, 2.5, -3}, far + a, far + b, far + c},
        {"ThroughEdgeMidpoint", {0.5, 0.5, 1}, {0, 0, -1}, a, b, c},
        {"ThroughVertex", {0, 0, 1}, {0.0, 0.0, -1}, a, b, c},
        {"ObliqueThroughVertex", {-1, -2, 3}, {1, 2, -3}, a, b, c},
        {"UnnormalisedLong", {0.25, 0.5, 1}, {0, 0, -1000}, a, b, c},
        {"UnnormalisedShort", {0.25, 0.5, 1}, {0, 0, -1e-3}, a, b, c},
    };
}

std::vector<SphereCase> sphereCases() {
    return {
        {"HeadOn", {0, 0, 0}, {0, 0, 1}, {0, 0, 5}, 1},
        {"AxisParallelNegZero", {0, 0, 0}, {-0.0, 0.0, 1}, {0, 0, 5}, 1},
        {"Oblique", {1, 2, 3}, {-0.3, 0.4, 1}, {0.5, 3, 9}, 1.5},
        {"Miss", {0, 0, 0}, {0, 0, 1}, {0, 3, 5}, 1},
        {"Tangent", {0, 0, 0}, {0, 0, 1}, {0, 1, 5}, 1},
        {"JustMissesTangent", {0, 0, 0}, {0, 0, 1}, {0, 1, 5}, 1 - std::ldexp(1.0, -20)},
        {"OriginInside", {0.5, 0.25, 0}, {0.3, -0.2, 0.9}, {0, 0, 0}, 2},
        {"OriginAtCentre", {0, 0, 0}, {0, 1, 0}, {0, 0, 0}, 3},
        {"BehindOrigin", {0, 0, 0}, {0, 0, -1}, {0, 0, 5}, 1},
        {"Far1e8", {0, 0, 0}, {0, 0, 1}, {0, 0, 1e8}, 1},
        {"FarOblique1e8", {0, 0, 0}, {0.6, 0, 0.8}, {0.6e8, 0.1, 0.8e8}, 1},
        {"Tiny1e-9", {0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1e-9},
        {"UnnormalisedLong", {0, 0, 0}, {0, 0, 1000}, {0, 0, 5}, 1},
        {"UnnormalisedShort", {0, 0, 0}, {0, 0, 1e-3}, {0, 0, 5}, 1},
    };
}

// Accuracy asked of the accurate kernels: a few dozen ulps of t, relative.
template <typename T>
double tTolerance() {
    return 64.0 * std::numeric_limits<T>::epsilon();
}

template <typename T>
TVec3<T> tv(const D3& v) {
    return TVec3<T>(v);
}

/// Inputs rounded to T are what the T kernel sees; the reference uses the same rounded values.
template <typename T>
D3 rounded(const D3& v) {
    return D3(tv<T>(v));
}

template <typename T>
class TriangleKernels : public ::testing::Test {};
template <typename T>
class SphereKernels : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(TriangleKernels, Scalars);
TYPED_TEST_SUITE(SphereKernels, Scalars);

/// Methods that must be right on every named case; the slides' methods must too, except where
/// the case exists to show them fail (listed per case in the test).
TYPED_TEST(TriangleKernels, NamedCasesAgainstExactArithmetic) {
    using T = TypeParam;
    const T inf = std::numeric_limits<T>::infinity();
    for (const TriangleCase& tc : triangleCases()) {
        const D3 o = rounded<T>(tc.o), d = rounded<T>(tc.d);
        const D3 a = rounded<T>(tc.a), b = rounded<T>(tc.b), c = rounded<T>(tc.c);
        const Reference ref = exactTriangle(o, d, a, b, c);
        for (TriangleMethod m :
             {TriangleMethod::Plane, TriangleMethod::MollerTrumbore, TriangleMethod::Watertight}) {
            SCOPED_TRACE(tc.name + " / " + std::string(name(m)));
            const auto h = intersectTriangle<T>(m, tv<T>(o), tv<T>(d), tv<T>(a), tv<T>(b), tv<T>(c),
                                                T(0), inf);
            // Edges and vertices: only the watertight test promises the exact closed triangle;
            // the others may fall either way by one rounding there (their crack rate is measured
            // in bench/ and docs/accuracy.md).
            const bool onBoundary = tc.name.rfind("Through", 0) == 0 ||
                                    tc.name.rfind("ObliqueThrough", 0) == 0 ||
                                    tc.name.rfind("Needle", 0) == 0;
            if (onBoundary && m != TriangleMethod::Watertight) continue;
            ASSERT_EQ(h.has_value(), ref.hit);
            if (!ref.hit) continue;
            EXPECT_NEAR(double(h->t), ref.t, tTolerance<T>() * ref.t);
            EXPECT_NEAR(double(h->u), ref.u, tTolerance<T>());
            EXPECT_NEAR(double(h->v), ref.v, tTolerance<T>());
        }
    }
}

TYPED_TEST(SphereKernels, NamedCasesAgainstFiftyDigits) {
    using T = TypeParam;
    const T inf = std::numeric_limits<T>::infinity();
    for (const SphereCase& sc : sphereCases()) {
        const D3 o = rounded<T>(sc.o), d = rounded<T>(sc.d), c = rounded<T>(sc.center);
        const double r = double(T(sc.radius));
        const Reference ref = exactSphere(o, d, c, r);
        SCOPED_TRACE(sc.name);
        // Off-axis at 1e8, float coordinates are 8 apart: no float kernel can see a unit sphere.
        if (std::is_same_v<T, float> && sc.name == "FarOblique1e8") continue;
        const auto t = intersectSphereStable<T>(tv<T>(o), tv<T>(d), tv<T>(c), T(r), T(0), inf);
        ASSERT_EQ(t.has_value(), ref.hit);
        if (ref.hit) {
            EXPECT_NEAR(double(*t), ref.t, tTolerance<T>() * ref.t);
        }
        // The textbook quadratic agrees on hit or miss everywhere but at the extremes.
        const bool extreme = sc.name.find("1e8") != std::string::npos ||
                             sc.name.find("1e-9") != std::string::npos ||
                             sc.name.find("Tangent") != std::string::npos;
        if (!extreme) {
            const auto tb =
                intersectSphereTextbook<T>(tv<T>(o), tv<T>(d), tv<T>(c), T(r), T(0), inf);
            ASSERT_EQ(tb.has_value(), ref.hit);
            if (ref.hit) {
                EXPECT_NEAR(double(*tb), ref.t, 1e3 * tTolerance<T>() * ref.t);
            }
        }
    }
}

TEST(SphereKernels, TextbookLosesTheFarSphereStableKeepsIt) {
    // Sphere of radius 1 at 1e8 (t = 1e8 - 1): in double, b^2 - 4ac cancels to 0 and the textbook
    // formula returns 1e8, off by a whole radius; the stable form is right to the last digit.
    const D3 o(0), d(0, 0, 1), c(0, 0, 1e8);
    const auto textbook = intersectSphereTextbook<double>(o, d, c, 1.0, 0.0, kInfinity);
    const auto stable = intersectSphereStable<double>(o, d, c, 1.0, 0.0, kInfinity);
    ASSERT_TRUE(textbook && stable);
    EXPECT_NEAR(*stable, 1e8 - 1, 4 * 1e8 * std::numeric_limits<double>::epsilon());
    EXPECT_GE(std::abs(*textbook - (1e8 - 1)), 0.5);
}

TEST(SphereKernels, TextbookLosesTheTinySphere) {
    // Radius 1e-9 at distance 1: t = 1 - 1e-9. c = 1 - 1e-18 rounds to 1 and the textbook root
    // is 1.
    const D3 o(0), d(0, 0, 1), c(0, 0, 1);
    const auto textbook = intersectSphereTextbook<double>(o, d, c, 1e-9, 0.0, kInfinity);
    const auto stable = intersectSphereStable<double>(o, d, c, 1e-9, 0.0, kInfinity);
    ASSERT_TRUE(stable);
    EXPECT_NEAR(*stable, 1.0 - 1e-9, 4 * std::numeric_limits<double>::epsilon());
    ASSERT_TRUE(textbook);
    EXPECT_GT(std::abs(*textbook - (1.0 - 1e-9)), 1e-10);
}

// --------------------------------------------------------------------------------------------
// Watertightness: rays through the shared edges and vertices of a closed mesh

/// An octahedron, rotated and moved so no coordinate is round, scaled by `scale`.
struct Mesh {
    std::vector<D3> v;
    std::vector<std::array<int, 3>> f;
};
Mesh octahedron(double scale) {
    const D3 centre = D3(1.3, -0.7, 2.1) * scale;
    const glm::dmat3 rot = glm::dmat3(glm::dvec3(0.36, 0.48, -0.8), glm::dvec3(-0.8, 0.6, 0.0),
                                      glm::dvec3(0.48, 0.64, 0.6));  // orthonormal
    Mesh m;
    for (D3 p : {D3(1, 0, 0), D3(-1, 0, 0), D3(0, 1, 0), D3(0, -1, 0), D3(0, 0, 1), D3(0, 0, -1)})
        m.v.push_back(centre + rot * p * scale);
    m.f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

template <typename T>
int hitsAmong(const Mesh& m, const std::vector<int>& faces, const D3& o, const D3& d,
              TriangleMethod method) {
    int hits = 0;
    for (int fi : faces) {
        const auto& f = m.f[fi];
        hits += intersectTriangle<T>(method, tv<T>(o), tv<T>(d), tv<T>(m.v[f[0]]), tv<T>(m.v[f[1]]),
                                     tv<T>(m.v[f[2]]), T(0), std::numeric_limits<T>::infinity())
                    .has_value();
    }
    return hits;
}

TYPED_TEST(TriangleKernels, WatertightNeverMissesSharedEdgesOrVertices) {
    using T = TypeParam;
    for (double scale : {1e-3, 1.0, 1e3}) {
        const Mesh m = octahedron(scale);
        const D3 centre = D3(1.3, -0.7, 2.1) * scale;
        Pcg32 rng(2024, static_cast<std::uint64_t>(std::log10(scale) + 10));
        const auto facesSeeing = [&](const D3& o, int v0, int v1) {
            // The faces holding the edge v0-v1 (or the vertex v0 when v1 < 0) that face o.
            std::vector<int> faces;
            bool allFront = true;
            for (int fi = 0; fi < 8; ++fi) {
                const auto& f = m.f[fi];
                const bool has0 = f[0] == v0 || f[1] == v0 || f[2] == v0;
                const bool has1 = v1 < 0 || f[0] == v1 || f[1] == v1 || f[2] == v1;
                if (!has0 || !has1) continue;
                const D3 n = glm::cross(m.v[f[1]] - m.v[f[0]], m.v[f[2]] - m.v[f[0]]);
                allFront = allFront && glm::dot(n, o - m.v[f[0]]) > 0;
                faces.push_back(fi);
            }
            return allFront ? faces : std::vector<int>{};
        };
        int tested = 0;
        for (int i = 0; i < 20000; ++i) {
            // An origin outside, and a target on an edge or at a vertex that the origin sees
            // from the front on every face around it (so the ray truly enters the solid there).
            const D3 dir(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
            const D3 o = centre + glm::normalize(dir) * scale * (2.0 + 8.0 * rng.uniform());
            const int v0 = static_cast<int>(rng.uniform() * 6);
            const bool vertex = i % 4 == 0;
            const auto& f = m.f[static_cast<int>(rng.uniform() * 8)];
            int v1 = -1;
            if (!vertex) {
                if (f[0] != v0 && f[1] != v0 && f[2] != v0) continue;
                v1 = f[(std::find(f.begin(), f.end(), v0) - f.begin() + 1) % 3];
            }
            const std::vector<int> faces = facesSeeing(o, v0, v1);
            if (faces.empty()) continue;
            const D3 target =
                vertex ? m.v[v0] : m.v[v0] + (0.05 + 0.9 * rng.uniform()) * (m.v[v1] - m.v[v0]);
            const D3 d = D3(tv<T>(target)) - D3(tv<T>(o));
            ++tested;
            ASSERT_GE(hitsAmong<T>(m, faces, o, d, TriangleMethod::Watertight), 1)
                << "crack at scale " << scale
                << (vertex ? " through a vertex" : " through an edge");
        }
        EXPECT_GT(tested, 2000);
    }
}

// --------------------------------------------------------------------------------------------
// Ray-box

template <typename T>
class BoxKernel : public ::testing::Test {};
TYPED_TEST_SUITE(BoxKernel, Scalars);

TYPED_TEST(BoxKernel, ZeroComponentsOfBothSignsNeverMakeNaN) {
    using T = TypeParam;
    const TVec3<T> lo(0, 0, 0), hi(1, 1, 1);
    const T inf = std::numeric_limits<T>::infinity();
    for (T zero : {T(0.0), T(-0.0)}) {
        // Inside the x slab (even on its face x = 0), moving along z only.
        for (T x : {T(0), T(0.5), T(1)}) {
            const auto r =
                intersectBox<T>(TVec3<T>(x, 0.5, -2), TVec3<T>(zero, zero, 1), lo, hi, T(0), inf);
            ASSERT_TRUE(r);
            EXPECT_FALSE(std::isnan(r->first) || std::isnan(r->second));
            EXPECT_EQ(r->first, T(2));   // enters at z = 0
            EXPECT_GE(r->second, T(3));  // leaves at z = 1 (widened)
            EXPECT_LE(r->second, T(3) * (1 + 4 * std::numeric_limits<T>::epsilon()));
        }
        // Outside the x slab with a zero x component: parallel and outside, a miss.
        EXPECT_FALSE(
            intersectBox<T>(TVec3<T>(1.5, 0.5, -2), TVec3<T>(zero, zero, 1), lo, hi, T(0), inf));
        EXPECT_FALSE(
            intersectBox<T>(TVec3<T>(-0.5, 0.5, -2), TVec3<T>(zero, zero, 1), lo, hi, T(0), inf));
    }
}

TYPED_TEST(BoxKernel, AgainstExactSlabs) {
    using T = TypeParam;
    Pcg32 rng(99, 1);
    const T inf = std::numeric_limits<T>::infinity();
    const TVec3<T> lo(-1, -2, -0.5), hi(2, 1, 0.5);
    int disagreements = 0;
    for (int i = 0; i < 20000; ++i) {
        const TVec3<T> o(T(6 * rng.uniform() - 3), T(6 * rng.uniform() - 3),
                         T(6 * rng.uniform() - 3));
        TVec3<T> d(T(rng.uniform() - 0.5), T(rng.uniform() - 0.5), T(rng.uniform() - 0.5));
        if (i % 3 == 0) d[i % 3 == 0 ? (i / 3) % 3 : 0] = (i % 2) ? T(0.0) : T(-0.0);
        // Exact: intersect the three slab intervals in rationals.
        Rational tNear = 0;
        bool miss = false, unbounded = true;
        Rational tFar = 0;
        for (int k = 0; k < 3 && !miss; ++k) {
            if (d[k] == T(0)) {
                miss = o[k] < lo[k] || o[k] > hi[k];
                continue;
            }
            Rational t0 =
                (Rational(double(lo[k])) - Rational(double(o[k]))) / Rational(double(d[k]));
            Rational t1 =
                (Rational(double(hi[k])) - Rational(double(o[k]))) / Rational(double(d[k]));
            if (t0 > t1) std::swap(t0, t1);
            if (t0 > tNear) tNear = t0;
            if (unbounded || t1 < tFar) tFar = t1;
            unbounded = false;
        }
        const bool exactHit = !miss && (unbounded || tNear <= tFar);
        const auto r = intersectBox<T>(o, d, lo, hi, T(0), inf);
        if (r) {
            EXPECT_FALSE(std::isnan(r->first) || std::isnan(r->second));
            EXPECT_LE(r->first, r->second);
        }
        // Conservative: every exact hit is found; a false hit may only be a grazing one.
        if (exactHit) {
            ASSERT_TRUE(r.has_value()) << i;
        }
        disagreements += exactHit != r.has_value();
    }
    EXPECT_LE(disagreements, 2);
}

// --------------------------------------------------------------------------------------------
// Secondary-ray origins

TYPED_TEST(TriangleKernels, RobustOffsetClearsTheSurfaceAtEveryScale) {
    // A ray leaving a hit point (either side, any direction) must never hit the triangle it left.
    using T = TypeParam;
    for (double scale : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
        const D3 shift = D3(0.37, -0.21, 0.73) * scale * 10.0;
        const D3 a = rounded<T>(shift + D3(0, 0, 0) * scale),
                 b = rounded<T>(shift + D3(1, 0.2, 0.1) * scale),
                 c = rounded<T>(shift + D3(0.3, 1, -0.2) * scale);
        const TVec3<T> n = glm::normalize(glm::cross(tv<T>(b) - tv<T>(a), tv<T>(c) - tv<T>(a)));
        Pcg32 rng(5, 5);
        for (int i = 0; i < 2000; ++i) {
            const T u = T(0.05 + 0.4 * rng.uniform()), v = T(0.05 + 0.4 * rng.uniform());
            const PointWithError<T> pe = trianglePoint<T>(tv<T>(a), tv<T>(b), tv<T>(c), u, v);
            TVec3<T> w = glm::normalize(
                TVec3<T>(T(rng.uniform() - 0.5), T(rng.uniform() - 0.5), T(rng.uniform() - 0.5)));
            if (std::abs(glm::dot(w, n)) < T(1e-3)) continue;
            const TVec3<T> origin = offsetRayOrigin<T>(pe, n, w);
            for (TriangleMethod m : {TriangleMethod::MollerTrumbore, TriangleMethod::Watertight}) {
                const auto self = intersectTriangle<T>(m, origin, w, tv<T>(a), tv<T>(b), tv<T>(c),
                                                       T(0), std::numeric_limits<T>::infinity());
                ASSERT_FALSE(self) << "self-hit at scale " << scale << " with " << name(m);
            }
        }
    }
}

TYPED_TEST(SphereKernels, RobustOffsetClearsTheSurfaceAtEveryScale) {
    // Leaving a sphere outwards must miss it; going inwards must find the far side, not the
    // point it left (t of the order of the chord, not of the rounding error).
    using T = TypeParam;
    const T inf = std::numeric_limits<T>::infinity();
    for (double scale : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
        const TVec3<T> centre = tv<T>(D3(0.37, -0.21, 0.73) * scale * 10.0);
        const T radius = T(scale);
        Pcg32 rng(8, 8);
        for (int i = 0; i < 2000; ++i) {
            const TVec3<T> dir = glm::normalize(
                TVec3<T>(T(rng.uniform() - 0.5), T(rng.uniform() - 0.5), T(rng.uniform() - 0.5)));
            const TVec3<T> o =
                centre - dir * (radius * T(3)) + TVec3<T>(T(0.3 * scale * rng.uniform()));
            const auto t = intersectSphereStable<T>(o, dir, centre, radius, T(0), inf);
            if (!t) continue;
            const PointWithError<T> pe = spherePoint<T>(o, dir, *t, centre, radius);
            const TVec3<T> n = glm::normalize(pe.p - centre);
            const TVec3<T> w = glm::normalize(
                TVec3<T>(T(rng.uniform() - 0.5), T(rng.uniform() - 0.5), T(rng.uniform() - 0.5)));
            const T cosine = glm::dot(w, n);
            if (std::abs(cosine) < T(1e-2)) continue;
            const auto again = intersectSphereStable<T>(offsetRayOrigin<T>(pe, n, w), w, centre,
                                                        radius, T(0), inf);
            if (cosine > 0) {
                ASSERT_FALSE(again) << "self-hit leaving the sphere at scale " << scale;
            } else {
                ASSERT_TRUE(again) << "lost the far side at scale " << scale;
                ASSERT_GT(*again, T(0.5) * T(2) * radius * -cosine)
                    << "self-hit at scale " << scale;
            }
        }
    }
}

TEST(RayOffset, GammaBoundsAreTheUnitRoundoffMultiples) {
    // gamma(n) = n u / (1 - n u), u = 2^-53 in double, 2^-24 in float.
    EXPECT_EQ(gamma<double>(1), std::ldexp(1.0, -53) / (1 - std::ldexp(1.0, -53)));
    EXPECT_NEAR(gamma<float>(3), 3 * std::ldexp(1.0, -24), 1e-13);
}

// --------------------------------------------------------------------------------------------
// Extreme magnitudes: the watertight test far away, and the range the kernels are exact in

TYPED_TEST(TriangleKernels, WatertightFindsAClearHitAtEveryDistance) {
    // A unit triangle straight ahead at t = 1 to the top of the range (1e18 included), for
    // directions of length 1, 1000 and 1/1000; and obliquely, as far as the precision resolves
    // a unit triangle. pbrt's t bound grew with the distance squared and rejected these hits.
    using T = TypeParam;
    const T inf = std::numeric_limits<T>::infinity();
    const D3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    const double largest =
        kernelRange(std::is_same_v<T, float> ? Precision::Float : Precision::Double).largest;
    std::vector<double> distances{1e18};
    for (double dist = 1; dist <= largest; dist *= 10) distances.push_back(dist);
    for (const double dist : distances) {
        if (dist > largest) continue;
        for (const double len : {1.0, 1000.0, 1e-3}) {
            const D3 o = rounded<T>(D3(0.25, 0.3, dist)), d = rounded<T>(D3(0, 0, -len));
            const Reference ref = exactTriangle(o, d, a, b, c);
            ASSERT_TRUE(ref.hit);
            const auto h = intersectTriangleWatertight<T>(tv<T>(o), tv<T>(d), tv<T>(a), tv<T>(b),
                                                          tv<T>(c), T(0), inf);
            ASSERT_TRUE(h.has_value()) << "straight ahead at " << dist << ", |d| = " << len;
            EXPECT_NEAR(double(h->t), ref.t, tTolerance<T>() * ref.t) << dist;
        }
    }
    const double resolved = std::is_same_v<T, float> ? 1e4 : 1e12;
    for (double dist = 1; dist <= resolved; dist *= 10) {
        const D3 d = rounded<T>(D3(0.3, -0.2, -1)), target(0.3, 0.35, 0);
        const D3 o = rounded<T>(target - dist * d);
        const Reference ref = exactTriangle(o, d, a, b, c);
        ASSERT_TRUE(ref.hit) << dist;
        const auto h = intersectTriangleWatertight<T>(tv<T>(o), tv<T>(d), tv<T>(a), tv<T>(b),
                                                      tv<T>(c), T(0), inf);
        ASSERT_TRUE(h.has_value()) << "oblique at " << dist;
        EXPECT_NEAR(double(h->t), ref.t, 1e3 * tTolerance<T>() * ref.t) << dist;
    }
}

/// Random triangles and spheres of size `scale` at distance about `scale`, with unit directions:
/// the accurate kernels must agree with exact arithmetic wherever the answer is clear (the ray
/// aimed well inside or well outside). Returns the number of disagreements.
template <typename T>
int disagreementsAtScale(double scale, std::uint64_t seed) {
    const T inf = std::numeric_limits<T>::infinity();
    Pcg32 rng(seed, 7);
    const auto inCube = [&](double r) {
        return D3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * (2 * r * scale);
    };
    int bad = 0;
    for (int i = 0; i < 400; ++i) {
        const bool inside = i % 2 == 0;
        // Triangle: aim at barycentric (u, v) at least 0.1 inside or outside its edges.
        const D3 ta = rounded<T>(inCube(1)), tb = rounded<T>(inCube(1)), tc = rounded<T>(inCube(1));
        const double u = inside ? 0.1 + 0.3 * rng.uniform() : -0.1 - rng.uniform();
        const double v = 0.1 + 0.3 * rng.uniform();
        const D3 aim = ta + u * (tb - ta) + v * (tc - ta);
        const D3 from = inCube(4);
        const D3 o = rounded<T>(from), d = rounded<T>(glm::normalize(aim - from));
        const Reference ref = exactTriangle(o, d, ta, tb, tc);
        for (TriangleMethod m : {TriangleMethod::Watertight, TriangleMethod::MollerTrumbore}) {
            const auto h = intersectTriangle<T>(m, tv<T>(o), tv<T>(d), tv<T>(ta), tv<T>(tb),
                                                tv<T>(tc), T(0), inf);
            if (h.has_value() != ref.hit ||
                (ref.hit && std::abs(double(h->t) - ref.t) > 1e3 * tTolerance<T>() * ref.t))
                ++bad;
        }
        // Sphere: aim within 0.8 radii of the centre, or beyond 1.2.
        const D3 centre = rounded<T>(inCube(1));
        const double radius = double(T((0.2 + 0.8 * rng.uniform()) * scale));
        const D3 so = rounded<T>(inCube(4));
        const D3 toCentre = glm::normalize(centre - so);
        const D3 side = glm::normalize(glm::cross(toCentre, D3(0.6, 0.8, 0.0)));
        const double off = inside ? 0.8 * rng.uniform() : 1.2 + rng.uniform();
        const D3 sd = rounded<T>(glm::normalize(centre + off * radius * side - so));
        const Reference sref = exactSphere(so, sd, centre, radius);
        const auto st =
            intersectSphereStable<T>(tv<T>(so), tv<T>(sd), tv<T>(centre), T(radius), T(0), inf);
        if (st.has_value() != sref.hit ||
            (sref.hit && std::abs(double(*st) - sref.t) > 1e3 * tTolerance<T>() * sref.t))
            ++bad;
    }
    return bad;
}

TEST(KernelRange, AccurateKernelsAreExactAcrossTheRange) {
    // The documented range, ends included: no disagreement with exact arithmetic.
    for (double scale : {1e-60, 1e-30, 1e-3, 1.0, 1e3, 1e30, 1e60})
        EXPECT_EQ(disagreementsAtScale<double>(scale, 11), 0) << "double at scale " << scale;
    for (double scale : {1e-7, 1e-3, 1.0, 1e3, 1e8})
        EXPECT_EQ(disagreementsAtScale<float>(scale, 12), 0) << "float at scale " << scale;
}

TEST(KernelRange, OutsideTheRangeTheKernelsFail) {
    // Why the range exists: squares overflow at 1e160 (every method misses a sphere hit head-on),
    // and at 1e-141 the stable sphere's discriminant underflows to -0: a wrong hit of a sphere
    // missed by 4% of its radius (inputs found by a search, checked in 50 digits).
    const D3 o(0), d(0, 0, 1), c(0, 0, 5e160);
    ASSERT_TRUE(exactSphere(o, d, c, 1e160).hit);
    EXPECT_FALSE(intersectSphereStable<double>(o, d, c, 1e160, 0.0, kInfinity));
    EXPECT_FALSE(intersectSphereTextbook<double>(o, d, c, 1e160, 0.0, kInfinity));
    const D3 tinyD(2.0340072443528589e-142, 0, 9.7909557516066899e-142), tinyC(0, 0, 5e-141);
    ASSERT_FALSE(exactSphere(o, tinyD, tinyC, 1e-141).hit);
    EXPECT_TRUE(intersectSphereStable<double>(o, tinyD, tinyC, 1e-141, 0.0, kInfinity));
    // The range check says so for both, and for neither inside the range.
    EXPECT_TRUE(kernelRangeProblem(Precision::Double, 5e160).has_value());
    EXPECT_TRUE(kernelRangeProblem(Precision::Double, 5e-141).has_value());
    EXPECT_FALSE(kernelRangeProblem(Precision::Double, 1e60).has_value());
    EXPECT_FALSE(kernelRangeProblem(Precision::Double, 1e-60).has_value());
    EXPECT_FALSE(kernelRangeProblem(Precision::Double, -1.0).has_value());
    EXPECT_TRUE(kernelRangeProblem(Precision::Double, 1.0000001e60).has_value());
    EXPECT_TRUE(kernelRangeProblem(Precision::Double, 0.0).has_value());
    EXPECT_TRUE(kernelRangeProblem(Precision::Double, kInfinity).has_value());
    EXPECT_TRUE(kernelRangeProblem(Precision::Double, std::numeric_limits<double>::quiet_NaN())
                    .has_value());
    EXPECT_FALSE(kernelRangeProblem(Precision::Float, 1e8).has_value());
    EXPECT_TRUE(kernelRangeProblem(Precision::Float, 1e9).has_value());
    EXPECT_TRUE(kernelRangeProblem(Precision::Float, 1e-8).has_value());
    const std::string why = *kernelRangeProblem(Precision::Double, 5e160);
    EXPECT_NE(why.find("5e+160"), std::string::npos) << why;
    EXPECT_NE(why.find("1e+60"), std::string::npos) << why;
}
}  // namespace
}  // namespace raystep
