// ====== The kd-tree's FAST BUILD: --kd-build fast and --bin-above ======
// Not the lecture's algorithm but its engineering: the same SAH, evaluated over 16-256 equal bins
// per axis instead of at every split event (O(n) a node, no sort), float references on per-thread
// stacks, big nodes partitioned and subtrees built on all cores (TBB), the build's big arrays on
// huge pages, four edges binned at a time (base/simd.h). The lecture's builds and TestTree are
// kdtree.cpp; the figures are in docs/performance.md.
#include "raystep/accel/kdtree_build.h"
#include "raystep/base/simd.h"
#include "raystep/scene/fast_prims.h"
#include "raystep/scene/scene2d.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <optional>

namespace raystep::kdbuild {

namespace {
/// The kernel's huge page: the build's big arrays are offered to it in these, since faulting
/// hundreds of MB in 4 KB at a time cost ~3 microseconds a fault on our VM.
constexpr std::size_t kHugePage = std::size_t(2) << 20;

/// Offers the whole huge pages inside [p, p + bytes), not yet touched, as huge pages.
void offerHugePages([[maybe_unused]] void* p, [[maybe_unused]] std::size_t bytes) {
#if defined(MADV_HUGEPAGE)
    const auto begin = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t first = (begin + kHugePage - 1) / kHugePage * kHugePage;
    const std::uintptr_t last = (begin + bytes) / kHugePage * kHugePage;
    if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
}

/// v.resize(n) on fresh memory offered as huge pages: a million-triangle tree's 35 MB, faulted
/// in 4 KB at a time, took ~20 ms.
template <typename T>
void resizeOnHugePages(std::vector<T>& v, std::size_t n) {
    v.reserve(n);  // allocated, not yet touched
    offerHugePages(v.data(), n * sizeof(T));
    v.resize(n);
}

void sizeUp(KdPiece& piece) {
    piece.totalNodes = piece.nodes.size();
    piece.totalIds = piece.ids.size();
    for (KdAttached& a : piece.attached) {
        sizeUp(*a.piece);
        piece.totalNodes += a.piece->totalNodes;
        piece.totalIds += a.piece->totalIds;
    }
}

/// Copies `piece` and what is attached to it into the tree's arrays from nodeBase and idBase,
/// in the order one thread would have made them: a node or id lands after every piece
/// attached before it was made.
void place(const KdPiece& piece, KdNode* nodes, std::uint32_t* ids, std::size_t nodeBase,
           std::size_t idBase) {
    const std::vector<KdAttached>& attached = piece.attached;
    // shiftN[a], shiftI[a]: nodes and ids of the first a pieces attached.
    std::vector<std::size_t> shiftN(attached.size() + 1), shiftI(attached.size() + 1);
    for (std::size_t a = 0; a < attached.size(); ++a) {
        shiftN[a + 1] = shiftN[a] + attached[a].piece->totalNodes;
        shiftI[a + 1] = shiftI[a] + attached[a].piece->totalIds;
    }
    // How many pieces were attached before local node i (or id i) was made.
    const auto before = [&](std::uint32_t i, std::uint32_t KdAttached::*at) {
        return static_cast<std::size_t>(
            std::partition_point(attached.begin(), attached.end(),
                                 [&](const KdAttached& a) { return a.*at <= i; }) -
            attached.begin());
    };
    std::size_t a = 0;
    for (std::uint32_t i = 0; i < piece.nodes.size(); ++i) {
        while (a < attached.size() && attached[a].nodeAt <= i) ++a;
        KdNode node = piece.nodes[i];
        node.index = static_cast<std::uint32_t>(
            node.leaf() ? idBase + node.index + shiftI[a]
                        : nodeBase + node.index + shiftN[before(node.index, &KdAttached::nodeAt)]);
        nodes[nodeBase + i + shiftN[a]] = node;
    }
    for (std::uint32_t i = 0; i < piece.ids.size(); ++i)
        ids[idBase + i + shiftI[before(i, &KdAttached::idAt)]] = piece.ids[i];
    tbb::parallel_for(std::size_t(0), attached.size(), [&](std::size_t k) {
        const KdAttached& at = attached[k];
        const std::size_t where = nodeBase + at.nodeAt + shiftN[k];
        const std::size_t parent =
            nodeBase + at.parent + shiftN[before(at.parent, &KdAttached::nodeAt)];
        nodes[parent].index = static_cast<std::uint32_t>(where);
        place(*at.piece, nodes, ids, where, idBase + at.idAt + shiftI[k]);
    });
}
}  // namespace

void spliceSubtrees(KdPiece& root, std::vector<KdNode>& nodes, std::vector<std::uint32_t>& ids) {
    if (root.attached.empty()) {
        nodes = std::move(root.nodes);
        ids = std::move(root.ids);
        return;
    }
    sizeUp(root);
    resizeOnHugePages(nodes, root.totalNodes);
    resizeOnHugePages(ids, root.totalIds);
    place(root, nodes.data(), ids.data(), 0, 0);
}

namespace {

/// The binned SAH build: the node's references counted into bins per axis, the cheapest bin
/// boundary chosen, the references partitioned (and counted into the children's bins) in one pass.
template <typename Prims, typename Rec>
class SahBinned {
  public:
    static constexpr int N = Prims::N;
    using Box = BoxN<N>;

