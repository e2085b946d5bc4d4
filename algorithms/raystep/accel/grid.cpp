#include "raystep/accel/grid.h"
#include "raystep/accel/query_impl.h"

#include "raystep/accel/mailbox.h"
#include "raystep/base/timer.h"
#include "raystep/scene/scene2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raystep {

namespace {
template <int N>
std::size_t totalCells(const IVecN<N>& res) {
    std::size_t cells = 1;
    for (int i = 0; i < N; ++i) cells *= static_cast<std::size_t>(res[i]);
    return cells;
}

/// Cleary & Wyvill's cells per axis, d_i (cells / V)^(1/N), written d_i / g * cells^(1/N) with g
/// the geometric mean of the d_i: scale-free, so no overflow or underflow whatever the scene's
/// size. Each axis is clamped to [1, kMaxCellsPerAxis] as a double, then rounded.
template <int N>
IVecN<N> clearyWyvill(const VecN<N, double>& d, double cells) {
    double meanLog = 0.0;
    for (int i = 0; i < N; ++i) meanLog += std::log(d[i]);
    meanLog /= N;
    const double perAxis = N == 2 ? std::sqrt(cells) : std::cbrt(cells);
    IVecN<N> res;
    for (int i = 0; i < N; ++i) {
        double r = std::exp(std::log(d[i]) - meanLog) * perAxis;
        if (!(r >= 1.0)) r = 1.0;
        r = std::min(r, double(GridOptions::kMaxCellsPerAxis));
        res[i] = static_cast<int>(std::lround(r));
    }
    return res;
}

/// The largest total in [1, maxCells] whose resolution passes `fits` (bisected on the total, in
/// a bracket that does not depend on lambda); 1 if none does.
template <typename Rule, typename Fits>
double largestFitting(std::size_t maxCells, Rule&& rule, Fits&& fits) {
    double lo = 1.0, hi = double(maxCells);
    if (fits(rule(hi))) return hi;
    for (int i = 0; i < 60 && hi - lo > 0.5; ++i) {
        const double mid = std::sqrt(lo * hi);
        (fits(rule(mid)) ? lo : hi) = mid;
    }
    return lo;
}
}  // namespace

