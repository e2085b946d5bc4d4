// Every accelerator must find what brute force finds: the same nearest primitive at the same t,
// for seeded random rays of every awkward kind, on every built-in scene.
#include "raystep/accel/accel.h"
#include "meshes.h"
#include "raystep/base/rng.h"
#include "raystep/render/render.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

namespace raystep {
namespace {

Vec3 randomDirection(Pcg32& rng) {
    for (;;) {
        const Vec3 v(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
        if (glm::length(v) > 0.1 && glm::length(v) <= 1) return glm::normalize(v);
    }
}

/// Rays from inside the scene's bounds, from outside, axis-parallel (with -0.0), grazing the
/// scene's faces, and the camera's own.
std::vector<Ray> testRays(const Scene& s, int count, std::uint64_t seed) {
    Pcg32 rng(seed, 17);
    const Bounds3 b = s.bounds();
    const Vec3 d = b.diagonal();
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const Vec3 inside = b.lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * d;
        Ray r;
        switch (i % 5) {
            case 0:  // from inside, any direction
                r = {inside, randomDirection(rng)};
                break;
            case 1:  // from outside, aimed at a point inside
                r.origin = inside + randomDirection(rng) * (2.0 * glm::length(d));
                r.dir = glm::normalize(inside - r.origin);
                break;
            case 2: {  // axis-parallel, signs and zeros of both kinds
                Vec3 dir(0.0);
                const int axis = static_cast<int>(rng.uniform() * 3);
                dir[axis] = rng.uniform() < 0.5 ? -1.0 : 1.0;
                for (int k = 0; k < 3; ++k)
                    if (k != axis) dir[k] = rng.uniform() < 0.5 ? -0.0 : 0.0;
                r = {inside, dir};
                break;
            }
            case 3: {  // grazing: along a face of the bounds
                Vec3 o = inside;
                const int axis = static_cast<int>(rng.uniform() * 3);
                o[axis] = rng.uniform() < 0.5 ? b.lo[axis] : b.hi[axis];
                Vec3 dir = randomDirection(rng);
                dir[axis] = 0.0;
                if (glm::length(dir) == 0.0) dir[(axis + 1) % 3] = 1.0;
                r = {o, glm::normalize(dir)};
                break;
            }
            default: {  // the camera's primary rays
                r = s.camera.generateRay(rng.uniform() * 64, rng.uniform() * 48, 64, 48);
                break;
            }
        }
        rays.push_back(r);
    }
    return rays;
}

void expectSameHits(const Scene& s, const Accelerator& accel, int count, const std::string& what) {
    const Accelerator brute = buildAccelerator(s, AccelKind::BruteForce);
    int hits = 0;
    for (const Ray& r : testRays(s, count, 11)) {
        TraversalCounters c1, c2;
        const auto expected = intersect(brute, r, c1);
        const auto got = intersect(accel, r, c2);
        ASSERT_EQ(got.has_value(), expected.has_value()) << what;
        EXPECT_EQ(occluded(accel, r, c2), expected.has_value()) << what;
        if (!expected) continue;
        ++hits;
        EXPECT_EQ(got->prim, expected->prim) << what;
        EXPECT_EQ(got->t, expected->t) << what;
    }
    EXPECT_GT(hits, count / 4) << what;
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, GridFindsWhatBruteForceFinds) {
    const Scene s = loadBuiltinScene(GetParam());
    const int count = s.primitiveCount() > 1000 ? 400 : 3000;
    for (bool mailbox : {true, false}) {
        AccelOptions opt;
        opt.grid.mailbox = mailbox;
        expectSameHits(s, buildAccelerator(s, AccelKind::Grid, {}, opt), count,
                       GetParam() + (mailbox ? " with mailbox" : " without mailbox"));
    }
    AccelOptions coarse, fine;
    coarse.grid.res = std::array<int, 3>{1, 1, 1};
    fine.grid.res = std::array<int, 3>{97, 3, 61};
    expectSameHits(s, buildAccelerator(s, AccelKind::Grid, {}, coarse), count / 4,
                   GetParam() + " 1x1x1");
    expectSameHits(s, buildAccelerator(s, AccelKind::Grid, {}, fine), count / 4,
                   GetParam() + " 97x3x61");
}

TEST_P(EveryScene, KdTreeFindsWhatBruteForceFinds) {
    const Scene s = loadBuiltinScene(GetParam());
    const int count = s.primitiveCount() > 1000 ? 400 : 3000;
    for (SplitMethod split : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah}) {
        for (bool mailbox : {true, false}) {
            AccelOptions opt;
            opt.kdtree.split = split;
            opt.kdtree.mailbox = mailbox;
            expectSameHits(s, buildAccelerator(s, AccelKind::KdTree, {}, opt), count,
                           GetParam() + " kdtree " + std::string(name(split)) +
                               (mailbox ? "" : " without mailbox"));
        }
    }
    // The other SAH builds: 256 bins above 64 primitives, and the fast build (32 bins at every
    // node, subtrees on other threads for the stadium).
    AccelOptions binned, fast;
    binned.kdtree.binAbove = 64;
    fast.kdtree.build = KdBuild::Fast;
    expectSameHits(s, buildAccelerator(s, AccelKind::KdTree, {}, binned), count,
                   GetParam() + " kdtree binned above 64");
    expectSameHits(s, buildAccelerator(s, AccelKind::KdTree, {}, fast), count,
                   GetParam() + " kdtree fast build");
    // Extremes of the parameters: one level only, and huge leaves.
    AccelOptions shallow, fat;
    shallow.kdtree.maxDepth = 1;
    fat.kdtree.leafSize = 50;
    expectSameHits(s, buildAccelerator(s, AccelKind::KdTree, {}, shallow), count / 4,
                   GetParam() + " kdtree depth 1");
    expectSameHits(s, buildAccelerator(s, AccelKind::KdTree, {}, fat), count / 4,
                   GetParam() + " kdtree leaf size 50");
}

TEST_P(EveryScene, BvhFindsWhatBruteForceFinds) {
    const Scene s = loadBuiltinScene(GetParam());
    const int count = s.primitiveCount() > 1000 ? 400 : 3000;
    for (SplitMethod split : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah}) {
        AccelOptions opt;
        opt.bvh.split = split;
        expectSameHits(s, buildAccelerator(s, AccelKind::Bvh, {}, opt), count,
                       GetParam() + " bvh " + std::string(name(split)));
    }
}

