// The trees beyond "same hit as brute force": the SAH cost they report against a recomputation
// written here, the split sweep against counting by hand, the 2D lecture scenes, the event log
// (its size, its cap, its file) and replay.
#include "meshes.h"
#include "random_scene2d.h"
#include "raystep/accel/accel.h"
#include "raystep/base/rng.h"
#include "raystep/base/simd.h"
#include "raystep/render/tracer.h"
#include "raystep/scene/scene2d.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/trace/trace_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>

namespace raystep {
namespace {

/// Surface area of a box, written out (not BoxN::area).
double surface(const Vec3& lo, const Vec3& hi) {
    const Vec3 d = hi - lo;
    return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

/// The lecture's formula, recursively from the root box: leaf C_isect N; interior
/// C_trav + A(L)/A(C) Cost(L) + A(R)/A(C) Cost(R).
double recomputeKdCost(const KdTree3& t, std::uint32_t id, Vec3 lo, Vec3 hi) {
    const KdNode& n = t.nodes()[id];
    const KdTreeOptions& o = t.options();
    if (n.leaf()) return o.cIsect * n.count;
    Vec3 midHi = hi, midLo = lo;
    midHi[n.axis] = n.split;
    midLo[n.axis] = n.split;
    const double a = surface(lo, hi);
    return o.cTrav + surface(lo, midHi) / a * recomputeKdCost(t, id + 1, lo, midHi) +
           surface(midLo, hi) / a * recomputeKdCost(t, n.index, midLo, hi);
}

/// The float at or below (down) or at or above x, by std::nextafter: the reference for
/// roundOutward, which steps bit patterns two at a time.
float outwardByNextafter(double x, bool down) {
    const auto f = static_cast<float>(x);
    const float inf = std::numeric_limits<float>::infinity();
    if (down && double(f) > x) return std::nextafter(f, -inf);
    if (!down && double(f) < x) return std::nextafter(f, inf);
    return f;
}

template <int N>
void expectOutwardAt(double x, int slot) {
    double in[2 * N];
    for (int i = 0; i < 2 * N; ++i) in[i] = 0.5;  // the other edges: a float, kept
    in[slot] = x;
    float out[2 * N];
    simd::roundOutward<N>(in, out);
    // The portable code (ARM64's) must give the same bits as the SSE2 code the build uses here.
    float portableOut[2 * N];
    simd::portable::roundOutward<N>(in, portableOut);
    for (int i = 0; i < 2 * N; ++i)
        EXPECT_EQ(std::bit_cast<std::uint32_t>(portableOut[i]),
                  std::bit_cast<std::uint32_t>(out[i]))
            << "x = " << x << " in slot " << slot;
    const float want = outwardByNextafter(x, slot < N);
    // Bit patterns: -0 and +0 differ, and NaN is compared too.
    EXPECT_EQ(std::bit_cast<std::uint32_t>(out[slot]), std::bit_cast<std::uint32_t>(want))
        << "x = " << x << " in slot " << slot << " of " << 2 * N << ": " << out[slot] << " against "
        << want;
    for (int i = 0; i < 2 * N; ++i) {
        if (i != slot) {
            EXPECT_EQ(out[i], 0.5f);
        }
    }
}

TEST(RoundOutward, MatchesNextafterAtTheExtremes) {
    const double fmax = std::numeric_limits<float>::max();
    const double fmin = std::numeric_limits<float>::min();
    const double dmin = std::numeric_limits<float>::denorm_min();
    std::vector<double> xs = {0.0,
                              -0.0,
                              1.0,
                              -2.5,
                              1.0 + std::ldexp(1.0, -30),
                              -(1.0 + std::ldexp(1.0, -30)),
                              1e-50,
                              -1e-50,
                              dmin,
                              -dmin,
                              dmin / 3,
                              -dmin / 3,
                              dmin * 1.5,
                              fmin,
                              -fmin,
                              fmin * (1 - 1e-9),
                              fmax,
                              -fmax,
                              fmax * (1 + 1e-12),
                              -fmax * (1 + 1e-12),
                              1e39,
                              -1e39,
                              std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity(),
                              0.1,
                              -0.1,
                              1.0 / 3.0};
    Pcg32 rng(20261122, 7);
    for (int k = 0; k < 4000; ++k) {
        // Every exponent a float has and beyond, both signs, most not floats.
        const double x =
            std::ldexp(1.0 + rng.uniform(), static_cast<int>(rng.uniform() * 300) - 150);
        xs.push_back(rng.uniform() < 0.5 ? x : -x);
    }
    for (const double x : xs) {
        for (int slot = 0; slot < 6; ++slot) expectOutwardAt<3>(x, slot);
        for (int slot = 0; slot < 4; ++slot) expectOutwardAt<2>(x, slot);
    }
    double nan[6] = {std::nan(""), 0, 0, 0, 0, 0};
    float out[6];
    simd::roundOutward<3>(nan, out);
    EXPECT_TRUE(std::isnan(out[0]));
}

#if defined(__SSE2__)
// The fast build's binning is written once over simd::Float4 and Int4: on x86 they are SSE2, on
// ARM64 the portable lanes. Same inputs, same bits, lane by lane, or the two builds' trees differ.
TEST(Simd, PortableLanesGiveTheSse2Bits) {
    namespace P = simd::portable;
    namespace S = simd::sse2;
    Pcg32 rng(20261128, 3);
    const auto draw = [&] {
        switch (static_cast<int>(rng.uniform() * 6)) {
            case 0:
                return 0.0f;
            case 1:
                return -0.0f;
            case 2:
                return std::numeric_limits<float>::infinity();
            case 3:
                return static_cast<float>(rng.uniform() * 64.0);
            default:
                return static_cast<float>(
                    std::ldexp(rng.uniform() - 0.5, static_cast<int>(rng.uniform() * 60) - 30));
        }
    };
    const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
    for (int k = 0; k < 20000; ++k) {
        float a[4], b[4];
        for (int i = 0; i < 4; ++i) a[i] = draw(), b[i] = draw();
        float p[4], q[4];
        const auto same = [&](const char* op) {
            for (int i = 0; i < 4; ++i)
                ASSERT_EQ(bits(p[i]), bits(q[i]))
                    << op << " lane " << i << ": " << a[i] << ", " << b[i];
        };
        P::store(p, P::load(a) - P::load(b)), S::store(q, S::load(a) - S::load(b)), same("-");
        P::store(p, P::load(a) * P::load(b)), S::store(q, S::load(a) * S::load(b)), same("*");
        P::store(p, P::min(P::load(a), P::load(b))), S::store(q, S::min(S::load(a), S::load(b))),
            same("min");
        P::store(p, P::max(P::load(a), P::load(b))), S::store(q, S::max(S::load(a), S::load(b))),
            same("max");
        P::store(p, P::set(a[0], b[1], a[2], b[3])), S::store(q, S::set(a[0], b[1], a[2], b[3])),
            same("set");
        P::store(p, P::splat(a[1])), S::store(q, S::splat(a[1])), same("splat");
        // Bins: clamped to [0, 63.5] first, as the binner does, then truncated and merged.
        const auto clamp = [&](auto load, auto mn, auto mx, auto splat) {
            return mn(mx(load(a), splat(0.0f)), splat(63.5f));
        };
        std::int32_t pi[4], qi[4];
        P::store(pi, P::shiftRight<1>(P::truncate(clamp(P::load, P::min, P::max, P::splat))));
        S::store(qi, S::shiftRight<1>(S::truncate(clamp(S::load, S::min, S::max, S::splat))));
        for (int i = 0; i < 4; ++i) ASSERT_EQ(pi[i], qi[i]) << "bin of " << a[i];
        const P::Int4 pl = P::truncate(clamp(P::load, P::min, P::max, P::splat));
        const S::Int4 sl = S::truncate(clamp(S::load, S::min, S::max, S::splat));
        ASSERT_EQ(P::lane<0>(pl), S::lane<0>(sl));
        ASSERT_EQ(P::lane<1>(pl), S::lane<1>(sl));
        std::uint32_t starts[4], ends[4];
        for (int i = 0; i < 4; ++i)
            starts[i] = rng.uniform() < 0.5 ? 0u : 7u, ends[i] = rng.uniform() < 0.5 ? 0u : 1u;
        ASSERT_EQ(P::occupied4(starts, ends), S::occupied4(starts, ends));
    }
    // The occupancy mask by hand: lanes 1 and 3 hold something.
    const std::uint32_t starts[4] = {0, 2, 0, 0}, ends[4] = {0, 0, 0, 5};
    EXPECT_EQ(P::occupied4(starts, ends), 0b1010u);
    EXPECT_EQ(S::occupied4(starts, ends), 0b1010u);
}
#endif

TEST(KdTree, SahCostEqualsARecomputation) {
    for (const char* name : {"default", "cornell", "whitted", "stadium"}) {
        const Scene s = loadBuiltinScene(name);
        for (SplitMethod split : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah}) {
            KdTreeOptions o;
            o.split = split;
            const KdTree3 t(ScenePrims(s, {}), o);
            const Bounds3 b = s.bounds();
            const double expected = recomputeKdCost(t, 0, b.lo, b.hi);
            EXPECT_NEAR(t.stats().sahCost, expected, 1e-9 * expected) << name;
        }
        // The fast build splices subtrees made on other threads: the same recomputation holds,
        // and every primitive is listed in some leaf.
        KdTreeOptions fast;
        fast.build = KdBuild::Fast;
        const KdTree3 t(ScenePrims(s, {}), fast);
        const Bounds3 b = s.bounds();
        const double expected = recomputeKdCost(t, 0, b.lo, b.hi);
        EXPECT_NEAR(t.stats().sahCost, expected, 1e-9 * expected) << name << " fast";
        std::vector<bool> listed(s.primitiveCount(), false);
        for (const std::uint32_t p : t.primIds()) listed[p] = true;
        EXPECT_EQ(std::count(listed.begin(), listed.end(), false), 0) << name << " fast";
        EXPECT_EQ(t.stats().nodes, t.nodes().size());
        EXPECT_EQ(t.stats().leaves, std::count_if(t.nodes().begin(), t.nodes().end(),
                                                  [](const KdNode& n) { return n.leaf(); }));
        EXPECT_EQ(t.stats().references, t.primIds().size());
    }
}

TEST(KdTree, ForEachNodeGivesEveryNodeOnceWithTheBoxTheBuildGaveIt) {
    for (const char* name : {"default", "cornell", "stadium"}) {
        for (KdBuild build : {KdBuild::Exact, KdBuild::Fast}) {
            const Scene s = loadBuiltinScene(name);
            KdTreeOptions o;
            o.build = build;
            EventLog log;
            const KdTree3 t(ScenePrims(s, {}), o, log);
            ASSERT_EQ(log.nodes().size(), t.nodes().size()) << name;
            std::vector<int> seen(t.nodes().size(), 0);
            std::vector<bool> parentSeen(t.nodes().size(), false);
            parentSeen[0] = true;
            t.forEachNode([&](std::uint32_t id, const KdNode& node, const BoxN<3>& box) {
                ASSERT_LT(id, seen.size());
                ++seen[id];
                EXPECT_TRUE(parentSeen[id]) << name << " node " << id;
                // The build recorded each node's box as it opened it: the walk must agree.
                for (int a = 0; a < 3; ++a) {
                    EXPECT_EQ(box.lo[a], log.nodes()[id].lo[a]) << name << " node " << id;
                    EXPECT_EQ(box.hi[a], log.nodes()[id].hi[a]) << name << " node " << id;
                }
                if (!node.leaf()) parentSeen[id + 1] = parentSeen[node.index] = true;
            });
            EXPECT_EQ(std::count(seen.begin(), seen.end(), 1),
                      static_cast<std::ptrdiff_t>(seen.size()))
                << name;
        }
    }
}

TEST(KdTree, SahBeatsMidpointAndMedianOnTheStadium) {
    // The teapot in a stadium: the SAH cuts away the empty room, the others cannot tell.
    const Scene s = loadBuiltinScene("stadium");
    double cost[3];
    for (int m = 0; m < 3; ++m) {
        KdTreeOptions o;
        o.split = static_cast<SplitMethod>(m);
        cost[m] = KdTree3(ScenePrims(s, {}), o).stats().sahCost;
    }
    EXPECT_LT(cost[2], cost[0]);
    EXPECT_LT(cost[2], cost[1]);
}

TEST(KdTree, RootCandidatesMatchCountingByHand) {
    // Four unit squares' worth of spheres on the x axis at 0, 2, 4, 6 (radius 0.5): the sweep
    // at each candidate plane must count exactly the spheres on each side.
    Scene s;
    s.materials.push_back(Material{});
    for (int i = 0; i < 4; ++i) s.spheres.push_back({Vec3(2.0 * i, 0, 0), 0.5, 0});
    EventLog log;
    KdTreeOptions o;
    const KdTree3 t(ScenePrims(s, {}), o, log);
    int candidates = 0;
    for (const Event& e : log.events()) {
        const auto* c = std::get_if<SplitCandidate>(&e);
        if (!c || c->node != 0) continue;
        ++candidates;
        std::uint32_t nl = 0, nr = 0;
        for (const Sphere& sp : s.spheres) {
            const double lo = sp.center[c->axis] - 0.5, hi = sp.center[c->axis] + 0.5;
            nl += lo < c->position;
            nr += hi > c->position;
        }
        EXPECT_EQ(c->nl, nl) << "axis " << int(c->axis) << " at " << c->position;
        EXPECT_EQ(c->nr, nr) << "axis " << int(c->axis) << " at " << c->position;
        // P(L|C) from the box [-0.5, 6.5] x [-0.5, 0.5]^2, by hand for x planes.
        if (c->axis == 0) {
            const double x = c->position + 0.5;
            const double areaL = 2 * (x * 1 + 1 * 1 + 1 * x), areaC = 2 * (7 + 1 + 7);
            EXPECT_NEAR(c->pl, areaL / areaC, 1e-12);
        }
        const double cost = 1.0 + 5.0 * (c->pl * c->nl + c->pr * c->nr);
        EXPECT_NEAR(c->sahCost, (c->nl == 0 || c->nr == 0) ? 0.5 * cost : cost, 1e-12);
    }
    // Along x: the 8 sphere faces minus the two on the box's own faces; y and z: none inside.
    EXPECT_EQ(candidates, 6);
    // The best root split is between two spheres, where nothing straddles.
    const auto chosen = std::find_if(log.events().begin(), log.events().end(),
                                     [](const Event& e) { return e.index() == 9; });
    ASSERT_NE(chosen, log.events().end());
    const auto& c = std::get<SplitChosen>(*chosen);
    EXPECT_EQ(c.axis, 0);
    EXPECT_TRUE(c.position == 2.5 || c.position == 3.5 || c.position == 0.5 || c.position == 1.5 ||
                c.position == 4.5 || c.position == 5.5);
    EXPECT_EQ(t.stats().references, 4u);
}

TEST(KdTree, BuildScalesAndStopsAtTheDepthLimit) {
    const Scene s = loadBuiltinScene("stadium");
    KdTreeOptions o;
    o.maxDepth = 5;
    const KdTree3 t(ScenePrims(s, {}), o);
    EXPECT_LE(t.stats().maxDepth, 5u);
    EXPECT_GT(t.stats().leafReasons[static_cast<int>(LeafReason::MaxDepth)], 0u);
    EXPECT_EQ(t.stats().nodes, 2 * t.stats().leaves - 1);
}

// Perfect splits: the triangle (0,0,0) (4,0,0) (0,4,0) cut at x = 1. By hand, the part left of
// the plane is the quad (0,0) (1,0) (1,3) (0,4), the part right of it the triangle (1,0) (4,0)
// (1,3). The clip is widened by a millionth of the node's width (4e-6 here).
TEST(KdTree, SplitClipsAStraddlingTriangleByHand) {
    const Vec3 a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
    const BoxN<3> box{Vec3(0, 0, -1), Vec3(4, 4, 1)};
    const auto [l, r] = splitTriangleBounds(a, b, c, box, 0, 1.0);
    const double tol = 1e-5;
    EXPECT_EQ(l.lo.x, 0.0);
    EXPECT_EQ(l.hi.x, 1.0);
    EXPECT_NEAR(l.hi.y, 4.0, tol);
    EXPECT_EQ(r.lo.x, 1.0);
    EXPECT_EQ(r.hi.x, 4.0);
    EXPECT_NEAR(r.hi.y, 3.0, tol);
    EXPECT_EQ(l.lo.z, 0.0);
    EXPECT_EQ(r.hi.z, 0.0);
    // A node the triangle misses on one side: only the other side gets it.
    const BoxN<3> corner{Vec3(2.5, 2.5, -1), Vec3(4, 4, 1)};
    EXPECT_TRUE(clipTriangleBounds(a, b, c, corner).empty());
    const BoxN<3> across{Vec3(1, 1, -1), Vec3(4, 4, 1)};
    const auto [l2, r2] = splitTriangleBounds(a, b, c, across, 1, 3.5);
    EXPECT_FALSE(l2.empty());
    EXPECT_TRUE(r2.empty());  // inside the node x >= 1, so y <= 4 - x <= 3 < 3.5
}

/// Bounds of triangle abc inside `box`, by listing the corners the part inside can have (not by
/// clipping, as the tree does): the triangle's vertices inside the box, where its edges cross the
/// box's faces, and where the box's edges pierce the triangle.
BoxN<3> cornerBounds(const Vec3& a, const Vec3& b, const Vec3& c, const BoxN<3>& box) {
    const double eps = 1e-12;
    const auto inBox = [&](const Vec3& p) {
        for (int k = 0; k < 3; ++k)
            if (p[k] < box.lo[k] - eps || p[k] > box.hi[k] + eps) return false;
        return true;
    };
    BoxN<3> out;
    const std::array<Vec3, 3> v{a, b, c};
    for (int i = 0; i < 3; ++i) {
        const Vec3 p = v[i], q = v[(i + 1) % 3];
        if (inBox(p)) out.extend(p);
        for (int k = 0; k < 3; ++k)
            for (const double plane : {box.lo[k], box.hi[k]})
                if ((p[k] - plane) * (q[k] - plane) < 0) {
                    Vec3 x = p + (q - p) * ((plane - p[k]) / (q[k] - p[k]));
                    x[k] = plane;
                    if (inBox(x)) out.extend(x);
                }
    }
    const Vec3 n = glm::cross(b - a, c - a);
    for (int k = 0; k < 3; ++k)  // the four box edges along axis k
        for (int corner = 0; corner < 4; ++corner) {
            Vec3 s0 = box.lo, s1;
            s0[(k + 1) % 3] = corner & 1 ? box.hi[(k + 1) % 3] : box.lo[(k + 1) % 3];
            s0[(k + 2) % 3] = corner & 2 ? box.hi[(k + 2) % 3] : box.lo[(k + 2) % 3];
            s1 = s0;
            s1[k] = box.hi[k];
            const double den = glm::dot(n, s1 - s0);
            if (den == 0) continue;
            const double t = glm::dot(n, a - s0) / den;
            if (t < 0 || t > 1) continue;
            const Vec3 x = s0 + t * (s1 - s0);
            // Inside the triangle: on the inner side of all three edges.
            const double w0 = glm::dot(glm::cross(b - a, x - a), n);
            const double w1 = glm::dot(glm::cross(c - b, x - b), n);
            const double w2 = glm::dot(glm::cross(a - c, x - c), n);
            if (w0 >= 0 && w1 >= 0 && w2 >= 0) out.extend(x);
        }
    return out;
}

// The same on random triangles and nodes, against the corners listed above: each side's bounds
// hold all of the triangle on that side, and no more than what lies within the clip's widening
// (a millionth of the node) of it.
TEST(KdTree, SplitBoundsHoldTheTriangleAndNoMore) {
    Pcg32 rng(7, 1);
    const auto point = [&] { return Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 4.0; };
    int straddling = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 a = point(), b = point(), c = point();
        BoxN<3> box;
        box.extend(point());
        box.extend(point());
        const int axis = trial % 3;
        const double pos = box.lo[axis] + (box.hi[axis] - box.lo[axis]) * rng.uniform();
        const auto [l, r] = splitTriangleBounds(a, b, c, box, axis, pos);
        BoxN<3> boxL = box, boxR = box;
        boxL.hi[axis] = pos;
        boxR.lo[axis] = pos;
        const Vec3 pad = 1e-6 * box.diagonal();
        const auto widened = [&](BoxN<3> b) { return BoxN<3>{b.lo - pad, b.hi + pad}; };
        for (const auto& [got, side] : {std::pair{l, boxL}, std::pair{r, boxR}}) {
            const BoxN<3> inner = cornerBounds(a, b, c, side);
            const BoxN<3> outer = cornerBounds(a, b, c, widened(side)).clippedTo(side);
            if (!inner.empty()) {
                ASSERT_FALSE(got.empty()) << "trial " << trial;
                for (int k = 0; k < 3; ++k) {
                    EXPECT_LE(got.lo[k], inner.lo[k] + 1e-12) << "trial " << trial;
                    EXPECT_GE(got.hi[k], inner.hi[k] - 1e-12) << "trial " << trial;
                }
            }
            if (got.empty()) continue;
            ASSERT_FALSE(outer.empty()) << "trial " << trial;
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(got.lo[k], outer.lo[k] - 1e-12) << "trial " << trial;
                EXPECT_LE(got.hi[k], outer.hi[k] + 1e-12) << "trial " << trial;
            }
        }
        straddling += !l.empty() && !r.empty();
    }
    EXPECT_GT(straddling, 200);  // the plane cuts the triangle often enough to test the cut
}

