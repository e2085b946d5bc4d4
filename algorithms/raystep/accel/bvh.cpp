#include "raystep/accel/bvh.h"
#include "raystep/accel/query_impl.h"

#include "raystep/accel/mailbox.h"
#include "raystep/base/timer.h"
#include "raystep/scene/fast_prims.h"
#include "raystep/scene/scene2d.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <utility>

namespace raystep {

namespace {
constexpr int kMaxBvhDepth = 48;  // deeper nodes split by the median, so the stack stays small
constexpr int kStackSize = 64;
}  // namespace

template <typename Prims, typename Rec>
class BvhBuilder {
  public:
    static constexpr int N = Prims::N;
    using Box = BoxN<N>;

    BvhBuilder(const Prims& prims, const BvhOptions& opt, Rec& rec, std::vector<BvhNode<N>>& nodes,
               std::vector<std::uint32_t>& ids, TreeStats& stats)
        : opt_(opt), rec_(rec), nodes_(nodes), ids_(ids), stats_(stats) {
        const std::uint32_t n = prims.count();
        bounds_.resize(n);
        centres_.resize(n);
        for (std::uint32_t p = 0; p < n; ++p) {
            bounds_[p] = prims.bounds(p);
            centres_[p] = bounds_[p].centroid();
        }
        ids_.resize(n);
        std::iota(ids_.begin(), ids_.end(), 0u);
    }

    /// One node over ids_[begin, end): its box, then a leaf, or a split and the two children.
    std::uint32_t build(std::uint32_t begin, std::uint32_t end, int depth, std::uint32_t parent) {
        const auto id = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        Box box, centreBox;
        for (std::uint32_t k = begin; k < end; ++k) {
            box.extend(bounds_[ids_[k]]);
            centreBox.extend(centres_[ids_[k]]);
        }
        nodes_[id].bounds = box;
        const std::uint32_t n = end - begin;
        stats_.maxDepth = std::max<std::uint32_t>(stats_.maxDepth, depth);
        if constexpr (Rec::kEnabled) {
            rec_.node(id, box.lo3(), box.hi3());
            rec_(BuildNode{id, parent, static_cast<std::uint32_t>(depth), n, opt_.cIsect,
                           opt_.cIsect * n});
        }
        const int axis = centreBox.longestAxis();
        if (n <= 1 || (opt_.split != SplitMethod::Sah && n <= maxLeaf()))
            return leaf(id, begin, end, LeafReason::FewPrimitives, depth);
        if (!(centreBox.hi[axis] > centreBox.lo[axis]))
            return leaf(id, begin, end, LeafReason::NoSplit, depth);

        // The three builds, one case each; past kMaxBvhDepth every method splits by the median.
        const Node node{id, begin, end, axis, centreBox.lo[axis], centreBox.hi[axis], box};
        Split split;
        switch (depth >= kMaxBvhDepth ? SplitMethod::Median : opt_.split) {
            case SplitMethod::Midpoint:
                split = splitMidpoint(node);
                break;
            case SplitMethod::Median:
                split = splitMedian(node);
                break;
            case SplitMethod::Sah:
                split = splitSahBinned(node);
                break;
        }
        if (split.leaf) return leaf(id, begin, end, *split.leaf, depth);

        if constexpr (Rec::kEnabled)
            rec_(SplitChosen{id, static_cast<std::uint8_t>(axis), split.position, split.cost,
                             opt_.cIsect * n});
        nodes_[id].axis = static_cast<std::uint8_t>(axis);
        const std::uint32_t mid = split.mid;
        const double fl = double(mid - begin) / n;
        progress_.child(fl, [&] { build(begin, mid, depth + 1, id); });
        std::uint32_t right = 0;
        progress_.child(1 - fl, [&] { right = build(mid, end, depth + 1, id); });
        nodes_[id].index = right;
        return id;
    }

  private:
    /// The node being split: ids_[begin, end), split along `axis` of the centres' bounds [lo, hi].
    struct Node {
        std::uint32_t id, begin, end;
        int axis;
        double lo, hi;
        const Box& box;
        std::uint32_t count() const { return end - begin; }
    };
    /// ids_[begin, mid) go left, [mid, end) right; or, when the SAH says so, a leaf.
    struct Split {
        std::uint32_t mid = 0;
        double position = 0.0, cost = 0.0;
        std::optional<LeafReason> leaf;
    };

    std::size_t maxLeaf() const {
        return opt_.split == SplitMethod::Sah ? std::max(opt_.maxLeafSize, 1)
                                              : std::max(opt_.leafSize, 1);
    }
    double centre(std::uint32_t p, int axis) const { return centres_[p][axis]; }

    /// Midpoint: the middle of the centres' bounds; everything on one side falls back to the
    /// median (pbrt's fallback).
    Split splitMidpoint(const Node& node) {
        const double position = 0.5 * (node.lo + node.hi);
        std::uint32_t* first = ids_.data() + node.begin;
        const std::uint32_t mid =
            node.begin +
            static_cast<std::uint32_t>(
                std::partition(first, ids_.data() + node.end,
                               [&](std::uint32_t p) { return centre(p, node.axis) < position; }) -
                first);
        if (mid == node.begin || mid == node.end) return splitMedian(node);
        return costOf(node, mid, position);
    }

