// The live controls: widgets over AccelOptions, ranges as the core (and the CLI) accept them, so a
// value the build would refuse cannot be entered.
#include "live_controls.h"

#include "language.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>

#include <algorithm>
#include <cmath>
#include <vector>

namespace raystep::gui {

namespace {
using O = AccelOption;

/// A box over an option of the table (structure_info.h): its limits, as the CLI and the lesson
/// reader check them, with auto (0) first where the option has one.
QDoubleSpinBox* doubleBox(const char* name, AccelOption option, double step, int decimals) {
    auto* b = new QDoubleSpinBox;
    b->setObjectName(name);
    const auto [lo, hi] = controlRange(option, std::pow(10.0, -decimals));
    b->setRange(lo, hi);
    b->setSingleStep(step);
    b->setDecimals(decimals);
    b->setKeyboardTracking(false);  // typing "12" builds once, not at "1" and again at "12"
    return b;
}

QSpinBox* intBox(const char* name, AccelOption option) {
    auto* b = new QSpinBox;
    b->setObjectName(name);
    const auto [lo, hi] = controlRange(option, 1.0);
    b->setRange(static_cast<int>(lo), static_cast<int>(hi));
    b->setKeyboardTracking(false);
    return b;
}

/// The resolution of the grid the session shows, if it shows one (its outline's).
std::optional<std::array<int, 3>> builtResolution(const Session& s) {
    if (const StructureOutline<2>* o = s.outline2D(); o && o->grid)
        return std::array<int, 3>{o->grid->spec.res[0], o->grid->spec.res[1], 1};
    if (const StructureOutline<3>* o = s.outline3D(); o && o->grid)
        return std::array<int, 3>{o->grid->spec.res[0], o->grid->spec.res[1], o->grid->spec.res[2]};
    return std::nullopt;
}
}  // namespace

LiveControls::LiveControls(Session& s, QWidget* parent) : QWidget(parent), session_(s) {
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(4, 4, 4, 4);
    grid->setVerticalSpacing(3);
    // The least width is minimumSizeHint()'s (one pair to a row), not the layout's of the moment.
    grid->setSizeConstraint(QLayout::SetNoConstraint);

    structure_ = new QComboBox;
    structure_->setObjectName("liveStructure");
    for (const StructureInfo& info : structures())
        structure_->addItem(structureName(info.kind), static_cast<int>(info.kind));
    split_ = new QComboBox;
    split_->setObjectName("liveSplit");
    split_->addItem(tr("midpoint"), static_cast<int>(SplitMethod::Midpoint));
    split_->addItem(tr("median"), static_cast<int>(SplitMethod::Median));
    split_->addItem(tr("SAH"), static_cast<int>(SplitMethod::Sah));
    split_->setToolTip(tr("How the kd-tree or the BVH chooses its split planes"));

    const char* cellNames[3] = {"liveNX", "liveNY", "liveNZ"};
    auto* cellsRow = new QHBoxLayout;
    cellsRow->setSpacing(2);
    for (int i = 0; i < 3; ++i) {
        cells_[i] = intBox(cellNames[i], O::GridRes);
        if (i == 2) {
            // NZ and its "x" together, hidden for a 2D scene.
            zCells_ = new QWidget;
            auto* z = new QHBoxLayout(zCells_);
            z->setContentsMargins(0, 0, 0, 0);
            z->setSpacing(2);
            z->addWidget(new QLabel(QStringLiteral("x")));
            z->addWidget(cells_[i]);
            cellsRow->addWidget(zCells_);
        } else {
            if (i) cellsRow->addWidget(new QLabel(QStringLiteral("x")));
            cellsRow->addWidget(cells_[i]);
        }
        connect(cells_[i], &QSpinBox::valueChanged, this, [this] { changed(); });
    }
    cellsRow->addStretch();
    cellsLabel_ = new QLabel(tr("Cells"));
    cellsLabel_->setToolTip(tr("The grid's cells per axis (NX, NY, NZ)"));
    byLambda_ = new QCheckBox(tr("By λ"));
    byLambda_->setObjectName("liveByLambda");
    byLambda_->setToolTip(
        tr("Cells from Cleary and Wyvill's rule: λ cells per primitive, in all (else the cells "
           "per axis above)"));
    lambda_ = doubleBox("liveLambda", O::GridLambda, 0.5, 2);
    cTrav_ = doubleBox("liveCTrav", O::CTrav, 0.5, 2);
    cTrav_->setToolTip(tr("SAH: the cost of one traversal step (cTrav)"));
    cIsect_ = doubleBox("liveCIsect", O::CIsect, 0.5, 2);
    cIsect_->setToolTip(tr("SAH: the cost of one ray-primitive test (cIsect)"));
    emptyBonus_ = doubleBox("liveEmptyBonus", O::EmptyBonus, 0.1, 2);
    emptyBonus_->setToolTip(
        tr("kd-tree SAH: a split with an empty side costs (1 - bonus) times as much"));
    leafSize_ = intBox("liveLeafSize", O::LeafSize);
    leafSize_->setSpecialValueText(tr("auto"));
    leafSize_->setToolTip(
        tr("This many primitives or fewer make a leaf (auto: 1 for the SAH, "
           "4 for midpoint and median)"));
    maxDepth_ = intBox("liveMaxDepth", O::MaxDepth);
    maxDepth_->setSpecialValueText(tr("auto"));
    maxDepth_->setToolTip(tr("The kd-tree's depth limit (auto: 8 + 1.3 log2 N)"));
    mailbox_ = new QCheckBox(tr("Mailboxing"));
    mailbox_->setObjectName("liveMailbox");
    mailbox_->setToolTip(tr("Test each primitive once per ray (grid and kd-tree)"));
    stats_ = new QLabel;
    stats_->setObjectName("liveStats");
    stats_->setWordWrap(true);
    stats_->setTextInteractionFlags(Qt::TextSelectableByMouse);

    // The statistics first: on a short screen the rarely used controls scroll, not these. Then
    // each control beside its name, two pairs to a row where the dock is wide enough, else one
    // (lessons.md F14: in Italian at 1366x768 "Taglio" and the leaf size were cut off).
    grid_ = grid;
    auto* cells = new QWidget;
    cellsRow->setContentsMargins(0, 0, 0, 0);
    cells->setLayout(cellsRow);
    // A long name ("Profondità massima") wraps rather than widen a narrow dock.
    const auto label = [](const QString& text) {
        auto* l = new QLabel(text);
        l->setWordWrap(true);
        return l;
    };
    cellsLabel_->setWordWrap(true);
    pairs_ = {{label(tr("Structure")), structure_},
              {label(tr("Split")), split_},
              {cellsLabel_, cells},
              {byLambda_, lambda_},
              {label(QStringLiteral("cTrav")), cTrav_},
              {label(QStringLiteral("cIsect")), cIsect_},
              {label(tr("Empty bonus")), emptyBonus_},
              {label(tr("Leaf size")), leafSize_},
              {label(tr("Max depth")), maxDepth_},
              {mailbox_, nullptr}};
    arrange(true);

    connect(structure_, &QComboBox::activated, this, [this] { changed(); });
    connect(split_, &QComboBox::activated, this, [this] { changed(); });
    connect(byLambda_, &QCheckBox::toggled, this, [this] { changed(); });
    connect(mailbox_, &QCheckBox::toggled, this, [this] { changed(); });
    for (QDoubleSpinBox* b : {lambda_, cTrav_, cIsect_, emptyBonus_})
        connect(b, &QDoubleSpinBox::valueChanged, this, [this] { changed(); });
    for (QSpinBox* b : {leafSize_, maxDepth_})
        connect(b, &QSpinBox::valueChanged, this, [this] { changed(); });

    connect(&session_, &Session::sceneChanged, this, [this] { sync(); });
    connect(&session_, &Session::logChanged, this, [this] { updateStatistics(); });
    connect(&session_, &Session::shownChanged, this, [this] { updateStatistics(); });
    sync();
}

AccelKind LiveControls::kind() const {
    return static_cast<AccelKind>(structure_->currentData().toInt());
}

AccelOptions LiveControls::options() const {
    AccelOptions o = session_.options();
    o.setProgress({});  // the last build's progress belonged to its task
    o.setSplit(static_cast<SplitMethod>(split_->currentData().toInt()));
    if (byLambda_->isChecked()) {
        o.grid.res.reset();
        o.grid.lambda = lambda_->value();
    } else {
        o.grid.res = std::array<int, 3>{cells_[0]->value(), cells_[1]->value(),
                                        session_.is2D() ? 1 : cells_[2]->value()};
    }
    o.set(O::Mailbox, mailbox_->isChecked());
    o.set(O::CTrav, cTrav_->value());
    o.set(O::CIsect, cIsect_->value());
    o.set(O::EmptyBonus, emptyBonus_->value());
    o.set(O::MaxDepth, maxDepth_->value());
    o.set(O::LeafSize, leafSize_->value());
    return o;
}

void LiveControls::changed() {
    if (syncing_ || !session_.hasScene()) return;
    enableForKind();
    emit applyRequested(kind(), options());
}

void LiveControls::sync() {
    syncing_ = true;
    const AccelKind k = session_.kind();
    const AccelOptions o = session_.options();
    structure_->setCurrentIndex(structure_->findData(static_cast<int>(k)));
    split_->setCurrentIndex(
        split_->findData(static_cast<int>(o.split(k).value_or(o.kdtree.split))));
    // A 2D scene may name the grid its slides draw: that grid is not lambda's.
    const Scene2D* s2 = session_.scene2D();
    const bool byRule = !o.grid.res && !(s2 && s2->gridRes);
    byLambda_->setChecked(byRule);
    lambda_->setValue(o.grid.lambda);
    std::optional<std::array<int, 3>> res = builtResolution(session_);
    if (!res && o.grid.res) res = o.grid.res;
    if (!res && s2 && s2->gridRes) res = std::array<int, 3>{s2->gridRes->x, s2->gridRes->y, 1};
    if (res)
        for (int i = 0; i < 3; ++i) cells_[i]->setValue((*res)[i]);
    zCells_->setVisible(!session_.is2D());
    mailbox_->setChecked(o.value(k, O::Mailbox) != 0.0);
    cTrav_->setValue(o.value(k, O::CTrav));
    cIsect_->setValue(o.value(k, O::CIsect));
    emptyBonus_->setValue(o.value(k, O::EmptyBonus));
    leafSize_->setValue(static_cast<int>(o.value(k, O::LeafSize)));
    maxDepth_->setValue(static_cast<int>(o.value(k, O::MaxDepth)));
    enableForKind();
    syncing_ = false;
    updateStatistics();
}

void LiveControls::enableForKind() {
    const AccelKind k = kind();
    const bool scene = session_.hasScene();
    const auto split = static_cast<SplitMethod>(split_->currentData().toInt());
    // A control is on where the structure's row says its build reads the option (the SAH's
    // costs for the SAH only).
    const auto on = [&](AccelOption o) { return scene && readsOption(k, o, split); };
    structure_->setEnabled(scene);
    split_->setEnabled(on(O::Split));
    byLambda_->setEnabled(on(O::GridLambda));
    lambda_->setEnabled(on(O::GridLambda) && byLambda_->isChecked());
    for (QSpinBox* b : cells_) b->setEnabled(on(O::GridRes) && !byLambda_->isChecked());
    mailbox_->setEnabled(on(O::Mailbox));
    cTrav_->setEnabled(on(O::CTrav));
    cIsect_->setEnabled(on(O::CIsect));
    emptyBonus_->setEnabled(on(O::EmptyBonus));
    leafSize_->setEnabled(on(O::LeafSize));
    maxDepth_->setEnabled(on(O::MaxDepth));
}

void LiveControls::updateStatistics() {
    if (!session_.hasScene()) {
        stats_->clear();
        return;
    }
    std::size_t tests = 0, cells = 0, nodes = 0, skips = 0, built = 0, leaves = 0;
    // What may be shown only: an exercise held in quiz mode may ask for these very counts.
    for (const Event& e : session_.shownEvents()) {
        tests += std::holds_alternative<PrimitiveTest>(e);
        cells += std::holds_alternative<DdaCell>(e);
        nodes += std::holds_alternative<NodeEnter>(e);
        skips += std::holds_alternative<MailboxSkip>(e);
        built += std::holds_alternative<BuildNode>(e);
        leaves += std::holds_alternative<LeafMade>(e);
    }
    const BuildSummary summary = session_.summary();
    const TreeStats& t = summary.stats;
    QStringList lines;
    // What the structure is, as its row and its outline say: cells (a grid), every primitive
    // (brute force) or a tree's nodes; a ray's counts the same way.
    const std::optional<std::array<int, 3>> cells3 = builtResolution(session_);
    const bool everyPrimitive = testsEveryPrimitive(session_.kind());
    if (cells3) {
        QStringList res;
        for (int a = 0; a < (session_.is2D() ? 2 : 3); ++a) res << QString::number((*cells3)[a]);
        lines << tr("Grid %1: %2 cells, %3 empty, %4 listings")
                     .arg(res.join('x'))
                     .arg(t.nodes)
                     .arg(t.emptyLeaves)
                     .arg(t.references);
    } else if (everyPrimitive) {
        lines << tr("Brute force: every primitive for every ray (%1)").arg(t.references);
    } else {
        lines << tr("%1 nodes, %2 leaves, depth %3; SAH cost %4")
                     .arg(t.nodes)
                     .arg(t.leaves)
                     .arg(t.maxDepth)
                     .arg(numberText(t.sahCost));
    }
    if (session_.hiding()) {
        // The rest waits with the replay: a count up to an exercise's position (or the cursor,
        // presenting) reads as the whole, so none is shown until the exercise is answered or
        // put away.
        lines << (session_.limit() ? tr("Traced: counts wait for the exercise")
                                   : tr("Traced: counts wait for the question's answer"));
    } else if (built > 0)
        lines << tr("Build replayed: %1 nodes made, %2 leaves").arg(built).arg(leaves);
    else if (cells3)
        lines << tr("Traced: %1 tests, %2 cells visited, %3 mailbox skips")
                     .arg(tests)
                     .arg(cells)
                     .arg(skips);
    else if (everyPrimitive)
        lines << tr("Traced: %1 tests").arg(tests);
    else
        lines << tr("Traced: %1 tests, %2 nodes visited, %3 mailbox skips")
                     .arg(tests)
                     .arg(nodes)
                     .arg(skips);
    stats_->setText(lines.join('\n'));
}

int LiveControls::pairsWidth(int columns) const {
    // The widest name and the widest control of each column of pairs, with the grid's spacing.
    const int perRow = std::max(1, columns / 2);
    std::vector<int> names(perRow, 0), fields(perRow, 0);
    for (std::size_t i = 0; i < pairs_.size(); ++i) {
        const int c = static_cast<int>(i) % perRow;
        if (!pairs_[i].second) continue;  // the mailboxing box spans a whole pair
        names[c] = std::max(names[c], pairs_[i].first->minimumSizeHint().width());
        fields[c] = std::max(fields[c], pairs_[i].second->minimumSizeHint().width());
    }
    const int spacing = std::max(0, grid_->horizontalSpacing());
    int w = grid_->contentsMargins().left() + grid_->contentsMargins().right();
    for (int c = 0; c < perRow; ++c) w += names[c] + fields[c] + 2 * spacing;
    return w;
}

void LiveControls::arrange(bool twoPairs) {
    if (arranged_ && twoPerRow_ == twoPairs) return;
    arranged_ = true;
    twoPerRow_ = twoPairs;
    while (grid_->count() > 0) delete grid_->takeAt(0);
    for (int c = 0; c < 4; ++c) grid_->setColumnStretch(c, 0);
    const int columns = twoPairs ? 4 : 2;
    int row = 0;
    grid_->addWidget(stats_, row++, 0, 1, columns);
    for (std::size_t i = 0; i < pairs_.size(); ++i) {
        const int at = twoPairs ? 2 * (static_cast<int>(i) % 2) : 0;
        if (pairs_[i].second) {
            grid_->addWidget(pairs_[i].first, row, at);
            grid_->addWidget(pairs_[i].second, row, at + 1);
        } else {
            grid_->addWidget(pairs_[i].first, row, at, 1, 2);
        }
        if (!twoPairs || i % 2 == 1) ++row;
    }
    if (twoPairs && pairs_.size() % 2 == 1) ++row;
    grid_->setRowStretch(row, 1);
    grid_->setColumnStretch(1, 1);
    if (twoPairs) grid_->setColumnStretch(3, 1);
}

void LiveControls::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    arrange(width() >= pairsWidth(4));
}

void LiveControls::changeEvent(QEvent* e) {
    QWidget::changeEvent(e);
    // Another font (the zoom) or language: the names' widths change.
    if (e->type() == QEvent::FontChange || e->type() == QEvent::LanguageChange)
        arrange(width() >= pairsWidth(4));
}

QSize LiveControls::minimumSizeHint() const {
    // One pair to a row fits a narrow dock; two are put side by side only where they fit.
    return {pairsWidth(2), QWidget::minimumSizeHint().height()};
}

QString LiveControls::statistics() const {
    return stats_->text();
}

}  // namespace raystep::gui
