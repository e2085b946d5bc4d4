#pragma once
// The rendered image beside the replay: rendered off the GUI thread (progress and cancel in the
// window's status bar); clicking a pixel traces it with recording on and replays it; a heat map
// of primitive tests per pixel can be laid over it; the wheel zooms.
#include "session.h"

#include <QImage>
#include <QWidget>

#include <atomic>
#include <thread>

namespace raystep::gui {

class ImageView : public QWidget {
    Q_OBJECT
  public:
    explicit ImageView(Session& session, QWidget* parent = nullptr);
    ~ImageView() override;
    QSize sizeHint() const override { return {480, 360}; }

    /// Renders the session's 3D scene at width x height in the background.
    void startRender(int width, int height);
    void cancelRender() { cancel_ = true; }
    bool rendering() const { return worker_.joinable() && !done_; }
    void setHeatmap(bool on) {
        heatmap_ = on;
        update();
    }
    const QImage& image() const { return image_; }

  signals:
    void progress(int percent);
    void finished(bool cancelled, double ms);
    void pixelClicked(int x, int y);

  protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;

  private:
    QRectF imageRect() const;
    void join();

    Session& session_;
    QImage image_, heat_;
    bool heatmap_ = false;
    double zoom_ = 1.0;
    QPoint marked_{-1, -1};
    std::thread worker_;
    std::atomic<bool> cancel_{false}, done_{true};
};

}  // namespace raystep::gui
