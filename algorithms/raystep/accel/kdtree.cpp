// The kd-tree of the lecture: how the slides build it (midpoint, median, the SAH) and TestTree,
// the traversal. The fast binned build (--kd-build fast, --bin-above) is kdtree_fast.cpp; what the
// builds share (nodes, leaves, clipping, split events) is kdtree_build.h.
#include "raystep/accel/kdtree.h"
#include "raystep/accel/query_impl.h"

#include "raystep/accel/kdtree_build.h"
#include "raystep/accel/mailbox.h"
#include "raystep/base/names.h"
#include "raystep/base/timer.h"
#include "raystep/scene/fast_prims.h"
#include "raystep/scene/scene2d.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace raystep {

namespace {
constexpr NameTable<KdBuild, 2> kBuildNames{{{KdBuild::Exact, "exact"}, {KdBuild::Fast, "fast"}}};
constexpr double kEps = std::numeric_limits<double>::epsilon();
}  // namespace

std::optional<KdBuild> parseKdBuild(std::string_view s) {
    return valueNamed(kBuildNames, s);
}
std::string_view name(KdBuild b) {
    return nameOf(kBuildNames, b);
}

namespace kdbuild {

// ---- "A metà" and "Nel punto mediano": midpoint and median splits ----

/// Midpoint and median: one plane on the node's longest axis, the middle of the node or the
/// median of the primitives' centres. No cost stops them: the leaf size and the depth do.
template <typename Prims, typename Rec>
class MidpointMedian {
  public:
    using Box = BoxN<Prims::N>;
    explicit MidpointMedian(KdNodeWriter<Prims, Rec>& out) : out_(out) {}

    /// Builds the whole tree; returns the root's box.
    Box build() {
        const std::uint32_t n = out_.prims.count();
        bounds_.resize(n);
        Box box;
        for (std::uint32_t p = 0; p < n; ++p) {
            bounds_[p] = out_.prims.bounds(p);
            box.extend(bounds_[p]);
        }
        box = out_.rootBox(box, n);
        std::vector<std::uint32_t> all(n);
        for (std::uint32_t p = 0; p < n; ++p) all[p] = p;
        node(std::move(all), box, 0, kNoId);
        return box;
    }

  private:
    void node(std::vector<std::uint32_t> prims, const Box& box, int depth, std::uint32_t parent) {
        const auto n = static_cast<std::uint32_t>(prims.size());
        const KdTreeOptions& opt = out_.opt;
        const std::uint32_t id = out_.openNode(box, depth, n, parent);
        if (out_.leafByCount(id, n, depth, out_.allOf(prims))) return;

        // Where the plane goes: the longest axis, at its middle or at the median centre.
        const int axis = box.longestAxis();
        double pos;
        if (opt.split == SplitMethod::Midpoint) {
            pos = box.centroid()[axis];
        } else {
            std::vector<double> centres(n);
            for (std::uint32_t k = 0; k < n; ++k)
                centres[k] = out_.prims.clippedBounds(prims[k], box).centroid()[axis];
            std::nth_element(centres.begin(), centres.begin() + n / 2, centres.end());
            pos = centres[n / 2];
        }
        if (!(pos > box.lo[axis] && pos < box.hi[axis]))
            return out_.makeLeaf(id, LeafReason::NoSplit, depth, out_.allOf(prims));

        // Which side each primitive goes to: every side its clipped part reaches (one flat in
        // the plane, both).
        // Not a structured binding: clang 14 cannot capture one in the lambdas below.
        const auto halves = box.splitAt(axis, pos);
        const Box& boxL = halves.first;
        const Box& boxR = halves.second;
        std::vector<std::uint32_t> left, right;
        for (std::uint32_t p : prims) {
            const Box& b = bounds_[p];
            if (b.hi[axis] < pos) {
                left.push_back(p);  // wholly on one side: no clipping needed
            } else if (b.lo[axis] > pos) {
                right.push_back(p);
            } else {
                const auto [l, r] = out_.clipToSides(p, box, axis, pos);
                if (!l.empty()) left.push_back(p);
                if (!r.empty()) right.push_back(p);
            }
        }
        // The plane's SAH cost, recorded so the three methods can be compared.
        const auto nl = static_cast<std::uint32_t>(left.size());
        const auto nr = static_cast<std::uint32_t>(right.size());
        const double areaC = box.area();
        const double pl = areaC > 0 ? boxL.area() / areaC : 0.5;
        const double pr = areaC > 0 ? boxR.area() / areaC : 0.5;
        const double cost = sahCost(opt.cTrav, opt.cIsect, opt.emptyBonus, pl, pr, nl, nr);
        if constexpr (Rec::kEnabled)
            out_.rec(
                SplitCandidate{id, static_cast<std::uint8_t>(axis), nl, nr, pos, pl, pr, cost});
        if (nl == n && nr == n)
            return out_.makeLeaf(id, LeafReason::NoProgress, depth, out_.allOf(prims));
        prims = {};

        // Build the children.
        out_.makeInterior(id, axis, pos, cost, leafCost(opt.cIsect, n));
        const double fl = double(nl) / double(nl + nr);
        out_.children(
            id, fl, [&] { node(std::move(left), boxL, depth + 1, id); },
            [&] { node(std::move(right), boxR, depth + 1, id); });
    }

