// The first place a student's ray departs from raystep's run of it, explained with the lecture's
// quantities: the tMax comparison of the cell before, the step's sign, the entry cell, a node's
// near child or interval, a cell's list of primitives, the hit.
#include "raystep/assess/divergence.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace raystep::assess_detail {

namespace {

using nlohmann::ordered_json;
using Kind = ReferenceUnit::Kind;

constexpr const char* kAxisNames = "XYZ";
constexpr const char* kAxisLower = "xyz";
}  // namespace

bool sameTime(double a, double b) {
    if (std::isinf(a) || std::isinf(b)) return a == b;
    return std::abs(a - b) <= kTimeTolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

namespace {

std::string num(double v, Language lang) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return formatNumber(v, lang);
}

std::string tuple(const std::array<long long, 3>& c, int dims, Language lang) {
    std::string s = "(";
    for (int i = 0; i < dims; ++i)
        s += (i ? std::string(listSeparator(lang)) : "") + std::to_string(c[i]);
    return s + ")";
}
std::string point(const std::array<double, 3>& p, int dims, Language lang) {
    std::string s = "(";
    for (int i = 0; i < dims; ++i)
        s += (i ? std::string(listSeparator(lang)) : "") + num(p[i], lang);
    return s + ")";
}
std::string tMaxName(int axis) {
    return std::string("tMax") + kAxisNames[axis];
}
std::string axisList(unsigned axes, Language lang) {
    std::string s;
    for (int i = 0; i < 3; ++i)
        if (axes & (1u << i))
            s += (s.empty() ? "" : " " + tr(lang, "and") + " ") + std::string(1, kAxisNames[i]);
    return s;
}
int firstAxis(unsigned axes) {
    for (int i = 0; i < 3; ++i)
        if (axes & (1u << i)) return i;
    return 0;
}

ordered_json cellJson(const std::array<long long, 3>& c, int dims) {
    ordered_json a = ordered_json::array();
    for (int i = 0; i < dims; ++i) a.push_back(c[i]);
    return a;
}
ordered_json timesJson(const std::array<double, 3>& t, int dims) {
    ordered_json a = ordered_json::array();
    for (int i = 0; i < dims; ++i)
        a.push_back(std::isfinite(t[i]) ? ordered_json(t[i]) : ordered_json(nullptr));
    return a;
}

}  // namespace

StudentRun group(const StudentRay& ray) {
    StudentRun run;
    for (const StudentRecord& r : ray.records) {
        switch (r.kind) {
            case StudentRecordKind::Cell:
            case StudentRecordKind::Node:
                run.logsWalk = true;
                run.units.push_back({&r, {}});
                break;
            case StudentRecordKind::Test:
                run.logsTests = true;
                if (run.units.empty()) run.units.push_back({nullptr, {}});
                run.units.back().tests.push_back(&r);
                break;
            case StudentRecordKind::Hit:
            case StudentRecordKind::Miss:
                run.end = &r;
                break;
        }
    }
    return run;
}

namespace {

/// The reference's units without their walk records, when the student logs tests only: one
/// unit holding every test in order.
ReferenceRay flattened(const ReferenceRay& ref) {
    ReferenceRay flat = ref;
    flat.units.assign(1, ReferenceUnit{});
    for (const ReferenceUnit& u : ref.units) {
        auto& f = flat.units[0];
        f.tests.insert(f.tests.end(), u.tests.begin(), u.tests.end());
        f.skipped.insert(f.skipped.end(), u.skipped.begin(), u.skipped.end());
        f.hits.insert(f.hits.end(), u.hits.begin(), u.hits.end());
    }
    return flat;
}

class Comparer {
  public:
    Comparer(const Reference& reference, const StudentRay& ray, const ReferenceRay& ref,
             Language lang, const Logged& logged)
        : refer_(reference), ray_(ray), ref_(ref), lang_(lang), dims_(ray.dims), logged_(logged) {}

