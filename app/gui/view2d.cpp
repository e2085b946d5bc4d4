// The 2D view's frame: the scene-to-widget mapping (fit, toScreen, toWorld), the cells a click
// names, and the order a frame is painted in. What each part draws is in a file of its own:
// view2d_structure.cpp (the grid, the tree's cells and planes, a build's replay), view2d_ray.cpp
// (the ray, its hits, the DDA's tMax and tDelta), view2d_chart.cpp (the SAH cost chart),
// view2d_legend.cpp (the caption and the legend); view2d_interaction.cpp takes the mouse.
#include "view2d.h"

#include "view2d_paint.h"

#include "presentation.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace raystep::gui {

using namespace draw2d;

View2D::View2D(Session& session, QWidget* parent) : QWidget(parent), session_(session) {
    // A click takes the keyboard from the answer box, so B, R and N reach the window.
    setFocusPolicy(Qt::ClickFocus);
    setMinimumSize(320, 220);
    setAutoFillBackground(false);
    connect(&session_, &Session::cursorChanged, this, [this] { update(); });
    connect(&session_, &Session::sceneChanged, this, [this] {
        layerDirty_ = true;
        sceneShown();
        update();
    });
    connect(&session_, &Session::logChanged, this, [this] {
        layerDirty_ = true;
        indexBuild();
    });
    connect(&session_, &Session::limitChanged, this, [this] {
        layerDirty_ = true;  // the tree's planes are drawn or not with the hold
        update();
    });
    // Presenter mode: the labels' font (zoomed, larger), line widths and palette.
    const auto restyle = [this] {
        setFont(presentation().labelFont());
        layerDirty_ = true;
        update();
    };
    restyle();
    connect(&presentation(), &Presentation::changed, this, restyle);
}

void View2D::fit() const {
    // The fitted box is kept until another scene is shown (or Fit): a live edit does not move
    // the picture under the mouse.
    if (needFit_) {
        const Scene2D* s = session_.scene2D();
        world_ = s->bounds();
        if (const auto ray = shownRay()) world_.extend(ray->origin);
        const Vec2 d = glm::max(world_.diagonal(), Vec2(1e-9));
        world_.lo -= 0.04 * d;  // the labels have room of their own (below)
        world_.hi += 0.04 * d;
        needFit_ = false;
    }
    const Vec2 size = world_.diagonal();
    const QFontMetricsF fm(font());
    // Room for the labels around the picture, as large as their font (the zoom's): the caption
    // over it, the cell indices under it and left of it.
    const double top =
        (captionShown_ ? QFontMetricsF(presentation().captionFont()).height() + 10 : 6) + 2;
    const double bottom = fm.height() + 8, left = fm.horizontalAdvance(QStringLiteral("00")) + 12;
    const double right = 10;
    // A build's replay keeps the bottom strip for the SAH cost chart, and a left one for its
    // cost axis' values (the chart's position axis is the view's own x). Both at most a share of
    // the view: on a laptop, or zoomed, the chart shrinks, not the scene (which it explains).
    const bool build = session_.showingBuild();
    const double chart = build ? chartStrip() : 0.0;
    const double axis = chart > 0 ? std::min(chartAxisRoom(fm), 0.2 * width()) : 0.0;
    const double roomX = std::max(1.0, width() - left - right - axis),
                 roomY = std::max(1.0, height() - top - bottom - chart);
    // The legend: a column on the right, or rows over the picture under the caption, whichever
    // leaves the picture larger (a scene bound by the view's height has room at its side, one
    // bound by the width above it).
    legend_ = {};
    double legendW = 0.0, legendH = 0.0;
    if (legendShown_) {
        const auto rows = legendRows(build);
        const QFontMetricsF lm(presentation().captionFont());
        const double row = lm.height() + 2, swatch = lm.height() - 2;
        double widest = 0;
        for (const auto& r : rows) widest = std::max(widest, lm.horizontalAdvance(r.second));
        const double entry = swatch + 10 + widest;  // one entry's width in the column
        const double sideW = entry + 12 + 12;
        const double sideScale = std::min((roomX - sideW) / size.x, roomY / size.y);
        // The rows: entries side by side, as many to a line as `across` holds; beside the
        // caption if it is short enough, else under it.
        const auto flowIn = [&](double across, double& boxW) {
            std::vector<QRectF> flow;
            double x = 0, line = 0;
            boxW = 0;
            for (const auto& r : rows) {
                const double w = swatch + 10 + lm.horizontalAdvance(r.second) + 14;
                if (x > 0 && x + w > across) x = 0, ++line;
                flow.emplace_back(x, line * row, w, row);
                x += w;
                boxW = std::max(boxW, x);
            }
            return flow;
        };
        const QFontMetricsF cm(presentation().captionFont());
        const double captionW = captionShown_ ? cm.horizontalAdvance(captionText()) + 24 : 0.0;
        double besideW = 0, underW = 0;
        const auto beside = flowIn(width() - 28 - captionW, besideW);
        const auto under = flowIn(width() - 28, underW);
        const double besideH = beside.back().bottom() + 8;
        const double underH = under.back().bottom() + 8;
        // Beside the caption the box starts where the caption does; what it adds is what it
        // reaches below the room kept for the caption.
        const double besideCost = std::max(0.0, 4 + besideH + 6 - top);
        const double underCost = underH + 6;
        const bool besideCaption = besideW <= width() - 28 - captionW && besideCost <= underCost;
        const auto& flow = besideCaption ? beside : under;
        const double flowW = besideCaption ? besideW : underW,
                     flowH = besideCaption ? besideH : underH;
        const double topH = besideCaption ? besideCost : underCost;
        const double topScale = std::min(roomX / size.x, (roomY - topH) / size.y);
        // The column unless the rows leave the picture clearly larger (the column is the usual
        // look; they are near equal on a wide view).
        legend_.inRows = topScale > 1.04 * sideScale;
        const double boxTop = top - 2;
        if (legend_.inRows) {
            const double y = besideCaption ? 4.0 : boxTop;
            legend_.box = QRectF(width() - 8 - (flowW + 12), y, flowW + 12, flowH);
            for (const QRectF& f : flow)
                legend_.entries.push_back(f.translated(legend_.box.left() + 6, y + 4));
            legendH = topH;
        } else {
            legend_.box =
                QRectF(width() - 8 - (entry + 12), boxTop, entry + 12, row * rows.size() + 8);
            for (std::size_t k = 0; k < rows.size(); ++k)
                legend_.entries.emplace_back(legend_.box.left() + 6, boxTop + 4 + row * k, entry,
                                             row);
            legendW = sideW;
        }
    }
    const double fitted = std::min((roomX - legendW) / size.x, (roomY - legendH) / size.y);
    // Then the user's zoom and pan (zoomAt keeps the point under the cursor in place).
    scale_ = fitted * zoom_;
    offset_ = QPointF(left + axis + (roomX - legendW - fitted * size.x) / 2,
                      bottom + chart + (roomY - legendH - fitted * size.y) / 2) +
              pan_;
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
    const OutlineGrid<2>* grid = shownGrid();
    if (!grid || session_.showingBuild()) return std::nullopt;
    fit();
    const auto c = grid->cellAt(toWorld(widgetPoint));
    if (!c) return std::nullopt;
    return std::array<int, 2>{(*c)[0], (*c)[1]};
}

