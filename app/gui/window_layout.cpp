// The main window's layout: its size and docks remembered between runs (QSettings), sized for
// the screen it opens on (a student's 1366x768 laptop, a 1920x1080 projector), and View > Reset
// layout. The window's parts are made in main_window.cpp; this file only sizes them.
#include "main_window.h"

#include "lesson_panel.h"
#include "vtk_view.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QScreen>
#include <QSettings>
#include <QShowEvent>
#include <QSplitter>
#include <QTimer>

#include <algorithm>

namespace raystep::gui {

namespace {
// Narrower than this a dock shows "test p..." and nothing else: the layout refuses it.
constexpr int kDockMinWidth = 180;
constexpr int kLessonMinWidth = 300;
// A saved dock narrower than this share of its default is a leftover of a small window.
constexpr double kDockShrunk = 0.8;

int clampedShare(int total, double share, int lo, int hi) {
    return std::clamp(static_cast<int>(total * share), lo, hi);
}
}  // namespace

int MainWindow::defaultLessonWidth(int windowWidth) {
    return clampedShare(windowWidth, 0.25, 300, 500);
}

int MainWindow::defaultDockWidth(int windowWidth) {
    return clampedShare(windowWidth, 0.2, 220, 420);
}

int MainWindow::defaultBottomDockHeight(int windowHeight, int zoomPercent) {
    // About eight rows of the table at 100%; zoomed, the rows grow and fewer fit (the views are
    // what the room looks at, and the chrome over and under them has grown too).
    const int h = clampedShare(windowHeight, 0.27, 170, 330);
    return zoomPercent > 100 ? h * 100 / zoomPercent : h;
}

void MainWindow::sizeForScreen() {
    if (!geometryRestored_) {
        // On a projector most of the screen (the back rows read it), on a laptop all of it.
        const QSize room = screen() ? screen()->availableGeometry().size() : QSize(1500, 900);
        resize(fitToScreen(QSize(1500, 900).expandedTo(room * 0.9)));
        return;
    }
    if (isMaximized() || isFullScreen() || !screen()) return;
    // A size saved on a larger screen (a projector), opened on a laptop: clamped, and moved
    // back onto the screen if it hung off it (Qt's restoreGeometry alone does neither here).
    QRect g = geometry();
    g.setSize(fitToScreen(g.size()));
    const QRect room = screen()->availableGeometry();
    const auto inside = [](int at, int lo, int span, int room) {
        return std::clamp(at, lo, lo + std::max(room - span, 0));
    };
    g.moveTo(inside(g.x(), room.x(), g.width(), room.width()),
             inside(g.y(), room.y(), g.height() + 40, room.height()));  // + the title bar
    setGeometry(g);
}

QList<QSplitter*> MainWindow::layoutSplitters() const {
    // The lesson panel beside the views; the 2D view beside the 3D view and image; those two.
    return {qobject_cast<QSplitter*>(centralWidget()), qobject_cast<QSplitter*>(views_),
            qobject_cast<QSplitter*>(view3D_->parentWidget())};
}

void MainWindow::addLayoutActions(QMenu* view) {
    resetLayout_ = new QAction(tr("Reset &layout"), this);
    resetLayout_->setObjectName("resetLayout");
    resetLayout_->setToolTip(
        tr("Docks and panels back to their places and default sizes for this window"));
    connect(resetLayout_, &QAction::triggered, this, [this] { resetLayout(); });
    view->addSeparator();
    view->addAction(resetLayout_);
    for (QDockWidget* d : findChildren<QDockWidget*>()) d->setMinimumWidth(kDockMinWidth);
    // The exercise box's header ("< Exercise 1 / 9 > Put away") needs this much, or is cut.
    lesson_->setMinimumWidth(std::max(lesson_->minimumWidth(), kLessonMinWidth));
}

void MainWindow::restoreLayout() {
    QSettings settings;
    // Qt's restoreGeometry clamps a size saved on a larger screen to this one's.
    geometryRestored_ = restoreGeometry(settings.value("window/geometry").toByteArray());
    stateRestored_ = restoreState(settings.value("window/state").toByteArray());
    const QList<QByteArray> saved = [&] {
        QList<QByteArray> l;
        for (const QVariant& v : settings.value("window/splitters").toList()) l << v.toByteArray();
        return l;
    }();
    const QList<QSplitter*> splitters = layoutSplitters();
    if (saved.size() == splitters.size())
        for (int i = 0; i < splitters.size(); ++i)
            if (splitters[i]) splitters[i]->restoreState(saved[i]);
}

void MainWindow::saveLayout() {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    QVariantList states;
    for (QSplitter* s : layoutSplitters()) states << (s ? s->saveState() : QByteArray());
    settings.setValue("window/splitters", states);
}

void MainWindow::showEvent(QShowEvent* e) {
    QMainWindow::showEvent(e);
    // Once the window has its size (the event loop has laid it out): the docks' sizes follow.
    if (!layoutSettled_) QTimer::singleShot(0, this, [this] { settleLayout(); });
}

void MainWindow::settleLayout() {
    if (layoutSettled_) return;
    layoutSettled_ = true;
    if (!stateRestored_) {
        resetLayout();
    } else {
        const int wanted = defaultDockWidth(width());
        QList<QDockWidget*> narrow;
        QList<int> widths;
        for (QDockWidget* d : findChildren<QDockWidget*>())
            if (d->isVisible() && !d->isFloating() && d->width() < kDockShrunk * wanted) {
                narrow << d;
                widths << wanted;
            }
        if (!narrow.isEmpty()) resizeDocks(narrow, widths, Qt::Horizontal);
    }
    emit layoutReady();
}

void MainWindow::resetLayout() {
    QList<QDockWidget*> docks = findChildren<QDockWidget*>();
    // The board and the live controls have their place under the views (placeBoardDocks).
    docks.removeAll(boardDock_);
    docks.removeAll(liveDock_);
    // Made in this order by createDocks: the inspector above the event list, on the right.
    for (QDockWidget* d : docks) {
        d->setFloating(false);
        addDockWidget(Qt::RightDockWidgetArea, d, Qt::Vertical);
        d->show();
    }
    const int w = width();
    const int dock = defaultDockWidth(w), lesson = defaultLessonWidth(w);
    resizeDocks(docks, QList<int>(docks.size(), dock), Qt::Horizontal);
    if (docks.size() == 2) {
        const int h = std::max(height() - 120, 200);
        resizeDocks(docks, {h * 2 / 5, h * 3 / 5}, Qt::Vertical);
    }
    const QList<QSplitter*> s = layoutSplitters();
    const int centre = std::max(w - lesson - dock - 24, 400);
    if (s[0]) s[0]->setSizes({lesson, centre});
    if (s[1]) s[1]->setSizes({centre * 3 / 5, centre * 2 / 5});
    if (s[2]) s[2]->setSizes({1000, 1000});  // the 3D view and the image, half and half
    placeBoardDocks();
}

}  // namespace raystep::gui
