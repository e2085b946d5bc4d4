// The 2D view's direct manipulation (issue 19): the kept view transform (zoom about the cursor,
// pan, fit), the ray's handles, and moving, resizing and selecting circles and segments. Each
// drag frame is a new scene shown live through the Live2D (live2d.h); a click without a drag
// stays a cell click for the lessons' exercises.
#include "view2d.h"

#include "live2d.h"
#include "presentation.h"

#include "course/palette.h"

#include <QApplication>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace raystep::gui {

namespace {
constexpr double kHandleRadius = 10.0;  // pixels: how near a press takes a handle
constexpr double kRimBand = 6.0;        // pixels either side of a circle's rim: resize
constexpr double kMinArrow = 40.0;      // pixels: the shortest direction arrow drawn
QColor paletteColour(const PaletteColour& c, int alpha = 255) {
    return QColor(c.r, c.g, c.b, alpha);
}
double distanceToSegment(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return QLineF(p, a + t * ab).length();
}
/// `v` turned to the nearest multiple of 15 degrees, its length kept; the axes and diagonals'
/// components exact where they can be (0 and +-length, not 6e-17).
Vec2 snapAngle15(Vec2 v) {
    const double len = glm::length(v);
    if (!(len > 0)) return v;
    const long k = std::lround(std::atan2(v.y, v.x) / (std::numbers::pi / 12));
    const long q = ((k % 24) + 24) % 24;
    if (q % 6 == 0) {
        static constexpr int kAxis[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        return len * Vec2(kAxis[q / 6][0], kAxis[q / 6][1]);
    }
    const double a = q * std::numbers::pi / 12;
    return len * Vec2(std::cos(a), std::sin(a));
}
}  // namespace

void View2D::setLive(Live2D* live) {
    live_ = live;
    // Hover feedback (the cursor says what a press would take) needs the moves without a button.
    setMouseTracking(live != nullptr);
    update();
}

void View2D::sceneShown() {
    const Scene2D* s = session_.scene2D();
    const std::optional<std::uint32_t> selectedBefore = selected_;
    if (!s) {
        shown_.reset();
        selected_.reset();
    } else {
        // A live edit, or the same shapes rebuilt (a live control): the view stays where it is.
        const bool same = (live_ && live_->changing()) || (shown_ && sameShapes(*shown_, *s));
        if (!same) {
            needFit_ = true;
            zoom_ = 1.0;
            pan_ = {};
            selected_.reset();
        }
        if (selected_ && *selected_ >= s->primitiveCount()) selected_.reset();
        shown_ = *s;
    }
    if (selected_ != selectedBefore) emit selectionChanged();
}

void View2D::fitView() {
    needFit_ = true;
    zoom_ = 1.0;
    pan_ = {};
    layerDirty_ = true;
    update();
}

void View2D::zoomAt(QPointF about, double factor) {
    if (!session_.scene2D() || !(factor > 0) || !std::isfinite(factor)) return;
    fit();
    const Vec2 w = toWorld(about);
    const double before = zoom_;
    zoom_ = std::clamp(zoom_ * factor, 0.05, 500.0);
    if (zoom_ == before) return;
    fit();
    // Pan so that the scene point under `about` is drawn there again (y grows upwards).
    const QPointF now = toScreen(w);
    pan_ += QPointF(about.x() - now.x(), now.y() - about.y());
    layerDirty_ = true;
    update();
}

void View2D::panBy(QPointF delta) {
    pan_ += QPointF(delta.x(), -delta.y());
    layerDirty_ = true;
    update();
}

void View2D::setSelected(std::optional<std::uint32_t> prim) {
    const Scene2D* s = session_.scene2D();
    if (prim && (!s || *prim >= s->primitiveCount())) prim.reset();
    if (prim == selected_) return;
    selected_ = prim;
    emit selectionChanged();
    update();
}

std::optional<Ray2> View2D::shownRay() const {
    const Scene2D* s = session_.scene2D();
    if (!s || session_.showingBuild()) return std::nullopt;
    // The ray the log replays (a lesson's own, or the example ray traced): the one drawn.
    if (!session_.log().rays().empty()) {
        const RayRecord& r = session_.log().rays().front();
        return Ray2{Vec2(r.origin.x, r.origin.y), Vec2(r.dir.x, r.dir.y)};
    }
    return s->exampleRay;
}

double View2D::tipScale() const {
    const auto ray = shownRay();
    if (!ray) return 1.0;
    const double len = glm::length(ray->dir) * scale_;
    return len >= kMinArrow || !(len > 0) ? 1.0 : kMinArrow / len;
}

std::optional<QPointF> View2D::tipHandle() const {
    const auto ray = shownRay();
    if (!ray) return std::nullopt;
    fit();
    return toScreen(ray->origin + tipScale() * ray->dir);
}

View2D::Target View2D::targetAt(QPointF p) const {
    const Scene2D* s = session_.scene2D();
    if (!s || !live_) return {};
    fit();
    // As far as the handles are drawn (presenter mode draws them larger).
    const double reach = kHandleRadius * presentation().handleScale();
    const auto near = [&](QPointF a, double r) { return QLineF(a, p).length() <= r; };
    // A build's replay draws no ray: only the primitives can be taken (lesson 11 edits them).
    if (const auto ray = shownRay()) {
        if (near(*tipHandle(), reach)) return {Grab::Tip, 0};
        if (near(toScreen(ray->origin), reach)) return {Grab::Origin, 0};
    }
    // The selected primitive first (its handles may lie over another), then the last drawn.
    std::vector<std::uint32_t> order;
    if (selected_ && *selected_ < s->primitiveCount()) order.push_back(*selected_);
    for (std::uint32_t q = s->primitiveCount(); q-- > 0;)
        if (q != selected_) order.push_back(q);
    for (std::uint32_t q : order) {
        if (s->isCircle(q)) {
            const Circle2& c = s->circles[q];
            const double d = QLineF(toScreen(c.center), p).length(), r = c.radius * scale_;
            if (d <= std::max(r - kRimBand, 0.5 * r)) return {Grab::Circle, q};
            if (std::abs(d - r) <= kRimBand) return {Grab::Rim, q};
        } else {
            const Segment2& seg = s->segments[q - s->circles.size()];
            const QPointF a = toScreen(seg.a), b = toScreen(seg.b);
            if (near(a, reach)) return {Grab::SegmentA, q};
            if (near(b, reach)) return {Grab::SegmentB, q};
            if (distanceToSegment(p, a, b) <= kRimBand) return {Grab::Segment, q};
        }
    }
    return {};
}

Vec2 View2D::snapPoint(Vec2 p) const {
    if (!snapCorners_) return p;
    // Corners and centres of the grid's cells: a ray from a centre through a corner passes the
    // vertex exactly (the DDA's tie), as the lecture's grids have cells of exact binary sizes.
    Vec2 lo(0.0), half(0.5);
    if (const OutlineGrid<2>* grid = shownGrid()) {
        const auto& spec = grid->spec;
        lo = Vec2(spec.lo.x, spec.lo.y);
        half = 0.5 * Vec2(spec.cellSize(0), spec.cellSize(1));
    }
    return lo + glm::round((p - lo) / half) * half;
}

void View2D::mousePressEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton && e->button() != Qt::MiddleButton) return;
    const Scene2D* s = session_.scene2D();
    if (!s) return;
    fit();
    Drag d;
    d.press = d.last = e->position();
    if (e->button() == Qt::MiddleButton) {
        d.pan = true;
    } else if (live_ && !session_.showingBuild() && (e->modifiers() & Qt::ShiftModifier)) {
        d.target = {Grab::NewRay, 0};  // Shift+drag draws a new example ray
    } else {
        d.target = targetAt(e->position());
        d.pan = d.target.grab == Grab::None;  // empty space: a pan, or a click on a cell
    }
    if (!d.pan) {
        d.start = *s;
        // The edit starts from the ray drawn (the replayed one), not from another of the scene's.
        if (const auto ray = shownRay()) d.start.exampleRay = ray;
        d.tipScale = tipScale();
        const Vec2 at = toWorld(e->position());
        const std::uint32_t q = d.target.prim;
        const std::uint32_t nc = static_cast<std::uint32_t>(s->circles.size());
        switch (d.target.grab) {
            case Grab::Origin:
                d.grabOffset = d.start.exampleRay->origin - at;
                break;
            case Grab::Tip:
                d.grabOffset =
                    d.start.exampleRay->origin + d.tipScale * d.start.exampleRay->dir - at;
                break;
            case Grab::Circle:
                d.grabOffset = s->circles[q].center - at;
                break;
            case Grab::SegmentA:
            case Grab::Segment:
                d.grabOffset = s->segments[q - nc].a - at;
                break;
            case Grab::SegmentB:
                d.grabOffset = s->segments[q - nc].b - at;
                break;
            default:
                break;
        }
    }
    drag_ = std::move(d);
}

