// The replay app's window: its views, its parts made and wired, its own actions and the menus.
#include "main_window.h"
#include "file_dialogs.h"
#include "practice_controller.h"

#include "assess_controller.h"
#include "board_docks.h"
#include "compare_launcher.h"
#include "event_list.h"
#include "image_view.h"
#include "inspector.h"
#include "language.h"
#include "lesson_panel.h"
#include "live_controls.h"
#include "live_edit.h"
#include "presentation.h"
#include "presenter_controls.h"
#include "scene_opener.h"
#include "timeline.h"
#include "view2d.h"
#include "vtk_view.h"
#include "window_layout.h"

#include "course/lesson_trace.h"
#include "course/practice/practice.h"

#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace raystep::gui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("raystep"));
    createViews();
    createTimeline();
    createDocks();
    // The parts, each owning one job; made in this order, their tool bars, docks and status bar
    // widgets take the places they had.
    opener_ = new SceneOpener(*this, session_, runner_, lesson_, imageView_,
                              [this] { return lessons_->language(); });
    const std::uint64_t& generation = opener_->generation();
    lessons_ =
        new LessonController(*this, session_, runner_, generation, lesson_, events_, view3D_);
    practice_ = new PracticeController(this, *lessons_, *lesson_);
    createStatusBar();
    createActions();
    const auto refused = [this](const QString& toWhat) { return refusedWhileHeld(toWhat); };
    image_ = new ImageRender(*this, session_, runner_, generation, imageView_, view3D_,
                             {refused, [this] { return lesson_->lessonLog(); }});
    createStructureControls();
    live_ = new LiveEdit(*this, session_, view2D_, [this](SceneRef s) { showLive(std::move(s)); });
    board_ = new BoardDocks(*this, session_);
    assess_ = new AssessController(*this, session_, view2D_, board_->boardTable(), {refused});
    // Its bar over the views, above the 2D view and the 3D one.
    qobject_cast<QVBoxLayout*>(views_->parentWidget()->layout())->insertWidget(0, assess_->bar());
    presenter_ = new PresenterControls(*this);
    compare_ = new CompareLauncher(*this, session_, runner_, generation, lesson_,
                                   {refused, [this](QSize s) { return fitToScreen(s); },
                                    QList<QAction*>{actions_.quit} + presenter_->sharedKeys()});
    layout_ = new WindowLayout(
        *this,
        {qobject_cast<QSplitter*>(centralWidget()), qobject_cast<QSplitter*>(views_),
         qobject_cast<QSplitter*>(view3D_->parentWidget())},
        lesson_, board_->docks(), [this] { board_->place(); });
    createMenus();

    // Opening: what the window shows of a scene or lesson once it is ready.
    const auto openLessonId = [this](const QString& id) { openLesson(id); };
    connect(lesson_, &LessonPanel::lessonRequested, this, openLessonId);
    connect(lessons_, &LessonController::lessonRequested, this, openLessonId);
    connect(practice_, &PracticeController::lessonRequested, this, openLessonId);
    connect(opener_, &SceneOpener::sceneReplaced, compare_, &CompareLauncher::close);
    connect(opener_, &SceneOpener::sceneShown, image_, &ImageRender::sceneShown);
    connect(opener_, &SceneOpener::sceneOpened, this, &MainWindow::showOpenedScene);
    connect(opener_, &SceneOpener::lessonArriving, lessons_, &LessonController::replaceLesson);
    connect(opener_, &SceneOpener::lessonOpened, this, &MainWindow::showOpenedLesson);
    connect(opener_, &SceneOpener::opened, this, &MainWindow::opened);
    // A student's ray is compared on the board: shown beside it, whatever the scene.
    connect(assess_, &AssessController::rayShown, board_, &BoardDocks::showBoard);
    // The lesson's requests: the timeline's N, its own scene again, a step's comparison.
    connect(lessons_, &LessonController::jumpKindSuggested, timeline_, &Timeline::setJumpKind);
    connect(lessons_, &LessonController::lessonSceneRequested, this, [this](SceneRef scene) {
        opener_->showScene(std::move(scene), !imageView_->isHidden());
    });
    connect(lessons_, &LessonController::compareRequested, compare_,
            qOverload<const std::vector<StructureChoice>&>(&CompareLauncher::open));
    // The live controls build through the structure chooser's path; a build that failed (or
    // was cancelled) leaves the scene as it was: so do the controls.
    connect(board_->liveControls(), &LiveControls::applyRequested, this, &MainWindow::applyLive);
    connect(this, &MainWindow::structureChanged, this, [this](bool ok) {
        if (!ok) board_->liveControls()->sync();
    });
    // The layout: ready once settled; the docks under the views follow the zoom, once the new
    // fonts have reached the widgets (posted events) and the window is laid out.
    connect(layout_, &WindowLayout::ready, this, &MainWindow::layoutReady);
    connect(&presentation(), &Presentation::changed, this, [this] {
        QTimer::singleShot(0, this, [this] {
            if (layout_->settled()) board_->fitToZoom();
        });
    });
    layout_->restore();
}