/// Visits every interior node whose one child is an empty leaf, with the width of that child
/// and of the node along the split axis.
void forEachEmptyCut(const KdTree3& t, std::uint32_t id, Vec3 lo, Vec3 hi,
                     const std::function<void(double, double)>& visit) {
    const KdNode& n = t.nodes()[id];
    if (n.leaf()) return;
    Vec3 midHi = hi, midLo = lo;
    midHi[n.axis] = n.split;
    midLo[n.axis] = n.split;
    const KdNode& l = t.nodes()[id + 1];
    const KdNode& r = t.nodes()[n.index];
    const double width = hi[n.axis] - lo[n.axis];
    if (l.leaf() && l.count == 0) visit(n.split - lo[n.axis], width);
    if (r.leaf() && r.count == 0) visit(hi[n.axis] - n.split, width);
    forEachEmptyCut(t, id + 1, lo, midHi, visit);
    forEachEmptyCut(t, n.index, midLo, hi, visit);
}

// On a curved mesh, clipping rounds a straddling triangle's bounds an ulp inside the node, and
// the sweep used to cut off that "empty" slab (with the empty bonus it halves the cost) at nearly
// every node of the torus knot, down to the depth limit. No empty slab thinner than a millionth
// of its node is cut now, in either build, and real empty space still is.
TEST(KdTree, NoEmptySlabThinnerThanRounding) {
    const Scene s = bench::knotScene(4 * 23, 23);
    const Bounds3 b = s.bounds();
    for (const KdBuild build : {KdBuild::Exact, KdBuild::Fast}) {
        KdTreeOptions o;
        o.build = build;
        const KdTree3 t(ScenePrims(s, {}), o);
        int cuts = 0;
        forEachEmptyCut(t, 0, b.lo, b.hi, [&](double slab, double width) {
            ++cuts;
            EXPECT_GE(slab, 1e-6 * width) << name(build);
        });
        EXPECT_GT(cuts, 100) << name(build);
    }
}

