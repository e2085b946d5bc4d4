#pragma once
// The 3D-DDA of Amanatides & Woo (1987), in 2D and 3D from one template: walk a regular grid
// cell by cell along a ray, from one cell boundary to the next. The lecture's variables are the
// walk's state (X, Y, Z as `cell_`, then `step_`, `tDelta_`, `tMax_`); what differs from the
// slides is how the next axis is chosen. `tMaxX < tMaxY` is decided on crossing times computed
// afresh from the ray (not summed step after step, which drifts over hundreds of cells), with a
// floating-point filter and, when the filter cannot tell, exact rational arithmetic. An exact tie
// (the ray through a grid vertex or edge) steps every tied axis at once, so a cell the ray only
// touches is never visited. The cells are exact for every finite grid and ray, whatever their
// magnitude: crossing times that overflow to inf, are subnormal or round to 0 in double are
// bounded with an absolute term for underflow and decided in rationals when the bounds overlap.
// Only non-finite input is refused.
#include "raystep/base/math.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace raystep {

/// A regular grid over [lo, hi] with res[i] cells along axis i; boundary k of axis i lies at
/// lo + k (hi - lo) / res, for k = 0 .. res.
template <int N, typename T = double>
struct GridSpec {
    VecN<N, T> lo{T(0)};
    VecN<N, T> hi{T(1)};
    IVecN<N> res{1};
    T cellSize(int axis) const { return (hi[axis] - lo[axis]) / T(res[axis]); }
};

/// A time along the ray: either a given value (tMin, tMax, possibly infinite) or the crossing of
/// boundary k of an axis, kept symbolic so it can be compared exactly. A crossing's exact value is
/// always finite (the grid and ray are), even where its double estimate overflowed to inf.
struct Crossing {
    bool plain = true;
    double t = 0.0;  // the value (plain), or its floating-point estimate (0 or inf out of range)
    // low <= exact value <= high; equal when the value is known exactly (plain values).
    double low = 0.0, high = 0.0;
    // The exact value is (lo + k (hi - lo) / res - o) / d.
    double lo = 0.0, hi = 0.0, o = 0.0, d = 1.0;
    int res = 1;
    long k = 0;
};

namespace detail {
/// Sign of a - b in exact arithmetic (the rare case the filter cannot decide): rationals, with a
/// plain -inf below and +inf above every finite value; two equal infinities tie.
int compareCrossingsExact(const Crossing& a, const Crossing& b);
}  // namespace detail

/// Sign of a - b, exact: floating point when the bounds separate them, rationals otherwise. An
/// infinite tMax never wins over a crossing (always finite, even when its estimate is inf).
inline int compareCrossings(const Crossing& a, const Crossing& b) {
    if (a.high < b.low) return -1;
    if (a.low > b.high) return 1;
    // Known exactly (a given value, or a ray starting on the boundary): compare as they are.
    if (a.low == a.high && b.low == b.high) return (a.t > b.t) - (a.t < b.t);
    // Two boundaries of the same axis and ray: their order is the order of k along d.
    if (!a.plain && !b.plain && a.lo == b.lo && a.hi == b.hi && a.res == b.res && a.o == b.o &&
        a.d == b.d) {
        const long byK = (a.k > b.k) - (a.k < b.k);
        return static_cast<int>(a.d > 0 ? byK : -byK);
    }
    return detail::compareCrossingsExact(a, b);
}

// The walk below is the slides' DDA3D with one change: where the slides accumulate
// `tMaxX += tDeltaX` at each step, this walk recomputes tMaxX from the index of the boundary ahead
// (X + 1 moving up, X moving down): t = (lo + k (hi - lo) / res - o) / d, kept symbolic. A sum
// rounds at every step and, hundreds of cells down the ray, the rounding errors add up to a wrong
// `tMaxX < tMaxY` (a cell skipped, or one the ray only touches); the recomputed time errs by a
// few ulps wherever it is, and when that is not enough to decide, the comparison goes exact. The
// slides' loop itself, drift included, is ddaTextbook() in dda_textbook.h.

