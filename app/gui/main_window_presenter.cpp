// Presenter mode (UI zoom, fullscreen, thicker lines, high contrast) and Help > Keyboard shortcuts.
#include "main_window.h"

#include "presentation.h"
#include "shortcuts.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QTimer>

namespace raystep::gui {

void MainWindow::createPresenter() {
    Presentation& p = presentation();
    // The zoom, presenter mode and palette the last run left (a new window starts as they were).
    p.restore();
    PresenterActions& a = presenterActions_;
    const auto action = [this](const QString& text, const char* name,
                               const QList<QKeySequence>& keys) {
        auto* act = new QAction(text, this);
        act->setObjectName(QString::fromLatin1(name));
        act->setShortcuts(keys);
        addAction(act);  // works with the menus closed and in full screen
        return act;
    };
    // Ctrl+= too: on most keyboards + needs Shift, and Ctrl+= is the same key without it.
    a.zoomIn =
        action(tr("Zoom &in"), "zoomIn",
               {QKeySequence(Qt::CTRL | Qt::Key_Plus), QKeySequence(Qt::CTRL | Qt::Key_Equal)});
    a.zoomOut = action(tr("Zoom &out"), "zoomOut", {QKeySequence(Qt::CTRL | Qt::Key_Minus)});
    a.resetZoom =
        action(tr("&Actual size (zoom 100%)"), "resetZoom", {QKeySequence(Qt::CTRL | Qt::Key_0)});
    a.fullScreen = action(tr("F&ull screen"), "fullScreen", {QKeySequence(Qt::Key_F11)});
    a.fullScreen->setCheckable(true);
    a.presenterMode =
        action(tr("&Presenter mode (thicker lines, larger labels)"), "presenterMode", {});
    a.presenterMode->setCheckable(true);
    a.highContrast = action(tr("High con&trast palette"), "highContrast", {});
    a.highContrast->setCheckable(true);
    // ? as typed: with Shift on most keyboards. A text box keeps the key (it types a ?).
    a.shortcuts = action(tr("&Keyboard shortcuts"), "keyboardShortcuts",
                         {QKeySequence(Qt::Key_F1), QKeySequence(Qt::Key_Question),
                          QKeySequence(Qt::SHIFT | Qt::Key_Question)});

    connect(a.zoomIn, &QAction::triggered, &p, &Presentation::zoomIn);
    connect(a.zoomOut, &QAction::triggered, &p, &Presentation::zoomOut);
    connect(a.resetZoom, &QAction::triggered, &p, &Presentation::resetZoom);
    for (QAction* z : {a.zoomIn, a.zoomOut, a.resetZoom})
        connect(z, &QAction::triggered, this, [this] {
            statusBar()->showMessage(tr("Zoom %1%").arg(presentation().zoomPercent()), 3000);
        });
    connect(a.fullScreen, &QAction::triggered, this, [this] {
        // The maximised state is kept under the full screen one, for when it ends.
        setWindowState(windowState() ^ Qt::WindowFullScreen);
        syncPresenterActions();
    });
    connect(a.presenterMode, &QAction::toggled, &p, &Presentation::setPresenterMode);
    connect(a.highContrast, &QAction::toggled, &p, &Presentation::setHighContrast);
    connect(a.shortcuts, &QAction::triggered, this, &MainWindow::showShortcuts);
    connect(&p, &Presentation::changed, this, &MainWindow::syncPresenterActions);
    // Once the new fonts have reached the widgets (posted events) and the window is laid out.
    connect(&p, &Presentation::changed, this,
            [this] { QTimer::singleShot(0, this, &MainWindow::fitBottomDocksToZoom); });
    syncPresenterActions();

    menus_.view->addSeparator();
    menus_.view->addActions({a.zoomIn, a.zoomOut, a.resetZoom, a.fullScreen});
    menus_.view->addSeparator();
    menus_.view->addActions({a.presenterMode, a.highContrast});
    menus_.help->addAction(a.shortcuts);
}

void MainWindow::syncPresenterActions() {
    const PresenterActions& a = presenterActions_;
    const Presentation& p = presentation();
    for (auto [act, on] :
         {std::pair(a.presenterMode, p.presenterMode()),
          std::pair(a.highContrast, p.highContrast()), std::pair(a.fullScreen, isFullScreen())}) {
        const QSignalBlocker block(act);
        act->setChecked(on);
    }
    a.zoomIn->setEnabled(p.zoomPercent() < Presentation::kZoomSteps.back());
    a.zoomOut->setEnabled(p.zoomPercent() > Presentation::kZoomSteps.front());
}

void MainWindow::fitBottomDocksToZoom() {
    const int zoom = presentation().zoomPercent();
    if (zoom == dockZoom_ || !layoutSettled_) return;
    dockZoom_ = zoom;
    // Only where the layout put them (a floated or moved dock is the user's).
    if (!boardDock_ || boardDock_->isFloating() ||
        dockWidgetArea(boardDock_) != Qt::BottomDockWidgetArea || !boardDock_->isVisible())
        return;
    resizeDocks({boardDock_}, {defaultBottomDockHeight(height(), zoom)}, Qt::Vertical);
}

void MainWindow::showShortcuts() {
    // Made anew each time: the keys as they are now (an action added since is listed).
    if (shortcuts_) shortcuts_->close();
    auto* dialog = new ShortcutsDialog(*this, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    shortcuts_ = dialog;
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

ShortcutsDialog* MainWindow::shortcutsDialog() const {
    return shortcuts_.data();
}

}  // namespace raystep::gui
