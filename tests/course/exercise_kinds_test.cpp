// The exercise kinds of issue 17 (choice, sequence, sweep_pick, compute), feedback that names the
// slip a student's number betrays, Italian answers and messages, and quiz mode's checks. Every
// reference value below is computed by hand (the comments show how) or in Python, never read
// from raystep.
#include "lesson_test_util.h"

#include "course/compute.h"
#include "course/exercise.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include "raystep/trace/replay.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace raystep {
namespace {

using test::expectLessonError;

// A lesson over the lecture grid (6 x 4 unit cells) and its example ray o = (0.4, 0.4),
// d = (1, 0.75); `trace` replaces the trace, `extra` adds keys.
std::string lessonWith(const std::string& extra, const std::string& trace = "\"example\"",
                       const std::string& setup = "{\"accel\": \"grid\"}") {
    return "{\n\"format\": \"raystep-lesson\",\n\"version\": 1,\n\"id\": \"t\",\n\"number\": 1,\n"
           "\"title\": {\"en\": \"T\"},\n\"text\": {\"en\": \"x\"},\n\"scene\": \"lecture-grid\",\n"
           "\"setup\": " +
           setup + ",\n\"trace\": {\"ray\": " + trace + "}" + extra + "\n}";
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// A compute exercise: `given` and `quantity`, the prompt stating `prompt`.
Exercise compute(const std::string& given, const std::string& quantity,
                 const std::string& setup = "{\"accel\": \"grid\"}") {
    const Lesson l = loadLessonText(
        lessonWith(",\n\"exercises\": [{\"id\": \"c\", \"type\": \"compute\", \"prompt\": {\"en\": "
                   "\"?\"},\n \"given\": " +
                       given + ",\n \"quantity\": \"" + quantity + "\"}]",
                   "\"example\"", setup),
        "c.json");
    return l.exercises.at(0);
}

double answerOf(const Exercise& ex) {
    return computeAnswer(ex, "c.json");
}

const char* kSphere =
    "{\"ray\": {\"o\": [1, 2, 10], \"d\": [0, 0, -2]}, \"sphere\": {\"c\": [1, 1, 0], \"r\": 3}}";

// f = o - c = (0, 1, 10): A = d.d = 4, B = 2 d.f = -40, C = |f|^2 - 9 = 92,
// disc = 1600 - 16 * 92 = 128, t0 = (40 - sqrt 128) / 8, t1 = (40 + sqrt 128) / 8.
TEST(ComputeExercises, TheSphereByHand) {
    EXPECT_EQ(answerOf(compute(kSphere, "a")), 4.0);
    EXPECT_EQ(answerOf(compute(kSphere, "b")), -40.0);
    EXPECT_EQ(answerOf(compute(kSphere, "c")), 92.0);
    EXPECT_EQ(answerOf(compute(kSphere, "discriminant")), 128.0);
    EXPECT_NEAR(answerOf(compute(kSphere, "t0")), 3.585786437626905, 1e-12);
    EXPECT_NEAR(answerOf(compute(kSphere, "t1")), 6.414213562373095, 1e-12);
    EXPECT_NEAR(answerOf(compute(kSphere, "t")), 3.585786437626905, 1e-12);
    // A ray beside the sphere: t is not defined, and the lecturer is told so.
    const Exercise miss = compute(
        "{\"ray\": {\"o\": [5, 0, 10], \"d\": [0, 0, -1]}, \"sphere\": {\"c\": [0, 0, 0], \"r\": "
        "1}}",
        "t");
    try {
        computeAnswer(miss, "c.json");
        ADD_FAILURE();
    } catch (const LessonError& e) {
        EXPECT_TRUE(has(e.what(), "misses the sphere")) << e.what();
    }
    // A sphere behind the ray: the roots are t0 = -6, t1 = -4, and no t lies ahead.
    const std::string behind =
        "{\"ray\": {\"o\": [0, 0, -5], \"d\": [0, 0, -1]}, \"sphere\": {\"c\": [0, 0, 0], \"r\": "
        "1}}";
    EXPECT_EQ(answerOf(compute(behind, "t0")), -6.0);
    try {
        computeAnswer(compute(behind, "t"), "c.json");
        ADD_FAILURE();
    } catch (const LessonError& e) {
        EXPECT_TRUE(has(e.what(), "behind the origin")) << e.what();
    }
}

TEST(ComputeExercises, TheSpheresSlipsAreNamedWithTheStudentsNumber) {
    const Exercise t = compute(kSphere, "t");
    // The other root, 6.41421.
    EXPECT_TRUE(has(computeSlip(t, 6.414, Language::En), "6.414 is the other root"))
        << computeSlip(t, 6.414, Language::En);
    // -B - sqrt(disc) = 40 - 11.3137 = 28.6863, not divided by 2A = 8.
    EXPECT_TRUE(has(computeSlip(t, 28.69, Language::En), "without the division by 2A"));
    EXPECT_TRUE(has(computeSlip(t, 28.69, Language::It), "senza la divisione per 2A"));
    EXPECT_TRUE(has(computeSlip(t, -3.586, Language::En), "wrong sign"));
    // C without -R^2: |f|^2 = 101.
    EXPECT_TRUE(has(computeSlip(compute(kSphere, "c"), 101, Language::En), "without − R²"));
    // The slide's C = ||dir - c||^2: d - c = (-1, -1, -2), 6 (and 6 - 9 = -3).
    EXPECT_TRUE(has(computeSlip(compute(kSphere, "c"), 6, Language::En), "a typo"));
    EXPECT_EQ(computeSlip(t, 3.5858, Language::En), "") << "a right answer betrays nothing";
    EXPECT_EQ(computeSlip(t, 17, Language::En), "");
    // The working shows the given numbers, in Italian with the decimal comma.
    const std::string w = computeWorking(compute(kSphere, "t0"), Language::It);
    EXPECT_TRUE(has(w, "Δ = B² − 4AC = (-40)² − 4 · 4 · 92 = 128")) << w;
    EXPECT_TRUE(has(w, "3,58579")) << w;
}

// n = (b - a) x (c - a) = (0, 0, 1), n.d = -1, t = (n.a - n.o) / n.d = (0 - 2) / -1 = 2,
// p = (0.2, 0.5, 0): u (the weight of b = (1, 0, 0)) = 0.2, v (of c = (0, 1, 0)) = 0.5.
TEST(ComputeExercises, TheTriangleByHandAndUVSwapped) {
    const std::string given =
        "{\"ray\": {\"o\": [0.2, 0.5, 2], \"d\": [0, 0, -1]}, \"triangle\": [[0, 0, 0], [1, 0, "
        "0], [0, 1, 0]]}";
    EXPECT_EQ(answerOf(compute(given, "n.dir")), -1.0);
    EXPECT_EQ(answerOf(compute(given, "t")), 2.0);
    EXPECT_NEAR(answerOf(compute(given, "u")), 0.2, 1e-15);
    EXPECT_NEAR(answerOf(compute(given, "v")), 0.5, 1e-15);
    EXPECT_TRUE(has(computeSlip(compute(given, "u"), 0.5, Language::En), "0.5 is v, not u"));
    EXPECT_TRUE(has(computeSlip(compute(given, "v"), 0.2, Language::It), "0,2 è u, non v"));
}

// n.d = -2, t = (k - n.o) / n.d = (2 - 5) / -2 = 1.5; the slide's sign: -(5 + 2) / -2 = 3.5.
TEST(ComputeExercises, ThePlaneAndTheSlidesSign) {
    const std::string given =
        "{\"ray\": {\"o\": [0, 5, 0], \"d\": [1, -2, 0]}, \"plane\": {\"n\": [0, 1, 0], \"k\": 2}}";
    EXPECT_EQ(answerOf(compute(given, "n.dir")), -2.0);
    EXPECT_EQ(answerOf(compute(given, "t")), 1.5);
    EXPECT_TRUE(has(computeSlip(compute(given, "t"), 3.5, Language::En), "the slide's t"));
}

// Slabs: x [1, 3], y [-1, 3], z [-2, 6]: t_enter = 1, t_exit = 3.
TEST(ComputeExercises, TheSlabTest) {
    const std::string given =
        "{\"ray\": {\"o\": [-1, 0.5, 0.5], \"d\": [1, 0.5, 0.25]}, \"box\": {\"min\": [0, 0, 0], "
        "\"max\": [2, 2, 2]}}";
    EXPECT_EQ(answerOf(compute(given, "t_enter")), 1.0);
    EXPECT_NEAR(answerOf(compute(given, "t_exit")), 3.0, 1e-12);
    EXPECT_TRUE(has(computeSlip(compute(given, "t_enter"), 3, Language::En), "3 is t_exit"));
    EXPECT_TRUE(has(computeSlip(compute(given, "t_exit"), 6, Language::En), "one slab"));
}

// From outside, d.x negative: o = (5, 1.5), d = (-2, 0.5), 4 x 4 unit cells from (0, 0). The ray
// meets x = 4 at t = 0.5, at y = 1.75: the first cell is (3, 1); then x = 3 at t = 1 and y = 2 at
// t = 1; tDelta = (1/2, 1/0.5) = (0.5, 2).
TEST(ComputeExercises, TheDdaSetUpFromOutsideWithANegativeDirection) {
    const std::string given =
        "{\"ray\": {\"o\": [5, 1.5], \"d\": [-2, 0.5]}, \"grid\": {\"min\": [0, 0], \"cell\": "
        "[1, 1], \"res\": [4, 4]}}";
    EXPECT_EQ(answerOf(compute(given, "cell.x")), 3.0);
    EXPECT_EQ(answerOf(compute(given, "cell.y")), 1.0);
    EXPECT_EQ(answerOf(compute(given, "tMax.x")), 1.0);
    EXPECT_EQ(answerOf(compute(given, "tMax.y")), 1.0);
    EXPECT_EQ(answerOf(compute(given, "tDelta.x")), 0.5);
    EXPECT_EQ(answerOf(compute(given, "tDelta.y")), 2.0);
    EXPECT_TRUE(has(computeSlip(compute(given, "cell.x"), 4, Language::En), "one cell off"));
    EXPECT_TRUE(has(computeSlip(compute(given, "tDelta.x"), -0.5, Language::En), "wrong sign"));
    // The boundary behind (x = 4): (4 - 5) / -2 = 0.5.
    EXPECT_TRUE(
        has(computeSlip(compute(given, "tMax.x"), 0.5, Language::En), "the boundary behind"));
    expectLessonError(lessonWith(",\n\"exercises\": [{\"id\": \"c\", \"type\": \"compute\", "
                                 "\"prompt\": {\"en\": \"?\"},\n \"given\": " +
                                 given + ",\n \"quantity\": \"tMax.z\"}]"),
                      13, "exercises[0].quantity", "tMax.x, tMax.y, tDelta.x");
}

// Node [0,4] x [0,2] x [0,2], plane x = 1: Area(C) = 2 (8 + 4 + 8) = 40, Area(L) = 2 (2 + 4 + 2)
// = 16, Area(R) = 2 (6 + 4 + 6) = 32; pL = 0.4, pR = 0.8; cost = 1 + 5 (0.4 * 2 + 0.8 * 6) = 29.
// Squared: 1 + 5 (0.16 * 2 + 0.64 * 6) = 21.8.
TEST(ComputeExercises, TheSahCostOfANamedPlane) {
    const std::string given =
        "{\"node\": {\"min\": [0, 0, 0], \"max\": [4, 2, 2]}, \"plane\": {\"axis\": \"x\", \"at\": "
        "1}, \"nl\": 2, \"nr\": 6}";
    EXPECT_NEAR(answerOf(compute(given, "pL")), 0.4, 1e-15);
    EXPECT_NEAR(answerOf(compute(given, "pR")), 0.8, 1e-15);
    EXPECT_NEAR(answerOf(compute(given, "sahCost")), 29.0, 1e-12);
    EXPECT_TRUE(has(computeSlip(compute(given, "sahCost"), 21.8, Language::En), "Area²/Area²"));
    // 2D, an empty left side: perimeters 12, 6, 10; cost 0.5 (1 + 5 (10/12) 3) = 6.75; without
    // the bonus 13.5. The lesson's setup sets the costs.
    const std::string flat =
        "{\"node\": {\"min\": [0, 0], \"max\": [4, 2]}, \"plane\": {\"axis\": \"x\", \"at\": 1}, "
        "\"nl\": 0, \"nr\": 3}";
    EXPECT_NEAR(answerOf(compute(flat, "sahCost")), 6.75, 1e-12);
    EXPECT_TRUE(has(computeSlip(compute(flat, "sahCost"), 13.5, Language::En), "bonus"));
    EXPECT_NEAR(answerOf(compute(flat, "sahCost", "{\"accel\": \"grid\", \"c_isect\": 1}")),
                0.5 * (1 + 2.5), 1e-12);
    expectLessonError(
        lessonWith(",\n\"exercises\": [{\"id\": \"c\", \"type\": \"compute\", \"prompt\": {\"en\": "
                   "\"?\"},\n \"given\": {\"node\": {\"min\": [0, 0], \"max\": [4, 2]},\n "
                   "\"plane\": {\"axis\": \"x\", \"at\": 5}, \"nl\": 0, \"nr\": 3},\n "
                   "\"quantity\": \"pL\"}]"),
        13, "exercises[0].given.plane.at", "strictly inside");
}

// Phong at a point, as render/shading.h's phong(): n = (0, 0, 1), l = (0, 0.6, 0.8), n.l = 0.8,
// I_diff = 2 * 0.5 * 0.8 = 0.8; r = 2 (n.l) n - l = (0, -0.6, 0.8), with v = n r.v = 0.8 and
// I_spec = 2 * 0.25 * 0.8^2 = 0.32 (with n.v = 1 instead: 0.5).
TEST(ComputeExercises, PhongShadingByHandAndItsSlips) {
    const auto shading = [](const std::string& l, const std::string& v) {
        return "{\"shading\": {\"n\": [0, 0, 1], \"l\": " + l + ", \"v\": " + v +
               ", \"kd\": 0.5, \"ks\": 0.25, \"shininess\": 2, \"intensity\": 2}}";
    };
    const std::string front = shading("[0, 0.6, 0.8]", "[0, 0, 1]");
    EXPECT_NEAR(answerOf(compute(front, "n.l")), 0.8, 1e-15);
    EXPECT_NEAR(answerOf(compute(front, "diffuse")), 0.8, 1e-15);
    EXPECT_NEAR(answerOf(compute(front, "r.v")), 0.8, 1e-15);
    EXPECT_NEAR(answerOf(compute(front, "specular")), 0.32, 1e-15);
    EXPECT_TRUE(has(computeSlip(compute(front, "diffuse"), 0.4, Language::En), "intensity"));
    EXPECT_TRUE(has(computeSlip(compute(front, "specular"), 0.5, Language::En), "n·v"));
    const std::string w = computeWorking(compute(front, "specular"), Language::It);
    EXPECT_TRUE(has(w, "r = 2 (n·l) n − l = 2 · 0,8 · (0; 0; 1) − (0; 0,6; 0,8)")) << w;
    EXPECT_TRUE(has(w, "= 0,32.")) << w;
    // The light behind the surface: n.l = -0.8, no term at all; the unclamped I kd n.l = -0.8.
    const std::string behind = shading("[0, 0.6, -0.8]", "[0, 0, 1]");
    EXPECT_EQ(answerOf(compute(behind, "diffuse")), 0.0);
    EXPECT_EQ(answerOf(compute(behind, "specular")), 0.0);
    EXPECT_TRUE(has(computeSlip(compute(behind, "diffuse"), -0.8, Language::En), "clamp"));
    // The mirrored light away from the eye: r = (0, -0.8, 0.6), v = (0, 0.8, 0.6), r.v = -0.28;
    // squared without the clamp: 2 * 0.25 * 0.0784 = 0.0392.
    const std::string away = shading("[0, 0.8, 0.6]", "[0, 0.8, 0.6]");
    EXPECT_NEAR(answerOf(compute(away, "r.v")), -0.28, 1e-15);
    EXPECT_EQ(answerOf(compute(away, "specular")), 0.0);
    EXPECT_TRUE(has(computeSlip(compute(away, "specular"), 0.0392, Language::En), "negative r·v"));
    // Without v, ks and shininess only the diffuse term is defined.
    const std::string diffuseOnly =
        "{\"shading\": {\"n\": [0, 0, 1], \"l\": [0, 0.6, 0.8], \"kd\": 0.5, \"intensity\": 1}}";
    EXPECT_NEAR(answerOf(compute(diffuseOnly, "diffuse")), 0.4, 1e-15);
    const auto with = [](const std::string& given, const std::string& quantity) {
        return lessonWith(
            ",\n\"exercises\": [{\"id\": \"c\", \"type\": \"compute\", \"prompt\": {\"en\": "
            "\"?\"},\n \"given\": " +
            given + ",\n \"quantity\": \"" + quantity + "\"}]");
    };
    expectLessonError(with(diffuseOnly, "specular"), 13, "exercises[0].quantity",
                      "this shape's quantities are n.l, diffuse");
    expectLessonError(with("{\"shading\": {\"n\": [0, 0, 2], \"l\": [0, 0, 1], \"kd\": 0.5, "
                           "\"intensity\": 1}}",
                           "diffuse"),
                      12, "exercises[0].given.shading.n", "unit vector");
    expectLessonError(with("{\"shading\": {\"n\": [0, 0, 1], \"l\": [0, 0, 1], \"v\": [0, 0, 1], "
                           "\"kd\": 0.5, \"intensity\": 1}}",
                           "diffuse"),
                      12, "exercises[0].given.shading", "all of");
    expectLessonError(with(shading("[0, 0, 1]", "[0, 0, -1]"), "specular"), 12,
                      "exercises[0].given.shading.v", "normal's side");
}

TEST(ComputeExercises, BadGivenDataNameLineAndKey) {
    const auto with = [](const std::string& given, const std::string& quantity) {
        return lessonWith(
            ",\n\"exercises\": [{\"id\": \"c\", \"type\": \"compute\", \"prompt\": {\"en\": "
            "\"?\"},\n \"given\": " +
            given + ",\n \"quantity\": \"" + quantity + "\"}]");
    };
    expectLessonError(with("{\"ray\": {\"o\": [0, 0, 0], \"d\": [0, 0, 1]}}", "t"), 12,
                      "exercises[0].given", "exactly one of");
    expectLessonError(
        with("{\"ray\": {\"o\": [0, 0], \"d\": [0, 1]}, \"sphere\": {\"c\": [0, 0, 0], \"r\": 1}}",
             "t"),
        12, "exercises[0].given.ray.o", "array of 3 numbers");
    expectLessonError(
        with("{\"ray\": {\"o\": [0, 0, 0], \"d\": [0, 0, 0]},\n \"plane\": {\"n\": [0, 1, 0], "
             "\"k\": 1}}",
             "t"),
        12, "exercises[0].given.ray.d", "must not be zero");
    expectLessonError(
        with("{\"ray\": {\"o\": [0, 0, 0], \"d\": [0, 0, 1]},\n \"sphere\": {\"c\": [0, 0, 5], "
             "\"r\": 1}}",
             "u"),
        14, "exercises[0].quantity", "this shape's quantities are a, b, c");
}

// Data at the ends of double's range: a finite answer or the lecturer's error, never a crash,
// an infinity or a NaN passed on as an answer.
TEST(ComputeExercises, ExtremeDataGiveAnAnswerOrAnError) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"{\"ray\": {\"o\": [1e300, 0, 0], \"d\": [-1e-300, 0, 0]}, \"sphere\": {\"c\": [0, 0, 0], "
         "\"r\": 1e300}}",
         "t"},
        {"{\"ray\": {\"o\": [0, 0], \"d\": [1e-300, 1]}, \"grid\": {\"min\": [0, 0], \"cell\": "
         "[1e300, 1e300], \"res\": [1000000, 1000000]}}",
         "tMax.x"},
        {"{\"ray\": {\"o\": [-1e308, 0, 0], \"d\": [1e308, 1, 1]}, \"box\": {\"min\": [0, 0, 0], "
         "\"max\": [1e308, 1e308, 1e308]}}",
         "t_exit"},
        {"{\"node\": {\"min\": [-1e308, 0, 0], \"max\": [1e308, 1, 1]}, \"plane\": {\"axis\": "
         "\"x\", \"at\": 0}, \"nl\": 1, \"nr\": 1}",
         "sahCost"},
        {"{\"ray\": {\"o\": [0, 0, 0], \"d\": [1e-320, 0, 0]}, \"plane\": {\"n\": [1e-320, 0, 0], "
         "\"k\": 1e308}}",
         "t"}};
    for (const auto& [given, quantity] : cases) {
        const Exercise ex = compute(given, quantity);
        try {
            const double v = computeAnswer(ex, "c.json");
            EXPECT_TRUE(std::isfinite(v)) << given;
            EXPECT_FALSE(computeWorking(ex, Language::It).empty());
            computeSlip(ex, v + 1.0, Language::En);
        } catch (const LessonError& e) {
            EXPECT_TRUE(has(e.what(), "is not defined for these data")) << e.what();
        }
    }
}

