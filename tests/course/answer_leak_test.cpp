// Validate's giveaway check (course/answer_leaks.h): a lesson made to fail in each form an answer
// can take in a text, and the near misses that must pass. The answers are the lecture grid's
// example ray, (0.4, 0.4) + t (0.8, 0.4) on cells of 1 x 1, worked by hand: the walk (0,0) (1,0)
// (1,1) (2,1) (3,1) (3,2) (4,2); tMaxX in (2,1) = (3 - 0.4) / 0.8 = 3.25; the circle (4.3, 2.3)
// r 0.25 hit at (3.88 - sqrt(3.88^2 - 0.8 * 18.7575)) / 0.8 = (3.88 - 0.22) / 0.8 = 4.575; the
// first test, segment 11 (the bottom border, (0,0)-(6,0)), misses; the long segment 6 is hit at
// t = 345/64 = 5.390625. The kd-tree scene's SAH root plane is y = 2.96 and its midpoint tree's
// TestTree order 0 1 2 14 (lessons.md, Appendix A, recomputed there).
#include "course/answer_leaks.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include <gtest/gtest.h>

#include <string>

namespace raystep {
namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// A lesson over `scene` with `setup` and `trace`, its `text` (en, it), one step at `stepAt`
/// with `stepText`, and the exercises `exercises` (JSON array items).
std::string lessonJson(const std::string& scene, const std::string& setup, const std::string& trace,
                       const std::string& textEn, const std::string& textIt,
                       const std::string& exercises, const std::string& steps = "") {
    return "{\"format\": \"raystep-lesson\", \"version\": 1, \"id\": \"t\", \"number\": 1,\n"
           "\"title\": {\"en\": \"T\"},\n\"text\": {\"en\": \"" +
           textEn + "\", \"it\": \"" + textIt + "\"},\n\"scene\": \"" + scene +
           "\",\n\"setup\": " + setup + ",\n\"trace\": " + trace +
           (steps.empty() ? "" : ",\n\"steps\": [" + steps + "]") + ",\n\"exercises\": [" +
           exercises + "]\n}";
}

/// The message of validate's giveaway check on `json`, or "" when it passes.
std::string giveaway(const std::string& json) {
    const Lesson l = loadLessonText(json, "leak.json");
    const LessonRun run = runLesson(l);
    try {
        checkNoAnswerGivenAway(l, run.logs(), run.scene.get());
    } catch (const LessonError& e) {
        EXPECT_EQ(e.file(), "leak.json");
        return e.what();
    }
    return "";
}

const std::string kGrid = "lecture-grid";
const std::string kGridSetup = "{\"accel\": \"grid\"}";
const std::string kExampleRay = "{\"ray\": \"example\"}";

/// An exercise of `type` with `keys` at `at`, whose prompt is `promptEn` / `promptIt`.
std::string exercise(const std::string& id, const std::string& typeAndKeys, const std::string& at,
                     const std::string& promptEn = "?", const std::string& promptIt = "?") {
    return "{\"id\": \"" + id + "\", " + typeAndKeys + ", \"at\": " + at +
           ", \"prompt\": {\"en\": \"" + promptEn + "\", \"it\": \"" + promptIt +
           "\"}, \"hint\": {\"en\": \"h\", \"it\": \"h\"}}";
}

const std::string kNextCell =
    exercise("next", "\"type\": \"next_cell\"", "{\"before\": \"dda_cell\", \"nth\": 5}");

/// Lesson 6's next cell (3, 1) with a second exercise whose prompt is `en` / `it`.
std::string nextCellAnd(const std::string& en, const std::string& it = "?") {
    return lessonJson(
        kGrid, kGridSetup, kExampleRay, "x", "x",
        kNextCell + ",\n" +
            exercise("later", "\"type\": \"count\", \"count\": \"dda_cell\"", "\"end\"", en, it));
}

TEST(AnswerLeaks, ACellInAnyForm) {
    for (const std::string form : {"The ray is in (3, 1).", "The ray is in (3,1).", "From 3, 1 on.",
                                   "From 3,1 on.", "Now X = 3, Y = 1.", "Now X = 3 and Y = 1."}) {
        const std::string why = giveaway(nextCellAnd(form));
        EXPECT_TRUE(has(why, "exercises[0]")) << form << ": " << why;
        EXPECT_TRUE(has(why, "exercises[1].prompt.en")) << form << ": " << why;
    }
    // In Italian: the tuple with a semicolon, and X = 3 e Y = 1.
    for (const std::string form : {"Il raggio è in (3; 1).", "Ora X = 3 e Y = 1."})
        EXPECT_TRUE(has(giveaway(nextCellAnd("?", form)), "exercises[1].prompt.it")) << form;
    // Not the cell: other numbers, a decimal, a lower-case line, the ray's direction, 3D.
    for (const std::string form :
         {"The ray is in (1, 3).", "At (3.5, 1).", "The line x = 3, y = 1.", "o + t (3, 1)",
          "d = (3, 1)", "(3, 1, 0)", "31 cells", "3 cells, 1 ray"})
        EXPECT_EQ(giveaway(nextCellAnd(form)), "") << form;
}

TEST(AnswerLeaks, AWalksCellsInOrder) {
    // After (3, 1): (3, 2) then (4, 2), the cells in order, others between them or not.
    const auto walk = [](const std::string& stepText) {
        return lessonJson(kGrid, kGridSetup, kExampleRay, "x", "x",
                          exercise("walk", "\"type\": \"sequence\", \"of\": \"dda_cell\"",
                                   "{\"after\": \"dda_cell\", \"nth\": 5}"),
                          "{\"text\": {\"en\": \"" + stepText +
                              "\"}, \"at\": {\"after\": \"dda_cell\", " + "\"nth\": 5}}");
    };
    EXPECT_TRUE(has(giveaway(walk("It goes to (3, 2) and then to (4, 2).")), "steps[0].text.en"));
    EXPECT_TRUE(has(giveaway(walk("Cells 3,2; 5,0; 4,2.")), "as \"3,2; 5,0; 4,2\""));
    // One of them, or both the other way round, is not the walk.
    EXPECT_EQ(giveaway(walk("In (3, 2) the segment lies.")), "");
    EXPECT_EQ(giveaway(walk("From (4, 2) back to (3, 2).")), "");
}

TEST(AnswerLeaks, ANumberAsATextPrintsIt) {
    // The circle's hit at t = 4.575 (tolerance 0.01: 4.529 to 4.621 is graded right).
    const auto hitIn = [](const std::string& en, const std::string& it) {
        return lessonJson(kGrid, kGridSetup, kExampleRay, en, it,
                          exercise("near", "\"type\": \"value\", \"quantity\": \"hit.t\"",
                                   "{\"after\": \"primitive_test\", \"nth\": 5}"));
    };
    for (const std::string form : {"t = 4.575", "about 4.58", "4.57 or so", "t ≈ 4.6", "4,575"})
        EXPECT_TRUE(has(giveaway(hitIn(form, "x")), "text.en")) << form;
    // The Italian text, with its decimal comma and with a point (a code span).
    EXPECT_TRUE(has(giveaway(hitIn("x", "circa 4,58")), "text.it as \"4,58\""));
    EXPECT_TRUE(has(giveaway(hitIn("x", "`t = 4.575`")), "text.it"));
    // Other numbers: 4.5 and 4.7 are graded wrong, 14.575 and 45.75 are not it, 4575 neither.
    for (const std::string form : {"4.5", "4.7", "14.575", "45.75", "4575", "-4.575", "x4.575"})
        EXPECT_EQ(giveaway(hitIn(form, "x")), "") << form;
}

TEST(AnswerLeaks, OnlyTheStepsAtOrBeforeThePositionAndTheExplanationsBefore) {
    // tMaxX in (2, 1) = 3.25, asked before the 4th cell: a step there shows; one after it waits.
    const std::string tmax = exercise("tmax", "\"type\": \"value\", \"quantity\": \"tMax.x\"",
                                      "{\"before\": \"dda_cell\", \"nth\": 4}");
    const auto stepAt = [&](const std::string& at) {
        return lessonJson(kGrid, kGridSetup, kExampleRay, "x", "x", tmax,
                          "{\"text\": {\"en\": \"tMaxX = 3.25\"}, \"at\": " + at + "}");
    };
    EXPECT_TRUE(has(giveaway(stepAt("{\"after\": \"dda_cell\", \"nth\": 3}")), "steps[0].text"));
    EXPECT_EQ(giveaway(stepAt("{\"after\": \"dda_cell\", \"nth\": 4}")), "");
    // The next cell's explanation ("In cell (2, 1) the DDA compares tMaxX = 3.25, ..."), shown
    // once that exercise is answered, gives the tMax of an exercise after it, not of one before.
    const std::string nextThenTmax =
        lessonJson(kGrid, kGridSetup, kExampleRay, "x", "x", kNextCell + ",\n" + tmax);
    EXPECT_TRUE(has(giveaway(nextThenTmax), "exercises[0]'s explanation"))
        << giveaway(nextThenTmax);
    EXPECT_EQ(
        giveaway(lessonJson(kGrid, kGridSetup, kExampleRay, "x", "x", tmax + ",\n" + kNextCell)),
        "");
}

TEST(AnswerLeaks, AnOutcomeNamedWithItsPrimitive) {
    // The first test: segment 11 (a primitive of 13: circles 0 to 4, segments 5 to 12) misses.
    const std::string miss = exercise("first", "\"type\": \"hit_or_miss\"",
                                      "{\"before\": \"primitive_test\", \"nth\": 1}");
    const auto with = [&](const std::string& text, const std::string& otherPrompt,
                          const std::string& otherIt = "?") {
        return lessonJson(kGrid, kGridSetup, kExampleRay, text, "x",
                          miss + ",\n" +
                              exercise("later", "\"type\": \"count\", \"count\": \"dda_cell\"",
                                       "\"end\"", otherPrompt, otherIt));
    };
    EXPECT_TRUE(has(giveaway(with("The ray misses segment 11.", "?")), "text.en"));
    EXPECT_TRUE(has(giveaway(with("Primitive 11 is missed.", "?")), "text.en"));
    EXPECT_TRUE(
        has(giveaway(with("x", "?", "Il raggio manca il segmento 11.")), "exercises[1].prompt.it"));
    // An exercise's text is about its primitive: "the segment" names it there.
    EXPECT_TRUE(has(giveaway(with("x", "Once the ray misses the segment, how many cells?")),
                    "exercises[1].prompt.en"));
    // A question of another kind takes the outcome as known.
    EXPECT_TRUE(has(giveaway(with("x", "How many cells after the miss on segment 11?")),
                    "exercises[1].prompt.en"));
    // Prose on segments in general, another segment, a yes-or-no question, no outcome word.
    for (const auto& [text, other] : std::initializer_list<std::pair<std::string, std::string>>{
             {"A ray misses a segment when s < 0.", "?"},
             {"The ray misses segment 12.", "?"},
             {"x", "Does the ray hit segment 11?"},
             {"Segment 11 is the bottom border.", "?"}})
        EXPECT_EQ(giveaway(with(text, other)), "") << text << " / " << other;
}

TEST(AnswerLeaks, AHitsTWithIt) {
    // The long segment 6 is hit at t = 345/64 = 5.390625: "hit 5.39" gives both.
    const std::string hit = exercise("hit", "\"type\": \"hit_or_miss\", \"with_t\": true",
                                     "{\"before\": \"primitive_test\", \"nth\": 5}");
    const auto in = [&](const std::string& text) {
        return giveaway(lessonJson(kGrid, kGridSetup, kExampleRay, text, "x", hit));
    };
    EXPECT_TRUE(has(in("The segment is crossed at t = 5.39."), "as \"5.39\""));
    EXPECT_TRUE(has(in("Segment 6 is hit."), "a hit on primitive 6"));
    EXPECT_EQ(in("The segment is crossed at t = 5.2."), "");
}

TEST(AnswerLeaks, ASplitsPlane) {
    const auto pick = [](const std::string& text) {
        return giveaway(lessonJson("lecture-kdtree", "{\"accel\": \"kdtree\", \"split\": \"sah\"}",
                                   "{\"build\": true}", text, "x",
                                   exercise("root", "\"type\": \"pick_split\"", "\"start\"")));
    };
    for (const std::string form : {"the plane y = 2.96", "y=2,96", "cut at y = 2.960"})
        EXPECT_TRUE(has(pick(form), "text.en")) << form;
    for (const std::string form : {"x = 2.96", "y = 3.5", "y = 3", "tMaxy = 2.96"})
        EXPECT_EQ(pick(form), "") << form;
}

TEST(AnswerLeaks, TestTreesNodeOrder) {
    const auto order = [](const std::string& text) {
        return giveaway(lessonJson(
            "lecture-kdtree", "{\"accel\": \"kdtree\", \"split\": \"midpoint\"}", kExampleRay, text,
            "x", exercise("nodes", "\"type\": \"sequence\", \"of\": \"node_enter\"", "\"start\"")));
    };
    for (const std::string form : {"It enters 0 1 2 14.", "nodes 0, 1, 2 and 14", "0 → 1 → 2 → 14"})
        EXPECT_TRUE(has(order(form), "text.en")) << form;
    // The tree described node by node is the data, not the order.
    EXPECT_EQ(order("The root 0 is cut into the leaf 1 and node 2; node 2 into node 3 and the "
                    "leaf 14."),
              "");
}

TEST(AnswerLeaks, ASweepsResolution) {
    AnswerForms eight;
    eight.resolution = 8;
    EXPECT_TRUE(findAnswer(eight, "a grid of 8 x 8 x 8 cells").has_value());
    EXPECT_TRUE(findAnswer(eight, "8 cells per axis").has_value());
    EXPECT_TRUE(findAnswer(eight, "con 8 celle per asse").has_value());
    EXPECT_FALSE(findAnswer(eight, "5 x 5 x 5 cells, 8 tests").has_value());
}

}  // namespace
}  // namespace raystep
