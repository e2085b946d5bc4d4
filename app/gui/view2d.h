#pragma once
// The lecture's 2D picture at the replay cursor: the grid (or the tree's cells), the primitives,
// the ray, the current and visited cells, tMax and tDelta as labelled ticks on the ray, mailbox
// skips and the nearest hit so far.
#include "session.h"

#include <QPainter>
#include <QPixmap>
#include <QWidget>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace raystep::gui {

class View2D : public QWidget {
    Q_OBJECT
  public:
    explicit View2D(Session& session, QWidget* parent = nullptr);
    QSize sizeHint() const override { return {640, 440}; }
    /// The grid cell under a widget point, if the structure is a grid and the point is on it.
    std::optional<std::array<int, 2>> cellAt(QPointF widgetPoint) const;
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
