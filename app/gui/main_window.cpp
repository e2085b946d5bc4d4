#include "main_window.h"

#include "compare_window.h"
#include "image_view.h"
#include "lesson_panel.h"
#include "view2d.h"
#include "vtk_view.h"

#include "course/grid_sweep.h"
#include "course/lesson_trace.h"

#include "raystep/base/file_error.h"
#include "raystep/render/image.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/trace/trace_io.h"
#include "raystep/render/tracer.h"

#include <QAbstractListModel>
#include <QAction>
#include <QApplication>
#include <QBuffer>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QLockFile>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSaveFile>
#include <QScreen>
#include <QSettings>
#include <QSlider>
#include <QSortFilterProxyModel>
#include <QSpinBox>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <cstring>
#include <exception>

namespace raystep::gui {

/// The log as a list: rows are made when shown, so a million events cost nothing up front.
class EventListModel : public QAbstractListModel {
  public:
    explicit EventListModel(Session& s, QObject* parent) : QAbstractListModel(parent), s_(s) {
        connect(&s_, &Session::logChanged, this, [this] {
            beginResetModel();
            endResetModel();
        });
    }
    int rowCount(const QModelIndex& parent) const override {
        return parent.isValid() ? 0 : static_cast<int>(s_.size());
    }
    QVariant data(const QModelIndex& index, int role) const override {
        if (role != Qt::DisplayRole || !index.isValid()) return {};
        return QStringLiteral("%1  %2")
            .arg(index.row() + 1)
            .arg(describeEvent(s_.log().events()[index.row()]));
    }