    std::optional<Divergence> compare() {
        StudentRun run = group(ray_);
        run.logsWalk = logged_.walk;
        run.logsTests = logged_.tests;
        ReferenceRay flat;
        const ReferenceRay* ref = &ref_;
        if (!run.logsWalk && run.logsTests) {
            flat = flattened(ref_);
            ref = &flat;
        }
        std::vector<StudentUnit>& su = run.units;
        const std::vector<ReferenceUnit>& ru = ref->units;
        int walkIndex = -1;
        const std::size_t n = std::min(su.size(), ru.size());
        for (std::size_t i = 0; i < n; ++i) {
            const StudentUnit& s = su[i];
            const ReferenceUnit& r = ru[i];
            if (s.walk) ++walkIndex;
            if (run.logsWalk && (s.walk != nullptr) != (r.kind != Kind::None)) {
                // Tests where the reference walks first, or the other way round.
                return generic(walkIndex, s.walk ? s.walk->line : s.tests[0]->line,
                               s.walk ? recordName(*s.walk) : "test", r, s);
            }
            if (s.walk) {
                if (auto d = compareWalk(walkIndex, i, *s.walk, ru)) return d;
            }
            if (run.logsTests) {
                if (auto d = compareTests(walkIndex, i, s, *ref)) return d;
            }
        }
        if (run.logsWalk) {
            const int studentWalks = walkCount(su), refWalks = ref->walkCount();
            if (studentWalks < refWalks) return stoppedEarly(su, *ref, run.end);
            if (studentWalks > refWalks) return wentOn(su, *ref);
        }
        if (run.logsTests && !run.logsWalk && su.empty() && !ru.empty() && !ru[0].tests.empty()) {
            Divergence d = base(-1, run.end ? run.end->line : ray_.line, "test");
            d.expected = ordered_json({{"test", ru[0].tests[0]}}).dump();
            d.got = "null";
            d.quantity = "test";
            d.explanation = trf(lang_, "Primitive %1 is tested first; you tested none.",
                                {std::to_string(ru[0].tests[0])});
            return d;
        }
        if (run.end) return compareEnd(walkCount(su) - 1, *run.end, *ref);
        return std::nullopt;
    }

  private:
    const Reference& refer_;
    const StudentRay& ray_;
    const ReferenceRay& ref_;
    Language lang_;
    int dims_;
    Logged logged_;

