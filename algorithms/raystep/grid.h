#pragma once
// The uniform grid of the lecture: primitives listed in every cell their bounds overlap, and the
// ray walked cell by cell with the 3D-DDA, testing only what the cells it crosses hold.
#include "raystep/accel_types.h"
#include "raystep/dda.h"
#include "raystep/scene.h"

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace raystep {

struct GridOptions {
    double lambda = 4.0;                    // Cleary-Wyvill density: about lambda primitives a cell
    std::optional<std::array<int, 3>> res;  // explicit cells per axis instead of the rule
    bool mailbox = true;                    // test each primitive once per ray (mailboxing)
    static constexpr int kMaxCellsPerAxis = 512;
};

class UniformGrid {
  public:
    UniformGrid(const Scene& scene, KernelOptions kernels, const GridOptions& options);

    std::optional<Hit> intersect(Ray ray, TraversalCounters& counters) const;
    bool occluded(Ray ray, TraversalCounters& counters) const;
    const KernelOptions& kernels() const { return kernels_; }

    const GridSpec<3, double>& spec() const { return spec_; }
    std::size_t cellCount() const { return cellStart_.size() - 1; }
    std::size_t references() const { return cellPrims_.size(); }
    std::size_t emptyCells() const;
    /// The primitives listed in cell (x, y, z).
    std::span<const std::uint32_t> cell(int x, int y, int z) const;

  private:
    template <bool AnyHit>
    std::optional<Hit> walk(Ray ray, TraversalCounters& counters) const;

    const Scene* scene_;
    KernelOptions kernels_;
    bool mailbox_;
    GridSpec<3, double> spec_;
    std::vector<std::uint32_t>
        cellStart_;  // cell c holds cellPrims_[cellStart_[c] .. cellStart_[c+1])
    std::vector<std::uint32_t> cellPrims_;
};

}  // namespace raystep
