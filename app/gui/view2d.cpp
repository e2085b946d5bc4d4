#include "view2d.h"

#include "course/palette.h"
#include "language.h"
#include "presentation.h"

#include <QMouseEvent>

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace raystep::gui {

namespace {
QColor colourOf(const PaletteColour& c, int alpha = 255) {
    return QColor(c.r, c.g, c.b, alpha);
}
// The roles' colours come from the one palette (course/palette.h), as the lessons name them.
QColor role(PaletteRole r, int alpha = 255) {
    return colourOf(roleColour(r), alpha);
}
/// The picture's colours as the palette (standard or high contrast) has them now.
struct Ink {
    QColor background, gridLine, primitive, label;
    QColor visited, current, tested, skipped, hit, ray;
};
Ink ink() {
    const bool high = presentation().highContrast();
    Ink k;
    // High contrast: a white page, darker lines and labels (a projector washes greys out).
    k.background = high ? QColor(255, 255, 255) : QColor(250, 250, 247);
    k.gridLine = high ? QColor(140, 140, 140) : QColor(200, 200, 200);
    k.primitive = high ? QColor(15, 15, 20) : QColor(60, 60, 70);  // ink, not a role
    k.label = high ? QColor(20, 20, 20) : QColor(120, 120, 120);
    // Visited cells as a light tint of the palette's colour, so the grid and labels stay readable.
    k.visited = role(PaletteRole::Visited, high ? 170 : 120);
    k.current = role(PaletteRole::Current, 200);
    k.tested = role(PaletteRole::Tested);
    k.skipped = role(PaletteRole::Skipped);
    k.hit = role(PaletteRole::Hit);
    k.ray = colourOf(rayColour(RayKind::Primary));
    return k;
}
/// A pen width (or a mark's radius) as drawn: wider in presenter mode.
double px(double width) {
    return width * presentation().lineScale();
}
// The cost chart: its strip under the picture and the room left of it for the cost values.
// Both grow with the label font (presenter mode, UI zoom): a plot about 116 px high between the
// title's row and two rows of values, and about four lines' height for a value like "0.1234".
constexpr double kChartPlot = 116;
double chartHeight(const QFontMetricsF& fm, double plot = kChartPlot) {
    return plot + (fm.height() + 14) + 2 * (fm.height() + 1) + 12;
}
double chartAxisRoom(const QFontMetricsF& fm) {
    return 4 * fm.height();
}
// The most of the view the chart's strip takes: the scene it explains keeps the rest.
constexpr double kChartShare = 0.42;
// Its X and Y curves in two of the palette's colours that no other part of the chart uses.
const PaletteColour& curveColour(int axis) {
    return rayColour(axis == 0 ? RayKind::Primary : RayKind::Diffuse);
}
}  // namespace

/// The legend's row for the ray: "the ray (orange-red)".
static QString rayLegendLabel(Language lang) {
    const std::string_view colour = rayColour(RayKind::Primary).name(lang);
    return QStringLiteral("%1 (%2)").arg(View2D::tr("the ray"),
                                         QString::fromUtf8(colour.data(), colour.size()));
}

static QString roleName(PaletteRole r) {
    switch (r) {
        case PaletteRole::Visited:
            return View2D::tr("visited");
        case PaletteRole::Current:
            return View2D::tr("current cell or node");
        case PaletteRole::Tested:
            return View2D::tr("tested primitive");
        case PaletteRole::Skipped:
            return View2D::tr("skipped");
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

QString View2D::captionText() const {
    return QString::fromStdString(session_.name()) + QStringLiteral("  -  ") +
           structureName(session_.kind());
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

double View2D::chartStrip() const {
    const QFontMetricsF fm(font());
    const double strip = std::min(chartHeight(fm), kChartShare * height());
    // A plot too low for three of its cost values is not drawn: the scene keeps that room too.
    return strip - chartHeight(fm, 0) >= 3 * (fm.height() + 6) ? strip : 0.0;
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
    const Ink ink = raystep::gui::ink();
    const QFontMetricsF fm(font());
    g.fillRect(rect(), ink.background);
    const Scene2D* s = session_.scene2D();
    if (!s) {
        g.drawText(rect(), Qt::AlignCenter, tr("The 2D view shows the lecture's 2D scenes."));
        return;
    }
    fit();
    const ReplayState& st = session_.state();

    // The structure's cells: the grid, or the tree's boxes.
    const StructureOutline<2>* outline = session_.outline2D();
    const OutlineGrid<2>* grid = shownGrid();
    const auto cellRect = [&](const std::array<std::int32_t, 3>& c) {
        const auto& spec = grid->spec;
        const Vec2 lo(spec.lo.x + c[0] * spec.cellSize(0), spec.lo.y + c[1] * spec.cellSize(1));
        const Vec2 hi(lo.x + spec.cellSize(0), lo.y + spec.cellSize(1));
        return QRectF(toScreen(Vec2(lo.x, hi.y)), toScreen(Vec2(hi.x, lo.y)));
    };
    if (layerDirty_ || layerSize_ != size()) buildLayer();
    // What moves with the cursor goes under the cached lines: visited and current cells, the
    // tree node being entered.
    if (grid) {
        for (const auto& c : st.visitedCells) g.fillRect(cellRect(c), ink.visited);
        if (st.ddaCell) g.fillRect(cellRect(st.ddaCell->cell), ink.current);
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
    }
    if (build && st.buildNode && st.buildNode->node < session_.log().nodes().size()) {
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

    // The ray: faint in full, solid up to where the replay has reached.
    if (!build && !session_.log().rays().empty()) {
        const RayRecord& r = session_.log().rays().front();
        const Vec2 o(r.origin.x, r.origin.y), d(r.dir.x, r.dir.y);
        // Far enough to leave the visible part, whatever the zoom and pan.
        const Vec2 seen = toWorld(QPointF(width(), 0)) - toWorld(QPointF(0, height()));
        const double tFar =
            (glm::length(seen) + glm::length(toWorld(rect().center()) - o)) / glm::length(d);
        g.setPen(QPen(QColor(ink.ray.red(), ink.ray.green(), ink.ray.blue(), 70), px(1.5),
                      Qt::DashLine));
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
            g.setPen(QPen(QColor(30, 30, 30), px(1.5)));
            g.setBrush(QColor(255, 255, 255, 230));
            g.drawEllipse(c, r, r);
            g.drawText(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r), Qt::AlignCenter,
                       QString::number(k + 1));
        }
        g.setFont(font());
    }
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

std::vector<std::pair<QColor, QString>> View2D::legendRows(bool build) const {
    // The colour roles this picture uses, from the palette (the lessons name the same colours).
    if (build)
        return {{role(PaletteRole::Current), roleLabel(PaletteRole::Current, lang_)},
                {role(PaletteRole::Candidate), roleLabel(PaletteRole::Candidate, lang_)},
                {role(PaletteRole::Chosen), roleLabel(PaletteRole::Chosen, lang_)}};
    std::vector<std::pair<QColor, QString>> rows{{ink().ray, rayLegendLabel(lang_)}};
    rows.emplace_back(ink().visited, roleLabel(PaletteRole::Visited, lang_));
    rows.emplace_back(ink().current, roleLabel(PaletteRole::Current, lang_));
    for (PaletteRole r : {PaletteRole::Tested, PaletteRole::Skipped, PaletteRole::Hit})
        rows.emplace_back(role(r), roleLabel(r, lang_));
    return rows;
}

void View2D::drawLegend(QPainter& g, bool build) const {
    // Where fit() laid it out: a column on the right or rows under the caption.
    const auto rows = legendRows(build);
    if (rows.size() != legend_.entries.size()) return;
    g.save();
    g.setFont(presentation().captionFont());
    const QFontMetricsF fm(g.font());
    const double swatch = fm.height() - 2;
    g.setPen(QColor(200, 200, 200));
    g.setBrush(QColor(255, 255, 255, 225));
    g.drawRoundedRect(legend_.box, 4, 4);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const QRectF& e = legend_.entries[k];
        g.setPen(Qt::NoPen);
        g.setBrush(rows[k].first);
        g.drawRect(QRectF(e.left(), e.center().y() - swatch / 2, swatch, swatch));
        g.setPen(presentation().highContrast() ? QColor(0, 0, 0) : QColor(40, 40, 40));
        g.drawText(QRectF(e.left() + swatch + 6, e.top(), e.width() - swatch - 6, e.height()),
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
    const Ink ink = raystep::gui::ink();
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
