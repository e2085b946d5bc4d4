#pragma once
// The rendered image beside the replay. The window renders it in the background (TaskRunner)
// and hands it over; meanwhile, and after a cancelled or failed render, the view keeps the
// image's frame so that a pixel can still be clicked (traced with recording on and replayed),
// says what happened and offers to render again. A heat map of primitive tests per pixel can be
// laid over it; the wheel zooms.
#include "session.h"

#include <QImage>
#include <QWidget>

#include <optional>

class QPushButton;

namespace raystep::gui {

class ImageView : public QWidget {
    Q_OBJECT
  public:
    enum class State { NoScene, Rendering, Done, Cancelled, Failed };

    explicit ImageView(Session& session, QWidget* parent = nullptr);
    QSize sizeHint() const override { return {480, 360}; }

    /// A render of a width x height image has started (the frame a click maps pixels in).
    void renderStarted(int width, int height);
    void renderProgress(int percent);
    void renderFinished(const QImage& image, const QImage& heat, double ms);
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

  protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;
    void resizeEvent(QResizeEvent*) override;

  private:
    QRectF imageRect() const;
    void placeButton();

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
};

}  // namespace raystep::gui