MainWindow::~MainWindow() {
    // Before any member or child goes: no worker may still read what they own.
    runner_.shutdown();
}

void MainWindow::createViews() {
    view2D_ = new View2D(session_);
    view3D_ = new VtkView(session_);
    imageView_ = new ImageView(session_);
    lesson_ = new LessonPanel;
    lesson_->setLessons(builtinLessons());
    auto* views = new QSplitter(Qt::Horizontal);
    views->addWidget(view2D_);
    auto* right = new QSplitter(Qt::Vertical);
    right->addWidget(view3D_);
    right->addWidget(imageView_);
    views->addWidget(right);
    views->setStretchFactor(0, 3);
    views->setStretchFactor(1, 2);
    views_ = views;
    connect(view2D_, &View2D::cellClicked, lesson_, &LessonPanel::fillCell);
    connect(lesson_, &LessonPanel::sequenceChanged, view2D_, &View2D::setSequence);
}

void MainWindow::createTimeline() {
    timeline_ = new Timeline(session_);
    auto* centre = new QWidget;
    auto* cl = new QVBoxLayout(centre);
    cl->setContentsMargins(0, 0, 0, 0);
    cl->addWidget(views_, 1);
    cl->addWidget(timeline_);
    auto* main = new QSplitter(Qt::Horizontal);
    main->addWidget(lesson_);
    main->addWidget(centre);
    lesson_->setMinimumWidth(260);
    main->setStretchFactor(0, 1);
    main->setStretchFactor(1, 4);
    main->setSizes({360, 1100});
    setCentralWidget(main);
}

void MainWindow::createDocks() {
    // Inspector and event list, as docks the user may move (kept with QSettings).
    inspector_ = new Inspector(session_);
    auto* inspectorDock = new QDockWidget(tr("Inspector"), this);
    inspectorDock->setObjectName("inspectorDock");
    inspectorDock->setWidget(inspector_);
    addDockWidget(Qt::RightDockWidgetArea, inspectorDock);
    events_ = new EventList(session_);
    auto* listDock = new QDockWidget(tr("Events"), this);
    listDock->setObjectName("eventsDock");
    listDock->setWidget(events_);
    addDockWidget(Qt::RightDockWidgetArea, listDock);
}

void MainWindow::createStatusBar() {
    // Background work in the status bar: what runs, how far, and Cancel.
    taskLabel_ = new QLabel;
    progress_ = new QProgressBar;
    progress_->setMaximumWidth(200);
    progress_->hide();
    cancel_ = new QPushButton(tr("Cancel"));
    cancel_->setObjectName("cancelTask");
    cancel_->hide();
    statusBar()->addPermanentWidget(taskLabel_);
    statusBar()->addPermanentWidget(progress_);
    statusBar()->addPermanentWidget(cancel_);
    connect(cancel_, &QPushButton::clicked, this, [this] {
        image_->cancelPending();
        runner_.cancelAll();
    });
    connect(&runner_, &TaskRunner::progressChanged, this,
            [this](const QString& label, int percent) {
                const bool running = !label.isEmpty();
                taskLabel_->setText(label);
                progress_->setVisible(running);
                cancel_->setVisible(running);
                progress_->setValue(percent);
            });
}