    /// Median: equal counts on both sides, split at the middle primitive's centre.
    Split splitMedian(const Node& node) {
        const std::uint32_t mid = node.begin + node.count() / 2;
        std::nth_element(ids_.data() + node.begin, ids_.data() + mid, ids_.data() + node.end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             return centre(a, node.axis) < centre(b, node.axis);
                         });
        return costOf(node, mid, centre(ids_[mid], node.axis));
    }

    /// The chosen split's SAH cost, for the record and the comparison of strategies.
    Split costOf(const Node& node, std::uint32_t mid, double position) {
        Box l, r;
        for (std::uint32_t k = node.begin; k < mid; ++k) l.extend(bounds_[ids_[k]]);
        for (std::uint32_t k = mid; k < node.end; ++k) r.extend(bounds_[ids_[k]]);
        const double area = node.box.area();
        const double pl = area > 0 ? l.area() / area : 0.5, pr = area > 0 ? r.area() / area : 0.5;
        const double cost =
            sahCost(opt_.cTrav, opt_.cIsect, 0.0, pl, pr, mid - node.begin, node.end - mid);
        if constexpr (Rec::kEnabled)
            rec_(SplitCandidate{node.id, static_cast<std::uint8_t>(node.axis), mid - node.begin,
                                node.end - mid, position, pl, pr, cost});
        return {mid, position, cost, std::nullopt};
    }

    /// Binned SAH: bin the centres, then sweep the bucket boundaries, the cost of each as a
    /// split; a leaf when no split separates anything, or when it is cheaper and small enough.
    Split splitSahBinned(const Node& node) {
        const std::uint32_t n = node.count();
        const double lo = node.lo, hi = node.hi;
        const int nb = std::clamp(opt_.buckets, 2, 256);
        std::vector<std::uint32_t> count(nb, 0);
        std::vector<Box> bucketBox(nb);
        const auto bucketOf = [&](std::uint32_t p) {
            return std::min(nb - 1,
                            static_cast<int>(nb * ((centre(p, node.axis) - lo) / (hi - lo))));
        };
        for (std::uint32_t k = node.begin; k < node.end; ++k) {
            const int b = bucketOf(ids_[k]);
            ++count[b];
            bucketBox[b].extend(bounds_[ids_[k]]);
        }
        std::vector<Box> below(nb);  // below[i]: buckets 0..i
        Box acc;
        for (int i = 0; i < nb; ++i) acc.extend(bucketBox[i]), below[i] = acc;
        const double area = node.box.area();
        double best = kInfinity;
        int bestSplit = -1;
        Box above;
        std::uint32_t nAbove = 0;
        std::vector<double> costs(nb - 1);
        std::vector<std::pair<double, double>> ratios(nb - 1);
        std::vector<std::uint32_t> nLeft(nb - 1);
        for (int i = nb - 1; i > 0; --i) {  // split between bucket i-1 and i
            above.extend(bucketBox[i]);
            nAbove += count[i];
            const std::uint32_t nBelow = n - nAbove;
            const double pl = nBelow ? below[i - 1].area() / area : 0.0;
            const double pr = nAbove ? above.area() / area : 0.0;
            costs[i - 1] = (nBelow && nAbove)
                               ? sahCost(opt_.cTrav, opt_.cIsect, 0.0, pl, pr, nBelow, nAbove)
                               : kInfinity;  // everything on one side splits nothing
            ratios[i - 1] = {pl, pr};
            nLeft[i - 1] = nBelow;
        }
        for (int i = 0; i < nb - 1; ++i) {
            if constexpr (Rec::kEnabled)
                if (std::isfinite(costs[i]))
                    rec_(SplitCandidate{node.id, static_cast<std::uint8_t>(node.axis), nLeft[i],
                                        n - nLeft[i], lo + (hi - lo) * (i + 1) / nb,
                                        ratios[i].first, ratios[i].second, costs[i]});
            if (costs[i] < best) best = costs[i], bestSplit = i;
        }
        const double leafCost = opt_.cIsect * n;
        if (bestSplit < 0) return {0, 0.0, 0.0, LeafReason::NoSplit};
        if (n <= maxLeaf() && leafCost <= best) return {0, 0.0, 0.0, LeafReason::SahCheaper};
        std::uint32_t* first = ids_.data() + node.begin;
        const std::uint32_t mid =
            node.begin +
            static_cast<std::uint32_t>(
                std::partition(first, ids_.data() + node.end,
                               [&](std::uint32_t p) { return bucketOf(p) <= bestSplit; }) -
                first);
        return {mid, lo + (hi - lo) * (bestSplit + 1) / nb, best, std::nullopt};
    }

