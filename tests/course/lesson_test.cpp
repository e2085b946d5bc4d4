// Lessons: every built-in lesson loads, records its trace and replays each step; every exercise's
// reference answer passes its own check and a wrong one fails; the references of the slides'
// examples equal a hand computation; bad lesson, answers and progress files name line and key.
#include "lesson_test_util.h"

#include "course/exercise.h"
#include "course/grading.h"
#include "course/grid_sweep.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"
#include "course/progress.h"

#include "raystep/accel/sah.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/trace/replay.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace raystep {
namespace {

using test::expectLessonError;
using test::lessonWith;

TEST(Lessons, ThirteenInTheLecturesOrderEachInBothLanguages) {
    const std::vector<Lesson> lessons = builtinLessons();
    ASSERT_EQ(lessons.size(), 13u);
    for (int i = 0; i < 13; ++i) {
        const Lesson& l = lessons[i];
        SCOPED_TRACE(l.file);
        EXPECT_EQ(l.number, i + 1);
        EXPECT_TRUE(l.title.has(Language::It));
        EXPECT_TRUE(l.text.has(Language::It));
        EXPECT_FALSE(l.exercises.empty()) << "every lesson has exercises";
        for (const LessonStep& s : l.steps) EXPECT_TRUE(s.text.has(Language::It));
        for (const Exercise& e : l.exercises) {
            EXPECT_TRUE(e.prompt.has(Language::It)) << e.id;
            ASSERT_FALSE(e.hints.empty()) << e.id << ": every exercise has a hint";
            for (const LocalText& h : e.hints) EXPECT_TRUE(h.has(Language::It)) << e.id;
        }
        // By id, by number, the same lesson.
        EXPECT_EQ(loadLesson(l.id).number, l.number);
        EXPECT_EQ(loadLesson(std::to_string(l.number)).id, l.id);
    }
}

void expectValid(const Lesson& l) {
    // Every check of validateLesson, the giveaways included (review lessons.md section 4.2).
    try {
        validateLesson(l);
    } catch (const LessonError& e) {
        ADD_FAILURE() << e.what();
    }
}

TEST(Lessons, EveryStepReplaysAndEveryExerciseChecksItsOwnReference) {
    for (const Lesson& l : builtinLessons()) {
        SCOPED_TRACE(l.id);
        expectValid(l);
        const LessonRun run = runLesson(l);
        const std::vector<GridSweepRow> sweep = sweepRowsIfNeeded(l, run);
        // Each step and exercise in its own structure's trace (the lesson's, or its setup's).
        const LessonLogs logs = run.logs();
        for (const LessonStep& s : l.steps) {
            Replay replay(logs.of(s.setup));
            const auto at = resolvePosition(s.at, logs.of(s.setup));
            ASSERT_TRUE(at.has_value()) << describePosition(s.at);
            EXPECT_EQ(replay.seek(*at).cursor, *at);
        }
        for (const Exercise& ex : l.exercises) {
            SCOPED_TRACE(ex.id);
            const EventLog& log = logs.of(ex.setup);
            const Answer ref = referenceAnswer(ex, log, l.file, &sweep);
            const Verdict right = checkAnswer(ex, log, ref, Language::En, l.file, &sweep);
            EXPECT_TRUE(right.correct);
            EXPECT_FALSE(right.feedback.empty());
            // As a student would type it, in both languages.
            for (const Language lang : {Language::En, Language::It}) {
                std::string why;
                const auto typed = parseAnswer(ex, formatAnswer(ex, ref, lang), &why, lang);
                ASSERT_TRUE(typed.has_value()) << why;
                EXPECT_TRUE(checkAnswer(ex, log, *typed, lang, l.file, &sweep).correct);
            }

            Answer wrong = ref;
            switch (ex.kind) {
                case ExerciseKind::NextCell:
                    wrong.numbers[0] += 1;
                    break;
                case ExerciseKind::Value:
                    wrong.numbers[0] = wrong.numbers[0] * 1.5 + 1.0;
                    break;
                case ExerciseKind::Count:
                    wrong.numbers[0] += 1;
                    break;
                case ExerciseKind::PickSplit: {
                    // A strictly dearer candidate.
                    double best = kInfinity;
                    for (const SplitCandidate& c : splitCandidates(ex, log))
                        best = std::min(best, c.sahCost);
                    for (const SplitCandidate& c : splitCandidates(ex, log))
                        if (c.sahCost > best * 1.01) {
                            wrong.numbers = {static_cast<double>(c.axis), c.position};
                            break;
                        }
                    ASSERT_NE(wrong.numbers, ref.numbers) << "every candidate costs the same";
                    break;
                }
                case ExerciseKind::HitOrMiss:
                    wrong.hit = !*ref.hit;
                    wrong.numbers = *wrong.hit ? std::vector<double>{1.0} : std::vector<double>{};
                    break;
                case ExerciseKind::Choice:
                    wrong.numbers[0] = ref.numbers[0] == 0 ? 1 : 0;
                    break;
                case ExerciseKind::Sequence:
                    wrong.numbers.back() += 1;
                    break;
                case ExerciseKind::SweepPick:
                    wrong.numbers[0] = sweep.front().resolution == ref.numbers[0]
                                           ? sweep.back().resolution
                                           : sweep.front().resolution;
                    break;
                case ExerciseKind::Compute:
                    wrong.numbers[0] = wrong.numbers[0] * 1.5 + 1.0;
                    break;
                case ExerciseKind::Overlap:
                    wrong.numbers = {0, 1};  // the root and its child: one inside the other
                    break;
                case ExerciseKind::SpotBug:
                    wrong.numbers[0] += 1;  // a later step: wrong, but not the first wrong one
                    break;
            }
            EXPECT_FALSE(checkAnswer(ex, log, wrong, Language::En, l.file, &sweep).correct);
        }
    }
}

// The slides' DDA example by hand: o = (0.4, 0.4), d = (0.8, 0.4), cells of 1 x 1.
TEST(Lessons, TheGridLessonsReferencesEqualAHandComputation) {
    const Lesson l = loadLesson("grid-2d-dda");
    const LessonRun run = runLesson(l);
    const auto ref = [&](const char* id) {
        return referenceAnswer(*l.exercise(id), *run.log, l.file);
    };
    EXPECT_NEAR(ref("tdelta-y").numbers[0], 1.0 / 0.4, 1e-15);
    // In (0, 0): tMaxY = (1 - 0.4) / 0.4 = 1.5.
    EXPECT_NEAR(ref("tmax-y-start").numbers[0], 1.5, 1e-15);
    // In (2, 1), after X, Y, X: tMaxX = (3 - 0.4) / 0.8 = 3.25.
    EXPECT_NEAR(ref("tmax-x-after-step").numbers[0], 3.25, 1e-15);
    // In (2, 1): tMaxX = 3.25 < tMaxY = (2 - 0.4) / 0.4 = 4: a step in X, as on the slides.
    EXPECT_EQ(ref("next-cell").numbers, (std::vector<double>{3, 1}));
    // The small circle (4.3, 2.3), r 0.25: (3.88 - sqrt(0.0484)) / 0.8 = 4.575 (see replay_test).
    EXPECT_NEAR(ref("nearest-hit").numbers[0], 4.575, 1e-12);
    std::string why;
    const auto near = parseAnswer(*l.exercise("tdelta-y"), "2,49", &why);  // Italian comma
    ASSERT_TRUE(near) << why;
    EXPECT_TRUE(
        checkAnswer(*l.exercise("tdelta-y"), *run.log, *near, Language::It, l.file).correct);
    EXPECT_FALSE(
        checkAnswer(*l.exercise("tdelta-y"), *run.log, Answer{{1.25}, {}}, Language::En, l.file)
            .correct);
}

// The mailboxing ray (1, 3.6) + t (1, 0.02) stays in row 3, cells x = 1..5. The wall
// y = 3.8, x in [1.2, 5.8] is listed in those five cells: tested once, skipped four times. The
// circle (4.1, 3.25) r 0.2 lies in row 3, cells 3 and 4: tested once, skipped once. The short
// segment (3.7, 3.5)-(3.9, 3.02) lies in cell (3, 3) only. So 5 skips and 3 tests, all misses
// (the ray passes 0.41 from the circle's centre and above the segment's top).
TEST(Lessons, TheMailboxLessonSavesFiveTestsByHand) {
    const Lesson l = loadLesson("mailboxing");
    const LessonRun run = runLesson(l);
    EXPECT_EQ(referenceAnswer(*l.exercise("skips"), *run.log, l.file).numbers[0], 5.0);
    EXPECT_EQ(referenceAnswer(*l.exercise("tests"), *run.log, l.file).numbers[0], 3.0);
}

// The ray (0.4, 0.4) + t (1, 1) meets x = 1 and y = 1 both at t = 0.6: the DDA steps diagonally.
TEST(Lessons, TheRobustnessLessonsTieGoesThroughTheCorner) {
    const Lesson l = loadLesson("robustness");
    const LessonRun run = runLesson(l);
    EXPECT_EQ(referenceAnswer(*l.exercise("tie-cell"), *run.log, l.file).numbers,
              (std::vector<double>{1, 1}));
    EXPECT_NEAR(referenceAnswer(*l.exercise("tie-tmax"), *run.log, l.file).numbers[0], 0.6, 1e-15);
    const Verdict v =
        checkAnswer(*l.exercise("tie-cell"), *run.log, Answer{{1, 0}, {}}, Language::En, l.file);
    EXPECT_FALSE(v.correct);
    EXPECT_NE(v.feedback.find("tie"), std::string::npos) << v.feedback;
}

// Lesson 9's centre ray, by hand: the rule gives 2 cbrt(4 * 30 / 8) = 4.93, so 5 cells of 0.4 per
// axis over [-1, 1]^3. The ray from (0, 0, 3.6) runs almost along -z in the middle column
// (x, y within 0.012 of 0), enters at z = 1 and meets the tall box's face at z = -0.507: the z
// layers 4, 3, 2 and 1, four cells.
TEST(Lessons, TheVoxelSizeLessonsCentreRayWalksFourCellsByHand) {
    const Lesson l = loadLesson("voxel-size");
    const LessonRun run = runLesson(l);
    EXPECT_EQ(referenceAnswer(*l.exercise("cells-walked"), *run.log, l.file).numbers[0], 4.0);
    int cells = 0;
    for (const Event& e : run.log->events()) {
        if (const auto* c = std::get_if<DdaCell>(&e)) {
            EXPECT_EQ(c->cell[0], 2);
            EXPECT_EQ(c->cell[1], 2);
            EXPECT_EQ(c->cell[2], 4 - cells);
            ++cells;
        }
        if (std::holds_alternative<RayHit>(e)) break;
    }
    EXPECT_EQ(cells, 4);
}

// Lesson 9's sweep against a walk written in Python (wt17-ctree-calc/l09_sweep.py: bounding-box
// listing, the DDA, the mailbox, the stop before the cell's far side; Moller-Trumbore, so a ray
// through an edge may count differently): tests and cells per ray agree to 0.003, and the cost
// 1 x cells + 5 x tests is lowest at 8 cells per axis (19.98, against 20.96 at 16 and 26.05 at
// the rule's 5), the answer of the lesson's sweep_pick.
TEST(Lessons, TheVoxelSizeSweepIsCheapestAtEightCellsPerAxis) {
    const Lesson l = loadLesson("voxel-size");
    ASSERT_TRUE(l.sweep.has_value());
    const auto rows = runGridSweep(loadAnyScene(lessonScenePath(l)), *l.sweep);
    struct Hand {
        int res;
        double tests, cells;
    };
    const Hand hand[] = {{1, 25.125, 0.8375},  {2, 11.919375, 1.243958}, {4, 5.688854, 2.348646},
                         {5, 4.631458, 2.895}, {8, 3.069271, 4.633385},  {16, 2.347396, 9.219427}};
    for (const Hand& h : hand) {
        SCOPED_TRACE(h.res);
        const auto row = std::find_if(rows.begin(), rows.end(),
                                      [&](const GridSweepRow& r) { return r.resolution == h.res; });
        ASSERT_NE(row, rows.end());
        EXPECT_NEAR(row->testsPerRay, h.tests, 3e-3);
        EXPECT_NEAR(row->cellsPerRay, h.cells, 3e-3);
    }
    const auto cost = [](const GridSweepRow& r) { return r.cellsPerRay + 5.0 * r.testsPerRay; };
    const auto best = std::min_element(
        rows.begin(), rows.end(),
        [&](const GridSweepRow& a, const GridSweepRow& b) { return cost(a) < cost(b); });
    EXPECT_EQ(best->resolution, 8);
    EXPECT_EQ(referenceAnswer(*l.exercise("cheapest-resolution"), *runLesson(l).log, l.file, &rows)
                  .numbers,
              (std::vector<double>{8}));
}

// Lesson 10's midpoint tree by hand: the ray (0.2, 7.6) + t (1, -0.55) is in the root box
// [0.5, 7.69] x [0.5, 7.5] for t in [0.3, 7.49] (x slab [0.3, 7.49], y slab [0.18, 12.9]). The
// root is cut at x = 4.095 (t = 3.895): leaf 1, then node 2, cut at y = 4 (t = 6.545); the origin
// is above, so leaf 14 [3.895, 6.545] comes first and holds the segment (4.2, 3.6)-(4.6, 5.4), met
// at t = 440/101 = 4.356: node 3 is skipped. The first test, circle (1.5, 6) r 0.5, is a miss
// (the line passes 0.775 from its centre).
TEST(Lessons, TheHierarchiesLessonsTestTreeEntersFourNodesByHand) {
    const Lesson l = loadLesson("hierarchies");
    const LessonRun run = runLesson(l);
    std::vector<std::uint32_t> entered;
    for (const Event& e : run.log->events())
        if (const auto* n = std::get_if<NodeEnter>(&e)) {
            if (entered.empty()) {
                EXPECT_NEAR(n->tNear, 0.3, 1e-12);
                EXPECT_NEAR(n->tFar, 7.49, 1e-12);
            }
            entered.push_back(n->node);
        }
    EXPECT_EQ(entered, (std::vector<std::uint32_t>{0, 1, 2, 14}));
    EXPECT_EQ(referenceAnswer(*l.exercise("nodes-in-order"), *run.log, l.file).numbers,
              (std::vector<double>{0, 1, 2, 14}));
    // The box [1.2, 7.2] x [5.5, 7.5] over the top of the scene (no node of the lesson's trees:
    // its exit is in no trace the student replays): the x slab [1, 7], the y slab
    // [(7.5 - 7.6) / -0.55, (5.5 - 7.6) / -0.55] = [2/11, 42/11]; the exit is 42/11 = 3.8181...,
    // the entry 1.
    EXPECT_NEAR(referenceAnswer(*l.exercise("box-exit"), *run.log, l.file).numbers[0], 42.0 / 11.0,
                1e-12);
    const Answer first = referenceAnswer(*l.exercise("first-leaf-test"), *run.log, l.file);
    ASSERT_TRUE(first.hit.has_value());
    EXPECT_FALSE(*first.hit);
}

// Lesson 11's numbers by hand (fractions): the root box [0.5, 7.69] x [0.5, 7.5] has perimeter
// 28.38; the plane x = 2.0 leaves a left cell 1.5 x 7, P(L|C) = 17 / 28.38 = 850/1419; the
// midpoint x = 4.095 (N_L 4, N_R 12) gives two halves 3.595 x 7, P = 2119/2838 each, cost
// 1 + 5 x 16 x 2119/2838 = 86179/1419 = 60.73; the SAH's best is y = 2.96 (N_L 11, N_R 4), cost
// 77954/1419 = 54.94, below the leaf's 75.
TEST(Lessons, TheKdTreeLessonsCandidatesEqualAHandComputation) {
    const Lesson l = loadLesson("building-kdtree");
    const LessonRun run = runLesson(l);
    bool sawX2 = false, sawBest = false;
    for (const Event& e : run.log->events()) {
        const auto* c = std::get_if<SplitCandidate>(&e);
        if (!c || c->node != 0) continue;
        if (c->axis == 0 && c->position == 2.0) {
            sawX2 = true;
            EXPECT_EQ(c->nl, 3u);
            EXPECT_EQ(c->nr, 14u);
            EXPECT_NEAR(c->pl, 850.0 / 1419.0, 1e-12);
        }
        if (c->axis == 1 && std::abs(c->position - 2.96) < 1e-12) {
            sawBest = true;
            EXPECT_EQ(c->nl, 11u);
            EXPECT_EQ(c->nr, 4u);
            EXPECT_NEAR(c->sahCost, 77954.0 / 1419.0, 1e-9);
        }
    }
    EXPECT_TRUE(sawX2);
    EXPECT_TRUE(sawBest);
    const double p = 2119.0 / 2838.0;
    EXPECT_NEAR(sahCost(1.0, 5.0, 0.5, p, p, 4, 12), 86179.0 / 1419.0, 1e-9);
    // The compute exercises: x = 1.5's P(L|C) (a cell 1 x 7: 16 / 28.38), the midpoint's and the
    // median's costs (x = 6.4, N_L 9, N_R 10: cells 5.9 x 7 and 1.29 x 7, 1 + 5 (9 x 10/11 + 10 x
    // 829/1419) = 100919/1419).
    const auto ref = [&](const char* id) {
        return referenceAnswer(*l.exercise(id), *run.log, l.file).numbers[0];
    };
    EXPECT_NEAR(ref("area-ratio"), 800.0 / 1419.0, 1e-12);
    EXPECT_NEAR(ref("midpoint-cost"), 86179.0 / 1419.0, 1e-9);
    EXPECT_NEAR(ref("median-cost"), 100919.0 / 1419.0, 1e-9);
}

TEST(Lessons, PickSplitFeedbackRecomputesTheWinnersCost) {
    const Lesson l = loadLesson("building-kdtree");
    const LessonRun run = runLesson(l);
    const Exercise& ex = *l.exercise("root-split");
    const auto candidates = splitCandidates(ex, *run.log);
    ASSERT_GT(candidates.size(), 4u);
    // The cheapest by a scan written here, and its cost by the slides' formula.
    const SplitCandidate* best = &candidates[0];
    for (const SplitCandidate& c : candidates)
        if (c.sahCost < best->sahCost) best = &c;
    const Answer ref = referenceAnswer(ex, *run.log, l.file);
    EXPECT_EQ(ref.numbers[0], best->axis);
    EXPECT_EQ(ref.numbers[1], best->position);
    const double bonus = (best->nl == 0 || best->nr == 0) ? 0.5 : 1.0;
    EXPECT_NEAR(best->sahCost, bonus * (1.0 + 5.0 * (best->pl * best->nl + best->pr * best->nr)),
                1e-12);
}

TEST(Lessons, AnswersAreParsedAsTyped) {
    Exercise cell;
    cell.kind = ExerciseKind::NextCell;
    std::string why;
    EXPECT_EQ(parseAnswer(cell, "(2, 1)", &why)->numbers, (std::vector<double>{2, 1}));
    EXPECT_EQ(parseAnswer(cell, "3,2,3", &why)->numbers, (std::vector<double>{3, 2, 3}));
    EXPECT_FALSE(parseAnswer(cell, "2.5,1", &why));
    EXPECT_FALSE(parseAnswer(cell, "2", &why));
    Exercise value;
    value.kind = ExerciseKind::Value;
    EXPECT_EQ(parseAnswer(value, " 0.75 ", &why)->numbers[0], 0.75);
    for (const char* bad : {"nan", "inf", "1e999", "", "abc", "1.2.3"})
        EXPECT_FALSE(parseAnswer(value, bad, &why)) << bad;
    Exercise count;
    count.kind = ExerciseKind::Count;
    EXPECT_FALSE(parseAnswer(count, "-1", &why));
    EXPECT_FALSE(parseAnswer(count, "2.5", &why));
    Exercise split;
    split.kind = ExerciseKind::PickSplit;
    EXPECT_EQ(parseAnswer(split, "Y = 2.96", &why)->numbers, (std::vector<double>{1, 2.96}));
    EXPECT_FALSE(parseAnswer(split, "w=1", &why));
    EXPECT_FALSE(parseAnswer(split, "2.96", &why));
    Exercise hit;
    hit.kind = ExerciseKind::HitOrMiss;
    hit.withT = true;
    EXPECT_EQ(*parseAnswer(hit, "miss", &why)->hit, false);
    const auto h = parseAnswer(hit, "hit t=3.5", &why);
    ASSERT_TRUE(h);
    EXPECT_EQ(*h->hit, true);
    EXPECT_EQ(h->numbers[0], 3.5);
    EXPECT_FALSE(parseAnswer(hit, "hit", &why)) << "the t is asked";
    EXPECT_FALSE(parseAnswer(hit, "maybe", &why));
}

TEST(Lessons, ABadLessonFileNamesLineAndKey) {
    EXPECT_NO_THROW(loadLessonText(lessonWith(""), "ok.json"));
    expectLessonError(lessonWith(",\n\"colour\": 1"), 11, "colour", "unknown key");
    expectLessonError(
        lessonWith(
            ",\n\"steps\": [{\"text\": {\"en\": \"a\"},\n \"at\": {\"after\": \"dda_walk\"}}]"),
        12, "steps[0].at.after", "unknown event kind");
    expectLessonError(lessonWith(",\n\"exercises\": [\n{\"id\": \"a\", \"type\": \"count\", "
                                 "\"count\": \"dda_cell\", \"prompt\": {\"en\": \"?\"}},\n"
                                 "{\"id\": \"a\", \"type\": \"count\", \"count\": \"dda_cell\", "
                                 "\"prompt\": {\"en\": \"?\"}}]"),
                      13, "exercises[1].id", "used twice");
    expectLessonError(
        lessonWith(
            ",\n\"exercises\": [{\"id\": \"a\", \"type\": \"value\", \"quantity\": \"tMax.x\",\n"
            "\"tolerance\": 1.5, \"prompt\": {\"en\": \"?\"}}]"),
        12, "exercises[0].tolerance", "accepts anything");
    expectLessonError(lessonWith(",\n\"exercises\": [{\"id\": \"a\", \"type\": \"guess\", "
                                 "\"prompt\": {\"en\": \"?\"}}]"),
                      11, "exercises[0].type", "expected next_cell");
    expectLessonError(lessonWith(",\n\"sweep\": {\"grid_res\": [4, NaN]}"), 11, "",
                      "malformed JSON");
    expectLessonError(lessonWith(",\n\"setup\": {\"accel\": \"octree\"}"), 11, "setup",
                      "given twice");
    // Grids past the cap of 2^24 cells (each axis alone within its limit): refused, not allocated.
    std::string big = lessonWith("");
    big.replace(big.find("{\"accel\": \"grid\"}"), 17,
                "{\"accel\": \"grid\", \"grid_res\": [512, 512, 512]}");
    expectLessonError(big, 9, "setup.grid_res", "more than the grid's 16777216");
    expectLessonError(lessonWith(",\n\"sweep\": {\"grid_res\": [4, 300]}"), 11, "sweep.grid_res[1]",
                      "256");
    expectLessonError(
        "{\"format\": \"raystep-lesson\", \"version\": 1, \"id\": \"t\", \"number\": 1,\n"
        "\"title\": {\"it\": \"Titolo\"}, \"text\": {\"en\": \"x\"}, \"scene\": \"s\", \"trace\": "
        "{\"build\": true}}",
        2, "title", "English text");
    expectLessonError("{\"format\": \"raystep-lesson\", \"version\": 2}", 1, "version",
                      "version 1");
}

TEST(Lessons, TheSetupReadsTheStructureTablesLimits) {
    // setup's keys, limits and structures are the table's (structure_info.h), as the CLI's.
    const auto withSetup = [](const std::string& setup) {
        std::string text = lessonWith("");
        text.replace(text.find("{\"accel\": \"grid\"}"), 17, setup);
        return text;
    };
    expectLessonError(withSetup("{\"accel\": \"kdtree\", \"max_depth\": 61}"), 9, "setup.max_depth",
                      "must be from 1 to 60, got 61");
    expectLessonError(withSetup("{\"accel\": \"bvh\", \"c_isect\": 0}"), 9, "setup.c_isect",
                      "must be greater than 0");
    expectLessonError(withSetup("{\"accel\": \"bvh\", \"buckets\": 1.5}"), 9, "setup.buckets",
                      "expected a whole number");
    expectLessonError(withSetup("{\"accel\": \"octree\"}"), 9, "setup.accel",
                      "expected bruteforce, grid, kdtree or bvh");
    expectLessonError(withSetup("{\"accel\": \"grid\", \"depth\": 3}"), 9, "setup.depth",
                      "bin_above, kd_build)");
    const Lesson l =
        loadLessonText(withSetup("{\"accel\": \"kdtree\", \"kd_build\": \"fast\", \"c_isect\": 20, "
                                 "\"leaf_size\": 2}"),
                       "ok.json");
    EXPECT_EQ(l.accel, AccelKind::KdTree);
    EXPECT_EQ(l.options.kdtree.build, KdBuild::Fast);
    EXPECT_EQ(l.options.kdtree.cIsect, 20.0);
    EXPECT_EQ(l.options.bvh.cIsect, 20.0);
    EXPECT_EQ(l.options.kdtree.leafSize, 2);
}

TEST(Lessons, TheRobustnessLessonSetsTheSlidesLoopBesideTheExactWalk) {
    Lesson l = loadLesson("robustness");
    const LessonRun run = runLesson(l);
    addStepNotes(l, *run.scene, run.accel2D ? &*run.accel2D : nullptr);
    const LessonStep* noted = nullptr;
    for (const LessonStep& s : l.steps)
        if (s.textbookDda) noted = &s;
    ASSERT_NE(noted, nullptr);
    // By hand: (0.4, 0.4) + t (1, 1) over unit cells meets a vertex at every cell. The slides'
    // loop finds tMaxX < tMaxY false at each tie and steps Y alone, then X; the exact walk steps
    // both axes at once.
    const std::string& en = noted->note.en;
    EXPECT_NE(en.find("through (0, 0) (0, 1) (1, 1) (1, 2) (2, 2)"), std::string::npos) << en;
    EXPECT_NE(en.find("the exact walk through (0, 0) (1, 1) (2, 2)"), std::string::npos) << en;
    EXPECT_NE(en.find("They part at cell 2: the loop enters (0, 1), the exact walk (1, 1)."),
              std::string::npos)
        << en;
    EXPECT_NE(noted->note.in(Language::It).find("Si separano alla cella 2"), std::string::npos)
        << noted->note.in(Language::It);
    // Only a 2D ray through a grid has such a walk: validation names the step that asks anyway.
    Lesson pixel = loadLesson("1");
    pixel.steps.at(0).textbookDda = true;
    try {
        validateLesson(pixel);
        ADD_FAILURE() << "a 3D lesson's textbook_dda step was accepted";
    } catch (const LessonError& e) {
        EXPECT_NE(std::string(e.what()).find("steps[0].textbook_dda"), std::string::npos)
            << e.what();
    }
    expectLessonError(
        lessonWith(",\n\"steps\": [{\"text\": {\"en\": \"a\"}, \"textbook_dda\": 1}]"), 11,
        "steps[0].textbook_dda", "expected true or false");
}

TEST(Lessons, AnAnswerSheetIsGradedAndItsMistakesNamed) {
    const Lesson l = loadLesson("6");
    const LessonRun run = runLesson(l);
    const AnswerSheet sheet = loadAnswerSheet(
        "{\"lesson\": \"grid-2d-dda\",\n \"answers\": {\n  \"tdelta-y\": 2.5,\n"
        "  \"next-cell\": [2, 2]\n }}",
        "answers.json");
    const Grade g = gradeAnswers(l, run.logs(), sheet, Language::En, "answers.json");
    EXPECT_EQ(g.score, 1);
    ASSERT_EQ(g.items.size(), l.exercises.size());
    EXPECT_TRUE(g.items[0].correct);
    EXPECT_FALSE(g.items[1].answered);
    EXPECT_TRUE(g.items[3].answered);  // next-cell: (3, 1) by hand, see above
    EXPECT_FALSE(g.items[3].correct);
    EXPECT_EQ(g.items[3].expected, "3,1");
    try {
        gradeAnswers(l, run.logs(),
                     loadAnswerSheet("{\"lesson\": \"6\",\n\"answers\": {\"x\": 1}}", "a.json"),
                     Language::En, "a.json");
        ADD_FAILURE();
    } catch (const LessonError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.key(), "answers.x");
    }
    EXPECT_THROW(
        gradeAnswers(l, *run.log, loadAnswerSheet("{\"lesson\": \"7\", \"answers\": {}}", "a.json"),
                     Language::En, "a.json"),
        LessonError);
    EXPECT_THROW(loadAnswerSheet("{\"lesson\": \"6\", \"answers\": {\"a\": {}}}", "a.json"),
                 LessonError);
}

