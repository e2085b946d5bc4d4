// The slips a wrong answer betrays, named with the student's own number (lessons.md F7), on the
// built-in lessons' exercises. Every wrong number is worked by hand (Python fractions):
// - L12's sphere, o = (0, 1, 7), d = (0, 0, -2), c = 0, R = 3: A = 4, B = 2 (-2 · 7) = -28,
//   C = 1 + 49 - 9 = 41, Δ = 784 - 656 = 128, t = (28 - √128) / 8 = 2.08579; divided by 2 only
//   (28 - √128) / 2 = 8.34315, by A only (28 - √128) / 4 = 4.17157, the half-b form's root over
//   2A, t / 2 = 1.04289; the half-b form's b = B/2 = -14 and its discriminant Δ/4 = 32.
// - L6's circle, c = (4.3, 2.3), r = 1/4, ray (2/5, 2/5) + t (4/5, 2/5): a = 4/5, b = -97/25,
//   c' = 7503/400, b² - a c' = 121/2500 = (11/50)²: t0 = 183/40 = 4.575, the far root
//   t1 = 41/8 = 5.125, t0 / 2 = 183/80 = 2.2875. tMaxX in (2, 1) = (3 - 2/5) / (4/5) = 13/4, in
//   (3, 1) the next cell's, (4 - 2/5) / (4/5) = 9/2.
// - L7's first voxel (2, 1, 3), entered through the face z = 2 going -z: (2, 1, 4) is outside.
// - L13's tie in (0, 0): the slides' loop enters (0, 1), X alone (1, 0); the exact walk (1, 1).
// - L12's reflection hit, u = 0.324586 and v = 0.444075 (lessons.md, Appendix A): u and v
//   swapped.
#include "course/answer_leaks.h"
#include "course/exercise.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>