// Every new key with a value of the wrong kind: a LessonError naming that key, never a crash.
TEST(NewKinds, EveryNewKeyOfTheWrongKindIsNamed) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"{\"id\": \"a\", \"type\": \"choice\", \"prompt\": {\"en\": \"?\"}, \"choices\": 3, "
         "\"answer\": 0}",
         "exercises[0].choices"},
        {"{\"id\": \"a\", \"type\": \"choice\", \"prompt\": {\"en\": \"?\"}, \"choices\": "
         "[{\"text\": {\"en\": \"a\"}}, {\"text\": {\"en\": \"b\"}, \"why\": {\"en\": \"w\"}}], "
         "\"answer\": 0}",
         "exercises[0].choices[0]"},
        {"{\"id\": \"a\", \"type\": \"choice\", \"prompt\": {\"en\": \"?\"}, \"choices\": "
         "[{\"text\": {\"en\": \"a\"}, \"why\": {\"en\": \"w\"}}, {\"text\": {\"en\": \"b\"}, "
         "\"why\": {\"en\": \"w\"}}], \"answer\": \"b\"}",
         "exercises[0].answer"},
        {"{\"id\": \"a\", \"type\": \"sequence\", \"of\": \"ray_hit\", \"prompt\": {\"en\": "
         "\"?\"}}",
         "exercises[0].of"},
        {"{\"id\": \"a\", \"type\": \"sequence\", \"of\": \"dda_cell\", \"length\": 0, "
         "\"prompt\": {\"en\": \"?\"}}",
         "exercises[0].length"},
        {"{\"id\": \"a\", \"type\": \"value\", \"quantity\": \"hit.t\", \"of\": \"dda_cell\", "
         "\"prompt\": {\"en\": \"?\"}}",
         "exercises[0].of"},
        {"{\"id\": \"a\", \"type\": \"compute\", \"quantity\": \"t\", \"prompt\": {\"en\": \"?\"}, "
         "\"given\": []}",
         "exercises[0].given"},
        {"{\"id\": \"a\", \"type\": \"compute\", \"quantity\": \"t\", \"prompt\": {\"en\": \"?\"}, "
         "\"given\": {\"ray\": {\"o\": [0, 0, 0], \"d\": [0, 0, 1]}, \"sphere\": {\"c\": [0, 0, "
         "5], \"r\": -1}}}",
         "exercises[0].given.sphere.r"},
        {"{\"id\": \"a\", \"type\": \"compute\", \"quantity\": \"t\", \"prompt\": {\"en\": \"?\"}, "
         "\"given\": {\"ray\": {\"o\": [0, 0, 0], \"d\": [0, 0, 1]}, \"triangle\": [[0, 0, 0], "
         "[1, 0, 0]]}}",
         "exercises[0].given.triangle"},
        {"{\"id\": \"a\", \"type\": \"compute\", \"quantity\": \"tMax.x\", \"prompt\": {\"en\": "
         "\"?\"}, \"given\": {\"ray\": {\"o\": [0, 0], \"d\": [1, 1]}, \"grid\": {\"min\": [0, 0], "
         "\"cell\": [0, 1]}}}",
         "exercises[0].given.grid.cell"},
        {"{\"id\": \"a\", \"type\": \"compute\", \"quantity\": \"tMax.x\", \"prompt\": {\"en\": "
         "\"?\"}, \"given\": {\"ray\": {\"o\": [0, 0], \"d\": [1, 1]}, \"grid\": {\"min\": [0, 0], "
         "\"cell\": [1, 1], \"res\": [4]}}}",
         "exercises[0].given.grid.res"},
        {"{\"id\": \"a\", \"type\": \"compute\", \"quantity\": \"pL\", \"prompt\": {\"en\": "
         "\"?\"}, "
         "\"given\": {\"node\": {\"min\": [0, 0], \"max\": [1, 1]}, \"plane\": {\"axis\": \"z\", "
         "\"at\": 0.5}, \"nl\": 1, \"nr\": 1}}",
         "exercises[0].given.plane.axis"},
        {"{\"id\": \"a\", \"type\": \"compute\", \"quantity\": \"pL\", \"prompt\": {\"en\": "
         "\"?\"}, "
         "\"given\": {\"node\": {\"min\": [0, 0], \"max\": [1, 1]}, \"plane\": {\"axis\": \"x\", "
         "\"at\": 0.5}, \"nl\": -1, \"nr\": 1}}",
         "exercises[0].given.nl"},
        {"{\"id\": \"a\", \"type\": \"sweep_pick\", \"metric\": \"trace_ms\", \"prompt\": {\"en\": "
         "\"?\"}}",
         "exercises[0].metric"},
    };
    for (const auto& [exercise, key] : cases) {
        try {
            loadLessonText(lessonWith(",\n\"sweep\": {\"grid_res\": [1, 2]},\n\"exercises\": [" +
                                      exercise + "]"),
                           "k.json");
            ADD_FAILURE() << "accepted: " << exercise;
        } catch (const LessonError& e) {
            EXPECT_EQ(e.key(), key) << e.what();
            EXPECT_GT(e.line(), 0) << e.what();
        }
    }
}