// Two windows of the app answer different exercises and each saves: what the other saved is
// folded in, so neither loses an answer.
TEST(Lessons, MergingProgressKeepsEveryAnswer) {
    Progress a, b;
    a.lessons["grid-2d-dda"].step = 2;
    a.lessons["grid-2d-dda"].exercises["next-cell"] = {false, 1, "3,1"};
    a.lessons["grid-2d-dda"].exercises["tdelta-y"] = {true, 2, "1.333"};
    b.lessons["grid-2d-dda"].step = 0;
    b.lessons["grid-2d-dda"].exercises["next-cell"] = {true, 3, "2,2"};
    b.lessons["grid-2d-dda"].exercises["tmax-x"] = {false, 1, "0.6"};
    b.lessons["mailboxing"].exercises["skips"] = {true, 1, "5"};
    const LessonProgress::ExerciseRecord* kept = &a.lessons["grid-2d-dda"].exercises["tdelta-y"];
    mergeProgress(a, b);
    const auto& dda = a.lessons.at("grid-2d-dda");
    EXPECT_EQ(dda.step, 2);  // this window's own step
    ASSERT_EQ(dda.exercises.size(), 3u);
    EXPECT_TRUE(dda.exercises.at("next-cell").correct);
    EXPECT_EQ(dda.exercises.at("next-cell").attempts, 3);
    EXPECT_EQ(dda.exercises.at("next-cell").answer, "2,2");
    EXPECT_TRUE(dda.exercises.at("tdelta-y").correct);
    EXPECT_EQ(dda.exercises.at("tdelta-y").attempts, 2);
    EXPECT_EQ(dda.exercises.at("tmax-x").answer, "0.6");
    EXPECT_TRUE(a.lessons.at("mailboxing").exercises.at("skips").correct);
    EXPECT_EQ(&dda.exercises.at("tdelta-y"), kept);  // the panel's pointers stay valid
    // A right answer is never undone by a run that got it wrong more often.
    Progress c;
    c.lessons["grid-2d-dda"].exercises["tdelta-y"] = {false, 5, "2"};
    mergeProgress(a, c);
    EXPECT_TRUE(a.lessons.at("grid-2d-dda").exercises.at("tdelta-y").correct);
    EXPECT_EQ(a.lessons.at("grid-2d-dda").exercises.at("tdelta-y").attempts, 5);
}

