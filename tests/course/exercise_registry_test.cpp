// The registry of exercise kinds (app/course/exercises/registry.cpp): one unit per ExerciseKind,
// named as the lesson format names it, and every built-in lesson's reference answers surviving
// formatAnswer then parseAnswer, in both languages.
#include "course/exercise.h"
#include "course/exercises/kind_unit.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace raystep {
namespace {

TEST(ExerciseRegistry, HoldsOneUnitPerKindNamedAsTheLessonFormatNamesIt) {
    const auto& units = exercises::kindUnits();
    EXPECT_EQ(units.size(), static_cast<std::size_t>(kExerciseKindCount));
    std::ifstream in(std::string(RAYSTEP_SOURCE_DIR) + "/docs/lesson-format.md");
    std::stringstream format;
    format << in.rdbuf();
    ASSERT_FALSE(format.str().empty());
    std::set<std::string> names;
    for (int k = 0; k < kExerciseKindCount; ++k) {
        const auto kind = static_cast<ExerciseKind>(k);
        int held = 0;
        for (const exercises::ExerciseKindUnit* u : units) held += u->kind() == kind;
        EXPECT_EQ(held, 1) << "kind " << k;
        const std::string name(exercises::unitOf(kind).name());
        EXPECT_EQ(name, exerciseKindName(kind));
        EXPECT_TRUE(names.insert(name).second) << name << " names two kinds";
        // Its row in the table of exercise types.
        EXPECT_NE(format.str().find("| `" + name + "` |"), std::string::npos)
            << name << " has no row in docs/lesson-format.md";
    }
}

TEST(ExerciseRegistry, ALessonNamesEveryKindByItsType) {
    // An unknown type's message lists every kind, in the registry's order.
    try {
        loadLessonText(
            "{\"format\": \"raystep-lesson\", \"version\": 1, \"id\": \"t\", \"number\": 1, "
            "\"title\": {\"en\": \"T\"}, \"text\": {\"en\": \"x\"}, \"scene\": \"lecture-grid\", "
            "\"setup\": {\"accel\": \"grid\"}, \"trace\": {\"ray\": \"example\"}, \"exercises\": "
            "[{\"id\": \"e\", \"type\": \"nope\", \"prompt\": {\"en\": \"?\"}}]}",
            "bad.json");
        ADD_FAILURE() << "an unknown type loads";
    } catch (const LessonError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "expected next_cell, value, pick_split, count, hit_or_miss, choice, "
                      "sequence, sweep_pick, compute, overlap or spot_bug"),
                  std::string::npos)
            << e.what();
    }
}

TEST(ExerciseRegistry, ReferenceAnswersRoundTripThroughTheirTypedForm) {
    std::set<ExerciseKind> seen;
    for (const Lesson& lesson : builtinLessons()) {
        const LessonRun run = runLesson(lesson);
        const LessonLogs logs = run.logs();
        const std::vector<GridSweepRow> sweep = sweepRowsIfNeeded(lesson, run);
        for (const Exercise& ex : lesson.exercises) {
            const EventLog& log = logs.of(ex.setup);
            const Answer ref = referenceAnswer(ex, log, lesson.file, &sweep);
            seen.insert(ex.kind);
            for (const Language lang : {Language::En, Language::It}) {
                const std::string typed = formatAnswer(ex, ref, lang);
                SCOPED_TRACE(lesson.id + " " + ex.id + " \"" + typed + "\"");
                EXPECT_FALSE(typed.empty());
                std::string why;
                const auto back = parseAnswer(ex, typed, &why, lang);
                ASSERT_TRUE(back) << why;
                EXPECT_EQ(formatAnswer(ex, *back, lang), typed);
                EXPECT_EQ(back->hit, ref.hit);
                // Numbers are typed rounded: the grader takes them, which is the round trip.
                EXPECT_TRUE(checkAnswer(ex, log, *back, lang, lesson.file, &sweep, run.scene.get())
                                .correct);
            }
        }
    }
    // The built-in lessons exercise every kind, so the loop above checks each unit.
    EXPECT_EQ(seen.size(), static_cast<std::size_t>(kExerciseKindCount));
}

TEST(ExerciseRegistry, AnswerInputFollowsTheKind) {
    Exercise ex;
    ex.kind = ExerciseKind::NextCell;
    EXPECT_EQ(answerInput(ex).click, AnswerInputSpec::ViewClick::Fills);
    ex.kind = ExerciseKind::Sequence;
    EXPECT_EQ(answerInput(ex).click, AnswerInputSpec::ViewClick::Appends);
    ex.ofNodes = true;
    EXPECT_EQ(answerInput(ex).click, AnswerInputSpec::ViewClick::None);
    EXPECT_EQ(answerInput(ex).widget, AnswerInputSpec::Widget::Text);
    ex.kind = ExerciseKind::PickSplit;
    EXPECT_EQ(answerInput(ex).widget, AnswerInputSpec::Widget::SplitPicker);
    ex.kind = ExerciseKind::Choice;
    EXPECT_EQ(answerInput(ex).widget, AnswerInputSpec::Widget::Options);
    ex.kind = ExerciseKind::SweepPick;
    EXPECT_EQ(answerInput(ex).widget, AnswerInputSpec::Widget::SweepRows);
    // Only a compute's box refuses letters; a value or a count is typed freely, as ever.
    ex.kind = ExerciseKind::Compute;
    EXPECT_EQ(answerInput(ex).widget, AnswerInputSpec::Widget::Number);
    for (const ExerciseKind k : {ExerciseKind::Value, ExerciseKind::Count}) {
        ex.kind = k;
        EXPECT_EQ(answerInput(ex).widget, AnswerInputSpec::Widget::Text);
        EXPECT_EQ(answerInput(ex).click, AnswerInputSpec::ViewClick::None);
    }
}

}  // namespace
}  // namespace raystep
