#include "session.h"

#include "raystep/render/tracer.h"
#include "raystep/scene/model_import.h"
#include "raystep/scene/scene_loader.h"

#include <algorithm>

namespace raystep::gui {

namespace {
/// The structure of a scene built in place (it points into the scene, which must not move).
void buildIn(LoadedScene& l, const AccelOptions& options) {
    l.structure = buildStructure(l.scene, l.kind, {}, options);
    // Here, on the worker that built it: a view never walks the structure itself.
    if (l.structure.in2D) l.outline2D = outline(*l.structure.in2D);
    if (l.structure.in3D) l.outline3D = outline(*l.structure.in3D);
    // The progress callback belonged to this build only.
    l.options.setProgress(nullptr);
}
}  // namespace

SceneRef Session::prepare(const std::string& nameOrPath, AccelKind kind,
                          const AccelOptions& options) {
    auto l = std::make_shared<LoadedScene>();
    // A model's import reports to the task's progress, and is killed by its cancel.
    l->scene = loadAnySceneOrModel(nameOrPath, options.kdtree.progress);
    l->name = nameOrPath;
    l->kind = kind;
    l->options = options;
    buildIn(*l, options);
    return l;
}

SceneRef Session::rebuild(const SceneRef& from, AccelKind kind, const AccelOptions& options) {
    // A copy: the old structure points into the old scene, which others still show meanwhile.
    auto l = std::make_shared<LoadedScene>();
    l->scene = from->scene;
    l->name = from->name;
    l->kind = kind;
    l->options = options;
    buildIn(*l, options);
    return l;
}

namespace {
/// A scene made in code (2D or 3D) with its structure built.
template <typename AnyScene>
SceneRef prepared(AnyScene scene, AccelKind kind, const AccelOptions& options) {
    auto l = std::make_shared<LoadedScene>();
    l->name = scene.name;
    l->scene = std::move(scene);
    l->kind = kind;
    l->options = options;
    buildIn(*l, options);
    return l;
}
}  // namespace

SceneRef Session::prepare(Scene2D scene, AccelKind kind, const AccelOptions& options) {
    return prepared(std::move(scene), kind, options);
}

SceneRef Session::prepare(Scene scene, AccelKind kind, const AccelOptions& options) {
    return prepared(std::move(scene), kind, options);
}

LogRef Session::recordBuild(const SceneRef& scene, const ProgressFn& progress) {
    auto log = std::make_shared<EventLog>();
    AccelOptions options = scene->options;
    options.setProgress(progress);
    buildStructure(scene->scene, scene->kind, {}, options, log.get());
    return log;
}

void Session::adopt(SceneRef scene) {
    emit aboutToChangeScene();
    scene_ = std::move(scene);
    showLog(std::make_shared<const EventLog>(), LogKind::None);
    emit sceneChanged();
}

void Session::load(const std::string& nameOrPath, AccelKind kind, const AccelOptions& options) {
    adopt(prepare(nameOrPath, kind, options));  // throws before anything changes
}

void Session::load(Scene2D scene, AccelKind kind, const AccelOptions& options) {
    adopt(prepare(std::move(scene), kind, options));
}

void Session::traceExampleRay() {
    const Scene2D* s = scene2D();
    if (!s || !s->exampleRay) return;
    auto log = std::make_shared<EventLog>();
    traceRay2D(*accel2D(), *s->exampleRay, *log);
    showLog(std::move(log), LogKind::ExampleRay);
}

void Session::recordBuild() {
    if (!scene_ || !hasBuild(scene_->kind)) return;
    showLog(recordBuild(scene_), LogKind::Build);
}

BuildSummary Session::summary() const {
    if (!scene_) return {};
    return scene_->structure.in2D ? summarize(*scene_->structure.in2D)
                                  : summarize(*scene_->structure.in3D);
}

void Session::tracePixel(int x, int y, int width, int height) {
    const Scene* s = scene3D();
    if (!s) return;
    auto log = std::make_shared<EventLog>();
    tracePixelEvents(*s, *accel3D(), x, y, width, height, *log);
    showLog(std::move(log), LogKind::Pixel);
}

void Session::tracePixel(int x, int y, int width, int height, const Camera& camera,
                         const TraceSettings& settings) {
    const Scene* s = scene3D();
    if (!s) return;
    auto log = std::make_shared<EventLog>();
    tracePixelEvents(*s, *accel3D(), camera, settings, x, y, width, height, *log);
    showLog(std::move(log), LogKind::Pixel);
}

void Session::showLog(LogRef log, LogKind kind) {
    // The new replay is made before the old one goes: the old log stays alive until then.
    auto replay = std::make_unique<Replay>(*log);
    replay->seek(0);
    replay_ = std::move(replay);
    log_ = std::move(log);
    logKind_ = kind;
    cursor_ = 0;
    emit logChanged();
    emit limitChanged();  // the held log is shown up to its limit, another one not at all
    emit shownChanged();
    emit cursorChanged(cursor_);
}

void Session::relive(SceneRef scene) {
    const Step at = step();
    // A lesson's trace that is a build is recorded again as a build, and so is any trace while
    // such a lesson holds: a ray traced instead would draw the whole tree, the held answers.
    bool build = logKind_ == LogKind::Build || holdsBuild();
    if (logKind_ == LogKind::Lesson)
        for (const Event& e : log_->events())
            if (std::holds_alternative<BuildNode>(e)) {
                build = true;
                break;
            }
    adopt(std::move(scene));
    if (build && hasBuild(scene_->kind))
        recordBuild();
    else if (is2D())
        traceExampleRay();
    seekStep(at);
}

Session::Step Session::step() const {
    Step at;
    if (cursor_ == 0) return at;
    const auto& events = log_->events();
    at.kind = events[cursor_ - 1].index();
    for (std::size_t i = 0; i < cursor_; ++i) at.nth += events[i].index() == *at.kind;
    return at;
}

void Session::seekStep(const Step& at) {
    if (!at.kind) return setCursor(0);
    const auto& events = log_->events();
    std::size_t seen = 0;
    for (std::size_t i = 0; i < events.size(); ++i)
        if (events[i].index() == *at.kind && ++seen == at.nth) return setCursor(i + 1);
    setCursor(events.size());
}

void Session::setLimit(const LogRef& log, std::optional<std::size_t> limit) {
    const std::optional<std::size_t> before = this->limit();
    // A limit at or past the log's end hides nothing: nothing is held.
    if (!log || (limit && *limit >= log->events().size())) limit.reset();
    // Whether the held trace is a build, once per hold (the 2D view asks at every layer).
    if (!limit || log != limitLog_)
        limitIsBuild_ =
            limit && std::any_of(log->events().begin(), log->events().end(), [](const Event& e) {
                return std::holds_alternative<BuildNode>(e);
            });
    limitLog_ = limit ? log : nullptr;
    limit_ = limit;
    if (this->limit() == before) return;
    emit limitChanged();
    emit shownChanged();
    if (cursor_ > end()) setCursor(end());
}

void Session::setHideAhead(bool on) {
    if (on == hideAhead_) return;
    hideAhead_ = on;
    emit shownChanged();
}

std::optional<std::size_t> Session::limit() const {
    if (!limit_) return std::nullopt;
    if (limitLog_ == log_) return limit_;
    return size() > 0 ? std::optional<std::size_t>(0) : std::nullopt;
}

void Session::setCursor(std::size_t cursor) {
    // Never past an open exercise's position (quiz mode), nor past the end.
    cursor = std::min(cursor, end());
    if (cursor == cursor_ && replay_->state().cursor == cursor) return;
    cursor_ = cursor;
    replay_->seek(cursor);
    emit cursorChanged(cursor_);
    // What is shown ends at the cursor: it moved with it.
    if (hideAhead_) emit shownChanged();
}

}  // namespace raystep::gui