void MainWindow::createActions() {
    const auto action = [this](const QString& text, QKeySequence key, auto slot) {
        auto* a = new QAction(text, this);
        if (!key.isEmpty()) a->setShortcut(key);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    Actions& a = actions_;
    a.open = action(tr("&Open scene..."), QKeySequence::Open, [this] { openFileDialog(); });
    a.saveScene =
        action(tr("&Save scene as..."), QKeySequence::SaveAs, [this] { saveSceneDialog(); });
    a.saveScene->setToolTip(tr("Save the scene made around an opened model as a scene file"));
    a.exportTrace = action(tr("Export &trace..."), QKeySequence::Save, [this] { exportTrace(); });
    a.shotWindow = action(tr("Export screenshot of the &window..."), {},
                          [this] { exportScreenshot(this, tr("window")); });
    a.shot2D = action(tr("Export screenshot of the &2D view..."), {},
                      [this] { exportScreenshot(view2D_, tr("2D view")); });
    a.shot3D = action(tr("Export screenshot of the &3D view..."), {},
                      [this] { exportScreenshot(view3D_, tr("3D view")); });
    a.shotImage = action(tr("Export screenshot of the &image view..."), {},
                         [this] { exportScreenshot(imageView_, tr("image view")); });
    a.exportReport =
        action(tr("Export &progress report..."), {}, [this] { lessons_->exportProgressReport(); });
    a.quit = action(tr("&Quit"), QKeySequence::Quit, [this] { close(); });

    a.stepForward = action(tr("Step &forward"), QKeySequence(Qt::Key_Right),
                           [this] { timeline_->stepForward(); });
    a.stepBack =
        action(tr("Step &back"), QKeySequence(Qt::Key_Left), [this] { timeline_->stepBack(); });
    a.play = action(tr("&Play / pause"), QKeySequence(Qt::Key_Space),
                    [this] { timeline_->togglePlay(); });
    a.nextOfKind = action(tr("&Next event of the kind"), QKeySequence(Qt::Key_N),
                          [this] { timeline_->jumpToNextOfKind(); });
    a.replayBuild = action(tr("Replay the &build (candidates, splits, leaves)"),
                           QKeySequence(Qt::Key_B), [this] { replayBuild(); });
    a.exampleRay = action(tr("Replay the &example ray"), QKeySequence(Qt::Key_R), [this] {
        if (session_.is2D()) {
            if (!refusedWhileHeld(tr("replay the example ray"))) session_.traceExampleRay();
        } else {
            statusBar()->showMessage(
                tr("R replays the example ray of a 2D scene; in 3D, click "
                   "a pixel of the image."));
        }
    });
    a.first =
        action(tr("&First event"), QKeySequence(Qt::Key_Home), [this] { session_.setCursor(0); });
    a.last = action(tr("&Last event"), QKeySequence(Qt::Key_End),
                    [this] { session_.setCursor(session_.size()); });

    a.openLessonFile = action(tr("Open lesson &file..."), {}, [this] {
        const QString path = openFileName(this, tr("Open lesson"), tr("Lessons (*.json)"));
        if (!path.isEmpty()) openLesson(path);
    });
    // Who the lesson runs for: a student (quiz), the room (presenting: everything free, the
    // answers hidden until revealed one by one), the lecturer preparing (every answer shown).
    // One of the three, remembered; a mode's key pressed again goes back to quiz mode.
    auto* modes = new QActionGroup(this);
    modes->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    const auto mode = [modes](const QString& text, QKeySequence key, const QString& tip) {
        auto* m = new QAction(text, modes);
        m->setCheckable(true);
        m->setShortcut(key);
        m->setStatusTip(tip);
        return m;
    };
    a.quizMode = mode(tr("&Quiz mode (the student answers)"), {},
                      tr("Every unsolved exercise holds the replay at its position"));
    a.presentMode = mode(
        tr("&Presenting mode (answers hidden)"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L),
        tr("Every step and view free; each exercise a question to the room, its answer "
           "shown when you reveal it"));
    a.lecturer = mode(tr("&Lecturer mode (show answers)"), QKeySequence(Qt::CTRL | Qt::Key_L),
                      tr("Every step and view free, every answer shown"));
    // Every run starts in quiz mode (--present or --lecturer say otherwise): a mode picked on a
    // shared lab computer must not leave the next student's run without its holds.
    connect(modes, &QActionGroup::triggered, this, [this] {
        setLessonMode(actions_.presentMode->isChecked() ? LessonMode::Presenting
                      : actions_.lecturer->isChecked()  ? LessonMode::Lecturer
                                                        : LessonMode::Quiz);
    });
    setLessonMode(LessonMode::Quiz);
    // The one way back after a pixel click, R or B: the lesson's trace, steps and exercises.
    a.backToLesson = action(tr("&Back to the lesson"), QKeySequence(Qt::Key_Escape),
                            [this] { lessons_->backToLesson(); });
    a.backToLesson->setEnabled(false);
    connect(lesson_, &LessonPanel::exploringChanged, a.backToLesson, &QAction::setEnabled);
    // The slides' errata under the texts: a lecturer may hide them; remembered.
    a.showErrata = new QAction(tr("Show &notes on the slides"), this);
    a.showErrata->setCheckable(true);
    a.showErrata->setChecked(QSettings().value("lessons/showErrata", true).toBool());
    lesson_->setShowErrata(a.showErrata->isChecked());
    connect(a.showErrata, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("lessons/showErrata", on);
        lesson_->setShowErrata(on);
    });

    // The screenshots of one kind of scene are off with the other: a 2D lesson's 3D screenshot
    // saved the hidden placeholder.
    for (const auto& [act, name] :
         {std::pair(a.shot2D, "screenshot2D"), std::pair(a.shot3D, "screenshot3D"),
          std::pair(a.shotImage, "screenshotImage"), std::pair(a.quit, "quit")})
        act->setObjectName(QString::fromLatin1(name));
    connect(&session_, &Session::sceneChanged, this, [this] { syncViewActions(); });
    // What the status bar said of the last scene (its render, its structure) is not of this one.
    connect(&session_, &Session::aboutToChangeScene, statusBar(), &QStatusBar::clearMessage);
    syncViewActions();
}

