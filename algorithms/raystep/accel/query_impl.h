#pragma once
// The four queries' bodies (query.h): included by a structure's .cpp, which instantiates them
// beside its traversal.
#include "raystep/accel/query.h"

namespace raystep {

template <typename Structure, typename Prims>
auto Queries<Structure, Prims>::intersect(RayT ray, TraversalCounters& counters) const
    -> std::optional<HitT> {
    NullRecorder rec;
    return self().template query<false>(ray, counters, rec, kNoId);
}
template <typename Structure, typename Prims>
bool Queries<Structure, Prims>::occluded(RayT ray, TraversalCounters& counters) const {
    NullRecorder rec;
    return self().template query<true>(ray, counters, rec, kNoId).has_value();
}
template <typename Structure, typename Prims>
auto Queries<Structure, Prims>::intersect(RayT ray, TraversalCounters& counters, EventLog& log,
                                          std::uint32_t rayId) const -> std::optional<HitT> {
    return self().template query<false>(ray, counters, log, rayId);
}
template <typename Structure, typename Prims>
bool Queries<Structure, Prims>::occluded(RayT ray, TraversalCounters& counters, EventLog& log,
                                         std::uint32_t rayId) const {
    return self().template query<true>(ray, counters, log, rayId).has_value();
}

}  // namespace raystep