    explicit SahBinned(KdNodeWriter<Prims, Rec>& out) : out_(out) {
        // --bin-above: nodes at or below binAbove primitives go to the exact sweep.
        if (out.opt.build != KdBuild::Fast && out.opt.binAbove > 0) sweep_.emplace(out);
    }
    /// A builder for a subtree on another thread, writing to `out`, sharing the parent's stacks.
    SahBinned(const SahBinned& parent, KdNodeWriter<Prims, Rec>& out)
        : out_(out), stacks_(parent.stacks_), stack_(&stacks_->local()) {}
    SahBinned(const SahBinned&) = delete;
    SahBinned& operator=(const SahBinned&) = delete;

    /// The binned build from the root, on this thread's stack; returns the root's box. The
    /// references and the root's box come from one pass over the primitives (a second, for the
    /// box alone, read a million triangles' 80 MB again).
    Box buildRoot() {
        const std::uint32_t n = out_.prims.count();
        const StackFrame frame(*stack_);
        Ref* refs = stack_->push(n);
        const bool fast = out_.opt.build == KdBuild::Fast;
        const bool parallel = fast && !Rec::kEnabled;
        std::vector<Box> part(shareCount(n));
        forEachShare(n, parallel, [&](std::size_t c) {
            const auto [begin, end] = shareRange(c, n);
            for (auto p = static_cast<std::uint32_t>(begin); p < end; ++p) {
                const Box b = out_.prims.bounds(p);
                refs[p] = Ref(p, b);
                part[c].extend(b);
            }
        });
        Box all;
        for (const Box& b : part) all.extend(b);
        const Box box = out_.rootBox(all, n);
        if (fast)
            startBinned<kFastBins>(refs, n, box, parallel);
        else
            startBinned<kBinAboveBins>(refs, n, box, parallel);
        return box;
    }

  private:
    /// A primitive with its bounds clipped to the node (the binned levels), rounded outward to
    /// float: the binned build streams every reference through memory at every level, and half
    /// the bytes of double bounds make it faster. Outward, so the bounds still hold the primitive
    /// and a side it lies wholly on is never mistaken. 16-byte aligned: the binning loads the
    /// edges four at a time.
    struct alignas(16) Ref {
        Ref() = default;
        Ref(std::uint32_t p, const Box& b) : prim(p) {
            double bounds[2 * N];
            for (int a = 0; a < N; ++a) bounds[a] = b.lo[a], bounds[N + a] = b.hi[a];
            simd::roundOutward<N>(bounds, edge.data());
        }
        float lo(int axis) const { return edge[axis]; }
        float hi(int axis) const { return edge[N + axis]; }
        // Left uninitialized by Ref(): RefStack allocates without writing.
        std::array<float, 2 * N> edge;  // lo[0..N), then hi[0..N)
        std::uint32_t prim;
    };

    /// One thread's references as a stack: a node's children are written above its own and
    /// released when its subtree is built, so the build allocates a few times per thread, not
    /// twice per node (malloc and fresh pages were a tenth of the fast build). In segments that
    /// never move, so a subtree handed to another thread reads its references where they are.
    /// Tasks stolen by a waiting thread run to completion above the waiting frame's references:
    /// one stack per thread stays last in, first out.
    class RefStack {
      public:
        struct Mark {
            std::size_t segment, top;
        };
        Mark mark() const { return {segment_, top_}; }
        void release(Mark m) { segment_ = m.segment, top_ = m.top; }
        /// Room for `count` references, uninitialized.
        Ref* push(std::size_t count) {
            if (segment_ < segments_.size() && top_ + count <= segments_[segment_].capacity) {
                Ref* at = segments_[segment_].refs.get() + top_;
                top_ += count;
                return at;
            }
            // The next segment: nothing above this one is in use, so a too small one is replaced.
            const std::size_t next = segments_.empty() ? 0 : segment_ + 1;
            if (next == segments_.size() || segments_[next].capacity < count) {
                const std::size_t capacity =
                    std::max({count, kMinSegment, 2 * (next ? segments_[next - 1].capacity : 0)});
                segments_.resize(std::max(segments_.size(), next + 1));
                segments_[next] = {allocate(capacity), capacity};
            }
            segment_ = next;
            top_ = count;
            return segments_[next].refs.get();
        }

