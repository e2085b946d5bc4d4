// A step's and an exercise's own structure (docs/lesson-format.md, "setup" on a step or an
// exercise; "compare"): read over the lesson's setup, refused with file, line and key; and lesson
// 10's exercises on the grid, the kd-tree and the BVH keyed from each structure's own trace,
// against a computation by hand from the scene (scenes/lecture-kdtree.json).
#include "lesson_test_util.h"

#include "course/exercise.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include "raystep/accel/accel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace raystep {
namespace {

using test::expectLessonError;
using test::lessonWith;

const std::string kStep = ",\n\"steps\": [{\"text\": {\"en\": \"s\"}, ";  // the step opens line 11

TEST(StructureSetup, AStepsSetupIsTheLessonsWithItsKeysOver) {
    const Lesson l = loadLessonText(
        lessonWith(kStep + "\"setup\": {\"accel\": \"bvh\", \"split\": \"sah\"}}, "
                           "{\"text\": {\"en\": \"t\"}}],\n\"exercises\": [{\"id\": \"e\", "
                           "\"type\": \"count\", \"count\": \"primitive_test\", \"prompt\": "
                           "{\"en\": \"p\"}, \"setup\": {\"accel\": \"kdtree\"}}]"),
        "ok.json");
    ASSERT_TRUE(l.steps[0].setup.has_value());
    EXPECT_EQ(l.steps[0].setup->accel, AccelKind::Bvh);
    EXPECT_EQ(l.steps[0].setup->options.bvh.split, SplitMethod::Sah);
    EXPECT_FALSE(l.steps[1].setup.has_value()) << "no setup: the lesson's grid";
    EXPECT_EQ(l.setupOf(l.steps[1].setup).accel, AccelKind::Grid);
    ASSERT_TRUE(l.exercises[0].setup.has_value());
    EXPECT_EQ(l.exercises[0].setup->accel, AccelKind::KdTree);
    // Three structures, the lesson's first, each once.
    const auto setups = l.setups();
    ASSERT_EQ(setups.size(), 3u);
    EXPECT_EQ(setups[0].accel, AccelKind::Grid);
    EXPECT_EQ(setups[1].accel, AccelKind::Bvh);
    EXPECT_EQ(setups[2].accel, AccelKind::KdTree);
    // The same BVH named twice is one structure: one key.
    LessonSetup again = *l.steps[0].setup;
    EXPECT_EQ(again.key(), l.steps[0].setup->key());
    again.options.setSplit(SplitMethod::Median);
    EXPECT_NE(again.key(), l.steps[0].setup->key());
}

TEST(StructureSetup, ABadOwnSetupNamesFileLineAndKey) {
    // Line 11 holds the step, 12 its setup's key.
    expectLessonError(lessonWith(kStep + "\n\"setup\": {\"accel\": \"octree\"}}]"), 12,
                      "steps[0].setup.accel", "expected bruteforce, grid, kdtree or bvh");
    expectLessonError(
        lessonWith(kStep + "\n\"setup\": {\"accel\": \"bvh\", \"split\": \"best\"}}]"), 12,
        "steps[0].setup.split", "expected midpoint, median or sah");
    expectLessonError(lessonWith(kStep + "\n\"setup\": {\"colour\": 1}}]"), 12,
                      "steps[0].setup.colour", "unknown key");
    expectLessonError(lessonWith(",\n\"exercises\": [{\"id\": \"e\", \"type\": \"count\", "
                                 "\"count\": \"primitive_test\", \"prompt\": {\"en\": \"p\"},\n"
                                 "\"setup\": {\"accel\": \"bvh\", \"split\": \"fast\"}}]"),
                      12, "exercises[0].setup.split", "expected midpoint, median or sah");
    expectLessonError(lessonWith(kStep + "\n\"compare\": {\"accel\": \"grid,octree\"}}]"), 12,
                      "steps[0].compare.accel", "octree");
    expectLessonError(
        lessonWith(kStep + "\"compare\": {\"accel\": \"grid,bvh\",\n\"split\": \"best\"}}]"), 12,
        "steps[0].compare.split", "best");
    expectLessonError(lessonWith(kStep + "\n\"compare\": {\"split\": \"sah\"}}]"), 12,
                      "steps[0].compare", "\"accel\" is required");
}

TEST(StructureSetup, ACompareStepListsItsStructures) {
    const Lesson l = loadLesson("hierarchies");
    const auto compare = std::find_if(l.steps.begin(), l.steps.end(),
                                      [](const LessonStep& s) { return !s.compare.empty(); });
    ASSERT_NE(compare, l.steps.end());
    EXPECT_EQ(compare->compare, (std::vector<StructureChoice>{{AccelKind::Grid, std::nullopt},
                                                              {AccelKind::KdTree, SplitMethod::Sah},
                                                              {AccelKind::Bvh, SplitMethod::Sah}}));
    EXPECT_FALSE(compare->setup.has_value()) << "the compare step is on the lesson's kd-tree";
}

// The ray o = (0.2, 7.6), d = (1, -0.55). A box [x0, x1] x [y0, y1]: the x slab from
// t = x0 - 0.2 to x1 - 0.2, the y slab from (y1 - 7.6) / -0.55 to (y0 - 7.6) / -0.55.
std::array<double, 2> slab(double x0, double y0, double x1, double y1) {
    const double tn = std::max(x0 - 0.2, (y1 - 7.6) / -0.55);
    const double tf = std::min(x1 - 0.2, (y0 - 7.6) / -0.55);
    return {tn, tf};
}
bool meets(const std::array<double, 2>& t) {
    return t[0] <= t[1];
}

TEST(StructureSetup, TheBvhExercisesKeysEqualAHandComputation) {
    const Lesson l = loadLesson("hierarchies");
    EXPECT_NO_THROW(validateLesson(l));
    const LessonRun run = runLesson(l);
    const LessonLogs logs = run.logs();
    const Exercise& nodes = *l.exercise("bvh-nodes");
    const EventLog& bvh = logs.of(nodes.setup);
    ASSERT_NE(&bvh, run.log.get()) << "the BVH's own trace, not the kd-tree's";

    // The boxes the prompts give (node: x0, y0, x1, y1) are the BVH's own.
    const std::vector<std::pair<std::uint32_t, std::array<double, 4>>> boxes{
        {1, {0.5, 0.5, 7.69, 2.96}},    {22, {0.8, 3.5, 7.6, 7.5}},
        {23, {0.8, 3.5, 4.6, 6.5}},     {28, {3, 6.8, 7.6, 7.5}},
        {24, {0.8, 3.5, 2.6, 6.5}},     {27, {4.2, 3.6, 4.6, 5.4}},
        {25, {0.8, 3.5, 2.6, 4.9}},     {26, {1, 5.5, 2, 6.5}},
        {3, {5.84, 0.82, 7.69, 2.96}},  {4, {5.98, 0.82, 7.57, 1.85}},
        {13, {5.84, 1.84, 7.69, 2.96}}, {5, {5.98, 0.98, 6.65, 1.85}},
        {8, {6.52, 0.82, 7.57, 1.7}}};
    for (const auto& [id, b] : boxes) {
        SCOPED_TRACE(id);
        ASSERT_LT(id, bvh.nodes().size());
        EXPECT_NEAR(bvh.nodes()[id].lo[0], b[0], 1e-9);
        EXPECT_NEAR(bvh.nodes()[id].lo[1], b[1], 1e-9);
        EXPECT_NEAR(bvh.nodes()[id].hi[0], b[2], 1e-9);
        EXPECT_NEAR(bvh.nodes()[id].hi[1], b[3], 1e-9);
    }
    // By hand, nearest child first: node 1's y slab starts at (2.96 - 7.6) / -0.55 = 8.44, past
    // its x exit 7.49: missed. Node 22: [max(0.6, 0.18), min(7.4, 7.45)] = [0.6, 7.4]; its leaf
    // 28 [2.8, 1.45] is missed; 23 [max(0.6, 2), min(4.4, 7.45)] = [2, 4.4]. In 23, 24 [2, 2.4]
    // comes before 27 [4, 4.4]; 24's leaves 25 [4.91, 2.4] and 26 [2, 1.8] are both missed.
    EXPECT_FALSE(meets(slab(0.5, 0.5, 7.69, 2.96)));
    EXPECT_TRUE(meets(slab(0.8, 3.5, 7.6, 7.5)));
    EXPECT_FALSE(meets(slab(3, 6.8, 7.6, 7.5)));
    EXPECT_NEAR(slab(0.8, 3.5, 4.6, 6.5)[0], 2.0, 1e-12);
    EXPECT_NEAR(slab(0.8, 3.5, 2.6, 6.5)[1], 2.4, 1e-12);
    EXPECT_NEAR(slab(4.2, 3.6, 4.6, 5.4)[0], 4.0, 1e-12);
    EXPECT_FALSE(meets(slab(0.8, 3.5, 2.6, 4.9)));
    EXPECT_FALSE(meets(slab(1, 5.5, 2, 6.5)));
    EXPECT_EQ(referenceAnswer(nodes, bvh, l.file).numbers,
              (std::vector<double>{0, 22, 23, 24, 27}));

    // Overlap, from the prompt's boxes: 4 and 13 share y in [1.84, 1.85] and x in [5.98, 7.57];
    // 5 and 8 share x in [6.52, 6.65] and y in [0.98, 1.7]; 8 ends at y = 1.7 below 13's 1.84
    // (apart); 4 lies inside 3 (the hierarchy, not an overlap).
    const Exercise& overlap = *l.exercise("bvh-overlap");
    const EventLog& same = logs.of(overlap.setup);
    const auto right = [&](double a, double b) {
        return checkAnswer(overlap, same, Answer{{a, b}, {}}, Language::En, l.file).correct;
    };
    EXPECT_TRUE(right(4, 13));
    EXPECT_TRUE(right(13, 4));
    EXPECT_TRUE(right(5, 8));
    EXPECT_FALSE(right(8, 13));
    EXPECT_FALSE(right(3, 4));
    EXPECT_FALSE(right(24, 27)) << "x 0.8..2.6 and 4.2..4.6 are apart";
    EXPECT_FALSE(right(4, 99)) << "no such node";
    EXPECT_NE(
        checkAnswer(overlap, same, Answer{{3, 4}, {}}, Language::En, l.file).slip.find("inside"),
        std::string::npos);

    // Primitive tests per structure. The BVH: the one leaf entered is 27, its one segment, hit at
    // 0.2 + t = 4.2 + 0.4 s, 7.6 - 0.55 t = 3.6 + 1.8 s: s = 90/101, t = 440/101.
    const auto tested = [](const EventLog& log) {
        std::vector<std::uint32_t> prims;
        for (const Event& e : log.events())
            if (const auto* t = std::get_if<PrimitiveTest>(&e)) prims.push_back(t->prim);
        return prims;
    };
    EXPECT_EQ(tested(bvh), (std::vector<std::uint32_t>{14}));
    EXPECT_EQ(referenceAnswer(*l.exercise("tests-bvh"), bvh, l.file).numbers,
              (std::vector<double>{1}));
    EXPECT_TRUE(std::any_of(bvh.events().begin(), bvh.events().end(), [](const Event& e) {
        const auto* h = std::get_if<RayHit>(&e);
        return h && std::abs(h->t - 440.0 / 101.0) < 1e-12;
    }));
    // The grid, 8 x 8 over [0.5, 7.69] x [0.5, 7.5] (cells 0.89875 x 0.875): the ray crosses
    // (0,7) (1,7) (1,6) (2,6) (3,6) (3,5) (4,5). The big circle's box [1, 2] x [5.5, 6.5] is in
    // the cells x 0..1, y 5..6, so in (1,6): tested, missed. The short segment's box
    // [4.2, 4.6] x [3.6, 5.4] is in x 4, y 3..5, so in (4,5): hit at 440/101 = 4.356, inside the
    // cell (entered at t = 3.895, left at 4.794): the walk stops. The long top segment's box is
    // in x 2..7 of row 7, which the ray leaves at x = 1; the segment below the circle is in
    // x 0..2 of rows 3..5, which the ray reaches at x = 3. Two tests.
    const Exercise& grid = *l.exercise("tests-grid");
    EXPECT_EQ(tested(logs.of(grid.setup)), (std::vector<std::uint32_t>{10, 14}));
    EXPECT_EQ(referenceAnswer(grid, logs.of(grid.setup), l.file).numbers, (std::vector<double>{2}));
    // The SAH kd-tree: its tests counted in a trace the core records on its own (not through the
    // lesson), as raystep-cli trace --accel kdtree --split sah does.
    const Exercise& kd = *l.exercise("tests-kdtree");
    AccelOptions sah;
    sah.setSplit(SplitMethod::Sah);
    const Scene2D& scene = std::get<Scene2D>(*run.scene);
    const Accelerator2D tree = buildAccelerator2D(scene, AccelKind::KdTree, sah);
    EventLog own;
    own.setDims(2);
    traceRay2D(tree, *scene.exampleRay, own);
    EXPECT_EQ(tested(own), (std::vector<std::uint32_t>{10, 13, 14}));
    EXPECT_EQ(referenceAnswer(kd, logs.of(kd.setup), l.file).numbers, (std::vector<double>{3}));
    // The lesson's own kd-tree (midpoint) is another structure again: 4 tests in leaf 1, 1 in 14.
    EXPECT_EQ(tested(*run.log).size(), 5u);
}

TEST(StructureSetup, AnAnswerSheetIsGradedPerStructure) {
    const Lesson l = loadLesson("hierarchies");
    const LessonRun run = runLesson(l);
    const AnswerSheet sheet = loadAnswerSheet(
        R"({"lesson": "hierarchies", "answers": {"bvh-nodes": "0 22 23 24 27", "tests-grid": 2,
            "tests-kdtree": 5, "tests-bvh": 1, "bvh-overlap": "5 8"}})",
        "sheet.json");
    const Grade g = gradeAnswers(l, run.logs(), sheet, Language::En, "sheet.json");
    const auto item = [&](const std::string& id) {
        return *std::find_if(g.items.begin(), g.items.end(),
                             [&](const Grade::Item& i) { return i.exercise == id; });
    };
    EXPECT_TRUE(item("bvh-nodes").correct);
    EXPECT_TRUE(item("tests-grid").correct);
    EXPECT_FALSE(item("tests-kdtree").correct) << "5 is the midpoint tree's, not the SAH's";
    EXPECT_TRUE(item("tests-bvh").correct);
    EXPECT_TRUE(item("bvh-overlap").correct);
}

}  // namespace
}  // namespace raystep
