// The 2D view's SAH cost chart under a build's replay: each candidate's cost against its
// position, one curve per axis at the view's scale under the node, the leaf's cost dashed, the
// current candidate and the choice marked with their values.
#include "view2d.h"

#include "view2d_paint.h"

#include "language.h"

#include "presentation.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace raystep::gui {

using namespace draw2d;

double View2D::chartStrip() const {
    const QFontMetricsF fm(font());
    const double strip = std::min(chartHeight(fm), kChartShare * height());
    // A plot too low for three of its cost values is not drawn: the scene keeps that room too.
    return strip - chartHeight(fm, 0) >= 3 * (fm.height() + 6) ? strip : 0.0;
}

std::vector<double> niceTicks(double lo, double hi, int count) {
    std::vector<double> ticks;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || count < 1) return ticks;
    const double rough = (hi - lo) / count;
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    double step = 10 * power;
    for (double m : {1.0, 2.0, 5.0})
        if (m * power >= rough) {
            step = m * power;
            break;
        }
    // Multiples of the step: k * step, not a running sum, so 0.1 + 0.2 does not drift.
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; ++k)
        ticks.push_back(k * step);
    return ticks;
}

std::optional<CostChart> View2D::costChart() const {
    const ReplayState& st = session_.state();
    if (!session_.showingBuild() || st.candidates.empty() || !st.buildNode ||
        st.buildNode->node >= session_.log().nodes().size() || !session_.scene2D())
        return std::nullopt;
    fit();
    const NodeRecord& n = session_.log().nodes()[st.buildNode->node];
    CostChart c;
    c.scale = scale_;
    c.nodeLo = {n.lo[0], n.lo[1]};
    const double left = toScreen(Vec2(n.lo[0], n.lo[1])).x();
    const double extent = std::max(n.hi[0] - n.lo[0], n.hi[1] - n.lo[1]) * scale_;
    const QFontMetricsF fm(font());
    const double strip = chartStrip();
    if (strip <= 0) return std::nullopt;
    const double top = height() - strip + fm.height() + 14,
                 bottom = height() - 2 * (fm.height() + 1) - 12;
    c.plot = QRectF(QPointF(left, top),
                    QPointF(std::min(left + std::max(extent, 40.0), width() - 8.0), bottom));
    double lo = kInfinity, hi = -kInfinity;
    bool onAxis[2] = {false, false};
    for (const SplitCandidate& k : st.candidates) {
        lo = std::min(lo, k.sahCost), hi = std::max(hi, k.sahCost);
        onAxis[k.axis & 1] = true;
    }
    // The leaf's cost (not splitting) with the build's own C_isect, from the node's first step;
    // an old trace cut before the node's outcome does not know it (no line).
    c.leafCost = st.buildNode->leafCost;
    if (std::isnan(c.leafCost) && st.chosen) c.leafCost = st.chosen->leafCost;
    if (std::isfinite(c.leafCost)) lo = std::min(lo, c.leafCost), hi = std::max(hi, c.leafCost);
    if (hi - lo < 1e-9 * std::max(1.0, std::abs(hi))) lo -= 1, hi += 1;  // one value: a band
    const double pad = 0.06 * (hi - lo);
    c.costLo = lo - pad, c.costHi = hi + pad;
    // About one value per 28 pixels, and three at least (a short plot: closer, never touching).
    const int most = std::max(3, int(c.plot.height() / (fm.height() + 2)));
    for (int n = std::max(2, int(c.plot.height() / 28)); n <= most; ++n) {
        c.costTicks = niceTicks(c.costLo, c.costHi, n);
        if (c.costTicks.size() >= 3) break;
    }
    for (int a = 0; a < 2; ++a)
        if (onAxis[a])
            c.positionTicks[a] =
                niceTicks(n.lo[a], n.hi[a], std::max(2, int((n.hi[a] - n.lo[a]) * scale_ / 70)));
    return c;
}