      private:
        static constexpr std::size_t kMinSegment = 1 << 16;
        struct Free {
            void operator()(Ref* p) const { std::free(p); }
        };
        using Refs = std::unique_ptr<Ref[], Free>;
        struct Segment {
            Refs refs;
            std::size_t capacity = 0;
        };
        /// Whole 2 MB pages, offered to the kernel as huge pages: the build touches hundreds of
        /// MB once, and faulting them in 4 KB at a time cost a sixth of the build on our VM
        /// (~3 microseconds a fault).
        static Refs allocate(std::size_t count) {
            const std::size_t bytes = (count * sizeof(Ref) + kHugePage - 1) / kHugePage * kHugePage;
            void* p = std::aligned_alloc(kHugePage, bytes);
            if (!p) throw std::bad_alloc();
            offerHugePages(p, bytes);
            return Refs(static_cast<Ref*>(p));
        }
        std::vector<Segment> segments_;
        std::size_t segment_ = 0, top_ = 0;
    };
    /// Releases what a frame pushed when it returns (or throws).
    class StackFrame {
      public:
        explicit StackFrame(RefStack& stack) : stack_(stack), mark_(stack.mark()) {}
        ~StackFrame() { stack_.release(mark_); }
        StackFrame(const StackFrame&) = delete;
        StackFrame& operator=(const StackFrame&) = delete;

      private:
        RefStack& stack_;
        typename RefStack::Mark mark_;
    };
    using Stacks = tbb::enumerable_thread_specific<RefStack>;

    /// A node's counts over B equal bins per axis: how many references start and end in each
    /// bin, and the references' extent.
    template <int B>
    struct Bins {
        std::array<std::array<std::uint32_t, B>, N> starts{}, ends{};
        std::array<float, N> minLo, maxHi;
        Bins() {
            minLo.fill(std::numeric_limits<float>::infinity());
            maxHi.fill(-std::numeric_limits<float>::infinity());
        }
        void add(const Bins& o) {
            for (int axis = 0; axis < N; ++axis) {
                for (int k = 0; k < B; ++k) {
                    starts[axis][k] += o.starts[axis][k];
                    ends[axis][k] += o.ends[axis][k];
                }
                minLo[axis] = std::min(minLo[axis], o.minLo[axis]);
                maxHi[axis] = std::max(maxHi[axis], o.maxHi[axis]);
            }
        }
    };

    /// Counts references into the bins of `box`: edge j of a reference falls in bin
    /// (edge - lo) * scale, clamped to [0, Fine), of Fine equal bins, merged in runs of Fine / B
    /// (a small node's 16 bins are the fast build's 32 in pairs, so both give the same tree).
    /// In float, as the references are: rounding only moves an edge into a neighbouring bin,
    /// which changes a candidate's estimated cost, never where a primitive goes (the partition
    /// reads the references themselves).
    template <int B, int Fine = B>
    class Binner {
        static_assert(Fine % B == 0 && std::has_single_bit(unsigned(Fine / B)));

      public:
        Binner(const Box& box, Bins<B>& bins) : bins_(bins) {
            std::array<float, N> axisLo, axisScale;  // one division per axis, not per lane
            for (int axis = 0; axis < N; ++axis) {
                const double width = box.hi[axis] - box.lo[axis];
                axisLo[axis] = static_cast<float>(box.lo[axis]);
                axisScale[axis] = width > 0.0 ? static_cast<float>(Fine / width) : 0.0f;
            }
            std::array<float, 8> lo{}, scale{};
            for (int i = 0; i < 8; ++i) {
                lo[i] = axisLo[edgeAt(i) % N];  // lane i reads edge edgeAt(i)
                scale[i] = axisScale[edgeAt(i) % N];
            }
            for (int v = 0; v < kLoads; ++v) {
                lo_[v] = simd::load(&lo[4 * v]);
                scale_[v] = simd::load(&scale[4 * v]);
                min_[v] = simd::splat(std::numeric_limits<float>::infinity());
                max_[v] = simd::splat(-std::numeric_limits<float>::infinity());
            }
        }
        Binner(const Binner&) = delete;
        Binner& operator=(const Binner&) = delete;
        ~Binner() {
            std::array<float, 8> mn, mx;
            for (int v = 0; v < kLoads; ++v) {
                simd::store(&mn[4 * v], min_[v]);
                simd::store(&mx[4 * v], max_[v]);
            }
            for (int axis = 0; axis < N; ++axis) {
                bins_.minLo[axis] = std::min(bins_.minLo[axis], mn[laneOf(axis)]);
                bins_.maxHi[axis] = std::max(bins_.maxHi[axis], mx[laneOf(N + axis)]);
            }
        }
        /// The bins of four edges, lane by lane: edge e of an axis starting at lo, with
        /// Fine / width bins per unit (scale), falls in bin (e - lo) * scale, clamped.
        static simd::Int4 binsOf(simd::Float4 e, simd::Float4 lo, simd::Float4 scale) {
            const simd::Float4 zero = simd::splat(0.0f), top = simd::splat(Fine - 0.5f);
            constexpr int kMerge = std::countr_zero(unsigned(Fine / B));
            const simd::Float4 x = (e - lo) * scale;
            return simd::shiftRight<kMerge>(simd::truncate(simd::min(simd::max(x, zero), top)));
        }
        // Always inlined: one call per reference per level, and GCC left it out of line.
        [[gnu::always_inline]] void add(const Ref& r) {
            alignas(16) std::array<std::int32_t, 8> bin;
            for (int v = 0; v < kLoads; ++v) {
                const simd::Float4 e = simd::load(&r.edge[kLoadAt[v]]);
                simd::store(&bin[4 * v], binsOf(e, lo_[v], scale_[v]));
                min_[v] = simd::min(min_[v], e);
                max_[v] = simd::max(max_[v], e);
            }
            for (int axis = 0; axis < N; ++axis) {
                ++bins_.starts[axis][bin[laneOf(axis)]];
                ++bins_.ends[axis][bin[laneOf(N + axis)]];
            }
        }

