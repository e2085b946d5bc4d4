#include "image_view.h"

#include "raystep/image.h"
#include "raystep/tracer.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

namespace raystep::gui {

ImageView::ImageView(Session& session, QWidget* parent) : QWidget(parent), session_(session) {
    setMinimumSize(240, 180);
    connect(&session_, &Session::aboutToChangeScene, this, [this] { join(); });
    connect(&session_, &Session::sceneChanged, this, [this] {
        image_ = heat_ = QImage();
        marked_ = {-1, -1};
        update();
    });
}

ImageView::~ImageView() {
    cancel_ = true;
    join();
}

void ImageView::join() {
    cancel_ = true;
    if (worker_.joinable()) worker_.join();
    cancel_ = false;
}

void ImageView::startRender(int width, int height) {
    join();
    const Scene* scene = session_.scene3D();
    const Accelerator* accel = session_.accel3D();
    if (!scene || !accel) return;
    done_ = false;
    worker_ = std::thread([this, scene, accel, width, height] {
        RenderOptions opt;
        opt.width = width;
        opt.height = height;
        opt.trace.bounces = scene->settings.bounces;
        const RenderResult r = raystep::render(*scene, *accel, opt, [this](double f) {
            emit progress(static_cast<int>(f * 100));
            return !cancel_.load();
        });
        QImage img(width, height, QImage::Format_RGB888);
        const auto rgb = toSrgb8(r.image);
        for (int y = 0; y < height; ++y)
            std::memcpy(img.scanLine(y), rgb.data() + std::size_t(y) * width * 3, width * 3);
        QImage heat(width, height, QImage::Format_RGB888);
        const auto h = heatmapRgb8(r.costPerPixel, width, height);
        for (int y = 0; y < height; ++y)
            std::memcpy(heat.scanLine(y), h.data() + std::size_t(y) * width * 3, width * 3);
        const bool cancelled = r.cancelled;
        const double ms = r.renderMs;
        // Hand the images to the GUI thread.
        QMetaObject::invokeMethod(this, [this, img, heat, cancelled, ms] {
            if (!cancelled) {
                image_ = img;
                heat_ = heat;
            }
            done_ = true;
            update();
            emit finished(cancelled, ms);
        });
    });
}

QRectF ImageView::imageRect() const {
    if (image_.isNull()) return {};
    const double s =
        zoom_ * std::min(double(width()) / image_.width(), double(height()) / image_.height());
    const QSizeF size(image_.width() * s, image_.height() * s);
    return {QPointF((width() - size.width()) / 2, (height() - size.height()) / 2), size};
}

void ImageView::paintEvent(QPaintEvent*) {
    QPainter g(this);
    g.fillRect(rect(), QColor(40, 40, 44));
    if (image_.isNull()) {
        g.setPen(Qt::white);
        g.drawText(rect(), Qt::AlignCenter,
                   session_.scene3D() ? tr("Rendering...") : tr("The image view shows 3D scenes."));
        return;
    }
    const QRectF r = imageRect();
    g.drawImage(r, heatmap_ ? heat_ : image_);
    g.setPen(QColor(230, 230, 230));
    g.drawText(QRectF(8, 6, width() - 16, 20), Qt::AlignLeft,
               heatmap_ ? tr("Primitive tests per pixel (dark: few, bright: many)")
                        : tr("Ray tracing (raystep): click a pixel to trace it"));
    if (marked_.x() >= 0) {
        const double s = r.width() / image_.width();
        g.setPen(QPen(QColor(255, 80, 60), 2));
        g.drawRect(QRectF(r.x() + marked_.x() * s - 3, r.y() + marked_.y() * s - 3, s + 6, s + 6));
    }
}

void ImageView::mousePressEvent(QMouseEvent* e) {
    const QRectF r = imageRect();
    if (image_.isNull() || !r.contains(e->position())) return;
    const int x = static_cast<int>((e->position().x() - r.x()) / r.width() * image_.width());
    const int y = static_cast<int>((e->position().y() - r.y()) / r.height() * image_.height());
    marked_ = {x, y};
    update();
    emit pixelClicked(x, y);
}

void ImageView::wheelEvent(QWheelEvent* e) {
    zoom_ = std::clamp(zoom_ * (e->angleDelta().y() > 0 ? 1.25 : 0.8), 0.25, 16.0);
    update();
}

}  // namespace raystep::gui