void View2D::mouseMoveEvent(QMouseEvent* e) {
    if (!drag_) {
        updateCursor(e->position());
        return;
    }
    if (!drag_->moving) {
        // Within the drag distance a press is still a click (a lesson's cell answer).
        if ((e->position() - drag_->press).manhattanLength() < QApplication::startDragDistance())
            return;
        drag_->moving = true;
        if (!drag_->pan && live_) {
            static const char* const kWhat[] = {"",
                                                QT_TR_NOOP("Move the ray's origin"),
                                                QT_TR_NOOP("Turn the ray"),
                                                QT_TR_NOOP("Draw a new ray"),
                                                QT_TR_NOOP("Move the circle"),
                                                QT_TR_NOOP("Resize the circle"),
                                                QT_TR_NOOP("Move the segment's end"),
                                                QT_TR_NOOP("Move the segment's end"),
                                                QT_TR_NOOP("Move the segment")};
            // i18n: the gestures' names are marked with QT_TR_NOOP in kWhat just above
            live_->begin(tr(kWhat[static_cast<int>(drag_->target.grab)]));
        }
        setCursor(drag_->pan ? Qt::ClosedHandCursor : cursor().shape());
    }
    if (drag_->pan) {
        panBy(e->position() - drag_->last);
        drag_->last = e->position();
        return;
    }
    dragTo(e->position());
}