template <typename Prims>
UniformGridT<Prims>::UniformGridT(Prims prims, const GridOptions& options)
    : prims_(std::move(prims)), mailbox_(options.mailbox) {
    ScopedTimer timer(buildMs_);
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
    extent = std::min(std::max(extent, far * 1e-12), std::numeric_limits<double>::max());
    if (extent == 0.0) extent = 1.0;  // everything at the origin
    for (int i = 0; i < N; ++i)
        if (!(b.hi[i] - b.lo[i] > 1e-6 * extent)) {
            b.lo[i] -= 0.5e-6 * extent;
            b.hi[i] += 0.5e-6 * extent;
        }
    spec_.lo = b.lo;
    spec_.hi = b.hi;
    // Cells of the box a primitive's bounds overlap, widened by a billionth of a cell so a
    // primitive on a boundary is listed on both sides whatever the rounding. Clamped as doubles
    // first: a cell index past int's range (or NaN) would be undefined behaviour as an int.
    const auto cellOf = [&](int i, double x, double widen) {
        const double f = std::floor((x - spec_.lo[i]) / spec_.cellSize(i) + widen);
        if (!(f > 0.0)) return 0;
        return f < spec_.res[i] - 1 ? static_cast<int>(f) : spec_.res[i] - 1;
    };
    const auto cellRange = [&](std::uint32_t p, IVecN<N>& lo, IVecN<N>& hi) {
        const BoxN<N> pb = prims_.bounds(p);
        for (int i = 0; i < N; ++i) {
            lo[i] = cellOf(i, pb.lo[i], -1e-9);
            hi[i] = cellOf(i, pb.hi[i], 1e-9);
        }
    };
    // The references a grid of resolution `res` would hold, counted without building it.
    const std::size_t maxCells = std::max<std::size_t>(options.maxCells, 1);
    const std::size_t maxReferences = std::max<std::size_t>(options.maxReferences, n);
    const auto fitsReferences = [&](const IVecN<N>& res) {
        spec_.res = res;
        std::size_t total = 0;
        IVecN<N> lo, hi;
        for (std::uint32_t p = 0; p < n && total <= maxReferences; ++p) {
            cellRange(p, lo, hi);
            std::size_t cells = 1;
            for (int i = 0; i < N; ++i) cells *= static_cast<std::size_t>(hi[i] - lo[i] + 1);
            total += cells;
        }
        return total <= maxReferences;
    };
    const auto fitsCells = [&](const IVecN<N>& res) { return totalCells<N>(res) <= maxCells; };
    IVecN<N> res;
    if (options.res) {
        for (int i = 0; i < N; ++i)
            res[i] = std::clamp((*options.res)[i], 1, GridOptions::kMaxCellsPerAxis);
        // Past the caps the asked resolution shrinks in proportion on every axis.
        const IVecN<N> asked = res;
        for (double shrink = 0.5; !(fitsCells(res) && fitsReferences(res)) && res != IVecN<N>(1);
             shrink *= 0.5)
            for (int i = 0; i < N; ++i) res[i] = std::max(1, static_cast<int>(asked[i] * shrink));
    } else {
        // Cleary & Wyvill: lambda N cells in all, so lambda is cells per primitive. The total is
        // clamped to [1, kMaxCells] before any conversion (NaN: one cell), so nothing wraps and
        // the cells never decrease as lambda grows.
        const VecN<N, double> d = 0.5 * b.hi - 0.5 * b.lo;  // half: never overflows
        const auto rule = [&](double cells) { return clearyWyvill<N>(d, cells); };
        double target = options.lambda * std::max(n, 1u);
        if (!(target >= 1.0)) target = 1.0;
        target = std::min(target, double(maxCells));
        // The largest total whose rounded resolution fits the cap depends on the scene's
        // proportions only: every lambda beyond it gets that same resolution.
        target = std::min(target, largestFitting(maxCells, rule, fitsCells));
        // Primitives overlapping very many cells each: coarser, within the memory budget.
        if (!fitsReferences(rule(target)))
            target = std::min(target, largestFitting(maxCells, rule, fitsReferences));
        res = rule(target);
    }
    spec_.res = res;

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
    cellStart_.assign(totalCells<N>(spec_.res) + 1, 0);
    IVecN<N> lo, hi;
    // Counting is half the work, filling the other half: every 2% of the primitives in each pass
    // is 1% of the build.
    const std::uint32_t every = std::max<std::uint32_t>(1, n / 50);
    const auto report = [&](double fraction, std::uint32_t p) {
        if (options.progress && (p + 1) % every == 0 && !options.progress(fraction))
            throw BuildCancelled();
    };
    for (std::uint32_t p = 0; p < n; ++p) {
        cellRange(p, lo, hi);
        forCells(lo, hi, [&](std::size_t c) { ++cellStart_[c + 1]; });
        report(0.5 * (p + 1) / n, p);
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    cellPrims_.resize(cellStart_.back());
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::uint32_t p = 0; p < n; ++p) {
        cellRange(p, lo, hi);
        forCells(lo, hi, [&](std::size_t c) { cellPrims_[fill[c]++] = p; });
        report(0.5 + 0.5 * (p + 1) / n, p);
    }
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
    if (dda.problem()) {
        // A ray the walk refuses (a NaN or infinite coordinate): test everything, as brute force
        // does, rather than report a miss the kernels never saw.
        for (std::uint32_t p = 0; p < prims_.count(); ++p)
            if (visitPrimitive<AnyHit>(prims_, p, ray, hit, closest, nullptr, counters, rec, rayId))
                return hit;
        return closest;
    }
    if constexpr (Rec::kEnabled) {
        if (dda.valid()) {
            DdaSetup e{rayId, {0, 0, 0}, N, {0.0, 0.0, 0.0}, dda.tEnter(), dda.tGridExit()};
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
        if (closest && closest->t < dda.tCellExit()) break;
    }
    return closest;
}

template class UniformGridT<ScenePrims>;
template class UniformGridT<Scene2DPrims>;
template class Queries<UniformGridT<ScenePrims>, ScenePrims>;
template class Queries<UniformGridT<Scene2DPrims>, Scene2DPrims>;

}  // namespace raystep