    static int walkCount(const std::vector<StudentUnit>& su) {
        int n = 0;
        for (const auto& u : su) n += u.walk != nullptr;
        return n;
    }
    static std::string recordName(const StudentRecord& r) {
        switch (r.kind) {
            case StudentRecordKind::Cell:
                return "cell";
            case StudentRecordKind::Node:
                return "node";
            case StudentRecordKind::Test:
                return "test";
            case StudentRecordKind::Hit:
                return "hit";
            case StudentRecordKind::Miss:
                return "miss";
        }
        return "cell";
    }
    Divergence base(int index, int line, const std::string& record) const {
        Divergence d;
        d.index = index;
        d.line = line;
        d.record = record;
        d.expected = d.got = "null";
        return d;
    }
    enum class Form { In, To, After };
    /// "in cell (3, 1)", "to leaf 5", "after node 2": the unit as a sentence takes it, in the
    /// language's own prepositions and articles ("nella cella", "dopo il nodo").
    std::string phrase(const ReferenceUnit& u, Form f) const {
        if (u.kind == Kind::Cell) return cellPhrase(u.cell, f);
        if (u.kind == Kind::None) return tr(lang_, "in the scene");
        const bool leaf = u.node < refer_.nodes().size() && refer_.nodes()[u.node].leaf;
        const std::string x = std::to_string(u.node);
        if (f == Form::In) return trf(lang_, leaf ? "in leaf %1" : "in node %1", {x});
        if (f == Form::To) return trf(lang_, leaf ? "to leaf %1" : "to node %1", {x});
        return trf(lang_, leaf ? "after leaf %1" : "after node %1", {x});
    }
    std::string cellPhrase(const std::array<long long, 3>& c, Form f) const {
        const std::string x = tuple(c, dims_, lang_);
        if (f == Form::In) return trf(lang_, "in cell %1", {x});
        if (f == Form::To) return trf(lang_, "to cell %1", {x});
        return trf(lang_, "after cell %1", {x});
    }
    /// A phrase that opens a sentence: its first letter in capitals (ASCII in every catalogue).
    static std::string capital(std::string s) {
        if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = char(s[0] - 'a' + 'A');
        return s;
    }
    std::string walkJson(const ReferenceUnit& u) const {
        if (u.kind == Kind::Cell) return ordered_json({{"cell", cellJson(u.cell, dims_)}}).dump();
        if (u.kind == Kind::Node) return ordered_json({{"node", u.node}}).dump();
        return "null";
    }
    std::string walkJson(const StudentRecord& r) const {
        if (r.kind == StudentRecordKind::Cell) {
            ordered_json j = {{"cell", cellJson(r.cell, dims_)}};
            if (r.tMax) j["tMax"] = timesJson(*r.tMax, dims_);
            return j.dump();
        }
        return ordered_json({{"node", r.id}}).dump();
    }
    Divergence generic(int index, int line, const std::string& record, const ReferenceUnit& r,
                       const StudentUnit& s) const {
        Divergence d = base(index, line, record);
        d.expected = walkJson(r);
        d.got = s.walk ? walkJson(*s.walk) : "null";
        d.quantity = r.kind == Kind::Node ? "tNear" : "tMax";
        d.explanation = trf(lang_, "Here raystep's run is %1.", {phrase(r, Form::In)});
        return d;
    }

    // ---- cells and nodes ----

    std::optional<Divergence> compareWalk(int index, std::size_t i, const StudentRecord& s,
                                          const std::vector<ReferenceUnit>& ru) const {
        const ReferenceUnit& r = ru[i];
        if (r.kind == Kind::Cell) {
            bool same = s.kind == StudentRecordKind::Cell;
            for (int a = 0; same && a < dims_; ++a) same = s.cell[a] == r.cell[a];
            if (!same) return cellDiverges(index, i, s, ru);
            if (s.tMax) {
                for (int a = 0; a < dims_; ++a)
                    if (!sameTime((*s.tMax)[a], r.tMax[a])) return tMaxDiverges(index, s, r, a);
            }
            return std::nullopt;
        }
        if (s.kind != StudentRecordKind::Node || s.id != r.node)
            return nodeDiverges(index, i, s, ru);
        return std::nullopt;
    }

    std::array<double, 3> entryPoint() const {
        std::array<double, 3> p{};
        for (int a = 0; a < dims_; ++a) p[a] = ray_.origin[a] + ref_.tEnter * ray_.dir[a];
        return p;
    }
    bool insideGrid(const std::array<long long, 3>& c) const {
        if (!refer_.grid()) return true;
        for (int a = 0; a < dims_; ++a)
            if (c[a] < 0 || c[a] >= refer_.grid()->res[a]) return false;
        return true;
    }
    std::string gridSize() const {
        std::string s;
        for (int a = 0; a < dims_; ++a)
            s += (a ? " x " : "") + std::to_string(refer_.grid() ? refer_.grid()->res[a] : 0);
        return s;
    }

