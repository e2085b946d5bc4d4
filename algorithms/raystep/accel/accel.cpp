#include "raystep/accel/accel.h"

#include <algorithm>
#include <stdexcept>

namespace raystep {

std::optional<SplitMethod> AccelOptions::split(AccelKind kind) const {
    if (!hasSplit(kind)) return std::nullopt;
    return kind == AccelKind::Bvh ? bvh.split : kdtree.split;
}

double AccelOptions::value(AccelKind kind, AccelOption option) const {
    const bool isBvh = kind == AccelKind::Bvh;
    switch (option) {
        case AccelOption::Split:
            return static_cast<int>(isBvh ? bvh.split : kdtree.split);
        case AccelOption::Mailbox:
            return (kind == AccelKind::KdTree ? kdtree.mailbox : grid.mailbox) ? 1.0 : 0.0;
        case AccelOption::GridLambda:
            return grid.lambda;
        case AccelOption::LeafSize:
            return isBvh ? bvh.leafSize : kdtree.leafSize;
        case AccelOption::MaxDepth:
            return kdtree.maxDepth;
        case AccelOption::CTrav:
            return isBvh ? bvh.cTrav : kdtree.cTrav;
        case AccelOption::CIsect:
            return isBvh ? bvh.cIsect : kdtree.cIsect;
        case AccelOption::EmptyBonus:
            return kdtree.emptyBonus;
        case AccelOption::Buckets:
            return bvh.buckets;
        case AccelOption::BinAbove:
            return kdtree.binAbove;
        case AccelOption::KdBuild:
            return static_cast<int>(kdtree.build);
        case AccelOption::GridRes:
            break;
    }
    throw std::logic_error("the grid's resolution is three values: read grid.res");
}

void AccelOptions::set(AccelOption option, double v) {
    switch (option) {
        case AccelOption::Split:
            return setSplit(static_cast<SplitMethod>(static_cast<int>(v)));
        case AccelOption::Mailbox:
            grid.mailbox = kdtree.mailbox = v != 0.0;
            return;
        case AccelOption::GridLambda:
            grid.lambda = v;
            return;
        case AccelOption::LeafSize:
            kdtree.leafSize = static_cast<int>(v);
            // The BVH has no auto size; its SAH leaves may grow past a larger size asked for.
            bvh.leafSize = v > 0 ? static_cast<int>(v) : BvhOptions{}.leafSize;
            bvh.maxLeafSize = std::max(BvhOptions{}.maxLeafSize, bvh.leafSize);
            return;
        case AccelOption::MaxDepth:
            kdtree.maxDepth = static_cast<int>(v);
            return;
        case AccelOption::CTrav:
            kdtree.cTrav = bvh.cTrav = v;
            return;
        case AccelOption::CIsect:
            kdtree.cIsect = bvh.cIsect = v;
            return;
        case AccelOption::EmptyBonus:
            kdtree.emptyBonus = v;
            return;
        case AccelOption::Buckets:
            bvh.buckets = static_cast<int>(v);
            return;
        case AccelOption::BinAbove:
            kdtree.binAbove = static_cast<int>(v);
            return;
        case AccelOption::KdBuild:
            kdtree.build = static_cast<KdBuild>(static_cast<int>(v));
            return;
        case AccelOption::GridRes:
            break;
    }
    throw std::logic_error("the grid's resolution is three values: set grid.res");
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

// One overload per structure (std::visit): a new alternative of the variant fails to compile here.
template <typename Prims>
BuildSummary summaryOf(const UniformGridT<Prims>& g) {
    BuildSummary s;
    s.stats.nodes = static_cast<std::uint32_t>(g.cellCount());
    s.stats.leaves = s.stats.nodes;
    s.stats.emptyLeaves = static_cast<std::uint32_t>(g.emptyCells());
    s.stats.references = g.references();
    s.stats.buildMs = g.buildMs();
    s.description = std::string(accelKindName(AccelKind::Grid)) + " ";
    for (int i = 0; i < Prims::N; ++i) {
        if (i) s.description += 'x';
        s.description += std::to_string(g.spec().res[i]);
    }
    return s;
}
template <typename Prims>
BuildSummary summaryOf(const KdTree<Prims>& k) {
    return {k.stats(), std::string(accelKindName(AccelKind::KdTree)) + " " +
                           std::string(name(k.options().split))};
}
template <typename Prims>
BuildSummary summaryOf(const Bvh<Prims>& b) {
    return {b.stats(), std::string(accelKindName(AccelKind::Bvh)) + " " +
                           std::string(name(b.options().split))};
}
template <typename Prims>
BuildSummary summaryOf(const BruteForceT<Prims>& bf) {
    BuildSummary s;
    s.stats.nodes = s.stats.leaves = 1;
    s.stats.references = bf.primitives().count();
    s.stats.sahCost = KdTreeOptions{}.cIsect * bf.primitives().count();  // C_isect N
    s.description = std::string(accelKindName(AccelKind::BruteForce));
    return s;
}

template <typename Prims>
BuildSummary summarizeT(const AcceleratorT<Prims>& accel) {
    return std::visit([](const auto& a) { return summaryOf(a); }, accel);
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

std::optional<Hit> traceRay3D(const Accelerator& accel, const Ray& ray, EventLog& log,
                              TraversalCounters* counters) {
    TraversalCounters local;
    TraversalCounters& c = counters ? *counters : local;
    log.setDims(3);
    const std::uint32_t id = log.beginRay(ray, RayKind::Primary, 0, kNoId);
    const auto hit = intersect(accel, ray, c, log, id);
    if (hit)
        log(RayHit{id, hit->prim, hit->t, hit->u, hit->v});
    else
        log(RayMiss{id});
    return hit;
}

}  // namespace raystep