  private:
    Session& s_;
};

namespace {
// Event kinds the timeline can jump to, with their variant index.
const std::pair<const char*, std::size_t> kJumpKinds[] = {
    {QT_TRANSLATE_NOOP("raystep::gui::MainWindow", "DDA step"), variantIndex<DdaCell>()},
    {QT_TRANSLATE_NOOP("raystep::gui::MainWindow", "primitive test"),
     variantIndex<PrimitiveTest>()},
    {QT_TRANSLATE_NOOP("raystep::gui::MainWindow", "mailbox skip"), variantIndex<MailboxSkip>()},
    {QT_TRANSLATE_NOOP("raystep::gui::MainWindow", "node enter"), variantIndex<NodeEnter>()},
    {QT_TRANSLATE_NOOP("raystep::gui::MainWindow", "ray begin"), variantIndex<RayBegin>()},
    {QT_TRANSLATE_NOOP("raystep::gui::MainWindow", "hit"), variantIndex<RayHit>()},
    {QT_TRANSLATE_NOOP("raystep::gui::MainWindow", "split chosen"), variantIndex<SplitChosen>()},
};
constexpr int kImageWidth = 320, kImageHeight = 240;
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    buildUi();
    // The student's progress: one JSON file under the user's data folder, replaced atomically.
    progressPath_ =
        QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/progress.json";
    try {
        if (auto saved = loadProgressFile(progressPath_.toStdString()))
            studentProgress_ = std::move(*saved);
    } catch (const LessonError& e) {
        // Keep the unreadable file aside rather than overwrite it at the next answer.
        QFile::rename(progressPath_, progressPath_ + ".unreadable");
        statusBar()->showMessage(tr("Progress file unreadable, kept as %1: %2")
                                     .arg(progressPath_ + ".unreadable", e.what()));
    }
    QSettings settings;
    geometryRestored_ = restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
}

MainWindow::~MainWindow() {
    // Before any member or child goes: no worker may still read what they own.
    runner_.shutdown();
}

void MainWindow::buildUi() {
    setWindowTitle(tr("raystep"));
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

    // The timeline: step, play, jump to the next event of a kind, speed, scrubber.
    auto* timeline = new QWidget;
    auto* tl = new QHBoxLayout(timeline);
    tl->setContentsMargins(6, 2, 6, 2);
    const auto button = [&](const QString& text, const QString& tip, auto slot) {
        auto* b = new QToolButton;
        b->setText(text);
        b->setToolTip(tip);
        connect(b, &QToolButton::clicked, this, slot);
        tl->addWidget(b);
        return b;
    };
    button(QStringLiteral("|<"), tr("First event (Home)"), [this] { session_.setCursor(0); });
    button(QStringLiteral("<"), tr("Step back (Left)"), [this] { stepBack(); });
    play_ = button(QStringLiteral(">"), tr("Play / pause (Space)"), [this] { togglePlay(); });
    button(QStringLiteral(">|"), tr("Step forward (Right)"), [this] { stepForward(); });
    kindCombo_ = new QComboBox;
    for (const auto& [name, kind] : kJumpKinds) kindCombo_->addItem(tr(name));
    tl->addWidget(kindCombo_);
    button(tr("next"), tr("Jump to the next event of this kind (N)"),
           [this] { jumpToNextOfKind(); });
    tl->addWidget(new QLabel(tr("speed")));
    speed_ = new QSpinBox;
    speed_->setRange(1, 200);
    speed_->setValue(4);
    speed_->setSuffix(tr(" /s"));
    tl->addWidget(speed_);
    scrubber_ = new QSlider(Qt::Horizontal);
    tl->addWidget(scrubber_, 1);
    position_ = new QLabel;
    tl->addWidget(position_);
    connect(scrubber_, &QSlider::valueChanged, this,
            [this](int v) { session_.setCursor(static_cast<std::size_t>(v)); });

    auto* centre = new QWidget;
    auto* cl = new QVBoxLayout(centre);
    cl->setContentsMargins(0, 0, 0, 0);
    cl->addWidget(views, 1);
    cl->addWidget(timeline);
    auto* main = new QSplitter(Qt::Horizontal);
    main->addWidget(lesson_);
    main->addWidget(centre);
    lesson_->setMinimumWidth(260);
    main->setStretchFactor(0, 1);
    main->setStretchFactor(1, 4);
    main->setSizes({360, 1100});
    setCentralWidget(main);

    // Inspector and event list, as docks the user may move (kept with QSettings).
    inspector_ = new QTextBrowser;
    inspector_->setObjectName("inspector");
    auto* inspectorDock = new QDockWidget(tr("Inspector"), this);
    inspectorDock->setObjectName("inspectorDock");
    inspectorDock->setWidget(inspector_);
    addDockWidget(Qt::RightDockWidgetArea, inspectorDock);
    auto* listPanel = new QWidget;
    auto* ll = new QVBoxLayout(listPanel);
    ll->setContentsMargins(0, 0, 0, 0);
    filterEdit_ = new QLineEdit;
    filterEdit_->setPlaceholderText(tr("Filter events (e.g. cell, test, mailbox)"));
    ll->addWidget(filterEdit_);
    eventModel_ = new EventListModel(session_, this);
    eventFilter_ = new QSortFilterProxyModel(this);
    eventFilter_->setSourceModel(eventModel_);
    eventFilter_->setFilterCaseSensitivity(Qt::CaseInsensitive);
    connect(filterEdit_, &QLineEdit::textChanged, eventFilter_,
            &QSortFilterProxyModel::setFilterFixedString);
    events_ = new QListView;
    events_->setModel(eventFilter_);
    events_->setUniformItemSizes(true);
    ll->addWidget(events_);
    connect(events_, &QListView::clicked, this, [this](const QModelIndex& i) {
        session_.setCursor(static_cast<std::size_t>(eventFilter_->mapToSource(i).row()) + 1);
    });
    auto* listDock = new QDockWidget(tr("Events"), this);
    listDock->setObjectName("eventsDock");
    listDock->setWidget(listPanel);
    addDockWidget(Qt::RightDockWidgetArea, listDock);

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
    connect(cancel_, &QPushButton::clicked, this, [this] { runner_.cancelAll(); });
    connect(&runner_, &TaskRunner::progressChanged, this,
            [this](const QString& label, int percent) {
                const bool running = !label.isEmpty();
                taskLabel_->setText(label);
                progress_->setVisible(running);
                cancel_->setVisible(running);
                progress_->setValue(percent);
                if (runner_.busy(TaskKind::Render))
                    imageView_->renderProgress(runner_.percent(TaskKind::Render));
            });
    connect(imageView_, &ImageView::renderRequested, this, [this] { renderImage(); });
    connect(imageView_, &ImageView::pixelClicked, this, [this](int x, int y) {
        session_.tracePixel(x, y, kImageWidth, kImageHeight);
        session_.setCursor(session_.size());
        statusBar()->showMessage(
            tr("Pixel (%1, %2): %3 events recorded").arg(x).arg(y).arg(session_.size()));
    });

    timer_ = new QTimer(this);
    connect(timer_, &QTimer::timeout, this, [this] {
        if (session_.cursor() >= session_.size()) return togglePlay();
        stepForward();
    });
    connect(speed_, &QSpinBox::valueChanged, this,
            [this](int v) { timer_->setInterval(1000 / v); });
    timer_->setInterval(1000 / speed_->value());

    connect(&session_, &Session::cursorChanged, this, [this] { updateTimeline(); });
    connect(&session_, &Session::logChanged, this, [this] {
        updateTimeline();
        if (lesson_->hasLesson()) {
            lesson_->setReplayNote(replayDescription());
        } else if (session_.showingBuild()) {
            lesson_->showText(
                tr("## Building the %1\n\nEach node is split by a plane. Step through the "
                   "**candidate** planes (dashed): the chart under the scene draws the cost of "
                   "each, "
                   "`Cost = C_trav + P(L|C) Cost(L) + P(R|C) Cost(R)` with `P = Area(L) / Area(C)` "
                   "(in 2D the area of a cell is its perimeter). The **chosen** plane (red) is the "
                   "cheapest, taken only if it beats the leaf's cost (dashed line). Jump to the "
                   "next "
                   "choice with the *split chosen* kind and **N**.")
                    .arg(QString::fromUtf8(accelKindName(session_.kind()).data())));
        }
    });

    // The lesson panel asks; the window moves the replay, opens lessons, saves progress.
    connect(lesson_, &LessonPanel::lessonRequested, this,
            [this](const QString& id) { openLesson(id); });
    connect(lesson_, &LessonPanel::stepShown, this, [this](int i) { applyStep(i); });
    connect(lesson_, &LessonPanel::lessonTraceRequested, this, [this] {
        showLessonTrace();
        applyStep(lesson_->step());
    });
    connect(lesson_, &LessonPanel::exerciseShown, this, [this](int i) {
        showLessonTrace();
        const auto at = resolvePosition(lesson_->lesson().exercises[i].at, session_.log());
        if (at) session_.setCursor(*at);
    });
    connect(lesson_, &LessonPanel::answered, this, [this] { saveProgress(); });
    connect(lesson_, &LessonPanel::sweepRequested, this, [this] { runSweep(); });
    connect(view2D_, &View2D::cellClicked, lesson_, &LessonPanel::fillCell);

    // Menus and the standard shortcuts.
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open scene..."), QKeySequence::Open, this, [this] { openFileDialog(); });
    file->addAction(tr("Export &trace..."), QKeySequence::Save, this, [this] { exportTrace(); });
    file->addAction(tr("Export screenshot of the &window..."), this,
                    [this] { exportScreenshot(this, tr("window")); });
    file->addAction(tr("Export screenshot of the &2D view..."), this,
                    [this] { exportScreenshot(view2D_, tr("2D view")); });
    file->addAction(tr("Export screenshot of the &3D view..."), this,
                    [this] { exportScreenshot(view3D_, tr("3D view")); });
    file->addAction(tr("Export screenshot of the &image view..."), this,
                    [this] { exportScreenshot(imageView_, tr("image view")); });
    file->addAction(tr("Export &progress report..."), this, [this] { exportProgressReport(); });
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    QMenu* replay = menuBar()->addMenu(tr("&Replay"));
    replay->addAction(tr("Step &forward"), QKeySequence(Qt::Key_Right), this,
                      [this] { stepForward(); });
    replay->addAction(tr("Step &back"), QKeySequence(Qt::Key_Left), this, [this] { stepBack(); });
    replay->addAction(tr("&Play / pause"), QKeySequence(Qt::Key_Space), this,
                      [this] { togglePlay(); });
    replay->addAction(tr("&Next event of the kind"), QKeySequence(Qt::Key_N), this,
                      [this] { jumpToNextOfKind(); });
    replay->addSeparator();
    replay->addAction(tr("Replay the &build (candidates, splits, leaves)"), QKeySequence(Qt::Key_B),
                      this, [this] { replayBuild(); });
    replay->addAction(tr("Replay the &example ray"), QKeySequence(Qt::Key_R), this, [this] {
        if (session_.is2D())
            session_.traceExampleRay();
        else
            statusBar()->showMessage(
                tr("R replays the example ray of a 2D scene; in 3D, click "
                   "a pixel of the image."));
    });
    replay->addAction(tr("&First event"), QKeySequence(Qt::Key_Home), this,
                      [this] { session_.setCursor(0); });
    replay->addAction(tr("&Last event"), QKeySequence(Qt::Key_End), this,
                      [this] { session_.setCursor(session_.size()); });
    QMenu* lessons = menuBar()->addMenu(tr("&Lessons"));
    lessonsMenu_ = lessons->addMenu(tr("&Built-in lessons"));
    fillLessonsMenu();
    lessons->addAction(tr("Open lesson &file..."), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open lesson"), QString(),
                                                          tr("Lessons (*.json)"));
        if (!path.isEmpty()) openLesson(path);
    });
    lecturerAction_ = lessons->addAction(tr("&Lecturer mode (show answers)"));
    lecturerAction_->setCheckable(true);
    lecturerAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    connect(lecturerAction_, &QAction::toggled, lesson_, &LessonPanel::setLecturerMode);
    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("&Compare midpoint, median and SAH..."), QKeySequence(Qt::Key_C), this,
                    [this] { openCompare(); });
    view->addAction(tr("Render the &image again"), this, [this] { renderImage(); });
    QAction* heat = view->addAction(tr("&Heat map of primitive tests"));
    heat->setCheckable(true);
    connect(heat, &QAction::toggled, imageView_, &ImageView::setHeatmap);
    view->addAction(tr("&Reset 3D camera"), this, [this] { view3D_->resetCamera(); });
}

