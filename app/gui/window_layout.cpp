// The main window's layout: its size and docks remembered between runs (QSettings), sized for
// the screen it opens on (a student's 1366x768 laptop, a 1920x1080 projector), and View > Reset
// layout (window_layout.h). The window's parts are made elsewhere; this file only sizes them.
#include "window_layout.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QScreen>
#include <QSettings>
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

int WindowLayout::defaultLessonWidth(int windowWidth) {
    return clampedShare(windowWidth, 0.25, 300, 500);
}

int WindowLayout::defaultDockWidth(int windowWidth) {
    return clampedShare(windowWidth, 0.2, 220, 420);
}

int WindowLayout::defaultBottomDockHeight(int windowHeight, int zoomPercent) {
    // About eight rows of the table at 100%; zoomed, the rows grow and fewer fit (the views are
    // what the room looks at, and the chrome over and under them has grown too).
    const int h = clampedShare(windowHeight, 0.27, 170, 330);
    return zoomPercent > 100 ? h * 100 / zoomPercent : h;
}

void WindowLayout::sizeForScreen() {
    if (!geometryRestored_) {
        // On a projector most of the screen (the back rows read it), on a laptop all of it.
        const QScreen* s = window_.screen();
        const QSize room = s ? s->availableGeometry().size() : QSize(1500, 900);
        window_.resize(fitToScreen(QSize(1500, 900).expandedTo(room * 0.9)));
        return;
    }
    if (window_.isMaximized() || window_.isFullScreen() || !window_.screen()) return;
    // A size saved on a larger screen (a projector), opened on a laptop: clamped, and moved
    // back onto the screen if it hung off it (Qt's restoreGeometry alone does neither here).
    QRect g = window_.geometry();
    g.setSize(fitToScreen(g.size()));
    const QRect room = window_.screen()->availableGeometry();
    const auto inside = [](int at, int lo, int span, int room) {
        return std::clamp(at, lo, lo + std::max(room - span, 0));
    };
    g.moveTo(inside(g.x(), room.x(), g.width(), room.width()),
             inside(g.y(), room.y(), g.height() + 40, room.height()));  // + the title bar
    window_.setGeometry(g);
}

WindowLayout::WindowLayout(QMainWindow& window, QList<QSplitter*> splitters, QWidget* lessonPanel,
                           QList<QDockWidget*> bottomDocks, std::function<void()> placeBottomDocks)
    : QObject(&window),
      window_(window),
      splitters_(std::move(splitters)),
      bottomDocks_(std::move(bottomDocks)),
      placeBottomDocks_(std::move(placeBottomDocks)) {
    reset_ = new QAction(tr("Reset &layout"), &window_);
    reset_->setObjectName("resetLayout");
    reset_->setToolTip(
        tr("Docks and panels back to their places and default sizes for this window"));
    connect(reset_, &QAction::triggered, this, [this] { reset(); });
    // The docks on the right (the ones under the views keep their own width).
    for (QDockWidget* d : window_.findChildren<QDockWidget*>())
        if (!bottomDocks_.contains(d)) d->setMinimumWidth(kDockMinWidth);
    // The exercise box's header ("< Exercise 1 / 9 > Put away") needs this much, or is cut.
    lessonPanel->setMinimumWidth(std::max(lessonPanel->minimumWidth(), kLessonMinWidth));
}

void WindowLayout::addViewItems(QMenu* view) {
    view->addAction(reset_);
}

QSize WindowLayout::fitToScreen(QSize wanted) const {
    const QScreen* s = window_.screen();
    if (!s) return wanted;
    const QSize room = s->availableGeometry().size() - QSize(40, 60);  // frame and title bar
    return wanted.boundedTo(room.expandedTo(QSize(640, 480)));
}

void WindowLayout::restore() {
    QSettings settings;
    // Qt's restoreGeometry clamps a size saved on a larger screen to this one's.
    geometryRestored_ = window_.restoreGeometry(settings.value("window/geometry").toByteArray());
    stateRestored_ = window_.restoreState(settings.value("window/state").toByteArray());
    const QList<QByteArray> saved = [&] {
        QList<QByteArray> l;
        for (const QVariant& v : settings.value("window/splitters").toList()) l << v.toByteArray();
        return l;
    }();
    if (saved.size() == splitters_.size())
        for (int i = 0; i < splitters_.size(); ++i)
            if (splitters_[i]) splitters_[i]->restoreState(saved[i]);
}

void WindowLayout::save() {
    QSettings settings;
    settings.setValue("window/geometry", window_.saveGeometry());
    settings.setValue("window/state", window_.saveState());
    QVariantList states;
    for (QSplitter* s : splitters_) states << (s ? s->saveState() : QByteArray());
    settings.setValue("window/splitters", states);
}

void WindowLayout::shown() {
    // Once the window has its size (the event loop has laid it out): the docks' sizes follow.
    if (!settled_) QTimer::singleShot(0, this, [this] { settle(); });
}

void WindowLayout::settle() {
    if (settled_) return;
    settled_ = true;
    if (!stateRestored_) {
        reset();
    } else {
        const int wanted = defaultDockWidth(window_.width());
        QList<QDockWidget*> narrow;
        QList<int> widths;
        for (QDockWidget* d : window_.findChildren<QDockWidget*>())
            if (d->isVisible() && !d->isFloating() && d->width() < kDockShrunk * wanted) {
                narrow << d;
                widths << wanted;
            }
        if (!narrow.isEmpty()) window_.resizeDocks(narrow, widths, Qt::Horizontal);
    }
    emit ready();
}

void WindowLayout::reset() {
    QList<QDockWidget*> docks = window_.findChildren<QDockWidget*>();
    // The board and the live controls have their place under the views (placeBottomDocks_).
    for (QDockWidget* d : bottomDocks_) docks.removeAll(d);
    // Made in this order by createDocks: the inspector above the event list, on the right.
    for (QDockWidget* d : docks) {
        d->setFloating(false);
        window_.addDockWidget(Qt::RightDockWidgetArea, d, Qt::Vertical);
        d->show();
    }
    const int w = window_.width();
    const int dock = defaultDockWidth(w), lesson = defaultLessonWidth(w);
    window_.resizeDocks(docks, QList<int>(docks.size(), dock), Qt::Horizontal);
    if (docks.size() == 2) {
        const int h = std::max(window_.height() - 120, 200);
        window_.resizeDocks(docks, {h * 2 / 5, h * 3 / 5}, Qt::Vertical);
    }
    const QList<QSplitter*>& s = splitters_;
    const int centre = std::max(w - lesson - dock - 24, 400);
    if (s[0]) s[0]->setSizes({lesson, centre});
    if (s[1]) s[1]->setSizes({centre * 3 / 5, centre * 2 / 5});
    if (s[2]) s[2]->setSizes({1000, 1000});  // the 3D view and the image, half and half
    placeBottomDocks_();
}

}  // namespace raystep::gui
