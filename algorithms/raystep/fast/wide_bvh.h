#pragma once
// The fast path: what real-time ray tracers (Embree, OpenRT) do with the BVH of the lecture.
// Four children per node instead of two, their boxes tested by one SIMD instruction each; float
// boxes and vertices in compact nodes; triangles stored four to a block and tested together with
// the watertight test (Woop, Benthin, Wald 2013). Built with binned SAH like the teaching BVH
// (accel/bvh.cpp), then collapsed from two children to four. It records nothing: the teaching
// structures trace what is shown, this one makes whole images (docs/architecture.md).
#include "raystep/accel/query.h"
#include "raystep/base/progress.h"
#include "raystep/geometry/kernels.h"
#include "raystep/scene/scene.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace raystep {

struct WideBvhOptions {
    int bins = 16;        // SAH bins along each axis
    double cTrav = 1.0;   // cost of one four-box node test, against
    double cIsect = 1.0;  // the cost of one four-triangle block test
    int maxLeafSize = 8;  // a leaf never holds more primitives than this
    ProgressFn progress;  // build progress (share of the primitives placed); may cancel
};

/// What the build made, and what it takes in memory.
struct WideBvhStats {
    std::uint32_t nodes = 0;  // four-wide nodes
    std::uint32_t leaves = 0;
    std::uint32_t blocks = 0;      // four-triangle blocks
    std::uint32_t emptyLanes = 0;  // triangle slots of the blocks left empty
    std::uint32_t maxDepth = 0;
    std::size_t bytes = 0;  // nodes, leaves, blocks and spheres
    double buildMs = 0.0;
};

class WideBvh {
  public:
    /// Which lanes the box and triangle tests run on: the compiler's SIMD (SSE2 on x86-64), or
    /// the portable code that computes the same bits (what an ARM64 build runs; the tests compare).
    enum class Lanes { Native, Portable };

    /// Builds over `scene`, which must outlive it and not change. Throws BuildCancelled when
    /// the progress callback says stop.
    explicit WideBvh(const Scene& scene, const WideBvhOptions& options = {});

    /// Nearest hit in (ray.tMin, ray.tMax), as the scene numbers primitives; t, u and v are
    /// computed in float.
    std::optional<Hit> intersect(const Ray& ray, TraversalCounters& counters,
                                 Lanes lanes = Lanes::Native) const;
    /// Any hit in (ray.tMin, ray.tMax): shadow rays stop at the first one.
    bool occluded(const Ray& ray, TraversalCounters& counters, Lanes lanes = Lanes::Native) const;

    /// Float, stable spheres, watertight triangles: what shading spawns secondary rays for.
    static constexpr KernelOptions kKernels{Precision::Float, SphereMethod::Stable,
                                            TriangleMethod::Watertight};
    const KernelOptions& kernels() const { return kernels_; }
    const Scene& scene() const { return *scene_; }
    const WideBvhStats& stats() const { return stats_; }

    // The layout, public for the tests and the lesson: a node's four boxes side by side, so one
    // SIMD load reads one bound of all four.
    static constexpr std::int32_t kEmpty = INT32_MIN;  // an unused child slot
    struct alignas(64) Node {
        float lo[3][4], hi[3][4];  // [axis][child]
        // >= 0: a node's index; < 0 and not kEmpty: leaf ~child.
        std::int32_t child[4];
    };
    /// Four triangles, coordinate by coordinate: v[vertex][axis][lane].
    struct alignas(16) Block {
        float v[3][3][4];
        std::uint32_t prim[4];  // the scene's ids; kNoPrim in an empty lane
    };
    static constexpr std::uint32_t kNoPrim = ~0u;
    struct Leaf {
        std::uint32_t firstBlock = 0, blocks = 0;
        std::uint32_t firstSphere = 0, spheres = 0;  // into spherePrims()
    };
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<Leaf>& leaves() const { return leaves_; }
    const std::vector<Block>& blocks() const { return blocks_; }
    const std::vector<std::uint32_t>& spherePrims() const { return spherePrims_; }

  private:
    friend class WideBvhCollapse;
    template <typename F, bool AnyHit>
    std::optional<Hit> traverse(const Ray& ray, TraversalCounters& counters) const;

    struct FloatSphere {
        float center[3];
        float radius;
    };
    const Scene* scene_;
    KernelOptions kernels_ = kKernels;
    std::vector<Node> nodes_;
    std::vector<Leaf> leaves_;
    std::vector<Block> blocks_;
    std::vector<std::uint32_t> spherePrims_;
    std::vector<FloatSphere> spheres_;  // beside spherePrims_
    std::int32_t root_ = kEmpty;        // a node, a leaf (a scene of a few primitives) or none
    WideBvhStats stats_;
};

}  // namespace raystep
