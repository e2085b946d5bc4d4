#pragma once
// The lecture's 2D picture at the replay cursor: the grid (or the tree's cells), the primitives,
// the ray, the current and visited cells, tMax and tDelta as labelled ticks on the ray, mailbox
// skips and the nearest hit so far.
#include "session.h"

#include <QPainter>
#include <QPixmap>
#include <QWidget>

namespace raystep::gui {

class View2D : public QWidget {
    Q_OBJECT
  public:
    explicit View2D(Session& session, QWidget* parent = nullptr);
    QSize sizeHint() const override { return {640, 440}; }

  protected:
    void paintEvent(QPaintEvent*) override;

  private:
    QPointF toScreen(const Vec2& p) const;
    void drawCostChart(QPainter& g, const ReplayState& st) const;
    void fit();

    /// The structure's lines and the primitives in their neutral colour, drawn once per size and
    /// scene (thousands of segments and tree nodes would otherwise cost most of every frame).
    void buildLayer(const UniformGridT<Scene2DPrims>* grid, const KdTree<Scene2DPrims>* kd);
    void drawPrimitive(QPainter& painter, std::uint32_t prim) const;

    Session& session_;
    QPixmap layer_;
    QSize layerSize_;
    bool layerDirty_ = true;
    std::vector<BoxN<2>> kdBoxes_;  // every kd node's box, made with the layer
    BoxN<2> world_;                 // what is shown, in scene units
    double scale_ = 1.0;
    QPointF offset_;
};

}  // namespace raystep::gui