void View2D::dragTo(QPointF p) {
    if (!live_ || !live_->inGesture()) return;
    fit();
    Scene2D s = drag_->start;
    const Vec2 w = toWorld(p) + drag_->grabOffset;
    const std::uint32_t q = drag_->target.prim;
    const std::uint32_t nc = static_cast<std::uint32_t>(s.circles.size());
    // The tip: the corner snap within a handle's reach of a corner when the angle snap is on
    // too (the 15 degrees elsewhere), else whichever is on.
    const auto tipAt = [&](Vec2 origin, Vec2 tip) {
        const Vec2 corner = snapPoint(tip);
        if (snapCorners_ && (!snapAngle_ || glm::length(corner - tip) * scale_ <= kHandleRadius))
            return corner;
        return snapAngle_ ? origin + snapAngle15(tip - origin) : tip;
    };
    switch (drag_->target.grab) {
        case Grab::Origin:
            s.exampleRay->origin = snapPoint(w);
            break;
        case Grab::Tip: {
            const Vec2 o = s.exampleRay->origin;
            const Vec2 dir = (tipAt(o, w) - o) / drag_->tipScale;
            if (dir == Vec2(0.0)) return;  // a ray needs a direction
            s.exampleRay->dir = dir;
            break;
        }
        case Grab::NewRay: {
            const Vec2 o = snapPoint(toWorld(drag_->press));
            const Vec2 dir = tipAt(o, toWorld(p)) - o;
            if (dir == Vec2(0.0)) return;
            s.exampleRay = Ray2{o, dir};
            break;
        }
        case Grab::Circle:
            s.circles[q].center = snapPoint(w);
            break;
        case Grab::Rim:
            // At least two pixels: a circle never vanishes under the mouse.
            s.circles[q].radius =
                std::max(glm::length(toWorld(p) - s.circles[q].center), 2.0 / scale_);
            break;
        case Grab::SegmentA:
        case Grab::SegmentB: {
            Segment2& seg = s.segments[q - nc];
            (drag_->target.grab == Grab::SegmentA ? seg.a : seg.b) = snapPoint(w);
            if (seg.a == seg.b) return;  // a segment keeps a length
            break;
        }
        case Grab::Segment: {
            Segment2& seg = s.segments[q - nc];
            const Vec2 by = snapPoint(w) - seg.a;
            seg.a += by;
            seg.b += by;
            break;
        }
        case Grab::None:
            return;
    }
    live_->preview(s);
}

