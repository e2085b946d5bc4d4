// The live controls (structure and its parameters, with the statistics) and the board table.
#include "main_window.h"

#include "board_table.h"
#include "live_controls.h"
#include "presentation.h"

#include <QDockWidget>
#include <QMenu>
#include <QScrollArea>

#include <algorithm>

namespace raystep::gui {

void MainWindow::createBoard() {
    board_ = new BoardTable(session_);
    boardDock_ = new QDockWidget(tr("Board"), this);
    boardDock_->setObjectName("boardDock");  // saveState/restoreState need a name
    boardDock_->setWidget(board_);

    liveControls_ = new LiveControls(session_);
    // A short screen (a laptop) scrolls the controls rather than squeezing them.
    auto* scroll = new QScrollArea;
    scroll->setWidget(liveControls_);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    liveDock_ = new QDockWidget(tr("Live controls"), this);
    liveDock_->setObjectName("liveControlsDock");
    liveDock_->setWidget(scroll);

    // The right column keeps the window's height; the board and the controls go under the views.
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    addDockWidget(Qt::BottomDockWidgetArea, boardDock_);
    splitDockWidget(boardDock_, liveDock_, Qt::Horizontal);

    connect(liveControls_, &LiveControls::applyRequested, this,
            [this](AccelKind kind, const AccelOptions& options) { applyLive(kind, options); });
    // A build that failed (or was cancelled) leaves the scene as it was: so do the controls.
    connect(this, &MainWindow::structureChanged, this, [this](bool ok) {
        if (!ok) liveControls_->sync();
    });
    // Shown with a 2D scene, hidden with a 3D one (View > Board shows them there too); a user's
    // choice holds until the kind of scene changes.
    connect(&session_, &Session::sceneChanged, this, [this] {
        if (!session_.hasScene() || boardFor2D_ == session_.is2D()) return;
        boardFor2D_ = session_.is2D();
        boardDock_->setVisible(*boardFor2D_);
        liveDock_->setVisible(*boardFor2D_);
    });
    menus_.view->addSeparator();
    menus_.view->addAction(boardDock_->toggleViewAction());
    menus_.view->addAction(liveDock_->toggleViewAction());
}

void MainWindow::applyLive(AccelKind kind, const AccelOptions& options) {
    const Scene2D* s2 = session_.scene2D();
    if (s2 && s2->gridRes && readsOption(kind, AccelOption::GridRes) && !options.grid.res) {
        // Lambda's grid asked for: the scene's own grid would win over it (buildAccelerator2D),
        // so the scene is shown without it.
        Scene2D copy = *s2;
        copy.gridRes.reset();
        showLiveBuild([&] { return Session::prepare(std::move(copy), kind, options); });
        return;
    }
    applyStructure(kind, options);
}

void MainWindow::placeBoardDocks() {
    const bool shown = !session_.hasScene() || session_.is2D();
    for (QDockWidget* d : {boardDock_, liveDock_}) {
        d->setFloating(false);
        d->setVisible(shown);
    }
    addDockWidget(Qt::BottomDockWidgetArea, boardDock_);
    splitDockWidget(boardDock_, liveDock_, Qt::Horizontal);
    // A quarter of the height for about eight rows of the table; the controls a fixed column.
    dockZoom_ = presentation().zoomPercent();
    resizeDocks({boardDock_}, {defaultBottomDockHeight(height(), dockZoom_)}, Qt::Vertical);
    resizeDocks({liveDock_}, {std::clamp(width() / 5, 300, 360)}, Qt::Horizontal);
}

}  // namespace raystep::gui