void View2D::drawCostChart(QPainter& g, const ReplayState& st) const {
    // The SAH cost of each candidate against its position, one curve per axis, at the view's
    // scale under the node; the leaf's cost (not splitting) dashed; the current candidate and
    // the choice marked with their values.
    const auto chart = costChart();
    if (!chart) return;
    const CostChart& c = *chart;
    const QFontMetricsF fm(g.font());
    const double axisRoom = chartAxisRoom(fm);
    const QRectF strip(4, height() - chartStrip() + 4, width() - 8, chartStrip() - 8);
    g.save();
    g.setPen(QColor(200, 200, 200));
    g.setBrush(QColor(255, 255, 255, 235));
    g.drawRoundedRect(strip, 4, 4);
    const QColor ink(50, 50, 50), faint(225, 225, 225);
    // The cost axis: its gridlines and values, left of the plot.
    for (double v : c.costTicks) {
        const double y = c.at(0, c.nodeLo[0], v).y();
        g.setPen(QPen(faint, 1));
        g.drawLine(QPointF(c.plot.left(), y), QPointF(c.plot.right(), y));
        g.setPen(ink);
        g.drawText(QRectF(c.plot.left() - axisRoom, y - fm.height() / 2, axisRoom - 8, fm.height()),
                   Qt::AlignRight | Qt::AlignVCenter, numberText(v, 'g', 4));
    }
    g.setPen(QPen(ink, 1));
    g.drawLine(c.plot.bottomLeft(), c.plot.topLeft());
    g.drawLine(c.plot.bottomLeft(), c.plot.bottomRight());
    // The position axes: one row of values per axis with candidates, in its curve's colour.
    int row = 0;
    for (int axis = 0; axis < 2; ++axis) {
        if (c.positionTicks[axis].empty()) continue;
        const QColor colour = colourOf(curveColour(axis));
        const double y = c.plot.bottom() + 2 + row * (fm.height() + 1);
        for (double v : c.positionTicks[axis]) {
            const double x = c.at(axis, v, c.costLo).x();
            if (x > c.plot.right() + 1) continue;
            g.setPen(QPen(colour, 1));
            g.drawLine(QPointF(x, c.plot.bottom()), QPointF(x, c.plot.bottom() + 3));
            g.drawText(QRectF(x - 40, y + 2, 80, fm.height()), Qt::AlignHCenter | Qt::AlignTop,
                       numberText(v, 'g', 4));
        }
        g.drawText(QRectF(c.plot.left() - axisRoom, y + 2, axisRoom - 8, fm.height()),
                   Qt::AlignRight | Qt::AlignTop,
                   axis == 0 ? QStringLiteral("x =") : QStringLiteral("y ="));
        ++row;
    }
    g.setClipRect(c.plot.adjusted(-6, -6, 6, 6));
    // At most about 2,000 points a curve: a screen has no more columns to show.
    const std::size_t stride = std::max<std::size_t>(1, st.candidates.size() / 2000);
    for (int axis = 0; axis < 2; ++axis) {
        QPolygonF line;
        for (std::size_t k = 0; k < st.candidates.size(); k += stride) {
            const SplitCandidate& s = st.candidates[k];
            if (s.axis == axis) line << c.at(axis, s.position, s.sahCost);
        }
        g.setPen(QPen(colourOf(curveColour(axis)), px(1.8)));
        g.setBrush(Qt::NoBrush);
        g.drawPolyline(line);
        if (line.size() < 200)
            for (const QPointF& p : line) g.drawEllipse(p, 2, 2);
    }
    if (std::isfinite(c.leafCost)) {
        g.setPen(QPen(QColor(90, 90, 90), 1, Qt::DashLine));
        const double yLeaf = c.at(0, c.nodeLo[0], c.leafCost).y();
        g.drawLine(QPointF(c.plot.left(), yLeaf), QPointF(c.plot.right(), yLeaf));
    }
    g.setClipping(false);
    // A value in a small white box beside its point, kept inside the strip.
    const auto tag = [&](QPointF p, const QString& text, const QColor& border) {
        const double w = fm.horizontalAdvance(text) + 8, h = fm.height() + 2;
        QRectF r(p.x() + 8, p.y() - h - 4, w, h);
        if (r.right() > strip.right() - 2) r.moveRight(p.x() - 8);
        if (r.top() < strip.top() + 2) r.moveTop(p.y() + 6);
        g.setPen(QPen(border, 1));
        g.setBrush(QColor(255, 255, 255, 240));
        g.drawRect(r);
        g.setPen(ink);
        g.drawText(r, Qt::AlignCenter, text);
    };
    const auto axisName = [](int axis) {
        return axis == 0 ? QStringLiteral("X") : QStringLiteral("Y");
    };
    if (st.chosen) {
        const QPointF p = c.at(st.chosen->axis, st.chosen->position, st.chosen->sahCost);
        g.setPen(Qt::NoPen);
        g.setBrush(role(PaletteRole::Chosen));
        g.drawEllipse(p, 5, 5);
        tag(p,
            tr("chosen: %1 = %2, cost %3")
                .arg(axisName(st.chosen->axis), numberText(st.chosen->position, 'g', 4),
                     numberText(st.chosen->sahCost, 'g', 4)),
            role(PaletteRole::Chosen));
    } else {
        // The candidate the cursor is at: the last one recorded.
        const SplitCandidate& k = st.candidates.back();
        const QPointF p = c.at(k.axis, k.position, k.sahCost);
        g.setPen(QPen(ink, 2));
        g.setBrush(Qt::NoBrush);
        g.drawEllipse(p, 5, 5);
        tag(p,
            tr("%1 = %2: cost %3")
                .arg(axisName(k.axis), numberText(k.position, 'g', 4),
                     numberText(k.sahCost, 'g', 4)),
            colourOf(curveColour(k.axis)));
    }
    // Title and legend on the strip's top row.
    double x = strip.left() + 8;
    const double y = strip.top() + 4;
    g.setPen(ink);
    const QString title = tr("SAH cost of each candidate");
    g.drawText(QPointF(x, y + fm.ascent()), title);
    x += fm.horizontalAdvance(title) + 16;
    const auto entry = [&](const QPen& pen, const QString& text) {
        g.setPen(pen);
        g.drawLine(QPointF(x, y + fm.height() / 2), QPointF(x + 22, y + fm.height() / 2));
        g.setPen(ink);
        g.drawText(QPointF(x + 26, y + fm.ascent()), text);
        x += 26 + fm.horizontalAdvance(text) + 14;
    };
    for (int axis = 0; axis < 2; ++axis) {
        const std::string_view name = curveColour(axis).name(lang_);
        entry(QPen(colourOf(curveColour(axis)), 2.5),
              (axis == 0 ? tr("X split (%1)") : tr("Y split (%1)"))
                  .arg(QString::fromUtf8(name.data(), name.size())));
    }
    entry(QPen(QColor(90, 90, 90), 1, Qt::DashLine), tr("leaf: no split"));
    g.restore();
}

}  // namespace raystep::gui
