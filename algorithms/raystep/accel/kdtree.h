#pragma once
// The kd-tree of the lecture: space cut by axis-aligned planes, a primitive listed in every leaf
// it overlaps. Three ways to place the plane: the middle of the node (midpoint), the median of
// the primitives' centres (median), or the plane of lowest Surface Area Heuristic cost (sah):
//   Cost = C_trav + P(L|C) Cost(L) + P(R|C) Cost(R),  P(L|C) = Area(L) / Area(C),
// with Cost(leaf) = C_isect N. The SAH build sweeps sorted split events and is O(N log N)
// (Wald & Havran 2006). Traversal is the slides' TestTree corrected: the slide's unordered
// toVisit stopping at the first finite t can return a farther hit, so children are visited
// front to back with a stack, stopping once the nearest hit lies in the node being left.
#include "raystep/accel/query.h"
#include "raystep/accel/sah.h"
#include "raystep/base/progress.h"
#include "raystep/scene/fast_prims.h"
#include "raystep/scene/prims.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace raystep {

/// How the SAH tree is built. Exact (the default): Wald & Havran's sweep over every split event,
/// straddling triangles clipped to each side (perfect splits), one thread. Fast: the SAH over
/// 16-32 bins per axis at every node (still perfect splits), float bounds rounded outward, big
/// nodes and subtrees on all cores: a tree 2-23% dearer on the knot meshes (cheaper on the
/// stadium: the greedy sweep is not optimal), built 11-20x faster from 262K triangles up
/// (docs/performance.md).
enum class KdBuild { Exact, Fast };
std::optional<KdBuild> parseKdBuild(std::string_view s);
std::string_view name(KdBuild b);

/// Build parameters, the lecture's names. Defaults after pbrt-v4's kd-tree (traversal 1,
/// intersection 5, empty bonus 0.5, one primitive a leaf for the SAH). Midpoint and median have
/// no cost to stop them, so their leaves default to 4 primitives.
struct KdTreeOptions {
    SplitMethod split = SplitMethod::Sah;
    double cTrav = 1.0;       // cost of one traversal step
    double cIsect = 5.0;      // cost of one ray-primitive test
    double emptyBonus = 0.5;  // a split with an empty side costs (1 - emptyBonus) times as much
    int maxDepth = 0;         // 0 = round(8 + 1.3 log2 N) (pbrt)
    int leafSize = 0;         // this many primitives or fewer make a leaf; 0 = 1 (SAH) or 4
    bool mailbox = true;      // test a primitive listed in several leaves once per ray
    // SAH: 0 (the default) sweeps every split event exactly (Wald & Havran). N > 0: nodes with
    // more than N primitives choose among 256 bin boundaries per axis instead (min-max binning).
    int binAbove = 0;
    KdBuild build = KdBuild::Exact;  // SAH only
    ProgressFn progress;  // build progress (share of the primitives placed in leaves); may cancel
};

/// One node: an interior node splits `axis` at `split` (left child next in the array, right child
/// at `index`); a leaf holds `count` primitive ids from prims()[index].
struct KdNode {
    double split = 0.0;
    std::uint32_t index = 0;
    std::uint32_t count = 0;  // leaves only
    std::uint8_t axis = 0;    // 0..N-1, kLeaf for a leaf
    static constexpr std::uint8_t kLeaf = 3;
    bool leaf() const { return axis == kLeaf; }
};

template <typename Prims>
class KdTree : public Queries<KdTree<Prims>, Prims> {
  public:
    static constexpr int N = Prims::N;
    using RayT = typename Prims::RayT;
    using HitT = typename Prims::HitT;

    KdTree(Prims prims, const KdTreeOptions& options);
    /// The same build, recording every node, candidate and decision into `log`.
    KdTree(Prims prims, const KdTreeOptions& options, EventLog& log);

    const Prims& primitives() const { return prims_; }
    const KernelOptions& kernels() const { return prims_.kernels(); }
    const KdTreeOptions& options() const { return options_; }
    const std::vector<KdNode>& nodes() const { return nodes_; }
    /// Calls visit(id, node, box) for every node, a parent before its children, with the node's
    /// box: how to draw the tree or find a node's box without knowing the nodes' order in memory.
    template <typename Visit>
    void forEachNode(Visit&& visit) const {
        if (nodes_.empty()) return;
        std::vector<std::pair<std::uint32_t, BoxN<N>>> stack{{0u, bounds_}};
        while (!stack.empty()) {
            const auto [id, box] = stack.back();
            stack.pop_back();
            const KdNode& node = nodes_[id];
            visit(id, node, box);
            if (node.leaf()) continue;
            const auto [left, right] = box.splitAt(node.axis, node.split);
            stack.push_back({node.index, right});  // popped after the whole left subtree
            stack.push_back({id + 1, left});
        }
    }
    /// Primitive ids of the leaves (leaf n holds primIds()[index .. index + count)).
    const std::vector<std::uint32_t>& primIds() const { return primIds_; }
    const BoxN<N>& bounds() const { return bounds_; }
    const TreeStats& stats() const { return stats_; }
    int maxDepthLimit() const { return maxDepth_; }

  private:
    friend class Queries<KdTree, Prims>;
    template <bool AnyHit, typename Rec>
    std::optional<HitT> query(RayT ray, TraversalCounters& counters, Rec& rec,
                              std::uint32_t rayId) const {
        return testTree<AnyHit>(ray, counters, rec, rayId);
    }
    template <typename Rec>
    void build(Rec& rec);
    template <bool AnyHit, typename Rec>
    /// The slides' TestTree, corrected (lesson 10): the nodes the ray crosses, nearest first,
    /// stopping once the nearest hit lies before the node being entered.
    std::optional<HitT> testTree(RayT ray, TraversalCounters& counters, Rec& rec,
                                 std::uint32_t rayId) const;

    Prims prims_;
    KdTreeOptions options_;
    int maxDepth_ = 0;
    BoxN<N> bounds_;
    std::vector<KdNode> nodes_;
    std::vector<std::uint32_t> primIds_;
    TreeStats stats_;
};

// Instantiated beside the traversal (kdtree.cpp).
extern template class Queries<KdTree<ScenePrims>, ScenePrims>;
extern template class Queries<KdTree<Scene2DPrims>, Scene2DPrims>;
extern template class Queries<KdTree<FloatScenePrims>, FloatScenePrims>;

}  // namespace raystep
