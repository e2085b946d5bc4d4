#include "live2d.h"

#include "raystep/base/file_error.h"
#include "raystep/scene/scene2d_io.h"

#include <QUndoCommand>

#include <exception>

namespace raystep::gui {

bool sameShapes(const Scene2D& a, const Scene2D& b) {
    const auto sameRay = [](const std::optional<Ray2>& r, const std::optional<Ray2>& s) {
        return r.has_value() == s.has_value() &&
               (!r || (r->origin == s->origin && r->dir == s->dir));
    };
    if (a.circles.size() != b.circles.size() || a.segments.size() != b.segments.size() ||
        !sameRay(a.exampleRay, b.exampleRay))
        return false;
    for (std::size_t i = 0; i < a.circles.size(); ++i)
        if (a.circles[i].center != b.circles[i].center ||
            a.circles[i].radius != b.circles[i].radius)
            return false;
    for (std::size_t i = 0; i < a.segments.size(); ++i)
        if (a.segments[i].a != b.segments[i].a || a.segments[i].b != b.segments[i].b) return false;
    return true;
}

namespace {
/// One edit on the history: the scene before and after it.
class SceneEdit : public QUndoCommand {
  public:
    SceneEdit(Live2D& live, Scene2D before, Scene2D after, const QString& text, bool shown)
        : QUndoCommand(text),
          live_(live),
          before_(std::move(before)),
          after_(std::move(after)),
          shown_(shown) {}
    void undo() override { live_.show(before_); }
    void redo() override {
        // A gesture's last frame is already shown when it is pushed.
        if (shown_) {
            shown_ = false;
            return;
        }
        live_.show(after_);
    }

  private:
    Live2D& live_;
    Scene2D before_, after_;
    bool shown_;
};
}  // namespace

Live2D::Live2D(Session& session, ShowFn show, QObject* parent)
    : QObject(parent), session_(session), show_(std::move(show)), undo_(this) {
    undo_.setObjectName("live2dUndo");
    connect(&session_, &Session::sceneChanged, this, [this] {
        const Scene2D* s = session_.scene2D();
        // Another scene (not an edit of this one, nor a rebuild of it): a new history.
        if (!changing_ && !(s && last_ && sameShapes(*s, *last_))) {
            before_.reset();
            undo_.clear();
        }
        if (s)
            last_ = *s;
        else
            last_.reset();
    });
}

bool Live2D::show(const Scene2D& scene) {
    SceneRef ref;
    try {
        // The structure and options shown now (a live control may have changed them).
        ref = Session::prepare(scene, session_.kind(), session_.options());
    } catch (const std::exception& e) {
        emit problem(QString::fromStdString(e.what()));
        return false;
    }
    changing_ = true;
    show_(std::move(ref));
    changing_ = false;
    // A drag's frames all keep the step the replay was at when it began: a frame whose walk is
    // shorter must not move the cursor for the frames after it.
    if (before_) session_.seekStep(gestureStep_);
    return true;
}

void Live2D::begin(const QString& what) {
    if (const Scene2D* s = scene()) {
        before_ = *s;
        gestureText_ = what;
        gestureStep_ = session_.step();
    }
}

void Live2D::preview(const Scene2D& scene) {
    if (before_) show(scene);
}

void Live2D::end() {
    if (!before_) return;
    Scene2D before = std::move(*before_);
    before_.reset();
    const Scene2D* now = scene();
    if (!now || sameShapes(before, *now)) return;  // a drag that changed nothing
    undo_.push(new SceneEdit(*this, std::move(before), *now, gestureText_, true));
}

void Live2D::cancel() {
    if (!before_) return;
    const Scene2D before = std::move(*before_);
    before_.reset();
    show(before);
}

void Live2D::apply(const Scene2D& scene, const QString& what) {
    const Scene2D* now = this->scene();
    if (!now) return;
    undo_.push(new SceneEdit(*this, *now, scene, what, false));
}

QString Live2D::save(const QString& path) const {
    const Scene2D* s = scene();
    if (!s) return tr("Only a 2D scene is saved as a 2D scene file; the scene shown is 3D");
    if (!path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
        return tr("%1: the scene is written as a scene file; name it *.json").arg(path);
    Scene2D out = *s;
    // The grid drawn now, if a live control set its resolution.
    const AccelOptions o = session_.options();
    if (readsOption(session_.kind(), AccelOption::GridRes) && o.grid.res)
        out.gridRes = IVecN<2>((*o.grid.res)[0], (*o.grid.res)[1]);
    try {
        saveScene2D(out, path.toStdString());
    } catch (const std::exception& e) {
        return QString::fromStdString(printable(e.what(), 4096));
    }
    return {};
}

}  // namespace raystep::gui
