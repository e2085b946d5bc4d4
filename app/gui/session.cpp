#include "session.h"

#include "raystep/scene/scene_loader.h"
#include "raystep/render/tracer.h"

#include <QStringList>

#include <algorithm>

namespace raystep::gui {

namespace {
/// The structure of a scene built in place (it points into the scene, which must not move).
void buildIn(LoadedScene& l, const AccelOptions& options) {
    if (const auto* s2 = std::get_if<Scene2D>(&l.scene))
        l.accel2D = buildAccelerator2D(*s2, l.kind, options);
    else
        l.accel3D = buildAccelerator(std::get<Scene>(l.scene), l.kind, {}, options);
    // The progress callback belonged to this build only.
    l.options.setProgress(nullptr);
}
}  // namespace

SceneRef Session::prepare(const std::string& nameOrPath, AccelKind kind,
                          const AccelOptions& options) {
    auto l = std::make_shared<LoadedScene>();
    l->scene = loadAnyScene(nameOrPath);
    l->name = nameOrPath;
    l->kind = kind;
    l->options = options;
    buildIn(*l, options);
    return l;
}

SceneRef Session::prepare(Scene2D scene, AccelKind kind, const AccelOptions& options) {
    auto l = std::make_shared<LoadedScene>();
    l->name = scene.name;
    l->scene = std::move(scene);
    l->kind = kind;
    l->options = options;
    buildIn(*l, options);
    return l;
}

LogRef Session::recordBuild(const SceneRef& scene, const ProgressFn& progress) {
    auto log = std::make_shared<EventLog>();
    AccelOptions options = scene->options;
    options.setProgress(progress);
    if (const Scene2D* s2 = std::get_if<Scene2D>(&scene->scene))
        buildAccelerator2D(*s2, scene->kind, options, log.get());
    else
        buildAccelerator(std::get<Scene>(scene->scene), scene->kind, {}, options, *log);
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
    return scene_->accel2D ? summarize(*scene_->accel2D) : summarize(*scene_->accel3D);
}

void Session::tracePixel(int x, int y, int width, int height) {
    const Scene* s = scene3D();
    if (!s) return;
    auto log = std::make_shared<EventLog>();
    tracePixelEvents(*s, *accel3D(), x, y, width, height, *log);
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
    emit cursorChanged(cursor_);
}

void Session::setCursor(std::size_t cursor) {
    cursor = std::min(cursor, size());
    if (cursor == cursor_ && replay_->state().cursor == cursor) return;
    cursor_ = cursor;
    replay_->seek(cursor);
    emit cursorChanged(cursor_);
}

namespace {
QString num(double v) {
    if (std::isinf(v)) return v > 0 ? QStringLiteral("inf") : QStringLiteral("-inf");
    return QString::number(v, 'g', 6);
}
QString axesName(unsigned axes) {
    QString s;
    for (int i = 0; i < 3; ++i)
        if (axes & (1u << i)) s += QChar("XYZ"[i]);
    return s.isEmpty() ? QStringLiteral("-") : s;
}
QString prim(std::uint32_t p) {
    return p == kNoId ? QStringLiteral("-") : QString::number(p);
}
}  // namespace

QString describeEvent(const Event& event) {
    return std::visit(
        [](const auto& e) -> QString {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, RayBegin>)
                return QStringLiteral("ray %1 begins: %2, depth %3")
                    .arg(e.ray)
                    .arg(QString::fromUtf8(kRayKindNames[static_cast<int>(e.kind)].data()))
                    .arg(e.depth);
            else if constexpr (std::is_same_v<E, DdaSetup>)
                return e.dims == 3
                           ? QStringLiteral("DDA set-up: step (%1, %2, %3), tDelta (%4, %5, %6)")
                                 .arg(e.step[0])
                                 .arg(e.step[1])
                                 .arg(e.step[2])
                                 .arg(num(e.tDelta[0]), num(e.tDelta[1]), num(e.tDelta[2]))
                           : QStringLiteral("DDA set-up: step (%1, %2), tDelta (%3, %4)")
                                 .arg(e.step[0])
                                 .arg(e.step[1])
                                 .arg(num(e.tDelta[0]), num(e.tDelta[1]));
            else if constexpr (std::is_same_v<E, DdaCell>) {
                // A 2D walk leaves the third axis at 0 (cell and tMax); a 3D one never has
                // tMaxZ = 0 (the first crossing lies ahead of the ray's start).
                const bool threeD = e.cell[2] != 0 || e.tMax[2] != 0.0;
                return QStringLiteral("cell (%1, %2%3)%4, tMax (%5, %6%7)")
                    .arg(e.cell[0])
                    .arg(e.cell[1])
                    .arg(threeD ? QStringLiteral(", %1").arg(e.cell[2]) : QString())
                    .arg(e.axes ? QStringLiteral(" by ") + axesName(e.axes)
                                : QStringLiteral(" (first cell)"),
                         num(e.tMax[0]), num(e.tMax[1]),
                         threeD ? QStringLiteral(", ") + num(e.tMax[2]) : QString());
            } else if constexpr (std::is_same_v<E, MailboxSkip>)
                return QStringLiteral("mailbox: primitive %1 already tested").arg(e.prim);
            else if constexpr (std::is_same_v<E, PrimitiveTest>)
                return e.hit ? QStringLiteral("test primitive %1: hit at t = %2")
                                   .arg(e.prim)
                                   .arg(num(e.t))
                             : QStringLiteral("test primitive %1: miss").arg(e.prim);
            else if constexpr (std::is_same_v<E, NodeEnter>)
                return QStringLiteral("enter node %1 [%2, %3]")
                    .arg(e.node)
                    .arg(num(e.tNear), num(e.tFar));
            else if constexpr (std::is_same_v<E, NodeSkip>)
                return QStringLiteral("skip node %1").arg(e.node);
            else if constexpr (std::is_same_v<E, BuildNode>)
                return QStringLiteral("build node %1: %2 primitives, depth %3")
                    .arg(e.node)
                    .arg(e.prims)
                    .arg(e.depth);
            else if constexpr (std::is_same_v<E, SplitCandidate>)
                return QStringLiteral("candidate %1 = %2: NL %3, NR %4, cost %5")
                    .arg(QChar("XYZ"[e.axis]))
                    .arg(num(e.position))
                    .arg(e.nl)
                    .arg(e.nr)
                    .arg(num(e.sahCost));
            else if constexpr (std::is_same_v<E, SplitChosen>)
                return QStringLiteral("split %1 = %2 (cost %3, leaf %4)")
                    .arg(QChar("XYZ"[e.axis]))
                    .arg(num(e.position), num(e.sahCost), num(e.leafCost));
            else if constexpr (std::is_same_v<E, LeafMade>)
                return QStringLiteral("leaf %1: %2 primitives (%3)")
                    .arg(e.node)
                    .arg(e.prims)
                    .arg(QString::fromUtf8(kLeafReasonNames[static_cast<int>(e.reason)].data()));
            else if constexpr (std::is_same_v<E, RayHit>)
                return QStringLiteral("ray %1 hits primitive %2 at t = %3")
                    .arg(e.ray)
                    .arg(prim(e.prim), num(e.t));
            else if constexpr (std::is_same_v<E, RayMiss>)
                return QStringLiteral("ray %1 misses").arg(e.ray);
            else if constexpr (std::is_same_v<E, ShadingTerm>)
                return QStringLiteral("%1 term (%2, %3, %4)")
                    .arg(QString::fromUtf8(kShadingTermNames[static_cast<int>(e.term)].data()))
                    .arg(num(e.rgb[0]), num(e.rgb[1]), num(e.rgb[2]));
            else
                return QStringLiteral("pixel (%1, %2) = (%3, %4, %5)")
                    .arg(e.x)
                    .arg(e.y)
                    .arg(num(e.rgb[0]), num(e.rgb[1]), num(e.rgb[2]));
        },
        event);
}