/// The walk itself. Construct it, then read cell() and step with next() until it returns false.
template <int N, typename T = double>
class Dda {
  public:
    Dda(const GridSpec<N, T>& grid, const VecN<N, T>& origin, const VecN<N, T>& dir, T tMin = T(0),
        T tMax = std::numeric_limits<T>::infinity())
        : grid_(grid), o_(origin), d_(dir) {
        for (int i = 0; i < N; ++i) {
            if (!(std::isfinite(grid_.lo[i]) && std::isfinite(grid_.hi[i]) &&
                  std::isfinite(o_[i]) && std::isfinite(d_[i]))) {
                problem_ = "the grid or the ray has a coordinate that is NaN or infinite";
                return;
            }
            if (grid_.res[i] < 1) {
                problem_ = "the grid has an axis without cells";
                return;
            }
            if (!(grid_.hi[i] > grid_.lo[i])) {
                problem_ = "the grid's upper corner is not above its lower corner on every axis";
                return;
            }
        }
        if (std::isnan(tMin) || std::isnan(tMax)) {
            problem_ = "the ray's interval [tMin, tMax] has a NaN end";
            return;
        }
        enter_ = plainTime(double(tMin));
        exit_ = plainTime(double(tMax));
        for (int i = 0; i < N; ++i) {
            step_[i] = d_[i] > T(0) ? 1 : (d_[i] < T(0) ? -1 : 0);
            tDelta_[i] =
                step_[i] ? std::abs(grid_.cellSize(i) / d_[i]) : std::numeric_limits<T>::infinity();
            if (step_[i] == 0) {
                // Parallel to this axis: inside its slab or never in the grid.
                if (o_[i] < grid_.lo[i] || o_[i] > grid_.hi[i]) return;
                continue;
            }
            // The slab [lo, hi] of this axis: entered at one end boundary, left at the other.
            const Crossing in = crossing(i, step_[i] > 0 ? 0 : grid_.res[i]);
            const Crossing out = crossing(i, step_[i] > 0 ? grid_.res[i] : 0);
            const int cmp = compareCrossings(in, enter_);
            if (cmp > 0) {
                enter_ = in;
                enteredThrough_ = 1u << i;
            } else if (cmp == 0 && enteredThrough_) {
                enteredThrough_ |= 1u << i;  // in through a grid edge or corner
            }
            if (compareCrossings(out, exit_) < 0) exit_ = out;
        }
        // Only an interval of positive length crosses the interior of a cell.
        if (compareCrossings(enter_, exit_) >= 0) return;
        for (int i = 0; i < N; ++i) {
            cell_[i] = firstCell(i);
            if (step_[i]) tMax_[i] = crossing(i, nextBoundary(i));
        }
        valid_ = true;
        lastAxes_ = enteredThrough_;
    }

    /// True while the walk is in a cell of the grid.
    bool valid() const { return valid_; }
    /// Why the walk refused its input (NaN or infinite grid, ray or interval end; an axis without
    /// cells; hi not above lo), or nullptr. A refused walk is not valid and lists no cell: the
    /// caller must report it (or fall back to testing everything), not take it for a miss.
    const char* problem() const { return problem_; }
    const IVecN<N>& cell() const { return cell_; }
    const IVecN<N>& step() const { return step_; }
    const VecN<N, T>& tDelta() const { return tDelta_; }
    /// tMax of each axis: where the ray crosses the next boundary of that axis (inf if parallel).
    /// These times, tEnter(), tCellExit() and tGridExit() are double estimates (0 or inf where the
    /// exact time is beyond double's range); the steps are decided on the exact times.
    VecN<N, T> tMax() const {
        VecN<N, T> m;
        for (int i = 0; i < N; ++i)
            m[i] = step_[i] ? T(tMax_[i].t) : std::numeric_limits<T>::infinity();
        return m;
    }
    /// Where the ray enters the current cell (clipped to [tMin, tMax]).
    T tEnter() const { return T(enter_.t); }
    /// Where the ray leaves the grid (or reaches tMax).
    T tGridExit() const { return T(exit_.t); }
    /// Where the ray leaves the current cell: its next crossing, or the grid's exit (or tMax).
    T tCellExit() const {
        const auto [next, axes] = nextCrossing();
        return T(axes && compareCrossings(next, exit_) < 0 ? next.t : exit_.t);
    }
    /// Axes stepped to reach the current cell (a bit each; two or three bits on an exact tie).
    /// For the first cell: the axis of the grid face the ray came in through, or 0 from inside.
    unsigned axesTaken() const { return lastAxes_; }

