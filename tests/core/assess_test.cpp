// The assessor (assess/): each named mistake on a ray where its first wrong cell is worked out by
// hand, the verdict that names it, and the scene-level mistakes on the lecture's own scenes.
#include "raystep/assess/assess.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace raystep;

namespace {

GridSpec<3, double> grid4x4() {
    GridSpec<3, double> g;
    g.lo = {0, 0, 0};
    g.hi = {4, 4, 1};
    g.res = {4, 4, 1};
    return g;
}

std::vector<IVecN<2>> cellsOf(std::optional<Mistake> m, VecN<2, double> o, VecN<2, double> d) {
    GridSpec<2, double> g;
    g.lo = {0, 0};
    g.hi = {4, 4};
    g.res = {4, 4};
    std::vector<IVecN<2>> out;
    for (const auto& c : ddaWithMistake<2>(g, o, d, m, 12)) out.push_back(c.cell);
    return out;
}

std::string ray(double ox, double oy, double dx, double dy) {
    return "{\"ray\": {\"origin\": [" + std::to_string(ox) + ", " + std::to_string(oy) +
           "], \"dir\": [" + std::to_string(dx) + ", " + std::to_string(dy) + "]}}\n";
}
/// -0.0 written as JSON keeps its sign (std::to_string gives "-0.000000").
std::string cells(const std::vector<IVecN<2>>& cs) {
    std::string s;
    for (const auto& c : cs)
        s += "{\"cell\": [" + std::to_string(c.x) + ", " + std::to_string(c.y) + "]}\n";
    return s;
}

RayVerdict verdictOf(const std::string& text) {
    const StudentTrace t = readStudentTrace(text, "t.jsonl", 2);
    const Assessment a = assess(t, Reference::dda(grid4x4(), 2), Language::En);
    EXPECT_EQ(a.rays.size(), 1u);
    return a.rays.at(0);
}

using C = std::vector<IVecN<2>>;

}  // namespace

// Each variant on its ray, the cells by hand (grid [0, 4]^2, cells 1 x 1).
TEST(Mistakes, EachVariantWalksTheCellsWorkedOutByHand) {
    // (3.5, 2.5) - t (1, 0.5): tMaxX = 0.5 < tMaxY = 1, so X first: (2, 2), then Y at t = 1.
    EXPECT_EQ(cellsOf(std::nullopt, {3.5, 2.5}, {-1, -0.5}),
              (C{{3, 2}, {2, 2}, {2, 1}, {1, 1}, {0, 1}, {0, 0}}));
    // The boundary X + 1 = 4 when moving down: tMaxX = -0.5, tMaxY = (3 - 2.5) / -0.5 = -1.
    const C negative = cellsOf(Mistake::NegativeDirectionBoundary, {3.5, 2.5}, {-1, -0.5});
    ASSERT_GE(negative.size(), 2u);
    EXPECT_EQ(negative[1], (IVecN<2>{3, 1}));
    EXPECT_EQ(cellsOf(Mistake::StartCellSkipped, {3.5, 2.5}, {-1, -0.5})[0], (IVecN<2>{2, 2}));
    // dy = +0: step -1 and (2 - 2.5) / +0 = -inf: down in Y, out of the grid after (0, 0).
    EXPECT_EQ(cellsOf(Mistake::ParallelAxisDivision, {0.5, 2.5}, {1, 0.0}),
              (C{{0, 2}, {0, 1}, {0, 0}}));
    EXPECT_EQ(cellsOf(std::nullopt, {0.5, 2.5}, {1, 0.0}), (C{{0, 2}, {1, 2}, {2, 2}, {3, 2}}));
    // dy = -0.0: step +1 (-0.0 >= 0) and (3 - 2.5) / -0.0 = -inf: up in Y.
    EXPECT_EQ(cellsOf(Mistake::NegativeZero, {0.5, 2.5}, {1, -0.0}), (C{{0, 2}, {0, 3}}));
    // Through the vertex (1, 1): the slides' loop steps Y at the tie, into (0, 1).
    EXPECT_EQ(cellsOf(std::nullopt, {0.5, 0.5}, {1, 1}), (C{{0, 0}, {1, 1}, {2, 2}, {3, 3}}));
    EXPECT_EQ(cellsOf(Mistake::TieOneAxis, {0.5, 0.5}, {1, 1})[1], (IVecN<2>{0, 1}));
    // From (-1, 0.5) along (1, 1): enters at t = 1, at (0, 1.5), cell (0, 1); the origin's is y 0.
    EXPECT_EQ(cellsOf(std::nullopt, {-1, 0.5}, {1, 1})[0], (IVecN<2>{0, 1}));
    EXPECT_EQ(cellsOf(Mistake::NoEntryClip, {-1, 0.5}, {1, 1})[0], (IVecN<2>{0, 0}));
    // No exit check: on past (3, 2) to (4, 2), (5, 2)... until the cap.
    const C past = cellsOf(Mistake::NoExitCheck, {0.5, 2.5}, {1, 0.0});
    EXPECT_EQ(past.size(), 12u);
    EXPECT_EQ(past[4], (IVecN<2>{4, 2}));
}