TEST(Bvh, EveryPrimitiveInExactlyOneLeaf) {
    const Scene s = loadBuiltinScene("stadium");
    for (SplitMethod split : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah}) {
        BvhOptions o;
        o.split = split;
        const Bvh3 b(ScenePrims(s, {}), o);
        std::vector<int> seen(s.primitiveCount(), 0);
        for (const auto& n : b.nodes()) {
            if (!n.leaf()) continue;
            for (std::uint32_t k = 0; k < n.count; ++k) {
                const std::uint32_t p = b.primIds()[n.index + k];
                ++seen[p];
                // The leaf's box holds the primitive's.
                const Bounds3 pb = s.primitiveBounds(p);
                for (int i = 0; i < 3; ++i) {
                    EXPECT_LE(n.bounds.lo[i], pb.lo[i]);
                    EXPECT_GE(n.bounds.hi[i], pb.hi[i]);
                }
            }
        }
        EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(seen.size()));
    }
}

// ---------------------------------------------------------------------------------------------
// 2D: the lecture's pictures run the same templates.

Scene2D randomScene2D(int count, std::uint64_t seed) {
    Scene2D s = raystep::randomScene2D(count, seed, 3);
    s.segments.push_back({Vec2(0, 0), Vec2(20, 0)});  // axis-parallel, on the box's face
    s.segments.push_back({Vec2(5, 2), Vec2(5, 8)});
    return s;
}

