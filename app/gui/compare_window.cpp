#include "compare_window.h"

#include "language.h"
#include "view2d.h"
#include "vtk_view.h"

#include <QCloseEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QTableWidget>
#include <QVBoxLayout>

namespace raystep::gui {

namespace {
constexpr SplitMethod kSplits[3] = {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah};
}

CompareWindow::Prepared CompareWindow::prepare(const SceneRef& scene, AccelKind kind,
                                               const ProgressFn& progress) {
    Prepared p;
    for (int i = 0; i < 3; ++i) {
        AccelOptions o;
        o.kdtree.split = o.bvh.split = kSplits[i];
        if (progress) o.setProgress([&progress, i](double f) { return progress((i + f) / 3.0); });
        p[i] = Session::rebuild(scene, kind, o);
    }
    return p;
}

CompareWindow::CompareWindow(Prepared prepared, Pixel pixel, QWidget* parent) : QWidget(parent) {
    setWindowTitle(tr("raystep - compare midpoint, median and SAH"));
    const AccelKind kind = prepared[0]->kind;
    // kSplits' names, as the columns and the table say them.
    const QStringList splitNames = {tr("midpoint"), tr("median"), tr("SAH")};
    auto* views = new QHBoxLayout;
    int longest = 0;
    for (int i = 0; i < 3; ++i) {
        sessions_[i] = std::make_unique<Session>();
        sessions_[i]->adopt(std::move(prepared[i]));
        if (sessions_[i]->is2D())
            sessions_[i]->traceExampleRay();
        else
            sessions_[i]->tracePixel(pixel.x, pixel.y, pixel.width, pixel.height);
        longest = std::max(longest, static_cast<int>(sessions_[i]->size()));
        auto* column = new QVBoxLayout;
        auto* title =
            new QLabel(QStringLiteral("<b>%1 %2</b>").arg(structureName(kind), splitNames[i]));
        column->addWidget(title);
        // One caption and one legend for the three views (the same in each), in the first.
        if (sessions_[i]->is2D()) {
            auto* v = new View2D(*sessions_[i]);
            v->setLanguage(interfaceLanguage());
            v->setOverlays(/*caption=*/false, /*legend=*/i == 0);
            views_[i] = v;
        } else {
            auto* v = new VtkView(*sessions_[i]);
            v->setLanguage(interfaceLanguage());
            v->setOverlays(/*caption=*/false, /*legend=*/i == 0);
            views_[i] = v;
        }
        views_[i]->setMinimumSize(300, 220);
        column->addWidget(views_[i], 1);
        views->addLayout(column, 1);
    }
    slider_ = new QSlider(Qt::Horizontal);
    slider_->setRange(0, longest);
    connect(slider_, &QSlider::valueChanged, this, [this](int v) { setStep(v); });

    // The statistics of the three trees, and of the example ray through each.
    const QStringList rows = {
        tr("build ms"),   tr("nodes"),    tr("leaves"),     tr("max depth"),
        tr("references"), tr("SAH cost"), tr("ray: tests"), tr("ray: nodes visited"),
        tr("ray: events")};
    table_ = new QTableWidget(rows.size(), 3);
    table_->setVerticalHeaderLabels(rows);
    table_->setHorizontalHeaderLabels(splitNames);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int i = 0; i < 3; ++i) {
        const BuildSummary b = sessions_[i]->summary();
        std::size_t tests = 0, visits = 0;
        for (const Event& e : sessions_[i]->log().events()) {
            tests += std::holds_alternative<PrimitiveTest>(e);
            visits += std::holds_alternative<NodeEnter>(e);
        }
        const QStringList values = {numberText(b.stats.buildMs, 'f', 2),
                                    QString::number(b.stats.nodes),
                                    QString::number(b.stats.leaves),
                                    QString::number(b.stats.maxDepth),
                                    QString::number(b.stats.references),
                                    numberText(b.stats.sahCost, 'g', 5),
                                    QString::number(tests),
                                    QString::number(visits),
                                    QString::number(sessions_[i]->size())};
        for (int r = 0; r < values.size(); ++r)
            table_->setItem(r, i, new QTableWidgetItem(values[r]));
    }
    table_->resizeRowsToContents();
    table_->setMinimumHeight(table_->horizontalHeader()->height() +
                             table_->rowHeight(0) * table_->rowCount() + 6);
    auto* layout = new QVBoxLayout(this);
    if (!sessions_[0]->is2D())
        layout->addWidget(new QLabel(
            tr("Rasterized by VTK: the same pixel's rays in each tree (drag to rotate a view)")));
    layout->addLayout(views, 1);
    auto* stepRow = new QHBoxLayout;
    stepRow->addWidget(new QLabel(tr("step (the same ray in each)")));
    stepRow->addWidget(slider_, 1);
    layout->addLayout(stepRow);
    layout->addWidget(table_);
    close_ = new QPushButton(tr("Close"));
    close_->setObjectName("closeCompare");
    close_->setShortcut(QKeySequence(Qt::Key_Escape));
    close_->setToolTip(tr("Close the compare window (Esc)"));
    connect(close_, &QPushButton::clicked, this, &QWidget::close);
    layout->addWidget(close_, 0, Qt::AlignRight);
    setStep(longest);
    slider_->setValue(longest);
}

CompareWindow::~CompareWindow() = default;

void CompareWindow::placeOnScreen(QSize fallback, QSize room) {
    // The size of the last one (clamped: it may have been saved on a larger screen).
    if (!restoreGeometry(QSettings().value("compare/geometry").toByteArray()))
        resize(fallback);
    else
        resize(size().boundedTo(room));
}

void CompareWindow::closeEvent(QCloseEvent* e) {
    QSettings().setValue("compare/geometry", saveGeometry());
    QWidget::closeEvent(e);
}

void CompareWindow::setStep(int n) {
    for (auto& s : sessions_) s->setCursor(static_cast<std::size_t>(std::max(n, 0)));
}

}  // namespace raystep::gui
