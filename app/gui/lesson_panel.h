#pragma once
// The lesson panel: the lesson's text, its steps (each puts the replay somewhere) and its
// exercises, checked against the recorded trace by the lesson engine (course/exercise.h). The
// main window opens lessons and moves the replay; the panel asks for it through signals.
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

/// Who a lesson is run for. Quiz: a student answers; every unsolved exercise holds the replay at
/// its position and the prompts after it. Presenting: a lecturer in front of the room; every
/// step and view is free, the exercises are questions to the room, an answer is shown only when
/// the lecturer reveals that one. Lecturer: preparing; every answer is shown.
enum class LessonMode { Quiz, Presenting, Lecturer };

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
    /// Forgets a sequence answer's clicked cells (the 2D view draws them).
    void clearSequence();
    void check();
    void hint();
    /// Whether the shown exercise's answer lies past where the replay is held.
    bool replayHeldBeforeAnswer() const;
    /// What the student answered, as text parseAnswer reads ("" when nothing is chosen yet).
    QString typedAnswer() const;
    /// The sweep's rows for grading a sweep_pick, or null before the sweep has run.
    const std::vector<GridSweepRow>* sweepRows() const;
    /// Every part's enabled and shown state (the steps, the notes, the exercise box), derived
    /// from the panel's state alone; called after every change of it.
    void updateWidgets();
    /// Scrolls the lesson text so the step's own text is in sight (its heading at the top when
    /// the whole does not fit), not the notes under it.
    void keepStepInView();
    /// The lesson's or a step's slide errata, as marked boxes at the end of the text.
    void appendErrata(QTextCursor& at, const std::vector<Erratum>& errata);

    Language lang_ = Language::En;
    Lesson lesson_;
    LogRef log_;
    std::map<std::string, LogRef> others_;  // by LessonSetup::key(): the other structures' traces
    bool hasLesson_ = false;
    LessonMode mode_ = LessonMode::Quiz;
    bool exploring_ = false;
    std::optional<bool> exploringSaid_;  // what exploringChanged last said
    QString heldNote_;
    int stepAnchor_ = -1;  // where the step's text starts in the lesson text
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

    QComboBox* picker_ = nullptr;
    QTextBrowser* text_ = nullptr;
    QWidget* noteRow_ = nullptr;
    QLabel* note_ = nullptr;
    QLabel* heldLabel_ = nullptr;
    QWidget* stepRow_ = nullptr;
    QLabel* stepLabel_ = nullptr;
    QPushButton* prevStep_ = nullptr;
    QPushButton* nextStep_ = nullptr;
    QGroupBox* exerciseBox_ = nullptr;
    QWidget* exerciseHeader_ = nullptr;
    QLabel* exerciseLabel_ = nullptr;
    QPushButton* openButton_ = nullptr;
    QLabel* exploreNote_ = nullptr;
    QLabel* waitNote_ = nullptr;  // an exercise after a held one: what it waits for
    QScrollArea* exerciseScroll_ = nullptr;
    QWidget* exerciseBody_ = nullptr;
    QWidget* buttonRow_ = nullptr;
    QLabel* hints_ = nullptr;
    QLabel* prompt_ = nullptr;
    QString promptSource_, hintsSource_;  // their Markdown, as the lesson gives it
    QLineEdit* answer_ = nullptr;
    QComboBox* candidates_ = nullptr;
    QWidget* choiceBox_ = nullptr;  // a choice exercise's radio buttons
    QButtonGroup* choiceGroup_ = nullptr;
    QPushButton* clearButton_ = nullptr;   // a sequence answer: start again
    QComboBox* sweepPicker_ = nullptr;     // a sweep_pick exercise: the sweep's resolutions
    QList<QPoint> sequence_;               // cells clicked for a sequence answer, in order
    std::vector<GridSweepRow> sweepRows_;  // the sweep's table, once run (sweep_pick grades it)
    QPushButton* checkButton_ = nullptr;
    QPushButton* hintButton_ = nullptr;
    QPushButton* revealButton_ = nullptr;
    QLabel* feedback_ = nullptr;
    QPushButton* sweepButton_ = nullptr;
    QPushButton* compareButton_ = nullptr;  // a step's "compare" list
    QTableWidget* sweepTable_ = nullptr;
};

}  // namespace raystep::gui
