// The replay app's window: its layout, wiring and menus, and opening scenes and lessons.
#include "main_window.h"
#include "file_dialogs.h"

#include "compare_chooser.h"
#include "compare_window.h"
#include "event_list.h"
#include "image_view.h"
#include "inspector.h"
#include "language.h"
#include "lesson_controller.h"
#include "lesson_panel.h"
#include "live2d.h"
#include "timeline.h"
#include "view2d.h"
#include "vtk_view.h"

#include "course/grid_sweep.h"
#include "course/lesson_trace.h"

#include "raystep/base/file_error.h"
#include "raystep/render/image.h"
#include "raystep/render/render.h"
#include "raystep/render/tracer.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/trace/trace_io.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QBuffer>
#include <QCloseEvent>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>
#include <cstring>
#include <exception>
#include <mutex>

namespace raystep::gui {

namespace {
constexpr int kImageWidth = 320, kImageHeight = 240;

/// A progressive render's picture as the image view shows it (8-bit sRGB, the heat map and its
/// scale); made on the worker.
RenderFrame frameOf(const ProgressiveRender& r) {
    const int w = r.options().width, h = r.options().height;
    RenderFrame f;
    f.image = QImage(w, h, QImage::Format_RGB888);
    const auto rgb = toSrgb8(r.image());
    for (int y = 0; y < h; ++y)
        std::memcpy(f.image.scanLine(y), rgb.data() + std::size_t(y) * w * 3, std::size_t(w) * 3);
    f.heat = QImage(w, h, QImage::Format_RGB888);
    const auto heat = heatmapRgb8(r.costPerPixel(), w, h);
    for (int y = 0; y < h; ++y)
        std::memcpy(f.heat.scanLine(y), heat.data() + std::size_t(y) * w * 3, std::size_t(w) * 3);
    const auto [lo, hi] = std::minmax_element(r.costPerPixel().begin(), r.costPerPixel().end());
    f.minTests = lo == r.costPerPixel().end() ? 0 : *lo;
    f.maxTests = hi == r.costPerPixel().end() ? 0 : *hi;
    if (const ProgressivePass* p = r.lastPass()) {
        f.block = p->block;
        f.samples = p->samples;
    }
    f.spp = r.options().spp;
    return f;
}
}  // namespace

/// The newest pass of a render under way, put by its worker and taken on the GUI thread (the
/// runner's rule: a worker never calls into a QObject).
struct FrameBox {
    std::mutex mutex;
    std::optional<RenderFrame> frame;
    void put(RenderFrame f) {
        const std::lock_guard lock(mutex);
        frame = std::move(f);
    }
    std::optional<RenderFrame> take() {
        const std::lock_guard lock(mutex);
        std::optional<RenderFrame> f = std::move(frame);
        frame.reset();
        return f;
    }
};

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("raystep"));
    createViews();
    createTimeline();
    createDocks();
    createStatusBar();
    createActions();
    createMenus();
    createStructureControls();
    createLiveLab();
    createBoard();
    createPresenter();
    restoreLayout();
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
    connect(imageView_, &ImageView::renderRequested, this, [this] { renderImage(); });
    connect(imageView_, &ImageView::pixelClicked, this, [this](int x, int y) {
        // A pixel beside the lesson's holds the same answers as the lesson's own.
        if (refusedWhileHeld(tr("trace a pixel's ray tree"))) return;
        // The camera, size and settings the image was made with: the pixel's ray is the one
        // drawn there.
        if (const auto& f = imageFrame_; f && slowPixelTraces()) {
            tracePixelHereOrInBackground(x, y, f->width, f->height, f->camera, f->trace);
            return;
        }
        if (const auto& f = imageFrame_)
            session_.tracePixel(x, y, f->width, f->height, f->camera, f->trace);
        else
            session_.tracePixel(x, y, kImageWidth, kImageHeight);
        session_.setCursor(session_.size());
        statusBar()->showMessage(
            tr("Pixel (%1, %2): %3 events recorded").arg(x).arg(y).arg(session_.size()));
    });
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

    lessons_ =
        new LessonController(*this, session_, runner_, generation_, lesson_, events_, view3D_);
    connect(lesson_, &LessonPanel::lessonRequested, this,
            [this](const QString& id) { openLesson(id); });
    connect(lessons_, &LessonController::lessonRequested, this,
            [this](const QString& id) { openLesson(id); });
    // The compare window replays whole traces: it closes when an exercise comes to hold the
    // replay (a lesson opened, a mode changed), and with its scene (showScene).
    connect(&session_, &Session::limitChanged, this, [this] {
        if (compare_ && (session_.held() || heldAmong(compare_->choices()))) compare_->close();
        if (chooser_ && session_.held()) chooser_->reject();
    });
    connect(lessons_, &LessonController::jumpKindSuggested, timeline_, &Timeline::setJumpKind);
    connect(lessons_, &LessonController::lessonSceneRequested, this,
            [this](SceneRef scene) { showScene(std::move(scene), !imageView_->isHidden()); });
    connect(lessons_, &LessonController::compareRequested, this,
            [this](const std::vector<StructureChoice>& choices) { openCompare(choices); });
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
        renderPending_ = false;  // a render about to start is cancelled too
        runner_.cancelAll();
    });
    connect(&runner_, &TaskRunner::progressChanged, this,
            [this](const QString& label, int percent) {
                const bool running = !label.isEmpty();
                taskLabel_->setText(label);
                progress_->setVisible(running);
                cancel_->setVisible(running);
                progress_->setValue(percent);
                if (runner_.busy(TaskKind::Render)) {
                    takeFrame();
                    imageView_->renderProgress(runner_.percent(TaskKind::Render));
                }
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

    // C at once (a tree's splits, or the slides' grid, kd-tree and BVH); Shift+C asks which.
    a.compare =
        action(tr("&Compare on this ray"), QKeySequence(Qt::Key_C), [this] { openCompare(); });
    a.chooseCompare = action(tr("Compare &structures..."), QKeySequence(Qt::SHIFT | Qt::Key_C),
                             [this] { chooseCompare(); });
    a.renderAgain = action(tr("Render the &image again"), {}, [this] { renderImage(); });
    a.heatmap = new QAction(tr("&Heat map of primitive tests"), this);
    a.heatmap->setCheckable(true);
    connect(a.heatmap, &QAction::toggled, imageView_, &ImageView::setHeatmap);
    a.resetCamera = action(tr("&Reset 3D camera"), {}, [this] { view3D_->resetCamera(); });
    createRenderSettings();
    // The items of one kind of scene are off with the other: a 2D lesson's heat map or "render
    // again" did nothing, and its 3D screenshot saved the hidden placeholder.
    for (const auto& [act, name] :
         {std::pair(a.heatmap, "heatmap"), std::pair(a.renderAgain, "renderAgain"),
          std::pair(a.resetCamera, "resetCamera"), std::pair(a.shot2D, "screenshot2D"),
          std::pair(a.shot3D, "screenshot3D"), std::pair(a.shotImage, "screenshotImage"),
          std::pair(a.quit, "quit")})
        act->setObjectName(QString::fromLatin1(name));
    connect(&session_, &Session::sceneChanged, this, [this] { syncViewActions(); });
    // What the status bar said of the last scene (its render, its structure) is not of this one.
    connect(&session_, &Session::aboutToChangeScene, statusBar(), &QStatusBar::clearMessage);
    syncViewActions();
}

void MainWindow::syncViewActions() {
    const bool scene = session_.hasScene(), in3D = scene && !session_.is2D();
    const Actions& a = actions_;
    for (QAction* act : {a.heatmap, a.renderAgain, a.resetCamera, a.shot3D, a.shotImage})
        act->setEnabled(in3D);
    rayTraceView_->setEnabled(in3D);
    if (renderBar_) renderBar_->setEnabled(in3D);
    a.shot2D->setEnabled(scene && session_.is2D());
}

void MainWindow::createMenus() {
    const Actions& a = actions_;
    QMenu* file = menus_.file = menuBar()->addMenu(tr("&File"));
    file->addActions({a.open, a.saveScene, a.exportTrace, a.shotWindow, a.shot2D, a.shot3D,
                      a.shotImage, a.exportReport});
    file->addSeparator();
    file->addAction(a.quit);
    menus_.edit = menuBar()->addMenu(tr("&Edit"));
    QMenu* replay = menus_.replay = menuBar()->addMenu(tr("&Replay"));
    replay->addActions({a.stepForward, a.stepBack, a.play, a.nextOfKind});
    replay->addSeparator();
    replay->addActions({a.replayBuild, a.exampleRay, a.first, a.last});
    QMenu* lessons = menus_.lessons = menuBar()->addMenu(tr("&Lessons"));
    lessons_->setLessonsMenu(lessons->addMenu(tr("&Built-in lessons")));
    lessons->addActions({a.openLessonFile, a.backToLesson});
    lessons->addSeparator();
    lessons->addActions({a.quizMode, a.presentMode, a.lecturer});
    lessons->addSeparator();
    lessons->addAction(a.showErrata);
    QMenu* view = menus_.view = menuBar()->addMenu(tr("&View"));
    view->addActions({a.compare, a.chooseCompare, a.renderAgain, a.heatmap, a.resetCamera});
    view->addAction(rayTraceView_);
    addLayoutActions(view);
    menus_.help = menuBar()->addMenu(tr("&Help"));
}

void MainWindow::openScene(const QString& nameOrPath, AccelKind kind, bool quiet,
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
            imageView_->setLessonPixel(std::nullopt);
            lessons_->showSceneIntro();
            // The lecture's 2D pictures use the 2D view; 3D scenes the 3D view and the image.
            showViews(session_.is2D(), !session_.is2D(), !session_.is2D());
            setWindowTitle(tr("raystep - %1").arg(nameOrPath));
            finishOpen(true, {});
        });
    if (!started) finishOpen(false, tr("the window is closing"));
}