    std::uint32_t leaf(std::uint32_t id, std::uint32_t begin, std::uint32_t end, LeafReason reason,
                       int depth) {
        std::sort(ids_.begin() + begin, ids_.begin() + end);  // tested in id order
        nodes_[id].index = begin;
        nodes_[id].count = end - begin;
        ++stats_.leaves;
        ++stats_.leafReasons[static_cast<int>(reason)];
        if constexpr (Rec::kEnabled)
            rec_(LeafMade{id, reason, end - begin, static_cast<std::uint32_t>(depth),
                          opt_.cIsect * (end - begin)});
        progress_.leafDone();
        return id;
    }

    const BvhOptions& opt_;
    Rec& rec_;
    std::vector<BvhNode<N>>& nodes_;
    std::vector<std::uint32_t>& ids_;
    TreeStats& stats_;
    std::vector<Box> bounds_;
    std::vector<VecN<N, double>> centres_;
    BuildProgress progress_{opt_.progress};
};

template <int N>
double bvhSahCost(const std::vector<BvhNode<N>>& nodes, std::uint32_t id, const BvhOptions& opt) {
    const BvhNode<N>& node = nodes[id];
    if (node.leaf()) return leafCost(opt.cIsect, node.count);
    const double area = node.bounds.area();
    if (!(area > 0)) return opt.cTrav;
    return interiorCost(opt.cTrav, area, nodes[id + 1].bounds.area(),
                        bvhSahCost(nodes, id + 1, opt), nodes[node.index].bounds.area(),
                        bvhSahCost(nodes, node.index, opt));
}

template <typename Prims>
Bvh<Prims>::Bvh(Prims prims, const BvhOptions& options)
    : prims_(std::move(prims)), options_(options) {
    NullRecorder rec;
    build(rec);
}

template <typename Prims>
Bvh<Prims>::Bvh(Prims prims, const BvhOptions& options, EventLog& log)
    : prims_(std::move(prims)), options_(options) {
    build(log);
}

template <typename Prims>
template <typename Rec>
void Bvh<Prims>::build(Rec& rec) {
    ScopedTimer timer(stats_.buildMs);
    const std::uint32_t n = prims_.count();
    if (n > 0) {
        nodes_.reserve(2 * std::size_t(n));
        BvhBuilder<Prims, Rec> builder(prims_, options_, rec, nodes_, primIds_, stats_);
        builder.build(0, n, 0, kNoId);
        stats_.sahCost = bvhSahCost(nodes_, 0, options_);
    }
    stats_.nodes = static_cast<std::uint32_t>(nodes_.size());
    stats_.references = primIds_.size();
    options_.progress = nullptr;  // it may refer to the caller's locals: only the build used it
}

template <typename Prims>
template <bool AnyHit, typename Rec>
auto Bvh<Prims>::traverse(RayT ray, TraversalCounters& counters, Rec& rec,
                          std::uint32_t rayId) const -> std::optional<HitT> {
    if (nodes_.empty()) return std::nullopt;
    const VecN<N, double> invDir = inverseDirection<N>(ray.dir);
    std::uint32_t todo[kStackSize];
    int top = 0;
    std::optional<HitT> closest;
    HitT hit;
    std::uint32_t id = 0;
    for (;;) {
        const BvhNode<N>& node = nodes_[id];
        // ray.tMax is the nearest hit so far: a box that starts beyond it is skipped.
        if (const auto range =
                intersectBoxN<N>(ray.origin, invDir, node.bounds, ray.tMin, ray.tMax)) {
            ++counters.nodeVisits;
            if constexpr (Rec::kEnabled) rec(NodeEnter{rayId, id, range->first, range->second});
            if (!node.leaf()) {
                // Nearer child first: the one on the side the ray comes from.
                if (invDir[node.axis] < 0) {
                    todo[top++] = id + 1;
                    id = node.index;
                } else {
                    todo[top++] = node.index;
                    id = id + 1;
                }
                continue;
            }
            // Each primitive is in one leaf only: no mailbox needed.
            for (std::uint32_t k = 0; k < node.count; ++k)
                if (visitPrimitive<AnyHit>(prims_, primIds_[node.index + k], ray, hit, closest,
                                           nullptr, counters, rec, rayId))
                    return hit;
        } else if constexpr (Rec::kEnabled) {
            const auto whole =
                intersectBoxN<N>(ray.origin, invDir, node.bounds, ray.tMin, kInfinity);
            rec(NodeSkip{rayId, id, whole ? whole->first : kInfinity,
                         whole ? whole->second : kInfinity});
        }
        if (top == 0) break;
        id = todo[--top];
    }
    return closest;
}

template class Bvh<ScenePrims>;
template class Bvh<Scene2DPrims>;
template class Bvh<FloatScenePrims>;
template class Queries<Bvh<ScenePrims>, ScenePrims>;
template class Queries<Bvh<Scene2DPrims>, Scene2DPrims>;
template class Queries<Bvh<FloatScenePrims>, FloatScenePrims>;

}  // namespace raystep