TEST(Lessons, ProgressRoundTripsAndABadFileIsNamed) {
    Progress p;
    p.lessons["grid-2d-dda"].step = 2;
    p.lessons["grid-2d-dda"].exercises["next-cell"] = {true, 3, "2,2"};
    p.lessons["mailboxing"].exercises["skips"] = {false, 1, "4"};
    const Progress back = parseProgress(progressToJson(p), "progress.json");
    ASSERT_EQ(back.lessons.size(), 2u);
    EXPECT_EQ(back.lessons.at("grid-2d-dda").step, 2);
    const auto& rec = back.lessons.at("grid-2d-dda").exercises.at("next-cell");
    EXPECT_TRUE(rec.correct);
    EXPECT_EQ(rec.attempts, 3);
    EXPECT_EQ(rec.answer, "2,2");
    const std::string report = progressReport(back, builtinLessons(), Language::En);
    // Each row: the lesson's exercises, then done, right, attempts from p.
    const auto exercises = [](const char* id) {
        return std::to_string(loadLesson(id).exercises.size());
    };
    EXPECT_NE(report.find("| 6. The uniform grid and the 2D DDA, step by step | " + exercises("6") +
                          " | 1 | 1 | 3 |"),
              std::string::npos)
        << report;
    EXPECT_NE(report.find("| 8. Mailboxing | " + exercises("8") + " | 1 | 0 | 1 |"),
              std::string::npos)
        << report;
    try {
        parseProgress("{\"format\": \"raystep-progress\",\n \"lessons\": {\"a\": {\"step\": -1}}}",
                      "p.json");
        ADD_FAILURE();
    } catch (const LessonError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.key(), "lessons.a.step");
    }
}

