#include "view2d.h"

#include "course/palette.h"
#include "language.h"

#include <QMouseEvent>

#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace raystep::gui {

namespace {
const QColor kBackground(250, 250, 247);
const QColor kGridLine(200, 200, 200);
const QColor kPrimitive(60, 60, 70);  // untouched primitives: ink, not a role
QColor colourOf(const PaletteColour& c, int alpha = 255) {
    return QColor(c.r, c.g, c.b, alpha);
}
// The roles' colours come from the one palette (course/palette.h), as the lessons name them.
QColor role(PaletteRole r, int alpha = 255) {
    return colourOf(roleColour(r), alpha);
}
// Visited cells as a light tint of the palette's colour, so the grid and labels stay readable.
const QColor kVisited = role(PaletteRole::Visited, 120);
const QColor kCurrent = role(PaletteRole::Current, 200);
const QColor kTested = role(PaletteRole::Tested);
const QColor kSkipped = role(PaletteRole::Skipped);
const QColor kHit = role(PaletteRole::Hit);
const QColor kRay = colourOf(rayColour(RayKind::Primary));
}  // namespace

static QString roleName(PaletteRole r) {
    switch (r) {
        case PaletteRole::Visited:
            return View2D::tr("visited cell");
        case PaletteRole::Current:
            return View2D::tr("current cell or node");
        case PaletteRole::Tested:
            return View2D::tr("tested primitive");
        case PaletteRole::Skipped:
            return View2D::tr("skipped (mailbox)");
        case PaletteRole::Hit:
            return View2D::tr("nearest hit");
        case PaletteRole::Candidate:
            return View2D::tr("candidate plane");
        case PaletteRole::Chosen:
            return View2D::tr("chosen plane");
    }
    return {};
}

/// A role as the legend shows it, with its colour's name as the lessons write it.
static QString roleLabel(PaletteRole r, Language lang) {
    const std::string_view colour = roleColour(r).name(lang);
    return QStringLiteral("%1 (%2)").arg(roleName(r),
                                         QString::fromUtf8(colour.data(), colour.size()));
}

View2D::View2D(Session& session, QWidget* parent) : QWidget(parent), session_(session) {
    // A click takes the keyboard from the answer box, so B, R and N reach the window.
    setFocusPolicy(Qt::ClickFocus);
    setMinimumSize(320, 220);
    setAutoFillBackground(false);
    connect(&session_, &Session::cursorChanged, this, [this] { update(); });
    connect(&session_, &Session::sceneChanged, this, [this] {
        layerDirty_ = true;
        update();
    });
    connect(&session_, &Session::logChanged, this, [this] {
        layerDirty_ = true;
        indexBuild();
    });
}

void View2D::fit() const {
    const Scene2D* s = session_.scene2D();
    world_ = s->bounds();
    if (s->exampleRay) world_.extend(s->exampleRay->origin);
    const Vec2 d = glm::max(world_.diagonal(), Vec2(1e-9));
    world_.lo -= 0.06 * d;
    world_.hi += 0.06 * d;
    const Vec2 size = world_.diagonal();
    // A build's replay keeps the bottom strip for the SAH cost chart.
    const double chart = session_.showingBuild() ? 130.0 : 0.0;
    // The legend keeps a strip on the right (when the view is wide enough to spare it).
    const double legend = width() > 560 ? legendWidth() + 12 : 0.0;
    scale_ = std::min((width() - 20 - legend) / size.x, (height() - 40 - chart) / size.y);
    offset_ = QPointF((width() - legend - scale_ * size.x) / 2,
                      chart + (height() - chart - scale_ * size.y) / 2);
}

QPointF View2D::toScreen(const Vec2& p) const {
    // y grows upwards in the scene, downwards on screen.
    return {offset_.x() + (p.x - world_.lo.x) * scale_,
            height() - offset_.y() - (p.y - world_.lo.y) * scale_};
}