    Divergence cellDiverges(int index, std::size_t i, const StudentRecord& s,
                            const std::vector<ReferenceUnit>& ru) const {
        const ReferenceUnit& r = ru[i];
        Divergence d = base(index, s.line, "cell");
        d.expected = walkJson(r);
        d.got = walkJson(s);
        const std::string got = tuple(s.cell, dims_, lang_), want = tuple(r.cell, dims_, lang_);
        if (i == 0 || ru[i - 1].kind != Kind::Cell) {
            d.quantity = "tEnter";
            if (ref_.tEnter > 0)
                d.explanation =
                    trf(lang_,
                        "Your first cell is %1, but the walk starts in %2, the cell "
                        "where the ray enters the grid, at tEnter = %3 (the point %4).",
                        {got, want, num(ref_.tEnter, lang_), point(entryPoint(), dims_, lang_)});
            else
                d.explanation = trf(lang_,
                                    "Your first cell is %1, but the walk starts in %2, the cell "
                                    "that holds the ray's origin %3.",
                                    {got, want, point(ray_.origin, dims_, lang_)});
            return d;
        }
        const ReferenceUnit& prev = ru[i - 1];
        const std::string from = tuple(prev.cell, dims_, lang_);
        unsigned moved = 0;
        bool neighbour = true;
        for (int a = 0; a < dims_; ++a) {
            const long long delta = s.cell[a] - prev.cell[a];
            if (delta) moved |= 1u << a;
            if (delta < -1 || delta > 1) neighbour = false;
        }
        const int winner = firstAxis(r.axes);
        const bool tie = (r.axes & (r.axes - 1)) != 0;
        d.quantity = tMaxName(winner);
        if (moved == 0) {
            d.quantity = "step";
            d.explanation =
                trf(lang_, "You logged %1 again: each step moves to the next cell.", {got});
            return d;
        }
        if (neighbour && (moved & (moved - 1)) == 0) {
            const int a = firstAxis(moved);
            const long long delta = s.cell[a] - prev.cell[a];
            if (ref_.step[a] == 0) {
                d.quantity = tMaxName(a);
                d.explanation = trf(
                    lang_,
                    "From %1 you stepped in %2, but the ray is parallel to %2 (d%3 = 0): it never "
                    "crosses a %2 boundary, %4 is infinite. The walk goes to %5.",
                    {from, std::string(1, kAxisNames[a]), std::string(1, kAxisLower[a]),
                     tMaxName(a), want});
                return d;
            }
            if (delta != ref_.step[a]) {
                d.quantity = std::string("step") + kAxisNames[a];
                d.explanation =
                    trf(lang_, "From %1 you stepped %2 by %3, but d%4 = %5: step%2 = %6.",
                        {from, std::string(1, kAxisNames[a]), delta > 0 ? "+1" : "-1",
                         std::string(1, kAxisLower[a]), num(ray_.dir[a], lang_),
                         ref_.step[a] > 0 ? "+1" : "-1"});
                return d;
            }
            if (tie && (r.axes & moved)) {
                std::string equal;
                for (int b = 0; b < dims_; ++b)
                    if (r.axes & (1u << b)) equal += (equal.empty() ? "" : " = ") + tMaxName(b);
                d.quantity = equal;
                d.explanation =
                    trf(lang_,
                        "%1, %2 = %3: the ray passes exactly through a corner where cells meet and "
                        "only touches %4. Every tied axis steps at once: the next cell is %5.",
                        {capital(cellPhrase(prev.cell, Form::In)), equal,
                         num(prev.tMax[winner], lang_), got, want});
                return d;
            }
            if (!tie) {
                d.explanation = trf(
                    lang_,
                    "%1, %2 = %3 and %4 = %5: %2 < %4, so the ray crosses the next %6 boundary "
                    "first and the next cell is %7; you stepped in %8, to %9.",
                    {capital(cellPhrase(prev.cell, Form::In)), tMaxName(winner),
                     num(prev.tMax[winner], lang_), tMaxName(a), num(prev.tMax[a], lang_),
                     std::string(1, kAxisNames[winner]), want, std::string(1, kAxisNames[a]), got});
                return d;
            }
        }
        if (neighbour && !tie) {
            d.explanation =
                trf(lang_,
                    "From %1 you stepped %2 at once, but %3 = %4 is the smallest: "
                    "only %5 is crossed first, to %6. Several axes step at once only "
                    "at an exact tie.",
                    {from, axisList(moved, lang_), tMaxName(winner), num(prev.tMax[winner], lang_),
                     std::string(1, kAxisNames[winner]), want});
            return d;
        }
        if (!insideGrid(s.cell)) {
            d.explanation = trf(lang_, "%1 is outside the grid (%2 cells); the walk goes to %3.",
                                {got, gridSize(), want});
            return d;
        }
        d.explanation = trf(lang_,
                            "From %1 you went to %2, which is not the next cell: a step crosses "
                            "the nearest boundary, the smallest tMax (%3 = %4), to %5.",
                            {from, got, tMaxName(winner), num(prev.tMax[winner], lang_), want});
        return d;
    }

