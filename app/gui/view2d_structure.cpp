// The 2D view's structure: the cached layer of the grid's lines and cell numbers, the kd-tree's
// planes, the BVH's boxes and the primitives; over it at the cursor the visited and current
// cells or the tree's nodes entered and skipped, and a build's replay (the node being split,
// its candidate planes, the planes chosen so far).
#include "view2d.h"

#include "view2d_paint.h"

#include <QPainter>

#include <algorithm>

namespace raystep::gui {

using namespace draw2d;

void View2D::drawWalk(QPainter& g, const ReplayState& st) const {
    const Ink ink = draw2d::ink();
    const StructureOutline<2>* outline = session_.outline2D();
    const OutlineGrid<2>* grid = shownGrid();
    if (grid) {
        for (const auto& c : st.visitedCells) g.fillRect(cellRect(*grid, c), ink.visited);
        if (st.ddaCell) g.fillRect(cellRect(*grid, st.ddaCell->cell), ink.current);
    } else if (outline && !outline->nodes.empty() && !session_.showingBuild()) {
        // A tree's walk, from its outline (any tree: the kd-tree's cells, the BVH's boxes): the
        // nodes it skipped dashed in grey, the ones it entered outlined in the visited colour,
        // the one being entered filled.
        const auto boxRect = [&](std::uint32_t id) -> std::optional<QRectF> {
            const BoxN<2>* b = outline->nodeBox(id);
            if (!b) return std::nullopt;
            return QRectF(toScreen(Vec2(b->lo.x, b->hi.y)), toScreen(Vec2(b->hi.x, b->lo.y)));
        };
        if (st.node)
            if (const auto r = boxRect(st.node->node))
                g.fillRect(*r, role(PaletteRole::Current, 110));
        g.setBrush(Qt::NoBrush);
        QPen skip(role(PaletteRole::Skipped), px(2.0), Qt::CustomDashLine);
        skip.setDashPattern({3, 2});  // in pen widths: dashes a box's small edge still shows
        g.setPen(skip);
        for (const std::uint32_t id : st.nodesSkipped)
            if (const auto r = boxRect(id)) g.drawRect(*r);
        g.setPen(QPen(role(PaletteRole::Visited, 230), px(2.5)));
        for (const std::uint32_t id : st.nodesEntered)
            if (const auto r = boxRect(id)) g.drawRect(*r);
    }
}

void View2D::drawStudentWalk(QPainter& g) const {
    const StudentWalk& w = *student_;
    const QColor blue = draw2d::ink().student;
    const StructureOutline<2>* outline = session_.outline2D();
    const OutlineGrid<2>* grid = shownGrid();
    // Each of the student's cells (or nodes) as a box inset in the reference's, so raystep's
    // colour still shows around it; the walk's order as a line through their centres.
    std::vector<QRectF> boxes;
    std::vector<std::size_t> index;  // each box's place in the student's walk
    if (grid) {
        for (std::size_t k = 0; k < w.cells.size(); ++k) {
            boxes.push_back(cellRect(*grid, w.cells[k]).normalized());
            index.push_back(k);
        }
    } else if (outline) {
        for (std::size_t k = 0; k < w.nodes.size(); ++k)
            if (const BoxN<2>* b = outline->nodeBox(w.nodes[k])) {
                boxes.push_back(
                    QRectF(toScreen(Vec2(b->lo.x, b->hi.y)), toScreen(Vec2(b->hi.x, b->lo.y)))
                        .normalized());
                index.push_back(k);
            }
    }
    const double inset = px(3.5);
    g.save();
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const QRectF r = boxes[i].adjusted(inset, inset, -inset, -inset);
        const bool divergent = w.divergent && index[i] == *w.divergent;
        // A tree's nodes nest: tinted, the root would be under every tint of its descendants.
        g.setBrush(divergent ? QBrush(blue, Qt::BDiagPattern)
                   : grid    ? QBrush(QColor(blue.red(), blue.green(), blue.blue(), 40))
                             : QBrush(Qt::NoBrush));
        QPen pen(blue, px(divergent ? 4.0 : 2.0));
        if (!divergent) pen.setStyle(Qt::DashLine);
        g.setPen(pen);
        g.drawRect(r);
    }
    // A tree's nodes nest: their centres say little of the order, so only a grid's are joined.
    if (grid && boxes.size() > 1) {
        QPolygonF path;
        for (const QRectF& r : boxes) path << r.center();
        g.setPen(QPen(blue, px(2.0)));
        g.setBrush(Qt::NoBrush);
        g.drawPolyline(path);
        g.setBrush(blue);
        for (const QPointF& c : path) g.drawEllipse(c, px(3.0), px(3.0));
    }
    // The first that differs, marked with the sign the board uses.
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (w.divergent && index[i] == *w.divergent) {
            QFont f = g.font();
            f.setBold(true);
            f.setPointSizeF(f.pointSizeF() * 1.6);
            g.setFont(f);
            const QRectF r = boxes[i];
            const QRectF tag(r.left() + inset, r.top() + inset, r.width() / 2, r.height() / 2);
            g.setPen(Qt::NoPen);
            g.setBrush(QColor(255, 255, 255, 230));
            const QFontMetricsF fm(f);
            const double s = fm.height();
            const QRectF badge(tag.left() + 2, tag.top() + 2, s, s);
            g.drawEllipse(badge);
            g.setPen(blue);
            g.drawText(badge, Qt::AlignCenter, QStringLiteral("\u2260"));
        }
    g.restore();
}

