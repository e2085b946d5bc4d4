#pragma once
// Mailboxing (lecture: "mailboxing"): a primitive listed in several cells or leaves is tested
// once per ray. Each primitive's box holds the id of the last ray that tested it.
#include "raystep/accel/query.h"
#include "raystep/base/progress.h"
#include "raystep/scene/prims.h"
#include "raystep/trace/events.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace raystep {

/// One per thread: ray ids grow per thread, so no two queries of a thread share an id and
/// threads never share a mailbox (no atomics, no false sharing).
class Mailbox {
  public:
    /// Starts a new ray over `primitiveCount` primitives.
    void beginRay(std::uint32_t primitiveCount) {
        if (lastRay_.size() < primitiveCount) lastRay_.assign(primitiveCount, 0);
        ++rayId_;
    }
    /// True if this ray tested `prim` already; otherwise marks it tested.
    bool seen(std::uint32_t prim) {
        if (lastRay_[prim] == rayId_) return true;
        lastRay_[prim] = rayId_;
        return false;
    }
    static Mailbox& forThisThread() {
        thread_local Mailbox mailbox;
        return mailbox;
    }

  private:
    std::vector<std::uint64_t> lastRay_;
    std::uint64_t rayId_ = 0;
};

/// What every structure does with a primitive it meets: skip it if the mailbox says this ray
/// tested it already (mailbox may be null), else test it, count and record both. Returns true when
/// an any-hit query is answered (`hit` holds the hit); nearest-hit queries keep `closest` instead.
template <bool AnyHit, typename Prims, typename Rec>
bool visitPrimitive(const Prims& prims, std::uint32_t p, typename Prims::RayT& ray,
                    typename Prims::HitT& hit, std::optional<typename Prims::HitT>& closest,
                    Mailbox* mailbox, TraversalCounters& counters, Rec& rec, std::uint32_t rayId) {
    if (mailbox && mailbox->seen(p)) {
        ++counters.mailboxSkips;
        if constexpr (Rec::kEnabled) rec(MailboxSkip{rayId, p});
        return false;
    }
    ++counters.primitiveTests;
    const bool isHit =
        AnyHit ? prims.intersect(p, ray, hit) : testForNearest(prims, p, ray, hit, closest);
    if constexpr (Rec::kEnabled) rec(PrimitiveTest{rayId, p, isHit, isHit ? hit.t : kInfinity});
    if (!isHit) return false;
    if constexpr (AnyHit) return true;
    closest = hit;
    return false;
}

}  // namespace raystep