void MainWindow::syncViewActions() {
    const bool scene = session_.hasScene(), in3D = scene && !session_.is2D();
    const Actions& a = actions_;
    for (QAction* act : {a.shot3D, a.shotImage}) act->setEnabled(in3D);
    a.shot2D->setEnabled(scene && session_.is2D());
}

void MainWindow::createMenus() {
    const Actions& a = actions_;
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(a.open);
    assess_->addFileItems(file);
    file->addAction(a.saveScene);
    live_->addFileItems(file);
    file->addActions(
        {a.exportTrace, a.shotWindow, a.shot2D, a.shot3D, a.shotImage, a.exportReport});
    file->addSeparator();
    file->addAction(a.quit);
    live_->addEditItems(menuBar()->addMenu(tr("&Edit")));
    QMenu* replay = menuBar()->addMenu(tr("&Replay"));
    replay->addActions({a.stepForward, a.stepBack, a.play, a.nextOfKind});
    replay->addSeparator();
    replay->addActions({a.replayBuild, a.exampleRay, a.first, a.last});
    QMenu* lessons = menuBar()->addMenu(tr("&Lessons"));
    lessons_->setLessonsMenu(lessons->addMenu(tr("&Built-in lessons")));
    lessons->addActions({a.openLessonFile, a.backToLesson});
    lessons->addSeparator();
    practice_->addLessonItems(lessons);
    lessons->addSeparator();
    lessons->addActions({a.quizMode, a.presentMode, a.lecturer});
    lessons->addSeparator();
    lessons->addAction(a.showErrata);
    QMenu* view = menuBar()->addMenu(tr("&View"));
    live_->addViewItems(view);
    compare_->addViewItems(view);
    image_->addViewItems(view);
    view->addSeparator();
    layout_->addViewItems(view);
    view->addSeparator();
    board_->addViewItems(view);
    view->addSeparator();
    presenter_->addViewItems(view);
    presenter_->addHelpItems(menuBar()->addMenu(tr("&Help")));
}

void MainWindow::showOpenedScene(const QString& nameOrPath) {
    imageView_->setLessonPixel(std::nullopt);
    lessons_->showSceneIntro();
    // The lecture's 2D pictures use the 2D view; 3D scenes the 3D view and the image.
    showViews(session_.is2D(), !session_.is2D(), !session_.is2D());
    setWindowTitle(tr("raystep - %1").arg(nameOrPath));
}

