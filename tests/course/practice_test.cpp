// The practice driver: ids, determinism, errors; and the lesson format's inline scene and 3D ray
// it relies on. The generators' answers are recomputed independently in tests/practice.
#include "course/practice/practice.h"
#include "course/exercise.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include <gtest/gtest.h>

#include <string>

using namespace raystep;

TEST(Practice, LessonIdsRoundTripAndRefuseOthers) {
    const std::string id = practiceLessonId("dda-2d", PracticeLevel::Hard, 18446744073709551615ull);
    EXPECT_EQ(id, "practice-dda-2d-hard-18446744073709551615");
    const auto k = parsePracticeLessonId(id);
    ASSERT_TRUE(k);
    EXPECT_EQ(k->topic, "dda-2d");
    EXPECT_EQ(k->level, PracticeLevel::Hard);
    EXPECT_EQ(k->seed, 18446744073709551615ull);
    for (const char* bad : {"practice-dda-2d-hard-", "practice-dda-2d-hard-1x",
                            "practice-nope-easy-1", "practice-dda-2d-extreme-1", "grid-2d-dda",
                            "practice-dda-2d-easy--1", "practice-dda-2d-easy-18446744073709551616"})
        EXPECT_FALSE(parsePracticeLessonId(bad)) << bad;
}

TEST(Practice, SameSeedSameInstanceOtherSeedOtherInstance) {
    const PracticeInstance a = makePractice("dda-3d", 11, PracticeLevel::Medium);
    const PracticeInstance b = makePractice("dda-3d", 11, PracticeLevel::Medium);
    const PracticeInstance c = makePractice("dda-3d", 12, PracticeLevel::Medium);
    EXPECT_EQ(a.lessonText, b.lessonText);
    EXPECT_EQ(a.toJson().dump(), b.toJson().dump());
    EXPECT_NE(a.given.dump(), c.given.dump());
    // The lesson id names the instance, and loadLesson makes it again from the id alone.
    EXPECT_EQ(a.lesson.id, "practice-dda-3d-medium-11");
    EXPECT_EQ(loadLesson(a.lesson.id).exercises.size(), a.lesson.exercises.size());
    EXPECT_NO_THROW(validateLesson(a.lesson));
}

TEST(Practice, UnknownTopicListsTheTopics) {
    try {
        makePractice("dda-4d", 1, PracticeLevel::Easy);
        FAIL() << "no error";
    } catch (const PracticeError& e) {
        EXPECT_NE(std::string(e.what()).find("dda-4d"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("dda-2d, dda-3d"), std::string::npos);
    }
}

namespace {
std::string lessonWithScene(const std::string& scene, const std::string& ray) {
    return R"({"format": "raystep-lesson", "version": 1, "id": "inline", "number": 5,
"title": {"en": "t"}, "text": {"en": "t"},
"scene": )" +
           scene + R"(,
"setup": {"accel": "grid"},
"trace": {"ray": )" +
           ray + "}}";
}
}  // namespace

TEST(Practice, InlineSceneErrorNamesTheLessonFileLineAndKey) {
    const std::string bad = lessonWithScene(
        R"({"dimensions": 2,
  "circles": [{"center": [0, 0], "radius": -1}]})",
        "[0, 0, 1, 1]");
    try {
        loadLessonText(bad, "my.json");
        FAIL() << "no error";
    } catch (const LessonError& e) {
        EXPECT_EQ(e.file(), "my.json");
        EXPECT_EQ(e.line(), 4);  // the radius's own line in the lesson file
        EXPECT_EQ(e.key(), "scene.circles[0].radius");
    }
}

TEST(Practice, A3DRayThroughAnInlineSceneRecordsItsWalk) {
    const Lesson l = loadLessonText(
        lessonWithScene(
            R"({"objects": [{"type": "sphere", "center": [0.5, 0.5, 0.5], "radius": 0.5},
                                         {"type": "sphere", "center": [3.5, 0.5, 0.5], "radius": 0.5}]})",
            "[0.25, 0.9, 0.95, 1, 0, 0]"),
        "l.json");
    EXPECT_EQ(l.trace.kind, LessonTrace::Kind::Ray3D);
    const LessonRun run = runLesson(l);
    int cells = 0;
    for (const Event& e : run.log->events()) cells += std::holds_alternative<DdaCell>(e);
    EXPECT_GE(cells, 1);
    // A 3D ray on a 2D scene is an error naming the trace.
    EXPECT_THROW(
        runLesson(loadLessonText(
            lessonWithScene(R"({"dimensions": 2, "circles": [{"center": [0, 0], "radius": 1}]})",
                            "[0, 0, 0, 1, 1, 1]"),
            "l.json")),
        LessonError);
}

TEST(Practice, AdviceAtTheStartPointsToTheGivenDataNotTheInspector) {
    // The set-up questions wait before the trace's first event: nothing is in the inspector yet.
    const PracticeInstance inst = makePractice("dda-2d", 3, PracticeLevel::Easy);
    int seen = 0;
    for (const Exercise& ex : inst.lesson.exercises) {
        if (ex.at.mode != ReplayPosition::Mode::Start) continue;
        ++seen;
        for (const Language lang : {Language::En, Language::It}) {
            const std::string advice = retryAdvice(ex, true, false, lang);
            EXPECT_EQ(advice.find("inspector"), std::string::npos) << ex.id << ": " << advice;
            EXPECT_EQ(advice.find("ispettore"), std::string::npos) << ex.id << ": " << advice;
            EXPECT_EQ(advice.find("current cell"), std::string::npos) << ex.id << ": " << advice;
        }
    }
    EXPECT_GE(seen, 2);  // the first cell and the tDelta at least
}