void MainWindow::showScene(SceneRef scene, bool renderImage) {
    ++generation_;
    if (compare_) compare_->close();  // its trees are of the scene shown until now
    // What ran for the old scene is of no use now (and holds its own share of it meanwhile).
    runner_.cancel(TaskKind::Render);
    runner_.cancel(TaskKind::Build);
    runner_.cancel(TaskKind::Sweep);
    session_.adopt(std::move(scene));
    if (session_.is2D()) {
        session_.traceExampleRay();
        imageView_->clear();
    } else {
        syncRenderSettings(*session_.scene3D());
        if (renderImage)
            this->renderImage();
        else
            imageView_->clear(tr("This view shows no rendered image."));
        // A first ray to replay before any click: the image's centre.
        tracePixelHereOrInBackground(kImageWidth / 2, kImageHeight / 2, kImageWidth, kImageHeight);
    }
}

void MainWindow::showLive(SceneRef scene) {
    ++generation_;
    runner_.cancel(TaskKind::Render);
    runner_.cancel(TaskKind::Build);
    runner_.cancel(TaskKind::Sweep);
    runner_.cancel(TaskKind::Structure);
    session_.relive(std::move(scene));
}

void MainWindow::openFailed(const QString& what, const TaskOutcome& outcome, bool quiet) {
    if (outcome.cancelled) {
        statusBar()->showMessage(tr("Opening %1 cancelled").arg(what));
        finishOpen(false, tr("cancelled"));
        return;
    }
    openFailed(what, outcome.errorText(), quiet);
}

