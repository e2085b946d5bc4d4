#include "raystep/accel.h"

#include "raystep/names.h"

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
template <typename Rec>
Accelerator build(const Scene& scene, AccelKind kind, KernelOptions kernels,
                  const AccelOptions& options, Rec* log) {
    const ScenePrims prims(scene, kernels);
    switch (kind) {
        case AccelKind::BruteForce:
            return BruteForce(prims);
        case AccelKind::Grid:
            return UniformGrid(prims, options.grid);
        case AccelKind::KdTree:
            if (log) return KdTree3(prims, options.kdtree, *log);
            return KdTree3(prims, options.kdtree);
        case AccelKind::Bvh:
            if (log) return Bvh3(prims, options.bvh, *log);
            return Bvh3(prims, options.bvh);
    }
    throw std::logic_error("unknown accelerator kind");
}
}  // namespace

Accelerator buildAccelerator(const Scene& scene, AccelKind kind, KernelOptions kernels,
                             const AccelOptions& options) {
    return build<EventLog>(scene, kind, kernels, options, nullptr);
}
Accelerator buildAccelerator(const Scene& scene, AccelKind kind, KernelOptions kernels,
                             const AccelOptions& options, EventLog& log) {
    return build(scene, kind, kernels, options, &log);
}

BuildSummary summarize(const Accelerator& accel) {
    BuildSummary s;
    if (const auto* g = std::get_if<UniformGrid>(&accel)) {
        s.stats.nodes = static_cast<std::uint32_t>(g->cellCount());
        s.stats.leaves = s.stats.nodes;
        s.stats.emptyLeaves = static_cast<std::uint32_t>(g->emptyCells());
        s.stats.references = g->references();
        s.stats.buildMs = g->buildMs();
        const auto& r = g->spec().res;
        s.description =
            "grid " + std::to_string(r.x) + "x" + std::to_string(r.y) + "x" + std::to_string(r.z);
    } else if (const auto* k = std::get_if<KdTree3>(&accel)) {
        s.stats = k->stats();
        s.description = "kdtree " + std::string(name(k->options().split));
    } else if (const auto* b = std::get_if<Bvh3>(&accel)) {
        s.stats = b->stats();
        s.description = "bvh " + std::string(name(b->options().split));
    } else {
        const auto& bf = std::get<BruteForce>(accel);
        s.stats.nodes = s.stats.leaves = 1;
        s.stats.references = bf.primitives().count();
        s.stats.sahCost = KdTreeOptions{}.cIsect * bf.primitives().count();  // C_isect N
        s.description = "bruteforce";
    }
    return s;
}

}  // namespace raystep
