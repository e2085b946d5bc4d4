#pragma once
// The window's rendered image: the render settings tool bar and View's image items, the
// progressive render in the background (coarse first, finer while nothing moves), and the ray of
// a clicked pixel or 3D view point recorded for the replay.
#include "session.h"
#include "task_runner.h"

#include "raystep/render/tracer.h"
#include "raystep/scene/camera.h"

#include <QObject>

#include <functional>
#include <memory>
#include <optional>

class QAction;
class QMainWindow;
class QMenu;
class QPointF;
class QSpinBox;
class QToolBar;

namespace raystep::gui {

class ImageView;
class VtkView;
struct FrameBox;

/// Past this many primitives brute force is asked about first and its pixel traces run in the
/// background: a pixel's three rays then test 600,000 primitives or more (most of a second on
/// a student's laptop), and its image takes minutes to hours.
inline constexpr std::size_t kBruteForceAsk = 200'000;

class ImageRender : public QObject {
    Q_OBJECT
  public:
    /// The image's size where nothing says another: a scene's first pixel, compare mode's.
    static constexpr int kWidth = 320, kHeight = 240;
    /// What the image is (being) made with: the camera, size and settings its pixels are traced
    /// with when clicked.
    struct Frame {
        Camera camera;
        int width = 0, height = 0;
        TraceSettings trace;
        int spp = 1;
        bool ofView = false;  // the 3D view's camera (ray trace this view), else the scene's
        /// The render's options: the app's passes (a coarse picture at once, then the samples
        /// doubling) of this camera, size and settings.
        RenderOptions options() const;
    };
    /// What the image asks of the rest of the window.
    struct Hooks {
        /// Quiz mode: true, the user told why, when an exercise holds the replay.
        std::function<bool(const QString& toWhat)> refusedWhileHeld;
        /// The open lesson's trace, or null: a pixel traced in the background does not replace it.
        std::function<LogRef()> lessonLog;
    };
    /// `generation` counts the scenes the window has shown: a result for an older one is dropped.
    ImageRender(QMainWindow& window, Session& session, TaskRunner& runner,
                const std::uint64_t& generation, ImageView* image, VtkView* view3D, Hooks hooks);
    ~ImageRender() override;

    /// View > Render the image again, Heat map, Reset 3D camera, Ray trace this view.
    void addViewItems(QMenu* view);
    QAction* rayTraceViewAction() const { return rayTraceView_; }
    const std::optional<Frame>& frame() const { return frame_; }

    /// A scene was shown: a 3D one gets its settings, its image (or none) and a first pixel.
    void sceneShown(bool renderImage);
    /// Renders the image of the 3D scene in the background (what the image view shows).
    void renderImage();
    /// A render scheduled (a move, a resize) that has not started yet: work still to come.
    bool pending() const { return pending_; }
    /// Cancel: a render about to start is cancelled too.
    void cancelPending() { pending_ = false; }

    /// Brute force on a scene so big that a pixel's trace takes more than a moment (every ray
    /// tests every primitive): the pixel is traced in the background, its log capped.
    bool slowPixelTraces() const;
    /// Records pixel (x, y) of a w x h image (the scene's camera and settings unless given: a
    /// click, replayed to its end) and replays it: here and now, or in the background when
    /// slowPixelTraces().
    void tracePixelHereOrInBackground(int x, int y, int w, int h,
                                      const std::optional<Camera>& camera = std::nullopt,
                                      const TraceSettings& settings = {});

  private:
    void createSettingsBar();
    /// The items of 3D scenes enabled with a 3D scene only.
    void syncActions();
    /// The control shows the scene's own render settings.
    void syncSettings(const Scene& scene);
    /// Renders the image again once events settle (a camera drag moves it many times).
    void scheduleRender();
    /// Renders again if the image's wanted size changed (the view's own size when it is of the
    /// 3D view's camera; the lesson's frame), unless it was cancelled or failed.
    void followImageSize();
    /// Shows the running render's newest pass, if one came.
    void takeFrame();
    /// A click on the image: the ray of its pixel, with the camera and settings it was made with.
    void tracePixelClicked(int x, int y);
    /// A click in the 3D view: records the ray under it, seen by the 3D view's camera.
    void traceViewPoint(QPointF widgetPos);

    QMainWindow& window_;
    Session& session_;
    TaskRunner& runner_;
    const std::uint64_t& generation_;
    ImageView* image_;
    VtkView* view3D_;
    Hooks hooks_;
    QAction *renderAgain_ = nullptr, *heatmap_ = nullptr, *resetCamera_ = nullptr,
            *rayTraceView_ = nullptr;
    QToolBar* bar_ = nullptr;
    QSpinBox *bouncesBox_ = nullptr, *diffuseBox_ = nullptr, *sppBox_ = nullptr;
    std::optional<Frame> frame_;
    std::uint64_t imageGeneration_ = ~std::uint64_t(0);  // the scene the image was made for
    bool pending_ = false;
    std::shared_ptr<FrameBox> frames_;  // the running render's newest pass
};

}  // namespace raystep::gui
