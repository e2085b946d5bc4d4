#include "raystep/accel.h"

#include "raystep/names.h"

#include <stdexcept>

namespace raystep {

std::optional<Hit> BruteForce::intersect(Ray ray, TraversalCounters& counters) const {
    std::optional<Hit> closest;
    Hit hit;
    const std::uint32_t n = scene_->primitiveCount();
    for (std::uint32_t p = 0; p < n; ++p) {
        ++counters.primitiveTests;
        // intersectPrimitive shortens ray.tMax, so later primitives must be closer to win.
        if (scene_->intersectPrimitive(p, ray, hit, kernels_)) closest = hit;
    }
    return closest;
}

bool BruteForce::occluded(Ray ray, TraversalCounters& counters) const {
    Hit hit;
    const std::uint32_t n = scene_->primitiveCount();
    for (std::uint32_t p = 0; p < n; ++p) {
        ++counters.primitiveTests;
        if (scene_->intersectPrimitive(p, ray, hit, kernels_)) return true;
    }
    return false;
}

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

Accelerator buildAccelerator(const Scene& scene, AccelKind kind, KernelOptions kernels,
                             const AccelOptions& options) {
    if (kind == AccelKind::BruteForce) return BruteForce(scene, kernels);
    if (kind == AccelKind::Grid) return UniformGrid(scene, kernels, options.grid);
    throw std::runtime_error("--accel " + std::string(accelKindName(kind)) +
                             ": not implemented yet; available: bruteforce, grid");
}

}  // namespace raystep
