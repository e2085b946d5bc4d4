#pragma once
// The lesson controller: what the window does for the open lesson. It moves the replay to the
// lesson's steps and exercises, keeps and saves the student's progress, runs the grid sweep, and
// writes the lecture's help texts (texts/) into the lesson panel.
#include "progress_store.h"
#include "session.h"
#include "task_runner.h"

#include "course/lesson.h"
#include "course/lesson_trace.h"
#include "course/progress.h"

#include <QObject>

#include <map>
#include <optional>
#include <string>
#include <vector>

class QLabel;
class QMainWindow;
class QMenu;

namespace raystep::gui {

class EventList;
class LessonPanel;
class VtkView;

class LessonController : public QObject {
    Q_OBJECT
  public:
    /// What a worker makes of a lesson: its scene with the structure built, and its trace.
    /// One more structure a step or an exercise sets up: built over the lesson's scene, with
    /// the lesson's trace through it.
    struct Structure {
        SceneRef scene;
        LogRef trace;
    };
    struct Opened {
        SceneRef scene;
        LogRef trace;
        Lesson lesson;  // the lesson with its steps' computed notes (addStepNotes)
        std::map<std::string, Structure> others;  // by LessonSetup::key()
    };
    /// Loads the lesson's scene, builds its structure and records its trace; any thread.
    static Opened prepare(const Lesson& lesson, const ProgressFn& progress);
    /// How the session replays a lesson's trace.
    static LogKind logKind(const Lesson& lesson);

    /// `generation` counts the scenes the window has shown: a sweep for an older one is dropped.
    LessonController(QMainWindow& window, Session& session, TaskRunner& runner,
                     const std::uint64_t& generation, LessonPanel* panel, EventList* events,
                     VtkView* view3D);

    /// A new lesson's scene is about to be shown (its open has finished): the old lesson's hold
    /// and its notes about the replay end here, not on the new lesson's scene and trace.
    void replaceLesson();
    /// Shows a lesson whose trace the session now replays, at the step the progress was at.
    void show(const Lesson& lesson, const LogRef& trace,
              std::map<std::string, Structure> others = {});
    /// The text beside a scene opened by hand: its name, description and how to replay it.
    void showSceneIntro();
    void setLanguage(Language lang);
    Language language() const { return lang_; }
    /// The menu the built-in lessons are listed in (filled again on a change of language).
    void setLessonsMenu(QMenu* menu);
    const Progress& studentProgress() const { return studentProgress_; }
    /// The progress to add to (the practice's records); saved with the next answer or `save`.
    Progress& studentProgress() { return studentProgress_; }
    void save() { saveProgress(); }
    QString progressPath() const { return progressPath_; }
    /// The last save failed: the answers since are in memory only (the note says so).
    bool progressUnsaved() const { return unsaved_; }
    /// The window may close: nothing is unsaved, or saving again worked, or the student chose
    /// to quit without saving. Otherwise a question is opened (without a nested event loop)
    /// and false returned; its "Quit without saving" closes the window.
    bool allowClose();
    void exportProgressReport();

    /// "Back to the lesson": its own trace again, at the open exercise or the step shown.
    void backToLesson();
    /// The event kind the lesson is about (N jumps to it): the first step's or exercise's kind
    /// that the trace holds more than once; nullopt when none does.
    static std::optional<std::size_t> lessonEventKind(const Lesson& lesson, const EventLog& log);

  signals:
    /// A lesson is shown (its trace replayed, its progress in studentProgress()).
    void lessonShown(const Lesson& lesson);
    /// A scene opened by hand replaces the lesson.
    void lessonClosed();
    /// An answer was recorded in the shown lesson's progress, about to be saved: a listener
    /// may add to the progress (the practice's result) and it is saved with the answer.
    void answerRecorded(const Lesson& lesson);
    /// A lesson picked in the lessons menu.
    void lessonRequested(const QString& id);
    /// A lesson was shown whose steps are about events of this kind (the timeline's N).
    void jumpKindSuggested(std::size_t eventKind);
    /// Back to the lesson after its structure was changed: the window shows its own scene and
    /// structure again (the lesson's trace is about them).
    void lessonSceneRequested(SceneRef scene);
    /// A step's "Compare these structures on this ray".
    void compareRequested(const std::vector<StructureChoice>& choices);

  private:
    void applyStep(int index);
    /// Quiz mode: the session's limit from the open exercise (course/lesson_trace.h's position).
    void updateQuizLimit();
    /// A lesson's steps and exercises are positions in its trace: replay it again if needed,
    /// through the structure `setup` names (a step's or an exercise's own, else the lesson's):
    /// the window shows that structure's scene first.
    void showLessonTrace(const std::optional<LessonSetup>& setup);
    /// The scene of the lesson's structure `key` (the lesson's own when it has no other).
    SceneRef sceneOf(const std::string& key) const;
    /// Whether the window shows one of the lesson's structures (its own or a step's).
    bool showsLessonScene() const;
    void saveProgress();
    /// The student is told, in a dialog, that the progress file could not be read and where it
    /// was kept (or that it could not be moved, and is left alone).
    void tellUnreadable(const ProgressStore::Unreadable& u);
    /// The persistent note in the status bar: the save's problem, or hidden when "".
    void showSaveProblem(const QString& why);
    void runSweep();
    void fillLessonsMenu();
    /// The panel's text for a new replay: a note when it is not the lesson's trace, the SAH's
    /// explanation for a build replayed without a lesson.
    void showReplayText();
    /// What the replay shows when it is not the lesson's trace ("" when it is).
    QString replayDescription() const;
    /// A help text of texts/ in the interface's language.
    QString lectureText(const QString& name) const;

    QMainWindow& window_;
    Session& session_;
    TaskRunner& runner_;
    const std::uint64_t& generation_;
    LessonPanel* lesson_;
    EventList* events_;
    VtkView* view3D_;
    QMenu* lessonsMenu_ = nullptr;
    SceneRef lessonScene_;  // the lesson's scene and structure, as its trace was recorded
    std::map<std::string, Structure> others_;  // the other structures its steps set up
    std::string currentKey_;                   // the structure the lesson shows now
    bool replacing_ = false;  // between replaceLesson and show: the old lesson says nothing
    Language lang_ = Language::En;
    Progress studentProgress_;
    QString progressPath_;
    ProgressStore store_{QString()};
    bool unsaved_ = false;        // the last save failed
    bool quitUnsaved_ = false;    // the student chose to quit without saving
    QLabel* saveNote_ = nullptr;  // the status bar's note while the progress is unsaved
    QString saveProblem_;         // why the last save failed
};

}  // namespace raystep::gui
