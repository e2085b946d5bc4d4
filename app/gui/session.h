#pragma once
// What the app shows: a scene (3D or one of the lecture's 2D pictures), its structure, a recorded
// log and the replay cursor over it. The views draw from it; they own no algorithm.
#include "raystep/accel.h"
#include "raystep/replay.h"
#include "raystep/scene.h"
#include "raystep/scene2d.h"

#include <QImage>
#include <QObject>

#include <memory>
#include <optional>
#include <string>
#include <variant>

namespace raystep::gui {

class Session : public QObject {
    Q_OBJECT
  public:
    /// A scene loaded and its structure built, ready to be shown. The scene lives on the heap so
    /// the structure's pointers to it survive the move into the session.
    struct Prepared {
        std::unique_ptr<std::variant<Scene, Scene2D>> scene;
        std::optional<Accelerator> accel3D;
        std::optional<Accelerator2D> accel2D;
        std::string name;
        AccelKind kind = AccelKind::Grid;
        AccelOptions options;
    };
    /// Loads and builds; safe on any thread (the window runs it off the GUI thread with a
    /// progress dialog). Throws SceneError, or BuildCancelled when the options' progress says stop.
    static Prepared prepare(const std::string& nameOrPath, AccelKind kind,
                            const AccelOptions& options = {});
    /// Shows a prepared scene (GUI thread).
    void adopt(Prepared prepared);
    /// prepare + adopt, on this thread.
    void load(const std::string& nameOrPath, AccelKind kind, const AccelOptions& options = {});
    /// A 2D scene made in code (benchmarks, tests), with its structure.
    void load(Scene2D scene, AccelKind kind, const AccelOptions& options = {});
    /// 3D: records pixel (x, y) of a `width` x `height` image; 2D: the scene's example ray.
    void tracePixel(int x, int y, int width, int height);
    void traceExampleRay();
    /// Records the structure's construction (kd-tree or BVH; 2D or 3D) and replays that instead.
    void recordBuild();
    /// Replays a log recorded elsewhere (a lesson's trace); `isBuild` when it is a build.
    void adoptLog(std::unique_ptr<EventLog> log, bool isBuild);
    const std::variant<Scene, Scene2D>& sceneVariant() const { return *scene_; }
    /// True while the log is a build (candidates, splits, leaves), not a ray.
    bool showingBuild() const { return showingBuild_; }

    bool is2D() const { return std::holds_alternative<Scene2D>(*scene_); }
    const Scene* scene3D() const { return std::get_if<Scene>(scene_.get()); }
    const Scene2D* scene2D() const { return std::get_if<Scene2D>(scene_.get()); }
    const Accelerator2D* accel2D() const { return accel2D_ ? &*accel2D_ : nullptr; }
    const Accelerator* accel3D() const { return accel3D_ ? &*accel3D_ : nullptr; }
    AccelKind kind() const { return kind_; }
    const AccelOptions& options() const { return options_; }
    /// What the structure's build made.
    BuildSummary summary() const;
    const std::string& name() const { return name_; }

    const EventLog& log() const { return *log_; }
    std::size_t size() const { return replay_ ? replay_->size() : 0; }
    std::size_t cursor() const { return cursor_; }
    const ReplayState& state() const { return replay_->state(); }
    const Replay& replay() const { return *replay_; }

  public slots:
    /// Moves the replay cursor (clamped) and tells the views.
    void setCursor(std::size_t cursor);

  signals:
    void aboutToChangeScene();  // views stop work that reads the old scene
    void sceneChanged();
    void logChanged();
    void cursorChanged(std::size_t cursor);

  private:
    void setLog(std::unique_ptr<EventLog> log);

    std::unique_ptr<std::variant<Scene, Scene2D>> scene_ =
        std::make_unique<std::variant<Scene, Scene2D>>();
    std::string name_;
    AccelKind kind_ = AccelKind::Grid;
    AccelOptions options_;
    std::optional<Accelerator> accel3D_;
    std::optional<Accelerator2D> accel2D_;
    std::unique_ptr<EventLog> log_ = std::make_unique<EventLog>();
    std::unique_ptr<Replay> replay_ = std::make_unique<Replay>(*log_);
    std::size_t cursor_ = 0;
    bool showingBuild_ = false;
};

/// One line describing event `i` of the log, for the event list.
QString describeEvent(const Event& e);
/// The inspector's text: the current event and the algorithm's variables.
QString describeState(const Session& s);

}  // namespace raystep::gui
