#pragma once
// The docks under the views: the board table and the live controls (structure and parameters,
// with the statistics). Shown with a 2D scene, hidden beside the 3D view and image.
#include "session.h"

#include <QObject>

#include <optional>

class QDockWidget;
class QMainWindow;
class QMenu;

namespace raystep::gui {

class BoardTable;
class LiveControls;

class BoardDocks : public QObject {
    Q_OBJECT
  public:
    BoardDocks(QMainWindow& window, Session& session);

    BoardTable* boardTable() const { return board_; }
    LiveControls* liveControls() const { return liveControls_; }
    /// The two docks (the layout places the others, and these with place()).
    QList<QDockWidget*> docks() const;
    /// View > Board and Live controls.
    void addViewItems(QMenu* view);
    /// A lesson's choice: the board and the live controls shown or not.
    void show(bool board, bool live);
    /// The board shown, the live controls as they are (a student's trace compared on it).
    void showBoard();
    /// View > Reset layout's part: the board and the live controls under the views, side by side.
    void place();
    /// After a zoom: the docks under the views at the zoom's height (defaultBottomDockHeight).
    void fitToZoom();

  private:
    QMainWindow& window_;
    Session& session_;
    BoardTable* board_ = nullptr;
    LiveControls* liveControls_ = nullptr;
    QDockWidget *boardDock_ = nullptr, *liveDock_ = nullptr;
    /// Whether the docks were last shown for a 2D scene (they follow the kind of scene: shown
    /// with the lecture's 2D pictures, hidden beside the 3D view and image, which need the room).
    std::optional<bool> boardFor2D_;
    int dockZoom_ = 100;  // the zoom the docks under the views were last fitted for
};

}  // namespace raystep::gui