void View2D::mouseReleaseEvent(QMouseEvent* e) {
    if (!drag_ || (e->button() != Qt::LeftButton && e->button() != Qt::MiddleButton)) return;
    const Drag d = std::move(*drag_);
    drag_.reset();
    if (!d.moving) {
        if (e->button() != Qt::LeftButton) return;
        // Ctrl+click selects the primitive under the mouse (a drag selects what it moved). A
        // plain click is a lesson's cell answer and marks nothing: an exercise's picture stays.
        if (live_ && (e->modifiers() & Qt::ControlModifier)) {
            const Target t = targetAt(e->position());
            const bool shape = t.grab != Grab::None && t.grab != Grab::Origin &&
                               t.grab != Grab::Tip && t.grab != Grab::NewRay;
            setSelected(shape ? std::optional<std::uint32_t>(t.prim) : std::nullopt);
            return;
        }
        if (const auto c = cellAt(e->position())) emit cellClicked((*c)[0], (*c)[1]);
        return;
    }
    if (!d.pan && live_) {
        live_->end();
        const Grab g = d.target.grab;
        if (g != Grab::Origin && g != Grab::Tip && g != Grab::NewRay) setSelected(d.target.prim);
    }
    updateCursor(e->position());
}

void View2D::wheelEvent(QWheelEvent* e) {
    const double notches = e->angleDelta().y() / 120.0;
    if (!session_.scene2D() || notches == 0) return e->ignore();
    zoomAt(e->position(), std::pow(1.2, notches));
    e->accept();
}

void View2D::updateCursor(QPointF p) {
    switch (targetAt(p).grab) {
        case Grab::Origin:
        case Grab::Tip:
        case Grab::Circle:
        case Grab::Segment:
            setCursor(Qt::SizeAllCursor);
            break;
        case Grab::Rim:
            setCursor(Qt::SizeFDiagCursor);
            break;
        case Grab::SegmentA:
        case Grab::SegmentB:
            setCursor(Qt::CrossCursor);
            break;
        default:
            unsetCursor();
    }
}

void View2D::drawHandles(QPainter& g) const {
    const Scene2D* s = session_.scene2D();
    if (!live_ || !s) return;
    g.save();
    const QColor ray = paletteColour(rayColour(RayKind::Primary));
    // The selection in plain dark ink: no palette role, so it is never read as the current cell.
    const QColor mark(25, 25, 30);
    const QColor fill(255, 255, 255, 220);
    const double k = presentation().handleScale();  // presenter mode: thicker, larger handles
    const auto square = [&](QPointF at) {
        g.setPen(QPen(mark, 1.5 * k));
        g.setBrush(fill);
        g.drawRect(QRectF(at - QPointF(4.5, 4.5) * k, QSizeF(9, 9) * k));
    };
    // The selected primitive: dashed, with squares where it can be taken.
    if (selected_ && *selected_ < s->primitiveCount()) {
        g.setPen(QPen(mark, 2.5 * k, Qt::DashLine));
        g.setBrush(Qt::NoBrush);
        drawPrimitive(g, *selected_);
        if (s->isCircle(*selected_)) {
            const Circle2& c = s->circles[*selected_];
            square(toScreen(c.center));
            square(toScreen(c.center + Vec2(c.radius, 0.0)));
        } else {
            const Segment2& seg = s->segments[*selected_ - s->circles.size()];
            square(toScreen(seg.a));
            square(toScreen(seg.b));
        }
    }
    // The replayed ray's direction as an arrow from its origin, with a ring at each end to take.
    if (const auto shown = shownRay()) {
        const QPointF o = toScreen(shown->origin), tip = *tipHandle();
        g.setPen(QPen(ray, 2.5 * k));
        g.drawLine(o, tip);
        const QLineF back(tip, o);
        if (back.length() > 1) {
            QLineF wing = back;
            wing.setLength(12 * k);
            for (double turn : {-25.0, 25.0}) {
                QLineF w = wing;
                w.setAngle(back.angle() + turn);
                g.drawLine(w);
            }
        }
        g.setBrush(fill);
        g.setPen(QPen(ray, 2 * k));
        g.drawEllipse(o, 7 * k, 7 * k);
        g.drawEllipse(tip, 6 * k, 6 * k);
        g.setBrush(ray);
        g.drawEllipse(o, 3 * k, 3 * k);
    }
    g.restore();
}

}  // namespace raystep::gui
