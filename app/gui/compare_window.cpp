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

std::vector<StructureChoice> defaultComparison(AccelKind shown) {
    if (hasSplit(shown))
        return std::get<std::vector<StructureChoice>>(
            parseStructureChoices(accelKindName(shown), std::nullopt));
    // The slides' hierarchy section: one way to subdivide the space against the other.
    return std::get<std::vector<StructureChoice>>(
        parseStructureChoices("grid,kdtree,bvh", std::nullopt));
}

QString choiceLabel(const StructureChoice& c) {
    if (!c.split) return structureName(c.kind);
    return CompareWindow::tr("%1, %2").arg(structureName(c.kind), splitName(*c.split));
}

CompareWindow::Prepared CompareWindow::prepare(const SceneRef& scene,
                                               const std::vector<StructureChoice>& choices,
                                               const ProgressFn& progress) {
    Prepared p;
    const double n = static_cast<double>(choices.size());
    for (std::size_t i = 0; i < choices.size(); ++i) {
        AccelOptions o = scene->options;  // the options shown (a lesson's costs, a live grid)
        if (choices[i].split) o.setSplit(*choices[i].split);
        if (progress) o.setProgress([&progress, i, n](double f) { return progress((i + f) / n); });
        p.push_back(Session::rebuild(scene, choices[i].kind, o));
    }
    return p;
}

StructureChoice CompareWindow::choice(int i) const {
    const Session& s = *sessions_[i];
    return {s.kind(), s.options().split(s.kind())};
}

std::vector<StructureChoice> CompareWindow::choices() const {
    std::vector<StructureChoice> out;
    for (int i = 0; i < count(); ++i) out.push_back(choice(i));
    return out;
}

