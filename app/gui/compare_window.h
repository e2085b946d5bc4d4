#pragma once
// Compare mode: midpoint, median and SAH trees of one scene side by side, the same ray replayed
// in each (one step slider for all three), and a table of their statistics.
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
    /// The three splits of `kind` (kdtree or bvh) on a 2D scene; throws SceneError.
    CompareWindow(const std::string& scene, AccelKind kind, QWidget* parent = nullptr);
    ~CompareWindow() override;
    Session& session(int i) { return *sessions_[i]; }
    QTableWidget* table() const { return table_; }
    /// Puts every replay at step n (each clamped to its own log).
    void setStep(int n);

  private:
    std::array<std::unique_ptr<Session>, 3> sessions_;
    std::array<View2D*, 3> views_{};
    QSlider* slider_ = nullptr;
    QTableWidget* table_ = nullptr;
};

}  // namespace raystep::gui