void View2D::drawBuildReplay(QPainter& g, const ReplayState& st) const {
    // The tree as far as it is built: the planes chosen before the cursor. A big build has
    // thousands (a frame must stay cheap while scrubbing): then only the current node's
    // ancestors' planes, which frame the node being split.
    const EventLog& log = session_.log();
    const auto line = [&](std::uint32_t node, int axis, double pos) {
        if (node >= log.nodes().size()) return;
        const NodeRecord& n = log.nodes()[node];
        const Vec2 a = axis == 0 ? Vec2(pos, n.lo[1]) : Vec2(n.lo[0], pos);
        const Vec2 b = axis == 0 ? Vec2(pos, n.hi[1]) : Vec2(n.hi[0], pos);
        g.drawLine(toScreen(a), toScreen(b));
    };
    g.setPen(QPen(QColor(90, 90, 100), px(1.5)));
    const std::size_t chosenSoFar = static_cast<std::size_t>(
        std::lower_bound(chosenAt_.begin(), chosenAt_.end(), st.cursor) - chosenAt_.begin());
    if (chosenSoFar <= kAllSplitsUpTo) {
        for (std::size_t k = 0; k < chosenSoFar; ++k) {
            const auto& c = std::get<SplitChosen>(log.events()[chosenAt_[k]]);
            line(c.node, c.axis, c.position);
        }
    } else if (st.buildNode) {
        for (std::uint32_t n = st.buildNode->parent; n != kNoId && n < buildParent_.size();
             n = buildParent_[n])
            if (splitOf_[n].first >= 0 && splitAt_[n] < st.cursor)
                line(n, splitOf_[n].first, splitOf_[n].second);
    }
    if (st.buildNode && st.buildNode->node < session_.log().nodes().size()) {
        const NodeRecord& n = session_.log().nodes()[st.buildNode->node];
        const QRectF box(toScreen(Vec2(n.lo[0], n.hi[1])), toScreen(Vec2(n.hi[0], n.lo[1])));
        g.fillRect(box, role(PaletteRole::Current, 50));
        g.setPen(QPen(role(PaletteRole::Current), px(2)));
        g.drawRect(box);
        // The most recent candidates (a big node has thousands; the chart shows them all).
        constexpr std::size_t kShown = 256;
        const std::size_t from = st.candidates.size() > kShown ? st.candidates.size() - kShown : 0;
        g.setPen(QPen(role(PaletteRole::Candidate, 110), px(1)));  // solid: dashes rasterize slowly
        for (std::size_t k = from; k < st.candidates.size(); ++k) {
            const SplitCandidate& c = st.candidates[k];
            const Vec2 a = c.axis == 0 ? Vec2(c.position, n.lo[1]) : Vec2(n.lo[0], c.position);
            const Vec2 b = c.axis == 0 ? Vec2(c.position, n.hi[1]) : Vec2(n.hi[0], c.position);
            g.drawLine(toScreen(a), toScreen(b));
        }
        if (st.chosen) {
            g.setPen(QPen(role(PaletteRole::Chosen), px(3)));
            const auto& c = *st.chosen;
            const Vec2 a = c.axis == 0 ? Vec2(c.position, n.lo[1]) : Vec2(n.lo[0], c.position);
            const Vec2 b = c.axis == 0 ? Vec2(c.position, n.hi[1]) : Vec2(n.hi[0], c.position);
            g.drawLine(toScreen(a), toScreen(b));
        }
    }
}

void View2D::drawPrimitive(QPainter& painter, std::uint32_t p) const {
    const Scene2D* s = session_.scene2D();
    if (s->isCircle(p)) {
        const Circle2& c = s->circles[p];
        painter.drawEllipse(toScreen(c.center), c.radius * scale_, c.radius * scale_);
    } else {
        const Segment2& seg = s->segments[p - s->circles.size()];
        painter.drawLine(toScreen(seg.a), toScreen(seg.b));
    }
}

const OutlineGrid<2>* View2D::shownGrid() const {
    const StructureOutline<2>* o = session_.outline2D();
    return o && o->grid ? &*o->grid : nullptr;
}

