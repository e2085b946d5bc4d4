// The 2D view's ray and what it meets: the ray faint in full and solid as far as the replay
// has reached, its origin, the nearest hit so far, the primitives tested, skipped by the mailbox
// and hit, and the DDA's tMax as labelled ticks and tDelta as brackets beside the ray.
#include "view2d.h"

#include "view2d_paint.h"

#include "language.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace raystep::gui {

using namespace draw2d;

void View2D::drawTouched(QPainter& g, const ReplayState& st) const {
    const Ink ink = draw2d::ink();
    const Scene2D* s = session_.scene2D();
    // Primitives: tested ones orange, skipped by the mailbox grey, the nearest hit green.
    const auto colourOf = [&](std::uint32_t p) {
        if (st.nearestT && st.nearestPrim == p) return ink.hit;
        for (auto q : st.mailboxSkips)
            if (q == p) return ink.skipped;
        for (const auto& t : st.tests)
            if (t.prim == p) return ink.tested;
        return ink.primitive;
    };
    g.drawPixmap(0, 0, layer_);
    // Then the few that the replay has touched, in their colour, over the neutral ones.
    std::vector<std::uint32_t> touched;
    for (const auto& t : st.tests) touched.push_back(t.prim);
    for (auto q : st.mailboxSkips) touched.push_back(q);
    if (st.nearestT) touched.push_back(st.nearestPrim);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (std::uint32_t p : touched) {
        if (p >= s->primitiveCount()) continue;
        g.setPen(QPen(colourOf(p), px(p == st.nearestPrim ? 3.0 : 2.0)));
        drawPrimitive(g, p);
    }
}

void View2D::drawRay(QPainter& g, const ReplayState& st) const {
    // The ray: faint in full, solid up to where the replay has reached.
    const Ink ink = draw2d::ink();
    const RayRecord& r = session_.log().rays().front();
    const Vec2 o(r.origin.x, r.origin.y), d(r.dir.x, r.dir.y);
    // Far enough to leave the visible part, whatever the zoom and pan.
    const Vec2 seen = toWorld(QPointF(width(), 0)) - toWorld(QPointF(0, height()));
    const double tFar =
        (glm::length(seen) + glm::length(toWorld(rect().center()) - o)) / glm::length(d);
    g.setPen(
        QPen(QColor(ink.ray.red(), ink.ray.green(), ink.ray.blue(), 70), px(1.5), Qt::DashLine));
    g.drawLine(toScreen(o), toScreen(o + tFar * d));
    double reached = 0.0;
    if (st.ddaCell) reached = std::min(st.ddaCell->tMax[0], st.ddaCell->tMax[1]);
    if (st.node) reached = std::max(reached, st.node->tFar);
    if (st.nearestT && (st.hit || st.blocked || st.missed)) reached = *st.nearestT;
    if (std::isfinite(reached) && reached > 0) {
        g.setPen(QPen(ink.ray, px(2.5)));
        g.drawLine(toScreen(o), toScreen(o + reached * d));
    }
    g.setBrush(ink.ray);
    g.drawEllipse(toScreen(o), px(4), px(4));
    // tMax as labelled ticks on the ray, tDelta as brackets beside it.
    drawnLabels_.clear();
    tDeltaSpans_ = {};
    if (st.ddaCell) drawDdaMarks(g, o, d, st);
    if (st.nearestT) {
        g.setBrush(ink.hit);
        g.setPen(Qt::NoPen);
        g.drawEllipse(toScreen(o + *st.nearestT * d), px(5), px(5));
    }
}

