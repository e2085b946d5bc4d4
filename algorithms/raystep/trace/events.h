#pragma once
// The event model: every algorithm is a template over a recorder. NullRecorder records nothing and
// its hooks sit behind `if constexpr`, so the uninstrumented code is the plain code. EventLog keeps
// small plain-data events (a std::variant, no strings, no heap per event) up to a cap, plus two
// side tables that would not fit in an event: the rays (origin, direction) and the tree nodes
// (bounds). docs/trace-format.md describes the file these are saved to.
#include "raystep/base/ray.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace raystep {

constexpr std::uint32_t kNoId = 0xffffffffu;

/// A ray starts: its geometry is rays[ray] of the log.
struct RayBegin {
    std::uint32_t ray;
    std::uint32_t parent;  // kNoId for a primary ray
    RayKind kind;
    std::uint8_t depth;
};
/// The DDA is set up: step and tDelta per axis, and the part of the ray inside the grid.
struct DdaSetup {
    std::uint32_t ray;
    std::array<std::int8_t, 3> step;
    std::uint8_t dims;
    std::array<double, 3> tDelta;
    // Where the ray enters and leaves the grid (not a cell's exit: Dda::tCellExit).
    double tEnter, tGridExit;
};
/// The DDA is in a new cell: the first cell (axes = the grid face it came in through, 0 from
/// inside) or a step (axes = the axis taken; several on an exact tie). tMax after the step.
struct DdaCell {
    std::uint32_t ray;
    std::uint8_t axes;
    std::array<std::int32_t, 3> cell;
    std::array<double, 3> tMax;
};
/// A primitive already tested by this ray (in an earlier cell or leaf) is not tested again.
struct MailboxSkip {
    std::uint32_t ray;
    std::uint32_t prim;
};
struct PrimitiveTest {
    std::uint32_t ray;
    std::uint32_t prim;
    bool hit;
    double t;  // the hit's t, or infinity
};
/// A tree node the ray visits, over [tNear, tFar] of the ray.
struct NodeEnter {
    std::uint32_t ray;
    std::uint32_t node;
    double tNear, tFar;
};
/// A node the ray does not visit: its interval starts beyond the closest hit, or the ray misses it.
struct NodeSkip {
    std::uint32_t ray;
    std::uint32_t node;
    double tNear, tFar;
};
/// Build: a node is opened with its primitives (bounds in nodes[node] of the log), and what
/// making it a leaf would cost with the build's C_isect: the chart's leaf line from the first step.
struct BuildNode {
    std::uint32_t node;
    std::uint32_t parent;
    std::uint32_t depth;
    std::uint32_t prims;
    double cIsect;    // the build's cost of one ray-primitive test
    double leafCost;  // C_isect N (NaN: a trace that did not record it, nor its node's outcome)
};
/// Build: one candidate split plane and its cost,
/// sahCost = C_trav + C_isect (pL nL + pR nR) (times 1 - emptyBonus when a side is empty).
struct SplitCandidate {
    std::uint32_t node;
    std::uint8_t axis;
    std::uint32_t nl, nr;
    double position;
    double pl, pr;  // Area(L)/Area(C), Area(R)/Area(C)
    double sahCost;
};
/// Build: the plane chosen for a node (its children are the next BuildNode events naming it as
/// parent: the left subtree first).
struct SplitChosen {
    std::uint32_t node;
    std::uint8_t axis;
    double position;
    double sahCost;
    double leafCost;  // C_isect N: what not splitting would cost
};
enum class LeafReason : std::uint8_t {
    FewPrimitives,  // at most the leaf size
    MaxDepth,       // the depth limit
    SahCheaper,     // no split costs less than the leaf
    NoSplit,        // no plane inside the node separates anything (flat node, all centroids equal)
    NoProgress,     // midpoint / median: every primitive would go to both sides
};
struct LeafMade {
    std::uint32_t node;
    LeafReason reason;
    std::uint32_t prims;
    std::uint32_t depth;
    double leafCost;
};
struct RayHit {
    std::uint32_t ray;
    std::uint32_t prim;
    double t, u, v;
};
struct RayMiss {
    std::uint32_t ray;
};
/// A shadow ray's any-hit query found something between the point and the light: primitive
/// `prim` at `t`, the first hit found (the query stops there), not necessarily the nearest.
struct RayBlocked {
    std::uint32_t ray;
    std::uint32_t prim;  // kNoId when the trace does not say (a hand-written one)
    double t;
};
enum class ShadingTermKind : std::uint8_t {
    Ambient,
    Diffuse,
    Specular,
    Reflected,
    Transmitted,
    DiffuseBounce
};
/// One term of the colour at a hit (already weighted: the terms of a ray sum to its colour).
struct ShadingTerm {
    std::uint32_t ray;
    ShadingTermKind term;
    std::uint32_t light;  // the light of a diffuse or specular term, kNoId otherwise
    std::array<double, 3> rgb;
};
/// The pixel's colour, and the image it is a pixel of (its frame: x < width, y < height).
struct PixelResult {
    std::uint32_t x, y;
    std::uint32_t width, height;  // 0 when a trace did not record it
    std::array<double, 3> rgb;
};

using Event = std::variant<RayBegin, DdaSetup, DdaCell, MailboxSkip, PrimitiveTest, NodeEnter,
                           NodeSkip, BuildNode, SplitCandidate, SplitChosen, LeafMade, RayHit,
                           RayMiss, ShadingTerm, PixelResult, RayBlocked>;