void MainWindow::showOpenedLesson(const LessonController::Opened& o) {
    const Lesson& lesson = o.lesson;
    const auto shows = [&](LessonView v) { return lessonShows(lesson, v); };
    // A new history, even on the same scene (lessons 10 and 11): an undo would bring back an
    // edit made in the lesson left.
    live_->newHistory();
    session_.showLog(o.trace, LessonController::logKind(lesson));
    showViews(shows(LessonView::View2D), shows(LessonView::View3D), shows(LessonView::Image));
    // The board beside a 2D lesson, or where the lesson asks (the 3D DDA's table); the live
    // controls beside a 2D one.
    board_->show(session_.is2D() || shows(LessonView::Board), session_.is2D());
    lessons_->show(o.lesson, o.trace, o.others);
    // The pixel the lesson traces, marked on the image in the lesson's own image size.
    if (lesson.trace.kind == LessonTrace::Kind::Pixel)
        imageView_->setLessonPixel(
            QRect(lesson.trace.x, lesson.trace.y, lesson.trace.width, lesson.trace.height));
    else
        imageView_->setLessonPixel(std::nullopt);
    const QString title = QString::fromStdString(lesson.title.in(lessons_->language()));
    setWindowTitle(parsePracticeLessonId(lesson.id)
                       ? tr("raystep - %1").arg(title)
                       : tr("raystep - lesson %1: %2").arg(lesson.number).arg(title));
}

void MainWindow::showViews(bool view2D, bool view3D, bool image) {
    view2D_->setVisible(view2D);
    view3D_->setVisible(view3D);
    imageView_->setVisible(image);
    view3D_->parentWidget()->setVisible(view3D || image);
}

void MainWindow::replayBuild() {
    if (!session_.hasScene()) {
        statusBar()->showMessage(tr("No scene is open."));
        return;
    }
    if (refusedWhileHeld(tr("replay the build"))) return;
    if (!Session::hasBuild(session_.kind())) {
        statusBar()->showMessage(
            tr("A %1 has no construction to replay: B replays how a kd-tree or a BVH is built.")
                .arg(structureName(session_.kind())));
        return;
    }
    const std::uint64_t generation = opener_->generation();
    runner_.start<LogRef>(
        TaskKind::Build,
        tr("Recording the construction of the %1...").arg(structureName(session_.kind())),
        [ref = session_.sceneRef()](const ProgressFn& progress) {
            return Session::recordBuild(ref, progress);
        },
        [this, generation](LogRef&& log, const TaskOutcome& outcome) {
            if (outcome.superseded || generation != opener_->generation()) return;
            if (!outcome.ok()) {
                statusBar()->showMessage(outcome.cancelled ? tr("Build replay cancelled")
                                                           : tr("Cannot record the build"));
                return;
            }
            session_.showLog(std::move(log), LogKind::Build);
        });
}

void MainWindow::setLanguage(Language lang) {
    lessons_->setLanguage(lang);
    practice_->retranslate(lang);
    view2D_->setLanguage(lang);
    view3D_->setLanguage(lang);
}

void MainWindow::setLessonMode(LessonMode mode) {
    modeAction(mode)->setChecked(true);
    lesson_->setMode(mode);
}

LessonMode MainWindow::lessonMode() const {
    return lesson_->mode();
}

QAction* MainWindow::modeAction(LessonMode mode) const {
    switch (mode) {
        case LessonMode::Presenting:
            return actions_.presentMode;
        case LessonMode::Lecturer:
            return actions_.lecturer;
        case LessonMode::Quiz:
            break;
    }
    return actions_.quizMode;
}

void MainWindow::setLecturerMode(bool on) {
    setLessonMode(on ? LessonMode::Lecturer : LessonMode::Quiz);
}

bool MainWindow::refusedWhileHeld(const QString& toWhat) {
    const auto held = lesson_->heldBy();
    if (!session_.held() || !held) return false;
    const QString why = tr("Exercise %1 holds the replay: answer the exercise first, or put it "
                           "away, to %2.")
                            .arg(held->first + 1)
                            .arg(toWhat);
    lesson_->showHeldNote(why);
    statusBar()->showMessage(why, 10000);
    return true;
}

const Progress& MainWindow::studentProgress() const {
    return lessons_->studentProgress();
}

QString MainWindow::progressPath() const {
    return lessons_->progressPath();
}

void MainWindow::closeEvent(QCloseEvent* e) {
    // Answers the last save could not write: asked about first (lesson_controller.h).
    if (!lessons_->allowClose()) {
        e->ignore();
        return;
    }
    layout_->save();
    // Stop and join every worker now, and start none after: the window is going away.
    runner_.shutdown();
    compare_->close();
    e->accept();
}

}  // namespace raystep::gui