void View2D::buildLayer() {
    static const StructureOutline<2> kNone;
    const StructureOutline<2>& shown = session_.outline2D() ? *session_.outline2D() : kNone;
    const OutlineGrid<2>* grid = shownGrid();
    const Scene2D* s = session_.scene2D();
    layer_ = QPixmap(size());
    layer_.fill(Qt::transparent);
    QPainter lp(&layer_);
    lp.setRenderHint(QPainter::Antialiasing, s->primitiveCount() < 5000);
    const Ink ink = draw2d::ink();
    const QFontMetricsF fm(font());
    if (grid) {
        const auto& spec = grid->spec;
        lp.setPen(QPen(ink.gridLine, px(1)));
        for (int i = 0; i <= spec.res.x; ++i) {
            const double x = spec.lo.x + i * spec.cellSize(0);
            lp.drawLine(toScreen(Vec2(x, spec.lo.y)), toScreen(Vec2(x, spec.hi.y)));
        }
        for (int j = 0; j <= spec.res.y; ++j) {
            const double y = spec.lo.y + j * spec.cellSize(1);
            lp.drawLine(toScreen(Vec2(spec.lo.x, y)), toScreen(Vec2(spec.hi.x, y)));
        }
        // Cell indices along the edges, as on the board.
        // Centred under (x) and left of (y) their cells, at any label size.
        lp.setPen(ink.label);
        for (int i = 0; i < spec.res.x; ++i) {
            const QString n = QString::number(i);
            lp.drawText(toScreen(Vec2(spec.lo.x + (i + 0.5) * spec.cellSize(0), spec.lo.y)) +
                            QPointF(-fm.horizontalAdvance(n) / 2, fm.ascent() + 2),
                        n);
        }
        for (int j = 0; j < spec.res.y; ++j) {
            const QString n = QString::number(j);
            lp.drawText(toScreen(Vec2(spec.lo.x, spec.lo.y + (j + 0.5) * spec.cellSize(1))) +
                            QPointF(-fm.horizontalAdvance(n) - 5, fm.ascent() / 2 - 1),
                        n);
        }
    }
    // A build's replay draws only the planes or boxes made so far (paintEvent), not the
    // answer; nor does any trace while a held build's exercise asks for them.
    const bool whole = !session_.showingBuild() && !session_.holdsBuild();
    if (whole) {
        // The kd-tree's split planes, each across its node's cell.
        lp.setPen(QPen(ink.gridLine, px(1)));
        for (const OutlinePlane<2>& plane : shown.planes) {
            const auto [a, b] = plane.extent();
            lp.drawLine(toScreen(Vec2(a.x, a.y)), toScreen(Vec2(b.x, b.y)));
        }
        // The BVH's boxes, overlapping as they are: deeper ones darker and drawn later, so a
        // child's edge shows over its parent's where they meet.
        if (shown.overlapping && !shown.nodes.empty()) {
            std::vector<std::uint32_t> order(shown.nodes.size());
            for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
            std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
                return shown.nodes[a].depth < shown.nodes[b].depth;
            });
            const double deepest = std::max<std::uint32_t>(1, shown.maxDepth);
            lp.setBrush(Qt::NoBrush);
            for (const std::uint32_t id : order) {
                const OutlineNode<2>& n = shown.nodes[id];
                const int shade = int(200 - 110 * (n.depth / deepest));
                lp.setPen(QPen(QColor(shade, shade, shade + 10), px(n.leaf ? 1.0 : 1.5)));
                lp.drawRect(QRectF(toScreen(Vec2(n.box.lo.x, n.box.hi.y)),
                                   toScreen(Vec2(n.box.hi.x, n.box.lo.y))));
            }
        }
    }
    lp.setPen(QPen(ink.primitive, px(2.0)));
    for (std::uint32_t p = 0; p < s->primitiveCount(); ++p) drawPrimitive(lp, p);
    layerSize_ = size();
    layerDirty_ = false;
}

void View2D::drawSequence(QPainter& g) const {
    const OutlineGrid<2>* grid = shownGrid();
    // A sequence answer: each clicked cell with its place in the order, over the picture.
    g.setFont([&] {
        QFont f = g.font();
        f.setBold(true);
        f.setPointSizeF(f.pointSizeF() * 1.3);
        return f;
    }());
    for (int k = 0; k < sequence_.size(); ++k) {
        const QRectF cell = cellRect(*grid, {sequence_[k].x(), sequence_[k].y(), 0}).normalized();
        const double r = std::min(cell.width(), cell.height()) * 0.22;
        const QPointF c = cell.center() + QPointF(cell.width() * 0.25, -cell.height() * 0.25);
        g.setPen(QPen(QColor(30, 30, 30), px(1.5)));
        g.setBrush(QColor(255, 255, 255, 230));
        g.drawEllipse(c, r, r);
        g.drawText(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r), Qt::AlignCenter,
                   QString::number(k + 1));
    }
    g.setFont(font());
}

}  // namespace raystep::gui