Vec2 View2D::toWorld(QPointF p) const {
    return {world_.lo.x + (p.x() - offset_.x()) / scale_,
            world_.lo.y + (height() - offset_.y() - p.y()) / scale_};
}

std::optional<std::array<int, 2>> View2D::cellAt(QPointF widgetPoint) const {
    const Accelerator2D* accel = session_.accel2D();
    const auto* grid = accel ? std::get_if<UniformGridT<Scene2DPrims>>(accel) : nullptr;
    if (!grid || session_.showingBuild()) return std::nullopt;
    fit();
    const Vec2 w = toWorld(widgetPoint);
    const auto& spec = grid->spec();
    std::array<int, 2> c{};
    for (int a = 0; a < 2; ++a) {
        const double f = std::floor((w[a] - spec.lo[a]) / spec.cellSize(a));
        if (!(f >= 0 && f < spec.res[a])) return std::nullopt;
        c[a] = static_cast<int>(f);
    }
    return c;
}

QPointF View2D::cellCentre(int x, int y) const {
    const Accelerator2D* accel = session_.accel2D();
    const auto* grid = accel ? std::get_if<UniformGridT<Scene2DPrims>>(accel) : nullptr;
    if (!grid) return {};
    fit();
    const auto& spec = grid->spec();
    return toScreen(
        Vec2(spec.lo[0] + (x + 0.5) * spec.cellSize(0), spec.lo[1] + (y + 0.5) * spec.cellSize(1)));
}

void View2D::setSequence(const QList<QPoint>& cells) {
    sequence_ = cells;
    update();
}

void View2D::mousePressEvent(QMouseEvent* e) {
    if (const auto c = cellAt(e->position())) emit cellClicked((*c)[0], (*c)[1]);
}

void View2D::indexBuild() {
    // Once per log: where each split was chosen, and each node's parent (a build's replay).
    chosenAt_.clear();
    buildParent_.clear();
    splitOf_.clear();
    splitAt_.clear();
    if (!session_.showingBuild()) return;
    const auto& events = session_.log().events();
    const auto grow = [&](std::uint32_t node) {
        if (node >= buildParent_.size()) {
            buildParent_.resize(node + 1, kNoId);
            splitOf_.resize(node + 1, {-1, 0.0});
            splitAt_.resize(node + 1, 0);
        }
    };
    for (std::size_t i = 0; i < events.size(); ++i) {
        if (const auto* b = std::get_if<BuildNode>(&events[i])) {
            grow(b->node);
            buildParent_[b->node] = b->parent;
        } else if (const auto* c = std::get_if<SplitChosen>(&events[i])) {
            grow(c->node);
            splitOf_[c->node] = {c->axis, c->position};
            splitAt_[c->node] = i;
            chosenAt_.push_back(i);
        }
    }
}

