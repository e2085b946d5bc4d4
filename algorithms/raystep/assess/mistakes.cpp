#include "raystep/assess/mistakes.h"

#include "raystep/base/i18n.h"

namespace raystep {

const std::array<MistakeInfo, kMistakeCount>& mistakes() {
    using M = Mistake;
    static const std::array<MistakeInfo, kMistakeCount> table = {{
        {M::StartCellSkipped, "start-cell-skipped",
         trNoop("the walk steps before it visits the cell it starts in"), true},
        {M::NegativeDirectionBoundary, "negative-direction-boundary",
         trNoop("tMax is set up with the boundary X + 1 also when the ray moves down (stepX = "
                "-1), where the boundary ahead is X: right in one quadrant only"),
         true},
        {M::ParallelAxisDivision, "parallel-axis-division",
         trNoop("for a direction component of 0 the walk takes step = -1 and divides by it: "
                "tMax = (b - o) / 0 = -inf, so it keeps stepping along an axis the ray is "
                "parallel to"),
         true},
        {M::NegativeZero, "negative-zero",
         trNoop("step = (d >= 0 ? 1 : -1) takes a direction of -0.0 for positive, and (b - o) / "
                "-0.0 = -inf: the walk keeps stepping along an axis the ray is parallel to"),
         true},
        {M::TieOneAxis, "tie-one-axis",
         trNoop("at an exact tie of tMax (the ray through a grid vertex) the walk steps one axis "
                "and visits a cell the ray only touches; every tied axis steps at once"),
         true},
        {M::NoEntryClip, "no-entry-clip",
         trNoop("the first cell is the cell of the ray's origin (clamped to the grid), not the "
                "cell where the ray enters the grid at tEnter"),
         true},
        {M::NoExitCheck, "no-exit-check",
         trNoop("the walk does not stop when a step leaves the grid: it goes on through cells "
                "outside it"),
         true},
        {M::AccumulatedTmax, "accumulated-tmax",
         trNoop("tMax += tDelta rounds at every step: far along the ray the sums decide a "
                "step wrong (tMax recomputed from the boundary's index stays exact)"),
         true},
        {M::FirstHitInCell, "first-hit-in-cell",
         trNoop("the walk stops at the first hit found in a cell although the hit lies beyond "
                "the cell's exit: a primitive in a later cell can be nearer"),
         false},
        {M::NoMailbox, "no-mailbox",
         trNoop("a primitive listed in several cells is tested again in each: the mailbox "
                "remembers it was tested for this ray"),
         false},
        {M::FirstHitInTree, "first-hit-in-tree",
         trNoop("TestTree stops at the first hit found in a leaf without checking it lies "
                "within the leaf's [tNear, tFar]: a nearer hit may be in a leaf still on the "
                "stack"),
         false},
    }};
    return table;
}

const MistakeInfo& mistakeInfo(Mistake m) {
    return mistakes()[static_cast<std::size_t>(m)];
}

std::optional<Mistake> parseMistake(std::string_view name) {
    for (const MistakeInfo& info : mistakes())
        if (info.name == name) return info.mistake;
    return std::nullopt;
}

}  // namespace raystep
