#pragma once
// Brute force, the slides' RaySceneIntersection: test every primitive, keep the closest. The
// baseline every acceleration structure is measured against (and must agree with).
#include "raystep/accel/mailbox.h"
#include "raystep/accel/query_impl.h"
#include "raystep/base/ray.h"
#include "raystep/scene/prims.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <cstdint>
#include <optional>
#include <utility>

namespace raystep {

/// No structure at all: every query tests every primitive of `Prims`, in order.
template <typename Prims>
class BruteForceT : public Queries<BruteForceT<Prims>, Prims> {
  public:
    using RayT = typename Prims::RayT;
    using HitT = typename Prims::HitT;
    explicit BruteForceT(Prims prims) : prims_(std::move(prims)) {}
    const Prims& primitives() const { return prims_; }
    const KernelOptions& kernels() const { return prims_.kernels(); }

  private:
    friend class Queries<BruteForceT, Prims>;
    template <bool AnyHit, typename Rec>
    std::optional<HitT> query(RayT ray, TraversalCounters& counters, Rec& rec,
                              std::uint32_t rayId) const {
        return raySceneIntersection<AnyHit>(ray, counters, rec, rayId);
    }
    /// The slides' loop: for each primitive, intersect; keep the nearest (AnyHit: the first).
    template <bool AnyHit, typename Rec>
    std::optional<HitT> raySceneIntersection(RayT ray, TraversalCounters& counters, Rec& rec,
                                             std::uint32_t rayId) const {
        std::optional<HitT> closest;
        HitT hit;
        // intersect shortens ray.tMax, so later primitives must be closer to win.
        for (std::uint32_t p = 0; p < prims_.count(); ++p)
            if (visitPrimitive<AnyHit>(prims_, p, ray, hit, closest, nullptr, counters, rec, rayId))
                return hit;
        return closest;
    }

    Prims prims_;
};
using BruteForce = BruteForceT<ScenePrims>;
using BruteForce2D = BruteForceT<Scene2DPrims>;

}  // namespace raystep
