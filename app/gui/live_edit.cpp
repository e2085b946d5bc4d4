// The 2D view's live editing (live_edit.h): its actions, their menus, the tool bar over the view.
#include "live_edit.h"
#include "file_dialogs.h"

#include "live2d.h"
#include "view2d.h"

#include <QAction>
#include <QEvent>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSplitter>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

namespace raystep::gui {

namespace {
/// Shows and hides `box` (the tool bar and the view) with the view: showViews hides the view.
class FollowVisibility : public QObject {
  public:
    FollowVisibility(QWidget* view, QWidget* box) : QObject(view), box_(box) {
        view->installEventFilter(this);
    }
    bool eventFilter(QObject* watched, QEvent* e) override {
        if (e->type() == QEvent::ShowToParent || e->type() == QEvent::HideToParent)
            box_->setVisible(!static_cast<QWidget*>(watched)->isHidden());
        return false;
    }

  private:
    QWidget* box_;
};
}  // namespace

LiveEdit::LiveEdit(QMainWindow& window, Session& session, View2D* view2D,
                   std::function<void(SceneRef)> showLive)
    : QObject(&window), window_(window), session_(session), view2D_(view2D) {
    live2d_ = new Live2D(session_, std::move(showLive), &window_);
    view2D_->setLive(live2d_);
    connect(live2d_, &Live2D::problem, this, [this](const QString& why) {
        window_.statusBar()->showMessage(tr("The edit was not applied: %1").arg(why));
    });
    QUndoStack* undo = live2d_->undoStack();
    QAction* undoAction = undo->createUndoAction(&window_, tr("&Undo"));
    undoAction->setObjectName("live2dUndoAction");
    undoAction->setShortcuts(QKeySequence::Undo);
    // The tool bar's button keeps one short label (the menu says what would be undone).
    undoAction->setIconText(tr("Undo"));
    QAction* redoAction = undo->createRedoAction(&window_, tr("&Redo"));
    redoAction->setObjectName("live2dRedoAction");
    redoAction->setIconText(tr("Redo"));
    redoAction->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});

    const auto action = [this](const QString& text, const QString& iconText, const char* name,
                               QKeySequence key, auto slot) {
        auto* a = new QAction(text, &window_);
        a->setIconText(iconText);
        a->setObjectName(QString::fromLatin1(name));
        if (!key.isEmpty()) a->setShortcut(key);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    // Where a new primitive goes: the middle of what the view shows, sized in pixels.
    const auto middle = [this] { return view2D_->worldOf(view2D_->rect().center()); };
    const auto pixels = [this](double n) {
        const QPointF c = view2D_->rect().center();
        return glm::length(view2D_->worldOf(c + QPointF(n, 0)) - view2D_->worldOf(c));
    };
    QAction* addCircle =
        action(tr("Add a &circle"), tr("+ Circle"), "live2dAddCircle", {}, [this, middle, pixels] {
            const Scene2D* s = live2d_->scene();
            if (!s) return;
            Scene2D edited = *s;
            edited.circles.push_back({middle(), pixels(30)});
            live2d_->apply(edited, tr("Add a circle"));
            view2D_->setSelected(std::uint32_t(edited.circles.size() - 1));
        });
    addCircle->setToolTip(tr("A circle in the middle of the 2D view: drag it, drag its rim"));
    QAction* addSegment = action(tr("Add a &segment"), tr("+ Segment"), "live2dAddSegment", {},
                                 [this, middle, pixels] {
                                     const Scene2D* s = live2d_->scene();
                                     if (!s) return;
                                     Scene2D edited = *s;
                                     const Vec2 c = middle(), half(pixels(60), 0.0);
                                     edited.segments.push_back({c - half, c + half});
                                     live2d_->apply(edited, tr("Add a segment"));
                                     view2D_->setSelected(edited.primitiveCount() - 1);
                                 });
    addSegment->setToolTip(tr("A segment in the middle of the 2D view: drag it, drag its ends"));
    QAction* remove =
        action(tr("&Delete the selected primitive"), tr("Delete"), "live2dDelete",
               QKeySequence::Delete, [this] {
                   const Scene2D* s = live2d_->scene();
                   const auto prim = view2D_->selected();
                   if (!s || !prim || *prim >= s->primitiveCount()) return;
                   if (s->primitiveCount() == 1) {
                       window_.statusBar()->showMessage(
                           tr("The last primitive stays: a scene needs one circle or segment"));
                       return;
                   }
                   Scene2D edited = *s;
                   if (s->isCircle(*prim))
                       edited.circles.erase(edited.circles.begin() + *prim);
                   else
                       edited.segments.erase(edited.segments.begin() + (*prim - s->circles.size()));
                   view2D_->setSelected(std::nullopt);
                   live2d_->apply(edited, s->isCircle(*prim) ? tr("Delete the circle")
                                                             : tr("Delete the segment"));
               });
    remove->setToolTip(
        tr("Ctrl+click a circle or segment (or drag it) to select it; Del deletes it"));
    remove->setEnabled(false);
    connect(view2D_, &View2D::selectionChanged, remove,
            [this, remove] { remove->setEnabled(view2D_->selected().has_value()); });
    QAction* snapCorners = action(tr("Snap to cell &corners and centres"), tr("Snap corners"),
                                  "live2dSnapCorners", {}, [] {});
    snapCorners->setCheckable(true);
    snapCorners->setToolTip(
        tr("Dragged points land on the grid's cell corners and centres: a ray from a centre "
           "through a corner shows the DDA's tie"));
    connect(snapCorners, &QAction::toggled, view2D_, &View2D::setSnapToCorners);
    QAction* snapAngle =
        action(tr("Snap the ray to &15 degrees"), tr("Snap 15°"), "live2dSnapAngle", {}, [] {});
    snapAngle->setCheckable(true);
    snapAngle->setToolTip(tr("The ray's direction turns in steps of 15 degrees"));
    connect(snapAngle, &QAction::toggled, view2D_, &View2D::setSnapToAngle);
    QAction* fit = action(tr("&Fit the 2D view"), tr("Fit"), "live2dFit", QKeySequence(Qt::Key_F),
                          [this] { view2D_->fitView(); });
    fit->setToolTip(
        tr("The whole scene in the 2D view (F). Wheel: zoom about the cursor; drag empty space: "
           "pan"));
    QAction* save2D = action(tr("Save &2D scene as..."), tr("Save 2D scene"), "live2dSave", {},
                             [this] { save2DSceneDialog(); });
    save2D->setToolTip(tr("Write the 2D scene as edited to a scene file (File > Open reads it)"));

    // Editing needs a 2D scene.
    const QList<QAction*> editing = {addCircle, addSegment, snapCorners, snapAngle, fit, save2D};
    const auto follow = [this, editing] {
        for (QAction* a : editing) a->setEnabled(session_.is2D());
        // The gesture that gives a scene its example ray, said where the user looks.
        if (const Scene2D* s = session_.scene2D(); s && !s->exampleRay)
            window_.statusBar()->showMessage(
                tr("This 2D scene has no example ray: Shift+drag in the 2D view draws one, from "
                   "where the drag starts to where it ends"));
    };
    connect(&session_, &Session::sceneChanged, this, follow);
    follow();

    undo_ = undoAction;
    redo_ = redoAction;
    addCircle_ = addCircle;
    addSegment_ = addSegment;
    remove_ = remove;
    snapCorners_ = snapCorners;
    snapAngle_ = snapAngle;
    fit_ = fit;
    save2D_ = save2D;
    placeToolBar();
}

