#pragma once
// What the kd-tree's builds share (internal to kdtree.cpp and kdtree_fast.cpp): writing nodes and
// leaves, recording them, the leaf rules, clipping a straddling primitive to each side, and the
// split events of the exact SAH sweep, which the fast file's --bin-above hands small nodes to.
#include "raystep/accel/kdtree.h"
#include "raystep/base/progress.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace raystep::kdbuild {

// An empty side thinner than this share of the node's width is not cut off. Clipping a straddling
// triangle rounds its bounds (and clipTriangleBounds widens the node by a millionth for that
// reason), so such a slab is rounding, not space; with the empty bonus it would still halve the
// node's cost, and the sweep would spend a level of the depth limit on it at nearly every node.
inline constexpr double kMinEmptySlab = 1e-6;
inline constexpr int kMaxDepthCap = 60;  // the traversal stack holds one entry per level

// Wald & Havran's split events: where a primitive's (clipped) bounds start and end along an
// axis, or lie flat in a plane. Sorted by (axis, position, type): at one position, the primitives
// that end come first, then the flat ones, then those that start.
enum class EventType : std::uint8_t { End = 0, Planar = 1, Start = 2 };
struct SplitEvent {
    double pos;
    std::uint32_t prim;
    std::uint8_t axis;
    EventType type;
    bool operator<(const SplitEvent& o) const {
        if (axis != o.axis) return axis < o.axis;
        if (pos != o.pos) return pos < o.pos;
        return type < o.type;
    }
};

/// Appends primitive p's events for its bounds `b`.
template <int N>
void addEvents(std::uint32_t p, const BoxN<N>& b, std::vector<SplitEvent>& out) {
    for (int a = 0; a < N; ++a) {
        const auto axis = static_cast<std::uint8_t>(a);
        if (b.lo[a] == b.hi[a]) {
            out.push_back({b.lo[a], p, axis, EventType::Planar});
        } else {
            out.push_back({b.lo[a], p, axis, EventType::Start});
            out.push_back({b.hi[a], p, axis, EventType::End});
        }
    }
}

/// A subtree the fast build made on another thread, in arrays of its own (kdtree_fast.cpp).
struct KdPiece;
struct KdAttached {
    std::uint32_t parent;  // the node whose right child the piece is
    std::uint32_t nodeAt;  // the node count when it was attached: it goes before that node
    std::uint32_t idAt;    // the id count then
    std::unique_ptr<KdPiece> piece;
};
struct KdPiece {
    std::vector<KdNode> nodes;
    std::vector<std::uint32_t> ids;
    std::vector<KdAttached> attached;          // in the order they were attached
    std::size_t totalNodes = 0, totalIds = 0;  // with everything attached (sizeUp)
};

/// Writes the tree's nodes and leaves in depth-first order (left child next to its parent),
/// records each into `rec`, keeps the statistics and reports progress.
template <typename Prims, typename Rec>
class KdNodeWriter {
  public:
    static constexpr int N = Prims::N;
    using Box = BoxN<N>;

    KdNodeWriter(const Prims& prims, const KdTreeOptions& opt, int maxDepth, Rec& rec,
                 KdPiece& piece, TreeStats& stats)
        : prims(prims),
          opt(opt),
          maxDepth(maxDepth),
          rec(rec),
          nodes_(piece.nodes),
          ids_(piece.ids),
          attached_(piece.attached),
          stats_(stats),
          progress_(opt.progress) {}
    /// A writer for a subtree built on another thread: its own piece and statistics (attached
    /// to the parent's afterwards), no progress reports.
    KdNodeWriter(const KdNodeWriter& parent, KdPiece& piece, TreeStats& stats)
        : prims(parent.prims),
          opt(parent.opt),
          maxDepth(parent.maxDepth),
          rec(parent.rec),
          nodes_(piece.nodes),
          ids_(piece.ids),
          attached_(piece.attached),
          stats_(stats),
          progress_(noProgress_) {}
    KdNodeWriter(const KdNodeWriter&) = delete;
    KdNodeWriter& operator=(const KdNodeWriter&) = delete;

