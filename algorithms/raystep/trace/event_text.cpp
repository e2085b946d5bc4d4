// Events as text: the lecture's wording of each event kind, and its numbers. Each line is one
// whole sentence of the catalogue (i18n/it/core.json), never pieced together from words, so the
// Italian can put its words in its own order.
#include "raystep/trace/event_text.h"

#include "raystep/base/format.h"

#include <cmath>
#include <cstdio>

namespace raystep {

namespace {
std::string intText(std::int32_t v) {
    return std::to_string(v);
}
std::string id(std::uint32_t v) {
    return v == kNoId ? "-" : std::to_string(v);
}
std::string axisLetter(std::uint8_t axis) {
    return std::string(1, "XYZ"[axis]);
}

std::string rayBeginText(const RayBegin& e, Language lang) {
    const std::string ray = id(e.ray), depth = std::to_string(e.depth);
    switch (e.kind) {
        case RayKind::Primary:
            return trf(lang, "ray %1 begins: primary, depth %2", {ray, depth});
        case RayKind::Shadow:
            return trf(lang, "ray %1 begins: shadow, depth %2", {ray, depth});
        case RayKind::Reflection:
            return trf(lang, "ray %1 begins: reflection, depth %2", {ray, depth});
        case RayKind::Refraction:
            return trf(lang, "ray %1 begins: refraction, depth %2", {ray, depth});
        case RayKind::Diffuse:
            return trf(lang, "ray %1 begins: diffuse, depth %2", {ray, depth});
    }
    return trf(lang, "ray %1 begins: primary, depth %2", {ray, depth});
}

std::string leafText(const LeafMade& e, Language lang) {
    const std::string node = id(e.node), prims = std::to_string(e.prims);
    switch (e.reason) {
        case LeafReason::FewPrimitives:
            return trf(lang, "leaf %1: %2 primitives (few_primitives)", {node, prims});
        case LeafReason::MaxDepth:
            return trf(lang, "leaf %1: %2 primitives (max_depth)", {node, prims});
        case LeafReason::SahCheaper:
            return trf(lang, "leaf %1: %2 primitives (sah_cheaper)", {node, prims});
        case LeafReason::NoSplit:
            return trf(lang, "leaf %1: %2 primitives (no_split)", {node, prims});
        case LeafReason::NoProgress:
            return trf(lang, "leaf %1: %2 primitives (no_progress)", {node, prims});
    }
    return trf(lang, "leaf %1: %2 primitives (few_primitives)", {node, prims});
}

/// A colour's components as the board writes them: one below what six digits of a unit value
/// hold (a specular term's cos^n of 2e-230) is 0, not a number no screen could show.
std::string colourText(std::array<double, 3> rgb, Language lang) {
    for (double& c : rgb)
        if (std::abs(c) < 5e-7) c = 0.0;
    return tupleText(rgb, 3, lang);
}

std::string termText(const ShadingTerm& e, Language lang) {
    const std::string rgb = colourText(e.rgb, lang);
    switch (e.term) {
        case ShadingTermKind::Ambient:
            return trf(lang, "ambient term %1", {rgb});
        case ShadingTermKind::Diffuse:
            return trf(lang, "diffuse term %1", {rgb});
        case ShadingTermKind::Specular:
            return trf(lang, "specular term %1", {rgb});
        case ShadingTermKind::Reflected:
            return trf(lang, "reflected term %1", {rgb});
        case ShadingTermKind::Transmitted:
            return trf(lang, "transmitted term %1", {rgb});
        case ShadingTermKind::DiffuseBounce:
            return trf(lang, "diffuse_bounce term %1", {rgb});
    }
    return trf(lang, "ambient term %1", {rgb});
}

/// A blocked shadow ray names what blocks it, when the trace says (a hand-written one may not).
std::string blockedText(const RayBlocked& e, Language lang) {
    if (e.prim == kNoId)
        return trf(lang, "shadow ray %1 blocked: the point is in shadow", {id(e.ray)});
    return trf(lang, "shadow ray %1 blocked by primitive %2 at t = %3: the point is in shadow",
               {id(e.ray), id(e.prim), numberText(e.t, lang)});
}
}  // namespace

std::string numberText(double v, Language lang) {
    if (std::isnan(v)) return "nan";
    return formatNumber(v + 0.0, lang);  // + 0.0: -0 reads "0", a sign on nothing would only puzzle
}

std::string cellText(const std::array<std::int32_t, 3>& cell, int dims) {
    std::string s = "(";
    for (int i = 0; i < dims; ++i) s += (i ? ", " : "") + intText(cell[i]);
    return s + ")";
}

std::string tupleText(const std::array<double, 3>& v, int dims, Language lang) {
    // Where the comma is the decimal mark (Italian) the items are parted otherwise ("; ").
    const std::string_view separator = listSeparator(lang);
    std::string s = "(";
    for (int i = 0; i < dims; ++i) {
        if (i) s += separator;
        s += numberText(v[i], lang);
    }
    return s + ")";
}

std::string axesText(unsigned axes) {
    std::string s;
    for (int i = 0; i < 3; ++i)
        if (axes & (1u << i)) s += "XYZ"[i];
    return s;
}

std::string eventText(const Event& event, int dims, Language lang) {
    return std::visit(
        [dims, lang](const auto& e) -> std::string {
            using E = std::decay_t<decltype(e)>;
            const auto num = [lang](double v) { return numberText(v, lang); };
            if constexpr (std::is_same_v<E, RayBegin>)
                return rayBeginText(e, lang);
            else if constexpr (std::is_same_v<E, DdaSetup>)
                return trf(lang, "DDA set-up: step %1, tDelta %2",
                           {cellText({e.step[0], e.step[1], e.step[2]}, e.dims == 3 ? 3 : 2),
                            tupleText(e.tDelta, e.dims == 3 ? 3 : 2, lang)});
            else if constexpr (std::is_same_v<E, DdaCell>)
                return e.axes ? trf(lang, "cell %1 by %2, tMax %3",
                                    {cellText(e.cell, dims), axesText(e.axes),
                                     tupleText(e.tMax, dims, lang)})
                              : trf(lang, "cell %1 (first cell), tMax %2",
                                    {cellText(e.cell, dims), tupleText(e.tMax, dims, lang)});
            else if constexpr (std::is_same_v<E, MailboxSkip>)
                return trf(lang, "mailbox: primitive %1 already tested", {id(e.prim)});
            else if constexpr (std::is_same_v<E, PrimitiveTest>)
                return e.hit ? trf(lang, "test primitive %1: hit at t = %2", {id(e.prim), num(e.t)})
                             : trf(lang, "test primitive %1: miss", {id(e.prim)});
            else if constexpr (std::is_same_v<E, NodeEnter>)
                return trf(lang, "enter node %1 [%2, %3]", {id(e.node), num(e.tNear), num(e.tFar)});
            else if constexpr (std::is_same_v<E, NodeSkip>)
                return trf(lang, "skip node %1", {id(e.node)});
            else if constexpr (std::is_same_v<E, BuildNode>)
                return trf(lang, "build node %1: %2 primitives, depth %3",
                           {id(e.node), std::to_string(e.prims), std::to_string(e.depth)});
            else if constexpr (std::is_same_v<E, SplitCandidate>)
                return trf(lang, "candidate %1 = %2: NL %3, NR %4, cost %5",
                           {axisLetter(e.axis), num(e.position), std::to_string(e.nl),
                            std::to_string(e.nr), num(e.sahCost)});
            else if constexpr (std::is_same_v<E, SplitChosen>)
                return trf(lang, "split %1 = %2 (cost %3, leaf %4)",
                           {axisLetter(e.axis), num(e.position), num(e.sahCost), num(e.leafCost)});
            else if constexpr (std::is_same_v<E, LeafMade>)
                return leafText(e, lang);
            else if constexpr (std::is_same_v<E, RayHit>)
                return trf(lang, "ray %1 hits primitive %2 at t = %3",
                           {id(e.ray), id(e.prim), num(e.t)});
            else if constexpr (std::is_same_v<E, RayBlocked>)
                return blockedText(e, lang);
            else if constexpr (std::is_same_v<E, RayMiss>)
                return trf(lang, "ray %1 misses", {id(e.ray)});
            else if constexpr (std::is_same_v<E, ShadingTerm>)
                return termText(e, lang);
            else if constexpr (std::is_same_v<E, PixelResult>)
                return trf(lang, "pixel (%1, %2) = %3",
                           {std::to_string(e.x), std::to_string(e.y), colourText(e.rgb, lang)});
            else
                static_assert(sizeof(E) == 0, "every event has its sentence");
        },
        event);
}

std::string eventText(const EventLog& log, std::size_t index, Language lang) {
    const Event& event = log.events().at(index);
    if (const auto* miss = std::get_if<RayMiss>(&event);
        miss && miss->ray < log.rays().size() && log.rays()[miss->ray].kind == RayKind::Shadow)
        return trf(lang, "shadow ray %1 misses: nothing lies between the point and the light",
                   {id(miss->ray)});
    return eventText(event, log.dims(), lang);
}

}  // namespace raystep
