// The sentences that explain a reference answer, English beside Italian, so a translator sees
// both at once: one function per exercise kind (course/feedback_text.h).
#include "feedback_text.h"

#include "course/lesson_trace.h"

#include "raystep/base/format.h"
#include "raystep/trace/event_text.h"

#include <cmath>

namespace raystep::feedback {

namespace {

/// Two-language feedback: picks the language's text.
std::string tr2(Language lang, const std::string& en, const std::string& it) {
    return lang == Language::It ? it : en;
}

}  // namespace

const char* axisName(int a) {
    return a == 0 ? "x" : a == 1 ? "y" : "z";
}

std::string nextCell(Language lang, const std::optional<DdaCell>& before, const DdaCell& next,
                     int dims) {
    if (!before)
        return tr2(lang,
                   "The walk starts in the cell that contains the ray's entry point (t_enter): " +
                       cellText(next.cell, dims) + ".",
                   "La visita comincia dalla cella che contiene il punto d'ingresso del raggio "
                   "(t_enter): " +
                       cellText(next.cell, dims) + ".");
    std::string tmax;
    for (int i = 0; i < dims; ++i)
        tmax +=
            std::string(i ? ", " : "") + "tMax" + "XYZ"[i] + " = " + formatNumber(before->tMax[i]);
    const std::string axes = axesText(next.axes);
    return tr2(lang,
               "In cell " + cellText(before->cell, dims) + " the DDA compares " + tmax +
                   ": the smallest is along " + axes + ", so it steps in " + axes + " to " +
                   cellText(next.cell, dims) +
                   (axes.size() > 1 ? " (a tie: the ray passes through a corner)" : "") + ".",
               "Nella cella " + cellText(before->cell, dims) + " il DDA confronta " + tmax +
                   ": il minore è lungo " + axes + ", quindi avanza in " + axes + " fino a " +
                   cellText(next.cell, dims) +
                   (axes.size() > 1 ? " (pareggio: il raggio passa per un vertice)" : "") + ".");
}

std::string value(Language lang, Quantity q, double v, const std::string& source) {
    return tr2(lang,
               "The trace records " + std::string(quantityName(q)) + " = " + formatNumber(v) +
                   " in the event " + source + ".",
               "La traccia registra " + std::string(quantityName(q)) + " = " + formatNumber(v) +
                   " nell'evento " + source + ".");
}

std::string pickSplit(Language lang, int count, std::uint32_t node, const SplitCandidate& best) {
    const std::string formula = "C_trav + C_isect (" + formatNumber(best.pl) + " x " +
                                std::to_string(best.nl) + " + " + formatNumber(best.pr) + " x " +
                                std::to_string(best.nr) + ")";
    return tr2(
        lang,
        "Of the " + std::to_string(count) + " candidates of node " + std::to_string(node) +
            ", the cheapest is " + axisName(best.axis) + " = " + formatNumber(best.position) +
            ": NL = " + std::to_string(best.nl) + ", NR = " + std::to_string(best.nr) + ", cost " +
            formula + " = " + formatNumber(best.sahCost) + ".",
        "Tra i " + std::to_string(count) + " candidati del nodo " + std::to_string(node) +
            ", il meno costoso è " + axisName(best.axis) + " = " + formatNumber(best.position) +
            ": NL = " + std::to_string(best.nl) + ", NR = " + std::to_string(best.nr) + ", costo " +
            formula + " = " + formatNumber(best.sahCost) + ".");
}

std::string count(Language lang, std::size_t n, const std::string& what, const ReplayPosition& from,
                  const ReplayPosition& to) {
    return tr2(lang,
               "The trace holds " + std::to_string(n) + " events " + what + " from " +
                   describePosition(from) + " to " + describePosition(to) + ".",
               "La traccia contiene " + std::to_string(n) + " eventi " + what + " tra " +
                   describePosition(from, Language::It) + " e " +
                   describePosition(to, Language::It) + ".");
}

std::string hitOrMiss(Language lang, const PrimitiveTest& test) {
    const std::string prim = std::to_string(test.prim);
    if (test.hit)
        return tr2(lang,
                   "The test of primitive " + prim + " hits at t = " + formatNumber(test.t) +
                       " (the smallest root inside the ray's interval).",
                   "Il test della primitiva " + prim + " colpisce a t = " + formatNumber(test.t) +
                       " (la radice più piccola nell'intervallo del raggio).");
    return tr2(lang,
               "The test of primitive " + prim +
                   " misses: no root lies inside the ray's interval (a negative discriminant, a "
                   "root behind the origin or beyond the nearest hit, or a point outside the "
                   "triangle or segment).",
               "Il test della primitiva " + prim +
                   " fallisce: nessuna radice cade nell'intervallo del raggio (discriminante "
                   "negativo, radice dietro l'origine o oltre il colpo più vicino, o punto fuori "
                   "dal triangolo o segmento).");
}

}  // namespace raystep::feedback