    /// The lecture's step: move to the neighbour across the nearest boundary. False when the ray
    /// leaves the grid (or reaches tMax) in the current cell.
    bool next() {
        if (!valid_) return false;
        const auto [next, axes] = nextCrossing();
        if (axes == 0 || compareCrossings(next, exit_) >= 0) {
            valid_ = false;
            return false;
        }
        for (int i = 0; i < N; ++i) {
            if (!(axes & (1u << i))) continue;
            cell_[i] += step_[i];
            tMax_[i] = crossing(i, nextBoundary(i));  // the slides' tMax += tDelta, exact
            if (cell_[i] < 0 || cell_[i] >= grid_.res[i]) {
                valid_ = false;
                return false;
            }
        }
        enter_ = next;
        lastAxes_ = axes;
        pending_.reset();  // a new cell: its next crossing is still to be found
        return true;
    }

  private:
    static Crossing plainTime(double t) {
        Crossing c;
        c.t = c.low = c.high = t;
        return c;
    }

    /// Crossing of boundary k of `axis`, with bounds on the rounding of its estimate. The grid's
    /// own faces (k = 0, res) are exact; inner boundaries carry the rounding of lo + k (hi-lo)/res.
    /// The error of (b - o) / d is then relative to |b - o|, which keeps the bound tight for a
    /// ray starting right next to a boundary (a shadow ray leaving a floor on the grid's face).
    Crossing crossing(int axis, long k) const {
        return crossingOf(grid_, axis, k, double(o_[axis]), double(d_[axis]));
    }
    /// Knuth's TwoSum: s = fl(a + b) is exact iff the rounding error it recovers is zero.
    static bool sumIsExact(double a, double b, double s) {
        const double bb = s - a;
        return (a - (s - bb)) + (b - bb) == 0.0;
    }
    static Crossing crossingOf(const GridSpec<N, T>& grid, int axis, long k, double o, double d) {
        Crossing c;
        c.plain = false;
        c.lo = double(grid.lo[axis]);
        c.hi = double(grid.hi[axis]);
        c.res = grid.res[axis];
        c.k = k;
        c.o = o;
        c.d = d;
        constexpr double eps = std::numeric_limits<double>::epsilon();
        // Each rounding errs by eps/2 relative or, in the subnormal range, by half of this.
        constexpr double tiny = std::numeric_limits<double>::denorm_min();
        double b, errB;
        if (k == 0) {
            b = c.lo, errB = 0.0;
        } else if (k == c.res) {
            b = c.hi, errB = 0.0;
        } else {
            const double width = c.hi - c.lo;
            const double size = width / c.res;
            const double offset = double(k) * size;
            b = c.lo + offset;
            // Error-free checks (a two-sum residual, fma residuals): was every step exact? On
            // round grids it is, and then b is the boundary itself (a camera on x = 0, say).
            const bool exact =
                sumIsExact(c.hi, -c.lo, width) && std::fma(size, double(c.res), -width) == 0.0 &&
                std::fma(double(k), size, -offset) == 0.0 && sumIsExact(c.lo, offset, b);
            // k times the size's underflow, plus the offset's: (k + 1) half-denormals at most,
            // below 2^-1040 for any int k.
            errB = exact ? 0.0 : 4 * eps * (std::abs(c.lo) + std::abs(c.hi)) + 0x1p-1040;
        }
        const double diff = b - c.o;  // a difference never underflows: relative error only
        c.t = diff / c.d;
        // |t - exact| <= errB / |d| + eps |t| + (a half-denormal of underflow), doubled against
        // the rounding of this bound itself; inf where it overflows.
        const double e = 2 * (errB / std::abs(c.d) + eps * std::abs(c.t)) + 4 * tiny;
        c.low = c.t - e;
        c.high = c.t + e;
        if (errB == 0.0 && diff == 0.0) {
            c.low = c.high = 0.0;  // the ray starts exactly on this boundary: t = 0, exactly
        } else if (std::isinf(c.t)) [[unlikely]] {
            // The quotient overflowed, so |diff / d| > DBL_MAX: if diff is finite and its error
            // small against it, the exact time lies beyond DBL_MAX / 2 with the estimate's sign;
            // else (a boundary beyond DBL_MAX, say) nothing is known.
            constexpr double big = std::numeric_limits<double>::max() / 2;
            constexpr double inf = std::numeric_limits<double>::infinity();
            const bool known =
                std::isfinite(diff) && errB + eps * std::abs(diff) <= 0.25 * std::abs(diff);
            c.low = known && c.t > 0 ? big : -inf;
            c.high = known && c.t < 0 ? -big : inf;
        }
        return c;
    }
    long nextBoundary(int axis) const { return step_[axis] > 0 ? cell_[axis] + 1 : cell_[axis]; }