      private:
        // The 2N edges in SSE loads of four: 3D edges 0-3 and 2-5 (lanes 0-7), 2D edges 0-3.
        static constexpr int kLoads = N == 3 ? 2 : 1;
        static constexpr std::array<int, 2> kLoadAt{0, 2};
        static constexpr int edgeAt(int lane) { return kLoadAt[lane / 4 % kLoads] + lane % 4; }
        /// The lane that holds edge j: the first load for 3D's lo, the second for its hi.
        static constexpr int laneOf(int j) { return N == 3 && j >= N ? j + 2 : j; }

        Bins<B>& bins_;
        simd::Float4 lo_[kLoads], scale_[kLoads], min_[kLoads], max_[kLoads];
    };
    // Bins per axis: the fast build's 32, and 16 (the 32 in pairs) in its nodes of at most
    // kSmallNode references, where the bins' fixed cost dominates (measured: 11% fewer
    // instructions, SAH cost +1%); the exact build's binned top levels (--bin-above) 256.
    static constexpr int kFastBins = 32;
    static constexpr int kSmallBins = kFastBins / 2;
    static constexpr std::uint32_t kSmallNode = 64;
    static constexpr int kBinAboveBins = 256;
    /// How finely a node of B bins counts its children: a small node's children are small too.
    static constexpr int fineBins(int b) { return b == kSmallBins ? kFastBins : b; }
    // Fast build: nodes above this many references are partitioned and binned by all cores,
    // in shares of kChunk references.
    static constexpr std::uint32_t kParallelNodeAbove = 65536;
    static constexpr std::size_t kChunk = 16384;
    /// How many shares n references make, and where share c begins and ends.
    static std::size_t shareCount(std::size_t n) { return (n + kChunk - 1) / kChunk; }
    static std::pair<std::size_t, std::size_t> shareRange(std::size_t c, std::size_t n) {
        return {c * kChunk, std::min(n, (c + 1) * kChunk)};
    }

    /// Calls visit(k), in order, for each bin boundary k in [1, B) next to an occupied bin (one a
    /// reference starts or ends in): across an empty bin NL and NR stay the same and the cost is
    /// linear in the plane's position, so only those can be the cheapest. Most bins of a small
    /// node are empty, so the occupied ones are found four at a time, as bits of a mask.
    template <int B, typename Visit>
    static void forEachOccupiedBoundary(const std::uint32_t* starts, const std::uint32_t* ends,
                                        Visit&& visit) {
        static_assert(B % 4 == 0);
        std::uint64_t carry = 0;  // the last bin of the previous 64 is occupied
        for (int first = 0; first < B; first += 64) {
            const int count = std::min(64, B - first);
            std::uint64_t occupied = 0;
            for (int j = 0; j < count; j += 4) {
                occupied |= std::uint64_t(simd::occupied4(starts + first + j, ends + first + j))
                            << j;
            }
            // Boundary k lies between bins k - 1 and k.
            std::uint64_t next = occupied | (occupied << 1) | carry;
            carry = occupied >> 63;
            if (first == 0) next &= ~std::uint64_t(1);                // boundary 0: the node's face
            if (count < 64) next &= (std::uint64_t(1) << count) - 1;  // boundary B: the other face
            for (; next != 0; next &= next - 1) visit(first + std::countr_zero(next));
        }
    }

    /// Area of `box` with its extent along `axis` replaced by `width`: the SAH's Area(L) and

    template <typename Share>
    static void forEachShare(std::uint32_t n, bool parallel, Share&& share) {
        if (parallel)
            tbb::parallel_for(std::size_t(0), shareCount(n), share);
        else
            for (std::size_t c = 0; c < shareCount(n); ++c) share(c);
    }