    KdNodeWriter<Prims, Rec>& out_;
    std::vector<Box> bounds_;  // each primitive's bounds
};

// ---- The SAH: every split event of each axis, swept in order (Wald & Havran 2006) ----

template <typename Prims, typename Rec>
SahSweep<Prims, Rec>::SahSweep(KdNodeWriter<Prims, Rec>& out)
    : out_(out), side_(out.prims.count(), Side::Both) {}

/// One sweep over the sorted events of each axis evaluates every candidate plane; the chosen
/// plane splits the event lists in order, so no sort happens below the root except for the few
/// primitives that straddle the plane.
template <typename Prims, typename Rec>
void SahSweep<Prims, Rec>::build(std::vector<SplitEvent> events, std::uint32_t n, const Box& box,
                                 int depth, std::uint32_t parent) {
    const KdTreeOptions& opt = out_.opt;
    const std::uint32_t id = out_.openNode(box, depth, n, parent);
    const auto nodePrims = [&](std::vector<std::uint32_t>& out) {
        for (const SplitEvent& e : events)
            if (e.axis == 0 && e.type != EventType::End) out.push_back(e.prim);
    };
    if (out_.leafByCount(id, n, depth, nodePrims)) return;

    // Evaluate every split event of each axis: sweeping left to right, nl primitives lie left
    // of the plane and nr right of it.
    const double areaC = box.area();
    const double costAsLeaf = leafCost(opt.cIsect, n);
    // The costs in locals: the sweep reads them at every event.
    const double cTrav = opt.cTrav, cIsect = opt.cIsect, emptyBonus = opt.emptyBonus;
    double bestCost = kInfinity, bestPos = 0.0;
    int bestAxis = -1;
    bool bestPlanarLeft = true;
    std::size_t i = 0;
    for (int axis = 0; axis < Prims::N; ++axis) {
        std::uint32_t nl = 0, nr = n;
        while (i < events.size() && events[i].axis == axis) {
            const double p = events[i].pos;
            std::uint32_t ends = 0, planars = 0, starts = 0;
            while (i < events.size() && events[i].axis == axis && events[i].pos == p &&
                   events[i].type == EventType::End)
                ++ends, ++i;
            while (i < events.size() && events[i].axis == axis && events[i].pos == p &&
                   events[i].type == EventType::Planar)
                ++planars, ++i;
            while (i < events.size() && events[i].axis == axis && events[i].pos == p &&
                   events[i].type == EventType::Start)
                ++starts, ++i;
            nr -= planars + ends;
            // Only planes strictly inside the node cut it into two smaller boxes.
            if (p > box.lo[axis] && p < box.hi[axis] && areaC > 0.0) {
                // Prob(L|C) and Prob(R|C): the children's areas over the node's.
                const double pl = out_.areaWithWidth(box, axis, p - box.lo[axis]) / areaC;
                const double pr = out_.areaWithWidth(box, axis, box.hi[axis] - p) / areaC;
                // Primitives lying in the plane go to whichever side is cheaper.
                const double costL = sahCost(cTrav, cIsect, emptyBonus, pl, pr, nl + planars, nr);
                const double costR = sahCost(cTrav, cIsect, emptyBonus, pl, pr, nl, nr + planars);
                const bool planarLeft = costL <= costR;
                const double cost = planarLeft ? costL : costR;
                const std::uint32_t nlChosen = planarLeft ? nl + planars : nl;
                const std::uint32_t nrChosen = planarLeft ? nr : nr + planars;
                const double minSlab = kMinEmptySlab * (box.hi[axis] - box.lo[axis]);
                if ((nlChosen == 0 && p - box.lo[axis] < minSlab) ||
                    (nrChosen == 0 && box.hi[axis] - p < minSlab)) {
                    nl += starts + planars;
                    continue;  // a rounding-thin "empty" slab (kMinEmptySlab)
                }
                if constexpr (Rec::kEnabled)
                    out_.rec(SplitCandidate{id, static_cast<std::uint8_t>(axis), nlChosen, nrChosen,
                                            p, pl, pr, cost});
                if (cost < bestCost) {
                    bestCost = cost;
                    bestPos = p;
                    bestAxis = axis;
                    bestPlanarLeft = planarLeft;
                }
            }
            nl += starts + planars;
        }
    }
    if (bestAxis < 0) return out_.makeLeaf(id, LeafReason::NoSplit, depth, nodePrims);
    if (!(bestCost < costAsLeaf))
        return out_.makeLeaf(id, LeafReason::SahCheaper, depth, nodePrims);

    // Which side each primitive goes to, read off its events on the chosen axis.
    for (const SplitEvent& e : events) side_[e.prim] = Side::Both;
    for (const SplitEvent& e : events) {
        if (e.axis != bestAxis) continue;
        if (e.type == EventType::End && e.pos <= bestPos)
            side_[e.prim] = Side::Left;
        else if (e.type == EventType::Start && e.pos >= bestPos)
            side_[e.prim] = Side::Right;
        else if (e.type == EventType::Planar) {
            if (e.pos < bestPos || (e.pos == bestPos && bestPlanarLeft))
                side_[e.prim] = Side::Left;
            else
                side_[e.prim] = Side::Right;
        }
    }

    // The children's events: those of one side keep their order; a straddling primitive is
    // clipped to each side ("perfect splits") and its new events are sorted and merged in.
    // Not a structured binding: clang 14 cannot capture one in the lambdas below.
    const auto halves = box.splitAt(bestAxis, bestPos);
    const Box& boxL = halves.first;
    const Box& boxR = halves.second;
    std::vector<SplitEvent> left, right, bothL, bothR;
    std::uint32_t nl = 0, nr = 0;
    for (const SplitEvent& e : events) {
        const Side s = side_[e.prim];
        if (s == Side::Left)
            left.push_back(e);
        else if (s == Side::Right)
            right.push_back(e);
        if (e.axis == 0 && e.type != EventType::End) {  // once per primitive
            nl += s != Side::Right;
            nr += s != Side::Left;
            if (s == Side::Both) {
                // A side its bounding box overlaps but the primitive itself misses does not get
                // it at all.
                const auto [l, r] = out_.clipToSides(e.prim, box, bestAxis, bestPos);
                if (l.empty())
                    --nl;
                else
                    addEvents(e.prim, l, bothL);
                if (r.empty())
                    --nr;
                else
                    addEvents(e.prim, r, bothR);
            }
        }
    }
    events.clear();
    events.shrink_to_fit();
    std::sort(bothL.begin(), bothL.end());
    std::sort(bothR.begin(), bothR.end());
    std::vector<SplitEvent> mergedL(left.size() + bothL.size());
    std::merge(left.begin(), left.end(), bothL.begin(), bothL.end(), mergedL.begin());
    std::vector<SplitEvent> mergedR(right.size() + bothR.size());
    std::merge(right.begin(), right.end(), bothR.begin(), bothR.end(), mergedR.begin());
    left = {};
    right = {};

    // Build the children.
    out_.makeInterior(id, bestAxis, bestPos, bestCost, costAsLeaf);
    const double fl = double(nl) / double(nl + nr);
    out_.children(
        id, fl, [&] { build(std::move(mergedL), nl, boxL, depth + 1, id); },
        [&] { build(std::move(mergedR), nr, boxR, depth + 1, id); });
}

/// The SAH tree by the sweep, from the root; returns the root's box.
template <typename Prims, typename Rec>
BoxN<Prims::N> buildSahSweep(KdNodeWriter<Prims, Rec>& out) {
    const std::uint32_t n = out.prims.count();
    std::vector<BoxN<Prims::N>> bounds(n);
    BoxN<Prims::N> box;
    for (std::uint32_t p = 0; p < n; ++p) {
        bounds[p] = out.prims.bounds(p);
        box.extend(bounds[p]);
    }
    box = out.rootBox(box, n);
    std::vector<SplitEvent> events;
    events.reserve(std::size_t(2) * Prims::N * n);
    for (std::uint32_t p = 0; p < n; ++p) addEvents(p, bounds[p].clippedTo(box), events);
    std::sort(events.begin(), events.end());
    SahSweep<Prims, Rec>(out).build(std::move(events), n, box, 0, kNoId);
    return box;
}

}  // namespace kdbuild

