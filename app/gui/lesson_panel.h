#pragma once
// The lesson panel: the lesson's text, its steps (each puts the replay somewhere) and its
// exercises, checked against the recorded trace by the lesson engine (course/exercise.h). The
// main window opens lessons and moves the replay; the panel asks for it through signals. Its
// parts: the text and its steps (lesson_text.h), the exercise box (exercise_box.h) with its answer
// inputs (answer_inputs.h), the sweep's table (sweep_table.h); the panel holds the lesson's state,
// what quiz mode holds, and grades (lesson_panel_answers.cpp).
#include "answer_input.h"
#include "lesson_mode.h"
#include "session.h"

#include "course/exercise.h"
#include "course/grid_sweep.h"
#include "course/lesson.h"
#include "course/progress.h"

#include <QList>
#include <QPoint>
#include <QTextCursor>
#include <QWidget>

#include <map>
#include <optional>
#include <set>
#include <utility>

#include <vector>

class QButtonGroup;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QScrollArea;
class QTableWidget;
class QTextBrowser;

namespace raystep::gui {

class ExerciseBox;
class LessonText;
class SweepTable;

class LessonPanel : public QWidget {
    Q_OBJECT
  public:
    explicit LessonPanel(QWidget* parent = nullptr);

    void setLanguage(Language lang) { lang_ = lang; }
    /// The lessons the picker offers.
    void setLessons(const std::vector<Lesson>& lessons);
    /// Shows a lesson whose trace is `log`: the panel keeps its share of it, and checks every
    /// answer against it whatever the replay shows meanwhile (a clicked pixel, a build). The
    /// panel records answers into `progress` (the window's, which it saves on `answered`); null
    /// keeps them in the panel only.
    /// `others`: the same trace through each other structure a step or an exercise sets up, by
    /// LessonSetup::key(); each exercise is checked against its own structure's.
    void showLesson(const Lesson& lesson, LogRef log, LessonProgress* progress,
                    std::map<std::string, LogRef> others = {});
    /// The lesson's trace (null when no lesson is open).
    const LogRef& lessonLog() const { return log_; }
    /// The trace a step or an exercise of the lesson is about: its own structure's, else the
    /// lesson's.
    const LogRef& logOf(const std::optional<LessonSetup>& setup) const;
    /// Whether `log` is one of the open lesson's traces (any of its structures).
    bool isLessonLog(const LogRef& log) const;
    /// The replay shows something else than the lesson's trace (`what`, e.g. "pixel (3, 4)"):
    /// the student explores. Say so, offer the one way back, and disable the steps and the
    /// exercises (they are about the lesson's own trace). An empty `what` ends it. `hidden`:
    /// an exercise holds the replay, so the explored trace is not shown (Session::limit).
    void setReplayNote(const QString& what, bool hidden = false);
    QString replayNote() const;
    bool exploring() const { return exploring_; }
    /// An action refused because an exercise holds the replay (a pixel click, B, R, C): why,
    /// until the student next steps, picks an exercise or answers.
    void showHeldNote(const QString& text);
    QString heldNote() const;
    /// The picker shows the open lesson again (after a pick that could not be opened).
    void syncPicker();
    /// A part the window puts under the picker (the practice bar), shown and hidden by its owner.
    void setHeader(QWidget* header);
    /// Free text when no lesson is open (a scene opened by hand, a build replay).
    void showText(const QString& markdown);
    bool hasLesson() const { return hasLesson_; }
    const Lesson& lesson() const { return lesson_; }
    void setMode(LessonMode mode);
    LessonMode mode() const { return mode_; }
    /// Lecturer mode on, or back to quiz mode.
    void setLecturerMode(bool on) { setMode(on ? LessonMode::Lecturer : LessonMode::Quiz); }
    bool lecturerMode() const { return mode_ == LessonMode::Lecturer; }