TEST(Assess, NamesEachDdaMistakeAtItsFirstWrongCell) {
    struct Case {
        Mistake mistake;
        std::string ray;
        C cells;
        int index;
        std::string quantity;
    };
    const std::vector<Case> cases = {
        {Mistake::NegativeDirectionBoundary, ray(3.5, 2.5, -1, -0.5),
         cellsOf(Mistake::NegativeDirectionBoundary, {3.5, 2.5}, {-1, -0.5}), 1, "tMaxX"},
        {Mistake::StartCellSkipped, ray(3.5, 2.5, -1, -0.5),
         C{{2, 2}, {2, 1}, {1, 1}, {0, 1}, {0, 0}}, 0, "tEnter"},
        {Mistake::ParallelAxisDivision, ray(0.5, 2.5, 1, 0), C{{0, 2}, {0, 1}, {0, 0}}, 1, "tMaxY"},
        {Mistake::NegativeZero, "{\"ray\": {\"origin\": [0.5, 2.5], \"dir\": [1, -0.0]}}\n",
         C{{0, 2}, {0, 3}}, 1, "tMaxY"},
        {Mistake::TieOneAxis, ray(0.5, 0.5, 1, 1), C{{0, 0}, {0, 1}, {1, 1}, {1, 2}}, 1,
         "tMaxX = tMaxY"},
        {Mistake::NoEntryClip, ray(-1, 0.5, 1, 1), cellsOf(Mistake::NoEntryClip, {-1, 0.5}, {1, 1}),
         0, "tEnter"},
        {Mistake::NoExitCheck, ray(0.5, 2.5, 1, 0), C{{0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}}, 4,
         "tGridExit"},
    };
    for (const Case& c : cases) {
        const RayVerdict v = verdictOf(c.ray + cells(c.cells));
        const std::string name(mistakeInfo(c.mistake).name);
        ASSERT_FALSE(v.passed) << name;
        ASSERT_TRUE(v.divergence) << name;
        EXPECT_EQ(v.divergence->index, c.index) << name << ": " << v.divergence->explanation;
        EXPECT_EQ(v.divergence->quantity, c.quantity) << name << ": " << v.divergence->explanation;
        ASSERT_TRUE(v.mistake) << name << ": " << v.divergence->explanation;
        EXPECT_EQ(mistakeInfo(*v.mistake).name, name) << v.divergence->explanation;
    }
    // The right walk passes, its tMax too: (0.5 - 3.5) ... tMaxX = 0.5, tMaxY = 1 in (3, 2).
    const RayVerdict right =
        verdictOf(ray(3.5, 2.5, -1, -0.5) + "{\"cell\": [3, 2], \"tMax\": [0.5, 1]}\n" +
                  cells(C{{2, 2}, {2, 1}, {1, 1}, {0, 1}, {0, 0}}));
    EXPECT_TRUE(right.passed) << (right.divergence ? right.divergence->explanation : "");
}

