#include "raystep/grid.h"

#include "raystep/mailbox.h"
#include "raystep/scene2d.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace raystep {

template <typename Prims>
UniformGridT<Prims>::UniformGridT(Prims prims, const GridOptions& options)
    : prims_(std::move(prims)), mailbox_(options.mailbox) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint32_t n = prims_.count();
    BoxN<N> b;
    for (std::uint32_t p = 0; p < n; ++p) b.extend(prims_.bounds(p));
    if (n == 0) b = BoxN<N>{VecN<N, double>(0.0), VecN<N, double>(1.0)};
    // A flat scene (one triangle, a floor) has no extent along some axis: give it a little,
    // relative to the scene's size, so cells have a size.
    double extent = 0.0, far = 0.0;
    for (int i = 0; i < N; ++i) {
        extent = std::max(extent, b.hi[i] - b.lo[i]);
        far = std::max({far, std::abs(b.lo[i]), std::abs(b.hi[i])});
    }
    extent = std::max(extent, far * 1e-12);
    if (extent == 0.0) extent = 1.0;  // everything at the origin
    for (int i = 0; i < N; ++i)
        if (!(b.hi[i] - b.lo[i] > 1e-6 * extent)) {
            b.lo[i] -= 0.5e-6 * extent;
            b.hi[i] += 0.5e-6 * extent;
        }
    spec_.lo = b.lo;
    spec_.hi = b.hi;
    const VecN<N, double> d = b.diagonal();
    if (options.res) {
        for (int i = 0; i < N; ++i)
            spec_.res[i] = std::clamp((*options.res)[i], 1, GridOptions::kMaxCellsPerAxis);
    } else {
        // Cleary & Wyvill: cells per axis = d_i * (lambda N / V)^(1/dim), about lambda
        // primitives a cell.
        double volume = 1.0;
        for (int i = 0; i < N; ++i) volume *= d[i];
        const double perUnit = std::pow(options.lambda * std::max(n, 1u) / volume, 1.0 / N);
        for (int i = 0; i < N; ++i)
            spec_.res[i] = std::clamp(static_cast<int>(std::lround(d[i] * perUnit)), 1,
                                      GridOptions::kMaxCellsPerAxis);
    }

    // Cells a primitive's bounds overlap, widened by a billionth of a cell so a primitive on a
    // boundary is listed on both sides whatever the rounding.
    const auto cellRange = [&](std::uint32_t p, IVecN<N>& lo, IVecN<N>& hi) {
        const BoxN<N> pb = prims_.bounds(p);
        for (int i = 0; i < N; ++i) {
            const double size = spec_.cellSize(i);
            lo[i] = std::clamp(static_cast<int>(std::floor((pb.lo[i] - spec_.lo[i]) / size - 1e-9)),
                               0, spec_.res[i] - 1);
            hi[i] = std::clamp(static_cast<int>(std::floor((pb.hi[i] - spec_.lo[i]) / size + 1e-9)),
                               0, spec_.res[i] - 1);
        }
    };
    // Every cell of the box [lo, hi] of cells, in any dimension (an odometer over the axes).
    const auto forCells = [&](const IVecN<N>& lo, const IVecN<N>& hi, auto&& f) {
        IVecN<N> c = lo;
        for (;;) {
            f(index(c));
            int i = 0;
            while (i < N && c[i] == hi[i]) c[i] = lo[i], ++i;
            if (i == N) return;
            ++c[i];
        }
    };
    // Two passes: count the references of each cell, then fill them (a flat array per cell).
    std::size_t cells = 1;
    for (int i = 0; i < N; ++i) cells *= static_cast<std::size_t>(spec_.res[i]);
    cellStart_.assign(cells + 1, 0);
    IVecN<N> lo, hi;
    for (std::uint32_t p = 0; p < n; ++p) {
        cellRange(p, lo, hi);
        forCells(lo, hi, [&](std::size_t c) { ++cellStart_[c + 1]; });
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    cellPrims_.resize(cellStart_.back());
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::uint32_t p = 0; p < n; ++p) {
        cellRange(p, lo, hi);
        forCells(lo, hi, [&](std::size_t c) { cellPrims_[fill[c]++] = p; });
    }
    buildMs_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