TEST(Trees2D, FindWhatBruteForceFinds) {
    const Scene2D s = randomScene2D(60, 5);
    const Scene2DPrims prims(s);
    const BruteForceT<Scene2DPrims> brute(prims);
    KdTreeOptions kdo;
    const KdTree<Scene2DPrims> kdSah(prims, kdo);
    kdo.split = SplitMethod::Midpoint;
    const KdTree<Scene2DPrims> kdMid(prims, kdo);
    const Bvh<Scene2DPrims> bvh(prims, BvhOptions{});
    const UniformGridT<Scene2DPrims> grid(prims, GridOptions{});
    // Cleary-Wyvill in 2D: cells per axis d_i sqrt(lambda N / A), by hand from the bounds.
    const BoxN<2> b = s.bounds();
    const Vec2 d = b.diagonal();
    const double perUnit = std::sqrt(4.0 * s.primitiveCount() / (d.x * d.y));
    EXPECT_EQ(grid.spec().res.x, std::lround(d.x * perUnit));
    EXPECT_EQ(grid.spec().res.y, std::lround(d.y * perUnit));
    Pcg32 rng(9, 1);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        Ray2 r;
        r.origin = Vec2(rng.uniform() * 24 - 2, rng.uniform() * 14 - 2);
        const double a = rng.uniform() * 2 * kPi;
        // Directions of any length: the kernels must not assume unit vectors.
        const double len = 0.1 + 3 * rng.uniform();
        r.dir = i % 7 == 0 ? Vec2(i % 2 ? len : -len, 0.0) : len * Vec2(std::cos(a), std::sin(a));
        TraversalCounters c;
        const auto expected = brute.intersect(r, c);
        hits += expected.has_value();
        for (const auto& got : {kdSah.intersect(r, c), kdMid.intersect(r, c), bvh.intersect(r, c),
                                grid.intersect(r, c)}) {
            ASSERT_EQ(got.has_value(), expected.has_value()) << i;
            if (expected) {
                EXPECT_EQ(got->prim, expected->prim) << i;
                EXPECT_EQ(got->t, expected->t) << i;
            }
        }
    }
    EXPECT_GT(hits, 1000);
}

