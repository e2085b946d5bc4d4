#include "raystep/assess/assess.h"

#include "raystep/assess/divergence.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace raystep {

namespace {

using nlohmann::ordered_json;
using Kind = ReferenceUnit::Kind;
using namespace assess_detail;

// ---- recognising a mistake ----

/// How many of the student's cells (with their tMax where logged) agree with `walk` from the
/// start; past both ends counts as one more (a whole match beats a long prefix).
template <int N>
int agreement(const std::vector<const StudentRecord*>& cells,
              const std::vector<WalkCell<N>>& walk) {
    std::size_t k = 0;
    for (; k < cells.size() && k < walk.size(); ++k) {
        bool same = true;
        for (int a = 0; a < N && same; ++a) same = cells[k]->cell[a] == walk[k].cell[a];
        if (same && cells[k]->tMax)
            for (int a = 0; a < N && same; ++a) {
                // A student's null (read as +inf) stands for any tMax JSON cannot hold: the
                // variant's -inf (d = 0 divided) or NaN (-inf + inf) too.
                const double st = (*cells[k]->tMax)[a], w = walk[k].tMax[a];
                same = std::isinf(st) && st > 0 ? !std::isfinite(w) : sameTime(st, w);
            }
        if (!same) break;
    }
    return int(k) + (k == cells.size() && k == walk.size() ? 1 : 0);
}

template <int N>
std::optional<Mistake> ddaMistake(const GridSpec<3, double>& grid3, const StudentRay& ray,
                                  const std::vector<const StudentRecord*>& cells, int diverged) {
    const auto [grid, o, d] = assess_detail::onGrid<N>(grid3, ray);
    int cap = N;
    for (int a = 0; a < N; ++a) cap += grid.res[a];
    cap = std::max(cap, int(cells.size())) + 1;
    std::optional<Mistake> best;
    int bestLength = diverged;  // a variant must agree beyond the reference's divergence
    for (const MistakeInfo& info : mistakes()) {
        if (!info.dda) continue;
        for (TieRule rule : {TieRule::LastAxis, TieRule::FirstAxis}) {
            if (rule == TieRule::FirstAxis && info.mistake != Mistake::TieOneAxis) continue;
            const auto walk = ddaWithMistake<N>(grid, o, d, info.mistake, cap, rule);
            const int length = agreement<N>(cells, walk);
            if (length > bestLength) bestLength = length, best = info.mistake;
        }
    }
    return best;
}

std::optional<Mistake> recognise(const Reference& reference, const StudentRay& ray,
                                 const ReferenceRay& ref, const Divergence& d) {
    const StudentRun run = group(ray);
    if (d.record == "test" && d.quantity == "mailbox") return Mistake::NoMailbox;
    // Stopping at the first unit whose tests hit: the reference cut there.
    if (run.logsWalk && !ref.units.empty()) {
        std::size_t first = ref.units.size();
        for (std::size_t i = 0; i < ref.units.size(); ++i)
            if (!ref.units[i].hits.empty()) {
                first = i;
                break;
            }
        int walksToFirst = 0;
        for (std::size_t i = 0; i <= first && i < ref.units.size(); ++i)
            walksToFirst += ref.units[i].kind != Kind::None;
        int studentWalks = 0;
        for (const auto& u : run.units) studentWalks += u.walk != nullptr;
        if (first < ref.units.size() && walksToFirst < ref.walkCount() &&
            studentWalks == walksToFirst && d.index >= walksToFirst - 1) {
            const auto& hit = ref.units[first].hits.back();
            const bool endMatches =
                !run.end || (run.end->kind == StudentRecordKind::Hit && run.end->id == hit.first);
            if (endMatches) return ref.cells ? Mistake::FirstHitInCell : Mistake::FirstHitInTree;
        }
    }
    if (!ref.cells || !reference.grid() || !run.logsWalk) return std::nullopt;
    std::vector<const StudentRecord*> cells;
    for (const auto& u : run.units)
        if (u.walk) cells.push_back(u.walk);
    const int diverged = std::max(d.index, 0);
    return ray.dims == 2 ? ddaMistake<2>(*reference.grid(), ray, cells, diverged)
                         : ddaMistake<3>(*reference.grid(), ray, cells, diverged);
}

}  // namespace

int Assessment::passed() const {
    int n = 0;
    for (const auto& r : rays) n += r.passed;
    return n;
}
double Assessment::score() const {
    return rays.empty() ? 0.0 : double(passed()) / double(rays.size());
}

