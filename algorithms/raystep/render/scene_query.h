#pragma once
// What the tracer finds hits with: a teaching structure, which can record every step of a ray,
// or the fast path (fast/wide_bvh.h), which records nothing and makes whole images quickly.
#include "raystep/accel/accel.h"
#include "raystep/fast/wide_bvh.h"

#include <optional>
#include <stdexcept>

namespace raystep {

class SceneQuery {
  public:
    // Implicit: a structure is what most callers render with.
    SceneQuery(const Accelerator& accel) : accel_(&accel) {}  // NOLINT(google-explicit-constructor)
    SceneQuery(const WideBvh& fast) : fast_(&fast) {}         // NOLINT(google-explicit-constructor)

    std::optional<Hit> intersect(const Ray& ray, TraversalCounters& counters) const {
        return fast_ ? fast_->intersect(ray, counters) : raystep::intersect(*accel_, ray, counters);
    }
    bool occluded(const Ray& ray, TraversalCounters& counters) const {
        return fast_ ? fast_->occluded(ray, counters) : raystep::occluded(*accel_, ray, counters);
    }
    /// The kernels hits are computed with (secondary rays clear their rounding).
    const KernelOptions& kernels() const { return fast_ ? fast_->kernels() : kernelsOf(*accel_); }
    /// The teaching structure, which records; the fast path has none to offer.
    const Accelerator& recording() const {
        if (!accel_)
            throw std::logic_error("the fast path records nothing: trace with a structure");
        return *accel_;
    }
    bool fast() const { return fast_ != nullptr; }

  private:
    const Accelerator* accel_ = nullptr;
    const WideBvh* fast_ = nullptr;
};

}  // namespace raystep