QPointF View2D::cellCentre(int x, int y) const {
    const OutlineGrid<2>* grid = shownGrid();
    if (!grid) return {};
    fit();
    const auto& spec = grid->spec;
    return toScreen(
        Vec2(spec.lo[0] + (x + 0.5) * spec.cellSize(0), spec.lo[1] + (y + 0.5) * spec.cellSize(1)));
}

void View2D::setSequence(const QList<QPoint>& cells) {
    sequence_ = cells;
    update();
}

void View2D::setStudentWalk(std::optional<StudentWalk> walk) {
    student_ = std::move(walk);
    update();
}

bool View2D::showsStudentWalk() const {
    return student_ && student_->log && student_->log == session_.logRef();
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

QRectF View2D::cellRect(const OutlineGrid<2>& grid, const std::array<std::int32_t, 3>& c) const {
    const auto& spec = grid.spec;
    const Vec2 lo(spec.lo.x + c[0] * spec.cellSize(0), spec.lo.y + c[1] * spec.cellSize(1));
    const Vec2 hi(lo.x + spec.cellSize(0), lo.y + spec.cellSize(1));
    return QRectF(toScreen(Vec2(lo.x, hi.y)), toScreen(Vec2(hi.x, lo.y)));
}

void View2D::paintEvent(QPaintEvent*) {
    QPainter g(this);
    g.setRenderHint(QPainter::Antialiasing);
    g.fillRect(rect(), ink().background);
    const Scene2D* s = session_.scene2D();
    if (!s) {
        g.drawText(rect(), Qt::AlignCenter, tr("The 2D view shows the lecture's 2D scenes."));
        return;
    }
    fit();
    const ReplayState& st = session_.state();
    if (layerDirty_ || layerSize_ != size()) buildLayer();
    drawWalk(g, st);
    if (showsStudentWalk()) drawStudentWalk(g);
    const bool build = session_.showingBuild();
    if (build) drawBuildReplay(g, st);
    drawTouched(g, st);
    if (!build && !session_.log().rays().empty()) drawRay(g, st);
    if (build) drawCostChart(g, st);
    if (shownGrid() && !build) drawSequence(g);
    drawHandles(g);
    if (legendShown_) drawLegend(g, build);
    g.setPen(presentation().highContrast() ? QColor(0, 0, 0) : QColor(60, 60, 60));
    if (captionShown_) {
        g.setFont(presentation().captionFont());
        g.drawText(QRectF(8, 6, width() - 16, g.fontMetrics().height() + 2), Qt::AlignLeft,
                   captionText());
        g.setFont(font());
    }
}
}  // namespace raystep::gui