// ---- The tree ----

/// The tree's expected SAH cost, node by node from the root box. The top `parallelLevels` levels
/// evaluate their two subtrees on two cores (a million-triangle tree took 20 ms on one).
template <int N>
double treeSahCost(const std::vector<KdNode>& nodes, std::uint32_t id, const BoxN<N>& box,
                   const KdTreeOptions& opt, int parallelLevels = 0) {
    const KdNode& node = nodes[id];
    if (node.leaf()) return leafCost(opt.cIsect, node.count);
    // Not a structured binding: clang 14 cannot capture one in the lambdas below.
    const auto halves = box.splitAt(node.axis, node.split);
    const BoxN<N>& l = halves.first;
    const BoxN<N>& r = halves.second;
    double costL = 0.0, costR = 0.0;
    if (parallelLevels > 0) {
        tbb::parallel_invoke(
            [&] { costL = treeSahCost(nodes, id + 1, l, opt, parallelLevels - 1); },
            [&] { costR = treeSahCost(nodes, node.index, r, opt, parallelLevels - 1); });
    } else {
        costL = treeSahCost(nodes, id + 1, l, opt);
        costR = treeSahCost(nodes, node.index, r, opt);
    }
    return interiorCost(opt.cTrav, box.area(), l.area(), costL, r.area(), costR);
}

