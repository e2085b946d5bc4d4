// The DDA against an exact rational traversal written here: every cell whose interior the ray
// crosses, in order. The reference lists every boundary crossing in rationals, sorts them, and
// locates each stretch between two crossings by its midpoint: nothing of dda.h is used.
#include "raystep/accel/dda.h"
#include "raystep/accel/dda_textbook.h"
#include "raystep/base/rng.h"

#include "exact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace raystep {
namespace {

using exact::Rational;

template <int N>
using Cells = std::vector<std::array<long, N>>;

template <int N>
Cells<N> exactWalk(const GridSpec<N, double>& g, const std::array<double, N>& o,
                   const std::array<double, N>& d, double tMin = 0.0) {
    // tMin = -inf: no lower bound but the grid's own faces (the parallel case is not needed).
    const bool fromMinusInf = tMin == -std::numeric_limits<double>::infinity();
    Rational t0(fromMinusInf ? 0.0 : tMin), t1;
    bool bounded = false, lowered = !fromMinusInf;
    std::array<Rational, N> lo, size;
    for (int i = 0; i < N; ++i) {
        lo[i] = Rational(g.lo[i]);
        size[i] = (Rational(g.hi[i]) - lo[i]) / g.res[i];
        if (d[i] == 0) {
            if (o[i] < g.lo[i] || o[i] > g.hi[i]) return {};
            continue;
        }
        Rational a = (lo[i] - Rational(o[i])) / Rational(d[i]);
        Rational b = (Rational(g.hi[i]) - Rational(o[i])) / Rational(d[i]);
        if (a > b) std::swap(a, b);
        if (!lowered || a > t0) t0 = a;
        if (!bounded || b < t1) t1 = b;
        lowered = true;
        bounded = true;
    }
    if (!bounded || t0 >= t1) return {};
    // Every boundary crossing strictly inside (t0, t1), then the stretches between them.
    std::vector<Rational> times{t0, t1};
    for (int i = 0; i < N; ++i) {
        if (d[i] == 0) continue;
        for (long k = 0; k <= g.res[i]; ++k) {
            const Rational t = (lo[i] + k * size[i] - Rational(o[i])) / Rational(d[i]);
            if (t > t0 && t < t1) times.push_back(t);
        }
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    Cells<N> cells;
    for (std::size_t s = 0; s + 1 < times.size(); ++s) {
        const Rational mid = (times[s] + times[s + 1]) / 2;
        std::array<long, N> cell{};
        for (int i = 0; i < N; ++i) {
            const Rational x = (Rational(o[i]) + mid * Rational(d[i]) - lo[i]) / size[i];
            // floor of a rational, then clamp (a ray lying exactly on the last face).
            long k = static_cast<long>(boost::multiprecision::numerator(x) /
                                       boost::multiprecision::denominator(x));
            if (x < 0 && Rational(k) != x) --k;
            cell[i] = std::clamp(k, 0L, static_cast<long>(g.res[i] - 1));
        }
        cells.push_back(cell);
    }
    return cells;
}

template <int N>
Cells<N> ddaWalk(const GridSpec<N, double>& g, const std::array<double, N>& o,
                 const std::array<double, N>& d, double tMin = 0.0,
                 double tMax = std::numeric_limits<double>::infinity()) {
    VecN<N, double> origin, dir;
    for (int i = 0; i < N; ++i) origin[i] = o[i], dir[i] = d[i];
    Cells<N> cells;
    Dda<N, double> dda(g, origin, dir, tMin, tMax);
    for (bool more = dda.valid(); more; more = dda.next()) {
        std::array<long, N> c{};
        for (int i = 0; i < N; ++i) c[i] = dda.cell()[i];
        cells.push_back(c);
        if (cells.size() > 100000) break;  // a runaway walk fails below, not forever
    }
    return cells;
}

GridSpec<2, double> grid2(int nx, int ny, double x0 = 0, double y0 = 0, double x1 = -1,
                          double y1 = -1) {
    GridSpec<2, double> g;
    g.res = {nx, ny};
    g.lo = {x0, y0};
    g.hi = {x1 < 0 ? x0 + nx : x1, y1 < 0 ? y0 + ny : y1};
    return g;
}

TEST(Dda, TheLecturesExample) {
    // 4 x 3 unit cells, from (0.5, 0.25) along (1, 0.6): tDeltaX = 1, tDeltaY = 1/0.6; by hand
    // the cells are (0,0) (1,0) (1,1) (2,1) (3,1) (3,2).
    const Cells<2> expected = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {3, 1}, {3, 2}};
    EXPECT_EQ(ddaWalk<2>(grid2(4, 3), {0.5, 0.25}, {1, 0.6}), expected);
    EXPECT_EQ(exactWalk<2>(grid2(4, 3), {0.5, 0.25}, {1, 0.6}), expected);
    Dda<2, double> dda(grid2(4, 3), {0.5, 0.25}, {1, 0.6});
    EXPECT_EQ(dda.tMax().x, 0.5);
    EXPECT_DOUBLE_EQ(dda.tMax().y, 0.75 / 0.6);
    EXPECT_EQ(dda.tDelta().x, 1.0);
    EXPECT_DOUBLE_EQ(dda.tDelta().y, 1 / 0.6);
    EXPECT_EQ(dda.step(), IVecN<2>(1, 1));
}

TEST(Dda, ThroughGridVerticesStepsDiagonally) {
    // Along the diagonal of unit cells: (0,0) (1,1) (2,2) only; (1,0) and (0,1) are touched at
    // a point and are not crossed.
    const Cells<2> expected = {{0, 0}, {1, 1}, {2, 2}};
    EXPECT_EQ(ddaWalk<2>(grid2(3, 3), {0, 0}, {1, 1}), expected);
    EXPECT_EQ(exactWalk<2>(grid2(3, 3), {0, 0}, {1, 1}), expected);
    // From outside, in through the corner.
    EXPECT_EQ(ddaWalk<2>(grid2(3, 3), {-1, -1}, {1, 1}), expected);
    Dda<2, double> dda(grid2(3, 3), {-1, -1}, {1, 1});
    EXPECT_EQ(dda.axesTaken(), 3u);
    ASSERT_TRUE(dda.next());
    EXPECT_EQ(dda.axesTaken(), 3u);  // the diagonal step
}

TEST(Dda, AlongAGridLineAndParallelToAxes) {
    // Exactly along y = 1 (a boundary) moving +x: the cells above the line, row 1.
    EXPECT_EQ(ddaWalk<2>(grid2(3, 3), {-0.5, 1}, {1, 0}),
              exactWalk<2>(grid2(3, 3), {-0.5, 1}, {1, 0}));
    EXPECT_EQ(ddaWalk<2>(grid2(3, 3), {-0.5, 1}, {1, 0}), (Cells<2>{{0, 1}, {1, 1}, {2, 1}}));
    // Negative zero components are parallel too.
    EXPECT_EQ(ddaWalk<2>(grid2(3, 3), {2.5, 3.5}, {-0.0, -1}), (Cells<2>{{2, 2}, {2, 1}, {2, 0}}));
    // Parallel and outside: nothing.
    EXPECT_TRUE(ddaWalk<2>(grid2(3, 3), {3.5, 0.5}, {0, 1}).empty());
}

TEST(Dda, MissesAndGrazes) {
    EXPECT_TRUE(ddaWalk<2>(grid2(3, 3), {-1, 5}, {1, 0.1}).empty());  // passes above
    EXPECT_TRUE(ddaWalk<2>(grid2(3, 3), {4, 4}, {1, 1}).empty());     // points away
    EXPECT_TRUE(ddaWalk<2>(grid2(3, 3), {-1, 2}, {1, 1}).empty());    // touches the corner (0, 3)
    EXPECT_TRUE(exactWalk<2>(grid2(3, 3), {-1, 2}, {1, 1}).empty());
    // The anti-diagonal through the same corner does cross the grid: (0,2) (1,1) (2,0).
    EXPECT_EQ(ddaWalk<2>(grid2(3, 3), {-1, 4}, {1, -1}), (Cells<2>{{0, 2}, {1, 1}, {2, 0}}));
}

TEST(Dda, StartsOnBoundariesAndOutside) {
    for (const auto& [o, d] : std::vector<std::pair<std::array<double, 2>, std::array<double, 2>>>{
             {{1, 1}, {1, 0.5}},      // on a grid vertex
             {{1, 1}, {-1, -0.5}},    // on a vertex, moving down
             {{2, 0.5}, {-1, 0.3}},   // on a vertical boundary, moving left
             {{0, 0}, {0.3, 1}},      // on the grid's corner
             {{3, 3}, {-1, -1}},      // on the far corner, coming back along the diagonal
             {{-5, 1.5}, {2, 0.1}},   // from outside, left
             {{1.5, 7}, {0.05, -1}},  // from outside, above
         }) {
        EXPECT_EQ(ddaWalk<2>(grid2(3, 3), o, d), exactWalk<2>(grid2(3, 3), o, d))
            << "origin " << o[0] << "," << o[1] << " dir " << d[0] << "," << d[1];
    }
}

/// The slides' loop (ddaTextbook, tMax accumulated by tMax += tDelta): its cells, for comparison.
template <int N>
Cells<N> textbookWalk(const GridSpec<N, double>& g, const std::array<double, N>& o,
                      const std::array<double, N>& d) {
    VecN<N, double> origin, dir;
    for (int i = 0; i < N; ++i) origin[i] = o[i], dir[i] = d[i];
    Cells<N> cells;
    for (const TextbookCell<N, double>& c : ddaTextbook(g, origin, dir)) {
        std::array<long, N> cell{};
        for (int i = 0; i < N; ++i) cell[i] = c.cell[i];
        cells.push_back(cell);
    }
    return cells;
}

TEST(Dda, LongNearDiagonalWalks) {
    // Hundreds of cells at a slope within 1e-12 of 1.
    GridSpec<2, double> g = grid2(500, 500);
    for (double eps : {1e-12, -1e-12, 1e-15, 0.0}) {
        const std::array<double, 2> o{0.3, 0.3}, d{1.0, 1.0 + eps};
        const Cells<2> exact = exactWalk<2>(g, o, d);
        EXPECT_GT(exact.size(), 499u);
        EXPECT_EQ(ddaWalk<2>(g, o, d), exact) << "slope 1 + " << eps;
    }
    // Past a grid vertex 700 cells down the walk, the slides' accumulated tMax += tDelta has
    // drifted: through the vertex it steps one axis (a cell only touched); beside it, it takes the
    // wrong axis. The exact decision does neither.
    const std::array<double, 2> o{0.5, 0.5};
    for (const std::array<double, 2> d :
         {std::array<double, 2>{399.5, 299.5},              // through (400, 300)
          std::array<double, 2>{0.7 * 399.5, 0.7 * 299.5},  // beside it
          std::array<double, 2>{399.5, 299.5 + 1e-13}}) {
        const Cells<2> exact = exactWalk<2>(g, o, d);
        EXPECT_EQ(ddaWalk<2>(g, o, d), exact);
        EXPECT_NE(textbookWalk<2>(g, o, d), exact);
    }
}

TEST(Dda, RandomRaysAgainstExactIn3D) {
    Pcg32 rng(31, 4);
    for (int i = 0; i < 300; ++i) {
        GridSpec<3, double> g;
        g.res = {1 + int(rng.uniform() * 12), 1 + int(rng.uniform() * 12),
                 1 + int(rng.uniform() * 12)};
        g.lo = {-1.3, 0.25, 2.0};
        g.hi = {0.7, 3.0, 2.5};
        std::array<double, 3> o{}, d{};
        for (int k = 0; k < 3; ++k) {
            o[k] = g.lo[k] - 1 + (g.hi[k] - g.lo[k] + 2) * rng.uniform();
            d[k] = rng.uniform() - 0.5;
        }
        if (i % 5 == 0) d[i % 3] = (i % 2) ? 0.0 : -0.0;  // axis-parallel in one axis
        if (i % 7 == 0)
            o[0] = g.lo[0] + (g.hi[0] - g.lo[0]) * int(rng.uniform() * g.res[0]) / g.res[0];
        EXPECT_EQ(ddaWalk<3>(g, o, d), exactWalk<3>(g, o, d)) << "ray " << i;
        // The slides' loop too, away from parallel axes and boundaries: a dozen cells, no drift.
        if (i % 5 != 0 && i % 7 != 0) {
            EXPECT_EQ(textbookWalk<3>(g, o, d), exactWalk<3>(g, o, d)) << "textbook ray " << i;
        }
    }
}

TEST(Dda, TextbookLoopOnTheLecturesExample) {
    // The lecture's example, as the slides' table: the cells, and tMax accumulated step by step.
    const auto rows = ddaTextbook(grid2(4, 3), {0.5, 0.25}, {1, 0.6});
    EXPECT_EQ(textbookWalk<2>(grid2(4, 3), {0.5, 0.25}, {1, 0.6}),
              exactWalk<2>(grid2(4, 3), {0.5, 0.25}, {1, 0.6}));
    ASSERT_EQ(rows.size(), 6u);
    EXPECT_EQ(rows[0].tMax.x, 0.5);
    EXPECT_DOUBLE_EQ(rows[0].tMax.y, 0.75 / 0.6);
    EXPECT_EQ(rows[1].tMax.x, 1.5);  // stepped X: tMaxX += tDeltaX
}

TEST(Dda, HugeAndTinyGrids) {
    for (double scale : {1e-9, 1e9}) {
        GridSpec<3, double> g;
        g.res = {64, 64, 64};
        g.lo = VecN<3, double>(1.0 * scale);
        g.hi = VecN<3, double>(3.0 * scale);
        const std::array<double, 3> o{0.5 * scale, 1.1 * scale, 0.9 * scale}, d{1.0, 0.37, 0.61};
        const Cells<3> exact = exactWalk<3>(g, o, d);
        EXPECT_GT(exact.size(), 20u);
        EXPECT_EQ(ddaWalk<3>(g, o, d), exact) << "scale " << scale;
        // Through grid vertices at that scale: the main diagonal, one cell per step.
        const Cells<3> diagonal = ddaWalk<3>(g, {0.0, 0.0, 0.0}, {1, 1, 1});
        EXPECT_EQ(diagonal.size(), 64u);
        EXPECT_EQ(diagonal, exactWalk<3>(g, {0.0, 0.0, 0.0}, {1, 1, 1}));
    }
}

// --------------------------------------------------------------------------------------------
// Crossing times beyond double's range: overflowing to infinity, subnormal, underflowing to 0

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

TEST(Dda, OverflowingCrossingTimesAreOrderedExactly) {
    // A tiny component against a large grid: that axis' crossings (1e10 / 1e-320) overflow to
    // inf in double though they are finite, and must be ordered against the other axis' finite
    // ones, against each other and against tMax = inf, never thrown on.
    const GridSpec<2, double> g = grid2(4, 4, 0, 0, 1e10, 1e10);
    for (const std::array<double, 2> d : {std::array<double, 2>{1, 1e-320},
                                          {1, kTiny},
                                          {-1, -1e-320},
                                          {1e-320, 1},
                                          {1e-320, 3e-320},  // both axes overflow
                                          {kTiny, 2 * kTiny},
                                          {1e-300, 1e-310}}) {
        for (const std::array<double, 2> o : {std::array<double, 2>{5e9, 5e9},
                                              {0, 0},  // on the grid's corner
                                              {-1, 2.5e9},
                                              {1e10, 1e10}}) {
            SCOPED_TRACE(testing::Message()
                         << "origin " << o[0] << "," << o[1] << " dir " << d[0] << "," << d[1]);
            Cells<2> got;
            EXPECT_NO_THROW(got = ddaWalk<2>(g, o, d));
            EXPECT_EQ(got, exactWalk<2>(g, o, d));
        }
    }
    // A grid wider than the largest double (its width overflows) and a 3D grid at 1e300.
    const GridSpec<2, double> wide = grid2(3, 5, -1e308, -1e308, 1e308, 1e308);
    for (const std::array<double, 2> d :
         {std::array<double, 2>{1, 1e-10}, {1e-300, -1}, {1e-320, 1}}) {
        Cells<2> got;
        EXPECT_NO_THROW(got = ddaWalk<2>(wide, {0, 0}, d));
        EXPECT_EQ(got, exactWalk<2>(wide, {0, 0}, d));
    }
    GridSpec<3, double> g3;
    g3.res = {5, 7, 3};
    g3.lo = VecN<3, double>(-1e300);
    g3.hi = VecN<3, double>(1e300);
    for (const std::array<double, 3> d :
         {std::array<double, 3>{1, 1e-10, 0.3}, {1e-20, -1, 1e-30}, {0, 1e-300, 1}}) {
        Cells<3> got;
        EXPECT_NO_THROW(got = ddaWalk<3>(g3, {1e299, -3e299, 0}, d));
        EXPECT_EQ(got, exactWalk<3>(g3, {1e299, -3e299, 0}, d));
    }
}

TEST(Dda, InfiniteIntervalEnds) {
    // tMin = -inf starts where the ray enters the grid (behind the origin too); tMin = tMax = inf
    // is an empty interval; tMax = inf never wins over a finite crossing, even one that
    // overflowed to inf in double.
    const GridSpec<2, double> g = grid2(4, 4, 0, 0, 1e10, 1e10);
    const std::array<double, 2> o{5e9, 5e9}, d{1, 1e-320};
    Cells<2> got;
    EXPECT_NO_THROW(got = ddaWalk<2>(g, o, d, -kInf));
    EXPECT_EQ(got, exactWalk<2>(g, o, d, -kInf));
    EXPECT_EQ(got.size(), 4u);
    EXPECT_NO_THROW(got = ddaWalk<2>(g, o, d, kInf, kInf));
    EXPECT_TRUE(got.empty());
    EXPECT_NO_THROW(got = ddaWalk<2>(g, o, d, -kInf, -kInf));
    EXPECT_TRUE(got.empty());
    EXPECT_EQ(ddaWalk<2>(grid2(3, 3), {0.5, 0.5}, {1, 1}, -kInf),
              (Cells<2>{{0, 0}, {1, 1}, {2, 2}}));
}

TEST(Dda, NonFiniteInputIsRefusedNotWalked) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const GridSpec<2, double> g = grid2(3, 3);
    const auto refused = [](const Dda<2, double>& dda) {
        return !dda.valid() && dda.problem() != nullptr;
    };
    EXPECT_TRUE(refused(Dda<2, double>(g, {nan, 0.5}, {1, 0})));
    EXPECT_TRUE(refused(Dda<2, double>(g, {0.5, 0.5}, {1, nan})));
    EXPECT_TRUE(refused(Dda<2, double>(g, {kInf, 0.5}, {-1, 0})));
    EXPECT_TRUE(refused(Dda<2, double>(g, {0.5, 0.5}, {1, 0}, nan)));
    EXPECT_TRUE(refused(Dda<2, double>(g, {0.5, 0.5}, {1, 0}, 0.0, nan)));
    EXPECT_TRUE(refused(Dda<2, double>(grid2(3, 3, 0, 0, kInf, 3), {0.5, 0.5}, {1, 0})));
    GridSpec<2, double> empty = grid2(3, 3);
    empty.res = {0, 3};
    EXPECT_TRUE(refused(Dda<2, double>(empty, {0.5, 0.5}, {1, 0})));
    // Finite input at any magnitude is walked, and says nothing.
    const Dda<2, double> fine(grid2(3, 3, 0, 0, 1e308, 3e-320), {0, 0}, {kTiny, 1e308});
    EXPECT_TRUE(fine.valid());
    EXPECT_EQ(fine.problem(), nullptr);
}

