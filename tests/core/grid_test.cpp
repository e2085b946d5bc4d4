// The uniform grid's resolution rule at the extremes of lambda, its memory caps, and the grid at
// magnitudes where the DDA's crossing times leave double's range. Expected resolutions are worked
// out by hand from the Cleary-Wyvill rule; hits are checked against brute force.
#include "raystep/accel/accel.h"
#include "raystep/base/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace raystep {
namespace {

/// 250 small spheres and 2 unit ones in the box [0, 2] x [0, 1] x [0, 1] (V = 2, N = 252).
Scene boxOfSpheres() {
    Scene s;
    s.materials.push_back(Material{});
    for (int i = 0; i < 250; ++i)
        s.spheres.push_back({Vec3(0.1 + 1.8 * (i % 10) / 9.0, 0.5, 0.5), 0.1, 0});
    s.spheres.push_back({Vec3(0.5, 0.5, 0.5), 0.5, 0});
    s.spheres.push_back({Vec3(1.5, 0.5, 0.5), 0.5, 0});
    return s;
}

std::size_t cellsOf(const IVecN<3>& r) {
    return std::size_t(r.x) * std::size_t(r.y) * std::size_t(r.z);
}

TEST(GridResolution, LambdaIsCellsPerPrimitive) {
    // lambda N = 4 * 252 = 1008 cells: cbrt(1008 / 2) = 7.96 cells a unit, 16 x 8 x 8 = 1024.
    // With lambda primitives a cell it would be 252 / 4 = 63 cells.
    const Scene s = boxOfSpheres();
    const UniformGrid g(ScenePrims(s, {}), GridOptions{});
    EXPECT_EQ(g.spec().res, IVecN<3>(16, 8, 8));
    GridOptions one;
    one.lambda = 1.0;  // 252 cells: cbrt(126) = 5.01 a unit, 10 x 5 x 5 = 250
    EXPECT_EQ(UniformGrid(ScenePrims(s, {}), one).spec().res, IVecN<3>(10, 5, 5));
}

TEST(GridResolution, MonotonicInLambdaUpToTheCap) {
    // Every lambda a user can type, tiny to DBL_MAX: cells never decrease, never pass the cap,
    // and a huge lambda is a fine grid, not one cell (it used to wrap through int).
    const Scene s = boxOfSpheres();
    GridOptions o;
    o.maxCells = 5000;  // a small cap, so the sweep builds small grids
    IVecN<3> last(1);
    for (double lambda :
         {1e-300, 1e-9, 1e-3, 0.01, 0.5, 1.0, 4.0, 10.0, 19.0, 20.0, 21.0, 1e3, 2147483647.0,
          4294967296.0, 1e18, 1e100, 1e300, std::numeric_limits<double>::max()}) {
        o.lambda = lambda;
        const UniformGrid g(ScenePrims(s, {}), o);
        const IVecN<3> r = g.spec().res;
        SCOPED_TRACE(testing::Message()
                     << "lambda " << lambda << ": " << r.x << " x " << r.y << " x " << r.z);
        EXPECT_GE(r.x, last.x);
        EXPECT_GE(r.y, last.y);
        EXPECT_GE(r.z, last.z);
        EXPECT_LE(g.cellCount(), o.maxCells);
        EXPECT_EQ(g.cellCount(), cellsOf(r));
        last = r;
    }
    // At the cap of 5000 cells: y and z round to 14 only once x has reached 27, and
    // 27 x 14 x 14 = 5292 is too many, so the largest resolution that fits is 27 x 13 x 13.
    EXPECT_EQ(last, IVecN<3>(27, 13, 13));
}

TEST(GridResolution, DefaultCapHoldsForAHugeLambda) {
    const Scene s = boxOfSpheres();
    GridOptions o;
    o.lambda = 1e300;
    const UniformGrid g(ScenePrims(s, {}), o);
    EXPECT_LE(g.cellCount(), GridOptions::kMaxCells);
    // cbrt(2^24 / 2) = 203.2 a unit: 406 x 203 x 203 = 16,730,908 cells, within 2^24.
    EXPECT_EQ(g.spec().res, IVecN<3>(406, 203, 203));
}

TEST(GridResolution, ExplicitResolutionPastTheCapShrinks) {
    const Scene s = boxOfSpheres();
    GridOptions o;
    o.maxCells = 4096;
    o.res = std::array<int, 3>{100, 40, 1 << 30};  // the last axis is clamped to 512 first
    const UniformGrid g(ScenePrims(s, {}), o);
    EXPECT_LE(g.cellCount(), o.maxCells);
    // Halved until it fits: 100 x 40 x 512 -> 12 x 5 x 64 = 3840.
    EXPECT_EQ(g.spec().res, IVecN<3>(12, 5, 64));
}

TEST(GridResolution, ReferenceBudgetHolds) {
    // 40 spheres each covering the whole box: every cell lists all of them.
    Scene s;
    s.materials.push_back(Material{});
    for (int i = 0; i < 40; ++i) s.spheres.push_back({Vec3(0.5, 0.5, 0.5 + 1e-3 * i), 0.5, 0});
    GridOptions o;
    o.lambda = 1e6;
    o.maxReferences = 40 * 1000;
    const UniformGrid g(ScenePrims(s, {}), o);
    EXPECT_LE(g.references(), o.maxReferences);
    EXPECT_GT(g.cellCount(), 100u);  // as fine as the budget allows, not one cell
    o.res = std::array<int, 3>{64, 64, 64};
    const UniformGrid h(ScenePrims(s, {}), o);
    EXPECT_LE(h.references(), o.maxReferences);
}

TEST(GridWalk, LargeSceneWithTinyDirectionComponents) {
    // A tiny direction component against a large grid: the DDA's crossing times along that axis
    // overflow (they used to abort in the exact comparison). The grid must find what brute force
    // finds, at 1e10 (kernels in range, rays hit) and at 1e300.
    const double tiny = std::numeric_limits<double>::denorm_min();
    for (const double big : {1e10, 1e300}) {
        Scene s;
        s.materials.push_back(Material{});
        s.triangles.push_back({Vec3(-big, -big, 0), Vec3(big, -big, 0), Vec3(0, big, 0), 0});
        s.triangles.push_back({Vec3(-big, -big, big), Vec3(big, -big, big), Vec3(0, big, -big), 0});
        s.spheres.push_back({Vec3(0.3 * big, 0.1 * big, 0.2 * big), 0.05 * big, 0});
        const Accelerator grid = buildAccelerator(s, AccelKind::Grid, {}, {});
        const Accelerator brute = buildAccelerator(s, AccelKind::BruteForce, {}, {});
        Pcg32 rng(3, 3);
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            Ray r;
            r.origin = Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * big;
            Vec3 d(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
            d[i % 3] = (i % 2 ? tiny : -1e-300) * (1 + i % 7);
            r.dir = d;
            TraversalCounters c;
            std::optional<Hit> got;
            ASSERT_NO_THROW(got = intersect(grid, r, c)) << big << " ray " << i;
            const auto expected = intersect(brute, r, c);
            ASSERT_EQ(got.has_value(), expected.has_value()) << big << " ray " << i;
            hits += expected.has_value();
            if (expected) {
                EXPECT_EQ(got->prim, expected->prim) << big << " ray " << i;
                EXPECT_EQ(got->t, expected->t) << big << " ray " << i;
            }
        }
        if (big == 1e10) {
            EXPECT_GT(hits, 100);
        }
    }
}

TEST(GridWalk, RefusedRayIsTestedAgainstEveryPrimitive) {
    // A ray the DDA refuses (a NaN tMax) walks no cell: rather than a miss nothing was tested
    // for, the grid tests every primitive, as brute force does.
    const Scene s = boxOfSpheres();
    const Accelerator grid = buildAccelerator(s, AccelKind::Grid, {}, {});
    Ray r{Vec3(-1, 0.5, 0.5), Vec3(1, 0, 0)};
    r.tMax = std::numeric_limits<double>::quiet_NaN();
    TraversalCounters c;
    EXPECT_FALSE(intersect(grid, r, c).has_value());
    EXPECT_EQ(c.primitiveTests, s.primitiveCount());
}

}  // namespace
}  // namespace raystep
