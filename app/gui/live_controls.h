#pragma once
// The live controls dock: the structure (brute force, grid, kd-tree, BVH) and its parameters (the
// grid's cells per axis or lambda, the split method, SAH's traversal and intersection costs, the
// empty bonus, the leaf size, the maximum depth, mailboxing), each change built and shown at once
// (MainWindow::applyStructure), with the statistics of what is shown. It follows the session, so
// the Structure tool bar and these controls always agree.
#include "session.h"

#include <QWidget>

#include <utility>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QSpinBox;

namespace raystep::gui {

class LiveControls : public QWidget {
    Q_OBJECT
  public:
    explicit LiveControls(Session& s, QWidget* parent = nullptr);

    /// The structure and options the controls show now.
    AccelKind kind() const;
    AccelOptions options() const;
    /// The statistics shown under the controls (tests read them).
    QString statistics() const;
    /// The controls show the session's structure and options (no applyRequested): on every new
    /// scene, and when a build the controls asked for failed.
    void sync();

    // The controls, for tests and the window.
    QComboBox* structureBox() const { return structure_; }
    QComboBox* splitBox() const { return split_; }
    QCheckBox* byLambdaBox() const { return byLambda_; }
    QDoubleSpinBox* lambdaBox() const { return lambda_; }
    QSpinBox* cellsBox(int axis) const { return cells_[axis]; }
    QDoubleSpinBox* cTravBox() const { return cTrav_; }
    QDoubleSpinBox* cIsectBox() const { return cIsect_; }
    QDoubleSpinBox* emptyBonusBox() const { return emptyBonus_; }
    QSpinBox* leafSizeBox() const { return leafSize_; }
    QSpinBox* maxDepthBox() const { return maxDepth_; }
    QCheckBox* mailboxBox() const { return mailbox_; }

  signals:
    /// The user changed a control: build `kind` with `options` and show it.
    void applyRequested(AccelKind kind, const AccelOptions& options);

  public:
    QSize minimumSizeHint() const override;

  protected:
    void resizeEvent(QResizeEvent*) override;
    void changeEvent(QEvent*) override;

  private:
    /// The controls beside their names: two pairs to a row (`twoPairs`), else one.
    void arrange(bool twoPairs);
    /// The least width of the pairs laid out `columns` wide (4: two pairs to a row; 2: one).
    int pairsWidth(int columns) const;
    /// Which controls apply to the structure shown.
    void enableForKind();
    void updateStatistics();
    void changed();

    Session& session_;
    bool syncing_ = false;
    QComboBox* structure_;
    QComboBox* split_;
    QCheckBox* byLambda_;
    QDoubleSpinBox* lambda_;
    QSpinBox* cells_[3];
    QLabel* cellsLabel_;
    QWidget* zCells_;  // NZ with its "x" (3D only)
    QDoubleSpinBox* cTrav_;
    QDoubleSpinBox* cIsect_;
    QDoubleSpinBox* emptyBonus_;
    QSpinBox* leafSize_;
    QSpinBox* maxDepth_;
    QCheckBox* mailbox_;
    QLabel* stats_;
    QGridLayout* grid_ = nullptr;
    std::vector<std::pair<QWidget*, QWidget*>> pairs_;  // name, control (none: it spans both)
    bool arranged_ = false, twoPerRow_ = true;
};

}  // namespace raystep::gui