template <typename Prims>
std::size_t UniformGridT<Prims>::index(const IVecN<N>& c) const {
    std::size_t k = 0;
    for (int i = N - 1; i >= 0; --i) k = k * static_cast<std::size_t>(spec_.res[i]) + c[i];
    return k;
}

template <typename Prims>
std::size_t UniformGridT<Prims>::emptyCells() const {
    std::size_t empty = 0;
    for (std::size_t c = 0; c + 1 < cellStart_.size(); ++c)
        empty += cellStart_[c] == cellStart_[c + 1];
    return empty;
}

template <typename Prims>
std::span<const std::uint32_t> UniformGridT<Prims>::cell(const IVecN<N>& c) const {
    const std::size_t k = index(c);
    return {cellPrims_.data() + cellStart_[k], cellStart_[k + 1] - cellStart_[k]};
}

template <typename Prims>
template <bool AnyHit, typename Rec>
auto UniformGridT<Prims>::walk(RayT ray, TraversalCounters& counters, Rec& rec,
                               std::uint32_t rayId) const -> std::optional<HitT> {
    Mailbox& mailbox = Mailbox::forThisThread();
    if (mailbox_) mailbox.beginRay(prims_.count());
    std::optional<HitT> closest;
    HitT hit;
    Dda<N, double> dda(spec_, ray.origin, ray.dir, ray.tMin, ray.tMax);
    if constexpr (Rec::kEnabled) {
        if (dda.valid()) {
            DdaSetup e{rayId, {0, 0, 0}, N, {0.0, 0.0, 0.0}, dda.tEnter(), dda.tLeave()};
            for (int i = 0; i < N; ++i) {
                e.step[i] = static_cast<std::int8_t>(dda.step()[i]);
                e.tDelta[i] = dda.tDelta()[i];
            }
            rec(e);
        }
    }
    for (bool more = dda.valid(); more; more = dda.next()) {
        ++counters.nodeVisits;
        if constexpr (Rec::kEnabled) {
            DdaCell e{
                rayId, static_cast<std::uint8_t>(dda.axesTaken()), {0, 0, 0}, {0.0, 0.0, 0.0}};
            const auto tMax = dda.tMax();
            for (int i = 0; i < N; ++i) {
                e.cell[i] = dda.cell()[i];
                e.tMax[i] = tMax[i];
            }
            rec(e);
        }
        for (std::uint32_t p : cell(dda.cell()))
            if (visitPrimitive<AnyHit>(prims_, p, ray, hit, closest, mailbox_ ? &mailbox : nullptr,
                                       counters, rec, rayId))
                return hit;
        // A hit beyond this cell may be beaten by a primitive of a later cell: walk on until the
        // nearest hit lies before the cell's far side.
        if (closest && closest->t < dda.tExit()) break;
    }
    return closest;
}

template <typename Prims>
auto UniformGridT<Prims>::intersect(RayT ray, TraversalCounters& counters) const
    -> std::optional<HitT> {
    NullRecorder rec;
    return walk<false>(ray, counters, rec, kNoId);
}
template <typename Prims>
bool UniformGridT<Prims>::occluded(RayT ray, TraversalCounters& counters) const {
    NullRecorder rec;
    return walk<true>(ray, counters, rec, kNoId).has_value();
}
template <typename Prims>
auto UniformGridT<Prims>::intersect(RayT ray, TraversalCounters& counters, EventLog& log,
                                    std::uint32_t rayId) const -> std::optional<HitT> {
    return walk<false>(ray, counters, log, rayId);
}
template <typename Prims>
bool UniformGridT<Prims>::occluded(RayT ray, TraversalCounters& counters, EventLog& log,
                                   std::uint32_t rayId) const {
    return walk<true>(ray, counters, log, rayId).has_value();
}

template class UniformGridT<ScenePrims>;
template class UniformGridT<Scene2DPrims>;

}  // namespace raystep