void View2D::paintEvent(QPaintEvent*) {
    QPainter g(this);
    g.setRenderHint(QPainter::Antialiasing);
    g.fillRect(rect(), kBackground);
    const Scene2D* s = session_.scene2D();
    if (!s) {
        g.drawText(rect(), Qt::AlignCenter, tr("The 2D view shows the lecture's 2D scenes."));
        return;
    }
    fit();
    const ReplayState& st = session_.state();

    // The structure's cells: the grid, or the tree's boxes.
    const Accelerator2D* accel = session_.accel2D();
    const auto* grid = accel ? std::get_if<UniformGridT<Scene2DPrims>>(accel) : nullptr;
    const auto cellRect = [&](const std::array<std::int32_t, 3>& c) {
        const auto& spec = grid->spec();
        const Vec2 lo(spec.lo.x + c[0] * spec.cellSize(0), spec.lo.y + c[1] * spec.cellSize(1));
        const Vec2 hi(lo.x + spec.cellSize(0), lo.y + spec.cellSize(1));
        return QRectF(toScreen(Vec2(lo.x, hi.y)), toScreen(Vec2(hi.x, lo.y)));
    };
    const auto* kd = accel ? std::get_if<KdTree<Scene2DPrims>>(accel) : nullptr;
    if (layerDirty_ || layerSize_ != size()) buildLayer(grid, kd);
    // What moves with the cursor goes under the cached lines: visited and current cells, the
    // tree node being entered.
    if (grid) {
        for (const auto& c : st.visitedCells) g.fillRect(cellRect(c), kVisited);
        if (st.ddaCell) g.fillRect(cellRect(st.ddaCell->cell), kCurrent);
    } else if (kd && st.node && st.node->node < kdBoxes_.size()) {
        const BoxN<2>& box = kdBoxes_[st.node->node];
        g.fillRect(QRectF(toScreen(Vec2(box.lo.x, box.hi.y)), toScreen(Vec2(box.hi.x, box.lo.y))),
                   role(PaletteRole::Current, 110));
    }

    // A build being replayed: the node being split, the candidate planes so far, the choice.
    const bool build = session_.showingBuild();
    if (build) {
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
        g.setPen(QPen(QColor(90, 90, 100), 1.5));
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
    }
    if (build && st.buildNode && st.buildNode->node < session_.log().nodes().size()) {
        const NodeRecord& n = session_.log().nodes()[st.buildNode->node];
        const QRectF box(toScreen(Vec2(n.lo[0], n.hi[1])), toScreen(Vec2(n.hi[0], n.lo[1])));
        g.fillRect(box, role(PaletteRole::Current, 50));
        g.setPen(QPen(role(PaletteRole::Current), 2));
        g.drawRect(box);
        // The most recent candidates (a big node has thousands; the chart shows them all).
        constexpr std::size_t kShown = 256;
        const std::size_t from = st.candidates.size() > kShown ? st.candidates.size() - kShown : 0;
        g.setPen(QPen(role(PaletteRole::Candidate, 110), 1));  // solid: dashes rasterize slowly
        for (std::size_t k = from; k < st.candidates.size(); ++k) {
            const SplitCandidate& c = st.candidates[k];
            const Vec2 a = c.axis == 0 ? Vec2(c.position, n.lo[1]) : Vec2(n.lo[0], c.position);
            const Vec2 b = c.axis == 0 ? Vec2(c.position, n.hi[1]) : Vec2(n.hi[0], c.position);
            g.drawLine(toScreen(a), toScreen(b));
        }
        if (st.chosen) {
            g.setPen(QPen(role(PaletteRole::Chosen), 3));
            const auto& c = *st.chosen;
            const Vec2 a = c.axis == 0 ? Vec2(c.position, n.lo[1]) : Vec2(n.lo[0], c.position);
            const Vec2 b = c.axis == 0 ? Vec2(c.position, n.hi[1]) : Vec2(n.hi[0], c.position);
            g.drawLine(toScreen(a), toScreen(b));
        }
    }

    // Primitives: tested ones orange, skipped by the mailbox grey, the nearest hit green.
    const auto colourOf = [&](std::uint32_t p) {
        if (st.nearestT && st.nearestPrim == p) return kHit;
        for (auto q : st.mailboxSkips)
            if (q == p) return kSkipped;
        for (const auto& t : st.tests)
            if (t.prim == p) return kTested;
        return kPrimitive;
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
        g.setPen(QPen(colourOf(p), p == st.nearestPrim ? 3.0 : 2.0));
        drawPrimitive(g, p);
    }

    // The ray: faint in full, solid up to where the replay has reached.
    if (!build && !session_.log().rays().empty()) {
        const RayRecord& r = session_.log().rays().front();
        const Vec2 o(r.origin.x, r.origin.y), d(r.dir.x, r.dir.y);
        const double tFar = (world_.diagonal().x + world_.diagonal().y) / glm::length(d);
        g.setPen(QPen(QColor(kRay.red(), kRay.green(), kRay.blue(), 70), 1.5, Qt::DashLine));
        g.drawLine(toScreen(o), toScreen(o + tFar * d));
        double reached = 0.0;
        if (st.ddaCell) reached = std::min(st.ddaCell->tMax[0], st.ddaCell->tMax[1]);
        if (st.node) reached = std::max(reached, st.node->tFar);
        if (st.nearestT && (st.hit || st.missed)) reached = *st.nearestT;
        if (std::isfinite(reached) && reached > 0) {
            g.setPen(QPen(kRay, 2.5));
            g.drawLine(toScreen(o), toScreen(o + reached * d));
        }
        g.setBrush(kRay);
        g.drawEllipse(toScreen(o), 4, 4);
        // tMax as labelled ticks on the ray.
        if (st.ddaCell) {
            const Vec2 n = glm::normalize(Vec2(-d.y, d.x));
            for (int axis = 0; axis < 2; ++axis) {
                const double t = st.ddaCell->tMax[axis];
                if (!std::isfinite(t)) continue;
                const Vec2 p = o + t * d;
                const QPointF a = toScreen(p + 0.12 * n), b = toScreen(p - 0.12 * n);
                g.setPen(QPen(axis == 0 ? QColor(30, 90, 200) : QColor(140, 40, 170), 2));
                g.drawLine(a, b);
                g.drawText(a + QPointF(4, -4),
                           (axis == 0 ? QStringLiteral("tMaxX = %1") : QStringLiteral("tMaxY = %1"))
                               .arg(numberText(t, 'g', 4)));
                // tDelta: the stretch of ray between two boundaries of this axis, drawn as a
                // bracket ending at tMax, on the axis's side of the ray.
                if (st.ddaSetup && std::isfinite(st.ddaSetup->tDelta[axis])) {
                    const double d0 = std::max(0.0, t - st.ddaSetup->tDelta[axis]);
                    const Vec2 side = (axis == 0 ? 0.22 : -0.22) * n;
                    const QPointF p0 = toScreen(o + d0 * d + side), p1 = toScreen(p + side);
                    g.setPen(QPen(g.pen().color(), 1));
                    g.drawLine(p0, p1);
                    g.drawLine(p0, toScreen(o + d0 * d + 0.6 * side));
                    g.drawLine(p1, toScreen(p + 0.6 * side));
                    g.drawText((p0 + p1) / 2 + (axis == 0 ? QPointF(-20, -6) : QPointF(4, 14)),
                               axis == 0 ? QStringLiteral("tDeltaX") : QStringLiteral("tDeltaY"));
                }
            }
        }
        if (st.nearestT) {
            g.setBrush(kHit);
            g.setPen(Qt::NoPen);
            g.drawEllipse(toScreen(o + *st.nearestT * d), 5, 5);
        }
    }
    if (build) drawCostChart(g, st);
    if (grid && !build) {
        // A sequence answer: each clicked cell with its place in the order, over the picture.
        g.setFont([&] {
            QFont f = g.font();
            f.setBold(true);
            f.setPointSizeF(f.pointSizeF() * 1.3);
            return f;
        }());
        for (int k = 0; k < sequence_.size(); ++k) {
            const QRectF cell = cellRect({sequence_[k].x(), sequence_[k].y(), 0}).normalized();
            const double r = std::min(cell.width(), cell.height()) * 0.22;
            const QPointF c = cell.center() + QPointF(cell.width() * 0.25, -cell.height() * 0.25);
            g.setPen(QPen(QColor(30, 30, 30), 1.5));
            g.setBrush(QColor(255, 255, 255, 230));
            g.drawEllipse(c, r, r);
            g.drawText(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r), Qt::AlignCenter,
                       QString::number(k + 1));
        }
        g.setFont(font());
    }
    drawLegend(g, build);
    g.setPen(QColor(60, 60, 60));
    g.drawText(QRectF(8, 6, width() - 16, 20), Qt::AlignLeft,
               QString::fromStdString(session_.name()) + QStringLiteral("  -  ") +
                   structureName(session_.kind()));
}