TEST(ComputeExercises, ThePromptMustStateEveryGivenNumberInBothLanguages) {
    const auto lesson = [](const std::string& en, const std::string& it) {
        return loadLessonText(
            lessonWith(",\n\"exercises\": [{\"id\": \"c\", \"type\": \"compute\",\n \"prompt\": "
                       "{\"en\": \"" +
                       en + "\", \"it\": \"" + it +
                       "\"},\n \"given\": {\"ray\": {\"o\": [0, 0, 5], \"d\": [0, 0, -1]}, "
                       "\"plane\": {\"n\": [0, 0, 1], \"k\": 0.5}},\n \"quantity\": \"t\"}]"),
            "p.json");
    };
    EXPECT_NO_THROW(
        checkComputePrompts(lesson("o = (0, 0, 5), d = (0, 0, −1); n = (0, 0, 1), k = 0.5.",
                                   "o = (0; 0; 5), d = (0; 0; −1); n = (0; 0; 1), k = 0,5.")));
    try {
        checkComputePrompts(lesson("o = (0, 0, 5), d = (0, 0, −1); n = (0, 0, 1), k = 0.5.",
                                   "o = (0; 0; 5), d = (0; 0; 1); n = (0; 0; 1), k = 0,5."));
        ADD_FAILURE() << "the Italian prompt gives d.z = 1, not -1";
    } catch (const LessonError& e) {
        EXPECT_EQ(e.key(), "exercises[0].prompt.it") << e.what();
        EXPECT_TRUE(has(e.what(), "-1")) << e.what();
    }
    EXPECT_THROW(
        checkComputePrompts(lesson("o = (0, 0, 5), d = (0, 0, −1); n = (0, 0, 1), k = 5.",
                                   "o = (0; 0; 5), d = (0; 0; −1); n = (0; 0; 1), k = 0,5.")),
        LessonError)
        << "k = 0.5 is missing in English";
    EXPECT_EQ(numbersInText("p = (1,5; −2) e 3e-2", Language::It),
              (std::vector<double>{1.5, -2, 0.03}));
    EXPECT_EQ(numbersInText("p = (1,5, -2), x2", Language::En), (std::vector<double>{1, 5, -2}));
}