template <typename Prims>
KdTree<Prims>::KdTree(Prims prims, const KdTreeOptions& options)
    : prims_(std::move(prims)), options_(options) {
    NullRecorder rec;
    build(rec);
}

template <typename Prims>
KdTree<Prims>::KdTree(Prims prims, const KdTreeOptions& options, EventLog& log)
    : prims_(std::move(prims)), options_(options) {
    build(log);
}

template <typename Prims>
template <typename Rec>
void KdTree<Prims>::build(Rec& rec) {
    using namespace kdbuild;
    const ScopedTimer timer(stats_.buildMs);
    const std::uint32_t n = prims_.count();
    if (options_.leafSize <= 0) options_.leafSize = options_.split == SplitMethod::Sah ? 1 : 4;
    maxDepth_ = options_.maxDepth > 0
                    ? options_.maxDepth
                    : static_cast<int>(std::lround(8 + 1.3 * std::log2(std::max(n, 1u))));
    maxDepth_ = std::min(maxDepth_, kMaxDepthCap);
    KdPiece root;
    KdNodeWriter<Prims, Rec> out(prims_, options_, maxDepth_, rec, root, stats_);
    if (options_.split != SplitMethod::Sah)
        bounds_ = MidpointMedian<Prims, Rec>(out).build();
    else if (options_.build == KdBuild::Fast || options_.binAbove > 0)
        bounds_ = buildSahBinned(out);  // kdtree_fast.cpp
    else
        bounds_ = buildSahSweep(out);
    spliceSubtrees(root, nodes_, primIds_);
    stats_.nodes = static_cast<std::uint32_t>(nodes_.size());
    stats_.references = primIds_.size();
    stats_.sahCost = bounds_.area() > 0 ? treeSahCost(nodes_, 0, bounds_, options_, 6)
                                        : leafCost(options_.cIsect, n);
    options_.progress = nullptr;  // it may refer to the caller's locals: only the build used it
}

// ---- TestTree: front to back, with a stack ----

