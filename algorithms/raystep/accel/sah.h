#pragma once
// The Surface Area Heuristic, once for both trees: the cost of a split, and a built tree's
// expected cost. The slides: Cost = C_trav + P(L|C) Cost(L) + P(R|C) Cost(R), with
// P(L|C) = Area(L) / Area(C) (the chance a ray through C also crosses L) and Cost(leaf) = C_isect
// N.
#include "raystep/base/names.h"
#include "raystep/trace/events.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace raystep {

/// Where a tree puts its plane: the middle of the node, the median of the primitives' centres,
/// or the plane of lowest SAH cost.
enum class SplitMethod { Midpoint, Median, Sah };
inline constexpr NameTable<SplitMethod, 3> kSplitMethodNames{{{SplitMethod::Midpoint, "midpoint"},
                                                              {SplitMethod::Median, "median"},
                                                              {SplitMethod::Sah, "sah"}}};
inline std::optional<SplitMethod> parseSplitMethod(std::string_view s) {
    return valueNamed(kSplitMethodNames, s);
}
inline std::string_view name(SplitMethod m) {
    return nameOf(kSplitMethodNames, m);
}

/// The cost of a leaf of n primitives: every one is tested.
inline double leafCost(double cIsect, std::uint32_t n) {
    return cIsect * n;
}

/// The cost of splitting a node: C_trav + C_isect (pL nL + pR nR), pL and pR the children's
/// P(L|C) and P(R|C), every primitive of a child counted as a leaf.
inline double splitCost(double cTrav, double cIsect, double pl, double pr, std::uint32_t nl,
                        std::uint32_t nr) {
    return cTrav + cIsect * (pl * nl + pr * nr);
}

/// The kd-tree's SAH cost of a split: splitCost, times (1 - emptyBonus) when a side is empty (an
/// empty side is cheap to skip, so cutting off empty space is encouraged).
inline double sahCost(double cTrav, double cIsect, double emptyBonus, double pl, double pr,
                      std::uint32_t nl, std::uint32_t nr) {
    const double bonus = (nl == 0 || nr == 0) ? 1.0 - emptyBonus : 1.0;
    return bonus * splitCost(cTrav, cIsect, pl, pr, nl, nr);
}

/// A built interior node's expected cost from its children's: the slides' formula with the
/// children's real costs (no empty bonus: this is what a ray pays, not a heuristic's nudge).
inline double interiorCost(double cTrav, double area, double areaL, double costL, double areaR,
                           double costR) {
    return cTrav + (areaL / area) * costL + (areaR / area) * costR;
}

/// What a tree's build made (`raystep-cli build`).
struct TreeStats {
    std::uint32_t nodes = 0;
    std::uint32_t leaves = 0;
    std::uint32_t emptyLeaves = 0;
    std::uint32_t maxDepth = 0;
    std::uint64_t references = 0;  // primitive ids stored in leaves (duplicates counted)
    double sahCost = 0.0;          // expected cost of a ray through the root box (no empty bonus)
    double buildMs = 0.0;
    std::array<std::uint32_t, kLeafReasonNames.size()> leafReasons{};  // by LeafReason
};

}  // namespace raystep
