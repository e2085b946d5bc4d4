#pragma once
// Compare mode: any set of structures over one scene side by side (a tree's midpoint, median and
// SAH splits, or the slides' grid, kd-tree and BVH), the same ray replayed in each (one step
// slider for all), and a table of their statistics. 2D scenes replay their example ray in 2D
// views; 3D scenes a pixel's ray tree in 3D views.
#include "session.h"

#include <QWidget>

#include <memory>
#include <vector>

class QLabel;
class QPushButton;
class QSlider;
class QTableWidget;

namespace raystep::gui {

/// The comparison a window opens with when nothing else is asked: a tree's split methods
/// against each other; for a grid or brute force, the slides' grid, kd-tree and BVH (SAH).
std::vector<StructureChoice> defaultComparison(AccelKind shown);
/// "kd-tree, SAH", "grid": a choice as the columns and the chooser name it, in the language shown.
QString choiceLabel(const StructureChoice& c);

class CompareWindow : public QWidget {
    Q_OBJECT
  public:
    /// For a 3D scene: which ray tree to replay, pixel (x, y) of a width x height image.
    struct Pixel {
        int x, y, width, height;
    };
    /// One scene per choice, each with that structure built over the scene shown (as edited live,
    /// with its example ray and its options: a lesson's own), on any thread (the main window
    /// builds them behind a progress dialog); `progress` sees the builds as one. Throws
    /// BuildCancelled.
    using Prepared = std::vector<SceneRef>;
    static Prepared prepare(const SceneRef& scene, const std::vector<StructureChoice>& choices,
                            const ProgressFn& progress = {});
    /// Shows them, each replaying the 2D scene's example ray or the 3D scene's `pixel`.
    CompareWindow(Prepared prepared, Pixel pixel, QWidget* parent = nullptr);
    ~CompareWindow() override;
    int count() const { return static_cast<int>(sessions_.size()); }
    Session& session(int i) { return *sessions_[i]; }
    /// What column i compares (its kind and, for a tree, its split).
    StructureChoice choice(int i) const;
    /// Every column's, in order.
    std::vector<StructureChoice> choices() const;
    QTableWidget* table() const { return table_; }
    /// The table's rows, by what they count (tests use them to find a row).
    enum Row {
        BuildMs,
        Nodes,
        Leaves,
        MaxDepth,
        References,
        SahCost,
        RayTests,
        RayVisits,
        RaySkips,
        RayEvents,
        RowCount
    };
    /// Puts every replay at step n (each clamped to its own log).
    void setStep(int n);
    /// The size this window had when last closed (at most `room`: this screen's), else
    /// `fallback`.
    void placeOnScreen(QSize fallback, QSize room);
    QPushButton* closeButton() const { return close_; }
    QWidget* view(int i) const { return views_[i]; }
    /// Column i's caption under its title: how far its replay is ("event 12 of 40").
    QString progressText(int i) const;

  protected:
    void closeEvent(QCloseEvent*) override;

  private:
    std::vector<std::unique_ptr<Session>> sessions_;
    std::vector<QWidget*> views_;
    std::vector<QLabel*> progress_;
    QSlider* slider_ = nullptr;
    QTableWidget* table_ = nullptr;
    QPushButton* close_ = nullptr;
    bool syncing_ = false;  // a camera being copied to the other views (not copied back)
};

}  // namespace raystep::gui
