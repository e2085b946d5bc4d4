#pragma once
// The rendered image beside the replay. The window renders it in the background (TaskRunner)
// and hands it over; meanwhile, and after a cancelled or failed render, the view keeps the
// image's frame so that a pixel can still be clicked (traced with recording on and replayed),
// says what happened and offers to render again. A heat map of primitive tests per pixel can be
// laid over it; the wheel zooms.
#include "session.h"

#include <QImage>
#include <QWidget>

#include <cstdint>
#include <optional>

class QAction;
class QPushButton;
class QToolButton;

namespace raystep::gui {

/// One picture of a progressive render: its passes' blocks and samples so far, and the heat
/// map's scale (primitive tests per pixel; the colours run from 0 to maxTests).
struct RenderFrame {
    QImage image, heat;
    std::uint64_t minTests = 0, maxTests = 0;
    int block = 1;    // side of the blocks that share a ray (1: every pixel its own)
    int samples = 1;  // samples per pixel so far
    int spp = 1;      // samples per pixel when done
};

class ImageView : public QWidget {
    Q_OBJECT
  public:
    enum class State { NoScene, Rendering, Done, Cancelled, Failed };

    explicit ImageView(Session& session, QWidget* parent = nullptr);
    QSize sizeHint() const override { return {480, 360}; }

    /// A render of a width x height image has started (the frame a click maps pixels in).
    void renderStarted(int width, int height, bool keepPicture = false);
    void renderProgress(int percent);
    void renderFinished(const QImage& image, const QImage& heat, double ms);
    /// A picture of the render under way (a progressive pass): shown while it goes on.
    void showFrame(const RenderFrame& frame);
    /// The render finished with `frame` as its last picture.
    void finishFrame(const RenderFrame& frame, double ms);
    /// Whether the image is of the 3D view's camera (ray trace this view) or the scene's: says
    /// so, and hides the lesson's pixel (a pixel of the scene's camera) meanwhile.
    void setOfView(bool ofView);
    bool ofView() const { return ofView_; }
    /// The size to render for this view: its own (capped) for the 3D view's camera; else the
    /// lesson's image size (its pixel is a pixel of it), or the scene's (both capped).
    QSize renderSize(bool ofView) const;
    /// The scene's own image size (its render settings), used when no lesson names one.
    void setSceneFrame(QSize size);
    /// The checkable "Ray trace this view" action, as a button on the view.
    void setRayTraceAction(QAction* action);
    /// The image's size in pixels (the frame clicks map into).
    QSize imageSize() const { return size_; }
    const RenderFrame& frame() const { return frame_; }
    /// Where the heat map's colour bar is drawn (empty when not shown); tests look there.
    QRectF colourBarRect() const;
    void renderCancelled();
    void renderFailed(const QString& why);
    /// No 3D scene to show (`why` says what happened, e.g. a scene that could not be opened).
    void clear(const QString& why = {});

    State state() const { return state_; }
    /// What the view says over its frame (tests read it).
    QString message() const;
    void setHeatmap(bool on) {
        heatmap_ = on;
        update();
    }
    const QImage& image() const { return image_; }
    /// The pixel a lesson traces, marked on the image: (x, y) of a width x height image (the
    /// lesson's size, which may differ from the rendered one); nullopt removes the mark.
    void setLessonPixel(std::optional<QRect> pixel);
    /// Where the lesson's pixel is marked in the widget (tests look there); null if not shown.
    QPointF lessonMarkCentre() const;
    QPushButton* renderButton() const { return renderButton_; }

  signals:
    void pixelClicked(int x, int y);
    /// The user asked for the image again (after a cancel or a failure).
    void renderRequested();
    /// What renderSize() gives may have changed (the view's size, the lesson's frame).
    void renderSizeChanged();

  protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;
    void resizeEvent(QResizeEvent*) override;
    void changeEvent(QEvent*) override;

  private:
    QRectF imageRect() const;
    void placeButton();
    void drawColourBar(QPainter& g);

    Session& session_;
    State state_ = State::NoScene;
    QString why_;
    int percent_ = 0;
    QSize size_;  // the image's size in pixels, known from the render's start
    QImage image_, heat_;
    bool heatmap_ = false;
    double zoom_ = 1.0;
    QPoint marked_{-1, -1};
    std::optional<QRect> lessonPixel_;  // x, y in a width x height image
    QPushButton* renderButton_ = nullptr;
    QToolButton* rayTraceButton_ = nullptr;
    RenderFrame frame_;
    bool ofView_ = false;
    QSize sceneFrame_{320, 240};
};

}  // namespace raystep::gui
