#include "raystep/accel/accel.h"

#include "raystep/base/names.h"

#include <stdexcept>

namespace raystep {

namespace {
constexpr NameTable<AccelKind, 4> kAccelNames{{{AccelKind::BruteForce, "bruteforce"},
                                               {AccelKind::Grid, "grid"},
                                               {AccelKind::KdTree, "kdtree"},
                                               {AccelKind::Bvh, "bvh"}}};
}  // namespace

std::optional<AccelKind> parseAccelKind(std::string_view name) {
    return valueNamed(kAccelNames, name);
}
std::string_view accelKindName(AccelKind kind) {
    return nameOf(kAccelNames, kind);
}

namespace {
template <typename Prims>
AcceleratorT<Prims> build(const Prims& prims, AccelKind kind, const AccelOptions& options,
                          EventLog* log) {
    if (log) log->setDims(Prims::N);
    GridOptions grid = options.grid;
    switch (kind) {
        case AccelKind::BruteForce:
            return BruteForceT<Prims>(prims);
        case AccelKind::Grid:
            return UniformGridT<Prims>(prims, grid);
        case AccelKind::KdTree:
            if (log) return KdTree<Prims>(prims, options.kdtree, *log);
            return KdTree<Prims>(prims, options.kdtree);
        case AccelKind::Bvh:
            if (log) return Bvh<Prims>(prims, options.bvh, *log);
            return Bvh<Prims>(prims, options.bvh);
    }
    throw std::logic_error("unknown accelerator kind");
}

template <typename Prims>
BuildSummary summarizeT(const AcceleratorT<Prims>& accel) {
    constexpr int N = Prims::N;
    BuildSummary s;
    if (const auto* g = std::get_if<UniformGridT<Prims>>(&accel)) {
        s.stats.nodes = static_cast<std::uint32_t>(g->cellCount());
        s.stats.leaves = s.stats.nodes;
        s.stats.emptyLeaves = static_cast<std::uint32_t>(g->emptyCells());
        s.stats.references = g->references();
        s.stats.buildMs = g->buildMs();
        s.description = "grid ";
        for (int i = 0; i < N; ++i) {
            if (i) s.description += 'x';
            s.description += std::to_string(g->spec().res[i]);
        }
    } else if (const auto* k = std::get_if<KdTree<Prims>>(&accel)) {
        s.stats = k->stats();
        s.description = "kdtree " + std::string(name(k->options().split));
    } else if (const auto* b = std::get_if<Bvh<Prims>>(&accel)) {
        s.stats = b->stats();
        s.description = "bvh " + std::string(name(b->options().split));
    } else {
        const auto& bf = std::get<BruteForceT<Prims>>(accel);
        s.stats.nodes = s.stats.leaves = 1;
        s.stats.references = bf.primitives().count();
        s.stats.sahCost = KdTreeOptions{}.cIsect * bf.primitives().count();  // C_isect N
        s.description = "bruteforce";
    }
    return s;
}
}  // namespace

Accelerator buildAccelerator(const Scene& scene, AccelKind kind, KernelOptions kernels,
                             const AccelOptions& options) {
    return build(ScenePrims(scene, kernels), kind, options, nullptr);
}
Accelerator buildAccelerator(const Scene& scene, AccelKind kind, KernelOptions kernels,
                             const AccelOptions& options, EventLog& log) {
    return build(ScenePrims(scene, kernels), kind, options, &log);
}
AnyStructure buildStructure(const std::variant<Scene, Scene2D>& scene, AccelKind kind,
                            const KernelOptions& kernels, const AccelOptions& options,
                            EventLog* log) {
    AnyStructure built;
    if (const auto* s2 = std::get_if<Scene2D>(&scene))
        built.in2D = buildAccelerator2D(*s2, kind, options, log);
    else if (log)
        built.in3D = buildAccelerator(std::get<Scene>(scene), kind, kernels, options, *log);
    else
        built.in3D = buildAccelerator(std::get<Scene>(scene), kind, kernels, options);
    return built;
}

Accelerator2D buildAccelerator2D(const Scene2D& scene, AccelKind kind, const AccelOptions& options,
                                 EventLog* log) {
    AccelOptions o = options;
    // The scene suggests the grid the slides draw, unless the user asked for another.
    if (!o.grid.res && scene.gridRes)
        o.grid.res = std::array<int, 3>{scene.gridRes->x, scene.gridRes->y, 1};
    return build(Scene2DPrims(scene), kind, o, log);
}

BuildSummary summarize(const Accelerator& accel) {
    return summarizeT<ScenePrims>(accel);
}
BuildSummary summarize(const Accelerator2D& accel) {
    return summarizeT<Scene2DPrims>(accel);
}

std::optional<Hit2> traceRay2D(const Accelerator2D& accel, const Ray2& ray, EventLog& log,
                               TraversalCounters* counters) {
    TraversalCounters local;
    TraversalCounters& c = counters ? *counters : local;
    log.setDims(2);
    const std::uint32_t id =
        log.beginRay(Ray{Vec3(ray.origin, 0.0), Vec3(ray.dir, 0.0), ray.tMin, ray.tMax},
                     RayKind::Primary, 0, kNoId);
    const auto hit = std::visit([&](const auto& a) { return a.intersect(ray, c, log, id); }, accel);
    if (hit)
        log(RayHit{id, hit->prim, hit->t, 0.0, 0.0});
    else
        log(RayMiss{id});
    return hit;
}

}  // namespace raystep