TEST(Scene2D, RayCircleAndSegmentByHand) {
    // The ray (0.4, 0.4) + t (1, 0.75), not of unit length (lecture-grid's example ray before
    // issue 17).
    const Ray2 r{Vec2(0.4, 0.4), Vec2(1.0, 0.75)};
    // Circle (4.2, 2.9), radius 0.3: a t^2 + 2 b t + c = 0 with a = 1.5625, b = -5.675,
    // c = 20.6; the nearer root (5.675 - sqrt(b^2 - a c)) / a, b^2 - a c = 0.018125.
    const auto t = intersectCircle(r, {Vec2(4.2, 2.9), 0.3});
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, (5.675 - std::sqrt(0.018125)) / 1.5625, 1e-13);
    // Segment (3.7, 3.5)-(3.9, 3.02): 0.4 + t = 3.7 + 0.2 s, 0.4 + 0.75 t = 3.5 - 0.48 s gives
    // t = 2.204 / 0.63 by elimination.
    const auto u = intersectSegment(r, {Vec2(3.7, 3.5), Vec2(3.9, 3.02)});
    ASSERT_TRUE(u);
    EXPECT_NEAR(*u, 2.204 / 0.63, 1e-13);
    // From inside a circle: the far root; behind the ray: nothing.
    EXPECT_NEAR(*intersectCircle(Ray2{Vec2(0, 0), Vec2(0, 2)}, {Vec2(0, 0), 1.0}), 0.5, 1e-15);
    EXPECT_FALSE(intersectCircle(Ray2{Vec2(3, 0), Vec2(1, 0)}, {Vec2(0, 0), 1.0}));
    EXPECT_FALSE(intersectSegment(Ray2{Vec2(0, 0), Vec2(1, 0)}, {Vec2(1, 0), Vec2(2, 0)}));
}

