#include "raystep/accel/kdtree.h"

#include "raystep/scene/fast_prims.h"
#include "raystep/accel/mailbox.h"
#include "raystep/base/names.h"
#include "raystep/base/round_outward.h"
#include "raystep/scene/scene2d.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_group.h>

#include <immintrin.h>  // SSE2, which every x86-64 has: the binning (Binner)

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <bit>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>

namespace raystep {

namespace {
constexpr NameTable<SplitMethod, 3> kSplitNames{{{SplitMethod::Midpoint, "midpoint"},
                                                 {SplitMethod::Median, "median"},
                                                 {SplitMethod::Sah, "sah"}}};
constexpr NameTable<KdBuild, 2> kBuildNames{{{KdBuild::Exact, "exact"}, {KdBuild::Fast, "fast"}}};

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

enum class Side : std::uint8_t { Both, Left, Right };

constexpr double kEps = std::numeric_limits<double>::epsilon();
// An empty side thinner than this share of the node's width is not cut off. Clipping a straddling
// triangle rounds its bounds (and clipTriangleBounds widens the node by a millionth for that
// reason), so such a slab is rounding, not space; with the empty bonus it would still halve the
// node's cost, and the sweep would spend a level of the depth limit on it at nearly every node.
constexpr double kMinEmptySlab = 1e-6;
constexpr int kMaxDepthCap = 60;  // the traversal stack holds one entry per level

/// A subtree built on another thread, in arrays of its own. It is attached where its parent's
/// right child goes and copied into the tree once, when the whole tree is built: splicing it
/// into its parent's arrays at every level of nested tasks copied each node several times.
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

std::optional<SplitMethod> parseSplitMethod(std::string_view s) {
    return valueNamed(kSplitNames, s);
}
std::string_view name(SplitMethod m) {
    return nameOf(kSplitNames, m);
}
std::optional<KdBuild> parseKdBuild(std::string_view s) {
    return valueNamed(kBuildNames, s);
}
std::string_view name(KdBuild b) {
    return nameOf(kBuildNames, b);
}

/// The build: state shared by the recursion.
template <typename Prims, typename Rec>
class KdBuilder {
  public:
    static constexpr int N = Prims::N;
    using Box = BoxN<N>;

    KdBuilder(const Prims& prims, const KdTreeOptions& opt, int maxDepth, Rec& rec, KdPiece& piece,
              TreeStats& stats)
        : prims_(prims),
          opt_(opt),
          maxDepth_(maxDepth),
          rec_(rec),
          nodes_(piece.nodes),
          ids_(piece.ids),
          attached_(piece.attached),
          stats_(stats),
          progress_(opt.progress) {}

    /// A builder for one subtree on another thread: its own piece and stats (attached to the
    /// parent's afterwards), the parent's primitive bounds, no progress reports.
    KdBuilder(const KdBuilder& parent, KdPiece& piece, TreeStats& stats)
        : prims_(parent.prims_),
          opt_(parent.opt_),
          maxDepth_(parent.maxDepth_),
          rec_(parent.rec_),
          nodes_(piece.nodes),
          ids_(piece.ids),
          attached_(piece.attached),
          stats_(stats),
          primBounds_(parent.primBounds_),
          progress_(noProgress_),
          stacks_(parent.stacks_),
          stack_(&stacks_->local()) {}
    KdBuilder(const KdBuilder&) = delete;
    KdBuilder& operator=(const KdBuilder&) = delete;

