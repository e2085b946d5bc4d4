#pragma once
// The accelerator interface: "given the scene, find the nearest hit of a ray efficiently".
// A closed set of structures dispatched through std::variant (no virtual call per ray).
// Brute force (bruteforce.h) is the slides' RaySceneIntersection; the uniform grid walks cells
// with the 3D-DDA; the kd-tree subdivides space, the BVH the objects.
#include "raystep/accel/bruteforce.h"
#include "raystep/accel/bvh.h"
#include "raystep/accel/grid.h"
#include "raystep/accel/kdtree.h"
#include "raystep/accel/mailbox.h"
#include "raystep/accel/query.h"
#include "raystep/accel/structure_info.h"
#include "raystep/base/progress.h"
#include "raystep/base/ray.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace raystep {

using KdTree3 = KdTree<ScenePrims>;
using Bvh3 = Bvh<ScenePrims>;
/// The structures over any primitive set: the 3D scene, or a 2D lecture scene.
template <typename Prims>
using AcceleratorT =
    std::variant<BruteForceT<Prims>, UniformGridT<Prims>, KdTree<Prims>, Bvh<Prims>>;
using Accelerator = AcceleratorT<ScenePrims>;
using Accelerator2D = AcceleratorT<Scene2DPrims>;
// A new structure is a new alternative, a new AccelKind and its row in structure_info.cpp.
static_assert(std::variant_size_v<Accelerator> == kAccelKindCount,
              "every structure has an AccelKind and a row in structure_info.cpp");

/// Build parameters of the structures (each reads its own).
struct AccelOptions {
    GridOptions grid;
    KdTreeOptions kdtree;
    BvhOptions bvh;
    /// The build's progress callback, whichever structure is built (nullptr: none).
    void setProgress(const ProgressFn& progress) {
        grid.progress = kdtree.progress = bvh.progress = progress;
    }
    /// The split method `kind` builds with; nullopt for a structure without one.
    std::optional<SplitMethod> split(AccelKind kind) const;
    /// Sets the split method of every structure that has one.
    void setSplit(SplitMethod method) { kdtree.split = bvh.split = method; }
    /// An option's value as `kind` reads it: a number, a switch as 0 or 1, a choice (Split,
    /// KdBuild) by its index, an auto value as 0. Not GridRes (three values: grid.res).
    double value(AccelKind kind, AccelOption option) const;
    /// Sets such an option (or a choice, by its index) for every structure that reads it; the
    /// value must pass optionProblem (structure_info.h), or be 0 for an option with an auto value.
    void set(AccelOption option, double value);
};

/// Builds the chosen structure over `scene` (which must outlive it).
Accelerator buildAccelerator(const Scene& scene, AccelKind kind, KernelOptions kernels = {},
                             const AccelOptions& options = {});
/// The same build with the tree's construction (nodes, candidates, leaves) recorded into `log`.
Accelerator buildAccelerator(const Scene& scene, AccelKind kind, KernelOptions kernels,
                             const AccelOptions& options, EventLog& log);

/// The same structures over a 2D scene (segments and circles), optionally recording the build.
Accelerator2D buildAccelerator2D(const Scene2D& scene, AccelKind kind,
                                 const AccelOptions& options = {}, EventLog* log = nullptr);

/// A structure over a scene of either kind: a 3D scene's, or one of the lecture's 2D pictures'.
struct AnyStructure {
    std::optional<Accelerator> in3D;
    std::optional<Accelerator2D> in2D;
};
/// Builds `kind` over `scene`, 3D or 2D (which must outlive it and not move), recording the
/// build into `log` if given: the one place the app, the lessons and the CLI choose between the
/// two builds.
AnyStructure buildStructure(const std::variant<Scene, Scene2D>& scene, AccelKind kind,
                            const KernelOptions& kernels, const AccelOptions& options,
                            EventLog* log = nullptr);

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
/// The queries with a recorder: NullRecorder calls the plain ones above.
template <typename Rec>
std::optional<Hit> intersect(const Accelerator& accel, const Ray& ray, TraversalCounters& counters,
                             Rec& rec, std::uint32_t rayId) {
    if constexpr (Rec::kEnabled)
        return std::visit([&](const auto& a) { return a.intersect(ray, counters, rec, rayId); },
                          accel);
    else
        return intersect(accel, ray, counters);
}
template <typename Rec>
bool occluded(const Accelerator& accel, const Ray& ray, TraversalCounters& counters, Rec& rec,
              std::uint32_t rayId) {
    if constexpr (Rec::kEnabled)
        return std::visit([&](const auto& a) { return a.occluded(ray, counters, rec, rayId); },
                          accel);
    else
        return occluded(accel, ray, counters);
}

/// What a structure's build made, for `raystep-cli build` and `compare`.
struct BuildSummary {
    TreeStats stats;
    std::string description;  // e.g. "grid 64x48x64", "kdtree sah"
};
BuildSummary summarize(const Accelerator& accel);
BuildSummary summarize(const Accelerator2D& accel);

/// Records one 2D ray through the structure: its RayBegin, the traversal, then RayHit or RayMiss.
std::optional<Hit2> traceRay2D(const Accelerator2D& accel, const Ray2& ray, EventLog& log,
                               TraversalCounters* counters = nullptr);
/// The same for one 3D ray (a practice's DDA walk through a 3D grid).
std::optional<Hit> traceRay3D(const Accelerator& accel, const Ray& ray, EventLog& log,
                              TraversalCounters* counters = nullptr);

}  // namespace raystep