TEST(Trees2D, AreaIsThePerimeter) {
    // In 2D the SAH's "area" is the perimeter: a random line meets a convex region in
    // proportion to it (Cauchy-Crofton).
    BoxN<2> b{Vec2(0, 0), Vec2(3, 1)};
    EXPECT_EQ(b.area(), 8.0);
}

// ---------------------------------------------------------------------------------------------
// The event log.

TEST(Events, SmallPlainAndCapped) {
    static_assert(sizeof(Event) <= 64);
    EventLog log(5);
    for (std::uint32_t i = 0; i < 8; ++i) log(MailboxSkip{0, i});
    EXPECT_EQ(log.events().size(), 5u);
    EXPECT_EQ(log.dropped(), 3u);
    EXPECT_TRUE(log.truncated());
    EXPECT_NE(capMessage(log).find("event cap of 5 reached: 3 later events"), std::string::npos);
}

TEST(Events, RecordingChangesNothing) {
    // The recorded pixel has the colour and the counts of the unrecorded one, for every
    // structure: recording observes, it does not steer.
    const Scene s = loadBuiltinScene("default");
    RenderOptions opt;
    opt.width = 64;
    opt.height = 48;
    opt.trace.bounces = 3;
    for (AccelKind kind :
         {AccelKind::BruteForce, AccelKind::Grid, AccelKind::KdTree, AccelKind::Bvh}) {
        const Accelerator accel = buildAccelerator(s, kind);
        const Tracer tracer(s, accel, opt.trace);
        for (auto [x, y] : {std::pair{30, 30}, {40, 20}, {5, 40}}) {
            RayCounters plain, recorded;
            EventLog log;
            const Color a = tracer.renderPixel(x, y, opt, plain);
            const Color b = tracer.renderPixel(x, y, opt, recorded, log);
            EXPECT_EQ(a, b);
            EXPECT_EQ(plain.rays, recorded.rays);
            EXPECT_EQ(plain.traversal.primitiveTests, recorded.traversal.primitiveTests);
            // Every test and skip counted is an event, and every ray has its RayBegin.
            std::uint64_t tests = 0, skips = 0, begins = 0;
            for (const Event& e : log.events()) {
                tests += std::holds_alternative<PrimitiveTest>(e);
                skips += std::holds_alternative<MailboxSkip>(e);
                begins += std::holds_alternative<RayBegin>(e);
            }
            EXPECT_EQ(tests, recorded.traversal.primitiveTests);
            EXPECT_EQ(skips, recorded.traversal.mailboxSkips);
            EXPECT_EQ(begins, recorded.totalRays());
            EXPECT_EQ(log.rays().size(), recorded.totalRays());
            // Shading terms add up to the pixel's colour (one sample per pixel here).
            Color sum(0.0);
            for (const Event& e : log.events())
                if (const auto* t = std::get_if<ShadingTerm>(&e); t && t->ray == 0)
                    sum += Color(t->rgb[0], t->rgb[1], t->rgb[2]);
            const bool primaryHit =
                std::any_of(log.events().begin(), log.events().end(), [](const Event& e) {
                    const auto* h = std::get_if<RayHit>(&e);
                    return h && h->ray == 0;
                });
            if (primaryHit) {
                EXPECT_NEAR(glm::length(sum - a), 0.0, 1e-12);
            }
        }
    }
}