double View2D::legendWidth() const {
    double w = 0;
    for (int r = 0; r < kPaletteRoleCount; ++r)
        w = std::max<double>(w, fontMetrics().horizontalAdvance(roleLabel(PaletteRole(r), lang_)));
    return w + 14 + 16;
}

void View2D::drawLegend(QPainter& g, bool build) const {
    // The colour roles this picture uses, from the palette (the lessons name the same colours).
    std::vector<std::pair<QColor, QString>> rows;
    if (build) {
        rows = {{role(PaletteRole::Current), roleLabel(PaletteRole::Current, lang_)},
                {role(PaletteRole::Candidate), roleLabel(PaletteRole::Candidate, lang_)},
                {role(PaletteRole::Chosen), roleLabel(PaletteRole::Chosen, lang_)}};
    } else {
        rows = {{kRay, QStringLiteral("%1 (%2)").arg(
                           tr("the ray"),
                           QString::fromUtf8(rayColour(RayKind::Primary).name(lang_).data()))}};
        rows.emplace_back(kVisited, roleLabel(PaletteRole::Visited, lang_));
        rows.emplace_back(kCurrent, roleLabel(PaletteRole::Current, lang_));
        for (PaletteRole r : {PaletteRole::Tested, PaletteRole::Skipped, PaletteRole::Hit})
            rows.emplace_back(role(r), roleLabel(r, lang_));
    }
    const QFontMetrics fm(g.font());
    const double row = fm.height() + 2, swatch = 14;
    double w = 0;
    for (const auto& r : rows) w = std::max<double>(w, fm.horizontalAdvance(r.second));
    const QRectF box(width() - (w + swatch + 22), 28, w + swatch + 16, row * rows.size() + 8);
    g.save();
    g.setPen(QColor(200, 200, 200));
    g.setBrush(QColor(255, 255, 255, 225));
    g.drawRoundedRect(box, 4, 4);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const double y = box.top() + 4 + row * k;
        g.setPen(Qt::NoPen);
        g.setBrush(rows[k].first);
        g.drawRect(QRectF(box.left() + 6, y + (row - swatch) / 2, swatch, swatch));
        g.setPen(QColor(40, 40, 40));
        g.drawText(QRectF(box.left() + 10 + swatch, y, w + 4, row),
                   Qt::AlignLeft | Qt::AlignVCenter, rows[k].second);
    }
    g.restore();
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

