#pragma once
// What the window shows and replays: a scene or a lesson opened in the background (the window
// shows the current one until the new one is ready, and keeps it if the new one cannot be
// opened), the scene made live by an edit, and the count of scenes shown that drops the results
// of work begun for an older one.
#include "lesson_controller.h"
#include "session.h"
#include "task_runner.h"

#include <QObject>

#include <functional>
#include <optional>

class QMainWindow;

namespace raystep::gui {

class ImageView;
class LessonPanel;

/// Whether `lesson` shows `view` (a 2D lesson needs no 3D view).
bool lessonShows(const Lesson& lesson, LessonView view);

class SceneOpener : public QObject {
    Q_OBJECT
  public:
    /// `language` is the lesson texts' (a lesson's title in the task label).
    SceneOpener(QMainWindow& window, Session& session, TaskRunner& runner, LessonPanel* lesson,
                ImageView* image, std::function<Language()> language);

    /// Counts the scenes shown: a result for an older one is dropped.
    const std::uint64_t& generation() const { return generation_; }
    /// Starts opening a scene (built-in name or file) with a structure, in the background.
    void openScene(const QString& nameOrPath, AccelKind kind, bool quiet,
                   const AccelOptions& options, bool renderImage);
    /// Starts opening a lesson (built-in id or number, or a file), likewise in the background.
    void openLesson(const QString& idOrPath, bool quiet);
    /// Shows a scene made by a worker: the views, the first ray to replay, the image.
    void showScene(SceneRef scene, bool renderImage);
    /// Shows `scene` at once, recording again what was replayed at the same step.
    void showLive(SceneRef scene);
    /// How the last open ended: nullopt while it runs (or before any), else true or false.
    std::optional<bool> lastOpenOk() const { return lastOpenOk_; }
    QString lastOpenError() const { return lastOpenError_; }

  signals:
    /// A new scene is about to be shown: what belongs to the old one closes (compare mode).
    void sceneReplaced();
    /// A scene was shown (the session has it): its image made, or not.
    void sceneShown(bool renderImage);
    /// openScene showed its scene (`nameOrPath`), before `opened`.
    void sceneOpened(const QString& nameOrPath);
    /// openLesson's lesson is ready: the old lesson ends before its scene is shown.
    void lessonArriving();
    /// openLesson showed its scene: the lesson's trace, views and text follow, before `opened`.
    void lessonOpened(const LessonController::Opened& opened);
    /// An openScene or openLesson ended: opened, or not (with why; "cancelled" included).
    void opened(bool ok, const QString& error);

  private:
    /// An open that did not end well: say why (a dialog unless quiet), keep what is shown.
    void openFailed(const QString& what, const TaskOutcome& outcome, bool quiet);
    /// The same for a failure told by a message (a lesson file that cannot be read).
    void openFailed(const QString& what, const QString& message, bool quiet);
    void finishOpen(bool ok, const QString& error);

    QMainWindow& window_;
    Session& session_;
    TaskRunner& runner_;
    LessonPanel* lesson_;
    ImageView* image_;
    std::function<Language()> language_;
    std::uint64_t generation_ = 0;
    std::optional<bool> lastOpenOk_;
    QString lastOpenError_;
};

}  // namespace raystep::gui
