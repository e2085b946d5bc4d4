// Presenter mode (UI zoom, full screen, thicker lines, high contrast) and Help > Keyboard
// shortcuts (presenter_controls.h).
#include "presenter_controls.h"

#include "presentation.h"
#include "shortcuts.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QSignalBlocker>
#include <QStatusBar>

namespace raystep::gui {

PresenterControls::PresenterControls(QMainWindow& window) : QObject(&window), window_(window) {
    Presentation& p = presentation();
    // The zoom, presenter mode and palette the last run left (a new window starts as they were).
    p.restore();
    const auto action = [this](const QString& text, const char* name,
                               const QList<QKeySequence>& keys) {
        auto* act = new QAction(text, &window_);
        act->setObjectName(QString::fromLatin1(name));
        act->setShortcuts(keys);
        window_.addAction(act);  // works with the menus closed and in full screen
        return act;
    };
    // Ctrl+= too: on most keyboards + needs Shift, and Ctrl+= is the same key without it.
    zoomIn_ =
        action(tr("Zoom &in"), "zoomIn",
               {QKeySequence(Qt::CTRL | Qt::Key_Plus), QKeySequence(Qt::CTRL | Qt::Key_Equal)});
    zoomOut_ = action(tr("Zoom &out"), "zoomOut", {QKeySequence(Qt::CTRL | Qt::Key_Minus)});
    resetZoom_ =
        action(tr("&Actual size (zoom 100%)"), "resetZoom", {QKeySequence(Qt::CTRL | Qt::Key_0)});
    fullScreen_ = action(tr("F&ull screen"), "fullScreen", {QKeySequence(Qt::Key_F11)});
    fullScreen_->setCheckable(true);
    presenterMode_ =
        action(tr("&Presenter mode (thicker lines, larger labels)"), "presenterMode", {});
    presenterMode_->setCheckable(true);
    highContrast_ = action(tr("High con&trast palette"), "highContrast", {});
    highContrast_->setCheckable(true);
    // ? as typed: with Shift on most keyboards. A text box keeps the key (it types a ?).
    shortcutsAction_ = action(tr("&Keyboard shortcuts"), "keyboardShortcuts",
                              {QKeySequence(Qt::Key_F1), QKeySequence(Qt::Key_Question),
                               QKeySequence(Qt::SHIFT | Qt::Key_Question)});

    connect(zoomIn_, &QAction::triggered, &p, &Presentation::zoomIn);
    connect(zoomOut_, &QAction::triggered, &p, &Presentation::zoomOut);
    connect(resetZoom_, &QAction::triggered, &p, &Presentation::resetZoom);
    for (QAction* z : {zoomIn_, zoomOut_, resetZoom_})
        connect(z, &QAction::triggered, this, [this] {
            window_.statusBar()->showMessage(tr("Zoom %1%").arg(presentation().zoomPercent()),
                                             3000);
        });
    connect(fullScreen_, &QAction::triggered, this, [this] {
        // The maximised state is kept under the full screen one, for when it ends.
        window_.setWindowState(window_.windowState() ^ Qt::WindowFullScreen);
        syncActions();
    });
    connect(presenterMode_, &QAction::toggled, &p, &Presentation::setPresenterMode);
    connect(highContrast_, &QAction::toggled, &p, &Presentation::setHighContrast);
    connect(shortcutsAction_, &QAction::triggered, this, &PresenterControls::showShortcuts);
    connect(&p, &Presentation::changed, this, &PresenterControls::syncActions);
    syncActions();
}

void PresenterControls::addViewItems(QMenu* view) {
    view->addActions({zoomIn_, zoomOut_, resetZoom_, fullScreen_});
    view->addSeparator();
    view->addActions({presenterMode_, highContrast_});
}

void PresenterControls::addHelpItems(QMenu* help) {
    help->addAction(shortcutsAction_);
}

QList<QAction*> PresenterControls::sharedKeys() const {
    return {zoomIn_, zoomOut_, resetZoom_, shortcutsAction_};
}

void PresenterControls::syncActions() {
    const Presentation& p = presentation();
    for (auto [act, on] :
         {std::pair(presenterMode_, p.presenterMode()), std::pair(highContrast_, p.highContrast()),
          std::pair(fullScreen_, window_.isFullScreen())}) {
        const QSignalBlocker block(act);
        act->setChecked(on);
    }
    zoomIn_->setEnabled(p.zoomPercent() < Presentation::kZoomSteps.back());
    zoomOut_->setEnabled(p.zoomPercent() > Presentation::kZoomSteps.front());
}

void PresenterControls::showShortcuts() {
    // Made anew each time: the keys as they are now (an action added since is listed).
    if (shortcuts_) shortcuts_->close();
    auto* dialog = new ShortcutsDialog(window_, &window_);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    shortcuts_ = dialog;
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

ShortcutsDialog* PresenterControls::shortcutsDialog() const {
    return shortcuts_.data();
}

}  // namespace raystep::gui
