// The sentences that explain a reference answer (course/feedback_text.h), through the one
// translation mechanism: English is the key, the Italian is in i18n/it/course.json.
#include "feedback_text.h"

#include "course/lesson_trace.h"

#include "raystep/trace/event_text.h"
#include "raystep/trace/replay.h"

namespace raystep::feedback {

const char* axisName(int a) {
    return a == 0 ? "x" : a == 1 ? "y" : "z";
}

std::string afterEvent(Language lang, std::size_t kind, const std::string& nth) {
    // The nth event of a kind, as the lecture would say it (no internal names).
    switch (kind) {
        case variantIndex<RayBegin>():
            return trf(lang, "after the %1 ray begins", {nth});
        case variantIndex<DdaSetup>():
            return trf(lang, "after the %1 DDA set-up", {nth});
        case variantIndex<DdaCell>():
            return trf(lang, "after the %1 cell visited", {nth});
        case variantIndex<MailboxSkip>():
            return trf(lang, "after the %1 test skipped by mailboxing", {nth});
        case variantIndex<PrimitiveTest>():
            return trf(lang, "after the %1 primitive test", {nth});
        case variantIndex<NodeEnter>():
            return trf(lang, "after the %1 node entered", {nth});
        case variantIndex<NodeSkip>():
            return trf(lang, "after the %1 node skipped", {nth});
        case variantIndex<BuildNode>():
            return trf(lang, "after the %1 node built", {nth});
        case variantIndex<SplitCandidate>():
            return trf(lang, "after the %1 candidate plane", {nth});
        case variantIndex<SplitChosen>():
            return trf(lang, "after the %1 chosen plane", {nth});
        case variantIndex<LeafMade>():
            return trf(lang, "after the %1 leaf made", {nth});
        case variantIndex<RayHit>():
            return trf(lang, "after the %1 intersection found", {nth});
        case variantIndex<RayMiss>():
            return trf(lang, "after the %1 ray that hits nothing", {nth});
        case variantIndex<RayBlocked>():
            return trf(lang, "after the %1 shadow ray blocked", {nth});
        case variantIndex<ShadingTerm>():
            return trf(lang, "after the %1 shading term", {nth});
        case variantIndex<PixelResult>():
            return trf(lang, "after the %1 pixel colour", {nth});
    }
    return std::string(kEventNames.at(kind));
}
std::string beforeEvent(Language lang, std::size_t kind, const std::string& nth) {
    // As afterEvent, before it.
    switch (kind) {
        case variantIndex<RayBegin>():
            return trf(lang, "before the %1 ray begins", {nth});
        case variantIndex<DdaSetup>():
            return trf(lang, "before the %1 DDA set-up", {nth});
        case variantIndex<DdaCell>():
            return trf(lang, "before the %1 cell visited", {nth});
        case variantIndex<MailboxSkip>():
            return trf(lang, "before the %1 test skipped by mailboxing", {nth});
        case variantIndex<PrimitiveTest>():
            return trf(lang, "before the %1 primitive test", {nth});
        case variantIndex<NodeEnter>():
            return trf(lang, "before the %1 node entered", {nth});
        case variantIndex<NodeSkip>():
            return trf(lang, "before the %1 node skipped", {nth});
        case variantIndex<BuildNode>():
            return trf(lang, "before the %1 node built", {nth});
        case variantIndex<SplitCandidate>():
            return trf(lang, "before the %1 candidate plane", {nth});
        case variantIndex<SplitChosen>():
            return trf(lang, "before the %1 chosen plane", {nth});
        case variantIndex<LeafMade>():
            return trf(lang, "before the %1 leaf made", {nth});
        case variantIndex<RayHit>():
            return trf(lang, "before the %1 intersection found", {nth});
        case variantIndex<RayMiss>():
            return trf(lang, "before the %1 ray that hits nothing", {nth});
        case variantIndex<RayBlocked>():
            return trf(lang, "before the %1 shadow ray blocked", {nth});
        case variantIndex<ShadingTerm>():
            return trf(lang, "before the %1 shading term", {nth});
        case variantIndex<PixelResult>():
            return trf(lang, "before the %1 pixel colour", {nth});
    }
    return std::string(kEventNames.at(kind));
}
std::string eventsCounted(Language lang, std::size_t kind) {
    switch (kind) {
        case variantIndex<RayBegin>():
            return tr(lang, "Rays");
        case variantIndex<DdaSetup>():
            return tr(lang, "DDA set-ups");
        case variantIndex<DdaCell>():
            return tr(lang, "Cells visited");
        case variantIndex<MailboxSkip>():
            return tr(lang, "Tests skipped by mailboxing");
        case variantIndex<PrimitiveTest>():
            return tr(lang, "Primitive tests");
        case variantIndex<NodeEnter>():
            return tr(lang, "Nodes entered");
        case variantIndex<NodeSkip>():
            return tr(lang, "Nodes skipped");
        case variantIndex<BuildNode>():
            return tr(lang, "Nodes built");
        case variantIndex<SplitCandidate>():
            return tr(lang, "Candidate planes");
        case variantIndex<SplitChosen>():
            return tr(lang, "Chosen planes");
        case variantIndex<LeafMade>():
            return tr(lang, "Leaves made");
        case variantIndex<RayHit>():
            return tr(lang, "Intersections found");
        case variantIndex<RayMiss>():
            return tr(lang, "Rays that hit nothing");
        case variantIndex<RayBlocked>():
            return tr(lang, "Shadow rays blocked");
        case variantIndex<ShadingTerm>():
            return tr(lang, "Shading terms");
        case variantIndex<PixelResult>():
            return tr(lang, "Pixel colours");
    }
    return std::string(kEventNames.at(kind));
}

std::string raysOfKind(Language lang, RayKind k) {
    switch (k) {
        case RayKind::Primary:
            return tr(lang, "Primary rays");
        case RayKind::Shadow:
            return tr(lang, "Shadow rays");
        case RayKind::Reflection:
            return tr(lang, "Reflected rays");
        case RayKind::Refraction:
            return tr(lang, "Refracted rays");
        case RayKind::Diffuse:
            return tr(lang, "Diffuse bounce rays");
    }
    return tr(lang, "Rays");
}

std::string axesWords(Language lang, unsigned axes, const std::string& prefix) {
    std::vector<std::string> names;
    for (int i = 0; i < 3; ++i)
        if (axes & (1u << i)) names.push_back(prefix + "XYZ"[i]);
    if (names.empty()) return "";
    std::string head = names[0];
    for (std::size_t i = 1; i + 1 < names.size(); ++i) head += ", " + names[i];
    return names.size() == 1 ? head : trf(lang, "%1 and %2", {head, names.back()});
}

std::string nextCell(Language lang, const std::optional<DdaCell>& before, const DdaCell& next,
                     int dims) {
    if (!before)
        return trf(lang,
                   "The walk starts in the cell that holds the ray's entry point (t_enter): %1.",
                   {cellText(next.cell, dims)});
    std::string tmax;
    // Where the comma is the decimal mark the list's separator is not: "tMaxX = 3,25; tMaxY = 4".
    for (int i = 0; i < dims; ++i)
        tmax += std::string(i ? listSeparator(lang) : "") + "tMax" + "XYZ"[i] + " = " +
                formatNumber(before->tMax[i], lang);
    const std::string axes = axesText(next.axes);
    if (axes.size() > 1)
        return trf(lang,
                   "In cell %1 the DDA compares %2: %3 are equal and the smallest, so it steps "
                   "along %4 at once, to %5 (the ray passes through a corner).",
                   {cellText(before->cell, dims), tmax, axesWords(lang, next.axes, "tMax"),
                    axesWords(lang, next.axes), cellText(next.cell, dims)});
    return trf(lang,
               "In cell %1 the DDA compares %2: the smallest is along %3, so it steps in %3 to %4.",
               {cellText(before->cell, dims), tmax, axes, cellText(next.cell, dims)});
}

std::string pickSplit(Language lang, int count, std::uint32_t node, const SplitCandidate& best) {
    const auto n = [&](double v) { return formatNumber(v, lang); };
    const std::string formula = "C_trav + C_isect (" + n(best.pl) + " · " +
                                std::to_string(best.nl) + " + " + n(best.pr) + " · " +
                                std::to_string(best.nr) + ")";
    return trf(lang,
               "Of the %1 candidates of node %2, the cheapest is %3 = %4: NL = %5, NR = %6, cost "
               "%7 = %8.",
               {std::to_string(count), std::to_string(node), axisName(best.axis), n(best.position),
                std::to_string(best.nl), std::to_string(best.nr), formula, n(best.sahCost)});
}

std::string hitOrMiss(Language lang, const PrimitiveTest& test) {
    const std::string prim = std::to_string(test.prim);
    if (test.hit)
        return trf(lang,
                   "The test of primitive %1 finds an intersection at t = %2, inside the ray's "
                   "interval.",
                   {prim, formatNumber(test.t, lang)});
    return trf(lang,
               "The test of primitive %1 fails: no intersection lies inside the ray's interval (a "
               "negative discriminant, an intersection behind the origin or beyond the nearest "
               "one found so far, or a point outside the triangle or segment).",
               {prim});
}

}  // namespace raystep::feedback