TEST(Events, TraceFileRoundTrip) {
    const Scene s = loadBuiltinScene("whitted");
    for (AccelKind kind : {AccelKind::Grid, AccelKind::KdTree, AccelKind::Bvh}) {
        EventLog build;
        const Accelerator accel = buildAccelerator(s, kind, {}, {}, build);
        RenderOptions opt;
        const Tracer tracer(s, accel, opt.trace);
        EventLog log;
        RayCounters c;
        tracer.renderPixel(opt.width / 2, opt.height / 2, opt, c, log);
        for (const EventLog* l : {&build, &log}) {
            TraceInfo info;
            info.scene = "whitted";
            info.what = "pixel";
            info.pixelX = 3;
            info.pixelY = 4;
            const std::string text = traceToJson(*l, info);
            TraceInfo back;
            const EventLog read = traceFromJson(text, "t.json", &back);
            ASSERT_EQ(read.events().size(), l->events().size());
            for (std::size_t i = 0; i < read.events().size(); ++i)
                EXPECT_EQ(read.events()[i].index(), l->events()[i].index());
            // Field by field through the file again: the same text.
            EXPECT_EQ(traceToJson(read, back), text);
            ASSERT_EQ(read.rays().size(), l->rays().size());
            for (std::size_t i = 0; i < read.rays().size(); ++i) {
                EXPECT_EQ(read.rays()[i].origin, l->rays()[i].origin);
                EXPECT_EQ(read.rays()[i].dir, l->rays()[i].dir);
                EXPECT_EQ(read.rays()[i].parent, l->rays()[i].parent);
            }
            EXPECT_EQ(back.pixelX, 3);
            EXPECT_EQ(back.scene, "whitted");
        }
    }
}