    int step() const { return step_; }
    int exercise() const { return exercise_; }
    void goToStep(int index);
    /// Shows and opens exercise `index` (the replay goes to its position); in quiz mode, one
    /// after a held exercise is shown closed, its prompt waiting (waitingFor).
    void selectExercise(int index);
    /// Quiz mode: the held exercise before `index` whose answer the prompt and hints of `index`
    /// wait for (a later prompt may state an earlier answer); nullopt when none holds it.
    std::optional<int> waitingFor(int index) const;
    /// Puts the open exercise away: the student chooses to look past its position (the other
    /// unsolved exercises still hold the replay at theirs).
    void closeExercise();
    bool exerciseOpen() const { return hasLesson_ && exerciseOpen_; }
    /// Quiz mode: the exercise that stops the replay at its position (open, not yet answered
    /// right, lecturer mode off), if any.
    std::optional<int> quizExercise() const;
    /// The exercises that hold the replay: every unsolved one the student has not put away
    /// (quiz mode only). The replay stops at the earliest of their positions.
    std::vector<int> heldExercises() const;
    /// The held exercise whose position comes first, and that position (the replay's limit).
    /// Among the exercises of the structure `setupKey` (LessonSetup::key): a position is only
    /// comparable with another in the same trace.
    std::optional<std::pair<int, std::size_t>> heldBy(const std::string& setupKey) const;
    /// The same over the lesson's own structure, else the first structure with a held exercise
    /// (a message names it).
    std::optional<std::pair<int, std::size_t>> heldBy() const;
    /// Presenting mode: the shown exercise is a question to the room (open, unsolved, its answer
    /// in the trace and not revealed): nothing past the cursor is listed or counted meanwhile.
    bool asksTheRoom() const;
    /// Lessons > Show notes on the slides: the errata boxes under the texts.
    void setShowErrata(bool on);
    bool showErrata() const { return showErrata_; }
    /// The hints revealed so far for the shown exercise, one a line.
    QString hintsText() const;
    /// Types an answer and checks it (what the Check button does); true if right.
    bool submit(const QString& answer);
    /// Shows the answer of the shown exercise (the Show answer button; presenting and lecturer
    /// modes only).
    void revealAnswer();
    QString feedback() const;
    QString exerciseText() const;
    void showSweep(const std::vector<GridSweepRow>& rows);

  public slots:
    /// A cell clicked in the 2D view fills a "next cell" answer.
    void fillCell(int x, int y);

  signals:
    void lessonRequested(const QString& id);
    /// "Back to the lesson": its own trace, steps and exercises.
    void lessonTraceRequested();
    /// The exercise stopping the replay changed (opened, closed, answered right, lecturer mode).
    void quizChanged();
    void stepShown(int index);
    void exerciseShown(int index);
    /// An answer was checked and recorded in the progress: the main window saves it.
    void answered(const QString& exerciseId, bool correct, const QString& answer);
    void sweepRequested();
    /// The step's "Compare these structures on this ray" (its "compare" list).
    void compareRequested(const std::vector<StructureChoice>& choices);
    /// The cells of a sequence answer so far (the 2D view numbers them); empty when none.
    void sequenceChanged(const QList<QPoint>& cells);
    /// The student started or stopped exploring (the window's Back to the lesson follows).
    void exploringChanged(bool exploring);

  protected:
    void resizeEvent(QResizeEvent* e) override;
    bool eventFilter(QObject* o, QEvent* e) override;
    void showEvent(QShowEvent* e) override;

  private:
    void refreshText();
    void refreshExercise();
    void check();
    void hint();
    /// What the shown exercise's answer input needs (its trace, the sweep, the language).
    AnswerContext answerContext(const Exercise& ex, bool waits) const;
    /// Whether the shown exercise's answer lies past where the replay is held.
    bool replayHeldBeforeAnswer() const;
    /// The sweep's rows for grading a sweep_pick, or null before the sweep has run.
    const std::vector<GridSweepRow>* sweepRows() const;
    /// Every part's enabled and shown state (the steps, the notes, the exercise box), derived
    /// from the panel's state alone; called after every change of it.
    void updateWidgets();

    Language lang_ = Language::En;
    Lesson lesson_;
    LogRef log_;
    std::map<std::string, LogRef> others_;  // by LessonSetup::key(): the other structures' traces
    bool hasLesson_ = false;
    LessonMode mode_ = LessonMode::Quiz;
    bool exploring_ = false;
    std::optional<bool> exploringSaid_;  // what exploringChanged last said
    QString heldNote_;
    bool exerciseOpen_ = false;
    std::set<int> putAway_;  // exercises the student chose to look past (Put away)
    bool showErrata_ = true;
    int hintsShown_ = 0;
    bool revealed_ = false;  // Show answer pressed on the shown exercise (presenting)
    int step_ = 0;
    int exercise_ = 0;
    /// This exercise's record in the progress (made on first use).
    LessonProgress::ExerciseRecord& record(int exercise);
    bool solved(int exercise) const;
    LessonProgress* progress_ = nullptr;  // the window's, or ownProgress_
    LessonProgress ownProgress_;
    QString freeText_;
    std::vector<GridSweepRow> sweepRows_;  // the sweep's table, once run (sweep_pick grades it)

    QComboBox* picker_ = nullptr;
    LessonText* text_ = nullptr;
    QWidget* noteRow_ = nullptr;
    QLabel* note_ = nullptr;
    QLabel* heldLabel_ = nullptr;
    QWidget* stepRow_ = nullptr;
    QLabel* stepLabel_ = nullptr;
    QPushButton* prevStep_ = nullptr;
    QPushButton* nextStep_ = nullptr;
    ExerciseBox* box_ = nullptr;
    QPushButton* sweepButton_ = nullptr;
    QPushButton* compareButton_ = nullptr;  // a step's "compare" list
    SweepTable* sweepTable_ = nullptr;
};

}  // namespace raystep::gui
