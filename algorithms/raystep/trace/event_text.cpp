// Events as text: the lecture's wording of each event kind, and its numbers.
#include "raystep/trace/event_text.h"

#include "raystep/base/format.h"

#include <cmath>
#include <cstdio>

namespace raystep {

namespace {
template <typename T>
std::string bracketed(const std::array<T, 3>& v, int dims, std::string (*text)(T)) {
    std::string s = "(";
    for (int i = 0; i < dims; ++i) s += (i ? ", " : "") + text(v[i]);
    return s + ")";
}
std::string intText(std::int32_t v) {
    return std::to_string(v);
}
std::string primText(std::uint32_t p) {
    return p == kNoId ? "-" : std::to_string(p);
}
std::string axisLetter(std::uint8_t axis) {
    return std::string(1, "XYZ"[axis]);
}
std::string nameText(std::string_view name) {
    return std::string(name);
}
}  // namespace

std::string numberText(double v) {
    if (std::isnan(v)) return "nan";
    return formatNumber(v + 0.0);  // + 0.0: -0 reads "0", a sign on nothing would only puzzle
}

std::string cellText(const std::array<std::int32_t, 3>& cell, int dims) {
    return bracketed(cell, dims, intText);
}

std::string tupleText(const std::array<double, 3>& v, int dims) {
    return bracketed(v, dims, numberText);
}

std::string axesText(unsigned axes) {
    std::string s;
    for (int i = 0; i < 3; ++i)
        if (axes & (1u << i)) s += "XYZ"[i];
    return s;
}

std::string eventText(const Event& event, int dims) {
    return std::visit(
        [dims](const auto& e) -> std::string {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, RayBegin>)
                return "ray " + std::to_string(e.ray) +
                       " begins: " + nameText(kRayKindNames[static_cast<int>(e.kind)]) +
                       ", depth " + std::to_string(e.depth);
            else if constexpr (std::is_same_v<E, DdaSetup>)
                return "DDA set-up: step " +
                       cellText({e.step[0], e.step[1], e.step[2]}, e.dims == 3 ? 3 : 2) +
                       ", tDelta " + tupleText(e.tDelta, e.dims == 3 ? 3 : 2);
            else if constexpr (std::is_same_v<E, DdaCell>)
                return "cell " + cellText(e.cell, dims) +
                       (e.axes ? " by " + axesText(e.axes) : " (first cell)") + ", tMax " +
                       tupleText(e.tMax, dims);
            else if constexpr (std::is_same_v<E, MailboxSkip>)
                return "mailbox: primitive " + std::to_string(e.prim) + " already tested";
            else if constexpr (std::is_same_v<E, PrimitiveTest>)
                return "test primitive " + std::to_string(e.prim) +
                       (e.hit ? ": hit at t = " + numberText(e.t) : ": miss");
            else if constexpr (std::is_same_v<E, NodeEnter>)
                return "enter node " + std::to_string(e.node) + " [" + numberText(e.tNear) + ", " +
                       numberText(e.tFar) + "]";
            else if constexpr (std::is_same_v<E, NodeSkip>)
                return "skip node " + std::to_string(e.node);
            else if constexpr (std::is_same_v<E, BuildNode>)
                return "build node " + std::to_string(e.node) + ": " + std::to_string(e.prims) +
                       " primitives, depth " + std::to_string(e.depth);
            else if constexpr (std::is_same_v<E, SplitCandidate>)
                return "candidate " + axisLetter(e.axis) + " = " + numberText(e.position) +
                       ": NL " + std::to_string(e.nl) + ", NR " + std::to_string(e.nr) + ", cost " +
                       numberText(e.sahCost);
            else if constexpr (std::is_same_v<E, SplitChosen>)
                return "split " + axisLetter(e.axis) + " = " + numberText(e.position) + " (cost " +
                       numberText(e.sahCost) + ", leaf " + numberText(e.leafCost) + ")";
            else if constexpr (std::is_same_v<E, LeafMade>)
                return "leaf " + std::to_string(e.node) + ": " + std::to_string(e.prims) +
                       " primitives (" + nameText(kLeafReasonNames[static_cast<int>(e.reason)]) +
                       ")";
            else if constexpr (std::is_same_v<E, RayHit>)
                return "ray " + std::to_string(e.ray) + " hits primitive " + primText(e.prim) +
                       " at t = " + numberText(e.t);
            else if constexpr (std::is_same_v<E, RayMiss>)
                return "ray " + std::to_string(e.ray) + " misses";
            else if constexpr (std::is_same_v<E, ShadingTerm>)
                return nameText(kShadingTermNames[static_cast<int>(e.term)]) + " term " +
                       tupleText(e.rgb, 3);
            else
                return "pixel (" + std::to_string(e.x) + ", " + std::to_string(e.y) +
                       ") = " + tupleText(e.rgb, 3);
        },
        event);
}

}  // namespace raystep
