#pragma once
// The accelerator interface: "given the scene, find the nearest hit of a ray efficiently".
// A closed set of structures dispatched through std::variant (no virtual call per ray).
// Brute force is the slides' RaySceneIntersection; the uniform grid walks cells with the 3D-DDA;
// kd-tree and BVH are still to come (issue 4).
#include "raystep/accel_types.h"
#include "raystep/grid.h"
#include "raystep/ray.h"
#include "raystep/scene.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace raystep {

/// The slides' loop: test every primitive, keep the closest.
class BruteForce {
  public:
    BruteForce(const Scene& scene, KernelOptions kernels) : scene_(&scene), kernels_(kernels) {}
    const KernelOptions& kernels() const { return kernels_; }
    /// Nearest hit in (ray.tMin, ray.tMax).
    std::optional<Hit> intersect(Ray ray, TraversalCounters& counters) const;
    /// Any hit in (ray.tMin, ray.tMax): shadow rays stop at the first one.
    bool occluded(Ray ray, TraversalCounters& counters) const;

  private:
    const Scene* scene_;
    KernelOptions kernels_;
};

enum class AccelKind { BruteForce, Grid, KdTree, Bvh };

/// Parses "bruteforce|grid|kdtree|bvh"; nullopt for anything else.
std::optional<AccelKind> parseAccelKind(std::string_view name);
std::string_view accelKindName(AccelKind kind);

using Accelerator = std::variant<BruteForce, UniformGrid>;

/// Build parameters of the structures (each reads its own).
struct AccelOptions {
    GridOptions grid;
};

/// Builds the chosen structure over `scene` (which must outlive it).
/// Throws std::runtime_error for a structure that is not implemented yet.
Accelerator buildAccelerator(const Scene& scene, AccelKind kind, KernelOptions kernels = {},
                             const AccelOptions& options = {});

/// The kernels and precision the structure tests primitives with.
inline const KernelOptions& kernelsOf(const Accelerator& accel) {
    return std::visit([](const auto& a) -> const KernelOptions& { return a.kernels(); }, accel);
}

inline std::optional<Hit> intersect(const Accelerator& accel, const Ray& ray,
                                    TraversalCounters& counters) {
    return std::visit([&](const auto& a) { return a.intersect(ray, counters); }, accel);
}
inline bool occluded(const Accelerator& accel, const Ray& ray, TraversalCounters& counters) {
    return std::visit([&](const auto& a) { return a.occluded(ray, counters); }, accel);
}

}  // namespace raystep