TEST(Lessons, NoAttemptCountsOnceAnExerciseIsSolved) {
    LessonProgress l;
    EXPECT_FALSE(recordAnswer(l, "next-cell", "2,2", false));
    EXPECT_FALSE(recordAnswer(l, "next-cell", "3,1", true));
    // Solved: a wrong click afterwards is neither an attempt nor the answer kept.
    EXPECT_TRUE(recordAnswer(l, "next-cell", "4,1", false));
    EXPECT_TRUE(recordAnswer(l, "next-cell", "3,1", true));
    const auto& rec = l.exercises.at("next-cell");
    EXPECT_TRUE(rec.correct);
    EXPECT_EQ(rec.attempts, 2);
    EXPECT_EQ(rec.answer, "3,1");
    // Not yet solved: every answer counts and the last one is kept.
    recordAnswer(l, "tdelta-y", "2.4", false);
    recordAnswer(l, "tdelta-y", "2.6", false);
    EXPECT_EQ(l.exercises.at("tdelta-y").attempts, 2);
    EXPECT_EQ(l.exercises.at("tdelta-y").answer, "2.6");
    EXPECT_FALSE(l.exercises.at("tdelta-y").correct);
}

TEST(Lessons, TheProgressReportNamesTheStudentTheDateAndEachExercise) {
    Progress p;
    LessonProgress& l6 = p.lessons["grid-2d-dda"];
    recordAnswer(l6, "next-cell", "2,2", false);
    recordAnswer(l6, "next-cell", "3,1", true);
    recordAnswer(l6, "next-cell", "9,9", false);  // after solving: not counted
    recordAnswer(l6, "tdelta-y", "2|5", false);   // a student's '|' cannot break the table
    const std::string en =
        progressReport(p, builtinLessons(), Language::En, {"Ada Lovelace", "2025-03-14"});
    EXPECT_NE(en.find("Student: Ada Lovelace"), std::string::npos) << en;
    EXPECT_NE(en.find("Date: 2025-03-14"), std::string::npos) << en;
    // The summary row: 2 done, 1 right, 2 + 1 = 3 attempts.
    EXPECT_NE(en.find(" | 2 | 1 | 3 |"), std::string::npos) << en;
    EXPECT_NE(en.find("## 6. The uniform grid and the 2D DDA, step by step"), std::string::npos);
    EXPECT_NE(en.find("| 4. next-cell | solved | 2 | 3,1 |"), std::string::npos) << en;
    EXPECT_NE(en.find("| 1. tdelta-y | not solved yet | 1 | 2\\|5 |"), std::string::npos) << en;
    EXPECT_NE(en.find("| 2. tmax-y-start | not attempted |  |  |"), std::string::npos) << en;
    // Lessons not worked on have no section.
    EXPECT_EQ(en.find("## 8."), std::string::npos);
    const std::string it =
        progressReport(p, builtinLessons(), Language::It, {"Ada Lovelace", "2025-03-14"});
    EXPECT_NE(it.find("Studente: Ada Lovelace"), std::string::npos) << it;
    EXPECT_NE(it.find("| 4. next-cell | risolto | 2 | 3,1 |"), std::string::npos) << it;
}

// One cell holds every primitive: each ray of the fan (all start inside the grid) walks that one
// cell and tests all 13 primitives (5 circles, 8 segments); 8 x 8 cells test fewer and walk more.
TEST(Lessons, TheGridSweepAtOneCellTestsEverything) {
    const auto scene = loadAnyScene("lecture-grid");
    GridSweepSpec spec;
    spec.resolutions = {1, 8};
    spec.width = 16;
    spec.height = 16;
    double last = -1.0;
    const auto rows = runGridSweep(scene, spec, [&](double f) {
        EXPECT_GE(f, last);
        last = f;
        return true;
    });
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(last, 1.0);
    EXPECT_EQ(rows[0].cells, 1u);
    EXPECT_EQ(rows[0].testsPerRay, 13.0);
    EXPECT_EQ(rows[0].cellsPerRay, 1.0);
    EXPECT_EQ(rows[1].cells, 64u);
    EXPECT_LT(rows[1].testsPerRay, rows[0].testsPerRay);
    EXPECT_GT(rows[1].cellsPerRay, rows[0].cellsPerRay);
    EXPECT_THROW(runGridSweep(scene, spec, [](double) { return false; }), BuildCancelled);
}

}  // namespace
}  // namespace raystep
