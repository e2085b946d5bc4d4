// The board table and the live controls, docked under the views (board_docks.h).
#include "board_docks.h"

#include "board_table.h"
#include "live_controls.h"
#include "presentation.h"
#include "window_layout.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QScrollArea>

#include <algorithm>

namespace raystep::gui {

BoardDocks::BoardDocks(QMainWindow& window, Session& session)
    : QObject(&window), window_(window), session_(session) {
    board_ = new BoardTable(session_);
    boardDock_ = new QDockWidget(tr("Board"), &window_);
    boardDock_->setObjectName("boardDock");  // saveState/restoreState need a name
    boardDock_->setWidget(board_);

    liveControls_ = new LiveControls(session_);
    // A short screen (a laptop) scrolls the controls rather than squeezing them.
    auto* scroll = new QScrollArea;
    scroll->setWidget(liveControls_);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    liveDock_ = new QDockWidget(tr("Live controls"), &window_);
    liveDock_->setObjectName("liveControlsDock");
    liveDock_->setWidget(scroll);

    // The right column keeps the window's height; the board and the controls go under the views.
    window_.setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    window_.addDockWidget(Qt::BottomDockWidgetArea, boardDock_);
    window_.splitDockWidget(boardDock_, liveDock_, Qt::Horizontal);

    // Shown with a 2D scene, hidden with a 3D one (View > Board shows them there too); a user's
    // choice holds until the kind of scene changes.
    connect(&session_, &Session::sceneChanged, this, [this] {
        if (!session_.hasScene() || boardFor2D_ == session_.is2D()) return;
        boardFor2D_ = session_.is2D();
        boardDock_->setVisible(*boardFor2D_);
        liveDock_->setVisible(*boardFor2D_);
    });
}

QList<QDockWidget*> BoardDocks::docks() const {
    return {boardDock_, liveDock_};
}

void BoardDocks::addViewItems(QMenu* view) {
    view->addAction(boardDock_->toggleViewAction());
    view->addAction(liveDock_->toggleViewAction());
}

void BoardDocks::show(bool board, bool live) {
    boardDock_->setVisible(board);
    liveDock_->setVisible(live);
}

void BoardDocks::showBoard() {
    boardDock_->setVisible(true);
}

void BoardDocks::place() {
    const bool shown = !session_.hasScene() || session_.is2D();
    for (QDockWidget* d : {boardDock_, liveDock_}) {
        d->setFloating(false);
        d->setVisible(shown);
    }
    window_.addDockWidget(Qt::BottomDockWidgetArea, boardDock_);
    window_.splitDockWidget(boardDock_, liveDock_, Qt::Horizontal);
    // A quarter of the height for about eight rows of the table; the controls a fixed column.
    dockZoom_ = presentation().zoomPercent();
    window_.resizeDocks({boardDock_},
                        {WindowLayout::defaultBottomDockHeight(window_.height(), dockZoom_)},
                        Qt::Vertical);
    window_.resizeDocks({liveDock_}, {std::clamp(window_.width() / 5, 300, 360)}, Qt::Horizontal);
}

void BoardDocks::fitToZoom() {
    const int zoom = presentation().zoomPercent();
    if (zoom == dockZoom_) return;
    dockZoom_ = zoom;
    // Only where the layout put them (a floated or moved dock is the user's).
    if (boardDock_->isFloating() ||
        window_.dockWidgetArea(boardDock_) != Qt::BottomDockWidgetArea || !boardDock_->isVisible())
        return;
    window_.resizeDocks({boardDock_},
                        {WindowLayout::defaultBottomDockHeight(window_.height(), zoom)},
                        Qt::Vertical);
}

}  // namespace raystep::gui
