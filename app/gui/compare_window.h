#pragma once
// Compare mode: midpoint, median and SAH trees of one scene side by side, the same ray replayed
// in each (one step slider for all three), and a table of their statistics. 2D scenes replay
// their example ray in three 2D views; 3D scenes a pixel's ray tree in three 3D views.
#include "session.h"

#include <QWidget>

#include <array>
#include <memory>

class QPushButton;
class QSlider;
class QTableWidget;

namespace raystep::gui {

class View2D;

class CompareWindow : public QWidget {
    Q_OBJECT
  public:
    /// For a 3D scene: which ray tree to replay, pixel (x, y) of a width x height image.
    struct Pixel {
        int x, y, width, height;
    };
    /// The three splits of `kind` (kdtree or bvh) built over the scene shown (as edited live,
    /// with its example ray: a lesson's own), on any thread (the main window builds them behind
    /// a progress dialog); `progress` sees the three builds as one. Throws BuildCancelled.
    using Prepared = std::array<SceneRef, 3>;
    static Prepared prepare(const SceneRef& scene, AccelKind kind, const ProgressFn& progress = {});
    /// Shows them, each replaying the 2D scene's example ray or the 3D scene's `pixel`.
    CompareWindow(Prepared prepared, Pixel pixel, QWidget* parent = nullptr);
    ~CompareWindow() override;
    Session& session(int i) { return *sessions_[i]; }
    QTableWidget* table() const { return table_; }
    /// Puts every replay at step n (each clamped to its own log).
    void setStep(int n);
    /// The size this window had when last closed (at most `room`: this screen's), else
    /// `fallback`.
    void placeOnScreen(QSize fallback, QSize room);
    QPushButton* closeButton() const { return close_; }
    QWidget* view(int i) const { return views_[i]; }

  protected:
    void closeEvent(QCloseEvent*) override;

  private:
    std::array<std::unique_ptr<Session>, 3> sessions_;
    std::array<QWidget*, 3> views_{};
    QSlider* slider_ = nullptr;
    QTableWidget* table_ = nullptr;
    QPushButton* close_ = nullptr;
};

}  // namespace raystep::gui
