#pragma once
// The queries every acceleration structure answers, and what one query cost.
#include "raystep/trace/events.h"

#include <cstdint>
#include <optional>

namespace raystep {

/// What one query cost: counted in locals by the caller and summed per pixel.
struct TraversalCounters {
    std::uint64_t primitiveTests = 0;
    std::uint64_t nodeVisits = 0;    // grid cells walked, tree nodes entered
    std::uint64_t mailboxSkips = 0;  // primitives not tested again thanks to the mailbox
    TraversalCounters& operator+=(const TraversalCounters& o) {
        primitiveTests += o.primitiveTests;
        nodeVisits += o.nodeVisits;
        mailboxSkips += o.mailboxSkips;
        return *this;
    }
};

/// The four queries of every structure (the nearest hit or any hit, recorded or not), written once
/// over the structure's one traversal, which it names as the slides do (raySceneIntersection, the
/// grid's walk, TestTree) and offers to this class as `query<AnyHit>(ray, counters, rec, rayId)`.
/// A structure derives from Queries<itself, Prims> and instantiates it beside its traversal
/// (query_impl.h), so the traversal's code stays in the structure's own .cpp.
template <typename Structure, typename Prims>
class Queries {
  public:
    using RayT = typename Prims::RayT;
    using HitT = typename Prims::HitT;

    /// Nearest hit in (ray.tMin, ray.tMax).
    std::optional<HitT> intersect(RayT ray, TraversalCounters& counters) const;
    /// Any hit in (ray.tMin, ray.tMax): shadow rays stop at the first one.
    bool occluded(RayT ray, TraversalCounters& counters) const;
    /// The same queries, recording every step of ray `rayId` into `log`.
    std::optional<HitT> intersect(RayT ray, TraversalCounters& counters, EventLog& log,
                                  std::uint32_t rayId) const;
    bool occluded(RayT ray, TraversalCounters& counters, EventLog& log, std::uint32_t rayId) const;

  private:
    const Structure& self() const { return static_cast<const Structure&>(*this); }
};

}  // namespace raystep
