#pragma once
// The uniform grid of the lecture: primitives listed in every cell their bounds overlap, and the
// ray walked cell by cell with the DDA, testing only what the cells it crosses hold. One template
// for the 3D scene and the lecture's 2D pictures.
#include "raystep/accel/dda.h"
#include "raystep/accel/query.h"
#include "raystep/base/progress.h"
#include "raystep/scene/prims.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace raystep {

/// The grid's resolution: the Cleary-Wyvill rule, cells per axis d_i cbrt(lambda N / V) (in 2D
/// d_i sqrt(lambda N / A)), that is lambda N cells for N primitives: lambda is cells per primitive
/// (the lecture's 3 to 5 means a few cells for each primitive, not a few primitives a cell). The
/// cells never decrease as lambda grows; memory is capped: at most kMaxCellsPerAxis on an axis,
/// kMaxCells in all and kMaxReferences primitive listings (or N, if more). A rule's resolution
/// past a cap is the largest that fits; an explicit `res` past one shrinks in proportion.
struct GridOptions {
    double lambda = 4.0;                    // Cleary-Wyvill density: lambda cells per primitive
    std::optional<std::array<int, 3>> res;  // explicit cells per axis instead of the rule
    bool mailbox = true;                    // test each primitive once per ray (mailboxing)
    static constexpr int kMaxCellsPerAxis = 512;
    static constexpr std::size_t kMaxCells = std::size_t(1) << 24;       // 64 MiB of cell starts
    static constexpr std::size_t kMaxReferences = std::size_t(1) << 27;  // 512 MiB of listings
    std::size_t maxCells = kMaxCells;  // the caps in force (tests lower them)
    std::size_t maxReferences = kMaxReferences;
    ProgressFn progress;  // build progress (share of the primitives listed); may cancel
};

template <typename Prims>
class UniformGridT : public Queries<UniformGridT<Prims>, Prims> {
  public:
    static constexpr int N = Prims::N;
    using RayT = typename Prims::RayT;
    using HitT = typename Prims::HitT;

    UniformGridT(Prims prims, const GridOptions& options);

    const Prims& primitives() const { return prims_; }
    const KernelOptions& kernels() const { return prims_.kernels(); }
    const GridSpec<N, double>& spec() const { return spec_; }
    std::size_t cellCount() const { return cellStart_.size() - 1; }
    std::size_t references() const { return cellPrims_.size(); }
    std::size_t emptyCells() const;
    double buildMs() const { return buildMs_; }
    /// The primitives listed in a cell.
    std::span<const std::uint32_t> cell(const IVecN<N>& c) const;

  private:
    friend class Queries<UniformGridT, Prims>;
    template <bool AnyHit, typename Rec>
    std::optional<HitT> query(RayT ray, TraversalCounters& counters, Rec& rec,
                              std::uint32_t rayId) const {
        return walk<AnyHit>(ray, counters, rec, rayId);
    }
    template <bool AnyHit, typename Rec>
    std::optional<HitT> walk(RayT ray, TraversalCounters& counters, Rec& rec,
                             std::uint32_t rayId) const;
    std::size_t index(const IVecN<N>& c) const;

    Prims prims_;
    bool mailbox_;
    GridSpec<N, double> spec_;
    std::vector<std::uint32_t> cellStart_;  // cell c holds cellPrims_[cellStart_[c] .. [c+1])
    std::vector<std::uint32_t> cellPrims_;
    double buildMs_ = 0.0;
};

using UniformGrid = UniformGridT<ScenePrims>;

// Instantiated beside the traversal (grid.cpp).
extern template class Queries<UniformGridT<ScenePrims>, ScenePrims>;
extern template class Queries<UniformGridT<Scene2DPrims>, Scene2DPrims>;

}  // namespace raystep