void View2D::buildLayer(const UniformGridT<Scene2DPrims>* grid, const KdTree<Scene2DPrims>* kd) {
    const Scene2D* s = session_.scene2D();
    layer_ = QPixmap(size());
    layer_.fill(Qt::transparent);
    QPainter lp(&layer_);
    lp.setRenderHint(QPainter::Antialiasing, s->primitiveCount() < 5000);
    if (grid) {
        const auto& spec = grid->spec();
        lp.setPen(QPen(kGridLine, 1));
        for (int i = 0; i <= spec.res.x; ++i) {
            const double x = spec.lo.x + i * spec.cellSize(0);
            lp.drawLine(toScreen(Vec2(x, spec.lo.y)), toScreen(Vec2(x, spec.hi.y)));
        }
        for (int j = 0; j <= spec.res.y; ++j) {
            const double y = spec.lo.y + j * spec.cellSize(1);
            lp.drawLine(toScreen(Vec2(spec.lo.x, y)), toScreen(Vec2(spec.hi.x, y)));
        }
        // Cell indices along the edges, as on the board.
        lp.setPen(QColor(120, 120, 120));
        for (int i = 0; i < spec.res.x; ++i)
            lp.drawText(toScreen(Vec2(spec.lo.x + (i + 0.45) * spec.cellSize(0), spec.lo.y)) +
                            QPointF(-3, 14),
                        QString::number(i));
        for (int j = 0; j < spec.res.y; ++j)
            lp.drawText(toScreen(Vec2(spec.lo.x, spec.lo.y + (j + 0.5) * spec.cellSize(1))) +
                            QPointF(-14, 4),
                        QString::number(j));
    }
    kdBoxes_.clear();
    if (kd && !kd->nodes().empty()) {
        // Every node's box (for the node being entered) and the split lines.
        kdBoxes_.resize(kd->nodes().size());
        lp.setPen(QPen(kGridLine, 1));
        kd->forEachNode([&](std::uint32_t id, const KdNode& n, const BoxN<2>& box) {
            kdBoxes_[id] = box;
            if (n.leaf()) return;
            const Vec2 a = n.axis == 0 ? Vec2(n.split, box.lo.y) : Vec2(box.lo.x, n.split);
            const Vec2 b = n.axis == 0 ? Vec2(n.split, box.hi.y) : Vec2(box.hi.x, n.split);
            // A build's replay draws only the planes chosen so far (paintEvent), not the answer.
            if (!session_.showingBuild()) lp.drawLine(toScreen(a), toScreen(b));
        });
    }
    lp.setPen(QPen(kPrimitive, 2.0));
    for (std::uint32_t p = 0; p < s->primitiveCount(); ++p) drawPrimitive(lp, p);
    layerSize_ = size();
    layerDirty_ = false;
}