void MainWindow::openFailed(const QString& what, const QString& message, bool quiet) {
    if (!session_.hasScene()) {
        // Nothing was open before (a bad scene at start-up): say so where the user looks.
        lesson_->showText(tr("## Nothing is open\n\n%1 could not be opened:\n\n    %2\n\n"
                             "Pick a lesson above, or open a scene with *File > Open scene*.")
                              .arg(what, message));
        imageView_->clear(tr("No scene is open."));
        setWindowTitle(tr("raystep"));
    }
    if (!quiet) warn(tr("Cannot open %1").arg(what), message);
    statusBar()->showMessage(tr("Cannot open %1").arg(what));
    finishOpen(false, message);
}

void MainWindow::finishOpen(bool ok, const QString& error) {
    lastOpenOk_ = ok;
    lastOpenError_ = error;
    emit opened(ok, error);
}

void MainWindow::warn(const QString& title, const QString& text) {
    auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();  // window-modal, without a nested event loop
}

void MainWindow::createRenderSettings() {
    // Off at start: a lesson's text, its pixel and its exercises are in the scene's camera.
    rayTraceView_ = new QAction(tr("Ray trace this &view"), this);
    rayTraceView_->setObjectName("rayTraceView");
    rayTraceView_->setCheckable(true);
    rayTraceView_->setToolTip(
        tr("Render the image from the 3D view's camera, again at every "
           "move, coarse first and finer while nothing moves"));
    connect(rayTraceView_, &QAction::toggled, this, [this] { scheduleRender(); });
    imageView_->setRayTraceAction(rayTraceView_);
    connect(view3D_, &VtkView::cameraMoved, this, [this] {
        if (rayTraceView_->isChecked()) scheduleRender();
    });
    connect(view3D_, &VtkView::pointPicked, this, [this](QPointF p) { traceViewPoint(p); });
    // An image of the view's own size follows it (not after a cancel or a failure: the user
    // asks for that one again).
    connect(imageView_, &ImageView::renderSizeChanged, this, [this] { followImageSize(); });

    renderBar_ = new QToolBar(tr("Render settings"), this);
    renderBar_->setObjectName("renderSettingsBar");
    renderBar_->addAction(rayTraceView_);
    renderBar_->addSeparator();
    const auto box = [this](const QString& label, const QString& name, int lo, int hi,
                            const QString& tip) {
        auto* text = new QLabel(label);
        text->setContentsMargins(6, 0, 2, 0);
        renderBar_->addWidget(text);
        auto* b = new QSpinBox;
        b->setObjectName(name);
        b->setRange(lo, hi);  // the scene format's limits (docs/scene-format.md)
        b->setToolTip(tip);
        text->setBuddy(b);
        renderBar_->addWidget(b);
        connect(b, &QSpinBox::valueChanged, this, [this] { scheduleRender(); });
        return b;
    };
    bouncesBox_ = box(tr("&Bounces"), "renderBounces", 0, kMaxBounces,
                      tr("Depth of secondary rays (reflection, refraction, diffuse)"));
    diffuseBox_ = box(tr("&Diffuse samples"), "renderDiffuseSamples", 0, kMaxDiffuseSamples,
                      tr("Diffuse bounce rays at the first diffuse hit: colour bleeding"));
    sppBox_ = box(tr("&Samples per pixel"), "renderSpp", 1, kMaxSpp,
                  tr("Jittered samples per pixel: the last pass of the progressive render"));
    addToolBar(Qt::TopToolBarArea, renderBar_);
    // A 2D scene has no image to render: its settings would only take the lecturer's room.
    connect(&session_, &Session::sceneChanged, this,
            [this] { renderBar_->setVisible(!session_.is2D()); });
}