Lesson choiceLesson() {
    return loadLessonText(
        lessonWith(
            ",\n\"exercises\": [{\"id\": \"why-overlap\", \"type\": \"choice\",\n "
            "\"prompt\": {\"en\": \"Why do BVH boxes overlap?\", \"it\": \"Perché?\"},\n "
            "\"choices\": [\n  {\"text\": {\"en\": \"Rounding\", \"it\": \"Arrotondamento\"}, "
            "\"why\": {\"en\": \"No: exact boxes overlap too.\", \"it\": \"No.\"}},\n"
            "  {\"text\": {\"en\": \"Primitives are split, not space\", \"it\": \"Si "
            "dividono le primitive\"}, \"why\": {\"en\": \"Each box bounds its own "
            "primitives.\", \"it\": \"Ogni box.\"}},\n"
            "  {\"text\": {\"en\": \"Mailboxing\"}, \"why\": {\"en\": \"Unrelated.\"}}],\n "
            "\"answer\": 1}]"),
        "choice.json");
}

TEST(NewKinds, AChoiceIsAnsweredByLetterOrNumber) {
    const Lesson l = choiceLesson();
    const Exercise& ex = l.exercises.at(0);
    ASSERT_EQ(ex.choices.size(), 3u);
    std::string why;
    EXPECT_EQ(parseAnswer(ex, "b", &why)->numbers, std::vector<double>{1});
    EXPECT_EQ(parseAnswer(ex, " B) ", &why)->numbers, std::vector<double>{1});
    EXPECT_EQ(parseAnswer(ex, "3", &why)->numbers, std::vector<double>{2});
    EXPECT_FALSE(parseAnswer(ex, "d", &why));
    EXPECT_TRUE(has(why, "a to c")) << why;
    EXPECT_FALSE(parseAnswer(ex, "4", &why, Language::It));
    EXPECT_TRUE(has(why, "da a a c")) << why;
    const LessonRun run = runLesson(l);
    const Verdict wrong =
        checkAnswer(ex, *run.log, *parseAnswer(ex, "a", &why), Language::En, l.file);
    EXPECT_FALSE(wrong.correct);
    EXPECT_EQ(wrong.expected, "b");
    // The chosen option's why first, then the right one's.
    const auto chosen = wrong.feedback.find("No: exact boxes overlap too.");
    const auto right = wrong.feedback.find("Each box bounds its own primitives.");
    ASSERT_NE(chosen, std::string::npos) << wrong.feedback;
    ASSERT_NE(right, std::string::npos) << wrong.feedback;
    EXPECT_LT(chosen, right);
    EXPECT_TRUE(
        checkAnswer(ex, *run.log, *parseAnswer(ex, "2", &why), Language::It, l.file).correct);
    EXPECT_FALSE(quizLimit(ex, *run.log).has_value()) << "a choice is not in the trace";
    expectLessonError(lessonWith(",\n\"exercises\": [{\"id\": \"q\", \"type\": \"choice\", "
                                 "\"prompt\": {\"en\": \"?\"},\n \"choices\": [{\"text\": "
                                 "{\"en\": \"a\"}, \"why\": {\"en\": \"w\"}}], \"answer\": 0}]"),
                      12, "exercises[0].choices", "2 to 6 options");
    expectLessonError(lessonWith(",\n\"exercises\": [{\"id\": \"q\", \"type\": \"choice\", "
                                 "\"prompt\": {\"en\": \"?\"},\n \"choices\": [{\"text\": "
                                 "{\"en\": \"a\"}, \"why\": {\"en\": \"w\"}},\n {\"text\": "
                                 "{\"en\": \"b\"}, \"why\": {\"en\": \"w\"}}],\n \"answer\": 2}]"),
                      14, "exercises[0].answer", "between 0 and 1");
}

