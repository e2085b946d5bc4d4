// Replay: the state at a cursor is what the lecture shows at that step, and seeking anywhere,
// in any order, gives the state of a fold from the start.
#include "raystep/trace/replay.h"
#include "raystep/accel/accel.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <random>

namespace raystep {
namespace {

TEST(Replay, TheSlidesDdaExampleStepByStep) {
    const Scene2D s = std::get<Scene2D>(loadAnyScene("lecture-grid"));
    const Accelerator2D grid = buildAccelerator2D(s, AccelKind::Grid);
    EventLog log;
    TraversalCounters c;
    const Ray2 r = *s.exampleRay;
    const std::uint32_t id =
        log.beginRay(Ray{Vec3(r.origin, 0.0), Vec3(r.dir, 0.0)}, RayKind::Primary, 0, kNoId);
    std::get<UniformGridT<Scene2DPrims>>(grid).intersect(r, c, log, id);

    Replay replay(log);
    // After the set-up and the first cell: X = 0, Y = 0, tMax = (0.6/0.8, 0.6/0.4) = (0.75, 1.5),
    // tDelta = (1/0.8, 1/0.4) = (1.25, 2.5), by hand from the origin (0.4, 0.4), the direction
    // (0.8, 0.4) and cells of 1.
    const std::size_t first = replay.nextOfKind(0, variantIndex<DdaCell>());
    const ReplayState& a = replay.seek(first + 1);
    ASSERT_TRUE(a.ddaSetup && a.ddaCell);
    EXPECT_EQ(a.ddaCell->cell[0], 0);
    EXPECT_EQ(a.ddaCell->cell[1], 0);
    EXPECT_NEAR(a.ddaCell->tMax[0], 0.75, 1e-15);
    EXPECT_NEAR(a.ddaCell->tMax[1], 1.5, 1e-15);
    EXPECT_NEAR(a.ddaSetup->tDelta[0], 1.25, 1e-15);
    EXPECT_NEAR(a.ddaSetup->tDelta[1], 2.5, 1e-15);
    // Three steps on: (1,0) by X, (1,1) by Y, (2,1) by X, as on the slides.
    std::size_t at = first;
    for (int i = 0; i < 3; ++i) at = replay.nextOfKind(at + 1, variantIndex<DdaCell>());
    const ReplayState& b = replay.seek(at + 1);
    const std::vector<std::array<std::int32_t, 3>> cells = {
        {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}};
    EXPECT_EQ(b.visitedCells, cells);
    EXPECT_EQ(b.ddaCell->axes, 1u);  // stepped in X
    EXPECT_FALSE(b.nearestT);
    // At the end: the long segment hit in cell (3,2) beyond it (the cell ends at t = 4.5), then
    // the small circle nearer in (4,2). The circle (4.3, 2.3), r 0.25, by hand: a = d.d = 0.8,
    // b = (o - c).d = -3.88, c = |o - c|^2 - r^2 = 18.7575, b^2 - a c = 0.0484 = 0.22^2, so
    // t = (3.88 - 0.22) / 0.8 = 4.575.
    const ReplayState& end = replay.seek(replay.size());
    EXPECT_EQ(end.visitedCells.back(), (std::array<std::int32_t, 3>{4, 2, 0}));
    ASSERT_TRUE(end.nearestT);
    EXPECT_NEAR(*end.nearestT, 4.575, 1e-13);
    // The segment (3.7, 2.95)-(5.5, 2.25), by hand: 0.4 + 0.8 t = 3.7 + 1.8 s and
    // 0.4 + 0.4 t = 2.95 - 0.7 s give s = 9/16, t = 345/64; seen before the circle's.
    bool segmentSeen = false;
    for (const PrimitiveTest& t : end.tests)
        if (t.hit && t.prim == 6) {
            segmentSeen = true;
            EXPECT_NEAR(t.t, 345.0 / 64.0, 1e-13);
        }
    EXPECT_TRUE(segmentSeen);
    EXPECT_EQ(end.mailboxSkips.size(), c.mailboxSkips);
}

// Lesson 11's "raise cIsect and watch where the SAH stops cutting": every node opens with what
// making it a leaf costs at the C_isect in use, before any candidate, leaves included.
TEST(Replay, EveryBuildNodeCarriesItsLeafCostAtTheCIsectInUse) {
    const Scene2D s = std::get<Scene2D>(loadAnyScene("lecture-kdtree"));
    ASSERT_EQ(s.primitiveCount(), 15u);  // lesson 11: "all 15 primitives"
    for (const AccelKind kind : {AccelKind::KdTree, AccelKind::Bvh}) {
        SCOPED_TRACE(accelKindName(kind));
        AccelOptions options;
        options.kdtree.cIsect = options.bvh.cIsect = 20.0;
        EventLog log;
        buildAccelerator2D(s, kind, options, &log);
        std::size_t nodes = 0, leaves = 0;
        std::optional<BuildNode> open;
        for (const Event& e : log.events()) {
            if (const auto* b = std::get_if<BuildNode>(&e)) {
                ++nodes;
                open = *b;
                EXPECT_EQ(b->cIsect, 20.0);
                EXPECT_EQ(b->leafCost, 20.0 * b->prims);
                if (b->parent == kNoId) {
                    EXPECT_EQ(b->leafCost, 300.0);  // 20 x 15
                }
            }
            // The node's outcome says the same cost as its opening did.
            if (const auto* c = std::get_if<SplitChosen>(&e)) {
                ASSERT_TRUE(open && open->node == c->node);
                EXPECT_EQ(c->leafCost, open->leafCost);
            }
            if (const auto* l = std::get_if<LeafMade>(&e)) {
                ++leaves;
                ASSERT_TRUE(open && open->node == l->node);
                EXPECT_EQ(l->leafCost, open->leafCost);
            }
        }
        EXPECT_GT(nodes, 1u);
        EXPECT_GT(leaves, 1u);
    }
}

TEST(Replay, ABlockedShadowRayEndsBlockedNotHit) {
    EventLog log;
    const std::uint32_t primary = log.beginRay(Ray{}, RayKind::Primary, 0, kNoId);
    log(RayHit{primary, 2, 3.0, 0.0, 0.0});
    const std::uint32_t shadow = log.beginRay(Ray{}, RayKind::Shadow, 1, primary);
    log(PrimitiveTest{shadow, 4, true, 0.5});
    log(RayBlocked{shadow, 4, 0.5});
    log.beginRay(Ray{}, RayKind::Shadow, 1, primary);
    Replay r(log);
    const ReplayState& at = r.seek(5);  // just after the RayBlocked
    EXPECT_EQ(at.ray, shadow);
    ASSERT_TRUE(at.blocked);
    EXPECT_EQ(at.blocked->prim, 4u);
    EXPECT_EQ(at.blocked->t, 0.5);
    EXPECT_FALSE(at.hit);  // the shadow ray's own state: no nearest hit of its own
    EXPECT_FALSE(at.missed);
    EXPECT_FALSE(r.seek(6).blocked);  // the next ray starts afresh
}

TEST(Replay, EveryChosenSplitIsTheCheapestCandidate) {
    // Replaying a SAH build: at each choice, the candidates shown so far include one of exactly
    // the chosen cost and none cheaper (the build picks the minimum of what it evaluated).
    for (const char* name : {"default", "cornell"}) {
        const Scene s = loadBuiltinScene(name);
        EventLog log;
        buildAccelerator(s, AccelKind::KdTree, {}, {}, log);
        Replay replay(log);
        std::size_t at = 0, choices = 0;
        while ((at = replay.nextOfKind(at, variantIndex<SplitChosen>())) < replay.size()) {
            const ReplayState& st = replay.seek(at + 1);
            ASSERT_TRUE(st.chosen);
            ASSERT_FALSE(st.candidates.empty());
            double cheapest = kInfinity;
            for (const SplitCandidate& c : st.candidates) cheapest = std::min(cheapest, c.sahCost);
            EXPECT_EQ(cheapest, st.chosen->sahCost) << name << " node " << st.chosen->node;
            EXPECT_LT(st.chosen->sahCost, st.chosen->leafCost);
            ++choices;
            ++at;
        }
        EXPECT_GT(choices, 3u) << name;
    }
}

TEST(Replay, SeekingAnywhereEqualsAFoldFromTheStart) {
    const Scene s = loadBuiltinScene("stadium");
    EventLog log(30000);  // capped: the first 30,000 events of the stadium's SAH build
    buildAccelerator(s, AccelKind::KdTree, {}, {}, log);
    ASSERT_TRUE(log.truncated());
    Replay replay(log);
    std::mt19937 rng(5);
    std::uniform_int_distribution<std::size_t> pick(0, replay.size());
    for (int i = 0; i < 40; ++i) {
        const std::size_t cursor = i == 0 ? replay.size() : pick(rng);
        const ReplayState got = replay.seek(cursor);
        ReplayState fold;
        for (std::size_t k = 0; k < cursor; ++k) applyEvent(fold, log.events()[k]);
        EXPECT_EQ(got.cursor, cursor);
        EXPECT_EQ(got.nodesBuilt, fold.nodesBuilt);
        EXPECT_EQ(got.leavesMade, fold.leavesMade);
        ASSERT_EQ(got.candidates.size(), fold.candidates.size()) << cursor;
        if (!got.candidates.empty()) {
            EXPECT_EQ(got.candidates.back().position, fold.candidates.back().position);
            EXPECT_EQ(got.candidates.back().sahCost, fold.candidates.back().sahCost);
        }
        EXPECT_EQ(got.buildNode.has_value(), fold.buildNode.has_value());
        if (got.buildNode) {
            EXPECT_EQ(got.buildNode->node, fold.buildNode->node);
        }
    }
}

// Brute force on a big model: one ray's 1.5 million tests. A checkpoint every 4096 events used
// to copy the ray's state each time (quadratic: 10 GB for 3 million events); past the budget
// the checkpoints are spaced wider, and seeking still equals a fold from the start.
TEST(Replay, ALongRayKeepsItsCheckpointsBoundedAndSeeksExactly) {
    EventLog log(2'000'000);
    log(RayBegin{0, kNoId, RayKind::Primary, 0});
    constexpr std::uint32_t kTests = 1'500'000;
    for (std::uint32_t p = 0; p < kTests; ++p)
        log(PrimitiveTest{0, p, p % 1000 == 999, p % 1000 == 999 ? 1.0 + p : kInfinity});
    const auto start = std::chrono::steady_clock::now();
    Replay replay(log);
    // Quadratic, 366 checkpoints of 0.75 M tests on average (24 bytes each) took 6.6 GB.
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
    std::mt19937 rng(7);
    std::uniform_int_distribution<std::size_t> pick(0, replay.size());
    for (int i = 0; i < 12; ++i) {
        const std::size_t cursor = i == 0 ? replay.size() : pick(rng);
        const ReplayState got = replay.seek(cursor);
        // Independent of the replay: cursor - 1 tests (the first event begins the ray), the
        // nearest hit the first test k with k % 1000 == 999 before it, at t = 1 + k.
        const std::size_t tests = cursor > 0 ? cursor - 1 : 0;
        ASSERT_EQ(got.tests.size(), tests) << cursor;
        if (tests >= 1000) {
            EXPECT_EQ(got.nearestPrim, 999u);
            EXPECT_EQ(got.nearestT, 1000.0);
        } else {
            EXPECT_FALSE(got.nearestT.has_value());
        }
        if (tests > 0) {
            EXPECT_EQ(got.tests.back().prim, tests - 1);
        }
    }
}

}  // namespace
}  // namespace raystep
