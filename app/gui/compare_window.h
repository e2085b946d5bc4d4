#pragma once
// Compare mode: midpoint, median and SAH trees of one scene side by side, the same ray replayed
// in each (one step slider for all three), and a table of their statistics. 2D scenes replay
// their example ray in three 2D views; 3D scenes a pixel's ray tree in three 3D views.
#include "session.h"

#include <QWidget>

#include <array>
#include <memory>

class QSlider;
class QTableWidget;

namespace raystep::gui {

class View2D;

class CompareWindow : public QWidget {
    Q_OBJECT
  public:
    /// The three splits of `kind` (kdtree or bvh) on a scene; for a 3D scene the ray tree of
    /// pixel (x, y) of a width x height image. Throws SceneError.
    struct Pixel {
        int x, y, width, height;
    };
    CompareWindow(const std::string& scene, AccelKind kind, Pixel pixel = {160, 120, 320, 240},
                  QWidget* parent = nullptr);
    ~CompareWindow() override;
    Session& session(int i) { return *sessions_[i]; }
    QTableWidget* table() const { return table_; }
    /// Puts every replay at step n (each clamped to its own log).
    void setStep(int n);

  private:
    std::array<std::unique_ptr<Session>, 3> sessions_;
    std::array<QWidget*, 3> views_{};
    QSlider* slider_ = nullptr;
    QTableWidget* table_ = nullptr;
};

}  // namespace raystep::gui
