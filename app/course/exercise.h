#pragma once
// Exercises: a student's answer as typed, the right answer read from the recorded trace (or, for
// a compute exercise, from raystep's kernels; for a choice, the lesson file; for a sweep_pick, the
// sweep's rows), and the check of one against the other with the explanation and, where a wrong
// answer betrays a known slip, its name.
#include "course/grid_sweep.h"
#include "course/lesson.h"

#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace raystep {

/// A student's answer. NextCell: the cell's indices; Value, Count, Compute: one number;
/// PickSplit: axis (0, 1, 2) and position; HitOrMiss: hit, and t when asked; Choice: the option
/// (0-based); Sequence: the cells' indices one after the other, or the node ids; SweepPick: the
/// resolution (cells per axis).
struct Answer {
    std::vector<double> numbers;
    std::optional<bool> hit;
    int perItem = 1;  // Sequence of cells: indices per cell (2 or 3)
};
/// Reads an answer as typed: "2,1" (cell), "0.75" or "0,75" (value, count, compute), "x=2.5"
/// (split), "miss" / "mancata" or "hit 3.55" / "colpita 3,55" (hit or miss), "b" or "2" (choice),
/// "0,0; 1,0; 1,1" or "(0,0) (1,0)" (cells in order), "0 1 4" (nodes), "8" (a resolution).
/// nullopt with `why` set, in `lang`, when it is not such an answer.
std::optional<Answer> parseAnswer(const Exercise& ex, std::string_view text, std::string* why,
                                  Language lang = Language::En);
/// An answer as a student would type it in `lang` (English: as an answers file holds it).
std::string formatAnswer(const Exercise& ex, const Answer& a, Language lang = Language::En);

/// The candidates of the split a PickSplit exercise is about (those the app lists).
std::vector<SplitCandidate> splitCandidates(const Exercise& ex, const EventLog& log);

/// The right answer; throws LessonError (naming the exercise's line in `lessonFile`) when the
/// trace does not hold what the exercise asks about. A sweep_pick needs the sweep's rows.
Answer referenceAnswer(const Exercise& ex, const EventLog& log, const std::string& lessonFile,
                       const std::vector<GridSweepRow>* sweep = nullptr);

/// The lesson's scene, when the caller has it: a missed test's feedback then names the cause.
using LessonScene = std::variant<Scene, Scene2D>;

struct Verdict {
    bool correct = false;
    std::string expected;  // the reference answer, as text in the verdict's language
    std::string feedback;  // the slip (if any), then why the right answer is right
    std::string slip;      // the slip the wrong answer betrays, with the student's numbers
};
Verdict checkAnswer(const Exercise& ex, const EventLog& log, const Answer& answer, Language lang,
                    const std::string& lessonFile, const std::vector<GridSweepRow>* sweep = nullptr,
                    const LessonScene* scene = nullptr);

/// The answer box's placeholder, in `lang`, for the kinds typed in one: for a cell or a
/// sequence the cell's indices for the trace's `dims` (X,Y or X,Y,Z), and the 2D view's click
/// only where there is one. Empty for the kinds answered by choosing (split, choice, sweep).
std::string answerPlaceholder(const Exercise& ex, int dims, Language lang);

/// The answer input an exercise wants, Qt-free: the app chooses its widget from it (one table,
/// app/gui/answer_inputs.cpp). Text: a line typed; Number: a line where only a number can be
/// typed (a letter cannot); SplitPicker: the split's candidates listed; Options: one button an
/// option; SweepRows: the sweep's resolutions listed.
struct AnswerInputSpec {
    enum class Widget { Text, Number, SplitPicker, Options, SweepRows };
    /// What a click on a cell of the 2D view does to the answer (where there is a 2D view).
    enum class ViewClick { None, Fills, Appends };
    Widget widget = Widget::Text;
    ViewClick click = ViewClick::None;
};
AnswerInputSpec answerInput(const Exercise& ex);

/// What a wrong answer's feedback advises for the next try, in `lang`: the panel shows it after
/// "Not right yet (try k of 3)." when no slip is named. By the exercise's kind; `replayHeld`: quiz
/// mode holds the replay at the exercise's position (it is open and not yet answered right);
/// `hintLeft`: Hint would show one more. Never "step the replay" while the replay is held, nor for
/// a compute, choice or sweep_pick exercise, whose answer is not in the trace.
std::string retryAdvice(const Exercise& ex, bool replayHeld, bool hintLeft, Language lang);

/// Quiz mode: while `ex` is open (not yet answered right), the replay must not pass this cursor
/// (its `at`, resolved in `log`). nullopt for the kinds whose answer is not in the trace (choice,
/// compute, sweep_pick) or when the position is not in the trace.
std::optional<std::size_t> quizLimit(const Exercise& ex, const EventLog& log);

/// The index of the event the reference answer is read from (the first one, for counts and
/// sequences); nullopt for kinds not read from the trace.
std::optional<std::size_t> answerEventIndex(const Exercise& ex, const EventLog& log,
                                            const std::string& lessonFile);

}  // namespace raystep