    /// The root's references counted into B bins, in shares, then buildNode.
    template <int B>
    void startBinned(const Ref* refs, std::uint32_t n, const Box& box, bool parallel) {
        std::vector<Bins<B>> part(shareCount(n));
        forEachShare(n, parallel, [&](std::size_t c) {
            const auto [begin, end] = shareRange(c, n);
            Binner<B> binner(box, part[c]);
            for (std::size_t p = begin; p < end; ++p) binner.add(refs[p]);
        });
        Bins<B> bins;
        for (const auto& b : part) bins.add(b);
        descend(refs, n, bins, box, 0, kNoId);
    }

    /// buildNode, in 16 bins (the 32 counted, in pairs) once the fast build's node is small.
    template <int B>
    void descend(const Ref* refs, std::uint32_t n, const Bins<B>& bins, const Box& box, int depth,
                 std::uint32_t parent) {
        if constexpr (B == kFastBins) {
            if (out_.opt.build == KdBuild::Fast && n <= kSmallNode) {
                Bins<kSmallBins> pairs;
                for (int axis = 0; axis < N; ++axis) {
                    for (int k = 0; k < kSmallBins; ++k) {
                        pairs.starts[axis][k] =
                            bins.starts[axis][2 * k] + bins.starts[axis][2 * k + 1];
                        pairs.ends[axis][k] = bins.ends[axis][2 * k] + bins.ends[axis][2 * k + 1];
                    }
                }
                pairs.minLo = bins.minLo;
                pairs.maxHi = bins.maxHi;
                return buildNode(refs, n, pairs, box, depth, parent);
            }
        }
        buildNode(refs, n, bins, box, depth, parent);
    }

