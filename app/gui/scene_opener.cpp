// What the window shows and replays: scenes and lessons opened in the background (scene_opener.h).
#include "scene_opener.h"

#include "image_view.h"
#include "language.h"
#include "lesson_panel.h"

#include "course/practice/practice.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>

#include <algorithm>

namespace raystep::gui {

bool lessonShows(const Lesson& lesson, LessonView view) {
    return std::find(lesson.views.begin(), lesson.views.end(), view) != lesson.views.end();
}

SceneOpener::SceneOpener(QMainWindow& window, Session& session, TaskRunner& runner,
                         LessonPanel* lesson, ImageView* image, std::function<Language()> language)
    : QObject(&window),
      window_(window),
      session_(session),
      runner_(runner),
      lesson_(lesson),
      image_(image),
      language_(std::move(language)) {}

void SceneOpener::openScene(const QString& nameOrPath, AccelKind kind, bool quiet,
                            const AccelOptions& base, bool renderImage) {
    lastOpenOk_.reset();
    const bool started = runner_.start<SceneRef>(
        TaskKind::Scene,
        tr("Loading %1 and building its %2...").arg(nameOrPath, structureName(kind)),
        [path = nameOrPath.toStdString(), kind, base](const ProgressFn& progress) {
            AccelOptions options = base;
            options.setProgress(progress);
            return Session::prepare(path, kind, options);
        },
        [this, nameOrPath, quiet, renderImage](SceneRef&& scene, const TaskOutcome& outcome) {
            if (outcome.superseded) return;  // a newer open is under way
            if (!outcome.ok()) return openFailed(nameOrPath, outcome, quiet);
            showScene(std::move(scene), renderImage);
            emit sceneOpened(nameOrPath);
            finishOpen(true, {});
        });
    if (!started) finishOpen(false, tr("the window is closing"));
}

void SceneOpener::showScene(SceneRef scene, bool renderImage) {
    ++generation_;
    emit sceneReplaced();  // compare mode's trees are of the scene shown until now
    // What ran for the old scene is of no use now (and holds its own share of it meanwhile).
    runner_.cancel(TaskKind::Render);
    runner_.cancel(TaskKind::Build);
    runner_.cancel(TaskKind::Sweep);
    session_.adopt(std::move(scene));
    if (session_.is2D()) session_.traceExampleRay();
    emit sceneShown(renderImage);
}

void SceneOpener::showLive(SceneRef scene) {
    ++generation_;
    runner_.cancel(TaskKind::Render);
    runner_.cancel(TaskKind::Build);
    runner_.cancel(TaskKind::Sweep);
    runner_.cancel(TaskKind::Structure);
    session_.relive(std::move(scene));
}

void SceneOpener::openFailed(const QString& what, const TaskOutcome& outcome, bool quiet) {
    if (outcome.cancelled) {
        window_.statusBar()->showMessage(tr("Opening %1 cancelled").arg(what));
        finishOpen(false, tr("cancelled"));
        return;
    }
    openFailed(what, outcome.errorText(), quiet);
}

void SceneOpener::openFailed(const QString& what, const QString& message, bool quiet) {
    if (!session_.hasScene()) {
        // Nothing was open before (a bad scene at start-up): say so where the user looks.
        lesson_->showText(tr("## Nothing is open\n\n%1 could not be opened:\n\n    %2\n\n"
                             "Pick a lesson above, or open a scene with *File > Open scene*.")
                              .arg(what, message));
        image_->clear(tr("No scene is open."));
        window_.setWindowTitle(tr("raystep"));
    }
    if (!quiet) {
        // Without a nested event loop: the window goes on.
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open %1").arg(what), message,
                                    QMessageBox::Ok, &window_);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    }
    window_.statusBar()->showMessage(tr("Cannot open %1").arg(what));
    finishOpen(false, message);
}

void SceneOpener::finishOpen(bool ok, const QString& error) {
    lastOpenOk_ = ok;
    lastOpenError_ = error;
    emit opened(ok, error);
}

void SceneOpener::openLesson(const QString& idOrPath, bool quiet) {
    lastOpenOk_.reset();
    Lesson lesson;
    try {
        lesson = loadLesson(idOrPath.toStdString());
    } catch (const LessonError& e) {
        // As a scene that cannot be opened: at start-up, the "Nothing is open" page.
        openFailed(tr("the lesson %1").arg(idOrPath), QString::fromUtf8(e.what()), quiet);
        lesson_->syncPicker();
        return;
    }
    const QString title = QString::fromStdString(lesson.title.in(language_()));
    // A practice instance has no lesson number to name it by (lessonHeading).
    const bool practice = parsePracticeLessonId(lesson.id).has_value();
    const bool started = runner_.start<LessonController::Opened>(
        TaskKind::Scene,
        practice ? tr("Opening %1...").arg(title)
                 : tr("Opening lesson %1: %2...").arg(lesson.number).arg(title),
        [lesson](const ProgressFn& progress) {
            return LessonController::prepare(lesson, progress);
        },
        [this, lesson, quiet, practice, title](LessonController::Opened&& o,
                                               const TaskOutcome& outcome) {
            if (outcome.superseded) return;
            if (!outcome.ok()) {
                openFailed(practice ? title : tr("lesson %1").arg(lesson.number), outcome, quiet);
                lesson_->syncPicker();  // back to what is shown
                return;
            }
            // The old lesson ends before the new scene is shown: its hold and its notes about
            // the replay are not applied to what replaces them.
            emit lessonArriving();
            showScene(o.scene, lessonShows(lesson, LessonView::Image));
            emit lessonOpened(o);
            finishOpen(true, {});
        });
    if (!started) finishOpen(false, tr("the window is closing"));
}

}  // namespace raystep::gui
