#pragma once
// View > Compare...: which structures the compare window puts side by side, either one tree's
// split methods against each other or any set of structures (the slides' BVH against space
// subdivision), every kind read from the core's table of structures.
#include "raystep/accel/structure_info.h"

#include <QDialog>

#include <vector>

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QRadioButton;

namespace raystep::gui {

class CompareChooser : public QDialog {
    Q_OBJECT
  public:
    /// Opens on `initial` (a comparison defaultComparison or choices() made).
    explicit CompareChooser(const std::vector<StructureChoice>& initial, QWidget* parent = nullptr);
    /// What is ticked now, in the table's order; empty when nothing is (Compare is then off).
    std::vector<StructureChoice> choices() const;
    /// The same as a comma list ("grid,kdtree,bvh|sah"), to remember; and back (nullopt:
    /// unreadable).
    static QString toText(const std::vector<StructureChoice>& c);
    static std::optional<std::vector<StructureChoice>> fromText(const QString& text);

    QRadioButton* splitsMode() const { return splitsMode_; }
    QRadioButton* structuresMode() const { return structuresMode_; }
    QComboBox* tree() const { return tree_; }
    QCheckBox* kindBox(AccelKind kind) const { return kinds_[static_cast<std::size_t>(kind)]; }
    QComboBox* split() const { return split_; }
    QDialogButtonBox* buttons() const { return buttons_; }

  private:
    void update();
    QRadioButton *splitsMode_ = nullptr, *structuresMode_ = nullptr;
    QComboBox* tree_ = nullptr;
    std::vector<QCheckBox*> kinds_;
    QComboBox* split_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace raystep::gui