INSTANTIATE_TEST_SUITE_P(Builtin, EveryScene,
                         ::testing::Values("default", "whitted", "cornell", "stadium"));

// The fast build's biggest nodes (over 65,536 references) are binned and partitioned by all
// cores in shares, and its subtrees built on other threads. With recording on the same build runs
// on one thread: both must make the same tree, node for node, and find what brute force finds.
TEST(KdTree, FastBuildOnAllCoresMakesTheOneThreadTree) {
    const Scene s = bench::knotScene(4 * 93, 93);  // 69,192 triangles
    ASSERT_GT(s.primitiveCount(), 65536u);
    KdTreeOptions o;
    o.build = KdBuild::Fast;
    const KdTree3 parallel(ScenePrims(s, {}), o);
    EventLog log(1000);  // capped: the build goes on unrecorded, on one thread
    const KdTree3 serial(ScenePrims(s, {}), o, log);
    ASSERT_EQ(parallel.nodes().size(), serial.nodes().size());
    for (std::size_t i = 0; i < parallel.nodes().size(); ++i) {
        const KdNode& a = parallel.nodes()[i];
        const KdNode& b = serial.nodes()[i];
        ASSERT_EQ(a.axis, b.axis) << "node " << i;
        ASSERT_EQ(a.split, b.split) << "node " << i;
        ASSERT_EQ(a.index, b.index) << "node " << i;
        ASSERT_EQ(a.count, b.count) << "node " << i;
    }
    EXPECT_EQ(parallel.primIds(), serial.primIds());
    EXPECT_EQ(parallel.stats().sahCost, serial.stats().sahCost);
    AccelOptions fast;
    fast.kdtree.build = KdBuild::Fast;
    expectSameHits(s, buildAccelerator(s, AccelKind::KdTree, {}, fast), 300, "knot fast build");
}