void MainWindow::syncRenderSettings(const Scene& scene) {
    {
        const QSignalBlocker block(imageView_);  // the render that follows has the new size
        imageView_->setSceneFrame(QSize(scene.settings.width, scene.settings.height));
    }
    // The scene's own settings, as the command line renders it; not a change by the user.
    for (auto [b, v] : {std::pair{bouncesBox_, scene.settings.bounces},
                        std::pair{diffuseBox_, scene.settings.diffuseSamples},
                        std::pair{sppBox_, scene.settings.spp}}) {
        const QSignalBlocker block(b);
        b->setValue(v);
    }
}

void MainWindow::scheduleRender() {
    if (renderPending_ || !session_.scene3D()) return;
    renderPending_ = true;
    // Once the events queued now are handled: a drag's many moves make one render, and the
    // running one is superseded (cancelled) by it.
    QTimer::singleShot(0, this, [this] {
        if (renderPending_) renderImage();
    });
}

void MainWindow::followImageSize() {
    // A cancelled or failed image waits for the user's "render again", whatever the size.
    const auto state = imageView_->state();
    if (!imageFrame_ || (state != ImageView::State::Done && state != ImageView::State::Rendering))
        return;
    if (imageView_->renderSize(imageFrame_->ofView) !=
        QSize(imageFrame_->width, imageFrame_->height))
        scheduleRender();
}