// The slides' walk from (0.4, 0.4) along (0.8, 0.4): tMax starts at (0.75, 1.5); X to (1, 0), then
// tMaxX = 2 > 1.5: Y to (1, 1); 2 < 4: X to (2, 1); 3.25 < 4: X to (3, 1) (by hand, lesson 6).
TEST(NewKinds, ASequenceOfCellsIsGradedAndItsFirstDepartureExplained) {
    const Lesson l = loadLessonText(
        lessonWith(",\n\"exercises\": [{\"id\": \"walk\", \"type\": \"sequence\", \"of\": "
                   "\"dda_cell\", \"length\": 5,\n \"prompt\": {\"en\": \"?\"}}]"),
        "seq.json");
    const Exercise& ex = l.exercises.at(0);
    const LessonRun run = runLesson(l);
    const Answer ref = referenceAnswer(ex, *run.log, l.file);
    EXPECT_EQ(ref.numbers, (std::vector<double>{0, 0, 1, 0, 1, 1, 2, 1, 3, 1}));
    EXPECT_EQ(formatAnswer(ex, ref), "0,0; 1,0; 1,1; 2,1; 3,1");
    std::string why;
    for (const char* typed :
         {"0,0; 1,0; 1,1; 2,1; 3,1", "(0,0) (1,0) (1,1) (2,1) (3,1)", "0,0 1,0 1,1 2,1 3,1"}) {
        const auto a = parseAnswer(ex, typed, &why);
        ASSERT_TRUE(a) << typed << ": " << why;
        EXPECT_TRUE(checkAnswer(ex, *run.log, *a, Language::En, l.file).correct) << typed;
    }
    const Verdict v = checkAnswer(ex, *run.log, *parseAnswer(ex, "0,0; 1,0; 2,0; 3,0; 3,1", &why),
                                  Language::En, l.file);
    EXPECT_FALSE(v.correct);
    EXPECT_TRUE(has(v.slip, "at the 3rd item (you wrote (2, 0))")) << v.slip;
    EXPECT_TRUE(has(v.slip, "tMaxX = 2, tMaxY = 1.5")) << v.slip;
    const Verdict it =
        checkAnswer(ex, *run.log, *parseAnswer(ex, "0,0; 1,0", &why), Language::It, l.file);
    EXPECT_TRUE(has(it.slip, "si ferma dopo 2 elementi")) << it.slip;
    EXPECT_FALSE(parseAnswer(ex, "0,0; 1", &why));
    EXPECT_EQ(quizLimit(ex, *run.log), std::optional<std::size_t>(0));
}

