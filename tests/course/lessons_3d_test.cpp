// The 3D lessons (1-5, 12): every trace-graded answer equals an independent recomputation (a
// pure-Python model of the camera, the primitives and the ray tree's rules, and fractions for the
// hand computations: /work/wt17-c3d-calc in the lesson author's notes), so a change to the
// tracer, the camera or a scene that moves an example ray shows here, not in a lecture.
#include "course/exercise.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace raystep {
namespace {

Answer referenceOf(const Lesson& l, const LessonRun& run, const std::string& id) {
    for (const Exercise& ex : l.exercises)
        if (ex.id == id) return referenceAnswer(ex, *run.log, l.file);
    ADD_FAILURE() << l.id << " has no exercise " << id;
    return {};
}

double countOf(const Lesson& l, const LessonRun& run, const std::string& id) {
    const Answer a = referenceOf(l, run, id);
    return a.numbers.empty() ? -1.0 : a.numbers[0];
}

TEST(Lessons3D, ThePredictionsEqualTheRayTreesRules) {
    {
        // Pixel (178, 96) meets the mirror sphere 0.31 R from its centre; both lights are in
        // front of the hit point (cosines 0.69 and 0.66).
        const Lesson l = loadLesson("raster-vs-raytracing");
        const LessonRun run = runLesson(l);
        EXPECT_EQ(referenceOf(l, run, "first-test").hit, std::optional<bool>(true));
        EXPECT_EQ(countOf(l, run, "shadow-rays"), 2);
    }
    {
        // The floor (triangle 4) is crossed at t = 11.71, beyond the mirror's 6.858: a miss.
        // The floor point's shadow rays: 9 tests, then 3 (blocked by the glass sphere, prim 2).
        const Lesson l = loadLesson("algorithm-steps");
        const LessonRun run = runLesson(l);
        EXPECT_EQ(referenceOf(l, run, "nearest-so-far").hit, std::optional<bool>(false));
        EXPECT_EQ(countOf(l, run, "floor-shadow-tests"), 12);
    }
    {
        // Glass, hit 0.12 R from the centre: 2 shadow + reflection + refraction at depth 1, and
        // the same four from the far side, inside (no total internal reflection: cos 0.997).
        const Lesson l = loadLesson("ray-tree");
        const LessonRun run = runLesson(l);
        EXPECT_EQ(countOf(l, run, "depth-one"), 4);
        EXPECT_EQ(countOf(l, run, "depth-two"), 4);
    }
    {
        // The floor by the red wall: one shadow ray (the light at cos 0.92) + 16 bounces.
        const Lesson l = loadLesson("phong-diffuse");
        const LessonRun run = runLesson(l);
        EXPECT_EQ(countOf(l, run, "depth-one"), 17);
    }
    {
        // Nine primitives; in the red sphere's shadow: 9 tests to the first light, 1 to the
        // second (the red sphere is primitive 0, tested first).
        const Lesson l = loadLesson("brute-force");
        const LessonRun run = runLesson(l);
        EXPECT_EQ(countOf(l, run, "primary-tests"), 9);
        EXPECT_EQ(countOf(l, run, "shadow-tests"), 10);
    }
}

TEST(Lessons3D, TheIntersectionLessonsSceneValuesEqualAHandComputation) {
    const Lesson l = loadLesson("intersections");
    const LessonRun run = runLesson(l);
    // Pixel (118, 116) against the mirror sphere: roots 7.87728 and 10.32463.
    const Answer sphere = referenceOf(l, run, "sphere-test");
    ASSERT_EQ(sphere.hit, std::optional<bool>(true));
    ASSERT_EQ(sphere.numbers.size(), 1u);
    EXPECT_NEAR(sphere.numbers[0], 7.87728, 1e-4);
    // Its reflection meets the floor inside triangle 2, far from every edge.
    EXPECT_EQ(referenceOf(l, run, "triangle-test").hit, std::optional<bool>(true));
    EXPECT_NEAR(referenceOf(l, run, "barycentric-u").numbers.at(0), 0.324586, 1e-4);
    EXPECT_NEAR(referenceOf(l, run, "barycentric-v").numbers.at(0), 0.444075, 1e-4);
}

// The hand computations on round data, by hand in fractions: A = 4, B = -28, C = 50 - 9 = 41,
// 784 - 656 = 128, t = (28 - sqrt(128)) / 8 = 3.5 - sqrt(2); moved up, C = 56 and 784 - 896;
// the plane y = 1: t = (1 - 19) / -5; the triangle's p = (1, 2, 0): u = 1/5, v = 2/5.
TEST(Lessons3D, TheIntersectionLessonsHandComputationsEqualFractions) {
    const Lesson l = loadLesson("intersections");
    const LessonRun run = runLesson(l);
    const auto value = [&](const std::string& id) {
        const Answer a = referenceOf(l, run, id);
        return a.numbers.empty() ? kInfinity : a.numbers[0];
    };
    EXPECT_DOUBLE_EQ(value("sphere-b"), -28.0);
    EXPECT_DOUBLE_EQ(value("sphere-c"), 41.0);
    EXPECT_DOUBLE_EQ(value("sphere-discriminant"), 128.0);
    EXPECT_NEAR(value("sphere-t"), 3.5 - std::sqrt(2.0), 1e-12);
    EXPECT_DOUBLE_EQ(value("sphere-miss"), -112.0);
    EXPECT_NEAR(value("plane-t"), 3.6, 1e-12);
    EXPECT_NEAR(value("triangle-u"), 0.2, 1e-12);
    EXPECT_NEAR(value("triangle-v"), 0.4, 1e-12);
}

}  // namespace
}  // namespace raystep