    Divergence tMaxDiverges(int index, const StudentRecord& s, const ReferenceUnit& r,
                            int a) const {
        Divergence d = base(index, s.line, "tMax");
        d.expected =
            ordered_json({{"cell", cellJson(r.cell, dims_)}, {"tMax", timesJson(r.tMax, dims_)}})
                .dump();
        d.got = walkJson(s);
        d.quantity = tMaxName(a);
        const std::string cell = capital(cellPhrase(r.cell, Form::In));
        const std::string yours = num((*s.tMax)[a], lang_);
        if (ref_.step[a] == 0) {
            d.explanation = trf(lang_,
                                "%1, your %2 is %3, but the ray is parallel to %4 (d%5 = 0): %2 is "
                                "infinite (null).",
                                {cell, tMaxName(a), yours, std::string(1, kAxisNames[a]),
                                 std::string(1, kAxisLower[a])});
            return d;
        }
        double boundary = 0.0;
        if (refer_.grid()) {
            const auto& g = *refer_.grid();
            const long long k = ref_.step[a] > 0 ? r.cell[a] + 1 : r.cell[a];
            boundary = g.lo[a] + double(k) * (g.hi[a] - g.lo[a]) / g.res[a];
        } else {
            boundary = ray_.origin[a] + r.tMax[a] * ray_.dir[a];
        }
        d.explanation =
            trf(lang_,
                "%1, your %2 is %3, but the next %4 boundary ahead (step%4 = %5) is %6 = %7, "
                "crossed at t = (%7 - %8) / %9",
                {cell, tMaxName(a), yours, std::string(1, kAxisNames[a]),
                 ref_.step[a] > 0 ? "+1" : "-1", std::string(1, kAxisLower[a]),
                 num(boundary, lang_), num(ray_.origin[a], lang_), num(ray_.dir[a], lang_)});
        d.explanation += " = " + num(r.tMax[a], lang_) + ".";
        return d;
    }

    const NodeSkip* skipOf(std::uint32_t node) const {
        for (const NodeSkip& s : ref_.skips)
            if (s.node == node) return &s;
        return nullptr;
    }