TEST(NewKinds, ASequenceOfNodesIsReadFromTheEnteredNodes) {
    const Lesson l = loadLessonText(
        lessonWith(",\n\"exercises\": [{\"id\": \"nodes\", \"type\": \"sequence\", \"of\": "
                   "\"node_enter\",\n \"prompt\": {\"en\": \"?\"}}]",
                   "\"example\"", "{\"accel\": \"kdtree\"}"),
        "nodes.json");
    const Exercise& ex = l.exercises.at(0);
    const LessonRun run = runLesson(l);
    std::vector<double> entered;
    for (const Event& e : run.log->events())
        if (const auto* n = std::get_if<NodeEnter>(&e)) entered.push_back(n->node);
    ASSERT_GE(entered.size(), 2u);
    EXPECT_EQ(referenceAnswer(ex, *run.log, l.file).numbers, entered);
    std::string why;
    const auto typed =
        parseAnswer(ex, formatAnswer(ex, referenceAnswer(ex, *run.log, l.file)), &why);
    ASSERT_TRUE(typed) << why;
    EXPECT_TRUE(checkAnswer(ex, *run.log, *typed, Language::En, l.file).correct);
    Answer swapped = *typed;
    std::swap(swapped.numbers[0], swapped.numbers[1]);
    const Verdict v = checkAnswer(ex, *run.log, swapped, Language::En, l.file);
    EXPECT_FALSE(v.correct);
    EXPECT_TRUE(has(v.slip, "at the 1st item")) << v.slip;
    EXPECT_TRUE(has(v.slip, "[tNear, tFar]")) << v.slip;
}

// Rows written here: cost = 1 x cells + 5 x tests: 1 -> 126, 2 -> 60.7, 8 -> 20.1, 16 -> 20.7.
TEST(NewKinds, ASweepPickIsGradedFromTheSweepsRows) {
    const auto lesson = [](const char* metric) {
        return loadLessonText(
            lessonWith(",\n\"sweep\": {\"grid_res\": [1, 2, 8, 16]},\n\"exercises\": [{\"id\": "
                       "\"s\", \"type\": \"sweep_pick\", \"metric\": \"" +
                       std::string(metric) + "\", \"prompt\": {\"en\": \"?\"}}]"),
            "s.json");
    };
    std::vector<GridSweepRow> rows(4);
    const int res[] = {1, 2, 8, 16};
    const double cells[] = {1, 1.2, 4.6, 9.2}, tests[] = {25, 11.9, 3.1, 2.3};
    for (int i = 0; i < 4; ++i) {
        rows[i].resolution = res[i];
        rows[i].cellsPerRay = cells[i];
        rows[i].testsPerRay = tests[i];
    }
    EventLog log;
    EXPECT_EQ(referenceAnswer(lesson("cost").exercises[0], log, "s.json", &rows).numbers[0], 8);
    EXPECT_EQ(
        referenceAnswer(lesson("tests_per_ray").exercises[0], log, "s.json", &rows).numbers[0], 16);
    EXPECT_EQ(
        referenceAnswer(lesson("cells_per_ray").exercises[0], log, "s.json", &rows).numbers[0], 1);
    const Exercise ex = lesson("cost").exercises[0];
    const Verdict v = checkAnswer(ex, log, Answer{{16}, {}}, Language::En, "s.json", &rows);
    EXPECT_FALSE(v.correct);
    EXPECT_TRUE(has(v.feedback, "16: 20.7")) << v.feedback;
    EXPECT_TRUE(has(v.slip, "At 16 the metric is higher than at 8")) << v.slip;
    const Verdict off = checkAnswer(ex, log, Answer{{5}, {}}, Language::It, "s.json", &rows);
    EXPECT_TRUE(has(off.slip, "5 non è una delle risoluzioni della scansione (1, 2, 8, 16)"))
        << off.slip;
    EXPECT_THROW(referenceAnswer(ex, log, "s.json"), LessonError) << "no rows, no grade";
    expectLessonError(lessonWith(",\n\"exercises\": [{\"id\": \"s\", \"type\": \"sweep_pick\", "
                                 "\"prompt\": {\"en\": \"?\"}}]"),
                      11, "exercises[0].type", "needs the lesson's \"sweep\"");
}