void MainWindow::openScene(const QString& nameOrPath, AccelKind kind, bool quiet,
                           const AccelOptions& base, bool renderImage) {
    lastOpenOk_.reset();
    const bool started = runner_.start<SceneRef>(
        TaskKind::Scene,
        tr("Loading %1 and building its %2...")
            .arg(nameOrPath, QString::fromUtf8(accelKindName(kind).data())),
        [path = nameOrPath.toStdString(), kind, base](const ProgressFn& progress) {
            AccelOptions options = base;
            options.setProgress(progress);
            return Session::prepare(path, kind, options);
        },
        [this, nameOrPath, quiet, renderImage](SceneRef&& scene, const TaskOutcome& outcome) {
            if (outcome.superseded) return;  // a newer open is under way
            if (!outcome.ok()) return openFailed(nameOrPath, outcome, quiet);
            showScene(std::move(scene), renderImage);
            if (session_.is2D()) {
                lesson_->showText(
                    tr("## %1\n\n%2\n\nThe ray is the slides' example. Step with **Right** and "
                       "**Left**, play with **Space**, jump to the next event of a kind with "
                       "**N**. The inspector shows X, Y, tMax and tDelta as on the board; the list "
                       "shows every event.")
                        .arg(QString::fromStdString(session_.name()),
                             QString::fromStdString(session_.scene2D()->description)));
            } else {
                lesson_->showText(
                    tr("## %1\n\n%2\n\nClick a pixel of the image to trace it: its ray tree is "
                       "recorded and replayed in the 3D view, the inspector and the event list.")
                        .arg(QString::fromStdString(session_.name()),
                             QString::fromStdString(session_.scene3D()->description)));
            }
            // The lecture's 2D pictures use the 2D view; 3D scenes the 3D view and the image.
            view2D_->setVisible(session_.is2D());
            view3D_->setVisible(!session_.is2D());
            imageView_->setVisible(!session_.is2D());
            view3D_->parentWidget()->setVisible(!session_.is2D());
            setWindowTitle(tr("raystep - %1").arg(nameOrPath));
            finishOpen(true, {});
        });
    if (!started) finishOpen(false, tr("the window is closing"));
}

