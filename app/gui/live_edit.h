#pragma once
// The 2D view's live editing: ray handles, adding, moving and deleting primitives, snapping, undo
// and redo, 2D scene files, and the view's fit. Its tool bar sits over the 2D view, shown with it.
#include "session.h"

#include <QObject>

#include <functional>

class QAction;
class QMainWindow;
class QMenu;

namespace raystep::gui {

class Live2D;
class View2D;

class LiveEdit : public QObject {
    Q_OBJECT
  public:
    /// `showLive` shows an edited scene at once (the window's live lecture mode).
    LiveEdit(QMainWindow& window, Session& session, View2D* view2D,
             std::function<void(SceneRef)> showLive);

    /// The scene edits and their undo stack.
    Live2D* live2D() const { return live2d_; }
    /// A new lesson: a new history, even on the same scene (an undo would bring back an edit
    /// made in the lesson left).
    void newHistory();

    /// File > Save 2D scene as.
    void addFileItems(QMenu* file);
    /// Edit > Undo, Redo, Add a circle or segment, Delete, the snaps.
    void addEditItems(QMenu* edit);
    /// View > Fit the 2D view.
    void addViewItems(QMenu* view);

  private:
    /// The tool bar over the 2D view, in a box that takes the view's place in its splitter.
    void placeToolBar();
    /// File > Save 2D scene as: asks where, then Live2D::save.
    void save2DSceneDialog();

    QMainWindow& window_;
    Session& session_;
    View2D* view2D_;
    Live2D* live2d_ = nullptr;
    QAction *undo_ = nullptr, *redo_ = nullptr, *addCircle_ = nullptr, *addSegment_ = nullptr,
            *remove_ = nullptr, *snapCorners_ = nullptr, *snapAngle_ = nullptr, *fit_ = nullptr,
            *save2D_ = nullptr;
};

}  // namespace raystep::gui
