#pragma once
// The lesson panel: the lesson's text, its steps (each puts the replay somewhere) and its
// exercises, checked against the recorded trace by the lesson engine (course/exercise.h). The
// main window opens lessons and moves the replay; the panel asks for it through signals.
#include "session.h"

#include "course/exercise.h"
#include "course/grid_sweep.h"
#include "course/lesson.h"
#include "course/progress.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;
class QTextBrowser;

namespace raystep::gui {

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
    void showLesson(const Lesson& lesson, LogRef log, LessonProgress* progress);
    /// The lesson's trace (null when no lesson is open).
    const LogRef& lessonLog() const { return log_; }
    /// The replay shows something else than the lesson's trace (`what`, e.g. "pixel (3, 4)"):
    /// say so and offer the way back; an empty `what` hides the note.
    void setReplayNote(const QString& what);
    QString replayNote() const;
    /// The picker shows the open lesson again (after a pick that could not be opened).
    void syncPicker();
    /// Free text when no lesson is open (a scene opened by hand, a build replay).
    void showText(const QString& markdown);
    bool hasLesson() const { return hasLesson_; }
    const Lesson& lesson() const { return lesson_; }
    void setLecturerMode(bool on);
    bool lecturerMode() const { return lecturer_; }

    int step() const { return step_; }
    int exercise() const { return exercise_; }
    void goToStep(int index);
    void selectExercise(int index);
    /// Types an answer and checks it (what the Check button does); true if right.
    bool submit(const QString& answer);
    QString feedback() const;
    QString exerciseText() const;
    void showSweep(const std::vector<GridSweepRow>& rows);

  public slots:
    /// A cell clicked in the 2D view fills a "next cell" answer.
    void fillCell(int x, int y);

  signals:
    void lessonRequested(const QString& id);
    /// "Back to the lesson's trace".
    void lessonTraceRequested();
    void stepShown(int index);
    void exerciseShown(int index);
    /// An answer was checked and recorded in the progress: the main window saves it.
    void answered(const QString& exerciseId, bool correct, const QString& answer);
    void sweepRequested();

  private:
    void refreshText();
    void refreshExercise();
    void check();
    void hint();
    void revealAnswer();

    Language lang_ = Language::En;
    Lesson lesson_;
    LogRef log_;
    bool hasLesson_ = false;
    bool lecturer_ = false;
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
    QWidget* stepRow_ = nullptr;
    QLabel* stepLabel_ = nullptr;
    QPushButton* prevStep_ = nullptr;
    QPushButton* nextStep_ = nullptr;
    QGroupBox* exerciseBox_ = nullptr;
    QLabel* exerciseLabel_ = nullptr;
    QLabel* prompt_ = nullptr;
    QLineEdit* answer_ = nullptr;
    QComboBox* candidates_ = nullptr;
    QPushButton* checkButton_ = nullptr;
    QPushButton* hintButton_ = nullptr;
    QPushButton* revealButton_ = nullptr;
    QLabel* feedback_ = nullptr;
    QPushButton* sweepButton_ = nullptr;
    QTableWidget* sweepTable_ = nullptr;
};

}  // namespace raystep::gui