    Divergence nodeDiverges(int index, std::size_t i, const StudentRecord& s,
                            const std::vector<ReferenceUnit>& ru) const {
        const ReferenceUnit& r = ru[i];
        Divergence d = base(index, s.line, "node");
        d.expected = walkJson(r);
        d.got = walkJson(s);
        d.quantity = "tNear";
        const auto& nodes = refer_.nodes();
        const std::string want = std::to_string(r.node), got = std::to_string(s.id);
        if (s.id < nodes.size() && r.node < nodes.size() &&
            nodes[s.id].parent == nodes[r.node].parent && nodes[r.node].parent != kNoId) {
            const ReferenceNode& p = nodes[nodes[r.node].parent];
            const std::string parent = std::to_string(nodes[r.node].parent);
            if (p.split && p.axis >= 0) {
                d.quantity = "split";
                const std::string axis(1, kAxisLower[p.axis]);
                d.explanation = trf(lang_,
                                    "Node %1 is split at %2 = %3, and the ray comes from the side "
                                    "of node %4 (its origin has %2 = %5): the near child, entered "
                                    "first; you entered node %6 first.",
                                    {parent, axis, num(*p.split, lang_), want,
                                     num(ray_.origin[p.axis], lang_), got});
            } else {
                d.explanation = trf(lang_,
                                    "Node %1's near child, on the side the ray comes from, is "
                                    "node %2, entered first; you entered node %3 first.",
                                    {parent, want, got});
            }
            return d;
        }
        if (const NodeSkip* skip = skipOf(s.id)) {
            if (ref_.hit && skip->tNear > ref_.t && std::isfinite(skip->tNear)) {
                d.explanation = trf(lang_,
                                    "Node %1 is never entered: its interval starts at tNear = %2, "
                                    "beyond the nearest hit, t = %3. The traversal enters node %4 "
                                    "here.",
                                    {got, num(skip->tNear, lang_), num(ref_.t, lang_), want});
            } else {
                d.explanation = trf(lang_,
                                    "The ray does not pass through node %1 within its [tNear, "
                                    "tFar]: the traversal skips it and enters node %2 here.",
                                    {got, want});
            }
            return d;
        }
        d.explanation = trf(lang_,
                            "The traversal enters node %1 here (tNear = %2, tFar = %3); you "
                            "entered node %4.",
                            {want, num(r.tNear, lang_), num(r.tFar, lang_), got});
        return d;
    }

    // ---- the walk's end ----

    Divergence stoppedEarly(const std::vector<StudentUnit>& su, const ReferenceRay& ref,
                            const StudentRecord* end) const {
        int m = 0;
        const StudentRecord* last = nullptr;
        for (const auto& u : su)
            if (u.walk) ++m, last = u.walk;
        // The reference's unit m among its walk units.
        std::size_t at = 0;
        for (int k = 0; at < ref.units.size(); ++at)
            if (ref.units[at].kind != Kind::None && k++ == m) break;
        const ReferenceUnit& next = ref.units[at];
        Divergence d = base(m, end ? end->line : (last ? last->line : ray_.line), "end");
        d.expected = walkJson(next);
        d.got = end ? (end->kind == StudentRecordKind::Hit
                           ? ordered_json({{"hit", {{"prim", end->id}, {"t", end->t}}}}).dump()
                           : ordered_json({{"miss", true}}).dump())
                    : "null";
        if (m == 0) {
            d.quantity = ref.cells ? "tEnter" : "tNear";
            d.explanation =
                ref.cells && ref.tEnter > 0
                    ? trf(lang_,
                          "You logged no cell, but the ray enters the grid at tEnter = %1, %2.",
                          {num(ref.tEnter, lang_), phrase(next, Form::In)})
                : ref.cells
                    ? trf(lang_,
                          "You logged no cell, but the ray starts inside the grid, %1, which "
                          "holds its origin.",
                          {phrase(next, Form::In)})
                    : trf(lang_,
                          "You logged no node, but the traversal starts "
                          "at node %1 (the root).",
                          {std::to_string(next.node)});
            return d;
        }
        const ReferenceUnit& here = ref.units[at - 1];
        const bool hitBeyond = end && end->kind == StudentRecordKind::Hit && end->t > here.tFar;
        if (ref.cells) {
            int axis = 0;
            for (int a = 1; a < dims_; ++a)
                if (here.tMax[a] < here.tMax[axis]) axis = a;
            d.quantity = tMaxName(axis);
            if (hitBeyond)
                d.explanation =
                    trf(lang_,
                        "You stopped %1 with the hit of primitive %2 at t = %3, but that hit lies "
                        "beyond this cell's exit, t = %4 (%5): a primitive in a later cell may be "
                        "nearer, so the walk goes on %6.",
                        {phrase(here, Form::In), std::to_string(end->id), num(end->t, lang_),
                         num(here.tFar, lang_), tMaxName(axis), phrase(next, Form::To)});
            else
                d.explanation =
                    trf(lang_,
                        "You stopped %1, but the ray goes on: it leaves this cell at t = %2 (%3), "
                        "before the grid's exit at t = %4, and the walk goes on %5.",
                        {phrase(here, Form::In), num(here.tFar, lang_), tMaxName(axis),
                         num(ref.tGridExit, lang_), phrase(next, Form::To)});
            return d;
        }
        d.quantity = hitBeyond ? "tFar" : "tNear";
        if (hitBeyond)
            d.explanation =
                trf(lang_,
                    "You stopped %1 with the hit of primitive %2 at t = %3, but that hit lies "
                    "beyond the leaf's tFar = %4: a nearer hit may lie in a node still on the "
                    "stack, and the traversal goes on to node %5 (tNear = %6).",
                    {phrase(here, Form::After), std::to_string(end->id), num(end->t, lang_),
                     num(here.tFar, lang_), std::to_string(next.node), num(next.tNear, lang_)});
        else
            d.explanation =
                trf(lang_,
                    "You stopped %1, but the traversal goes on to node %2 (tNear = %3, tFar = %4).",
                    {phrase(here, Form::After), std::to_string(next.node), num(next.tNear, lang_),
                     num(next.tFar, lang_)});
        return d;
    }

