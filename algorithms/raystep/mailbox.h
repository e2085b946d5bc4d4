#pragma once
// Mailboxing (lecture: "mailboxing"): a primitive listed in several cells or leaves is tested
// once per ray. Each primitive's box holds the id of the last ray that tested it.
#include <cstdint>
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

}  // namespace raystep
