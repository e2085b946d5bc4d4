#pragma once
// What the app shows: a scene (3D or one of the lecture's 2D pictures), its structure, a recorded
// log and the replay cursor over it. The views draw from it; they own no algorithm.
#include "raystep/accel/accel.h"
#include "raystep/accel/outline.h"
#include "raystep/render/tracer.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/replay.h"

#include <QImage>
#include <QObject>

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <variant>

namespace raystep::gui {

/// A scene loaded and its structure built: immutable once made, and shared by the session, the
/// views and every worker that reads it, so none of them can outlive it. The structure points
/// into the scene, so neither is ever moved or copied.
struct LoadedScene {
    LoadedScene() = default;
    LoadedScene(const LoadedScene&) = delete;
    LoadedScene& operator=(const LoadedScene&) = delete;

    std::variant<Scene, Scene2D> scene;
    // The built structure, 2D or 3D (as the core's assessor of a student's trace takes it).
    AnyStructure structure;
    // The structure's outline, made with it (once per structure: the views draw from it).
    std::optional<StructureOutline<3>> outline3D;
    std::optional<StructureOutline<2>> outline2D;
    std::string name;
    AccelKind kind = AccelKind::Grid;
    AccelOptions options;

    bool is2D() const { return std::holds_alternative<Scene2D>(scene); }
};
using SceneRef = std::shared_ptr<const LoadedScene>;
/// A recorded log, shared by whoever replays or grades it (the session, the lesson panel).
using LogRef = std::shared_ptr<const EventLog>;

/// What the replayed log is, for the window to say.
enum class LogKind { None, ExampleRay, Pixel, Build, Lesson, StudentRay };

class Session : public QObject {
    Q_OBJECT
  public:
    /// Loads (a built-in scene, a scene file or a model: model_import.h) and builds; safe on any
    /// thread (the window runs it on a worker). Throws SceneError, or BuildCancelled when the
    /// options' progress says stop.
    static SceneRef prepare(const std::string& nameOrPath, AccelKind kind,
                            const AccelOptions& options = {});
    /// The scene of `from` (3D or 2D) with another structure built over a copy of it; any thread.
    /// Throws BuildCancelled when the options' progress says stop.
    static SceneRef rebuild(const SceneRef& from, AccelKind kind, const AccelOptions& options);
    /// The same for a 2D scene made in code (benchmarks, tests).
    static SceneRef prepare(Scene2D scene, AccelKind kind, const AccelOptions& options = {});
    /// The same for a 3D scene made in code (tests).
    static SceneRef prepare(Scene scene, AccelKind kind, const AccelOptions& options = {});
    /// Records the construction of the scene's structure (kd-tree or BVH; 2D or 3D); any thread.
    /// Throws BuildCancelled when `progress` says stop.
    static LogRef recordBuild(const SceneRef& scene, const ProgressFn& progress = {});
    /// Whether the structure has a construction to replay (its row in structure_info.h).
    static bool hasBuild(AccelKind kind) { return recordsBuild(kind); }

    /// Shows a prepared scene (GUI thread), with an empty log.
    void adopt(SceneRef scene);
    /// prepare + adopt, on this thread.
    void load(const std::string& nameOrPath, AccelKind kind, const AccelOptions& options = {});
    void load(Scene2D scene, AccelKind kind, const AccelOptions& options = {});
    /// 3D: records pixel (x, y) of a `width` x `height` image; 2D: the scene's example ray.
    void tracePixel(int x, int y, int width, int height);
    /// The same seen by another camera with other trace settings (an image of the 3D view's).
    void tracePixel(int x, int y, int width, int height, const Camera& camera,
                    const TraceSettings& settings);
    void traceExampleRay();
    /// recordBuild on this thread, then replays it.
    void recordBuild();
    /// Replays a log recorded elsewhere (a lesson's trace, a build made by a worker).
    void showLog(LogRef log, LogKind kind);
    /// Live lecture mode (GUI thread): shows `scene`, the shown one edited or rebuilt with other
    /// options, and records again what was replayed: the build if a build was shown, else (2D)
    /// the scene's example ray. The cursor stays at the same step: after as many events of the
    /// kind just replayed as before (the end if the new log has fewer).
    void relive(SceneRef scene);
    /// A replay's step, as a log of the same kind has it again: after the n-th event of a kind
    /// (none: at the start).
    struct Step {
        std::optional<std::size_t> kind;
        std::size_t nth = 0;
    };
    /// Where the cursor is, as a step.
    Step step() const;
    /// The cursor after the step's event in the log replayed now (its end if the log has fewer).
    void seekStep(const Step& at);