TEST(Italian, AnswersInItalianAndMessagesInItalian) {
    Exercise hit;
    hit.kind = ExerciseKind::HitOrMiss;
    std::string why;
    for (const char* yes : {"colpita", "Colpito", "sì", "si", "hit", "colpisce"})
        EXPECT_EQ(parseAnswer(hit, yes, &why)->hit, std::optional<bool>(true)) << yes;
    for (const char* no : {"mancata", "mancato", "no", "miss", "manca"})
        EXPECT_EQ(parseAnswer(hit, no, &why)->hit, std::optional<bool>(false)) << no;
    // Without with_t, the message does not ask for a t.
    EXPECT_FALSE(parseAnswer(hit, "forse", &why, Language::En));
    EXPECT_EQ(why, "expected \"hit\" or \"miss\"");
    EXPECT_FALSE(parseAnswer(hit, "forse", &why, Language::It));
    EXPECT_EQ(why, "scrivi \"colpita\" oppure \"mancata\"");
    hit.withT = true;
    EXPECT_FALSE(parseAnswer(hit, "colpita", &why, Language::It));
    EXPECT_TRUE(has(why, "colpita T")) << why;
    const auto withT = parseAnswer(hit, "colpita 3,55", &why, Language::It);
    ASSERT_TRUE(withT) << why;
    EXPECT_EQ(withT->numbers, std::vector<double>{3.55});
    EXPECT_EQ(formatAnswer(hit, *withT, Language::It), "colpita 3,55");
    Exercise value;
    value.kind = ExerciseKind::Value;
    EXPECT_FALSE(parseAnswer(value, "tre", &why, Language::It));
    EXPECT_EQ(why, "scrivi un numero");
}

TEST(Italian, PositionsAndCountsWithoutInternalNames) {
    ReplayPosition after{ReplayPosition::Mode::AfterEvent, 0, variantIndex<RayHit>(), 1};
    EXPECT_EQ(describePosition(after, Language::En), "after the 1st intersection found");
    EXPECT_EQ(describePosition(after, Language::It), "dopo la 1ª intersezione trovata");
    ReplayPosition before{ReplayPosition::Mode::BeforeEvent, 0, variantIndex<RayBegin>(), 2};
    EXPECT_EQ(describePosition(before, Language::En), "before the 2nd ray begins");
    EXPECT_EQ(describePosition(before, Language::It), "prima dell'inizio del 2° raggio");
    // Lesson 1: shadow rays of depth 1 after the first hit.
    const Lesson l = loadLesson("1");
    const LessonRun run = runLesson(l);
    const Exercise* shadows = nullptr;
    for (const Exercise& ex : l.exercises)
        if (ex.kind == ExerciseKind::Count && ex.rayKind == RayKind::Shadow) shadows = &ex;
    ASSERT_NE(shadows, nullptr);
    const Answer ref = referenceAnswer(*shadows, *run.log, l.file);
    const std::string n = std::to_string(static_cast<int>(ref.numbers[0]));
    const Verdict it = checkAnswer(*shadows, *run.log, ref, Language::It, l.file);
    EXPECT_TRUE(has(it.feedback,
                    "Raggi d'ombra di profondità 1 dopo la 1ª intersezione trovata: " + n + "."))
        << it.feedback;
    const Verdict en = checkAnswer(*shadows, *run.log, ref, Language::En, l.file);
    EXPECT_TRUE(has(en.feedback, "Shadow rays of depth 1 after the 1st intersection found: " + n))
        << en.feedback;
    for (const std::string& text : {it.feedback, en.feedback}) {
        EXPECT_FALSE(has(text, "ray_begin")) << text;
        EXPECT_FALSE(has(text, "ray_hit")) << text;
    }
    // Counting every ray of the range, of any kind, is named.
    std::size_t all = 0;
    const auto from = *resolvePosition(shadows->at, *run.log);
    for (std::size_t i = from; i < run.log->events().size(); ++i)
        all += std::holds_alternative<RayBegin>(run.log->events()[i]);
    if (all != ref.numbers[0]) {
        const Verdict slip =
            checkAnswer(*shadows, *run.log, Answer{{double(all)}, {}}, Language::En, l.file);
        EXPECT_TRUE(has(slip.slip, "counts every ray in the range")) << slip.slip;
    }
}

// Lesson 6's scene and ray: the long segment is found first (t = 345/64 = 5.390625, in cell
// (3, 2)) but the small circle is nearer (t = (3.88 - 0.22) / 0.8 = 4.575): the slide's `break`
// gives the farther one (Python fractions, by the segment's 2x2 system and the quadratic).
TEST(Slips, TheFartherHitOfTheSlidesBreakAndTDeltaWithoutAbs) {
    const Lesson l = loadLessonText(
        lessonWith(",\n\"exercises\": [{\"id\": \"t\", \"type\": \"value\", \"quantity\": "
                   "\"hit.t\", \"prompt\": {\"en\": \"?\"}}]"),
        "v.json");
    const LessonRun run = runLesson(l);
    const Exercise& ex = l.exercises[0];
    EXPECT_NEAR(referenceAnswer(ex, *run.log, l.file).numbers[0], 4.575, 1e-9);
    const Verdict v = checkAnswer(ex, *run.log, Answer{{5.39}, {}}, Language::En, l.file);
    EXPECT_FALSE(v.correct);
    EXPECT_TRUE(has(v.slip, "5.39 is primitive")) << v.slip;
    EXPECT_TRUE(has(v.slip, "`break`")) << v.slip;
    // d = (-1, -0.5) over unit cells: tDelta.y = 1 / |-0.5| = 2; without the abs, -2.
    const Lesson down = loadLessonText(
        lessonWith(",\n\"exercises\": [{\"id\": \"d\", \"type\": \"value\", \"quantity\": "
                   "\"tDelta.y\", \"prompt\": {\"en\": \"?\"}}]",
                   "[5.5, 2.5, -1, -0.5]"),
        "v.json");
    const LessonRun walk = runLesson(down);
    EXPECT_EQ(referenceAnswer(down.exercises[0], *walk.log, down.file).numbers[0], 2.0);
    const Verdict abs =
        checkAnswer(down.exercises[0], *walk.log, Answer{{-2}, {}}, Language::It, down.file);
    EXPECT_TRUE(has(abs.slip, "senza valore assoluto")) << abs.slip;
    EXPECT_TRUE(has(abs.feedback, "= 1 / |-0,5| = 2")) << abs.feedback;
    // Along a positive d the abs changes nothing: a negative answer is only a wrong sign.
    const Lesson up = loadLessonText(
        lessonWith(",\n\"exercises\": [{\"id\": \"d\", \"type\": \"value\", \"quantity\": "
                   "\"tDelta.y\", \"prompt\": {\"en\": \"?\"}}]"),
        "v.json");
    const LessonRun upRun = runLesson(up);
    const Verdict sign =
        checkAnswer(up.exercises[0], *upRun.log, Answer{{-2.5}, {}}, Language::En, up.file);
    EXPECT_TRUE(has(sign.slip, "wrong sign")) << sign.slip;
}