TEST(Dda, SubnormalBoundariesAgainstPythonFractions) {
    // A 3 x 2 grid 10 denormals wide: the inner x boundaries 10/3 and 20/3 denormals are not
    // doubles, and the y crossing at 5 / 1.55 denormals rounds to 3. Cells by hand, and from
    // Python's fractions (an exact walk written apart from this file's).
    const GridSpec<2, double> g = grid2(3, 2, 0, 0, 10 * kTiny, 10 * kTiny);
    EXPECT_EQ(ddaWalk<2>(g, {0, 0}, {1, 1.55}), (Cells<2>{{0, 0}, {0, 1}, {1, 1}}));
    EXPECT_EQ(ddaWalk<2>(g, {0, 0}, {1, 1.4}), (Cells<2>{{0, 0}, {1, 0}, {1, 1}, {2, 1}}));
}

TEST(Dda, SubnormalGridsAgainstExact) {
    Pcg32 rng(97, 5);
    for (int i = 0; i < 600; ++i) {
        GridSpec<2, double> g;
        g.res = {1 + int(rng.uniform() * 9), 1 + int(rng.uniform() * 9)};
        std::array<double, 2> o{}, d{};
        for (int k = 0; k < 2; ++k) {
            // Boundaries a few denormals to a few thousand apart, most of them not doubles.
            const double width = std::floor(1 + rng.uniform() * (i % 2 ? 40 : 4000));
            g.lo[k] = std::floor((rng.uniform() - 0.5) * 100) * kTiny;
            g.hi[k] = g.lo[k] + width * kTiny;
            o[k] = g.lo[k] + std::floor((rng.uniform() * 1.4 - 0.2) * width) * kTiny;
            d[k] = (rng.uniform() - 0.5) * (i % 3 == 0 ? 1e-300 : 1.0);
        }
        if (i % 11 == 0) d[i % 2] = 0.0;
        EXPECT_EQ(ddaWalk<2>(g, o, d), exactWalk<2>(g, o, d))
            << "grid " << i << ": lo " << g.lo[0] << "," << g.lo[1] << " hi " << g.hi[0] << ","
            << g.hi[1] << " res " << g.res[0] << "," << g.res[1] << " origin " << o[0] << ","
            << o[1] << " dir " << d[0] << "," << d[1];
    }
}