    Divergence wentOn(const std::vector<StudentUnit>& su, const ReferenceRay& ref) const {
        const int n = ref.walkCount();
        const StudentRecord* extra = nullptr;
        for (int k = 0, i = 0; i < int(su.size()); ++i)
            if (su[i].walk && k++ == n) {
                extra = su[i].walk;
                break;
            }
        Divergence d = base(n, extra->line, recordName(*extra));
        d.got = walkJson(*extra);
        const ReferenceUnit* last = nullptr;
        for (const auto& u : ref.units)
            if (u.kind != Kind::None) last = &u;
        if (ref.cells) {
            const std::string got = tuple(extra->cell, dims_, lang_);
            if (!last) {
                d.quantity = "tEnter";
                d.explanation = trf(lang_,
                                    "The ray misses the grid: it never enters the grid's box, so "
                                    "it visits no cell; you logged %1.",
                                    {got});
            } else if (ref.hit && ref.t < last->tFar) {
                d.quantity = "tMax";
                d.explanation =
                    trf(lang_,
                        "The walk ends %1: the hit at t = %2 lies before this cell's exit, t = %3, "
                        "so no later cell can hold a nearer one; you went on to %4.",
                        {phrase(*last, Form::In), num(ref.t, lang_), num(last->tFar, lang_), got});
            } else {
                d.quantity = "tGridExit";
                d.explanation =
                    trf(lang_, "The ray leaves the grid %1, at t = %2; you went on to %3%4.",
                        {phrase(*last, Form::After), num(ref.tGridExit, lang_), got,
                         insideGrid(extra->cell)
                             ? ""
                             : trf(lang_, ", outside the grid (%1 cells)", {gridSize()})});
            }
            return d;
        }
        d.quantity = "tNear";
        if (!last)
            d.explanation = trf(lang_,
                                "The ray misses the tree's box: it enters no node; you "
                                "entered node %1.",
                                {std::to_string(extra->id)});
        else if (ref.hit)
            d.explanation =
                trf(lang_,
                    "The traversal ends %1: the nearest hit, t = %2, lies before every node still "
                    "on the stack; you entered node %3.",
                    {phrase(*last, Form::After), num(ref.t, lang_), std::to_string(extra->id)});
        else
            d.explanation = trf(lang_, "The traversal ends %1; you entered node %2.",
                                {phrase(*last, Form::After), std::to_string(extra->id)});
        return d;
    }

    // ---- tests and the hit ----