QString describeState(const Session& s) {
    const ReplayState& st = s.state();
    QStringList lines;
    lines << QStringLiteral("step %1 of %2").arg(st.cursor).arg(s.size());
    if (st.cursor > 0) lines << describeEvent(s.log().events()[st.cursor - 1]);
    if (st.ray != kNoId) lines << QStringLiteral("ray %1").arg(st.ray);
    if (st.ddaCell) {
        const DdaCell& c = *st.ddaCell;
        lines << QStringLiteral("X = %1   Y = %2%3")
                     .arg(c.cell[0])
                     .arg(c.cell[1])
                     .arg(s.is2D() ? QString() : QStringLiteral("   Z = %1").arg(c.cell[2]));
        lines << QStringLiteral("tMaxX = %1   tMaxY = %2%3")
                     .arg(num(c.tMax[0]), num(c.tMax[1]))
                     .arg(s.is2D() ? QString()
                                   : QStringLiteral("   tMaxZ = %1").arg(num(c.tMax[2])));
    }
    if (st.ddaSetup) {
        const DdaSetup& d = *st.ddaSetup;
        const bool threeD = d.dims == 3;
        lines << QStringLiteral("tDeltaX = %1   tDeltaY = %2%3")
                     .arg(num(d.tDelta[0]), num(d.tDelta[1]),
                          threeD ? QStringLiteral("   tDeltaZ = ") + num(d.tDelta[2]) : QString());
        lines << QStringLiteral("stepX = %1   stepY = %2%3")
                     .arg(d.step[0])
                     .arg(d.step[1])
                     .arg(threeD ? QStringLiteral("   stepZ = %1").arg(d.step[2]) : QString());
        lines << QStringLiteral("t_enter = %1   t_exit = %2").arg(num(d.tEnter), num(d.tExit));
    }
    if (st.node)
        lines << QStringLiteral("node %1, t in [%2, %3]")
                     .arg(st.node->node)
                     .arg(num(st.node->tNear), num(st.node->tFar));
    if (!st.mailboxSkips.empty()) {
        QStringList m;
        for (auto p : st.mailboxSkips) m << QString::number(p);
        lines << QStringLiteral("mailbox: skipped primitive %1 (already tested by this ray)")
                     .arg(m.join(", "));
    }
    if (st.ray != kNoId) lines << QStringLiteral("tests: %1").arg(st.tests.size());
    if (st.nearestT)
        lines << QStringLiteral("nearest hit so far: primitive %1 at t = %2")
                     .arg(st.nearestPrim)
                     .arg(num(*st.nearestT));
    if (st.buildNode) {
        lines << QStringLiteral("building node %1 (%2 primitives, depth %3), %4 candidates")
                     .arg(st.buildNode->node)
                     .arg(st.buildNode->prims)
                     .arg(st.buildNode->depth)
                     .arg(st.candidates.size());
        if (!st.candidates.empty()) {
            const SplitCandidate& c = st.candidates.back();
            lines << QStringLiteral("candidate %1 = %2")
                         .arg(QChar("XYZ"[c.axis]))
                         .arg(num(c.position));
            lines << QStringLiteral("  NL = %1   NR = %2").arg(c.nl).arg(c.nr);
            lines << QStringLiteral("  P(L|C) = %1   P(R|C) = %2").arg(num(c.pl), num(c.pr));
            lines << QStringLiteral("  sahCost = %1").arg(num(c.sahCost));
            const auto best =
                std::min_element(st.candidates.begin(), st.candidates.end(),
                                 [](const SplitCandidate& a, const SplitCandidate& b) {
                                     return a.sahCost < b.sahCost;
                                 });
            lines << QStringLiteral("cheapest so far: %1 = %2, cost %3")
                         .arg(QChar("XYZ"[best->axis]))
                         .arg(num(best->position), num(best->sahCost));
        }
        if (st.chosen)
            lines << QStringLiteral("chosen: %1 = %2 (cost %3 < leaf %4)")
                         .arg(QChar("XYZ"[st.chosen->axis]))
                         .arg(num(st.chosen->position), num(st.chosen->sahCost),
                              num(st.chosen->leafCost));
    }
    return lines.join('\n');
}

}  // namespace raystep::gui