template <typename Prims>
template <bool AnyHit, typename Rec>
auto KdTree<Prims>::testTree(RayT ray, TraversalCounters& counters, Rec& rec,
                             std::uint32_t rayId) const -> std::optional<HitT> {
    const VecN<N, double> invDir = inverseDirection<N>(ray.dir);
    const auto range = intersectBoxN<N>(ray.origin, invDir, bounds_, ray.tMin, ray.tMax);
    if (!range) {
        if constexpr (Rec::kEnabled) rec(NodeSkip{rayId, 0, kInfinity, kInfinity});
        return std::nullopt;
    }
    Mailbox* mailbox = options_.mailbox ? &Mailbox::forThisThread() : nullptr;
    if (mailbox) mailbox->beginRay(prims_.count());

    struct Todo {
        std::uint32_t node;
        double tNear, tFar;
    };
    Todo todo[kdbuild::kMaxDepthCap + 1];
    int top = 0;
    std::optional<HitT> closest;
    HitT hit;
    std::uint32_t id = 0;
    double tNear = range->first, tFar = range->second;
    for (;;) {
        // TestTree's early exit: the nearest hit lies before this node, and before every node
        // still on the stack (they are further along the ray).
        if (closest && closest->t < tNear) {
            if constexpr (Rec::kEnabled) {
                rec(NodeSkip{rayId, id, tNear, tFar});
                while (top > 0) {
                    --top;
                    rec(NodeSkip{rayId, todo[top].node, todo[top].tNear, todo[top].tFar});
                }
            }
            break;
        }
        ++counters.nodeVisits;
        if constexpr (Rec::kEnabled) rec(NodeEnter{rayId, id, tNear, tFar});
        const KdNode& node = nodes_[id];
        if (!node.leaf()) {
            const int axis = node.axis;
            const double o = ray.origin[axis];
            // The split plane's t, with its rounding bounded (two roundings, 4 eps is ample):
            // the children's intervals overlap by that much rather than leave a gap.
            const double tSplit = (node.split - o) * invDir[axis];
            const double tSplitLo = tSplit * (1 - 4 * kEps), tSplitHi = tSplit * (1 + 4 * kEps);
            const bool belowFirst = o < node.split || (o == node.split && ray.dir[axis] <= 0);
            const std::uint32_t first = belowFirst ? id + 1 : node.index;
            const std::uint32_t second = belowFirst ? node.index : id + 1;
            // The sign of tSplit is exact: a rounded difference keeps its sign.
            if (!(tSplit > 0) || tSplitLo > tFar) {
                if constexpr (Rec::kEnabled) rec(NodeSkip{rayId, second, tSplit, tSplit});
                id = first;
            } else if (tSplitHi < tNear) {
                if constexpr (Rec::kEnabled) rec(NodeSkip{rayId, first, tSplit, tSplit});
                id = second;
            } else {
                todo[top++] = {second, std::max(tSplitLo, tNear), tFar};
                id = first;
                tFar = std::min(tSplitHi, tFar);
            }
            continue;
        }
        for (std::uint32_t k = 0; k < node.count; ++k)
            if (visitPrimitive<AnyHit>(prims_, primIds_[node.index + k], ray, hit, closest, mailbox,
                                       counters, rec, rayId))
                return hit;
        if (top == 0) break;
        --top;
        id = todo[top].node;
        tNear = todo[top].tNear;
        tFar = todo[top].tFar;
    }
    return closest;
}

template class KdTree<ScenePrims>;
template class KdTree<Scene2DPrims>;
template class KdTree<FloatScenePrims>;
template class Queries<KdTree<ScenePrims>, ScenePrims>;
template class Queries<KdTree<Scene2DPrims>, Scene2DPrims>;
template class Queries<KdTree<FloatScenePrims>, FloatScenePrims>;

namespace kdbuild {
template class SahSweep<ScenePrims, NullRecorder>;
template class SahSweep<ScenePrims, EventLog>;
template class SahSweep<Scene2DPrims, NullRecorder>;
template class SahSweep<Scene2DPrims, EventLog>;
template class SahSweep<FloatScenePrims, NullRecorder>;
template class SahSweep<FloatScenePrims, EventLog>;
}  // namespace kdbuild

}  // namespace raystep
