#include "raystep/grid.h"

#include <algorithm>
#include <cmath>

namespace raystep {

namespace {

/// Per-thread mailbox: the id of the last ray that tested each primitive. Ray ids grow per
/// thread, so no two queries of a thread share one and threads never share a mailbox.
struct Mailbox {
    std::vector<std::uint64_t> lastRay;
    std::uint64_t rayId = 0;
};
thread_local Mailbox tlsMailbox;

}  // namespace

UniformGrid::UniformGrid(const Scene& scene, KernelOptions kernels, const GridOptions& options)
    : scene_(&scene), kernels_(kernels), mailbox_(options.mailbox) {
    const std::uint32_t n = scene.primitiveCount();
    Bounds3 b = scene.bounds();
    // A flat scene (one triangle, a floor) has no extent along some axis: give it a little,
    // relative to the scene's size, so cells have a size.
    const double extent = std::max(maxComponent(b.diagonal()), maxAbsComponent(b.hi) * 1e-12);
    for (int i = 0; i < 3; ++i)
        if (!(b.hi[i] - b.lo[i] > 1e-6 * extent)) {
            b.lo[i] -= 0.5e-6 * extent;
            b.hi[i] += 0.5e-6 * extent;
        }
    spec_.lo = b.lo;
    spec_.hi = b.hi;
    const Vec3 d = b.diagonal();
    if (options.res) {
        for (int i = 0; i < 3; ++i)
            spec_.res[i] = std::clamp((*options.res)[i], 1, GridOptions::kMaxCellsPerAxis);
    } else {
        // Cleary & Wyvill: cells per axis = d_i * cbrt(lambda N / V), about lambda primitives a
        // cell.
        const double perUnit = std::cbrt(options.lambda * n / (d.x * d.y * d.z));
        for (int i = 0; i < 3; ++i)
            spec_.res[i] = std::clamp(static_cast<int>(std::lround(d[i] * perUnit)), 1,
                                      GridOptions::kMaxCellsPerAxis);
    }

    // Cells a primitive's bounds overlap, widened by a billionth of a cell so a primitive on a
    // boundary is listed on both sides whatever the rounding.
    const auto cellRange = [&](std::uint32_t p, std::array<int, 3>& lo, std::array<int, 3>& hi) {
        const Bounds3 pb = scene.primitiveBounds(p);
        for (int i = 0; i < 3; ++i) {
            const double size = spec_.cellSize(i);
            lo[i] = std::clamp(static_cast<int>(std::floor((pb.lo[i] - spec_.lo[i]) / size - 1e-9)),
                               0, spec_.res[i] - 1);
            hi[i] = std::clamp(static_cast<int>(std::floor((pb.hi[i] - spec_.lo[i]) / size + 1e-9)),
                               0, spec_.res[i] - 1);
        }
    };
    const auto index = [&](int x, int y, int z) {
        return (static_cast<std::size_t>(z) * spec_.res.y + y) * spec_.res.x + x;
    };
    // Two passes: count the references of each cell, then fill them (a flat array per cell).
    cellStart_.assign(static_cast<std::size_t>(spec_.res.x) * spec_.res.y * spec_.res.z + 1, 0);
    std::array<int, 3> lo{}, hi{};
    for (std::uint32_t p = 0; p < n; ++p) {
        cellRange(p, lo, hi);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) ++cellStart_[index(x, y, z) + 1];
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    cellPrims_.resize(cellStart_.back());
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::uint32_t p = 0; p < n; ++p) {
        cellRange(p, lo, hi);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) cellPrims_[fill[index(x, y, z)]++] = p;
    }
}

std::size_t UniformGrid::emptyCells() const {
    std::size_t empty = 0;
    for (std::size_t c = 0; c + 1 < cellStart_.size(); ++c)
        empty += cellStart_[c] == cellStart_[c + 1];
    return empty;
}

std::span<const std::uint32_t> UniformGrid::cell(int x, int y, int z) const {
    const std::size_t c = (static_cast<std::size_t>(z) * spec_.res.y + y) * spec_.res.x + x;
    return {cellPrims_.data() + cellStart_[c], cellStart_[c + 1] - cellStart_[c]};
}

template <bool AnyHit>
std::optional<Hit> UniformGrid::walk(Ray ray, TraversalCounters& counters) const {
    Mailbox& mb = tlsMailbox;
    if (mailbox_) {
        if (mb.lastRay.size() < scene_->primitiveCount())
            mb.lastRay.assign(scene_->primitiveCount(), 0);
        ++mb.rayId;
    }
    std::optional<Hit> closest;
    Hit hit;
    Dda<3, double> dda(spec_, ray.origin, ray.dir, ray.tMin, ray.tMax);
    for (bool more = dda.valid(); more; more = dda.next()) {
        ++counters.nodeVisits;
        for (std::uint32_t p : cell(dda.cell().x, dda.cell().y, dda.cell().z)) {
            if (mailbox_) {
                if (mb.lastRay[p] == mb.rayId) {
                    ++counters.mailboxSkips;
                    continue;
                }
                mb.lastRay[p] = mb.rayId;
            }
            ++counters.primitiveTests;
            if (scene_->intersectPrimitive(p, ray, hit, kernels_)) {
                if constexpr (AnyHit) return hit;
                closest = hit;
            }
        }
        // A hit beyond this cell may be beaten by a primitive of a later cell: walk on until the
        // nearest hit lies before the cell's far side.
        if (closest && closest->t < dda.tExit()) break;
    }
    return closest;
}

std::optional<Hit> UniformGrid::intersect(Ray ray, TraversalCounters& counters) const {
    return walk<false>(ray, counters);
}

bool UniformGrid::occluded(Ray ray, TraversalCounters& counters) const {
    return walk<true>(ray, counters).has_value();
}

}  // namespace raystep