namespace raystep {
namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// The slip named for `typed` as the answer to exercise `id` of lesson `lesson`, in `lang`.
std::string slipFor(const std::string& lesson, const std::string& id, const std::string& typed,
                    Language lang = Language::En) {
    static std::map<std::string, std::pair<Lesson, std::shared_ptr<LessonRun>>> runs;
    auto it = runs.find(lesson);
    if (it == runs.end()) {
        Lesson l = loadLesson(lesson);
        auto run = std::make_shared<LessonRun>(runLesson(l));
        it = runs.emplace(lesson, std::pair{std::move(l), std::move(run)}).first;
    }
    const Lesson& l = it->second.first;
    const LessonRun& run = *it->second.second;
    const Exercise* ex = l.exercise(id);
    if (!ex) {
        ADD_FAILURE() << lesson << " has no exercise " << id;
        return "";
    }
    std::string why;
    const auto answer = parseAnswer(*ex, typed, &why, lang);
    if (!answer) {
        ADD_FAILURE() << typed << ": " << why;
        return "";
    }
    // Each exercise on its own structure's trace (a spot_bug's is its replayed walk).
    const LessonLogs logs = run.logs();
    const Verdict v =
        checkAnswer(*ex, logs.of(ex->setup), *answer, lang, l.file, nullptr, run.scene.get());
    EXPECT_FALSE(v.correct) << typed;
    // A slip is shown at once, with two tries left and the exercises after this one still open:
    // it names the student's mistake, not this answer (the three tries would be one) nor a later
    // one (L6's 'one step later' slip once named the next cell, exercise 4's answer).
    for (auto other = l.exercises.begin() + (ex - l.exercises.data()); other != l.exercises.end();
         ++other) {
        if (other->kind == ExerciseKind::Choice || other->kind == ExerciseKind::Count ||
            other->kind == ExerciseKind::SweepPick)
            continue;
        const AnswerForms forms =
            answerForms(*other, logs.of(other->setup), l.file, run.scene.get(), nullptr);
        // The student's own number may be another exercise's answer ("0.4441 is v, not u").
        if (const auto found = findAnswer(forms, v.slip, TextRole::Prose); found && *found != typed)
            ADD_FAILURE() << lesson << " " << id << " '" << typed << "': the slip gives "
                          << other->id << "'s answer away (" << *found << "): " << v.slip;
    }
    return v.slip;
}

TEST(Slips, TheSpheresRootHalvedOrDoubled) {
    const std::string twoOnly = slipFor("12", "sphere-t", "8.343");
    EXPECT_TRUE(has(twoOnly, "8.343 is (−B ∓ √Δ) / 2: divided by 2 but not by A = 4")) << twoOnly;
    const std::string aOnly = slipFor("12", "sphere-t", "4.1716");
    EXPECT_TRUE(has(aOnly, "4.1716 is (−B ∓ √Δ) / A: divided by A but not by 2")) << aOnly;
    const std::string halfB = slipFor("12", "sphere-t", "1.0429");
    EXPECT_TRUE(has(halfB, "1.0429 is half the root: with the half-b form (b = B/2 = -14)"))
        << halfB;
    // The far root stays "the other root"; no division at all stays the slide's missing /2A.
    EXPECT_TRUE(has(slipFor("12", "sphere-t", "4.91421"), "is the other root"));
    EXPECT_TRUE(has(slipFor("12", "sphere-t", "16.686"), "without the division by 2A"));
    // In Italian, with the student's decimal comma.
    EXPECT_TRUE(has(slipFor("12", "sphere-t", "8,343", Language::It), "8,343"));
}

TEST(Slips, TheHalfBFormsBAndDiscriminant) {
    EXPECT_TRUE(has(slipFor("12", "sphere-b", "-14"), "the half-b form's b = B/2"));
    EXPECT_TRUE(has(slipFor("12", "sphere-discriminant", "32"), "the half-b form's discriminant"));
    EXPECT_TRUE(has(slipFor("12", "sphere-discriminant", "32", Language::It),
                    "il discriminante della forma con b dimezzato"));
}

TEST(Slips, ACirclesFarRootAndAHalvedRoot) {
    const std::string far = slipFor("6", "nearest-hit", "5.125");
    EXPECT_TRUE(has(far, "5.125 is the far root, where the ray leaves the circle")) << far;
    EXPECT_FALSE(has(far, "4.575")) << far;  // the right t waits for the third try
    const std::string half = slipFor("6", "nearest-hit", "2.2875");
    EXPECT_TRUE(has(half, "2.2875 is half the root: one division by 2 too many")) << half;
    // The sphere of a 3D hit: twice t is the slide's missing /2A with a unit d.
    EXPECT_TRUE(has(slipFor("12", "sphere-test", "hit 15.755"), "is twice the root"));
}

TEST(Slips, SwappedUAndV) {
    EXPECT_TRUE(has(slipFor("12", "barycentric-u", "0.4441"), "0.4441 is v, not u"));
    EXPECT_TRUE(has(slipFor("12", "barycentric-v", "0.3246"), "0.3246 is u, not v"));
}

TEST(Slips, TheNextCellsTMax) {
    const std::string s = slipFor("6", "tmax-x-after-step", "4.5");
    EXPECT_TRUE(has(s, "4.5 is tMax.x one step later, once the walk has left this cell: in (2, 1)"))
        << s;
    // The cell before's stays named as it was: 13/4 - 5/4 = 2.
    EXPECT_TRUE(has(slipFor("6", "tmax-x-after-step", "2"), "the tMax.x of the cell before"));
}

TEST(Slips, AVoxelOutsideTheGridOffByOneOnTheEntryFace) {
    const std::string s = slipFor("7", "first-voxel", "2,1,4");
    EXPECT_TRUE(has(s, "(2, 1, 4) lies outside the grid, off by one on the entry face")) << s;
    EXPECT_TRUE(has(s, "the face z = 2")) << s;
    // Inside the grid, another voxel: no such slip.
    EXPECT_EQ(slipFor("7", "first-voxel", "2,1,2"), "");
}

TEST(Slips, TheSlidesTieAnswerAndOneAxisOfATie) {
    const std::string detour = slipFor("13", "tie-cell", "0,1");
    EXPECT_TRUE(has(detour, "(0, 1) is the slides' conservative detour")) << detour;
    EXPECT_TRUE(has(slipFor("13", "tie-cell", "0,1", Language::It),
                    "la deviazione conservativa delle slide"));
    EXPECT_TRUE(has(slipFor("13", "tie-cell", "1,0"), "(1, 0) is a step along X alone"));
    // Not a tie: a step along the axis whose tMax is not the least (tMaxX = 3.25 < tMaxY = 4).
    EXPECT_TRUE(has(slipFor("6", "next-cell", "2,2"),
                    "(2, 2) is a step along Y, but in (2, 1) tMaxY = 4 is not the smallest"));
}

/// The explanation of exercise `id` of lesson `lesson` for the answer `typed`.
std::string feedbackFor(const std::string& lesson, const std::string& id, const std::string& typed,
                        Language lang = Language::En) {
    const Lesson l = loadLesson(lesson);
    const LessonRun run = runLesson(l);
    const Exercise* ex = l.exercise(id);
    std::string why;
    const auto answer = parseAnswer(*ex, typed, &why, lang);
    EXPECT_TRUE(answer.has_value()) << why;
    return checkAnswer(*ex, *run.log, answer.value_or(Answer{}), lang, l.file, nullptr,
                       run.scene.get())
        .feedback;
}

// lessons.md F5 and F8: the explanations' wording and numbers.
TEST(Feedback, ACountUpToAnEventSaysFromTheStart) {
    // L9's centre ray walks (2,2,4) (2,2,3) (2,2,2) (2,2,1) up to its hit: 4 (Appendix A).
    const std::string en = feedbackFor("9", "cells-walked", "3");
    EXPECT_TRUE(has(en, "Cells visited from the start until after the 1st intersection found: 4."))
        << en;
    const std::string it = feedbackFor("9", "cells-walked", "3", Language::It);
    EXPECT_TRUE(has(it, "dall'inizio fino a dopo la 1ª intersezione trovata: 4.")) << it;
}

TEST(Feedback, NumbersAsWrittenNegativesBracketedOnlyAsOperands) {
    // B = 2 (0 · 0 + 0 · 1 + (-2) · 7) = -28: the operand in brackets, the result not.
    const std::string b = feedbackFor("12", "sphere-b", "-27");
    EXPECT_TRUE(has(b, "(-2) · 7) = -28.")) << b;
    // The slab test's entries and exits are listed plainly: z [-1.2, 6.8].
    EXPECT_TRUE(has(feedbackFor("7", "slab-exit", "7"), "z [-1.2, 6.8]"));
    // An answers file's 0.4 is echoed as 0.4.
    const AnswerSheet sheet = loadAnswerSheet(
        R"({"lesson": 6, "answers": {"tdelta-y": 0.4, "next-cell": [3, 1]}})", "s.json");
    EXPECT_EQ(sheet.answers.at("tdelta-y"), "0.4");
    EXPECT_EQ(sheet.answers.at("next-cell"), "3,1");
}

TEST(Feedback, AChoiceAndItsWhyAreJoinedOnce) {
    const std::string f = feedbackFor("6", "first-hit", "a");
    EXPECT_FALSE(has(f, ".:")) << f;
    EXPECT_TRUE(has(f, "holds the nearest one: The cells come in order")) << f;
}

TEST(Feedback, OneItemIsSingular) {
    const std::string en = feedbackFor("6", "walk-on", "3,2");
    EXPECT_TRUE(has(en, "Your order stops after 1 item; the trace goes on with (4, 2).")) << en;
    EXPECT_TRUE(has(feedbackFor("6", "walk-on", "3,2", Language::It), "dopo 1 elemento;"));
}

TEST(Feedback, TheCellBelowOnlyForAPointOnAFace) {
    // L6's ray starts inside cell X = 3 (3 < 3.7 < 4): no face to choose a side of.
    EXPECT_FALSE(has(feedbackFor("6", "tmax-negative", "1"), "on a face"));
    // L7's ray enters the box through the face y = 2 going down: the cell below it, Y = 7.
    EXPECT_TRUE(has(feedbackFor("7", "first-cell-outside", "8"), "on a face, the cell below it"));
}

TEST(RetryAdvice, NeverStepTheReplayWhileHeldNorForAnAnswerOutsideTheTrace) {
    for (const Lesson& l : builtinLessons())
        for (const Exercise& ex : l.exercises)
            for (const bool held : {false, true})
                for (const bool hint : {false, true}) {
                    SCOPED_TRACE(l.id + " " + ex.id + (held ? " held" : "") +
                                 (hint ? " hint" : ""));
                    const std::string en = retryAdvice(ex, held, hint, Language::En);
                    const std::string it = retryAdvice(ex, held, hint, Language::It);
                    // An overlap's answer is the structure's boxes, drawn at every step; a
                    // spot_bug's replay is never held: its whole wrong walk is what is studied.
                    const bool inTrace =
                        ex.kind != ExerciseKind::Compute && ex.kind != ExerciseKind::Choice &&
                        ex.kind != ExerciseKind::SweepPick && ex.kind != ExerciseKind::Overlap &&
                        ex.kind != ExerciseKind::SpotBug;
                    // Step the replay only when it can be stepped and the answer is in it.
                    EXPECT_EQ(has(en, "Step the replay"), inTrace && !held) << en;
                    EXPECT_EQ(has(it, "Fai avanzare la riproduzione"), inTrace && !held) << it;
                    EXPECT_EQ(has(en, "until you answer"), inTrace && held) << en;
                    // Held before the first event: the inspector has nothing to show yet.
                    if (held && ex.at.mode == ReplayPosition::Mode::Start)
                        EXPECT_FALSE(has(en, "inspector")) << en;
                    EXPECT_EQ(has(en, "Or ask for a hint."), hint) << en;
                    EXPECT_EQ(has(it, "Oppure chiedi un suggerimento."), hint) << it;
                    EXPECT_NE(en, it);
                }
    // By kind: a compute exercise is worked from its prompt, a sweep from its table.
    const Lesson l12 = loadLesson("12");
    EXPECT_TRUE(has(retryAdvice(*l12.exercise("sphere-t"), false, false, Language::En),
                    "from the data the prompt gives"));
    const Lesson l6 = loadLesson("6");
    EXPECT_TRUE(has(retryAdvice(*l6.exercise("next-cell"), true, false, Language::En),
                    "compare the current cell's tMax"));
}

}  // namespace
}  // namespace raystep