    /// A new node of `count` primitives in `box`; returns its id.
    std::uint32_t openNode(const Box& box, int depth, std::uint32_t count, std::uint32_t parent) {
        const auto id = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        stats_.maxDepth = std::max<std::uint32_t>(stats_.maxDepth, depth);
        if constexpr (Rec::kEnabled) {
            rec.node(id, box.lo3(), box.hi3());
            rec(BuildNode{id, parent, static_cast<std::uint32_t>(depth), count, opt.cIsect,
                          leafCost(opt.cIsect, count)});
        }
        return id;
    }

    /// IsLeaf: makes node `id` a leaf of the primitives `append(ids_)` appends to the tree's ids,
    /// written in place, not gathered into a vector first (a malloc per leaf, 2% of the fast
    /// build).
    template <typename Append>
    void makeLeaf(std::uint32_t id, LeafReason reason, int depth, Append&& append) {
        const std::size_t at = ids_.size();
        append(ids_);
        std::sort(ids_.begin() + at, ids_.end());  // tested in id order, as brute force does
        KdNode& node = nodes_[id];
        node.axis = KdNode::kLeaf;
        node.index = static_cast<std::uint32_t>(at);
        node.count = static_cast<std::uint32_t>(ids_.size() - at);
        ++stats_.leaves;
        stats_.emptyLeaves += node.count == 0;
        ++stats_.leafReasons[static_cast<int>(reason)];
        if constexpr (Rec::kEnabled)
            rec(LeafMade{id, reason, node.count, static_cast<std::uint32_t>(depth),
                         leafCost(opt.cIsect, node.count)});
        progress_.leafDone();
    }
    /// Appends all of `prims` (a leaf's primitives held in a vector).
    static auto allOf(const std::vector<std::uint32_t>& prims) {
        return [&prims](std::vector<std::uint32_t>& out) {
            out.insert(out.end(), prims.begin(), prims.end());
        };
    }
    /// The rules every split method shares: few enough primitives, or the depth limit, make a
    /// leaf (of what `append` appends). True if node `id` became one.
    template <typename Append>
    bool leafByCount(std::uint32_t id, std::uint32_t n, int depth, Append&& append) {
        if (n <= static_cast<std::uint32_t>(opt.leafSize)) {
            makeLeaf(id, LeafReason::FewPrimitives, depth, append);
            return true;
        }
        if (depth >= maxDepth) {
            makeLeaf(id, LeafReason::MaxDepth, depth, append);
            return true;
        }
        return false;
    }

    /// Makes node `id` an interior node split on `axis` at `pos`.
    void makeInterior(std::uint32_t id, int axis, double pos, double cost, double costAsLeaf) {
        nodes_[id].axis = static_cast<std::uint8_t>(axis);
        nodes_[id].split = pos;
        if constexpr (Rec::kEnabled)
            rec(SplitChosen{id, static_cast<std::uint8_t>(axis), pos, cost, costAsLeaf});
    }
    /// Builds node `id`'s children in the tree's order, left next to it, then the right, whose
    /// index the node records; `fl` is the left's share of the progress.
    template <typename Left, typename Right>
    void children(std::uint32_t id, double fl, Left&& left, Right&& right) {
        progress_.child(fl, left);
        nodes_[id].index = static_cast<std::uint32_t>(nodes_.size());
        progress_.child(1 - fl, right);
    }
    BuildProgress& progress() { return progress_; }