    std::optional<Divergence> compareTests(int index, std::size_t i, const StudentUnit& s,
                                           const ReferenceRay& ref) const {
        const ReferenceUnit& r = ref.units[i];
        const std::set<std::uint32_t> want(r.tests.begin(), r.tests.end());
        std::set<std::uint32_t> seen;
        for (const StudentRecord* t : s.tests) {
            if (want.count(t->id) && !seen.count(t->id)) {
                seen.insert(t->id);
                continue;
            }
            Divergence d = base(index, t->line, "test");
            d.got = ordered_json({{"test", t->id}}).dump();
            const std::string prim = std::to_string(t->id);
            // Tested before by this ray: in an earlier unit, or twice here.
            std::string earlier;
            for (std::size_t k = 0; k < i && earlier.empty(); ++k)
                for (std::uint32_t p : ref.units[k].tests)
                    if (p == t->id) earlier = phrase(ref.units[k], Form::In);
            if (!earlier.empty() || seen.count(t->id)) {
                d.quantity = "mailbox";
                d.explanation = trf(lang_,
                                    "%1, you tested primitive %2 again: this ray already tested it "
                                    "%3, and the mailbox skips it.",
                                    {capital(phrase(r, Form::In)), prim,
                                     earlier.empty() ? phrase(r, Form::In) : earlier});
            } else {
                d.quantity = r.kind == Kind::Cell ? "cell" : "leaf";
                d.explanation =
                    trf(lang_, "%1, you tested primitive %2, which is not listed there.",
                        {capital(phrase(r, Form::In)), prim});
            }
            return d;
        }
        for (std::uint32_t p : r.tests) {
            if (seen.count(p)) continue;
            Divergence d = base(index, s.walk ? s.walk->line : ray_.line, "test");
            d.expected = ordered_json({{"test", p}}).dump();
            d.quantity = r.kind == Kind::Cell ? "cell" : "leaf";
            d.explanation = trf(lang_,
                                "%1, primitive %2 is listed and not yet tested by this ray: it is "
                                "tested here, and you did not test it.",
                                {capital(phrase(r, Form::In)), std::to_string(p)});
            return d;
        }
        return std::nullopt;
    }

    std::optional<Divergence> compareEnd(int index, const StudentRecord& end,
                                         const ReferenceRay& ref) const {
        const bool studentHit = end.kind == StudentRecordKind::Hit;
        if (studentHit == ref.hit && (!ref.hit || (end.id == ref.prim && sameTime(end.t, ref.t))))
            return std::nullopt;
        Divergence d = base(index, end.line, studentHit ? "hit" : "miss");
        d.expected = ref.hit ? ordered_json({{"hit", {{"prim", ref.prim}, {"t", ref.t}}}}).dump()
                             : ordered_json({{"miss", true}}).dump();
        d.got = studentHit ? ordered_json({{"hit", {{"prim", end.id}, {"t", end.t}}}}).dump()
                           : ordered_json({{"miss", true}}).dump();
        d.quantity = "t";
        if (!ref.hit)
            d.explanation = trf(lang_, "The ray hits nothing; you report primitive %1 at t = %2.",
                                {std::to_string(end.id), num(end.t, lang_)});
        else if (!studentHit)
            d.explanation = trf(lang_, "The ray hits primitive %1 at t = %2; you report a miss.",
                                {std::to_string(ref.prim), num(ref.t, lang_)});
        else if (end.id != ref.prim)
            d.explanation = trf(lang_,
                                "The nearest hit is primitive %1 at t = %2; you report primitive "
                                "%3 at t = %4.",
                                {std::to_string(ref.prim), num(ref.t, lang_),
                                 std::to_string(end.id), num(end.t, lang_)});
        else
            d.explanation = trf(lang_, "Primitive %1 is hit at t = %2; you report t = %3.",
                                {std::to_string(ref.prim), num(ref.t, lang_), num(end.t, lang_)});
        return d;
    }
};

}  // namespace

std::optional<Divergence> firstDivergence(const Reference& reference, const StudentRay& ray,
                                          const ReferenceRay& ref, Language lang,
                                          const Logged& logged) {
    return Comparer(reference, ray, ref, lang, logged).compare();
}

}  // namespace raystep::assess_detail