TEST(Events, BadTraceFilesNameTheLineAndKey) {
    const auto expectError = [](const std::string& text, const std::string& expected) {
        try {
            traceFromJson(text, "t.json");
            FAIL() << "no error for: " << text;
        } catch (const TraceError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    const std::string head = "{\"format\": \"raystep-trace\", \"version\": 1,\n\"rays\": [],\n";
    expectError("{", "t.json:1: malformed JSON");
    expectError("[]", "t.json:1: a trace file holds one JSON object");
    expectError("{\"format\": \"x\"}", "key 'format'");
    expectError("{\"format\": \"raystep-trace\", \"version\": 7}", "version 7");
    expectError(head + "\"events\": [\n{\"type\": \"warp\"}]}", "t.json:4: key 'events[0].type'");
    expectError(head + "\"events\": [\n{\"type\": \"ray_miss\"}]}", "key 'events[0].ray': missing");
    expectError(head + "\"events\": [\n{\"type\": \"ray_miss\", \"ray\": 3}]}",
                "ray 3 is not in 'rays'");
    expectError(head + "\"events\": [\n{\"type\": \"mailbox_skip\", \"ray\": null, \"prim\": -1}]}",
                "key 'events[0].prim'");
    expectError(head +
                    "\"events\": [\n{\"type\": \"primitive_test\", \"ray\": null, \"prim\": 1,"
                    " \"hit\": 1, \"t\": 2}]}",
                "key 'events[0].hit': expected true or false");
    expectError(
        "{\"format\": \"raystep-trace\", \"version\": 1,\n\"rays\": [{\"kind\": \"primary\","
        " \"depth\": 0, \"parent\": null,\n \"origin\": [0, 0, 1e999]}]}",
        "t.json:3: number '1e999' is out of range");
}

TEST(Events, ReplayRebuildsTheSameTraversal) {
    // The rays of a recorded log, traced again from the log alone (no camera, no image), give
    // exactly the recorded events: the log holds all a replay needs.
    const Scene s = loadBuiltinScene("default");
    for (AccelKind kind : {AccelKind::Grid, AccelKind::KdTree, AccelKind::Bvh}) {
        const Accelerator accel = buildAccelerator(s, kind);
        RenderOptions opt;
        opt.trace.bounces = 2;
        const Tracer tracer(s, accel, opt.trace);
        EventLog log;
        RayCounters c;
        tracer.renderPixel(300, 300, opt, c, log);
        const EventLog read = traceFromJson(traceToJson(log, {}), "t.json");
        for (std::uint32_t id = 0; id < read.rays().size(); ++id) {
            const RayRecord& r = read.rays()[id];
            EventLog again;
            TraversalCounters tc;
            const Ray ray{r.origin, r.dir, r.tMin, r.tMax};
            if (r.kind == RayKind::Shadow)
                occluded(accel, ray, tc, again, id);
            else
                intersect(accel, ray, tc, again, id);
            // The recorded traversal events of this ray, in order.
            std::vector<Event> recorded;
            for (const Event& e : read.events()) {
                const bool traversal =
                    std::holds_alternative<DdaSetup>(e) || std::holds_alternative<DdaCell>(e) ||
                    std::holds_alternative<NodeEnter>(e) || std::holds_alternative<NodeSkip>(e) ||
                    std::holds_alternative<PrimitiveTest>(e) ||
                    std::holds_alternative<MailboxSkip>(e);
                const bool ofRay = std::visit(
                    [&](const auto& ev) {
                        if constexpr (requires { ev.ray; })
                            return ev.ray == id;
                        else
                            return false;
                    },
                    e);
                if (traversal && ofRay) recorded.push_back(e);
            }
            ASSERT_EQ(again.events().size(), recorded.size()) << "ray " << id;
            for (std::size_t i = 0; i < recorded.size(); ++i)
                EXPECT_EQ(again.events()[i].index(), recorded[i].index()) << "ray " << id;
            EventLog a, b;
            for (const Event& e : again.events()) a.append(e);
            for (const Event& e : recorded) b.append(e);
            EXPECT_EQ(traceToJson(a, {}), traceToJson(b, {})) << "ray " << id;
        }
    }
}

TEST(Events, GridRecordsTheLectureVariables) {
    // A grid over [0,4]^2 with cells of 1 (one cell deep in z) and the ray from (0.5, 0.2) along
    // (1, 0.5), by hand: tDelta = (1, 2); tMax starts at (0.5, 1.6); X steps at 0.5 and 1.5,
    // Y at 1.6, X at 2.5, and the ray leaves at 3.5: cells (0,0) (1,0) (2,0) (2,1) (3,1).
    Scene s;
    s.materials.push_back(Material{});
    s.spheres.push_back({Vec3(2, 2, 0.5), 0.01, 0});
    s.spheres.push_back({Vec3(0.01, 0.01, 0.01), 0.01, 0});
    s.spheres.push_back({Vec3(3.99, 3.99, 0.99), 0.01, 0});
    GridOptions go;
    go.res = std::array<int, 3>{4, 4, 1};
    const UniformGrid g(ScenePrims(s, {}), go);
    EventLog log;
    TraversalCounters c;
    g.intersect(Ray{Vec3(0.5, 0.2, 0.5), Vec3(1, 0.5, 0)}, c, log, 0);
    std::vector<std::array<int, 2>> cells;
    std::vector<std::array<double, 2>> tMax;
    const DdaSetup* setup = nullptr;
    for (const Event& e : log.events()) {
        if (const auto* d = std::get_if<DdaSetup>(&e)) setup = d;
        if (const auto* d = std::get_if<DdaCell>(&e)) {
            cells.push_back({d->cell[0], d->cell[1]});
            tMax.push_back({d->tMax[0], d->tMax[1]});
        }
    }
    ASSERT_NE(setup, nullptr);
    EXPECT_EQ(setup->step[0], 1);
    EXPECT_EQ(setup->step[1], 1);
    EXPECT_EQ(setup->step[2], 0);
    EXPECT_DOUBLE_EQ(setup->tDelta[0], 1.0);
    EXPECT_DOUBLE_EQ(setup->tDelta[1], 2.0);
    const std::vector<std::array<int, 2>> expected = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {3, 1}};
    EXPECT_EQ(cells, expected);
    const std::vector<std::array<double, 2>> expectedTMax = {
        {0.5, 1.6}, {1.5, 1.6}, {2.5, 1.6}, {2.5, 3.6}, {3.5, 3.6}};
    ASSERT_EQ(tMax.size(), expectedTMax.size());
    for (std::size_t i = 0; i < tMax.size(); ++i) {
        EXPECT_NEAR(tMax[i][0], expectedTMax[i][0], 1e-15) << i;
        EXPECT_NEAR(tMax[i][1], expectedTMax[i][1], 1e-15) << i;
    }
}

}  // namespace
}  // namespace raystep

namespace raystep {
namespace {

TEST(Build, ProgressRisesToTheEndAndCanCancel) {
    const Scene s = loadBuiltinScene("stadium");
    for (AccelKind kind : {AccelKind::Grid, AccelKind::KdTree, AccelKind::Bvh}) {
        SCOPED_TRACE(accelKindName(kind));
        std::vector<double> seen;
        AccelOptions o;
        o.setProgress([&](double f) {
            seen.push_back(f);
            return true;
        });
        buildAccelerator(s, kind, {}, o);
        ASSERT_GT(seen.size(), 10u);
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
        EXPECT_GT(seen.back(), 0.98);  // every primitive's share ends in a leaf
        EXPECT_LE(seen.back(), 1.0);
        // Asked to stop at 30%: the build stops with BuildCancelled, and soon.
        int calls = 0;
        o.setProgress([&](double f) {
            ++calls;
            return f < 0.3;
        });
        EXPECT_THROW(buildAccelerator(s, kind, {}, o), BuildCancelled);
        EXPECT_LT(calls, 40);
    }
}

}  // namespace
}  // namespace raystep