void View2D::drawCostChart(QPainter& g, const ReplayState& st) const {
    // The SAH cost of each candidate against its place in the node, one curve per axis, with
    // the leaf's cost (not splitting) dashed and the chosen plane marked.
    if (st.candidates.empty() || !st.buildNode) return;
    const NodeRecord& n = session_.log().nodes()[st.buildNode->node];
    const QRectF chart(12, height() - 122, std::min(520, width() - 24), 112);
    g.fillRect(chart, QColor(255, 255, 255, 230));
    g.setPen(QColor(150, 150, 150));
    g.drawRect(chart);
    double lo = kInfinity, hi = 0.0;
    for (const SplitCandidate& c : st.candidates)
        lo = std::min(lo, c.sahCost), hi = std::max(hi, c.sahCost);
    const double leaf = st.chosen ? st.chosen->leafCost : st.buildNode->prims * 5.0;
    hi = std::max(hi, leaf) * 1.05;
    lo = std::min(lo, leaf) * 0.95;
    const auto at = [&](int axis, double pos, double cost) {
        const double f = (pos - n.lo[axis]) / std::max(n.hi[axis] - n.lo[axis], 1e-300);
        return QPointF(
            chart.left() + 6 + f * (chart.width() - 12),
            chart.bottom() - 6 - (cost - lo) / std::max(hi - lo, 1e-300) * (chart.height() - 22));
    };
    const QColor axisColour[2] = {QColor(30, 90, 200), QColor(140, 40, 170)};
    // At most about 2,000 points a curve: a screen has no more columns to show.
    const std::size_t stride = std::max<std::size_t>(1, st.candidates.size() / 2000);
    for (int axis = 0; axis < 2; ++axis) {
        QPolygonF line;
        for (std::size_t k = 0; k < st.candidates.size(); k += stride) {
            const SplitCandidate& c = st.candidates[k];
            if (c.axis == axis) line << at(axis, c.position, c.sahCost);
        }
        g.setPen(QPen(axisColour[axis], 1.5));
        g.drawPolyline(line);
        if (line.size() < 200)
            for (const QPointF& p : line) g.drawEllipse(p, 2, 2);
    }
    g.setPen(QPen(QColor(90, 90, 90), 1, Qt::DashLine));
    const double yLeaf = at(0, n.lo[0], leaf).y();
    g.drawLine(QPointF(chart.left(), yLeaf), QPointF(chart.right(), yLeaf));
    if (st.chosen) {
        g.setPen(Qt::NoPen);
        g.setBrush(role(PaletteRole::Chosen));
        g.drawEllipse(at(st.chosen->axis, st.chosen->position, st.chosen->sahCost), 4, 4);
    }
    g.setPen(QColor(60, 60, 60));
    g.drawText(chart.adjusted(6, 2, -6, 0), Qt::AlignLeft | Qt::AlignTop,
               tr("SAH cost of each candidate (X blue, Y purple; dashed: leaf)"));
}

}  // namespace raystep::gui