void MainWindow::takeFrame() {
    if (!frames_) return;
    if (std::optional<RenderFrame> f = frames_->take()) imageView_->showFrame(*f);
}

void MainWindow::traceViewPoint(QPointF widgetPos) {
    if (!session_.scene3D() || !view3D_->isVisible()) return;
    if (refusedWhileHeld(tr("trace a ray of the 3D view"))) return;
    // The ray under the mouse: pixel (x, y) of an image of the 3D view's size and camera.
    const int w = std::max(1, view3D_->width()), h = std::max(1, view3D_->height());
    const int x = std::clamp(static_cast<int>(widgetPos.x()), 0, w - 1);
    const int y = std::clamp(static_cast<int>(widgetPos.y()), 0, h - 1);
    const Camera camera = view3D_->currentCamera();
    if (!cameraUsable(camera)) return;
    TraceSettings settings;
    settings.bounces = bouncesBox_->value();
    settings.diffuseSamples = diffuseBox_->value();
    if (slowPixelTraces()) return tracePixelHereOrInBackground(x, y, w, h, camera, settings);
    session_.tracePixel(x, y, w, h, camera, settings);
    session_.setCursor(session_.size());
    statusBar()->showMessage(
        tr("3D view point (%1, %2): %3 events recorded").arg(x).arg(y).arg(session_.size()));
}

void MainWindow::renderImage() {
    renderPending_ = false;
    const Scene* scene = session_.scene3D();
    if (!scene) return;
    struct Rendered {
        RenderFrame frame;
        double ms = 0.0;
    };
    ImageFrame f;
    f.ofView = rayTraceView_->isChecked();
    f.camera = f.ofView ? view3D_->currentCamera() : scene->camera;
    if (!cameraUsable(f.camera)) {
        f.ofView = false;
        f.camera = scene->camera;
    }
    const QSize size = imageView_->renderSize(f.ofView);
    f.width = size.width();
    f.height = size.height();
    // What the control says (the scene's settings until the user changes them).
    f.trace.bounces = bouncesBox_->value();
    f.trace.diffuseSamples = diffuseBox_->value();
    f.spp = sppBox_->value();
    // Another view of the same scene keeps its picture until the new one's first pass.
    const bool sameScene = imageGeneration_ == generation_;
    imageFrame_ = f;
    imageGeneration_ = generation_;
    imageView_->setOfView(f.ofView);
    imageView_->renderStarted(f.width, f.height, sameScene);
    auto box = std::make_shared<FrameBox>();
    frames_ = box;
    const std::uint64_t generation = generation_;
    runner_.start<Rendered>(
        TaskKind::Render, tr("Rendering %1...").arg(QString::fromStdString(session_.name())),
        [ref = session_.sceneRef(), f, box](const ProgressFn& progress) {
            const Scene& s = std::get<Scene>(ref->scene);
            RenderOptions o;
            o.firstBlock = 8;  // a coarse picture at once, then the samples doubling
            o.refine = true;
            o.camera = f.camera;
            o.width = f.width;
            o.height = f.height;
            o.spp = f.spp;
            o.trace = f.trace;
            ProgressiveRender r(s, *ref->accel3D, o);
            const double passes = static_cast<double>(r.plan().size());
            while (!r.done()) {
                const double before = static_cast<double>(r.passesDone());
                if (!r.nextPass([&](double x) { return progress((before + x) / passes); }))
                    throw BuildCancelled();
                // Every pass but the last is shown as it comes; the last one by `done`.
                if (!r.done()) box->put(frameOf(r));
            }
            Rendered out;
            out.frame = frameOf(r);
            for (const double ms : r.passMs()) out.ms += ms;
            return out;
        },
        [this, generation, box](Rendered&& r, const TaskOutcome& outcome) {
            if (outcome.superseded || generation != generation_) return;
            if (outcome.cancelled) {
                renderPending_ = false;  // Cancel holds for a render scheduled meanwhile too
                imageView_->renderCancelled();
                statusBar()->showMessage(tr("Render cancelled"));
            } else if (outcome.error) {
                const QString why = outcome.errorText();
                imageView_->renderFailed(why);
                statusBar()->showMessage(tr("Render failed: %1").arg(why));
            } else {
                imageView_->finishFrame(r.frame, r.ms);
                statusBar()->showMessage(
                    tr("Rendered in %1 ms; click a pixel to trace it").arg(r.ms, 0, 'f', 0));
            }
        });
}

