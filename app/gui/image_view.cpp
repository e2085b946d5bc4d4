#include "image_view.h"

#include "presentation.h"

#include "raystep/render/image.h"

#include <QAction>
#include <QLinearGradient>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QTimer>
#include <QToolButton>
#include <QWheelEvent>

namespace raystep::gui {

ImageView::ImageView(Session& session, QWidget* parent) : QWidget(parent), session_(session) {
    // A click takes the keyboard from the answer box, so B, R and N reach the window.
    setFocusPolicy(Qt::ClickFocus);
    setMinimumSize(240, 180);
    renderButton_ = new QPushButton(tr("Render the image again"), this);
    renderButton_->setObjectName("renderAgain");
    renderButton_->hide();
    connect(renderButton_, &QPushButton::clicked, this, &ImageView::renderRequested);
    connect(&session_, &Session::sceneChanged, this, [this] {
        marked_ = {-1, -1};
        if (!session_.scene3D()) clear();
    });
    // A clicked pixel stays marked while its ray tree is replayed (not after going back).
    connect(&session_, &Session::logChanged, this, [this] {
        if (session_.logKind() != LogKind::Pixel && marked_.x() >= 0) {
            marked_ = {-1, -1};
            update();
        }
    });
}

void ImageView::renderStarted(int width, int height, bool keepPicture) {
    state_ = State::Rendering;
    size_ = {width, height};
    percent_ = 0;
    // A new view of the same scene keeps the old picture until the first pass replaces it.
    if (!keepPicture) image_ = heat_ = QImage();
    frame_ = RenderFrame{};
    why_.clear();
    renderButton_->hide();
    update();
}

void ImageView::renderProgress(int percent) {
    if (state_ != State::Rendering || percent == percent_) return;
    percent_ = percent;
    update();
}

void ImageView::renderFinished(const QImage& image, const QImage& heat, double) {
    state_ = State::Done;
    image_ = image;
    heat_ = heat;
    size_ = image.size();
    renderButton_->hide();
    update();
}

void ImageView::showFrame(const RenderFrame& frame) {
    if (state_ != State::Rendering) return;
    frame_ = frame;
    image_ = frame.image;
    heat_ = frame.heat;
    size_ = frame.image.size();
    update();
}

void ImageView::finishFrame(const RenderFrame& frame, double ms) {
    frame_ = frame;
    renderFinished(frame.image, frame.heat, ms);
}

void ImageView::setOfView(bool ofView) {
    ofView_ = ofView;
    update();
}

QSize ImageView::renderSize(bool ofView) const {
    // Enough for a projector at full screen, and the first pass stays quick (about 1 Mpixel).
    constexpr int kMaxSide = 1280;
    const QSize room = (QSizeF(size()) * devicePixelRatioF()).toSize().expandedTo(QSize(64, 48));
    if (ofView)
        return room.width() > kMaxSide || room.height() > kMaxSide
                   ? room.scaled(kMaxSide, kMaxSide, Qt::KeepAspectRatio)
                   : room;
    // The scene's camera: the lesson's own frame, so that its pixel is a pixel of the image.
    const QSize frame = lessonPixel_ && lessonPixel_->width() > 0 && lessonPixel_->height() > 0
                            ? lessonPixel_->size()
                            : sceneFrame_;
    // Its own size whatever the view's (the view scales it): a resize does not render again.
    if (frame.width() <= kMaxSide && frame.height() <= kMaxSide) return frame;
    return frame.scaled(kMaxSide, kMaxSide, Qt::KeepAspectRatio).expandedTo(QSize(1, 1));
}

void ImageView::setSceneFrame(QSize size) {
    if (size.isEmpty() || size == sceneFrame_) return;
    sceneFrame_ = size;
    emit renderSizeChanged();
}

void ImageView::setRayTraceAction(QAction* action) {
    if (!rayTraceButton_) {
        rayTraceButton_ = new QToolButton(this);
        rayTraceButton_->setObjectName("rayTraceViewButton");
        rayTraceButton_->setToolButtonStyle(Qt::ToolButtonTextOnly);
    }
    rayTraceButton_->setDefaultAction(action);
    placeButton();
}

void ImageView::renderCancelled() {
    state_ = State::Cancelled;
    renderButton_->show();
    placeButton();
    update();
}

void ImageView::renderFailed(const QString& why) {
    state_ = State::Failed;
    why_ = why;
    renderButton_->show();
    placeButton();
    update();
}

void ImageView::clear(const QString& why) {
    state_ = State::NoScene;
    why_ = why;
    image_ = heat_ = QImage();
    size_ = {};
    marked_ = {-1, -1};
    renderButton_->hide();
    update();
}

QString ImageView::message() const {
    switch (state_) {
        case State::NoScene:
            return why_.isEmpty() ? tr("The image view shows 3D scenes.") : why_;
        case State::Rendering:
            if (!image_.isNull() && frame_.block > 1)
                return tr("Rendering: one ray per %1x%1 block of pixels... %2%")
                    .arg(frame_.block)
                    .arg(percent_);
            if (!image_.isNull() && frame_.samples < frame_.spp)
                return tr("Refining: %1 of %2 samples per pixel... %3%")
                    .arg(frame_.samples)
                    .arg(frame_.spp)
                    .arg(percent_);
            return tr("Rendering... %1%\nClick a pixel to trace it meanwhile.").arg(percent_);
        case State::Done:
            if (heatmap_) return tr("Primitive tests per pixel (dark: few, bright: many)");
            return ofView_ ? tr("Ray tracing this view (the 3D view's camera): click a pixel to "
                                "trace it")
                           : tr("Ray tracing (raystep): click a pixel to trace it");
        case State::Cancelled:
            return tr("Render cancelled. Pixels can still be clicked and traced.");
        case State::Failed:
            return tr("The render failed: %1").arg(why_);
    }
    return {};
}

QRectF ImageView::imageRect() const {
    if (size_.isEmpty()) return {};
    const double s =
        zoom_ * std::min(double(width()) / size_.width(), double(height()) / size_.height());
    const QSizeF size(size_.width() * s, size_.height() * s);
    return {QPointF((width() - size.width()) / 2, (height() - size.height()) / 2), size};
}

void ImageView::placeButton() {
    const QSize hint = renderButton_->sizeHint();
    renderButton_->setGeometry((width() - hint.width()) / 2, height() / 2 + 30, hint.width(),
                               hint.height());
    if (rayTraceButton_) {
        const QSize h = rayTraceButton_->sizeHint();
        rayTraceButton_->setGeometry(width() - h.width() - 6, 4, h.width(), h.height());
    }
}

void ImageView::changeEvent(QEvent* e) {
    QWidget::changeEvent(e);
    // The zoom: the buttons' sizes follow their new font, which reaches them after this one.
    if (e->type() == QEvent::FontChange) QTimer::singleShot(0, this, [this] { placeButton(); });
}

void ImageView::resizeEvent(QResizeEvent*) {
    placeButton();
    emit renderSizeChanged();
}

QRectF ImageView::colourBarRect() const {
    const QRectF r = imageRect();
    if (!heatmap_ || heat_.isNull() || r.isEmpty()) return {};
    const double w = std::min(260.0, width() - 24.0);
    // Under the image when there is room, else over its bottom edge.
    const double y = std::min(r.bottom() + 22.0, height() - 22.0);
    return {(width() - w) / 2, y, w, 12};
}

void ImageView::drawColourBar(QPainter& g) {
    const QRectF bar = colourBarRect();
    if (bar.isEmpty()) return;
    // The heat map's own scale (image.h's heatmapColor), 0 at the left, the maximum at the right.
    QLinearGradient grad(bar.topLeft(), bar.topRight());
    for (int i = 0; i <= 16; ++i) {
        const auto c = heatmapColor(i / 16.0);
        grad.setColorAt(i / 16.0, QColor(c[0], c[1], c[2]));
    }
    g.save();
    g.setPen(Qt::NoPen);
    g.setBrush(QColor(0, 0, 0, 170));
    g.drawRoundedRect(bar.adjusted(-8, -g.fontMetrics().height() - 3, 8, 4), 4, 4);
    g.fillRect(bar, grad);
    g.setPen(QColor(235, 235, 235));
    const double line = g.fontMetrics().height();
    const QRectF labels(bar.left(), bar.top() - line - 2, bar.width(), line);
    g.drawText(labels, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("0"));
    g.drawText(labels, Qt::AlignRight | Qt::AlignVCenter, QString::number(frame_.maxTests));
    g.drawText(labels, Qt::AlignHCenter | Qt::AlignVCenter,
               tr("tests per pixel (min %1, max %2)").arg(frame_.minTests).arg(frame_.maxTests));
    g.restore();
}

void ImageView::paintEvent(QPaintEvent*) {
    QPainter g(this);
    g.fillRect(rect(), QColor(40, 40, 44));
    const QRectF r = imageRect();
    const bool picture = !image_.isNull() && (state_ == State::Done || state_ == State::Rendering);
    if (picture) {
        // A progressive render shows each pass's complete picture while it refines.
        g.drawImage(r, heatmap_ && !heat_.isNull() ? heat_ : image_);
        if (heatmap_) drawColourBar(g);
        // The caption on a dark box: readable over a bright sky as over a dark floor. In the
        // views' caption font (the chrome's zoom), as high as it, left of the view's button.
        g.save();
        g.setFont(presentation().captionFont());
        const QFontMetricsF fm(g.font());
        const double right = rayTraceButton_ && rayTraceButton_->isVisible()
                                 ? rayTraceButton_->x() - 8
                                 : width() - 8;
        const QString caption =
            fm.elidedText(message(), Qt::ElideRight, std::max(0.0, right - 8 - 8));
        const QRectF at(8, 6, fm.horizontalAdvance(caption), fm.height());
        g.setPen(Qt::NoPen);
        g.setBrush(QColor(0, 0, 0, 150));
        g.drawRoundedRect(at.adjusted(-4, -1, 4, 1), 3, 3);
        g.setPen(QColor(235, 235, 235));
        g.drawText(at, Qt::AlignLeft | Qt::AlignVCenter, caption);
        g.restore();
        if (state_ == State::Rendering) {
            g.fillRect(QRectF(r.x(), r.y(), r.width() * percent_ / 100.0, 3), QColor(90, 160, 230));
        }
    } else {
        // The image's frame, where a click still picks a pixel, and what is happening.
        if (!r.isEmpty()) {
            g.setPen(QPen(QColor(110, 110, 118), 1, Qt::DashLine));
            g.drawRect(r);
        }
        g.setPen(state_ == State::Failed ? QColor(255, 150, 130) : QColor(235, 235, 235));
        g.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap,
                   message());
        if (state_ == State::Rendering && !r.isEmpty()) {
            const QRectF bar(r.x() + r.width() * 0.2, r.center().y() + 34, r.width() * 0.6, 6);
            g.fillRect(bar, QColor(70, 70, 78));
            g.fillRect(QRectF(bar.topLeft(), QSizeF(bar.width() * percent_ / 100.0, bar.height())),
                       QColor(90, 160, 230));
        }
    }
    if (marked_.x() >= 0 && !r.isEmpty()) {
        // The pixel being explored: its square and a ring around it, in red over dark.
        const double s = r.width() / size_.width();
        const QPointF c(r.x() + (marked_.x() + 0.5) * s, r.y() + (marked_.y() + 0.5) * s);
        g.setRenderHint(QPainter::Antialiasing);
        g.setBrush(Qt::NoBrush);
        for (const QPen& pen : {QPen(QColor(0, 0, 0, 200), 4.5), QPen(QColor(255, 80, 60), 2)}) {
            g.setPen(pen);
            g.drawRect(QRectF(c.x() - s / 2 - 3, c.y() - s / 2 - 3, s + 6, s + 6));
            g.drawEllipse(c, s / 2 + 10, s / 2 + 10);
        }
    }
    if (const QPointF c = lessonMarkCentre(); !c.isNull()) {
        // The lesson's pixel: a ring and a cross-hair with a gap, dark under light, so it reads
        // on any picture; and its name.
        g.setRenderHint(QPainter::Antialiasing);
        const double ring = 11, inner = 5, outer = 22;
        const auto mark = [&](const QPen& pen) {
            g.setPen(pen);
            g.setBrush(Qt::NoBrush);
            g.drawEllipse(c, ring, ring);
            for (const QPointF d : {QPointF(1, 0), QPointF(-1, 0), QPointF(0, 1), QPointF(0, -1)})
                g.drawLine(c + inner * d, c + outer * d);
        };
        mark(QPen(QColor(0, 0, 0, 200), 4.5));
        mark(QPen(QColor(255, 235, 60), 2));
        const QString label =
            tr("lesson's pixel (%1, %2)").arg(lessonPixel_->x()).arg(lessonPixel_->y());
        const QRectF text = g.fontMetrics().boundingRect(label).adjusted(-4, -2, 4, 2);
        QPointF at = c + QPointF(outer + 4, -outer - 2);
        if (at.x() + text.width() > width()) at.setX(c.x() - outer - 4 - text.width());
        if (at.y() - text.height() < 0) at.setY(c.y() + outer + text.height());
        const QRectF box(at.x(), at.y() - text.height(), text.width(), text.height());
        g.setPen(Qt::NoPen);
        g.setBrush(QColor(0, 0, 0, 170));
        g.drawRoundedRect(box, 3, 3);
        g.setPen(QColor(255, 235, 60));
        g.drawText(box, Qt::AlignCenter, label);
    }
}

