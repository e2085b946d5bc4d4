#pragma once
// The live lab's editable 2D scene (issue 19): every edit made in the 2D view (a ray handle
// dragged, a circle or segment moved, resized, added or deleted) becomes a new scene, built with
// the shown structure and options and shown at once (MainWindow::showLive: the walk or the build
// recorded again at the same step). One undo entry per gesture, on a QUndoStack.
#include "session.h"

#include <QObject>
#include <QUndoStack>

#include <functional>
#include <optional>

namespace raystep::gui {

/// Whether two 2D scenes have the same primitives and example ray (a structure rebuilt with
/// other options keeps them; an edit, or another scene, does not).
bool sameShapes(const Scene2D& a, const Scene2D& b);

class Live2D : public QObject {
    Q_OBJECT
  public:
    /// `show` shows a scene made from the edited one (the window's showLive).
    using ShowFn = std::function<void(SceneRef)>;
    Live2D(Session& session, ShowFn show, QObject* parent = nullptr);

    QUndoStack* undoStack() { return &undo_; }
    /// The shown 2D scene (what an edit starts from), or null in 3D.
    const Scene2D* scene() const { return session_.scene2D(); }
    /// True while this object shows one of its scenes: the view keeps its transform and the
    /// history stays. Any other scene shown (File > Open, a lesson, Esc) clears the history.
    bool changing() const { return changing_; }

    /// A gesture (a drag): begin remembers the scene, preview shows each frame of it, end puts
    /// one undo entry for the whole gesture (none if nothing changed), cancel goes back.
    void begin(const QString& what);
    void preview(const Scene2D& scene);
    void end();
    void cancel();
    bool inGesture() const { return before_.has_value(); }
    /// A one-step edit (add, delete): shown, and put on the undo stack.
    void apply(const Scene2D& scene, const QString& what);
    /// Shows `scene` as an edit of the shown one without a history entry (undo, redo, a frame).
    /// False (with problem() set) if its structure could not be built: nothing changes then.
    bool show(const Scene2D& scene);

    /// File > Save 2D scene as: the shown 2D scene written to `path` (*.json), atomically, with
    /// the grid resolution in force. The one-line problem, or an empty string.
    QString save(const QString& path) const;

  signals:
    /// An edit could not be shown (its structure was not built): why.
    void problem(const QString& why);

  private:
    Session& session_;
    ShowFn show_;
    QUndoStack undo_;
    bool changing_ = false;
    std::optional<Scene2D> before_;  // the scene at the start of a gesture
    QString gestureText_;
    Session::Step gestureStep_;    // the replay's step when the gesture began
    std::optional<Scene2D> last_;  // the scene this object last showed
};

}  // namespace raystep::gui