Assessment assess(const StudentTrace& trace, const Reference& reference, Language lang) {
    Assessment a;
    a.file = trace.file;
    // A bare walk has nothing but its cells to log: they are always checked.
    Logged logged;
    logged.walk = reference.bare();
    for (const StudentRay& ray : trace.rays)
        for (const StudentRecord& r : ray.records) {
            logged.walk = logged.walk || r.kind == StudentRecordKind::Cell ||
                          r.kind == StudentRecordKind::Node;
            logged.tests = logged.tests || r.kind == StudentRecordKind::Test;
        }
    for (std::size_t i = 0; i < trace.rays.size(); ++i) {
        const StudentRay& ray = trace.rays[i];
        RayVerdict v;
        v.ray = int(i);
        v.line = ray.line;
        v.reference = reference.run(ray);
        for (const auto& r : ray.records)
            v.walkRecords += r.kind == StudentRecordKind::Cell || r.kind == StudentRecordKind::Node;
        v.divergence = firstDivergence(reference, ray, v.reference, lang, logged);
        v.passed = !v.divergence;
        if (v.divergence) v.mistake = recognise(reference, ray, v.reference, *v.divergence);
        a.rays.push_back(std::move(v));
    }
    return a;
}

std::string divergencePlace(const Divergence& d, Language lang) {
    const std::string i = std::to_string(std::max(d.index, 0));
    if (d.record == "cell") return trf(lang, "cell record %1", {i});
    if (d.record == "node") return trf(lang, "node record %1", {i});
    if (d.record == "tMax") return trf(lang, "the tMax of cell record %1", {i});
    if (d.record == "test") return tr(lang, "a primitive test");
    if (d.record == "end") return tr(lang, "the end of the walk");
    return tr(lang, "the hit or miss");
}

std::string assessmentJson(const Assessment& a, Language lang) {
    // One ray a line: a class's file stays readable, and a diff points at the ray.
    ordered_json head;
    head["score"] = a.score();
    head["rays_passed"] = a.passed();
    head["rays_total"] = a.rays.size();
    head["passed"] = a.allPassed();
    std::string out = "{\n";
    for (const auto& [k, v] : head.items())
        out += "  " + ordered_json(k).dump() + ": " + v.dump() + ",\n";
    out += "  \"rays\": [";
    for (std::size_t i = 0; i < a.rays.size(); ++i) {
        const RayVerdict& v = a.rays[i];
        ordered_json r;
        r["ray"] = v.ray;
        r["line"] = v.line;
        r["passed"] = v.passed;
        r["walk_records"] = v.walkRecords;
        if (v.divergence) {
            const Divergence& d = *v.divergence;
            r["first_divergence"] = {{"index", d.index},
                                     {"line", d.line},
                                     {"record", d.record},
                                     {"expected", ordered_json::parse(d.expected)},
                                     {"got", ordered_json::parse(d.got)},
                                     {"quantity", d.quantity},
                                     {"explanation", d.explanation}};
        } else {
            r["first_divergence"] = nullptr;
        }
        if (v.mistake) {
            const MistakeInfo& info = mistakeInfo(*v.mistake);
            // i18n: the descriptions are marked in mistakes.cpp
            const std::string description = tr(lang, info.description);
            r["mistake"] = {{"name", info.name}, {"description", description}};
        } else {
            r["mistake"] = nullptr;
        }
        out += std::string(i ? "," : "") + "\n    " + r.dump();
    }
    return out + (a.rays.empty() ? "]\n}\n" : "\n  ]\n}\n");
}

std::string assessmentText(const Assessment& a, Language lang) {
    std::string out;
    for (const RayVerdict& v : a.rays) {
        if (v.passed) {
            out +=
                trf(lang,
                    v.reference.cells ? "ray %1: passed (%2 cells)" : "ray %1: passed (%2 nodes)",
                    {std::to_string(v.ray), std::to_string(v.walkRecords)}) +
                "\n";
            continue;
        }
        const Divergence& d = *v.divergence;
        out += trf(lang, "ray %1: failed at line %2, %3",
                   {std::to_string(v.ray), std::to_string(d.line), divergencePlace(d, lang)}) +
               "\n  " + d.explanation + "\n";
        if (v.mistake)
            out += "  " +
                   trf(lang, "This is the known mistake \"%1\": %2.",
                       {std::string(mistakeInfo(*v.mistake).name),
                        // i18n: the descriptions are marked in mistakes.cpp
                        tr(lang, mistakeInfo(*v.mistake).description)}) +
                   "\n";
    }
    out += trf(lang, "score: %1/%2 rays passed",
               {std::to_string(a.passed()), std::to_string(a.rays.size())}) +
           "\n";
    return out;
}

}  // namespace raystep