void ImageView::setLessonPixel(std::optional<QRect> pixel) {
    const QSize before = renderSize(false);
    lessonPixel_ = pixel;
    update();
    if (renderSize(false) != before) emit renderSizeChanged();
}

QPointF ImageView::lessonMarkCentre() const {
    const QRectF r = imageRect();
    // The lesson's pixel is one of the scene's camera: nowhere in another camera's image.
    if (ofView_ || !lessonPixel_ || r.isEmpty() || lessonPixel_->width() <= 0 ||
        lessonPixel_->height() <= 0)
        return {};
    return {r.x() + (lessonPixel_->x() + 0.5) / lessonPixel_->width() * r.width(),
            r.y() + (lessonPixel_->y() + 0.5) / lessonPixel_->height() * r.height()};
}

void ImageView::mousePressEvent(QMouseEvent* e) {
    const QRectF r = imageRect();
    if (!session_.scene3D() || r.isEmpty() || !r.contains(e->position())) return;
    const int x =
        std::clamp(static_cast<int>((e->position().x() - r.x()) / r.width() * size_.width()), 0,
                   size_.width() - 1);
    const int y =
        std::clamp(static_cast<int>((e->position().y() - r.y()) / r.height() * size_.height()), 0,
                   size_.height() - 1);
    marked_ = {x, y};
    update();
    emit pixelClicked(x, y);
}

void ImageView::wheelEvent(QWheelEvent* e) {
    zoom_ = std::clamp(zoom_ * (e->angleDelta().y() > 0 ? 1.25 : 0.8), 0.25, 16.0);
    update();
}

}  // namespace raystep::gui
