#pragma once
// The classic mistakes of a student's DDA and TestTree, as named variants of the slides' own
// walk: the assessor (assess.h) recognises a student's run by the variant it matches, and the
// lessons replay a variant for "spot the bug". Each variant is the slides' loop with one line
// changed, written as the student would write it, IEEE arithmetic included (a -inf tMax, a NaN
// comparison): the names and what each one does wrong are in docs/assignment-format.md.
#include "raystep/accel/dda_textbook.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

namespace raystep {

enum class Mistake : std::uint8_t {
    StartCellSkipped,
    NegativeDirectionBoundary,
    ParallelAxisDivision,
    NegativeZero,
    TieOneAxis,
    NoEntryClip,
    NoExitCheck,
    AccumulatedTmax,
    FirstHitInCell,
    NoMailbox,
    FirstHitInTree,
};
constexpr int kMistakeCount = 11;

struct MistakeInfo {
    Mistake mistake;
    std::string_view name;         // stable: the JSON's and the CSV's
    std::string_view description;  // English; tr() gives the language's
    bool dda;                      // a variant of the DDA walk (ddaWithMistake makes it)
};
/// Every mistake, in the order of docs/assignment-format.md (a tie between two variants that
/// explain a run equally well goes to the earlier one).
const std::array<MistakeInfo, kMistakeCount>& mistakes();
const MistakeInfo& mistakeInfo(Mistake m);
std::optional<Mistake> parseMistake(std::string_view name);

/// A cell of a walk and its tMax there, as the walk's own arithmetic has it.
template <int N>
struct WalkCell {
    IVecN<N> cell;
    VecN<N, double> tMax;
};

/// At an exact tie of tMax, which axis the slides' loop steps: the last tied one (the slides'
/// `if (tMaxX < tMaxY) X else Y`), the first (`tMaxX <= tMaxY`), or every tied axis at once.
enum class TieRule : std::uint8_t { LastAxis, FirstAxis, AllAxes };

/// The slides' DDA (`tMax += tDelta`, in double) from t = 0 along o + t d, with `mistake` made in
/// it; nullopt makes none (every tied axis steps at once, as the exact walk does). At most
/// `maxCells` cells: a walk with NoExitCheck, or one that a NaN keeps from ending, stops there.
template <int N>
std::vector<WalkCell<N>> ddaWithMistake(const GridSpec<N, double>& grid, const VecN<N, double>& o,
                                        const VecN<N, double>& d, std::optional<Mistake> mistake,
                                        int maxCells, TieRule tieRule = TieRule::LastAxis) {
    using M = Mistake;
    const auto is = [&](M m) { return mistake && *mistake == m; };
    std::vector<WalkCell<N>> cells;
    // Where the ray enters the grid's box (the slab test), t >= 0.
    double tEnter = 0.0;
    if (!detail::textbookEntry<N, double>(grid, o, d, tEnter)) return cells;
    // The set-up: X, stepX, tMaxX, tDeltaX per axis.
    IVecN<N> X{0}, step{0}, justOut{0};
    VecN<N, double> tMax{0.0}, tDelta{0.0};
    for (int i = 0; i < N; ++i) {
        const double size = grid.cellSize(i);
        // NoEntryClip: the cell of the origin, clamped into the grid, not of the entry point.
        const double p = is(M::NoEntryClip) ? o[i] : o[i] + tEnter * d[i];
        if (is(M::ParallelAxisDivision))
            step[i] = d[i] > 0 ? 1 : -1;  // d = 0 steps down
        else if (is(M::NegativeZero))
            step[i] = d[i] >= 0 ? 1 : -1;  // -0.0 >= 0 is true: steps up
        else
            step[i] = d[i] > 0 ? 1 : (d[i] < 0 ? -1 : 0);
        // The cell the ray goes into, as dda.h's: on a boundary moving down, the one below it.
        const double f = (p - grid.lo[i]) / size;
        const double c = d[i] < 0 && !is(M::NoEntryClip) ? std::ceil(f) - 1 : std::floor(f);
        X[i] = int(std::clamp(c, 0.0, double(grid.res[i] - 1)));
        justOut[i] = step[i] > 0 ? grid.res[i] : -1;
        // The boundary ahead: X + 1 moving up, X moving down (NegativeDirectionBoundary: X + 1).
        const int k = is(M::NegativeDirectionBoundary) || step[i] > 0 ? X[i] + 1 : X[i];
        tMax[i] = step[i] ? (grid.lo[i] + k * size - o[i]) / d[i]
                          : std::numeric_limits<double>::infinity();
        tDelta[i] = step[i] ? size / std::abs(d[i]) : std::numeric_limits<double>::infinity();
    }
    const TieRule ties = is(M::TieOneAxis) ? tieRule : TieRule::AllAxes;
    for (bool first = true; int(cells.size()) < maxCells; first = false) {
        if (!(first && is(M::StartCellSkipped))) cells.push_back({X, tMax});
        // The axis of the smallest tMax, as the slides' comparisons choose it.
        int a = 0;
        for (int i = 1; i < N; ++i) {
            if (ties == TieRule::FirstAxis ? tMax[i] < tMax[a] : !(tMax[a] < tMax[i])) a = i;
        }
        if (std::isinf(tMax[a]) && tMax[a] > 0) break;  // no boundary ahead: a zero direction
        bool out = false;
        for (int i = 0; i < N; ++i) {
            if (i != a && !(ties == TieRule::AllAxes && tMax[i] == tMax[a])) continue;
            X[i] += step[i];
            if (X[i] == justOut[i] && !is(M::NoExitCheck)) out = true;
            tMax[i] += tDelta[i];
        }
        if (out) break;
    }
    return cells;
}

}  // namespace raystep
