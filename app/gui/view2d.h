#pragma once
// The lecture's 2D picture at the replay cursor: the grid (or the tree's cells), the primitives,
// the ray, the current and visited cells, tMax and tDelta as labelled ticks on the ray, mailbox
// skips and the nearest hit so far.
#include "session.h"

#include "raystep/accel/outline.h"

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
    double leafCost = 0;             // not splitting (dashed): C_isect N; NaN if not known
    QPointF at(int axis, double position, double cost) const {
        return {plot.left() + (position - nodeLo[axis]) * scale,
                plot.bottom() - (cost - costLo) / (costHi - costLo) * plot.height()};
    }
};

/// Round tick values (1, 2 or 5 times a power of ten apart) covering [lo, hi], at most about
/// `count` of them, all inside the range.
std::vector<double> niceTicks(double lo, double hi, int count);

class Live2D;

/// A student's walk drawn over raystep's (File > Open student trace, assess_controller.h): their
/// cells or nodes in the order logged, and the first that differs from raystep's.
struct StudentWalk {
    LogRef log;  // raystep's run of the same ray: the walk is drawn while that log is replayed
    std::vector<std::array<std::int32_t, 3>> cells;  // a grid's walk
    std::vector<std::uint32_t> nodes;                // a tree's (the reference's numbering)
    std::optional<std::size_t> divergent;            // into cells or nodes; none: all agree
};

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
    /// The legend's rows: each role's colour and name, for a build's replay or a ray's (compare
    /// mode shows them once, under its views).
    std::vector<std::pair<QColor, QString>> legendRows(bool build) const;
    /// The cost chart at the replay's cursor (a build's replay with candidates), else nullopt.
    std::optional<CostChart> costChart() const;
    /// Where the scene point `p` is drawn (tests line the chart up with the node).
    QPointF screenOf(const Vec2& p) const {
        fit();
        return toScreen(p);
    }
    /// Where the centre of grid cell (x, y) is drawn (tests click there).
    QPointF cellCentre(int x, int y) const;

    // The view transform and direct manipulation (view2d_interaction.cpp). The transform is kept:
    // fitted when a new scene is shown, not on a live edit of the same one (the picture would
    // jump under a drag), then zoomed and panned by the user.
    /// Fits the scene and its example ray's origin in the view (View > Fit the 2D view, F).
    void fitView();
    /// Zooms by `factor` about the widget point `about`, which stays over the same scene point.
    void zoomAt(QPointF about, double factor);
    /// Moves the picture by `delta` pixels.
    void panBy(QPointF delta);
    /// The zoom relative to the fitted view (1: fitted).
    double zoom() const { return zoom_; }
    /// The scene point under a widget point.
    Vec2 worldOf(QPointF widgetPoint) const {
        fit();
        return toWorld(widgetPoint);
    }
    /// The live lab that takes this view's drags and edits (none: the view only shows).
    void setLive(Live2D* live);
    /// Snap a dragged point to the grid's cell corners and centres (the tie case); snap the
    /// ray's direction to multiples of 15 degrees.
    void setSnapToCorners(bool on) { snapCorners_ = on; }
    void setSnapToAngle(bool on) { snapAngle_ = on; }
    /// The primitive selected for editing (circles first, then segments), if any.
    std::optional<std::uint32_t> selected() const { return selected_; }
    void setSelected(std::optional<std::uint32_t> prim);
    /// The ray the view draws and its handles take: the one the log replays (a lesson's own
    /// ray, or the example ray traced), else the scene's example ray; none in a build's replay.
    std::optional<Ray2> shownRay() const;
    /// Where the ray's direction handle is drawn: the tip of the arrow o + k d (k = 1 unless the
    /// arrow would be too short on screen to grab). Nullopt without a shown ray.
    std::optional<QPointF> tipHandle() const;

    /// The DDA's labels as the last paint placed them (tMax, tDelta), and the stretch of t each
    /// tDelta bracket spans (X, Y; none where not drawn): tests look at them.
    struct Label {
        QString text;
        QRectF box;
    };
    const std::vector<Label>& ddaLabels() const { return drawnLabels_; }
    const std::array<std::optional<std::array<double, 2>>, 2>& tDeltaSpans() const {
        return tDeltaSpans_;
    }

    /// The student's walk drawn over raystep's while its log is replayed (none: not drawn).
    void setStudentWalk(std::optional<StudentWalk> walk);
    /// Whether a student's walk is drawn now (its log is the one replayed).
    bool showsStudentWalk() const;

  public slots:
    /// The cells a student has clicked for a sequence exercise, numbered in order on the grid.
    void setSequence(const QList<QPoint>& cells);

  signals:
    /// A click on a grid cell (the lessons' "predict the next cell", "order the cells").
    void cellClicked(int x, int y);
    /// The selection changed (the Delete action follows it).
    void selectionChanged();

  protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;

  private:
    QPointF toScreen(const Vec2& p) const;
    Vec2 toWorld(QPointF p) const;
    void drawCostChart(QPainter& g, const ReplayState& st) const;
    /// The height of the cost chart's strip under a build's replay: its natural height, at most
    /// a share of the view's (0: too low to draw).
    double chartStrip() const;
    /// The DDA's state on the ray o + t d: tMax as labelled ticks, tDelta as brackets, labels
    /// kept apart and inside the view.
    void drawDdaMarks(QPainter& g, Vec2 o, Vec2 d, const ReplayState& st) const;
    void drawDdaMarksIn(QPainter& g, Vec2 o, Vec2 d, const ReplayState& st,
                        const OutlineGrid<2>* grid) const;
    /// The parts of a frame, in the order paintEvent draws them. Under the cached lines, what
    /// moves with the cursor: the visited and current cells, or a tree walk's nodes entered,
    /// skipped and being entered (view2d_structure.cpp).
    void drawWalk(QPainter& g, const ReplayState& st) const;
    /// A build being replayed: the planes chosen so far, the node being split, its candidate
    /// planes, the choice.
    void drawBuildReplay(QPainter& g, const ReplayState& st) const;
    /// The cached layer, then the primitives the replay touched in their colour: tested, skipped
    /// by the mailbox, the nearest hit (view2d_ray.cpp).
    void drawTouched(QPainter& g, const ReplayState& st) const;
    /// The ray, faint in full and solid as far as the replay has reached, with its DDA marks and
    /// the nearest hit.
    void drawRay(QPainter& g, const ReplayState& st) const;
    /// A sequence answer's clicked cells, numbered in order (view2d_structure.cpp).
    void drawSequence(QPainter& g) const;
    /// A student's walk over raystep's: their cells or nodes outlined and joined in order, the
    /// first that differs hatched (view2d_structure.cpp).
    void drawStudentWalk(QPainter& g) const;
    /// Where grid cell `c` is drawn.
    QRectF cellRect(const OutlineGrid<2>& grid, const std::array<std::int32_t, 3>& c) const;
    /// The caption over the picture: the scene's name and its structure.
    QString captionText() const;
    /// The colour roles of the picture (the palette's), where fit() put them.
    void drawLegend(QPainter& g, bool build) const;
    /// The scene-to-widget mapping for the current size: the kept view (fitted on a new scene,
    /// then zoomed and panned), with room for the legend and the cost chart.
    void fit() const;
    /// The live lab's marks over the picture: the ray's handles, the selected primitive's.
    void drawHandles(QPainter& g) const;
    /// What a press at a widget point takes hold of.
    enum class Grab { None, Origin, Tip, NewRay, Circle, Rim, SegmentA, SegmentB, Segment };
    struct Target {
        Grab grab = Grab::None;
        std::uint32_t prim = 0;
    };
    Target targetAt(QPointF widgetPoint) const;
    /// The tip handle's k: the arrow o + k d is at least about 40 pixels long.
    double tipScale() const;
    /// A dragged scene point after the snaps in force (cell corners and centres).
    Vec2 snapPoint(Vec2 p) const;
    /// One frame of a drag: the scene with the grabbed part where the mouse is.
    void dragTo(QPointF widgetPoint);
    void updateCursor(QPointF widgetPoint);
    /// A scene was shown: refit unless it is a live edit or a rebuild of the one shown.
    void sceneShown();

    /// The structure's lines and the primitives in their neutral colour, drawn once per size and
    /// scene (thousands of segments and tree nodes would otherwise cost most of every frame).
    /// The cached lines: the grid's, the kd-tree's planes or the BVH's boxes (from the
    /// session's outline of the structure), and the primitives.
    void buildLayer();
    /// The shown structure's grid (its outline's), if it is one.
    const OutlineGrid<2>* shownGrid() const;
    void drawPrimitive(QPainter& painter, std::uint32_t prim) const;
    /// A build's replay: where each split was chosen and each node's parent, once per log.
    void indexBuild();

    Session& session_;
    QList<QPoint> sequence_;  // a sequence answer's cells, in the order clicked
    std::optional<StudentWalk> student_;
    Language lang_ = Language::En;
    bool legendShown_ = true, captionShown_ = true;
    QPixmap layer_;
    QSize layerSize_;
    bool layerDirty_ = true;
    static constexpr std::size_t kAllSplitsUpTo = 256;  // as many lines as the candidates shown
    std::vector<std::size_t> chosenAt_;  // event indices of the SplitChosen events, in order
    std::vector<std::uint32_t> buildParent_;
    std::vector<std::pair<int, double>> splitOf_;  // per node: axis (-1: none) and position
    std::vector<std::size_t> splitAt_;             // per node: the event that chose its split
    mutable BoxN<2> world_;                        // what is fitted, in scene units
    mutable double scale_ = 1.0;
    /// The legend as fit() laid it out: its box, and each row's place in it.
    struct LegendLayout {
        bool inRows = false;  // rows under the caption (else a column on the right)
        QRectF box;
        std::vector<QRectF> entries;
    };
    mutable LegendLayout legend_;
    mutable std::vector<Label> drawnLabels_;
    mutable std::array<std::optional<std::array<double, 2>>, 2> tDeltaSpans_;
    mutable QPointF offset_;
    // The kept view: fitted box, zoom and pan; refitted when another scene is shown.
    mutable bool needFit_ = true;
    double zoom_ = 1.0;
    QPointF pan_;
    std::optional<Scene2D> shown_;  // the primitives and ray last shown (a new scene or an edit)
    // Direct manipulation.
    Live2D* live_ = nullptr;
    bool snapCorners_ = false, snapAngle_ = false;
    std::optional<std::uint32_t> selected_;
    struct Drag {
        Target target;
        QPointF press;          // where the button went down
        Vec2 grabOffset{0.0};   // the grabbed point minus the scene point under the press
        double tipScale = 1.0;  // the tip handle's k at the press
        Scene2D start;          // the scene at the press
        bool moving = false;    // past the drag distance: not a click
        bool pan = false;
        QPointF last;  // a pan's previous point
    };
    std::optional<Drag> drag_;
};

}  // namespace raystep::gui