TEST(Dda, UnderflowingCrossingTimesAgainstExact) {
    // Small grids, huge directions: crossing times of 1e-309 down to 1e-322 are subnormal (a few
    // bits of precision left) or round to 0, and ties between axes are decided there.
    Pcg32 rng(13, 8);
    for (int i = 0; i < 600; ++i) {
        GridSpec<3, double> g;
        g.res = {1 + int(rng.uniform() * 7), 1 + int(rng.uniform() * 7),
                 1 + int(rng.uniform() * 7)};
        const double size = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 1e-9 : 1e-13);
        g.lo = {-1.0 * size, 0.0, 0.25};
        g.hi = {0.5 * size, 1.0 * size, 0.25 + 0.5 * size};
        const double scale = i % 2 ? 1e308 : 1e300;
        std::array<double, 3> o{}, d{};
        for (int k = 0; k < 3; ++k) {
            o[k] = g.lo[k] + (g.hi[k] - g.lo[k]) * rng.uniform();
            d[k] = (rng.uniform() - 0.5) * scale;
        }
        if (i % 4 == 0) d[1] = d[0];  // the same speed along x and y: ties through edges
        if (i % 5 == 0)
            o[0] = g.lo[0] +
                   (g.hi[0] - g.lo[0]) * int(rng.uniform() * g.res[0]) / g.res[0];  // on a boundary
        EXPECT_EQ(ddaWalk<3>(g, o, d), exactWalk<3>(g, o, d)) << "ray " << i;
    }
}

}  // namespace
}  // namespace raystep
