#pragma once
// The bounding volume hierarchy: object subdivision, against the kd-tree's space subdivision.
// Each primitive is in exactly one leaf; boxes may overlap. Split by the middle of the centres'
// bounds (midpoint), by equal counts (median), or by the SAH over binned centres (12 buckets,
// pbrt). Traversal visits the nearer child first and skips boxes beyond the nearest hit.
#include "raystep/accel/query.h"
#include "raystep/accel/sah.h"
#include "raystep/base/progress.h"
#include "raystep/scene/fast_prims.h"
#include "raystep/scene/prims.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace raystep {

struct BvhOptions {
    SplitMethod split = SplitMethod::Sah;
    double cTrav = 1.0;    // cost of one box test and step
    double cIsect = 5.0;   // cost of one ray-primitive test
    int leafSize = 4;      // midpoint and median: leaves of at most this many primitives
    int maxLeafSize = 16;  // SAH: a leaf may hold more only when no split is cheaper, up to this
    int buckets = 12;      // SAH bins along the axis
    ProgressFn progress;   // build progress (share of the primitives placed in leaves); may cancel
};

template <int N>
struct BvhNode {
    BoxN<N> bounds;
    std::uint32_t index = 0;  // interior: right child (left is next); leaf: first primitive
    std::uint32_t count = 0;  // 0 for interior nodes
    std::uint8_t axis = 0;    // split axis (the traversal's near-first order)
    bool leaf() const { return count > 0; }
};

template <typename Prims>
class Bvh : public Queries<Bvh<Prims>, Prims> {
  public:
    static constexpr int N = Prims::N;
    using RayT = typename Prims::RayT;
    using HitT = typename Prims::HitT;

    Bvh(Prims prims, const BvhOptions& options);
    Bvh(Prims prims, const BvhOptions& options, EventLog& log);

    const Prims& primitives() const { return prims_; }
    const KernelOptions& kernels() const { return prims_.kernels(); }
    const BvhOptions& options() const { return options_; }
    const std::vector<BvhNode<N>>& nodes() const { return nodes_; }
    const std::vector<std::uint32_t>& primIds() const { return primIds_; }
    const TreeStats& stats() const { return stats_; }

  private:
    friend class Queries<Bvh, Prims>;
    template <bool AnyHit, typename Rec>
    std::optional<HitT> query(RayT ray, TraversalCounters& counters, Rec& rec,
                              std::uint32_t rayId) const {
        return traverse<AnyHit>(ray, counters, rec, rayId);
    }
    template <typename Rec>
    void build(Rec& rec);
    template <bool AnyHit, typename Rec>
    std::optional<HitT> traverse(RayT ray, TraversalCounters& counters, Rec& rec,
                                 std::uint32_t rayId) const;

    Prims prims_;
    BvhOptions options_;
    std::vector<BvhNode<N>> nodes_;
    std::vector<std::uint32_t> primIds_;
    TreeStats stats_;
};

// Instantiated beside the traversal (bvh.cpp).
extern template class Queries<Bvh<ScenePrims>, ScenePrims>;
extern template class Queries<Bvh<Scene2DPrims>, Scene2DPrims>;
extern template class Queries<Bvh<FloatScenePrims>, FloatScenePrims>;

}  // namespace raystep