void MainWindow::openLesson(const QString& idOrPath, bool quiet) {
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
    const QString title = QString::fromStdString(lesson.title.in(lessons_->language()));
    const bool started = runner_.start<LessonController::Opened>(
        TaskKind::Scene, tr("Opening lesson %1: %2...").arg(lesson.number).arg(title),
        [lesson](const ProgressFn& progress) {
            return LessonController::prepare(lesson, progress);
        },
        [this, lesson, quiet, title](LessonController::Opened&& o, const TaskOutcome& outcome) {
            if (outcome.superseded) return;
            if (!outcome.ok()) {
                openFailed(tr("lesson %1").arg(lesson.number), outcome, quiet);
                lesson_->syncPicker();  // back to what is shown
                return;
            }
            const auto shows = [&](LessonView v) {
                return std::find(lesson.views.begin(), lesson.views.end(), v) != lesson.views.end();
            };
            // The old lesson ends before the new scene is shown: its hold and its notes about
            // the replay are not applied to what replaces them.
            lessons_->replaceLesson();
            showScene(std::move(o.scene), shows(LessonView::Image));
            // A new history, even on the same scene (lessons 10 and 11): an undo would bring
            // back an edit made in the lesson left.
            if (live2d_) live2d_->undoStack()->clear();
            session_.showLog(o.trace, LessonController::logKind(lesson));
            showViews(shows(LessonView::View2D), shows(LessonView::View3D),
                      shows(LessonView::Image));
            // The board beside a 2D lesson, or where the lesson asks (the 3D DDA's table); the
            // live controls beside a 2D one.
            boardDock_->setVisible(session_.is2D() || shows(LessonView::Board));
            liveDock_->setVisible(session_.is2D());
            lessons_->show(o.lesson, o.trace, std::move(o.others));
            // The pixel the lesson traces, marked on the image in the lesson's own image size.
            if (lesson.trace.kind == LessonTrace::Kind::Pixel)
                imageView_->setLessonPixel(
                    QRect(lesson.trace.x, lesson.trace.y, lesson.trace.width, lesson.trace.height));
            else
                imageView_->setLessonPixel(std::nullopt);
            setWindowTitle(tr("raystep - lesson %1: %2").arg(lesson.number).arg(title));
            finishOpen(true, {});
        });
    if (!started) finishOpen(false, tr("the window is closing"));
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
    const std::uint64_t generation = generation_;
    runner_.start<LogRef>(
        TaskKind::Build,
        tr("Recording the construction of the %1...").arg(structureName(session_.kind())),
        [ref = session_.sceneRef()](const ProgressFn& progress) {
            return Session::recordBuild(ref, progress);
        },
        [this, generation](LogRef&& log, const TaskOutcome& outcome) {
            if (outcome.superseded || generation != generation_) return;
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

void MainWindow::openCompare() {
    openCompare(defaultComparison(session_.kind()));
}

std::optional<std::pair<int, StructureChoice>> MainWindow::heldAmong(
    const std::vector<StructureChoice>& choices) const {
    // Each column replays its whole trace and counts it: not one that an unsolved exercise of
    // the lesson asks about (lesson 10 asks each structure's tests), whichever is shown now.
    for (const StructureChoice& c : choices) {
        LessonSetup setup{c.kind, session_.options()};
        if (c.split) setup.options.setSplit(*c.split);
        if (const auto held = lesson_->heldBy(setup.key())) return std::pair(held->first, c);
    }
    return std::nullopt;
}

bool MainWindow::refusedWhileAnyHeld(const std::vector<StructureChoice>& choices) {
    if (refusedWhileHeld(tr("compare structures on the ray"))) return true;
    const auto held = heldAmong(choices);
    if (!held) return false;
    const QString why = tr("Exercise %1 asks about the %2: answer it first, or put it away, to "
                           "compare structures on the ray.")
                            .arg(held->first + 1)
                            .arg(choiceLabel(held->second));
    lesson_->showHeldNote(why);
    statusBar()->showMessage(why, 10000);
    return true;
}

void MainWindow::chooseCompare() {
    if (!session_.hasScene()) {
        statusBar()->showMessage(tr("No scene is open: nothing to compare."));
        return;
    }
    if (refusedWhileHeld(tr("compare structures on the ray"))) return;
    if (chooser_) {
        chooser_->raise();
        return;
    }
    // Opened on what was compared last, else on the comparison made for the structure shown;
    // not modal by exec() (no nested event loop: architecture.md), window-modal by open().
    const auto last = CompareChooser::fromText(QSettings().value("compare/choice").toString());
    auto* chooser = new CompareChooser(last ? *last : defaultComparison(session_.kind()), this);
    chooser->setAttribute(Qt::WA_DeleteOnClose);
    connect(chooser, &QDialog::accepted, this, [this, chooser] {
        QSettings().setValue("compare/choice", CompareChooser::toText(chooser->choices()));
        openCompare(chooser->choices());
    });
    chooser_ = chooser;
    chooser->open();
}

CompareChooser* MainWindow::compareChooser() const {
    return chooser_.data();
}

void MainWindow::openCompare(const std::vector<StructureChoice>& choices) {
    if (!session_.hasScene()) {
        statusBar()->showMessage(tr("No scene is open: nothing to compare."));
        return;
    }
    if (choices.empty()) return;
    // Compare mode replays whole traces: not while an exercise holds them (quiz mode).
    if (refusedWhileAnyHeld(choices)) return;
    // 3D: the pixel being replayed, in the image it is a pixel of (its event says: clicked on
    // the image, or a lesson's), else the image's centre.
    CompareWindow::Pixel pixel{kImageWidth / 2, kImageHeight / 2, kImageWidth, kImageHeight};
    for (const Event& e : session_.log().events())
        if (const auto* p = std::get_if<PixelResult>(&e)) {
            pixel = {static_cast<int>(p->x), static_cast<int>(p->y), kImageWidth, kImageHeight};
            if (p->width > 0 && p->height > 0)  // 0: a trace written before the frame was
                pixel.width = static_cast<int>(p->width),
                pixel.height = static_cast<int>(p->height);
        }
    QStringList names;
    for (const StructureChoice& c : choices) names << choiceLabel(c);
    // Several structures over a big mesh take seconds: built in the background, with Cancel.
    const std::uint64_t generation = generation_;
    runner_.start<CompareWindow::Prepared>(
        TaskKind::Compare, tr("Building %1...").arg(names.join(QStringLiteral(", "))),
        [scene = session_.sceneRef(), choices](const ProgressFn& progress) {
            return CompareWindow::prepare(scene, choices, progress);
        },
        [this, generation, pixel, choices](CompareWindow::Prepared&& prepared,
                                           const TaskOutcome& outcome) {
            if (outcome.superseded || generation != generation_) return;
            // An exercise may have come to hold the replay while the structures were built.
            if (refusedWhileAnyHeld(choices)) return;
            if (outcome.cancelled) {
                statusBar()->showMessage(tr("Compare cancelled"));
                return;
            }
            if (outcome.error) {
                warn(tr("Compare"), outcome.errorText());
                return;
            }
            // A window of its own that closes with this one.
            if (compare_) compare_->close();
            auto* compare = new CompareWindow(std::move(prepared), pixel, this);
            compare->setWindowFlag(Qt::Window);
            compare->setAttribute(Qt::WA_DeleteOnClose);
            compare->placeOnScreen(fitToScreen(QSize(1400, 800)),
                                   fitToScreen(QSize(1 << 16, 1 << 16)));
            // The window's own keys work there too: Quit, the zoom, the keyboard shortcuts.
            const PresenterActions& p = presenterActions_;
            compare->addActions({actions_.quit, p.zoomIn, p.zoomOut, p.resetZoom, p.shortcuts});
            compare->show();
            compare_ = compare;
        });
}

CompareWindow* MainWindow::compareWindow() const {
    return compare_.data();
}

QSize MainWindow::fitToScreen(QSize wanted) const {
    const QScreen* s = screen();
    if (!s) return wanted;
    const QSize room = s->availableGeometry().size() - QSize(40, 60);  // frame and title bar
    return wanted.boundedTo(room.expandedTo(QSize(640, 480)));
}

void MainWindow::whenIdle(std::function<void()> f) {
    if (!runner_.busy()) {
        QTimer::singleShot(0, this, std::move(f));
        return;
    }
    auto once = std::make_shared<QMetaObject::Connection>();
    *once = connect(&runner_, &TaskRunner::idle, this, [once, f = std::move(f)] {
        QObject::disconnect(*once);
        f();
    });
}

bool MainWindow::waitUntilIdle(int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    // A render scheduled (a move, a resize) counts as work: it starts once events settle.
    const auto busy = [this] { return runner_.busy() || renderPending_; };
    for (;;) {
        while (busy() && clock.elapsed() < timeoutMs)
            QApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents, 20);
        QApplication::processEvents();
        if (!busy()) return true;
        if (clock.elapsed() >= timeoutMs) return false;
    }
}

QString MainWindow::inspectorText() const {
    return inspector_->toPlainText();
}

void MainWindow::stepForward() {
    timeline_->stepForward();
}
void MainWindow::stepBack() {
    timeline_->stepBack();
}
void MainWindow::jumpToNextOfKind() {
    timeline_->jumpToNextOfKind();
}
void MainWindow::togglePlay() {
    timeline_->togglePlay();
}

void MainWindow::openFileDialog() {
    // Models too: the scene is made around them (model_import.h). Not the lesson's structure
    // (brute force in lesson 1 would take minutes on a big mesh): the chooser's, else a kd-tree.
    const QString path = openFileName(
        this, tr("Open scene"),
        tr("Scenes and models (*.json *.obj *.ply *.stl *.gltf *.glb)") + ";;" +
            tr("Scenes (*.json)") + ";;" + tr("Models (*.obj *.ply *.stl *.gltf *.glb)"));
    if (!path.isEmpty()) openScene(path, openKind(), false, openOptions());
}

QString savePng(const QImage& image, const QString& path) {
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) return path + ": cannot encode the image as PNG";
    try {
        writeFileAtomic(path.toStdString(), png.toStdString());
    } catch (const std::exception& e) {
        return QString::fromStdString(printable(e.what(), 4096));
    }
    return {};
}

void MainWindow::exportScreenshot(QWidget* w, const QString& what) {
    // A hidden view would be saved as its placeholder ("The 3D view shows 3D scenes").
    if (!w->isVisible()) {
        statusBar()->showMessage(
            tr("The %1 is not shown with this scene: there is nothing of it to export").arg(what));
        return;
    }
    const QString path =
        saveFileName(this, tr("Screenshot of the %1").arg(what), tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    if (const QString problem = savePng(w->grab().toImage(), path); !problem.isEmpty())
        QMessageBox::warning(this, tr("Cannot save"), problem);
}

void MainWindow::exportTrace() {
    // The file holds the whole trace, past where an exercise holds the replay.
    if (refusedWhileHeld(tr("export the trace"))) return;
    const QString path = saveFileName(this, tr("Export trace"), tr("Trace files (*.json)"));
    if (path.isEmpty()) return;
    TraceInfo info;
    info.scene = session_.name();
    info.accel = std::string(accelKindName(session_.kind()));
    info.what = session_.is2D() ? "ray" : "pixel";
    try {
        writeFileAtomic(path.toStdString(), traceToJson(session_.log(), info));
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Cannot save"), QString::fromUtf8(e.what()));
    }
}

void MainWindow::closeEvent(QCloseEvent* e) {
    // Answers the last save could not write: asked about first (lesson_controller.h).
    if (!lessons_->allowClose()) {
        e->ignore();
        return;
    }
    saveLayout();
    // Stop and join every worker now, and start none after: the window is going away.
    runner_.shutdown();
    if (compare_) compare_->close();
    e->accept();
}

}  // namespace raystep::gui