// A dearer plane is named with its own cost, as the trace's candidate event records it; a plane
// that is not a candidate is named as such.
TEST(Slips, ADearerSplitIsNamedWithItsCost) {
    const Lesson l = loadLessonText(
        "{\"format\": \"raystep-lesson\", \"version\": 1, \"id\": \"t\", \"number\": 1,\n"
        "\"title\": {\"en\": \"T\"}, \"text\": {\"en\": \"x\"}, \"scene\": \"lecture-grid\",\n"
        "\"setup\": {\"accel\": \"kdtree\", \"split\": \"sah\"}, \"trace\": {\"build\": true},\n"
        "\"exercises\": [{\"id\": \"p\", \"type\": \"pick_split\", \"prompt\": {\"en\": "
        "\"?\"}}]}",
        "p.json");
    const LessonRun run = runLesson(l);
    const Exercise& ex = l.exercises[0];
    const auto candidates = splitCandidates(ex, *run.log);
    ASSERT_GT(candidates.size(), 2u);
    double best = candidates[0].sahCost;
    for (const SplitCandidate& c : candidates) best = std::min(best, c.sahCost);
    const SplitCandidate* dear = nullptr;
    for (const SplitCandidate& c : candidates)
        if (c.sahCost > best * 1.01) dear = &c;
    ASSERT_NE(dear, nullptr);
    const Verdict v = checkAnswer(ex, *run.log, Answer{{double(dear->axis), dear->position}, {}},
                                  Language::En, l.file);
    EXPECT_FALSE(v.correct);
    EXPECT_TRUE(has(v.slip, " = " + formatNumber(dear->sahCost) + ", more than the cheapest"))
        << v.slip;
    const Verdict none = checkAnswer(ex, *run.log, Answer{{0, -1234.5}, {}}, Language::It, l.file);
    EXPECT_TRUE(has(none.slip, "x = -1234,5 non è uno dei candidati")) << none.slip;
}

// A 3D miss, named from the scene. The ray (0, 0, 5) + t (0, 0, -1): sphere 0 at (3, 0, 0), r 1:
// f = (-3, 0, 5), B = -10, C = 33, B^2 - 4AC = 100 - 132 = -32. Triangle 1, (1, 1, 0) (2, 1, 0)
// (1, 2, 0): the plane z = 0 at t = 5, the point (0, 0, 0) = a - (b - a) - (c - a): u = v = -1.
TEST(Slips, AMissIn3DNamesItsCause) {
    Scene scene;
    scene.spheres.push_back({Vec3(3, 0, 0), 1.0, 0});
    scene.triangles.push_back({Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2, 0), 0});
    EventLog log;
    const std::uint32_t ray =
        log.beginRay(Ray{Vec3(0, 0, 5), Vec3(0, 0, -1)}, RayKind::Primary, 0, kNoId);
    log(PrimitiveTest{ray, 0, false, kInfinity});
    log(PrimitiveTest{ray, 1, false, kInfinity});
    Exercise ex;
    ex.kind = ExerciseKind::HitOrMiss;
    ex.at = ReplayPosition{ReplayPosition::Mode::Cursor, 1};
    const LessonScene withScene = scene;
    const Verdict sphere =
        checkAnswer(ex, log, Answer{{}, true}, Language::En, "m.json", nullptr, &withScene);
    EXPECT_TRUE(has(sphere.feedback, "B² − 4AC = -32 is negative")) << sphere.feedback;
    ex.at.cursor = 2;
    const Verdict tri =
        checkAnswer(ex, log, Answer{{}, true}, Language::It, "m.json", nullptr, &withScene);
    EXPECT_TRUE(has(tri.feedback, "fuori dal triangolo: u = -1, v = -1")) << tri.feedback;
    // Without the scene, the general reasons.
    const Verdict general = checkAnswer(ex, log, Answer{{}, true}, Language::En, "m.json");
    EXPECT_TRUE(has(general.feedback, "a negative discriminant, an intersection behind"))
        << general.feedback;
}

TEST(Quiz, TheReplayLimitIsTheExercisesPosition) {
    const Lesson l = loadLesson("grid-2d-dda");
    const LessonRun run = runLesson(l);
    const LessonLogs logs = run.logs();
    for (const Exercise& ex : l.exercises) {
        const EventLog& log = logs.of(ex.setup);
        // A choice or a compute exercise's answer is not in the trace: nothing to hold back; a
        // spot_bug's whole replayed walk is what the student looks at.
        if (ex.kind == ExerciseKind::Choice || ex.kind == ExerciseKind::Compute ||
            ex.kind == ExerciseKind::SpotBug)
            EXPECT_FALSE(quizLimit(ex, log).has_value()) << ex.id;
        else
            EXPECT_EQ(quizLimit(ex, log), resolvePosition(ex.at, log)) << ex.id;
    }
    EXPECT_FALSE(quizLimit(compute(kSphere, "t"), *run.log).has_value());
}

TEST(Quiz, AnAnswerWrittenInTheLessonIsFound) {
    // tDelta.y = 1 / 0.4 = 2.5: a step shown with the exercise that writes "2.5" gives it.
    const auto lesson = [](const std::string& stepText, const std::string& hint) {
        return loadLessonText(
            lessonWith(",\n\"steps\": [{\"text\": {\"en\": \"" + stepText +
                       "\"}, \"at\": \"start\"}],\n\"exercises\": [{\"id\": \"d\", \"type\": "
                       "\"value\", \"quantity\": \"tDelta.y\",\n \"prompt\": {\"en\": \"?\"}, "
                       "\"hint\": {\"en\": \"" +
                       hint + "\", \"it\": \"" + hint + "\"}}]"),
            "g.json");
    };
    const Lesson clean = lesson("tDeltaX = 1", "divide");
    const LessonRun run = runLesson(clean);
    EXPECT_NO_THROW(checkNoAnswerGivenAway(clean, *run.log));
    try {
        checkNoAnswerGivenAway(lesson("tDeltaY = 1/0.4 = 2.5", "divide"), *run.log);
        ADD_FAILURE() << "the step writes the answer";
    } catch (const LessonError& e) {
        EXPECT_TRUE(has(e.what(), "steps[0].text.en as \"2.5\"")) << e.what();
    }
    EXPECT_THROW(checkNoAnswerGivenAway(lesson("x", "about 2,5"), *run.log), LessonError)
        << "the Italian form";
    // 12.5 or 2.55 are other numbers, not the answer written.
    EXPECT_NO_THROW(checkNoAnswerGivenAway(lesson("12.5 and 2.55", "divide"), *run.log));
}

}  // namespace
}  // namespace raystep