TEST(Accelerators, RendersMatchBruteForce) {
    for (const char* scene : {"default", "whitted", "cornell"}) {
        const Scene s = loadBuiltinScene(scene);
        RenderOptions opt;
        opt.width = 40;
        opt.height = 30;
        opt.trace.bounces = 4;
        const RenderResult brute = render(s, buildAccelerator(s, AccelKind::BruteForce), opt);
        for (AccelKind kind : {AccelKind::Grid, AccelKind::KdTree, AccelKind::Bvh}) {
            const RenderResult r = render(s, buildAccelerator(s, kind), opt);
            const std::string what = std::string(scene) + " " + std::string(accelKindName(kind));
            EXPECT_EQ(r.image.pixels, brute.image.pixels) << what;
            EXPECT_EQ(r.counters.rays, brute.counters.rays) << what;
            EXPECT_GT(r.counters.traversal.nodeVisits, 0u) << what;
        }
    }
}

TEST(Grid, ClearyWyvillResolution) {
    // A 2 x 1 x 1 box holding N spheres: cells per axis d_i cbrt(lambda N / V).
    Scene s;
    s.materials.push_back(Material{});
    for (int i = 0; i < 250; ++i)
        s.spheres.push_back({Vec3(0.1 + 1.8 * (i % 10) / 9.0, 0.5, 0.5), 0.1, 0});
    s.spheres.push_back({Vec3(0.5, 0.5, 0.5), 0.5, 0});
    s.spheres.push_back({Vec3(1.5, 0.5, 0.5), 0.5, 0});
    // Bounds are [0, 2] x [0, 1] x [0, 1]: V = 2, N = 252, lambda 4: cbrt(504) = 7.96 per unit.
    const UniformGrid g(ScenePrims(s, {}), GridOptions{});
    EXPECT_EQ(g.spec().res, IVecN<3>(16, 8, 8));
    EXPECT_EQ(g.cellCount(), 16u * 8u * 8u);
    // A primitive is listed in every cell its bounds overlap: the big spheres cover 8 x 8 x 8.
    EXPECT_GE(g.references(), 2u * 8u * 8u * 8u);
}

TEST(Grid, MailboxSavesRepeatedTests) {
    // The floor's two big triangles lie in every cell of its layer: without the mailbox a ray
    // along the floor tests them again in every cell.
    const Scene s = loadBuiltinScene("default");
    AccelOptions on, off;
    off.grid.mailbox = false;
    const Accelerator withBox = buildAccelerator(s, AccelKind::Grid, {}, on);
    const Accelerator without = buildAccelerator(s, AccelKind::Grid, {}, off);
    TraversalCounters a, b;
    const Ray grazing{Vec3(-11.9, 0.05, -11.9), glm::normalize(Vec3(1, 0, 1))};
    const auto h1 = intersect(withBox, grazing, a);
    const auto h2 = intersect(without, grazing, b);
    ASSERT_EQ(h1.has_value(), h2.has_value());
    EXPECT_GT(a.mailboxSkips, 0u);
    EXPECT_EQ(b.mailboxSkips, 0u);
    EXPECT_EQ(a.primitiveTests + a.mailboxSkips, b.primitiveTests);
    EXPECT_EQ(a.nodeVisits, b.nodeVisits);
}

}  // namespace
}  // namespace raystep

namespace raystep {
namespace {

TEST(Accelerators, SameHitsAtTheExtremesOfScale) {
    // The trees' plane tests and the DDA's crossings are relative: tiny, huge and far-away
    // copies of the scene give brute force's answers too.
    const Scene base = loadBuiltinScene("default");
    for (const auto& [scale, shift] : {std::pair{1e-6, Vec3(0.0)}, std::pair{1e6, Vec3(0.0)},
                                       std::pair{1.0, Vec3(1e5, -1e5, 3e5)}}) {
        const Scene s = transformScene(base, scale, shift);
        for (AccelKind kind : {AccelKind::Grid, AccelKind::KdTree, AccelKind::Bvh})
            expectSameHits(s, buildAccelerator(s, kind), 1500,
                           std::string(accelKindName(kind)) + " at scale " + std::to_string(scale));
    }
}

}  // namespace
}  // namespace raystep