    /// The nearest boundary crossing ahead, and every axis that crosses at that same time;
    /// found once per cell (tCellExit() and next() both need it).
    const std::pair<Crossing, unsigned>& nextCrossing() const {
        if (!pending_) pending_ = computeNextCrossing();
        return *pending_;
    }
    std::pair<Crossing, unsigned> computeNextCrossing() const {
        Crossing best;
        unsigned axes = 0;
        for (int i = 0; i < N; ++i) {
            if (!step_[i]) continue;
            const Crossing& c = tMax_[i];
            const int cmp = axes ? compareCrossings(c, best) : -1;
            if (cmp < 0) {
                best = c;
                axes = 1u << i;
            } else if (cmp == 0) {
                axes |= 1u << i;
            }
        }
        return {best, axes};
    }

    /// The largest k in [0, res) with pred(k), for pred true at 0 (not asked again) and true then
    /// false: checked at the guess and its neighbour first (the usual answer), else by bisection.
    template <typename Pred>
    static int lastTrue(int res, int guess, Pred&& pred) {
        int lo = 0, hi = res;  // pred(lo) holds; hi == res or pred(hi) fails
        if (guess > 0 && !pred(guess))
            hi = guess;
        else
            lo = guess;
        if (lo == guess && lo + 1 < hi) {
            if (!pred(lo + 1)) return lo;
            lo = lo + 1;
        }
        while (hi - lo > 1) {
            const int mid = lo + (hi - lo) / 2;
            (pred(mid) ? lo : hi) = mid;
        }
        return lo;
    }
    /// floor((p - lo) / size) clamped to the axis' cells, before any conversion to int (p may be
    /// inf or NaN where the entry time overflowed).
    int estimateCell(int axis, double p) const {
        const double f = std::floor((p - double(grid_.lo[axis])) / double(grid_.cellSize(axis)));
        if (!(f > 0.0)) return 0;
        return f < grid_.res[axis] - 1 ? int(f) : grid_.res[axis] - 1;
    }

    /// The cell of `axis` just after the entry time: found from an estimate, then confirmed or
    /// corrected with exact comparisons of boundary crossings against the entry time.
    int firstCell(int axis) const {
        const int res = grid_.res[axis];
        if (step_[axis] == 0) {
            // Parallel: the cell holding the origin's coordinate (b_k <= o < b_k+1; o = hi: last).
            const auto below = [&](long j) {  // boundary j <= o, decided exactly
                // (b_j - o) / 1 compared with 0: the sign of b_j - o.
                const Crossing c = crossingOf(grid_, axis, j, double(o_[axis]), 1.0);
                return compareCrossings(c, plainTime(0.0)) <= 0;
            };
            return lastTrue(res, estimateCell(axis, double(o_[axis])), below);
        }
        // Boundaries already crossed at the entry time: crossing <= enter.
        const auto crossed = [&](long j) {
            return compareCrossings(crossing(axis, j), enter_) <= 0;
        };
        const int guess = estimateCell(axis, double(o_[axis]) + enter_.t * double(d_[axis]));
        // Cell k moving up: boundary k crossed, k+1 not yet (boundary 0 is, at the entry time).
        if (step_[axis] > 0) return lastTrue(res, guess, crossed);
        // Moving down: boundary k+1 crossed, k not yet (boundary 0 is where the ray leaves).
        return lastTrue(res, guess, [&](long j) { return !crossed(j); });
    }

    GridSpec<N, T> grid_;
    VecN<N, T> o_, d_;
    // The slides' variables: X, Y, Z; stepX...; tDeltaX...; tMaxX... (exact, for a non-zero step).
    IVecN<N> cell_{0};
    IVecN<N> step_{0};
    VecN<N, T> tDelta_{T(0)};
    std::array<Crossing, N> tMax_{};
    Crossing enter_, exit_;
    unsigned enteredThrough_ = 0;
    unsigned lastAxes_ = 0;
    bool valid_ = false;
    const char* problem_ = nullptr;
    mutable std::optional<std::pair<Crossing, unsigned>> pending_;
};

}  // namespace raystep
