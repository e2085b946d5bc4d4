// The rendered image and its pixels: the settings bar, the render in the background, the rays of
// clicked pixels and 3D view points (image_render.h).
#include "image_render.h"

#include "image_view.h"
#include "vtk_view.h"

#include "raystep/render/image.h"
#include "raystep/render/render.h"

#include <QAction>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

#include <algorithm>
#include <cstring>
#include <mutex>

namespace raystep::gui {

namespace {
/// The events a pixel's trace keeps there: a million triangles by brute force recorded 3 million
/// tests, whose replay and views took 10 GB and froze the window for 40 s.
constexpr std::size_t kSlowPixelEventCap = 50'000;

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

RenderOptions ImageRender::Frame::options() const {
    RenderOptions o;
    o.firstBlock = 8;
    o.refine = true;
    o.camera = camera;
    o.width = width;
    o.height = height;
    o.spp = spp;
    o.trace = trace;
    return o;
}

ImageRender::ImageRender(QMainWindow& window, Session& session, TaskRunner& runner,
                         const std::uint64_t& generation, ImageView* image, VtkView* view3D,
                         Hooks hooks)
    : QObject(&window),
      window_(window),
      session_(session),
      runner_(runner),
      generation_(generation),
      image_(image),
      view3D_(view3D),
      hooks_(std::move(hooks)) {
    // The window's own children, as they were before the image had a class of its own (the
    // shortcuts list and the tests find them there).
    renderAgain_ = new QAction(tr("Render the &image again"), &window_);
    connect(renderAgain_, &QAction::triggered, this, [this] { renderImage(); });
    heatmap_ = new QAction(tr("&Heat map of primitive tests"), &window_);
    heatmap_->setCheckable(true);
    connect(heatmap_, &QAction::toggled, image_, &ImageView::setHeatmap);
    resetCamera_ = new QAction(tr("&Reset 3D camera"), &window_);
    connect(resetCamera_, &QAction::triggered, this, [this] { view3D_->resetCamera(); });
    renderAgain_->setObjectName("renderAgain");
    heatmap_->setObjectName("heatmap");
    resetCamera_->setObjectName("resetCamera");
    createSettingsBar();
    connect(image_, &ImageView::renderRequested, this, [this] { renderImage(); });
    connect(image_, &ImageView::pixelClicked, this, &ImageRender::tracePixelClicked);
    // The items of one kind of scene are off with the other: a 2D lesson's heat map or "render
    // again" did nothing.
    connect(&session_, &Session::sceneChanged, this, [this] { syncActions(); });
    syncActions();
    connect(&runner_, &TaskRunner::progressChanged, this, [this] {
        if (!runner_.busy(TaskKind::Render)) return;
        takeFrame();
        image_->renderProgress(runner_.percent(TaskKind::Render));
    });
}

ImageRender::~ImageRender() = default;

void ImageRender::addViewItems(QMenu* view) {
    view->addActions({renderAgain_, heatmap_, resetCamera_, rayTraceView_});
}

void ImageRender::syncActions() {
    const bool in3D = session_.hasScene() && !session_.is2D();
    for (QAction* act : {heatmap_, renderAgain_, resetCamera_, rayTraceView_})
        act->setEnabled(in3D);
    bar_->setEnabled(in3D);
}

void ImageRender::tracePixelClicked(int x, int y) {
    // A pixel beside the lesson's holds the same answers as the lesson's own.
    if (hooks_.refusedWhileHeld(tr("trace a pixel's ray tree"))) return;
    // The camera, size and settings the image was made with: the pixel's ray is the one drawn
    // there.
    if (const auto& f = frame_; f && slowPixelTraces()) {
        tracePixelHereOrInBackground(x, y, f->width, f->height, f->camera, f->trace);
        return;
    }
    if (const auto& f = frame_)
        session_.tracePixel(x, y, f->width, f->height, f->camera, f->trace);
    else
        session_.tracePixel(x, y, kWidth, kHeight);
    session_.setCursor(session_.size());
    window_.statusBar()->showMessage(
        tr("Pixel (%1, %2): %3 events recorded").arg(x).arg(y).arg(session_.size()));
}

void ImageRender::sceneShown(bool renderImage) {
    if (session_.is2D()) {
        image_->clear();
        return;
    }
    syncSettings(*session_.scene3D());
    if (renderImage)
        this->renderImage();
    else
        image_->clear(tr("This view shows no rendered image."));
    // A first ray to replay before any click: the image's centre.
    tracePixelHereOrInBackground(kWidth / 2, kHeight / 2, kWidth, kHeight);
}

void ImageRender::createSettingsBar() {
    // Off at start: a lesson's text, its pixel and its exercises are in the scene's camera.
    rayTraceView_ = new QAction(tr("Ray trace this &view"), &window_);
    rayTraceView_->setObjectName("rayTraceView");
    rayTraceView_->setCheckable(true);
    rayTraceView_->setToolTip(
        tr("Render the image from the 3D view's camera, again at every "
           "move, coarse first and finer while nothing moves"));
    connect(rayTraceView_, &QAction::toggled, this, [this] { scheduleRender(); });
    image_->setRayTraceAction(rayTraceView_);
    connect(view3D_, &VtkView::cameraMoved, this, [this] {
        if (rayTraceView_->isChecked()) scheduleRender();
    });
    connect(view3D_, &VtkView::pointPicked, this, [this](QPointF p) { traceViewPoint(p); });
    // An image of the view's own size follows it (not after a cancel or a failure: the user
    // asks for that one again).
    connect(image_, &ImageView::renderSizeChanged, this, [this] { followImageSize(); });

    bar_ = new QToolBar(tr("Render settings"), &window_);
    bar_->setObjectName("renderSettingsBar");
    bar_->addAction(rayTraceView_);
    bar_->addSeparator();
    const auto box = [this](const QString& label, const QString& name, int lo, int hi,
                            const QString& tip) {
        auto* text = new QLabel(label);
        text->setContentsMargins(6, 0, 2, 0);
        bar_->addWidget(text);
        auto* b = new QSpinBox;
        b->setObjectName(name);
        b->setRange(lo, hi);  // the scene format's limits (docs/scene-format.md)
        b->setToolTip(tip);
        text->setBuddy(b);
        bar_->addWidget(b);
        connect(b, &QSpinBox::valueChanged, this, [this] { scheduleRender(); });
        return b;
    };
    bouncesBox_ = box(tr("&Bounces"), "renderBounces", 0, kMaxBounces,
                      tr("Depth of secondary rays (reflection, refraction, diffuse)"));
    diffuseBox_ = box(tr("&Diffuse samples"), "renderDiffuseSamples", 0, kMaxDiffuseSamples,
                      tr("Diffuse bounce rays at the first diffuse hit: colour bleeding"));
    sppBox_ = box(tr("&Samples per pixel"), "renderSpp", 1, kMaxSpp,
                  tr("Jittered samples per pixel: the last pass of the progressive render"));
    window_.addToolBar(Qt::TopToolBarArea, bar_);
    // A 2D scene has no image to render: its settings would only take the lecturer's room.
    connect(&session_, &Session::sceneChanged, this,
            [this] { bar_->setVisible(!session_.is2D()); });
}

void ImageRender::syncSettings(const Scene& scene) {
    {
        const QSignalBlocker block(image_);  // the render that follows has the new size
        image_->setSceneFrame(QSize(scene.settings.width, scene.settings.height));
    }
    // The scene's own settings, as the command line renders it; not a change by the user.
    for (auto [b, v] : {std::pair{bouncesBox_, scene.settings.bounces},
                        std::pair{diffuseBox_, scene.settings.diffuseSamples},
                        std::pair{sppBox_, scene.settings.spp}}) {
        const QSignalBlocker block(b);
        b->setValue(v);
    }
}

void ImageRender::scheduleRender() {
    if (pending_ || !session_.scene3D()) return;
    pending_ = true;
    // Once the events queued now are handled: a drag's many moves make one render, and the
    // running one is superseded (cancelled) by it.
    QTimer::singleShot(0, this, [this] {
        if (pending_) renderImage();
    });
}

void ImageRender::followImageSize() {
    // A cancelled or failed image waits for the user's "render again", whatever the size.
    const auto state = image_->state();
    if (!frame_ || (state != ImageView::State::Done && state != ImageView::State::Rendering))
        return;
    if (image_->renderSize(frame_->ofView) != QSize(frame_->width, frame_->height))
        scheduleRender();
}

void ImageRender::takeFrame() {
    if (!frames_) return;
    if (std::optional<RenderFrame> f = frames_->take()) image_->showFrame(*f);
}

void ImageRender::traceViewPoint(QPointF widgetPos) {
    if (!session_.scene3D() || !view3D_->isVisible()) return;
    if (hooks_.refusedWhileHeld(tr("trace a ray of the 3D view"))) return;
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
    window_.statusBar()->showMessage(
        tr("3D view point (%1, %2): %3 events recorded").arg(x).arg(y).arg(session_.size()));
}

void ImageRender::renderImage() {
    pending_ = false;
    const Scene* scene = session_.scene3D();
    if (!scene) return;
    struct Rendered {
        RenderFrame frame;
        double ms = 0.0;
    };
    Frame f;
    f.ofView = rayTraceView_->isChecked();
    f.camera = f.ofView ? view3D_->currentCamera() : scene->camera;
    if (!cameraUsable(f.camera)) {
        f.ofView = false;
        f.camera = scene->camera;
    }
    const QSize size = image_->renderSize(f.ofView);
    f.width = size.width();
    f.height = size.height();
    // What the control says (the scene's settings until the user changes them).
    f.trace.bounces = bouncesBox_->value();
    f.trace.diffuseSamples = diffuseBox_->value();
    f.spp = sppBox_->value();
    // Another view of the same scene keeps its picture until the new one's first pass.
    const bool sameScene = imageGeneration_ == generation_;
    frame_ = f;
    imageGeneration_ = generation_;
    image_->setOfView(f.ofView);
    image_->renderStarted(f.width, f.height, sameScene);
    auto box = std::make_shared<FrameBox>();
    frames_ = box;
    const std::uint64_t generation = generation_;
    runner_.start<Rendered>(
        TaskKind::Render, tr("Rendering %1...").arg(QString::fromStdString(session_.name())),
        [ref = session_.sceneRef(), f, box](const ProgressFn& progress) {
            const Scene& s = std::get<Scene>(ref->scene);
            ProgressiveRender r(s, *ref->structure.in3D, f.options());
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
                pending_ = false;  // Cancel holds for a render scheduled meanwhile too
                image_->renderCancelled();
                window_.statusBar()->showMessage(tr("Render cancelled"));
            } else if (outcome.error) {
                const QString why = outcome.errorText();
                image_->renderFailed(why);
                window_.statusBar()->showMessage(tr("Render failed: %1").arg(why));
            } else {
                image_->finishFrame(r.frame, r.ms);
                window_.statusBar()->showMessage(
                    tr("Rendered in %1 ms; click a pixel to trace it").arg(r.ms, 0, 'f', 0));
            }
        });
}

bool ImageRender::slowPixelTraces() const {
    const Scene* scene = session_.scene3D();
    return scene && testsEveryPrimitive(session_.kind()) &&
           scene->primitiveCount() > kBruteForceAsk;
}

void ImageRender::tracePixelHereOrInBackground(int x, int y, int w, int h,
                                               const std::optional<Camera>& camera,
                                               const TraceSettings& settings) {
    if (!slowPixelTraces()) {
        if (camera)
            session_.tracePixel(x, y, w, h, *camera, settings);
        else
            session_.tracePixel(x, y, w, h);
        return;
    }
    const std::uint64_t generation = generation_;
    const std::size_t n = session_.scene3D()->primitiveCount();
    runner_.start<LogRef>(
        TaskKind::Pixel,
        tr("Tracing pixel (%1, %2) by brute force, %3 primitives...").arg(x).arg(y).arg(n),
        [ref = session_.sceneRef(), x, y, w, h, camera, settings](const ProgressFn&) {
            auto log = std::make_shared<EventLog>(kSlowPixelEventCap);
            const Scene& s = std::get<Scene>(ref->scene);
            if (camera)
                tracePixelEvents(s, *ref->structure.in3D, *camera, settings, x, y, w, h, *log);
            else
                tracePixelEvents(s, *ref->structure.in3D, x, y, w, h, *log);
            return LogRef(std::move(log));
        },
        [this, generation, x, y, clicked = camera.has_value()](LogRef&& log,
                                                               const TaskOutcome& outcome) {
            // A newer pixel, or another scene: this trace is of no use now.
            if (outcome.superseded || generation != generation_ || !outcome.ok() || !log) return;
            // Nor does it take the place of a lesson's trace: unasked (the scene's first pixel)
            // or while an exercise holds the replay.
            const bool lessonShown = hooks_.lessonLog() && session_.logRef() == hooks_.lessonLog();
            if (lessonShown && (!clicked || session_.held())) return;
            session_.showLog(log, LogKind::Pixel);
            // A click replays its pixel to the end, as a click does; the first pixel from 0.
            if (clicked) session_.setCursor(session_.size());
            window_.statusBar()->showMessage(
                log->truncated()
                    ? tr("Pixel (%1, %2): the first %3 events recorded, %4 more left out "
                         "(brute force tests every primitive)")
                          .arg(x)
                          .arg(y)
                          .arg(log->events().size())
                          .arg(log->dropped())
                    : tr("Pixel (%1, %2): %3 events recorded")
                          .arg(x)
                          .arg(y)
                          .arg(log->events().size()));
        });
}

}  // namespace raystep::gui