void MainWindow::showScene(SceneRef scene, bool renderImage) {
    ++generation_;
    // What ran for the old scene is of no use now (and holds its own share of it meanwhile).
    runner_.cancel(TaskKind::Render);
    runner_.cancel(TaskKind::Build);
    runner_.cancel(TaskKind::Sweep);
    session_.adopt(std::move(scene));
    if (session_.is2D()) {
        session_.traceExampleRay();
        imageView_->clear();
    } else {
        if (renderImage)
            this->renderImage();
        else
            imageView_->clear(tr("This view shows no rendered image."));
        // A first ray to replay before any click: the image's centre.
        session_.tracePixel(kImageWidth / 2, kImageHeight / 2, kImageWidth, kImageHeight);
    }
    updateTimeline();
}

void MainWindow::openFailed(const QString& what, const TaskOutcome& outcome, bool quiet) {
    if (outcome.cancelled) {
        statusBar()->showMessage(tr("Opening %1 cancelled").arg(what));
        finishOpen(false, tr("cancelled"));
        return;
    }
    const QString message = outcome.errorText();
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

void MainWindow::renderImage() {
    const Scene* scene = session_.scene3D();
    if (!scene) return;
    struct Rendered {
        QImage image, heat;
        double ms = 0.0;
    };
    imageView_->renderStarted(kImageWidth, kImageHeight);
    const std::uint64_t generation = generation_;
    runner_.start<Rendered>(
        TaskKind::Render, tr("Rendering %1...").arg(QString::fromStdString(session_.name())),
        [ref = session_.sceneRef()](const ProgressFn& progress) {
            const Scene& s = std::get<Scene>(ref->scene);
            RenderOptions opt;
            opt.width = kImageWidth;
            opt.height = kImageHeight;
            // What the scene asks for, as the command line renders it (only the size is ours).
            opt.spp = s.settings.spp;
            opt.trace.bounces = s.settings.bounces;
            opt.trace.diffuseSamples = s.settings.diffuseSamples;
            const RenderResult r = raystep::render(s, *ref->accel3D, opt, progress);
            if (r.cancelled) throw BuildCancelled();
            Rendered out;
            out.image = QImage(opt.width, opt.height, QImage::Format_RGB888);
            const auto rgb = toSrgb8(r.image);
            for (int y = 0; y < opt.height; ++y)
                std::memcpy(out.image.scanLine(y), rgb.data() + std::size_t(y) * opt.width * 3,
                            opt.width * 3);
            out.heat = QImage(opt.width, opt.height, QImage::Format_RGB888);
            const auto h = heatmapRgb8(r.costPerPixel, opt.width, opt.height);
            for (int y = 0; y < opt.height; ++y)
                std::memcpy(out.heat.scanLine(y), h.data() + std::size_t(y) * opt.width * 3,
                            opt.width * 3);
            out.ms = r.renderMs;
            return out;
        },
        [this, generation](Rendered&& r, const TaskOutcome& outcome) {
            if (outcome.superseded || generation != generation_) return;
            if (outcome.cancelled) {
                imageView_->renderCancelled();
                statusBar()->showMessage(tr("Render cancelled"));
            } else if (outcome.error) {
                const QString why = outcome.errorText();
                imageView_->renderFailed(why);
                statusBar()->showMessage(tr("Render failed: %1").arg(why));
            } else {
                imageView_->renderFinished(r.image, r.heat, r.ms);
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
        if (!quiet) warn(tr("Cannot open the lesson"), QString::fromUtf8(e.what()));
        finishOpen(false, QString::fromUtf8(e.what()));
        return;
    }
    struct Opened {
        SceneRef scene;
        LogRef trace;
    };
    const QString title = QString::fromStdString(lesson.title.in(lang_));
    const bool started = runner_.start<Opened>(
        TaskKind::Scene, tr("Opening lesson %1: %2...").arg(lesson.number).arg(title),
        [lesson](const ProgressFn& progress) {
            AccelOptions options = lesson.options;
            options.setProgress(progress);
            Opened o;
            o.scene = Session::prepare(lessonScenePath(lesson), lesson.accel, options);
            o.trace = recordLessonTrace(lesson, o.scene->scene,
                                        o.scene->accel3D ? &*o.scene->accel3D : nullptr,
                                        o.scene->accel2D ? &*o.scene->accel2D : nullptr);
            return o;
        },
        [this, lesson, quiet, title](Opened&& o, const TaskOutcome& outcome) {
            if (outcome.superseded) return;
            if (!outcome.ok()) {
                openFailed(tr("lesson %1").arg(lesson.number), outcome, quiet);
                lesson_->syncPicker();  // back to what is shown
                return;
            }
            const auto shows = [&](LessonView v) {
                return std::find(lesson.views.begin(), lesson.views.end(), v) != lesson.views.end();
            };
            showScene(std::move(o.scene), shows(LessonView::Image));
            session_.showLog(o.trace, lesson.trace.kind == LessonTrace::Kind::Build
                                          ? LogKind::Build
                                          : LogKind::Lesson);
            view2D_->setVisible(shows(LessonView::View2D));
            view3D_->setVisible(shows(LessonView::View3D));
            imageView_->setVisible(shows(LessonView::Image));
            view3D_->parentWidget()->setVisible(shows(LessonView::View3D) ||
                                                shows(LessonView::Image));
            // The panel records answers into this lesson's progress (std::map entries do not
            // move) and grades them against its own share of the trace.
            lesson_->showLesson(lesson, o.trace, &studentProgress_.lessons[lesson.id]);
            setWindowTitle(tr("raystep - lesson %1: %2").arg(lesson.number).arg(title));
            applyStep(lesson_->step());
            finishOpen(true, {});
        });
    if (!started) finishOpen(false, tr("the window is closing"));
}

void MainWindow::showLessonTrace() {
    if (!lesson_->hasLesson() || !lesson_->lessonLog()) return;
    if (session_.logRef() == lesson_->lessonLog()) return;
    session_.showLog(lesson_->lessonLog(), lesson_->lesson().trace.kind == LessonTrace::Kind::Build
                                               ? LogKind::Build
                                               : LogKind::Lesson);
}

QString MainWindow::replayDescription() const {
    if (!lesson_->hasLesson() || session_.logRef() == lesson_->lessonLog()) return {};
    switch (session_.logKind()) {
        case LogKind::Pixel:
            for (auto it = session_.log().events().rbegin(); it != session_.log().events().rend();
                 ++it)
                if (const auto* p = std::get_if<PixelResult>(&*it))
                    return tr("the ray tree of pixel (%1, %2)").arg(p->x).arg(p->y);
            return tr("a pixel's ray tree");
        case LogKind::ExampleRay:
            return tr("the scene's example ray");
        case LogKind::Build:
            return tr("the construction of the %1")
                .arg(QString::fromUtf8(accelKindName(session_.kind()).data()));
        default:
            return tr("another trace");
    }
}

void MainWindow::replayBuild() {
    if (!session_.hasScene()) {
        statusBar()->showMessage(tr("No scene is open."));
        return;
    }
    if (!Session::hasBuild(session_.kind())) {
        statusBar()->showMessage(
            tr("A %1 has no construction to replay: B replays how a kd-tree or a BVH is built.")
                .arg(QString::fromUtf8(accelKindName(session_.kind()).data())));
        return;
    }
    const std::uint64_t generation = generation_;
    runner_.start<LogRef>(
        TaskKind::Build,
        tr("Recording the construction of the %1...")
            .arg(QString::fromUtf8(accelKindName(session_.kind()).data())),
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

void MainWindow::applyStep(int index) {
    if (!lesson_->hasLesson() || lesson_->lesson().steps.empty()) {
        session_.setCursor(session_.size());
        return;
    }
    showLessonTrace();
    const LessonStep& step = lesson_->lesson().steps[index];
    if (const auto at = resolvePosition(step.at, session_.log())) session_.setCursor(*at);
    filterEdit_->setText(QString::fromStdString(step.filter));
    if (step.camera)
        view3D_->orbit(step.camera->azimuth, step.camera->elevation, step.camera->zoom);
    studentProgress_.lessons[lesson_->lesson().id].step = index;
    saveProgress();
}

void MainWindow::saveProgress() {
    // Another window of the app may have saved since: fold its answers in under a lock, then
    // write beside and rename (QSaveFile), so neither a crash nor a second window loses work.
    QDir().mkpath(QFileInfo(progressPath_).absolutePath());
    QLockFile lock(progressPath_ + ".lock");
    if (!lock.tryLock(2000)) {
        statusBar()->showMessage(tr("Cannot save the progress: %1 is locked").arg(progressPath_));
        return;
    }
    try {
        if (const auto saved = loadProgressFile(progressPath_.toStdString()))
            mergeProgress(studentProgress_, *saved);
    } catch (const LessonError&) {
        // Unreadable now (it was read at start): replaced by what this window knows.
    }
    QSaveFile f(progressPath_);
    if (!f.open(QIODevice::WriteOnly) ||
        f.write(QByteArray::fromStdString(progressToJson(studentProgress_))) < 0 || !f.commit())
        statusBar()->showMessage(tr("Cannot save the progress to %1").arg(progressPath_));
}

void MainWindow::exportProgressReport() {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export progress report"),
                                     QStringLiteral("raystep-progress.md"), tr("Markdown (*.md)"));
    if (path.isEmpty()) return;
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) ||
        f.write(QByteArray::fromStdString(
            progressReport(studentProgress_, builtinLessons(), lang_))) < 0 ||
        !f.commit())
        QMessageBox::warning(this, tr("Cannot save"), tr("Could not write %1").arg(path));
}

void MainWindow::runSweep() {
    if (!lesson_->hasLesson() || !lesson_->lesson().sweep || !session_.hasScene()) return;
    const GridSweepSpec spec = *lesson_->lesson().sweep;
    const std::uint64_t generation = generation_;
    const LogRef lessonLog = lesson_->lessonLog();
    runner_.start<std::vector<GridSweepRow>>(
        TaskKind::Sweep,
        tr("Tracing the same rays at %1 grid resolutions...").arg(spec.resolutions.size()),
        [ref = session_.sceneRef(), spec](const ProgressFn& progress) {
            return runGridSweep(ref->scene, spec, progress);
        },
        [this, generation, lessonLog](std::vector<GridSweepRow>&& rows,
                                      const TaskOutcome& outcome) {
            // Only for the lesson that asked.
            if (outcome.superseded || generation != generation_ ||
                lesson_->lessonLog() != lessonLog)
                return;
            if (outcome.ok())
                lesson_->showSweep(rows);
            else
                statusBar()->showMessage(outcome.cancelled ? tr("Sweep cancelled")
                                                           : tr("The sweep failed"));
        });
}

void MainWindow::setLanguage(Language lang) {
    lang_ = lang;
    lesson_->setLanguage(lang);
    lesson_->setLessons(builtinLessons());
    fillLessonsMenu();
}

void MainWindow::fillLessonsMenu() {
    lessonsMenu_->clear();
    for (const Lesson& l : builtinLessons()) {
        const QString id = QString::fromStdString(l.id);
        lessonsMenu_->addAction(
            QStringLiteral("&%1. %2").arg(l.number).arg(QString::fromStdString(l.title.in(lang_))),
            this, [this, id] { openLesson(id); });
    }
}

void MainWindow::setLecturerMode(bool on) {
    lecturerAction_->setChecked(on);
}

void MainWindow::openCompare() {
    if (!session_.hasScene()) {
        statusBar()->showMessage(tr("No scene is open: nothing to compare."));
        return;
    }
    const AccelKind kind = session_.kind() == AccelKind::Bvh ? AccelKind::Bvh : AccelKind::KdTree;
    // 3D: the pixel being replayed (clicked, or a lesson's, in the lesson's image size), else
    // the image's centre.
    CompareWindow::Pixel pixel{kImageWidth / 2, kImageHeight / 2, kImageWidth, kImageHeight};
    for (const Event& e : session_.log().events())
        if (const auto* p = std::get_if<PixelResult>(&e)) {
            pixel = {static_cast<int>(p->x), static_cast<int>(p->y), kImageWidth, kImageHeight};
            const bool lessons =
                lesson_->hasLesson() && lesson_->lesson().trace.kind == LessonTrace::Kind::Pixel;
            if (lessons && lesson_->lesson().trace.x == pixel.x &&
                lesson_->lesson().trace.y == pixel.y) {
                pixel.width = lesson_->lesson().trace.width;
                pixel.height = lesson_->lesson().trace.height;
            }
        }
    // Three trees of a big mesh take seconds: built in the background, with Cancel.
    const std::uint64_t generation = generation_;
    runner_.start<CompareWindow::Prepared>(
        TaskKind::Compare, tr("Building the midpoint, median and SAH trees..."),
        [name = session_.name(), kind](const ProgressFn& progress) {
            return CompareWindow::prepare(name, kind, progress);
        },
        [this, generation, pixel](CompareWindow::Prepared&& prepared, const TaskOutcome& outcome) {
            if (outcome.superseded || generation != generation_) return;
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
            compare->resize(fitToScreen(QSize(1400, 800)));
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
    while (runner_.busy() && clock.elapsed() < timeoutMs)
        QApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents, 20);
    QApplication::processEvents();
    return !runner_.busy();
}

QString MainWindow::inspectorText() const {
    return inspector_->toPlainText();
}

void MainWindow::stepForward() {
    session_.setCursor(session_.cursor() + 1);
}
void MainWindow::stepBack() {
    if (session_.cursor() > 0) session_.setCursor(session_.cursor() - 1);
}
void MainWindow::jumpToNextOfKind() {
    const std::size_t kind = kJumpKinds[std::max(0, kindCombo_->currentIndex())].second;
    const std::size_t at = session_.replay().nextOfKind(session_.cursor(), kind);
    session_.setCursor(at < session_.size() ? at + 1 : session_.size());
}
void MainWindow::togglePlay() {
    if (timer_->isActive()) {
        timer_->stop();
        play_->setText(QStringLiteral(">"));
    } else {
        if (session_.cursor() >= session_.size()) session_.setCursor(0);
        timer_->start();
        play_->setText(QStringLiteral("||"));
    }
}

void MainWindow::updateTimeline() {
    const QSignalBlocker block(scrubber_);
    scrubber_->setRange(0, static_cast<int>(session_.size()));
    scrubber_->setValue(static_cast<int>(session_.cursor()));
    position_->setText(tr("%1 / %2").arg(session_.cursor()).arg(session_.size()));
    inspector_->setPlainText(describeState(session_));
    if (session_.cursor() > 0) {
        const QModelIndex i = eventFilter_->mapFromSource(
            eventModel_->index(static_cast<int>(session_.cursor()) - 1));
        if (i.isValid()) {
            events_->setCurrentIndex(i);
            events_->scrollTo(i);
        }
    }
}

void MainWindow::openFileDialog() {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open scene"), QString(), tr("Scenes (*.json)"));
    if (!path.isEmpty()) openScene(path, session_.kind());
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
    const QString path = QFileDialog::getSaveFileName(this, tr("Screenshot of the %1").arg(what),
                                                      QString(), tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    if (const QString problem = savePng(w->grab().toImage(), path); !problem.isEmpty())
        QMessageBox::warning(this, tr("Cannot save"), problem);
}

void MainWindow::exportTrace() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export trace"), QString(),
                                                      tr("Trace files (*.json)"));
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
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    // Stop and join every worker now, and start none after: the window is going away.
    runner_.shutdown();
    if (compare_) compare_->close();
    e->accept();
}

}  // namespace raystep::gui