    /// Builds the tree; returns the root's box, the primitives' bounds (found on the way).
    Box run() {
        const std::uint32_t n = prims_.count();
        if (opt_.split == SplitMethod::Sah &&
            (opt_.build == KdBuild::Fast || opt_.exactBelow > 0)) {
            return runBinned();
        }
        ownBounds_.resize(n);
        Box box;
        for (std::uint32_t p = 0; p < n; ++p) {
            ownBounds_[p] = prims_.bounds(p);
            box.extend(ownBounds_[p]);
        }
        box = rootBox(box, n);
        primBounds_ = &ownBounds_;
        if (opt_.split == SplitMethod::Sah) {
            side_.assign(n, Side::Both);
            std::vector<SplitEvent> events;
            events.reserve(std::size_t(2) * N * n);
            for (std::uint32_t p = 0; p < n; ++p)
                addEvents(p, ownBounds_[p].clippedTo(box), events);
            std::sort(events.begin(), events.end());
            buildSah(std::move(events), n, box, 0, kNoId);
        } else {
            std::vector<std::uint32_t> all(n);
            for (std::uint32_t p = 0; p < n; ++p) all[p] = p;
            buildSimple(std::move(all), box, 0, kNoId);
        }
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
            roundOutward<N>(bounds, edge.data());
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
                lo_[v] = _mm_loadu_ps(&lo[4 * v]);
                scale_[v] = _mm_loadu_ps(&scale[4 * v]);
                min_[v] = _mm_set1_ps(std::numeric_limits<float>::infinity());
                max_[v] = _mm_set1_ps(-std::numeric_limits<float>::infinity());
            }
        }
        Binner(const Binner&) = delete;
        Binner& operator=(const Binner&) = delete;
        ~Binner() {
            std::array<float, 8> mn, mx;
            for (int v = 0; v < kLoads; ++v) {
                _mm_storeu_ps(&mn[4 * v], min_[v]);
                _mm_storeu_ps(&mx[4 * v], max_[v]);
            }
            for (int axis = 0; axis < N; ++axis) {
                bins_.minLo[axis] = std::min(bins_.minLo[axis], mn[laneOf(axis)]);
                bins_.maxHi[axis] = std::max(bins_.maxHi[axis], mx[laneOf(N + axis)]);
            }
        }
        /// The bins of four edges, lane by lane: edge e of an axis starting at lo, with
        /// Fine / width bins per unit (scale), falls in bin (e - lo) * scale, clamped.
        static __m128i binsOf(__m128 e, __m128 lo, __m128 scale) {
            const __m128 zero = _mm_setzero_ps(), top = _mm_set1_ps(Fine - 0.5f);
            constexpr int kMerge = std::countr_zero(unsigned(Fine / B));
            const __m128 x = _mm_mul_ps(_mm_sub_ps(e, lo), scale);
            return _mm_srli_epi32(_mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(x, zero), top)), kMerge);
        }
        void add(const Ref& r) {
            alignas(16) std::array<std::int32_t, 8> bin;
            for (int v = 0; v < kLoads; ++v) {
                const __m128 e = _mm_loadu_ps(&r.edge[kLoadAt[v]]);
                _mm_store_si128(reinterpret_cast<__m128i*>(&bin[4 * v]),
                                binsOf(e, lo_[v], scale_[v]));
                min_[v] = _mm_min_ps(min_[v], e);
                max_[v] = _mm_max_ps(max_[v], e);
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
        __m128 lo_[kLoads], scale_[kLoads], min_[kLoads], max_[kLoads];
    };
    // Bins per axis: the fast build's 32, and 16 (the 32 in pairs) in its nodes of at most
    // kSmallNode references, where the bins' fixed cost dominates (measured: 11% fewer
    // instructions, SAH cost +1%); the exact build's binned top levels (--bin-above) 256.
    static constexpr int kFastBins = 32;
    static constexpr int kSmallBins = kFastBins / 2;
    static constexpr std::uint32_t kSmallNode = 64;
    static constexpr int kExactBins = 256;
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
        const auto load = [](const std::uint32_t* p) {
            return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
        };
        std::uint64_t carry = 0;  // the last bin of the previous 64 is occupied
        for (int first = 0; first < B; first += 64) {
            const int count = std::min(64, B - first);
            std::uint64_t occupied = 0;
            for (int j = 0; j < count; j += 4) {
                const __m128i any = _mm_or_si128(load(starts + first + j), load(ends + first + j));
                const int empty =
                    _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(any, _mm_setzero_si128())));
                occupied |= std::uint64_t(~empty & 0xF) << j;
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
    /// Area(R) in closed form, without building the child boxes.
    static double areaWithWidth(const Box& box, int axis, double width) {
        const auto [a, b] = areaTerms(box, axis);
        return 2.0 * (width * a + b);
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

    /// The root's box: the primitives' bounds `all`, or a point for none.
    static Box rootBox(const Box& all, std::uint32_t n) {
        return n > 0 ? all : Box{VecN<N, double>(0.0), VecN<N, double>(0.0)};
    }
    /// Runs share(c) for each share of n (on all cores if `parallel`).
    template <typename Share>
    static void forEachShare(std::uint32_t n, bool parallel, Share&& share) {
        if (parallel)
            tbb::parallel_for(std::size_t(0), shareCount(n), share);
        else
            for (std::size_t c = 0; c < shareCount(n); ++c) share(c);
    }

    /// The binned build from the root, on this thread's stack; returns the root's box. The
    /// references and the root's box come from one pass over the primitives (a second, for the
    /// box alone, read a million triangles' 80 MB again).
    Box runBinned() {
        const std::uint32_t n = prims_.count();
        side_.assign(n, Side::Both);
        const StackFrame frame(*stack_);
        Ref* refs = stack_->push(n);
        const bool fast = opt_.build == KdBuild::Fast;
        const bool parallel = fast && !Rec::kEnabled;
        std::vector<Box> part(shareCount(n));
        forEachShare(n, parallel, [&](std::size_t c) {
            const auto [begin, end] = shareRange(c, n);
            for (auto p = static_cast<std::uint32_t>(begin); p < end; ++p) {
                const Box b = prims_.bounds(p);
                refs[p] = Ref(p, b);
                part[c].extend(b);
            }
        });
        Box all;
        for (const Box& b : part) all.extend(b);
        const Box box = rootBox(all, n);
        if (fast)
            startBinned<kFastBins>(refs, n, box, parallel);
        else
            startBinned<kExactBins>(refs, n, box, parallel);
        return box;
    }
    /// The root's references counted into B bins, in shares, then buildBinned.
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

    /// buildBinned, in 16 bins (the 32 counted, in pairs) once the fast build's node is small.
    template <int B>
    void descend(const Ref* refs, std::uint32_t n, const Bins<B>& bins, const Box& box, int depth,
                 std::uint32_t parent) {
        if constexpr (B == kFastBins) {
            if (opt_.build == KdBuild::Fast && n <= kSmallNode) {
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
                return buildBinned(refs, n, pairs, box, depth, parent);
            }
        }
        buildBinned(refs, n, bins, box, depth, parent);
    }

    /// Big nodes: the SAH over B equal bins per axis (min-max binning: where each primitive
    /// starts and ends), O(n) a node, on the node's `n` references `refs`; `bins` were counted
    /// when the parent partitioned them. Below opt_.exactBelow primitives, the exact sweep over
    /// sorted events takes over (buildSah). Candidates are the bin boundaries.
    template <int B>
    void buildBinned(const Ref* refs, std::uint32_t n, const Bins<B>& bins, const Box& box,
                     int depth, std::uint32_t parent) {
        const bool fast = opt_.build == KdBuild::Fast;
        if (!fast && n <= static_cast<std::uint32_t>(opt_.exactBelow)) {
            // The exact sweep wants exact bounds: each primitive clipped to the node again.
            std::vector<SplitEvent> events;
            events.reserve(std::size_t(2) * N * n);
            for (std::uint32_t k = 0; k < n; ++k)
                addEvents(refs[k].prim, prims_.clippedBounds(refs[k].prim, box), events);
            std::sort(events.begin(), events.end());
            return buildSah(std::move(events), n, box, depth, parent);
        }
        const std::uint32_t id = openNode(box, depth, n, parent);
        const auto nodePrims = [&](std::vector<std::uint32_t>& out) {
            for (std::uint32_t k = 0; k < n; ++k) out.push_back(refs[k].prim);
        };
        if (leafByCount(id, n, depth, nodePrims)) return;

        const double areaC = box.area();
        const double leafCost = opt_.cIsect * n;
        double bestCost = kInfinity, bestPos = 0.0;
        int bestAxis = -1;
        // Only the planes at the primitives' extent (emptySide) leave a side with none.
        enum class Empty { None, Left, Right } bestEmpty = Empty::None;
        const double twoOverAreaC = 2.0 / areaC;
        // A candidate plane with its cost: recorded, and kept if the cheapest so far.
        const auto offer = [&](int axis, double pos, std::uint32_t nl, std::uint32_t nr, double pl,
                               double pr, double cost) {
            if constexpr (Rec::kEnabled)
                rec_(
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
            const auto terms = areaTerms(box, axis);
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
                // sahCost inline (no side is empty, so no bonus): this runs ~50 times a node.
                const auto [pl, pr] = probabilities(pos);
                offer(axis, pos, nl, nr, pl, pr, opt_.cTrav + opt_.cIsect * (pl * nl + pr * nr));
            });
            // The empty space on either side, cut at the primitives' edge (with the bonus).
            const auto emptySide = [&](double pos, std::uint32_t nl, std::uint32_t nr) {
                const auto [pl, pr] = probabilities(pos);
                offer(axis, pos, nl, nr, pl, pr,
                      sahCost(opt_.cTrav, opt_.cIsect, opt_.emptyBonus, pl, pr, nl, nr));
            };
            const double minSlab = kMinEmptySlab * (hi - lo);
            if (minLo - lo >= minSlab && minLo < hi) emptySide(minLo, 0, n);
            if (hi - maxHi >= minSlab && maxHi > lo) emptySide(maxHi, n, 0);
        }
        if (bestAxis < 0) return makeLeaf(id, LeafReason::NoSplit, depth, nodePrims);
        if (!(bestCost < leafCost)) return makeLeaf(id, LeafReason::SahCheaper, depth, nodePrims);
        if (bestEmpty != Empty::None &&
            cutEmptySpace(refs, n, bins, box, depth, id, bestAxis, bestPos,
                          bestEmpty == Empty::Left, bestCost, leafCost))
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
                    const auto [l, rr] = clipToSides(r->prim, box, bestAxis, bestPos);
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
            if (depth + 1 >= maxDepth_)
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
                            clipToSides(p->prim, box, bestAxis, bestPos);
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
        split(id, bestAxis, bestPos, bestCost, leafCost);
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
                KdBuilder sub(*this, *piece, subStats);
                sub.descend(right, nR, binsR, boxR, depth + 1, id);
            });
            try {
                progress_.child(fl, [&] { descend(left, nL, binsL, boxL, depth + 1, id); });
            } catch (...) {
                group.wait();  // the task uses this frame's locals
                throw;
            }
            group.wait();
            attach(id, std::move(piece), subStats);
            progress_.child(1 - fl, [&] { progress_.leafDone(); });
            return;
        }
        children(
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
        const __m128 lo = _mm_set1_ps(static_cast<float>(kept.lo[axis]));
        const __m128 scale = _mm_set1_ps(width > 0.0 ? static_cast<float>(kFine / width) : 0.0f);
        Bins<B> keptBins = bins;
        const bool countBins = depth + 1 < maxDepth_;  // else the child is a leaf: no bins needed
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
                const __m128i bin =
                    Binner<B, kFine>::binsOf(_mm_setr_ps(rlo, rhi, 0, 0), lo, scale);
                ++starts[_mm_cvtsi128_si32(bin)];
                ++ends[_mm_cvtsi128_si32(_mm_srli_si128(bin, 4))];
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
        split(id, axis, pos, cost, leafCost);
        const Bins<B> none;
        // The side cut off is an empty leaf; the other keeps every reference.
        if (emptyLeft)
            children(
                id, 0.0, [&] { descend(refs, 0, none, boxL, depth + 1, id); },
                [&] { descend(refs, n, keptBins, boxR, depth + 1, id); });
        else
            children(
                id, 1.0, [&] { descend(refs, n, keptBins, boxL, depth + 1, id); },
                [&] { descend(refs, 0, none, boxR, depth + 1, id); });
        return true;
    }

    /// A subtree built apart becomes node `parent`'s right child, where the next node would go
    /// (place() copies it there once the tree is done).
    void attach(std::uint32_t parent, std::unique_ptr<KdPiece> piece, const TreeStats& subStats) {
        attached_.push_back({parent, static_cast<std::uint32_t>(nodes_.size()),
                             static_cast<std::uint32_t>(ids_.size()), std::move(piece)});
        stats_.leaves += subStats.leaves;
        stats_.emptyLeaves += subStats.emptyLeaves;
        stats_.maxDepth = std::max(stats_.maxDepth, subStats.maxDepth);
        for (std::size_t r = 0; r < stats_.leafReasons.size(); ++r)
            stats_.leafReasons[r] += subStats.leafReasons[r];
    }

    static void addEvents(std::uint32_t p, const Box& b, std::vector<SplitEvent>& out) {
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

    std::uint32_t openNode(const Box& box, int depth, std::uint32_t count, std::uint32_t parent) {
        const auto id = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        stats_.maxDepth = std::max<std::uint32_t>(stats_.maxDepth, depth);
        if constexpr (Rec::kEnabled) {
            rec_.node(id, box.lo3(), box.hi3());
            rec_(BuildNode{id, parent, static_cast<std::uint32_t>(depth), count});
        }
        return id;
    }

    /// Makes node `id` a leaf of the primitives `append(ids_)` appends to the tree's ids: written
    /// in place, not gathered into a vector first (a malloc per leaf, 2% of the fast build).
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
            rec_(LeafMade{id, reason, node.count, static_cast<std::uint32_t>(depth),
                          opt_.cIsect * node.count});
        progress_.leafDone();
    }
    /// Appends all of `prims` (a leaf's primitives held in a vector).
    static auto allOf(const std::vector<std::uint32_t>& prims) {
        return [&prims](std::vector<std::uint32_t>& out) {
            out.insert(out.end(), prims.begin(), prims.end());
        };
    }

    /// Checks shared by every strategy; true if the node must be a leaf (and makes it of the
    /// primitives `append` appends).
    template <typename Append>
    bool leafByCount(std::uint32_t id, std::uint32_t n, int depth, Append&& append) {
        if (n <= static_cast<std::uint32_t>(opt_.leafSize)) {
            makeLeaf(id, LeafReason::FewPrimitives, depth, append);
            return true;
        }
        if (depth >= maxDepth_) {
            makeLeaf(id, LeafReason::MaxDepth, depth, append);
            return true;
        }
        return false;
    }

    /// A straddling primitive's bounds on each side of the plane: one clip of it to the node
    /// where the primitive set offers that (triangles), else one clip per side.
    std::pair<Box, Box> clipToSides(std::uint32_t p, const Box& box, int axis, double pos) const {
        if constexpr (requires { prims_.splitBounds(p, box, axis, pos); }) {
            return prims_.splitBounds(p, box, axis, pos);
        } else {
            const auto [l, r] = box.splitAt(axis, pos);
            return {prims_.clippedBounds(p, l), prims_.clippedBounds(p, r)};
        }
    }

    /// Wald & Havran: one sweep over the sorted events of each axis evaluates every candidate
    /// plane; the chosen plane splits the event lists in order, so no sort happens below the root
    /// except for the few primitives that straddle the plane.
    void buildSah(std::vector<SplitEvent> events, std::uint32_t n, const Box& box, int depth,
                  std::uint32_t parent) {
        const std::uint32_t id = openNode(box, depth, n, parent);
        const auto nodePrims = [&](std::vector<std::uint32_t>& out) {
            for (const SplitEvent& e : events)
                if (e.axis == 0 && e.type != EventType::End) out.push_back(e.prim);
        };
        if (leafByCount(id, n, depth, nodePrims)) return;

        const double areaC = box.area();
        const double leafCost = opt_.cIsect * n;
        double bestCost = kInfinity, bestPos = 0.0;
        int bestAxis = -1;
        bool bestPlanarLeft = true;
        std::size_t i = 0;
        for (int axis = 0; axis < N; ++axis) {
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
                    const double pl = areaWithWidth(box, axis, p - box.lo[axis]) / areaC;
                    const double pr = areaWithWidth(box, axis, box.hi[axis] - p) / areaC;
                    // Primitives lying in the plane go to whichever side is cheaper.
                    const double costL =
                        sahCost(opt_.cTrav, opt_.cIsect, opt_.emptyBonus, pl, pr, nl + planars, nr);
                    const double costR =
                        sahCost(opt_.cTrav, opt_.cIsect, opt_.emptyBonus, pl, pr, nl, nr + planars);
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
                        rec_(SplitCandidate{id, static_cast<std::uint8_t>(axis), nlChosen, nrChosen,
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
        if (bestAxis < 0) return makeLeaf(id, LeafReason::NoSplit, depth, nodePrims);
        if (!(bestCost < leafCost)) return makeLeaf(id, LeafReason::SahCheaper, depth, nodePrims);

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
                    // A straddling primitive, clipped to each side, gives new events there
                    // ("perfect splits"); a side its bounding box overlaps but the primitive
                    // itself misses does not get it at all.
                    const auto [l, r] = clipToSides(e.prim, box, bestAxis, bestPos);
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

        split(id, bestAxis, bestPos, bestCost, leafCost);
        const double fl = double(nl) / double(nl + nr);
        children(
            id, fl, [&] { buildSah(std::move(mergedL), nl, boxL, depth + 1, id); },
            [&] { buildSah(std::move(mergedR), nr, boxR, depth + 1, id); });
    }

    /// Builds node `id`'s children in the tree's order, left next to it, then the right, whose
    /// index the node records; `fl` is the left's share of the progress.
    template <typename Left, typename Right>
    void children(std::uint32_t id, double fl, Left&& left, Right&& right) {
        progress_.child(fl, left);
        nodes_[id].index = static_cast<std::uint32_t>(nodes_.size());
        progress_.child(1 - fl, right);
    }

    void split(std::uint32_t id, int axis, double pos, double cost, double leafCost) {
        nodes_[id].axis = static_cast<std::uint8_t>(axis);
        nodes_[id].split = pos;
        if constexpr (Rec::kEnabled)
            rec_(SplitChosen{id, static_cast<std::uint8_t>(axis), pos, cost, leafCost});
    }

    /// Midpoint and median: one plane on the node's longest axis, the middle of the node or the
    /// median of the primitives' centres.
    void buildSimple(std::vector<std::uint32_t> prims, const Box& box, int depth,
                     std::uint32_t parent) {
        const auto n = static_cast<std::uint32_t>(prims.size());
        const std::uint32_t id = openNode(box, depth, n, parent);
        if (leafByCount(id, n, depth, allOf(prims))) return;

        const int axis = box.longestAxis();
        double pos;
        if (opt_.split == SplitMethod::Midpoint) {
            pos = box.centroid()[axis];
        } else {
            std::vector<double> centres(n);
            for (std::uint32_t k = 0; k < n; ++k)
                centres[k] = prims_.clippedBounds(prims[k], box).centroid()[axis];
            std::nth_element(centres.begin(), centres.begin() + n / 2, centres.end());
            pos = centres[n / 2];
        }
        if (!(pos > box.lo[axis] && pos < box.hi[axis]))
            return makeLeaf(id, LeafReason::NoSplit, depth, allOf(prims));

        // Each primitive goes to every side its clipped part reaches (one flat in the plane, both).
        // Not a structured binding: clang 14 cannot capture one in the lambdas below.
        const auto halves = box.splitAt(axis, pos);
        const Box& boxL = halves.first;
        const Box& boxR = halves.second;
        std::vector<std::uint32_t> left, right;
        for (std::uint32_t p : prims) {
            const Box& b = (*primBounds_)[p];
            if (b.hi[axis] < pos) {
                left.push_back(p);  // wholly on one side: no clipping needed
            } else if (b.lo[axis] > pos) {
                right.push_back(p);
            } else {
                const auto [l, r] = clipToSides(p, box, axis, pos);
                if (!l.empty()) left.push_back(p);
                if (!r.empty()) right.push_back(p);
            }
        }
        const auto nl = static_cast<std::uint32_t>(left.size());
        const auto nr = static_cast<std::uint32_t>(right.size());
        const double areaC = box.area();
        const double pl = areaC > 0 ? boxL.area() / areaC : 0.5;
        const double pr = areaC > 0 ? boxR.area() / areaC : 0.5;
        const double cost = sahCost(opt_.cTrav, opt_.cIsect, opt_.emptyBonus, pl, pr, nl, nr);
        if constexpr (Rec::kEnabled)
            rec_(SplitCandidate{id, static_cast<std::uint8_t>(axis), nl, nr, pos, pl, pr, cost});
        if (nl == n && nr == n) return makeLeaf(id, LeafReason::NoProgress, depth, allOf(prims));
        prims = {};
        split(id, axis, pos, cost, opt_.cIsect * n);
        const double fl = double(nl) / double(nl + nr);
        children(
            id, fl, [&] { buildSimple(std::move(left), boxL, depth + 1, id); },
            [&] { buildSimple(std::move(right), boxR, depth + 1, id); });
    }

    const Prims& prims_;
    const KdTreeOptions& opt_;
    int maxDepth_;
    Rec& rec_;
    std::vector<KdNode>& nodes_;
    std::vector<std::uint32_t>& ids_;
    std::vector<KdAttached>& attached_;
    TreeStats& stats_;
    std::vector<Box> ownBounds_;
    const std::vector<Box>* primBounds_ = nullptr;
    std::vector<Side> side_;
    ProgressFn noProgress_;
    BuildProgress progress_;
    // The binned build's references: a stack per thread, shared by the whole build.
    std::shared_ptr<Stacks> stacks_ = std::make_shared<Stacks>();
    // This builder's thread's stack, looked up once: a builder runs on the thread that made it
    // (a subtree's builder is made inside its task).
    RefStack* stack_ = &stacks_->local();
};

/// The tree's SAH cost, node by node from the root box (no empty bonus: the expected cost). The
/// top `parallelLevels` levels evaluate their two subtrees on two cores (a million-triangle tree
/// took 20 ms on one).
template <int N>
double treeSahCost(const std::vector<KdNode>& nodes, std::uint32_t id, const BoxN<N>& box,
                   const KdTreeOptions& opt, int parallelLevels = 0) {
    const KdNode& node = nodes[id];
    if (node.leaf()) return opt.cIsect * node.count;
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
    const double area = box.area();
    return opt.cTrav + (l.area() / area) * costL + (r.area() / area) * costR;
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
    const auto start = std::chrono::steady_clock::now();
    const std::uint32_t n = prims_.count();
    if (options_.leafSize <= 0) options_.leafSize = options_.split == SplitMethod::Sah ? 1 : 4;
    maxDepth_ = options_.maxDepth > 0
                    ? options_.maxDepth
                    : static_cast<int>(std::lround(8 + 1.3 * std::log2(std::max(n, 1u))));
    maxDepth_ = std::min(maxDepth_, kMaxDepthCap);
    KdPiece root;
    KdBuilder<Prims, Rec> builder(prims_, options_, maxDepth_, rec, root, stats_);
    bounds_ = builder.run();
    if (root.attached.empty()) {
        nodes_ = std::move(root.nodes);
        primIds_ = std::move(root.ids);
    } else {
        sizeUp(root);
        resizeOnHugePages(nodes_, root.totalNodes);
        resizeOnHugePages(primIds_, root.totalIds);
        place(root, nodes_.data(), primIds_.data(), 0, 0);
    }
    stats_.nodes = static_cast<std::uint32_t>(nodes_.size());
    stats_.references = primIds_.size();
    stats_.sahCost =
        bounds_.area() > 0 ? treeSahCost(nodes_, 0, bounds_, options_, 6) : options_.cIsect * n;
    stats_.buildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    options_.progress = nullptr;  // it may refer to the caller's locals: only the build used it
}

template <typename Prims>
template <bool AnyHit, typename Rec>
auto KdTree<Prims>::traverse(RayT ray, TraversalCounters& counters, Rec& rec,
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
    Todo todo[kMaxDepthCap + 1];
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

template <typename Prims>
auto KdTree<Prims>::intersect(RayT ray, TraversalCounters& counters) const -> std::optional<HitT> {
    NullRecorder rec;
    return traverse<false>(ray, counters, rec, kNoId);
}
template <typename Prims>
bool KdTree<Prims>::occluded(RayT ray, TraversalCounters& counters) const {
    NullRecorder rec;
    return traverse<true>(ray, counters, rec, kNoId).has_value();
}
template <typename Prims>
auto KdTree<Prims>::intersect(RayT ray, TraversalCounters& counters, EventLog& log,
                              std::uint32_t rayId) const -> std::optional<HitT> {
    return traverse<false>(ray, counters, log, rayId);
}
template <typename Prims>
bool KdTree<Prims>::occluded(RayT ray, TraversalCounters& counters, EventLog& log,
                             std::uint32_t rayId) const {
    return traverse<true>(ray, counters, log, rayId).has_value();
}

template class KdTree<ScenePrims>;
template class KdTree<Scene2DPrims>;
template class KdTree<FloatScenePrims>;

}  // namespace raystep