    const SceneRef& sceneRef() const { return scene_; }
    const std::variant<Scene, Scene2D>& sceneVariant() const { return scene_->scene; }
    /// True while the log is a build (candidates, splits, leaves), not a ray.
    bool showingBuild() const { return logKind_ == LogKind::Build; }
    LogKind logKind() const { return logKind_; }

    bool hasScene() const { return scene_ != nullptr; }
    bool is2D() const { return scene_ && scene_->is2D(); }
    const Scene* scene3D() const { return scene_ ? std::get_if<Scene>(&scene_->scene) : nullptr; }
    const Scene2D* scene2D() const {
        return scene_ ? std::get_if<Scene2D>(&scene_->scene) : nullptr;
    }
    const Accelerator2D* accel2D() const {
        return scene_ && scene_->structure.in2D ? &*scene_->structure.in2D : nullptr;
    }
    const Accelerator* accel3D() const {
        return scene_ && scene_->structure.in3D ? &*scene_->structure.in3D : nullptr;
    }
    /// The shown structure's outline (2D or 3D), made once when it was built: the same object
    /// for as long as the structure is shown, a new one with each new structure.
    const StructureOutline<2>* outline2D() const {
        return scene_ && scene_->outline2D ? &*scene_->outline2D : nullptr;
    }
    const StructureOutline<3>* outline3D() const {
        return scene_ && scene_->outline3D ? &*scene_->outline3D : nullptr;
    }
    AccelKind kind() const { return scene_ ? scene_->kind : AccelKind::Grid; }
    AccelOptions options() const { return scene_ ? scene_->options : AccelOptions{}; }
    /// What the structure's build made.
    BuildSummary summary() const;
    std::string name() const { return scene_ ? scene_->name : std::string(); }

    const EventLog& log() const { return *log_; }
    const LogRef& logRef() const { return log_; }
    std::size_t size() const { return replay_->size(); }
    /// Quiz mode: `log` (a lesson's trace) is held at `limit` (a held exercise's position):
    /// while it is replayed the cursor stays at or before the limit and nothing past it is
    /// shown; while another trace is replayed (a pixel clicked, a structure changed, a ray
    /// dragged) none of that one is shown, since a trace beside the lesson's holds the same
    /// answers. nullopt lifts the hold.
    void setLimit(const LogRef& log, std::optional<std::size_t> limit);
    /// Whether a lesson's trace is held (an exercise waits for its answer).
    bool held() const { return limit_.has_value(); }
    /// Whether the held trace is a build: its answers are the tree's planes, which no view
    /// draws whole while it holds.
    bool holdsBuild() const { return limit_ && limitIsBuild_; }
    /// The limit on the log replayed now, if it has one that hides events (0 for a trace other
    /// than the held one).
    std::optional<std::size_t> limit() const;
    /// How far the cursor may go: the limit, else the end of the log.
    std::size_t end() const { return limit().value_or(size()); }
    /// Presenting mode: while a question to the room is open, nothing past the cursor is shown
    /// (the event list's later rows, the counts of the whole trace), though the cursor is free.
    void setHideAhead(bool on);
    /// Whether a question to the room hides what lies past the cursor (presenting mode).
    bool hidesAhead() const { return hideAhead_; }
    /// Whether part of the log is not shown now (a quiz limit, or hidden ahead).
    bool hiding() const { return shownEvents().size() < size(); }
    /// What may be shown of the replayed log: its events before end(), and before the cursor
    /// while hiding ahead. Every view, list and count that reads past the cursor reads this,
    /// never the whole log.
    std::span<const Event> shownEvents() const {
        return std::span<const Event>(log_->events())
            .first(hideAhead_ ? std::min(cursor_, end()) : end());
    }
    std::size_t cursor() const { return cursor_; }
    const ReplayState& state() const { return replay_->state(); }
    const Replay& replay() const { return *replay_; }

  public slots:
    /// Moves the replay cursor (clamped) and tells the views.
    void setCursor(std::size_t cursor);

  signals:
    void aboutToChangeScene();
    void sceneChanged();
    void logChanged();
    void cursorChanged(std::size_t cursor);
    /// The quiz limit was set, moved or lifted (the timeline ends at end()).
    void limitChanged();
    /// What shownEvents() holds changed: the limit, hiding ahead, or the cursor while hiding
    /// ahead (the event list's rows, the live controls' counts).
    void shownChanged();

  private:
    SceneRef scene_;
    LogRef log_ = std::make_shared<const EventLog>();
    LogKind logKind_ = LogKind::None;
    std::unique_ptr<Replay> replay_ = std::make_unique<Replay>(*log_);  // over *log_
    std::size_t cursor_ = 0;
    LogRef limitLog_;  // the log the limit belongs to (a lesson's trace)
    std::optional<std::size_t> limit_;
    bool limitIsBuild_ = false;  // limitLog_ records a build
    bool hideAhead_ = false;
};

}  // namespace raystep::gui