    /// Big nodes: the SAH over B equal bins per axis (min-max binning: where each primitive
    /// starts and ends), O(n) a node, on the node's `n` references `refs`; `bins` were counted
    /// when the parent partitioned them. Below out_.opt.binAbove primitives, the exact sweep over
    /// sorted events takes over (buildSah). Candidates are the bin boundaries.
    template <int B>
    void buildNode(const Ref* refs, std::uint32_t n, const Bins<B>& bins, const Box& box, int depth,
                   std::uint32_t parent) {
        const bool fast = out_.opt.build == KdBuild::Fast;
        if (!fast && n <= static_cast<std::uint32_t>(out_.opt.binAbove)) {
            // The exact sweep wants exact bounds: each primitive clipped to the node again.
            std::vector<SplitEvent> events;
            events.reserve(std::size_t(2) * N * n);
            for (std::uint32_t k = 0; k < n; ++k)
                addEvents(refs[k].prim, out_.prims.clippedBounds(refs[k].prim, box), events);
            std::sort(events.begin(), events.end());
            return sweep_->build(std::move(events), n, box, depth, parent);
        }
        const std::uint32_t id = out_.openNode(box, depth, n, parent);
        const auto nodePrims = [&](std::vector<std::uint32_t>& out) {
            for (std::uint32_t k = 0; k < n; ++k) out.push_back(refs[k].prim);
        };
        if (out_.leafByCount(id, n, depth, nodePrims)) return;

        const double areaC = box.area();
        // The costs in locals: the candidate loop below reads them ~50 times a node.
        const double cTrav = out_.opt.cTrav, cIsect = out_.opt.cIsect;
        const double emptyBonus = out_.opt.emptyBonus;
        const double costAsLeaf = raystep::leafCost(cIsect, n);
        double bestCost = kInfinity, bestPos = 0.0;
        int bestAxis = -1;
        // Only the planes at the primitives' extent (emptySide) leave a side with none.
        enum class Empty { None, Left, Right } bestEmpty = Empty::None;
        const double twoOverAreaC = 2.0 / areaC;
        // A candidate plane with its cost: recorded, and kept if the cheapest so far.
        const auto offer = [&](int axis, double pos, std::uint32_t nl, std::uint32_t nr, double pl,
                               double pr, double cost) {
            if constexpr (Rec::kEnabled)
                out_.rec(
                    SplitCandidate{id, static_cast<std::uint8_t>(axis), nl, nr, pos, pl, pr, cost});
            if (cost < bestCost) {
                bestCost = cost;
                bestPos = pos;
                bestAxis = axis;
                bestEmpty = nl == 0 ? Empty::Left : nr == 0 ? Empty::Right : Empty::None;
            }
        };
        for (int axis = 0; axis < N; ++axis) {
            const double lo = box.lo[axis], hi = box.hi[axis];
            if (!(hi > lo && areaC > 0.0)) continue;
            // Not a structured binding: clang 14 cannot capture one in the lambdas below.
            const auto terms = out_.areaTerms(box, axis);
            const double a = terms.first, b = terms.second;
            const double binWidth = (hi - lo) / B;
            const std::uint32_t* st = bins.starts[axis].data();
            const std::uint32_t* en = bins.ends[axis].data();
            // The primitives' extent: empty space is cut off at its edge, as the exact sweep
            // does, never at a bin boundary (which would slice ever thinner slabs off a flat
            // primitive lying in the node's face, down to the depth limit).
            const double minLo = bins.minLo[axis], maxHi = bins.maxHi[axis];
            // P(L|C) and P(R|C) of the plane at pos, from the areas in closed form.
            const auto probabilities = [&](double pos) {
                return std::pair{((pos - lo) * a + b) * twoOverAreaC,
                                 ((hi - pos) * a + b) * twoOverAreaC};
            };
            std::uint32_t nl = 0, nr = n;
            forEachOccupiedBoundary<B>(st, en, [&](int k) {
                // The bins skipped since the last boundary were empty: only bin k - 1 counts.
                nl += st[k - 1];  // started in a bin below this boundary
                nr -= en[k - 1];  // ended in a bin below it
                const double pos = lo + binWidth * k;
                // Planes that leave primitives on both sides, strictly inside their extent
                // (the empty space beyond it is cut at its edge, below).
                if (nl == 0 || nr == 0 || !(pos > minLo && pos < maxHi)) return;
                // No side is empty, so no bonus: the split's cost as it is.
                const auto [pl, pr] = probabilities(pos);
                offer(axis, pos, nl, nr, pl, pr, splitCost(cTrav, cIsect, pl, pr, nl, nr));
            });
            // The empty space on either side, cut at the primitives' edge (with the bonus).
            const auto emptySide = [&](double pos, std::uint32_t nl, std::uint32_t nr) {
                const auto [pl, pr] = probabilities(pos);
                offer(axis, pos, nl, nr, pl, pr,
                      sahCost(cTrav, cIsect, emptyBonus, pl, pr, nl, nr));
            };
            const double minSlab = kMinEmptySlab * (hi - lo);
            if (minLo - lo >= minSlab && minLo < hi) emptySide(minLo, 0, n);
            if (hi - maxHi >= minSlab && maxHi > lo) emptySide(maxHi, n, 0);
        }
        if (bestAxis < 0) return out_.makeLeaf(id, LeafReason::NoSplit, depth, nodePrims);
        if (!(bestCost < costAsLeaf))
            return out_.makeLeaf(id, LeafReason::SahCheaper, depth, nodePrims);
        if (bestEmpty != Empty::None &&
            cutEmptySpace(refs, n, bins, box, depth, id, bestAxis, bestPos,
                          bestEmpty == Empty::Left, bestCost, costAsLeaf))
            return;

        // The partition counts each child's bins on the way, while the reference is at hand.
        // Not a structured binding: clang 14 cannot capture one in the lambdas below.
        const auto halves = box.splitAt(bestAxis, bestPos);
        const Box& boxL = halves.first;
        const Box& boxR = halves.second;
        // Which side of the plane a reference lies on: wholly below (or flat in the plane: left,
        // as the sweep), wholly above, or across it.
        enum : int { kLeft, kRight, kAcross };
        const int axis = bestAxis;  // copies the loops keep in registers
        const double pos = bestPos;
        const auto sideOf = [axis, pos](const Ref& r) {
            const double lo = r.lo(axis), hi = r.hi(axis);
            if (hi < pos || (hi == pos && lo < pos) || (lo == hi && lo == pos)) return kLeft;
            return lo >= pos ? kRight : kAcross;
        };
        // Partitions [begin, end) into outL and outR (room for one per reference on each side),
        // counting each child's bins on the way, while the reference is at hand (unless
        // `countBins` is false).
        const auto partitionRange = [&](auto countBins, const Ref* begin, const Ref* end, Ref* outL,
                                        Ref* outR, std::size_t& nlOut, std::size_t& nrOut,
                                        Bins<B>& binsL, Bins<B>& binsR) {
            Binner<B, fineBins(B)> inL(boxL, binsL), inR(boxR, binsR);
            std::size_t nl = 0, nr = 0;
            const auto put = [](const Ref& r, Ref* out, std::size_t& count, auto& binner) {
                out[count++] = r;
                if constexpr (decltype(countBins)::value) binner.add(r);
            };
            for (const Ref* r = begin; r != end; ++r) {
                const int side = sideOf(*r);
                if (side == kLeft) {
                    put(*r, outL, nl, inL);
                } else if (side == kRight) {
                    put(*r, outR, nr, inR);
                } else {
                    // Straddles: clipped to each side ("perfect splits"), dropped where it misses.
                    const auto [l, rr] = out_.clipToSides(r->prim, box, bestAxis, bestPos);
                    if (!l.empty()) put(Ref(r->prim, l), outL, nl, inL);
                    if (!rr.empty()) put(Ref(r->prim, rr), outR, nr, inR);
                }
            }
            nlOut = nl;
            nrOut = nr;
        };
        // Children at the depth limit will be leaves, which need no bins (a twentieth of the
        // node visits on a big mesh, whose leaves mostly end there).
        const auto partition = [&](auto&&... args) {
            if (depth + 1 >= out_.maxDepth)
                partitionRange(std::false_type{}, args...);
            else
                partitionRange(std::true_type{}, args...);
        };
        // The children's references go on top of this thread's stack.
        RefStack& stack = *stack_;
        const StackFrame frame(stack);
        Ref* left = nullptr;
        Ref* right = nullptr;
        std::size_t nl = 0, nr = 0;
        Bins<B> binsL, binsR;
        if (fast && !Rec::kEnabled && n > kParallelNodeAbove) {
            // A big node (the top few levels, before the subtrees keep every core busy): the
            // cores count each share's references on each side, then partition the shares
            // straight into place, their bins added up after.
            const std::size_t chunks = shareCount(n);
            const auto share = [&](std::size_t c) {
                const auto [begin, end] = shareRange(c, n);
                return std::pair{refs + begin, refs + end};
            };
            // Where each share's references go. A straddling one is clipped here too, to count
            // only the sides it reaches: few straddle at these levels (under 1%), and a gap left
            // by one that misses a side would have moved every share after it.
            std::vector<std::size_t> atL(chunks + 1), atR(chunks + 1);
            tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
                std::size_t l = 0, r = 0;
                for (auto [p, end] = share(c); p != end; ++p) {
                    const int side = sideOf(*p);
                    if (side == kAcross) {
                        const auto [partOnL, partOnR] =
                            out_.clipToSides(p->prim, box, bestAxis, bestPos);
                        l += !partOnL.empty();
                        r += !partOnR.empty();
                    } else {
                        l += side == kLeft;
                        r += side == kRight;
                    }
                }
                atL[c + 1] = l;
                atR[c + 1] = r;
            });
            for (std::size_t c = 0; c < chunks; ++c) {
                atL[c + 1] += atL[c];
                atR[c + 1] += atR[c];
            }
            left = stack.push(atL[chunks] + atR[chunks]);
            right = left + atL[chunks];
            std::vector<std::size_t> partL(chunks), partR(chunks);
            std::vector<Bins<B>> partBinsL(chunks), partBinsR(chunks);
            tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
                const auto [begin, end] = share(c);
                partition(begin, end, left + atL[c], right + atR[c], partL[c], partR[c],
                          partBinsL[c], partBinsR[c]);
            });
            nl = atL[chunks];
            nr = atR[chunks];
            for (std::size_t c = 0; c < chunks; ++c) {
                assert(partL[c] == atL[c + 1] - atL[c] && partR[c] == atR[c + 1] - atR[c]);
                binsL.add(partBinsL[c]);
                binsR.add(partBinsR[c]);
            }
        } else {
            // Each reference gives at most one on each side: room for n on each.
            left = stack.push(2 * std::size_t(n));
            right = left + n;
            partition(refs, refs + n, left, right, nl, nr, binsL, binsR);
        }
        out_.makeInterior(id, bestAxis, bestPos, bestCost, costAsLeaf);
        const double fl = double(nl) / double(nl + nr);
        const auto nL = static_cast<std::uint32_t>(nl), nR = static_cast<std::uint32_t>(nr);
        constexpr std::size_t kParallelAbove = 4096;
        if (fast && !Rec::kEnabled && nr > kParallelAbove) {
            // The right subtree on another core, into a piece of its own, attached after. Its
            // references stay where they are until this frame returns.
            auto piece = std::make_unique<KdPiece>();
            TreeStats subStats;
            tbb::task_group group;
            group.run([&] {
                KdNodeWriter<Prims, Rec> subOut(out_, *piece, subStats);
                SahBinned sub(*this, subOut);
                sub.descend(right, nR, binsR, boxR, depth + 1, id);
            });
            try {
                out_.progress().child(fl, [&] { descend(left, nL, binsL, boxL, depth + 1, id); });
            } catch (...) {
                group.wait();  // the task uses this frame's locals
                throw;
            }
            group.wait();
            out_.attach(id, std::move(piece), subStats);
            out_.progress().child(1 - fl, [&] { out_.progress().leafDone(); });
            return;
        }
        out_.children(
            id, fl, [&] { descend(left, nL, binsL, boxL, depth + 1, id); },
            [&] { descend(right, nR, binsR, boxR, depth + 1, id); });
    }

    /// A plane at the primitives' extent (bins.minLo on `axis` if `emptyLeft`, else bins.maxHi)
    /// keeps every reference on one side, unclipped: that child reads them where they are, and its
    /// bins on the other axes are the parent's (the same references over the same extent), so only
    /// `axis` is counted again. Half the fast build's node visits are such cuts on a triangle mesh.
    /// Returns false, having done nothing, if a flat reference lies in a plane at minLo: the
    /// partition sends it left, so the left side is not empty.
    template <int B>
    bool cutEmptySpace(const Ref* refs, std::uint32_t n, const Bins<B>& bins, const Box& box,
                       int depth, std::uint32_t id, int axis, double pos, bool emptyLeft,
                       double cost, double leafCost) {
        assert(pos == double(emptyLeft ? bins.minLo[axis] : bins.maxHi[axis]));
        // Not a structured binding: clang 14 cannot capture one in the lambdas below.
        const auto halves = box.splitAt(axis, pos);
        const Box& boxL = halves.first;
        const Box& boxR = halves.second;
        const Box& kept = emptyLeft ? boxR : boxL;
        // The cut axis in the kept box's bins, as Binner<B, fineBins(B)> counts them.
        constexpr int kFine = fineBins(B);
        const double width = kept.hi[axis] - kept.lo[axis];
        const simd::Float4 lo = simd::splat(static_cast<float>(kept.lo[axis]));
        const simd::Float4 scale =
            simd::splat(width > 0.0 ? static_cast<float>(kFine / width) : 0.0f);
        Bins<B> keptBins = bins;
        const bool countBins =
            depth + 1 < out_.maxDepth;  // else the child is a leaf: no bins needed
        auto& starts = keptBins.starts[axis];
        auto& ends = keptBins.ends[axis];
        starts.fill(0);
        ends.fill(0);
        // With the left side empty every reference starts at or above the plane, so one ending
        // in it lies flat in it (counted without a branch: there is rarely one).
        const auto plane = static_cast<float>(pos);
        std::uint32_t flat = 0;
        if (countBins) {
            for (std::uint32_t k = 0; k < n; ++k) {
                const float rlo = refs[k].lo(axis), rhi = refs[k].hi(axis);
                flat += rhi == plane;
                const simd::Int4 bin =
                    Binner<B, kFine>::binsOf(simd::set(rlo, rhi, 0, 0), lo, scale);
                ++starts[simd::lane<0>(bin)];
                ++ends[simd::lane<1>(bin)];
            }
        } else if (emptyLeft) {
            for (std::uint32_t k = 0; k < n; ++k) flat += refs[k].hi(axis) == plane;
        }
        if (emptyLeft && flat > 0) return false;
#ifndef NDEBUG
        if (countBins) {
            Bins<B> check;
            {
                Binner<B, kFine> binner(kept, check);
                for (std::uint32_t k = 0; k < n; ++k) binner.add(refs[k]);
            }
            assert(check.starts == keptBins.starts && check.ends == keptBins.ends);
        }
#endif
        out_.makeInterior(id, axis, pos, cost, leafCost);
        const Bins<B> none;
        // The side cut off is an empty leaf; the other keeps every reference.
        if (emptyLeft)
            out_.children(
                id, 0.0, [&] { descend(refs, 0, none, boxL, depth + 1, id); },
                [&] { descend(refs, n, keptBins, boxR, depth + 1, id); });
        else
            out_.children(
                id, 1.0, [&] { descend(refs, n, keptBins, boxL, depth + 1, id); },
                [&] { descend(refs, 0, none, boxR, depth + 1, id); });
        return true;
    }

    KdNodeWriter<Prims, Rec>& out_;
    std::optional<SahSweep<Prims, Rec>> sweep_;  // --bin-above's small nodes
    // The references: a stack per thread, shared by the whole build.
    std::shared_ptr<Stacks> stacks_ = std::make_shared<Stacks>();
    // This builder's thread's stack, looked up once: a builder runs on the thread that made it
    // (a subtree's builder is made inside its task).
    RefStack* stack_ = &stacks_->local();
};

}  // namespace

template <typename Prims, typename Rec>
BoxN<Prims::N> buildSahBinned(KdNodeWriter<Prims, Rec>& out) {
    return SahBinned<Prims, Rec>(out).buildRoot();
}

template BoxN<3> buildSahBinned(KdNodeWriter<ScenePrims, NullRecorder>&);
template BoxN<3> buildSahBinned(KdNodeWriter<ScenePrims, EventLog>&);
template BoxN<2> buildSahBinned(KdNodeWriter<Scene2DPrims, NullRecorder>&);
template BoxN<2> buildSahBinned(KdNodeWriter<Scene2DPrims, EventLog>&);
template BoxN<3> buildSahBinned(KdNodeWriter<FloatScenePrims, NullRecorder>&);
template BoxN<3> buildSahBinned(KdNodeWriter<FloatScenePrims, EventLog>&);

}  // namespace raystep::kdbuild