CompareWindow::CompareWindow(Prepared prepared, Pixel pixel, QWidget* parent) : QWidget(parent) {
    const int n = static_cast<int>(prepared.size());
    auto* views = new QHBoxLayout;
    int longest = 0;
    QStringList names, legend, legendTexts;
    for (int i = 0; i < n; ++i) {
        auto session = std::make_unique<Session>();
        session->adopt(std::move(prepared[i]));
        if (session->is2D())
            session->traceExampleRay();
        else
            session->tracePixel(pixel.x, pixel.y, pixel.width, pixel.height);
        longest = std::max(longest, static_cast<int>(session->size()));
        sessions_.push_back(std::move(session));
        names << choiceLabel(choice(i));
        auto* column = new QVBoxLayout;
        column->addWidget(
            new QLabel(QStringLiteral("<b>%1</b>").arg(names.back().toHtmlEscaped())));
        progress_.push_back(new QLabel);
        column->addWidget(progress_.back());
        // The titles say what each view is; a 2D legend would shrink one picture of the set,
        // so the 2D views share one under them, the 3D views' ray legend is in the first.
        Session& s = *sessions_.back();
        QWidget* view = nullptr;
        if (s.is2D()) {
            auto* v = new View2D(s);
            v->setLanguage(interfaceLanguage());
            v->setOverlays(/*caption=*/false, /*legend=*/false);
            for (const auto& [colour, text] : v->legendRows(/*build=*/false))
                if (!legendTexts.contains(text)) {
                    legendTexts << text;
                    legend << QStringLiteral("<span style='color:%1'>&#9632;</span>&nbsp;%2")
                                  .arg(colour.name(), text.toHtmlEscaped());
                }
            view = v;
        } else {
            auto* v = new VtkView(s);
            v->setLanguage(interfaceLanguage());
            v->setOverlays(/*caption=*/false, /*legend=*/i == 0);
            v->setButtonsShown(false);
            view = v;
        }
        view->setMinimumSize(260, 200);
        views_.push_back(view);
        column->addWidget(view, 1);
        views->addLayout(column, 1);
    }
    // The 3D views look the same way: whichever is turned, the others follow.
    for (QWidget* w : views_)
        if (auto* v = qobject_cast<VtkView*>(w))
            connect(v, &VtkView::cameraMoved, this, [this, v] {
                if (syncing_) return;
                syncing_ = true;
                for (QWidget* other : views_)
                    if (auto* o = qobject_cast<VtkView*>(other); o && o != v)
                        o->setCamera(v->currentCamera());
                syncing_ = false;
            });
    if (auto* lead = views_.empty() ? nullptr : qobject_cast<VtkView*>(views_.back())) {
        // The last view frames the set (the rest follow it): a grid's view would frame its
        // whole box, and the rays would be drawn small in every view.
        syncing_ = true;
        for (QWidget* other : views_)
            if (auto* o = qobject_cast<VtkView*>(other); o && o != lead)
                o->setCamera(lead->currentCamera());
        syncing_ = false;
    }
    setWindowTitle(tr("raystep - compare %1").arg(names.join(QStringLiteral(" | "))));
    slider_ = new QSlider(Qt::Horizontal);
    slider_->setRange(0, longest);
    connect(slider_, &QSlider::valueChanged, this, [this](int v) { setStep(v); });

    // The statistics of each structure (a grid's nodes and leaves are its cells), and of the
    // same ray through each.
    QStringList rows;
    rows << tr("build ms") << tr("nodes or cells") << tr("leaves or cells") << tr("max depth")
         << tr("references") << tr("SAH cost") << tr("ray: primitive tests")
         << tr("ray: nodes or cells visited") << tr("ray: mailbox skips") << tr("ray: events");
    Q_ASSERT(rows.size() == RowCount);
    table_ = new QTableWidget(rows.size(), n);
    table_->setVerticalHeaderLabels(rows);
    table_->setHorizontalHeaderLabels(names);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int i = 0; i < n; ++i) {
        const Session& s = *sessions_[i];
        const BuildSummary b = s.summary();
        std::size_t tests = 0, visits = 0, skips = 0;
        for (const Event& e : s.log().events()) {
            tests += std::holds_alternative<PrimitiveTest>(e);
            visits += std::holds_alternative<NodeEnter>(e) || std::holds_alternative<DdaCell>(e);
            skips += std::holds_alternative<MailboxSkip>(e);
        }
        // Only a tree has a SAH cost and a depth of its own (brute force's would be C_isect N).
        const bool tree = hasSplit(s.kind());
        const QString none = QStringLiteral("-");
        const QStringList values = {numberText(b.stats.buildMs, 'f', 2),
                                    QString::number(b.stats.nodes),
                                    QString::number(b.stats.leaves),
                                    tree ? QString::number(b.stats.maxDepth) : none,
                                    QString::number(b.stats.references),
                                    tree ? numberText(b.stats.sahCost, 'g', 5) : none,
                                    QString::number(tests),
                                    QString::number(visits),
                                    QString::number(skips),
                                    QString::number(s.size())};
        for (int r = 0; r < values.size(); ++r) {
            auto* item = new QTableWidgetItem(values[r]);
            item->setTextAlignment(Qt::AlignCenter);
            table_->setItem(r, i, item);
        }
    }
    table_->resizeRowsToContents();
    table_->setMinimumHeight(table_->horizontalHeader()->height() +
                             table_->rowHeight(0) * table_->rowCount() + 6);
    auto* layout = new QVBoxLayout(this);
    if (!sessions_.empty() && !sessions_[0]->is2D())
        layout->addWidget(new QLabel(
            tr("Rasterized by VTK: the same pixel's rays in each structure (drag to rotate a "
               "view)")));
    layout->addLayout(views, 1);
    if (!legend.isEmpty()) {
        auto* key = new QLabel(legend.join(QStringLiteral(" &nbsp; ")));
        key->setObjectName("compareLegend");
        key->setWordWrap(true);
        layout->addWidget(key);
    }
    auto* stepRow = new QHBoxLayout;
    if (auto* lead = views_.empty() ? nullptr : qobject_cast<VtkView*>(views_.back())) {
        // One pair of camera buttons for every view (each view's own would not fit four wide).
        auto* eye = new QPushButton(tr("View from the eye"));
        auto* beside = new QPushButton(tr("Beside the eye"));
        eye->setObjectName("compareFromEye");
        beside->setObjectName("compareBesideEye");
        connect(eye, &QPushButton::clicked, lead, &VtkView::viewFromEye);
        connect(beside, &QPushButton::clicked, lead, &VtkView::frameBesideEye);
        stepRow->addWidget(eye);
        stepRow->addWidget(beside);
    }
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

QString CompareWindow::progressText(int i) const {
    const Session& s = *sessions_[i];
    if (s.cursor() >= s.size()) return tr("all %1 events: the ray is done").arg(s.size());
    return tr("event %1 of %2").arg(s.cursor()).arg(s.size());
}

void CompareWindow::setStep(int n) {
    for (std::size_t i = 0; i < sessions_.size(); ++i) {
        sessions_[i]->setCursor(static_cast<std::size_t>(std::max(n, 0)));
        progress_[i]->setText(progressText(static_cast<int>(i)));
    }
}

}  // namespace raystep::gui