TEST(Assess, ExplainsTheStepWithTheSlidesQuantitiesInBothLanguages) {
    // In (3, 2): tMaxX = 0.5 < tMaxY = 1; a student who steps Y is told why X comes first.
    const std::string text = ray(3.5, 2.5, -1, -0.5) + cells(C{{3, 2}, {3, 1}});
    const Reference ref = Reference::dda(grid4x4(), 2);
    const StudentTrace t = readStudentTrace(text, "t.jsonl", 2);
    const Divergence en = *assess(t, ref, Language::En).rays[0].divergence;
    EXPECT_EQ(
        en.explanation,
        "In cell (3, 2), tMaxX = 0.5 and tMaxY = 1: tMaxX < tMaxY, so the ray crosses the next "
        "X boundary first and the next cell is (2, 2); you stepped in Y, to (3, 1).");
    EXPECT_EQ(en.line, 3);
    const Divergence it = *assess(t, ref, Language::It).rays[0].divergence;
    EXPECT_NE(it.explanation.find("Nella cella (3; 2), tMaxX = 0,5 e tMaxY = 1"), std::string::npos)
        << it.explanation;
}

TEST(StudentTrace, RefusesBadRecordsNamingTheLine) {
    const auto problem = [](const std::string& text) {
        try {
            readStudentTrace(text, "s.jsonl", 2);
        } catch (const FileError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(problem(ray(0, 0, 1, 0) + "{\"cell\": [1]}\n"),
              "s.jsonl:2: key 'cell': expected 2 whole numbers [i, j]");
    EXPECT_NE(problem(ray(0, 0, 1, 0) + "\n\n{\"test\": -1}\n").find("s.jsonl:4: key 'test'"),
              std::string::npos);
    EXPECT_NE(problem("{\"hit\": {\"prim\": 1, \"t\": 2}}\n").find("s.jsonl:1: key 'hit'"),
              std::string::npos);
    EXPECT_NE(problem(ray(0, 0, 1, 0) + "{\"cell\": [0, 0], \"tMax\": [NaN, 1]}\n")
                  .find("s.jsonl:2: Infinity and NaN"),
              std::string::npos);
    EXPECT_EQ(problem(""), "s.jsonl: no ray: the trace has no {\"ray\": ...} line");
    // C's printf("%g", -0.0) writes -0: its sign is kept.
    const StudentTrace z =
        readStudentTrace("{\"ray\": {\"origin\": [0.5, 0.5], \"dir\": [1, -0]}}\n", "z", 2);
    EXPECT_TRUE(std::signbit(z.rays[0].dir[1]));
    // CRLF, a BOM and a null tMax (a parallel axis) read.
    const StudentTrace t = readStudentTrace(
        "\xEF\xBB\xBF" + ray(0.5, 0.5, 1, 0) + "{\"cell\": [0, 0], \"tMax\": [0.5, null]}\r\n",
        "s.jsonl", 2);
    ASSERT_EQ(t.rays.size(), 1u);
    ASSERT_TRUE(t.rays[0].records[0].tMax);
    EXPECT_TRUE(std::isinf((*t.rays[0].records[0].tMax)[1]));
}

// lecture-grid (its comment): along (0.4, 0.4) + t (0.8, 0.4) the slanted segment is hit in cell
// (3, 2) at t = 345/64, beyond that cell (it ends at t = 4.5); the circle in (4, 2) at 4.575.
TEST(Assess, NamesTheFirstHitInACellAndTheMissingMailbox) {
    const std::variant<Scene, Scene2D> scene = loadAnyScene("lecture-grid");
    const AnyStructure s = buildStructure(scene, AccelKind::Grid, {}, {});
    const Reference ref = Reference::structure(s, AccelKind::Grid);
    const std::string walk =
        ray(0.4, 0.4, 0.8, 0.4) + cells(C{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {3, 1}, {3, 2}});
    // The segment's id: the scene's primitives are its circles, then its segments.
    const ReferenceRay r = ref.run(readStudentTrace(walk, "w", 2).rays[0]);
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.t, 4.575, 1e-12);
    std::uint32_t segment = kNoId;
    for (const auto& u : r.units)
        if (u.kind == ReferenceUnit::Kind::Cell && u.cell[0] == 3 && u.cell[1] == 2 &&
            !u.hits.empty()) {
            segment = u.hits[0].first;
            EXPECT_NEAR(u.hits[0].second, 345.0 / 64, 1e-12);
        }
    ASSERT_NE(segment, kNoId);
    const std::string early =
        walk + "{\"hit\": {\"prim\": " + std::to_string(segment) + ", \"t\": 5.390625}}\n";
    const Assessment a = assess(readStudentTrace(early, "w", 2), ref, Language::En);
    ASSERT_FALSE(a.rays[0].passed);
    EXPECT_EQ(a.rays[0].divergence->record, "end");
    EXPECT_EQ(a.rays[0].divergence->index, 6);
    ASSERT_TRUE(a.rays[0].mistake);
    EXPECT_EQ(*a.rays[0].mistake, Mistake::FirstHitInCell);
    EXPECT_NE(a.rays[0].divergence->explanation.find("beyond this cell's exit, t = 4.5"),
              std::string::npos)
        << a.rays[0].divergence->explanation;
    // Every cell's tests, and the first cell's primitive tested again in the second.
    std::string tests = ray(0.4, 0.4, 0.8, 0.4);
    std::uint32_t first = kNoId;
    for (const auto& u : r.units) {
        tests +=
            "{\"cell\": [" + std::to_string(u.cell[0]) + ", " + std::to_string(u.cell[1]) + "]}\n";
        for (std::uint32_t p : u.tests) tests += "{\"test\": " + std::to_string(p) + "}\n";
        if (first == kNoId && !u.tests.empty())
            first = u.tests[0];
        else if (first != kNoId && !u.skipped.empty() && u.skipped[0] == first)
            tests += "{\"test\": " + std::to_string(first) + "}\n";
    }
    const Assessment m = assess(readStudentTrace(tests, "m", 2), ref, Language::En);
    ASSERT_FALSE(m.rays[0].passed);
    EXPECT_EQ(m.rays[0].divergence->record, "test");
    ASSERT_TRUE(m.rays[0].mistake);
    EXPECT_EQ(*m.rays[0].mistake, Mistake::NoMailbox);
}

// A kd-tree's TestTree stopped at the first leaf with a hit: a ray of a fan over lecture-kdtree
// whose first hitting leaf is not its last, cut there as the student's code would.
TEST(Assess, NamesTestTreeStoppingAtItsFirstHit) {
    const std::variant<Scene, Scene2D> scene = loadAnyScene("lecture-kdtree");
    const AnyStructure s = buildStructure(scene, AccelKind::KdTree, {}, {});
    const Reference ref = Reference::structure(s, AccelKind::KdTree);
    int named = 0, tried = 0;
    for (int k = 0; k < 360; ++k) {
        const double a = k * 0.0174533;
        const std::string head =
            ray(k % 2 ? 0.2 : 7.8, k % 3 ? 7.6 : 0.3, std::cos(a), std::sin(a));
        const ReferenceRay r = ref.run(readStudentTrace(head, "f", 2).rays[0]);
        std::size_t firstHit = r.units.size();
        for (std::size_t i = 0; i < r.units.size() && firstHit == r.units.size(); ++i)
            if (!r.units[i].hits.empty()) firstHit = i;
        if (firstHit + 1 >= r.units.size()) continue;
        const auto& h = r.units[firstHit].hits.back();
        ++tried;
        std::string text = head;
        for (std::size_t i = 0; i <= firstHit; ++i)
            text += "{\"node\": " + std::to_string(r.units[i].node) + "}\n";
        text += "{\"hit\": {\"prim\": " + std::to_string(h.first) +
                ", \"t\": " + std::to_string(h.second) + "}}\n";
        const Assessment as = assess(readStudentTrace(text, "f", 2), ref, Language::En);
        ASSERT_FALSE(as.rays[0].passed);
        EXPECT_EQ(as.rays[0].divergence->record, "end") << as.rays[0].divergence->explanation;
        named += as.rays[0].mistake == Mistake::FirstHitInTree;
    }
    EXPECT_GT(tried, 0);
    EXPECT_EQ(named, tried);
}