void LiveEdit::newHistory() {
    live2d_->undoStack()->clear();
}

void LiveEdit::addFileItems(QMenu* file) {
    file->addAction(save2D_);
}

void LiveEdit::addEditItems(QMenu* edit) {
    edit->addActions({undo_, redo_});
    edit->addSeparator();
    edit->addActions({addCircle_, addSegment_, remove_});
    edit->addSeparator();
    edit->addActions({snapCorners_, snapAngle_});
}

void LiveEdit::addViewItems(QMenu* view) {
    view->addAction(fit_);
}

void LiveEdit::placeToolBar() {
    // The tool bar over the 2D view, in a box that takes the view's place in the splitter.
    auto* bar = new QToolBar(tr("2D editing"));
    bar->setObjectName("live2dBar");
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addActions({fit_, addCircle_, addSegment_, remove_});
    bar->addSeparator();
    bar->addActions({snapCorners_, snapAngle_});
    bar->addSeparator();
    bar->addActions({undo_, redo_});
    auto* splitter = qobject_cast<QSplitter*>(view2D_->parentWidget());
    auto* box = new QWidget;
    box->setObjectName("view2DBox");
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    if (splitter) {
        const int at = splitter->indexOf(view2D_);
        splitter->insertWidget(at, box);
        splitter->setStretchFactor(at, 3);
    }
    layout->addWidget(bar);
    layout->addWidget(view2D_, 1);
    new FollowVisibility(view2D_, box);
}

void LiveEdit::save2DSceneDialog() {
    QString path = saveFileName(&window_, tr("Save 2D scene as"), tr("2D scenes (*.json)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
    if (const QString problem = live2d_->save(path); !problem.isEmpty())
        QMessageBox::warning(&window_, tr("Cannot save"), problem);
    else {
        window_.statusBar()->showMessage(tr("Saved %1").arg(path));
        window_.setWindowTitle(tr("raystep - %1").arg(path));  // the scene shown is that file's now
    }
}

}  // namespace raystep::gui
