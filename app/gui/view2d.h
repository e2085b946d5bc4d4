#pragma once
// The lecture's 2D picture at the replay cursor: the grid (or the tree's cells), the primitives,
// the ray, the current and visited cells, tMax and tDelta as labelled ticks on the ray, mailbox
// skips and the nearest hit so far.
#include "session.h"

#include "raystep/base/i18n.h"

#include <QPainter>
#include <QPixmap>
#include <QWidget>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace raystep::gui {

/// The SAH cost chart under a build's replay, as drawn: its axes, in widget pixels. The split
/// position runs along x at the view's own scale, from the node's left edge, so the X curve lies
/// under the candidate planes above it; the cost runs up.
struct CostChart {
    QRectF plot;                                       // where the curves are drawn
    double costLo = 0, costHi = 1;                     // the cost axis' range, bottom to top
    std::vector<double> costTicks;                     // labelled values on the cost axis
    std::array<std::vector<double>, 2> positionTicks;  // per axis (empty: no candidate on it)
    std::array<double, 2> nodeLo{};  // the node's low edge per axis: at plot.left()
    double scale = 1;                // pixels per scene unit, the view's
    double leafCost = 0;             // not splitting (dashed)
    QPointF at(int axis, double position, double cost) const {
        return {plot.left() + (position - nodeLo[axis]) * scale,
                plot.bottom() - (cost - costLo) / (costHi - costLo) * plot.height()};
    }
};

/// Round tick values (1, 2 or 5 times a power of ten apart) covering [lo, hi], at most about
/// `count` of them, all inside the range.
std::vector<double> niceTicks(double lo, double hi, int count);

class View2D : public QWidget {
    Q_OBJECT
  public:
    explicit View2D(Session& session, QWidget* parent = nullptr);
    QSize sizeHint() const override { return {640, 440}; }
    /// The grid cell under a widget point, if the structure is a grid and the point is on it.
    std::optional<std::array<int, 2>> cellAt(QPointF widgetPoint) const;
    /// The legend's language (its colour names are the lessons').
    void setLanguage(Language lang) {
        lang_ = lang;
        update();
    }
    /// Whether the scene's name and the colour legend are drawn (compare mode's three views
    /// have their own titles and show one legend).
    void setOverlays(bool caption, bool legend) {
        captionShown_ = caption;
        legendShown_ = legend;
        update();
    }
    /// The cost chart at the replay's cursor (a build's replay with candidates), else nullopt.
    std::optional<CostChart> costChart() const;
    /// Where the scene point `p` is drawn (tests line the chart up with the node).
    QPointF screenOf(const Vec2& p) const {
        fit();
        return toScreen(p);
    }
    /// Where the centre of grid cell (x, y) is drawn (tests click there).
    QPointF cellCentre(int x, int y) const;

  public slots:
    /// The cells a student has clicked for a sequence exercise, numbered in order on the grid.
    void setSequence(const QList<QPoint>& cells);

  signals:
    /// A click on a grid cell (the lessons' "predict the next cell", "order the cells").
    void cellClicked(int x, int y);

  protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;

  private:
    QPointF toScreen(const Vec2& p) const;
    Vec2 toWorld(QPointF p) const;
    void drawCostChart(QPainter& g, const ReplayState& st) const;
    /// The colour roles of the picture (the palette's), top right.
    void drawLegend(QPainter& g, bool build) const;
    double legendWidth() const;
    void fit() const;  // the scene-to-widget mapping for the current size

    /// The structure's lines and the primitives in their neutral colour, drawn once per size and
    /// scene (thousands of segments and tree nodes would otherwise cost most of every frame).
    void buildLayer(const UniformGridT<Scene2DPrims>* grid, const KdTree<Scene2DPrims>* kd);
    void drawPrimitive(QPainter& painter, std::uint32_t prim) const;
    /// A build's replay: where each split was chosen and each node's parent, once per log.
    void indexBuild();

    Session& session_;
    QList<QPoint> sequence_;  // a sequence answer's cells, in the order clicked
    Language lang_ = Language::En;
    bool legendShown_ = true, captionShown_ = true;
    QPixmap layer_;
    QSize layerSize_;
    bool layerDirty_ = true;
    std::vector<BoxN<2>> kdBoxes_;                      // every kd node's box, made with the layer
    static constexpr std::size_t kAllSplitsUpTo = 256;  // as many lines as the candidates shown
    std::vector<std::size_t> chosenAt_;  // event indices of the SplitChosen events, in order
    std::vector<std::uint32_t> buildParent_;
    std::vector<std::pair<int, double>> splitOf_;  // per node: axis (-1: none) and position
    std::vector<std::size_t> splitAt_;             // per node: the event that chose its split
    mutable BoxN<2> world_;                        // what is shown, in scene units
    mutable double scale_ = 1.0;
    mutable QPointF offset_;
};

}  // namespace raystep::gui
