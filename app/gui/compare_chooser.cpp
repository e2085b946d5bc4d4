#include "compare_chooser.h"

#include "language.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

#include <algorithm>

namespace raystep::gui {

namespace {
/// Whether `c` is one tree's split methods, each once (the first mode).
bool oneTreesSplits(const std::vector<StructureChoice>& c) {
    if (c.size() < 2) return false;
    for (const StructureChoice& x : c)
        if (x.kind != c.front().kind || !x.split) return false;
    return true;
}
}  // namespace

CompareChooser::CompareChooser(const std::vector<StructureChoice>& initial, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Compare structures"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Put side by side, on the same ray:")));
    auto* grid = new QGridLayout;
    splitsMode_ = new QRadioButton(tr("The split methods of one tree (midpoint, median, SAH):"));
    tree_ = new QComboBox;
    structuresMode_ = new QRadioButton(tr("These structures (BVH against space subdivision):"));
    auto* kinds = new QHBoxLayout;
    kinds_.assign(kAccelKindCount, nullptr);
    for (const StructureInfo& s : structures()) {
        if (!s.splits.empty()) tree_->addItem(structureName(s.kind), static_cast<int>(s.kind));
        auto* box = new QCheckBox(structureName(s.kind));
        box->setObjectName(QString::fromUtf8(s.name.data(), static_cast<int>(s.name.size())));
        kinds_[static_cast<std::size_t>(s.kind)] = box;
        kinds->addWidget(box);
        connect(box, &QCheckBox::toggled, this, [this] { update(); });
    }
    kinds->addStretch(1);
    split_ = new QComboBox;
    for (const SplitMethod m : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah})
        split_->addItem(splitName(m), static_cast<int>(m));
    auto* splitRow = new QHBoxLayout;
    splitRow->addWidget(new QLabel(tr("trees split by")));
    splitRow->addWidget(split_);
    splitRow->addStretch(1);
    grid->addWidget(splitsMode_, 0, 0, 1, 2);
    grid->addWidget(tree_, 1, 1, Qt::AlignLeft);
    grid->addWidget(structuresMode_, 2, 0, 1, 2);
    grid->addLayout(kinds, 3, 1);
    grid->addLayout(splitRow, 4, 1);
    grid->setColumnMinimumWidth(0, 20);
    layout->addLayout(grid);
    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons_->button(QDialogButtonBox::Ok)->setText(tr("Open the comparison"));
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons_);
    for (QRadioButton* r : {splitsMode_, structuresMode_})
        connect(r, &QRadioButton::toggled, this, [this] { update(); });

    // Opened on what was asked (or compared last).
    split_->setCurrentIndex(split_->findData(static_cast<int>(SplitMethod::Sah)));
    if (oneTreesSplits(initial)) {
        splitsMode_->setChecked(true);
        tree_->setCurrentIndex(tree_->findData(static_cast<int>(initial.front().kind)));
        for (const AccelKind k : {AccelKind::Grid, AccelKind::KdTree, AccelKind::Bvh})
            kindBox(k)->setChecked(true);
    } else {
        structuresMode_->setChecked(true);
        for (const StructureChoice& c : initial) {
            kindBox(c.kind)->setChecked(true);
            if (c.split) split_->setCurrentIndex(split_->findData(static_cast<int>(*c.split)));
        }
    }
    update();
}

void CompareChooser::update() {
    const bool splits = splitsMode_->isChecked();
    tree_->setEnabled(splits);
    for (QCheckBox* b : kinds_) b->setEnabled(!splits);
    split_->setEnabled(!splits);
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(!choices().empty());
}

std::vector<StructureChoice> CompareChooser::choices() const {
    std::vector<StructureChoice> out;
    if (splitsMode_->isChecked()) {
        const auto kind = static_cast<AccelKind>(tree_->currentData().toInt());
        for (const SplitMethod m : structureInfo(kind).splits) out.push_back({kind, m});
        return out;
    }
    const auto split = static_cast<SplitMethod>(split_->currentData().toInt());
    for (const StructureInfo& s : structures())
        if (kindBox(s.kind)->isChecked())
            out.push_back({s.kind, s.splits.empty() ? std::nullopt : std::optional(split)});
    return out;
}

QString CompareChooser::toText(const std::vector<StructureChoice>& c) {
    QStringList kinds, splits;
    for (const StructureChoice& x : c) {
        const QString k = QString::fromUtf8(accelKindName(x.kind).data());
        if (!kinds.contains(k)) kinds << k;
        if (x.split) {
            const QString s = QString::fromUtf8(name(*x.split).data());
            if (!splits.contains(s)) splits << s;
        }
    }
    return kinds.join(',') + '|' + splits.join(',');
}

std::optional<std::vector<StructureChoice>> CompareChooser::fromText(const QString& text) {
    const QStringList parts = text.split('|');
    if (parts.size() != 2) return std::nullopt;
    const std::string kinds = parts[0].toStdString(), splits = parts[1].toStdString();
    const auto parsed = parseStructureChoices(
        kinds, splits.empty() ? std::nullopt : std::optional<std::string_view>(splits));
    if (const auto* c = std::get_if<std::vector<StructureChoice>>(&parsed)) return *c;
    return std::nullopt;
}

}  // namespace raystep::gui