    /// A subtree built apart becomes node `parent`'s right child, where the next node would go
    /// (the tree's arrays get it once the whole tree is built).
    void attach(std::uint32_t parent, std::unique_ptr<KdPiece> piece, const TreeStats& subStats) {
        attached_.push_back({parent, static_cast<std::uint32_t>(nodes_.size()),
                             static_cast<std::uint32_t>(ids_.size()), std::move(piece)});
        stats_.leaves += subStats.leaves;
        stats_.emptyLeaves += subStats.emptyLeaves;
        stats_.maxDepth = std::max(stats_.maxDepth, subStats.maxDepth);
        for (std::size_t r = 0; r < stats_.leafReasons.size(); ++r)
            stats_.leafReasons[r] += subStats.leafReasons[r];
    }

    /// A straddling primitive's bounds on each side of the plane ("perfect splits"): one clip of
    /// it to the node where the primitive set offers that (triangles), else one clip per side.
    std::pair<Box, Box> clipToSides(std::uint32_t p, const Box& box, int axis, double pos) const {
        if constexpr (requires { prims.splitBounds(p, box, axis, pos); }) {
            return prims.splitBounds(p, box, axis, pos);
        } else {
            const auto [l, r] = box.splitAt(axis, pos);
            return {prims.clippedBounds(p, l), prims.clippedBounds(p, r)};
        }
    }

    /// Area(box with its extent along `axis` set to w) = 2 (w a + b): in 3D a is the sum and b
    /// the product of the other two extents; in 2D (the perimeter) a = 1, b the other extent.
    static std::pair<double, double> areaTerms(const Box& box, int axis) {
        const VecN<N, double> d = box.diagonal();
        if constexpr (N == 3) {
            const double e1 = d[(axis + 1) % 3], e2 = d[(axis + 2) % 3];
            return {e1 + e2, e1 * e2};
        } else {
            return {1.0, d[1 - axis]};
        }
    }
    /// Area of `box` with its extent along `axis` replaced by `width`: the SAH's Area(L) and
    /// Area(R) in closed form, without building the child boxes.
    static double areaWithWidth(const Box& box, int axis, double width) {
        const auto [a, b] = areaTerms(box, axis);
        return 2.0 * (width * a + b);
    }
    /// The root's box: the primitives' bounds `all`, or a point for none.
    static Box rootBox(const Box& all, std::uint32_t n) {
        return n > 0 ? all : Box{VecN<N, double>(0.0), VecN<N, double>(0.0)};
    }

    const Prims& prims;
    const KdTreeOptions& opt;
    const int maxDepth;
    Rec& rec;

  private:
    std::vector<KdNode>& nodes_;
    std::vector<std::uint32_t>& ids_;
    std::vector<KdAttached>& attached_;
    TreeStats& stats_;
    ProgressFn noProgress_;
    BuildProgress progress_;
};

/// The exact SAH sweep of kdtree.cpp, for the nodes of the --bin-above hybrid that are small
/// enough (kdtree_fast.cpp hands them over).
template <typename Prims, typename Rec>
class SahSweep {
  public:
    using Box = BoxN<Prims::N>;
    explicit SahSweep(KdNodeWriter<Prims, Rec>& out);
    /// Builds the subtree of the n primitives whose (clipped) bounds gave `events`, sorted.
    void build(std::vector<SplitEvent> events, std::uint32_t n, const Box& box, int depth,
               std::uint32_t parent);

  private:
    enum class Side : std::uint8_t { Both, Left, Right };
    KdNodeWriter<Prims, Rec>& out_;
    std::vector<Side> side_;  // by primitive: which side of the chosen plane
};

/// The SAH tree over bins (--kd-build fast, or --bin-above's big nodes), from the root; returns
/// the root's box (kdtree_fast.cpp).
template <typename Prims, typename Rec>
BoxN<Prims::N> buildSahBinned(KdNodeWriter<Prims, Rec>& out);

/// The root piece with every subtree attached to it, copied into the tree's arrays in the order
/// one thread would have made them (kdtree_fast.cpp).
void spliceSubtrees(KdPiece& root, std::vector<KdNode>& nodes, std::vector<std::uint32_t>& ids);

}  // namespace raystep::kdbuild