static_assert(sizeof(Event) <= 64, "an event must fit in 64 bytes");
static_assert(std::is_trivially_copyable_v<Event>);

/// Names used in the trace file, by variant index (a new event goes last: the others keep
/// their index).
constexpr std::array<std::string_view, std::variant_size_v<Event>> kEventNames = {
    "ray_begin", "dda_setup",    "dda_cell",        "mailbox_skip", "primitive_test", "node_enter",
    "node_skip", "build_node",   "split_candidate", "split_chosen", "leaf_made",      "ray_hit",
    "ray_miss",  "shading_term", "pixel_result",    "ray_blocked"};
constexpr std::array<std::string_view, 5> kLeafReasonNames = {
    "few_primitives", "max_depth", "sah_cheaper", "no_split", "no_progress"};
constexpr std::array<std::string_view, 6> kShadingTermNames = {
    "ambient", "diffuse", "specular", "reflected", "transmitted", "diffuse_bounce"};

/// Records nothing: every hook is behind `if constexpr (Rec::kEnabled)`.
struct NullRecorder {
    static constexpr bool kEnabled = false;
    template <typename E>
    void operator()(const E&) {}
    std::uint32_t beginRay(const Ray&, RayKind, int, std::uint32_t) { return kNoId; }
    void node(std::uint32_t, const std::array<double, 3>&, const std::array<double, 3>&) {}
};

/// Geometry of a recorded ray (rays[id] of the log).
struct RayRecord {
    Vec3 origin, dir;
    double tMin, tMax;
    RayKind kind;
    std::uint8_t depth;
    std::uint32_t parent;
};
/// Bounds of a recorded tree node (nodes[id] of the log; 2D uses the first two coordinates).
struct NodeRecord {
    std::array<double, 3> lo, hi;
};
/// The grid a bare DDA walk was recorded on (a lesson's replayed wrong walk): its box and cells
/// per axis, so that a reader can walk the same ray exactly. Not written to a trace file.
struct GridRecord {
    std::array<double, 3> lo, hi;
    std::array<int, 3> res;
};

/// Appends events until `cap`; past it, counts what it drops (truncated() says so).
class EventLog {
  public:
    static constexpr bool kEnabled = true;
    static constexpr std::size_t kDefaultCap = 4'000'000;  // about 224 MB of events

    explicit EventLog(std::size_t cap = kDefaultCap) : cap_(cap) {}

    template <typename E>
    void operator()(const E& e) {
        if (events_.size() < cap_)
            events_.emplace_back(e);
        else
            ++dropped_;
    }
    /// Records a new ray (RayBegin + its geometry) and returns its id.
    std::uint32_t beginRay(const Ray& r, RayKind kind, int depth, std::uint32_t parent) {
        const auto id = static_cast<std::uint32_t>(rays_.size());
        rays_.push_back(
            {r.origin, r.dir, r.tMin, r.tMax, kind, static_cast<std::uint8_t>(depth), parent});
        (*this)(RayBegin{id, parent, kind, static_cast<std::uint8_t>(depth)});
        return id;
    }
    /// Records the bounds of tree node `id` (nodes are numbered as the structure numbers them).
    void node(std::uint32_t id, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
        if (nodes_.size() <= id) nodes_.resize(id + 1);
        nodes_[id] = {lo, hi};
    }

    const std::vector<Event>& events() const { return events_; }
    const std::vector<RayRecord>& rays() const { return rays_; }
    const std::vector<NodeRecord>& nodes() const { return nodes_; }
    const std::optional<GridRecord>& grid() const { return grid_; }
    void setGrid(const GridRecord& g) { grid_ = g; }
    std::size_t cap() const { return cap_; }
    /// 2 for a log of a 2D scene, 3 for a 3D one: said once by whoever records, so a reader of
    /// an event (a 2D cell leaves its third coordinate at 0) need not guess.
    int dims() const { return dims_; }
    void setDims(int dims) { dims_ = dims; }
    std::size_t dropped() const { return dropped_; }
    bool truncated() const { return dropped_ > 0; }
    void clear() {
        events_.clear();
        rays_.clear();
        nodes_.clear();
        grid_.reset();
        dropped_ = 0;
    }
    // For the trace reader.
    void append(const Event& e) { events_.push_back(e); }
    void addRay(const RayRecord& r) { rays_.push_back(r); }
    void setDropped(std::size_t d) { dropped_ = d; }

  private:
    std::size_t cap_;
    std::vector<Event> events_;
    std::vector<RayRecord> rays_;
    std::vector<NodeRecord> nodes_;
    std::optional<GridRecord> grid_;
    std::size_t dropped_ = 0;
    int dims_ = 3;
};

/// What blocks shadow ray `ray`, from its events in [from, to): its last primitive test that
/// hit, where the any-hit query stopped. No such test (a log cut by the cap): prim kNoId.
inline RayBlocked blockedBy(const std::vector<Event>& events, std::uint32_t ray, std::size_t from,
                            std::size_t to) {
    for (std::size_t i = std::min(to, events.size()); i-- > from;) {
        if (const auto* t = std::get_if<PrimitiveTest>(&events[i]); t && t->ray == ray && t->hit)
            return {ray, t->prim, t->t};
        if (const auto* b = std::get_if<RayBegin>(&events[i]); b && b->ray == ray) break;
    }
    return {ray, kNoId, kInfinity};
}

/// What a cap message says: one line for the user.
inline std::string capMessage(const EventLog& log) {
    return "event cap of " + std::to_string(log.cap()) +
           " reached: " + std::to_string(log.dropped()) + " later events were not recorded";
}

}  // namespace raystep
