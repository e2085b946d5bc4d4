// The lesson panel's exercises: the shown one made ready in the exercise box, an answer read
// from its input and checked against the trace (course/exercise.h), recorded in the progress,
// with feedback by mode; hints one a press; the answer revealed (presenting and lecturer modes).
#include "lesson_panel.h"

#include "exercise_box.h"
#include "sweep_table.h"

#include <QStringList>

namespace raystep::gui {

namespace {
QString q(const std::string& s) {
    return QString::fromStdString(s);
}
using Tone = ExerciseBox::Tone;
}  // namespace

AnswerContext LessonPanel::answerContext(const Exercise& ex, bool waits) const {
    AnswerContext ctx;
    ctx.lang = lang_;
    ctx.log = log_ ? logOf(ex.setup).get() : nullptr;
    ctx.dims = log_ ? log_->dims() : 2;
    ctx.resolutions = lesson_.sweep ? &lesson_.sweep->resolutions : nullptr;
    ctx.waits = waits;
    return ctx;
}

void LessonPanel::refreshExercise() {
    box_->clearAnswer();
    if (lesson_.exercises.empty()) return;
    const Exercise& ex = lesson_.exercises[exercise_];
    // An exercise that waits for a held one shows nothing of itself: no prompt, hint or choice.
    const bool waits = waitingFor(exercise_).has_value();
    hintsShown_ = 0;
    revealed_ = false;
    box_->showExercise(ex, answerContext(ex, waits));
    if (mode_ == LessonMode::Lecturer && log_ && !waits) revealAnswer();
}

void LessonPanel::fillCell(int x, int y) {
    if (!hasLesson_ || exploring_ || !exerciseOpen_ || lesson_.exercises.empty() ||
        !box_->input()->isVisible())
        return;
    if (box_->input()->fillCell(x, y)) check();
}

bool LessonPanel::submit(const QString& answer) {
    if (!hasLesson_ || lesson_.exercises.empty()) return false;
    box_->input()->setAnswer(answer);
    box_->setCorrect(false);
    check();
    return box_->correct();
}

QString LessonPanel::feedback() const {
    return box_->feedback();
}
QString LessonPanel::exerciseText() const {
    return box_->promptText();
}
QString LessonPanel::hintsText() const {
    return box_->hintsText();
}

void LessonPanel::check() {
    if (!hasLesson_ || !log_ || lesson_.exercises.empty()) return;
    // While exploring, the exercises wait (their box is disabled; a script may still call).
    if (exploring_) {
        box_->setCorrect(false);
        box_->say(Tone::Note, box_->exploreNote());
        return;
    }
    // One after a held exercise waits (its prompt is not shown; a script may still call).
    if (waitingFor(exercise_)) {
        box_->setCorrect(false);
        box_->say(Tone::Note, box_->waitNote());
        return;
    }
    heldNote_.clear();
    if (!exerciseOpen_) {
        exerciseOpen_ = true;  // answering an exercise is working on it: it holds again
        putAway_.erase(exercise_);
        updateWidgets();
        emit quizChanged();
    }
    const Exercise& ex = lesson_.exercises[exercise_];
    const AnswerInput* input = box_->input();
    const QString typed = input->text();
    if (typed.isEmpty() && input->choosesAnOption()) {
        box_->setCorrect(false);
        box_->say(Tone::Note, tr("Pick one of the options first."));
        return;
    }
    if (input->needsSweep() && !sweepRows()) {
        // Graded from the sweep's table: run it first (in the background).
        box_->setCorrect(false);
        box_->say(Tone::Note, tr("The answer is graded from the sweep's table: the sweep runs now; "
                                 "check again when its table is shown."));
        emit sweepRequested();
        return;
    }
    std::string why;
    const auto answer = parseAnswer(ex, typed.toStdString(), &why, lang_);
    if (!answer) {
        box_->setCorrect(false);
        box_->say(Tone::Note, tr("Cannot read that answer: %1.").arg(q(why)));
        return;
    }
    Verdict v;
    try {
        v = checkAnswer(ex, *logOf(ex.setup), *answer, lang_, lesson_.file, sweepRows());
    } catch (const LessonError& e) {
        // A lesson whose trace lacks what the exercise asks about: say so, grade nothing.
        box_->setCorrect(false);
        box_->say(Tone::Note, q(e.what()));
        return;
    }
    // The course's rule (recordAnswer): once solved, an answer is no attempt and is not kept.
    // Only a student's answers are the student's progress: the room's (presenting) and the
    // lecturer's are not recorded, and a right one there reveals that exercise's answer.
    const bool quiz = mode_ == LessonMode::Quiz;
    const bool wasSolved =
        quiz ? recordAnswer(*progress_, ex.id, typed.toStdString(), v.correct) : solved(exercise_);
    const int attempts = quiz ? record(exercise_).attempts : 0;
    if (!quiz && v.correct) revealed_ = true;
    box_->setCorrect(v.correct);
    // Right: why, from the trace. Wrong: try again; the explanation after three tries.
    if (v.correct) {
        box_->say(Tone::Right, tr("Right. %1").arg(q(v.feedback)));
    } else if (wasSolved && mode_ != LessonMode::Presenting) {
        // Solved before: the attempt is not counted against the student.
        box_->say(Tone::Wrong,
                  tr("Not right. The answer is %1: %2").arg(q(v.expected), q(v.feedback)));
    } else {
        // A slip the answer betrays is named at once, with the student's own numbers; else
        // where the answer can be worked out. The answer itself: after three tries in quiz
        // mode, at once in lecturer mode, never in front of the room (Show answer reveals it).
        const QString advice =
            v.slip.empty()
                ? q(raystep::retryAdvice(ex, replayHeldBeforeAnswer(),
                                         hintsShown_ < static_cast<int>(ex.hints.size()), lang_))
                : q(v.slip);
        box_->say(Tone::Wrong,
                  mode_ == LessonMode::Presenting ? tr("Not right yet. %1").arg(advice)
                  : attempts >= 3 || mode_ == LessonMode::Lecturer
                      ? tr("Not right. The answer is %1: %2").arg(q(v.expected), q(v.feedback))
                      : tr("Not right yet (try %1 of 3). %2").arg(attempts).arg(advice));
    }
    updateWidgets();
    box_->showFeedback();
    if (quiz) emit answered(q(ex.id), v.correct, typed);
    // Answered right: the replay may go past the exercise now (or the room's question ends).
    if (v.correct && !wasSolved) emit quizChanged();
}

LessonProgress::ExerciseRecord& LessonPanel::record(int exercise) {
    return progress_->exercises[lesson_.exercises[exercise].id];
}

bool LessonPanel::solved(int exercise) const {
    const auto it = progress_->exercises.find(lesson_.exercises[exercise].id);
    return it != progress_->exercises.end() && it->second.correct;
}

void LessonPanel::hint() {
    // One more hint each press: a nudge, then the formula, then the worked first step.
    const Exercise& ex = lesson_.exercises[exercise_];
    if (hintsShown_ >= static_cast<int>(ex.hints.size())) return;
    ++hintsShown_;
    QStringList shown;
    for (int k = 0; k < hintsShown_; ++k)
        shown << tr("**Hint %1 of %2.** %3")
                     .arg(k + 1)
                     .arg(ex.hints.size())
                     .arg(q(ex.hints[k].in(lang_)));
    box_->showHints(shown.join(QStringLiteral("\n\n")),
                    hintsShown_ < static_cast<int>(ex.hints.size()));
}

const std::vector<GridSweepRow>* LessonPanel::sweepRows() const {
    return sweepRows_.empty() ? nullptr : &sweepRows_;
}

bool LessonPanel::replayHeldBeforeAnswer() const {
    if (!log_ || mode_ != LessonMode::Quiz) return false;
    const Exercise& ex = lesson_.exercises[exercise_];
    const auto held = heldBy(lesson_.setupOf(ex.setup).key());
    const auto answerAt = answerEventIndex(ex, *logOf(ex.setup), lesson_.file);
    return held && answerAt && *answerAt >= held->second;
}

void LessonPanel::revealAnswer() {
    // Quiz mode: the answer comes after three tries, never from a button.
    if (!log_ || !hasLesson_ || lesson_.exercises.empty() || mode_ == LessonMode::Quiz ||
        waitingFor(exercise_))
        return;
    const Exercise& ex = lesson_.exercises[exercise_];
    if (box_->input()->needsSweep() && !sweepRows()) {
        box_->say(Tone::Answer, tr("Run the sweep to see the answer: it is read from its table."));
        return;
    }
    Verdict v;
    try {
        v = checkAnswer(ex, *logOf(ex.setup), Answer{}, lang_, lesson_.file, sweepRows());
    } catch (const LessonError& e) {
        box_->say(Tone::Note, q(e.what()));
        return;
    }
    box_->say(Tone::Answer, tr("Answer: %1. %2").arg(q(v.expected), q(v.feedback)));
    box_->showFeedback();
    if (!revealed_) {
        revealed_ = true;
        emit quizChanged();  // presenting: what lies past the cursor may show now
    }
}

void LessonPanel::showSweep(const std::vector<GridSweepRow>& rows) {
    sweepRows_ = rows;
    sweepTable_->showRows(rows);
}

}  // namespace raystep::gui