namespace {
/// Labels put where they overlap no label put before and stay inside the view: from the spot
/// asked for, outwards along `away`, then shifted along the ray.
class LabelPlacer {
  public:
    LabelPlacer(QRectF bounds, const QFontMetricsF& fm) : bounds_(bounds), fm_(fm) {}
    /// Where `text` goes near `anchor`, on the side `away` (a unit vector on screen).
    QRectF place(const QString& text, QPointF anchor, QPointF away, QPointF along) {
        const QSizeF size(fm_.horizontalAdvance(text) + 8, fm_.height() + 2);
        // The spots nearest the anchor first: a step away, or a shift along the ray.
        std::vector<std::pair<double, QPointF>> spots;
        for (int k = 0; k < 4; ++k)
            for (const double shift : {0.0, 0.6, -0.6, 1.2, -1.2}) {
                const QPointF by =
                    away * (k * (size.height() + 2)) + along * (shift * size.width());
                spots.emplace_back(std::hypot(by.x(), by.y()), by);
            }
        std::stable_sort(spots.begin(), spots.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        QRectF best;
        for (const auto& spot : spots) {
            // The box's corner nearest the anchor on the `away` side.
            const QPointF c = anchor + spot.second;
            QRectF r(c - QPointF(away.x() < 0 ? size.width() : 0, away.y() < 0 ? size.height() : 0),
                     size);
            if (std::abs(away.x()) < 0.35) r.moveLeft(c.x() - size.width() / 2);
            if (std::abs(away.y()) < 0.35) r.moveTop(c.y() - size.height() / 2);
            // Kept inside the view (a label at the top edge was cut).
            r.moveLeft(std::clamp(r.left(), bounds_.left(), bounds_.right() - r.width()));
            r.moveTop(std::clamp(r.top(), bounds_.top(), bounds_.bottom() - r.height()));
            if (best.isNull()) best = r;
            const bool free = std::none_of(placed_.begin(), placed_.end(),
                                           [&](const QRectF& p) { return p.intersects(r); });
            if (free) {
                placed_.push_back(r);
                return r;
            }
        }
        placed_.push_back(best);
        return best;
    }
    /// A part of the picture labels keep off (a tick, the ray's origin).
    void keepOff(QRectF r) { placed_.push_back(r); }

  private:
    QRectF bounds_;
    const QFontMetricsF& fm_;
    std::vector<QRectF> placed_;
};
}  // namespace

void View2D::drawDdaMarks(QPainter& g, Vec2 o, Vec2 d, const ReplayState& st) const {
    // Labels no taller than about 40% of a cell (a large zoom on a small screen made them wider
    // than the cells they name and pushed them far from their ticks), nor smaller than the
    // caption's font.
    const OutlineGrid<2>* grid = shownGrid();
    g.save();
    if (grid) {
        const double cell = std::min(grid->spec.cellSize(0), grid->spec.cellSize(1)) * scale_ * 0.4;
        const double now = QFontMetricsF(g.font()).height();
        const double least = QFontMetricsF(presentation().captionFont()).height();
        if (now > cell && now > least) {
            QFont f = g.font();
            const double k = std::max(cell, least) / now;
            if (f.pointSizeF() > 0)
                f.setPointSizeF(f.pointSizeF() * k);
            else
                f.setPixelSize(std::max(1, int(f.pixelSize() * k)));
            g.setFont(f);
        }
    }
    drawDdaMarksIn(g, o, d, st, grid);
    g.restore();
}

void View2D::drawDdaMarksIn(QPainter& g, Vec2 o, Vec2 d, const ReplayState& st,
                            const OutlineGrid<2>* grid) const {
    const QFontMetricsF fm(g.font());
    // The ray's direction and its normal on screen, in pixels (y grows downwards).
    const QPointF from = toScreen(o), ahead = toScreen(o + d) - from;
    const double len = std::hypot(ahead.x(), ahead.y());
    if (!(len > 0)) return;
    const QPointF u = ahead / len, n(u.y(), -u.x());  // n: to the ray's left as drawn
    const double tick = px(7), bracket = px(7) + 0.6 * fm.height();
    LabelPlacer labels(QRectF(rect()).adjusted(2, 2, -2, -2), fm);
    labels.keepOff(QRectF(from - QPointF(px(8), px(8)), QSizeF(px(16), px(16))));
    // Off the grid's cell numbers too: the row under it and the column left of it.
    if (grid) {
        const auto& spec = grid->spec;
        const QPointF lo = toScreen(Vec2(spec.lo.x, spec.lo.y)),
                      hi = toScreen(Vec2(spec.hi.x, spec.hi.y));
        labels.keepOff(
            QRectF(QPointF(lo.x(), lo.y() + 1), QPointF(hi.x(), lo.y() + fm.height() + 4)));
        labels.keepOff(
            QRectF(QPointF(lo.x() - fm.horizontalAdvance(QStringLiteral("00")) - 8, hi.y()),
                   QPointF(lo.x() - 1, lo.y())));
    }
    const auto label = [&](const QString& text, QPointF anchor, QPointF away, const QColor& c) {
        const QRectF r = labels.place(text, anchor, away, u);
        drawnLabels_.push_back({text, r});
        g.setPen(Qt::NoPen);
        g.setBrush(QColor(255, 255, 255, 205));
        g.drawRoundedRect(r, 3, 3);
        g.setPen(c);
        g.drawText(r, Qt::AlignCenter, text);
    };
    const QColor colour[2] = {QColor(30, 90, 200), QColor(140, 40, 170)};
    const double tX = st.ddaCell->tMax[0], tY = st.ddaCell->tMax[1];
    // A tie (the ray through a grid vertex): one tick and one label for both.
    const bool tie = std::isfinite(tX) && tX == tY;
    for (int axis = 0; axis < 2; ++axis) {
        const double t = st.ddaCell->tMax[axis];
        if (!std::isfinite(t)) continue;
        const QPointF p = toScreen(o + t * d);
        g.setPen(QPen(colour[axis], px(2)));
        g.drawLine(p + tick * n, p - tick * n);
        labels.keepOff(QRectF(p - QPointF(tick, tick), QSizeF(2 * tick, 2 * tick)));
    }
    for (int axis = 0; axis < 2; ++axis) {
        const double t = st.ddaCell->tMax[axis];
        if (!std::isfinite(t) || (tie && axis == 1)) continue;
        const QPointF p = toScreen(o + t * d);
        const QString text =
            tie ? QStringLiteral("tMaxX = tMaxY = %1").arg(numberText(t, 'g', 4))
                : (axis == 0 ? QStringLiteral("tMaxX = %1") : QStringLiteral("tMaxY = %1"))
                      .arg(numberText(t, 'g', 4));
        // X's on the ray's left, Y's on its right, as their brackets.
        label(text, p + (axis == 0 ? 1 : -1) * (tick + 2) * n, axis == 0 ? n : -n,
              tie ? QColor(60, 60, 60) : colour[axis]);
    }
    // tDelta: the stretch of ray between two boundaries of this axis, a bracket ending at tMax.
    // Where it starts behind the origin (the first boundary is nearer than a whole cell), the
    // part behind the origin is dashed: the ray's line goes on back there, the ray does not.
    if (!st.ddaSetup) return;
    for (int axis = 0; axis < 2; ++axis) {
        const double t = st.ddaCell->tMax[axis], delta = st.ddaSetup->tDelta[axis];
        if (!std::isfinite(t) || !std::isfinite(delta)) continue;
        const QPointF side = (axis == 0 ? 1.0 : -1.0) * bracket * n;
        const double t0 = t - delta;
        tDeltaSpans_[axis] = {t0, t};
        const QPointF p0 = toScreen(o + t0 * d) + side, p1 = toScreen(o + t * d) + side;
        const QPointF at0 = toScreen(o + std::max(0.0, t0) * d) + side;
        g.setPen(QPen(colour[axis], px(1.2)));
        g.drawLine(at0, p1);
        if (t0 < 0) {
            g.setPen(QPen(colour[axis], px(1.2), Qt::DashLine));
            g.drawLine(p0, at0);
            g.setPen(QPen(colour[axis], px(1.2)));
        }
        g.drawLine(p0, p0 - 0.5 * side);
        g.drawLine(p1, p1 - 0.5 * side);
        label(axis == 0 ? QStringLiteral("tDeltaX") : QStringLiteral("tDeltaY"), (p0 + p1) / 2,
              side / bracket, colour[axis]);
    }
}

}  // namespace raystep::gui
