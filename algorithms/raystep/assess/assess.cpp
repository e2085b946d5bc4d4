#include "raystep/assess/assess.h"

#include "raystep/accel/outline.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace raystep {

namespace {

using nlohmann::ordered_json;
using Kind = ReferenceUnit::Kind;

constexpr const char* kAxisNames = "XYZ";
constexpr const char* kAxisLower = "xyz";
/// A student's double arithmetic in another order: times agree to this relative tolerance.
constexpr double kTimeTolerance = 1e-9;

bool sameTime(double a, double b) {
    if (std::isinf(a) || std::isinf(b)) return a == b;
    return std::abs(a - b) <= kTimeTolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

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

/// The student's records of one ray, unit by unit as the reference's.
struct StudentUnit {
    const StudentRecord* walk = nullptr;  // the cell or node (nullptr: tests before any)
    std::vector<const StudentRecord*> tests;
};
struct StudentRun {
    std::vector<StudentUnit> units;
    const StudentRecord* end = nullptr;  // the hit or miss
    bool logsWalk = false, logsTests = false;
};
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

/// What a student's file logs: its cells or nodes, its tests (what it does not log is not
/// checked).
struct Logged {
    bool walk = false, tests = false;
};

class Comparer {
  public:
    /// `logged`: what the file logs (on any of its rays), so a ray that logs no cell is checked
    /// for none when the others log theirs.
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
                    "%1, %2 = %3 and %4 = %5: %2 < %4, so the ray crosses the next %6 boundary first and the next cell is %7; you stepped in %8, to %9.",
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
                "crossed at t = (%7 - %8) / %9.",
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
                ref.cells
                    ? trf(lang_,
                          "You logged no cell, but the ray enters the grid at tEnter = %1, %2.",
                          {num(ref.tEnter, lang_), phrase(next, Form::In)})
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
            for (int a = 0; a < N && same; ++a)
                same = sameTime((*cells[k]->tMax)[a], walk[k].tMax[a]);
        if (!same) break;
    }
    return int(k) + (k == cells.size() && k == walk.size() ? 1 : 0);
}

template <int N>
std::optional<Mistake> ddaMistake(const GridSpec<3, double>& grid3, const StudentRay& ray,
                                  const std::vector<const StudentRecord*>& cells, int diverged) {
    GridSpec<N, double> grid;
    VecN<N, double> o, d;
    for (int a = 0; a < N; ++a) {
        grid.lo[a] = grid3.lo[a];
        grid.hi[a] = grid3.hi[a];
        grid.res[a] = grid3.res[a];
        o[a] = ray.origin[a];
        d[a] = ray.dir[a];
    }
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

// ---- the reference runs ----

template <int N>
ReferenceRay ddaReference(const GridSpec<3, double>& grid3, const StudentRay& ray) {
    GridSpec<N, double> grid;
    VecN<N, double> o, d;
    for (int a = 0; a < N; ++a) {
        grid.lo[a] = grid3.lo[a];
        grid.hi[a] = grid3.hi[a];
        grid.res[a] = grid3.res[a];
        o[a] = ray.origin[a];
        d[a] = ray.dir[a];
    }
    ReferenceRay ref;
    ref.dims = N;
    ref.cells = true;
    Dda<N, double> dda(grid, o, d);
    for (int a = 0; a < N; ++a) {
        ref.step[a] = dda.step()[a];
        ref.tDelta[a] = dda.tDelta()[a];
    }
    ref.entersGrid = dda.valid();
    ref.tEnter = dda.tEnter();
    ref.tGridExit = dda.tGridExit();
    for (bool more = dda.valid(); more; more = dda.next()) {
        ReferenceUnit u;
        u.kind = Kind::Cell;
        for (int a = 0; a < N; ++a) {
            u.cell[a] = dda.cell()[a];
            u.tMax[a] = dda.tMax()[a];
        }
        u.axes = dda.axesTaken();
        u.tNear = dda.tEnter();
        u.tFar = dda.tCellExit();
        ref.units.push_back(u);
    }
    return ref;
}

ReferenceRay fromLog(const EventLog& log, int dims) {
    ReferenceRay ref;
    ref.dims = dims;
    ref.cells = false;
    const auto unit = [&]() -> ReferenceUnit& {
        if (ref.units.empty()) ref.units.push_back({});
        return ref.units.back();
    };
    for (const Event& e : log.events()) {
        if (const auto* s = std::get_if<DdaSetup>(&e)) {
            ref.cells = true;
            ref.entersGrid = true;
            for (int a = 0; a < dims; ++a) {
                ref.step[a] = s->step[a];
                ref.tDelta[a] = s->tDelta[a];
            }
            ref.tEnter = s->tEnter;
            ref.tGridExit = s->tGridExit;
        } else if (const auto* c = std::get_if<DdaCell>(&e)) {
            ref.cells = true;
            ReferenceUnit u;
            u.kind = Kind::Cell;
            for (int a = 0; a < dims; ++a) {
                u.cell[a] = c->cell[a];
                u.tMax[a] = c->tMax[a];
            }
            u.axes = c->axes;
            u.tNear = ref.units.empty() || ref.units.back().kind != Kind::Cell
                          ? ref.tEnter
                          : ref.units.back().tFar;
            u.tFar = ref.tGridExit;
            for (int a = 0; a < dims; ++a) u.tFar = std::min(u.tFar, u.tMax[a]);
            ref.units.push_back(u);
        } else if (const auto* n = std::get_if<NodeEnter>(&e)) {
            ReferenceUnit u;
            u.kind = Kind::Node;
            u.node = n->node;
            u.tNear = n->tNear;
            u.tFar = n->tFar;
            ref.units.push_back(u);
        } else if (const auto* k = std::get_if<NodeSkip>(&e)) {
            ref.skips.push_back(*k);
        } else if (const auto* t = std::get_if<PrimitiveTest>(&e)) {
            unit().tests.push_back(t->prim);
            if (t->hit) unit().hits.push_back({t->prim, t->t});
        } else if (const auto* m = std::get_if<MailboxSkip>(&e)) {
            unit().skipped.push_back(m->prim);
        } else if (const auto* h = std::get_if<RayHit>(&e)) {
            ref.hit = true;
            ref.prim = h->prim;
            ref.t = h->t;
        }
    }
    return ref;
}

template <int N>
std::vector<ReferenceNode> treeNodes(const StructureOutline<N>& o) {
    std::vector<ReferenceNode> nodes(o.nodes.size());
    for (std::size_t i = 0; i < o.nodes.size(); ++i) {
        const auto& n = o.nodes[i];
        nodes[i].parent = n.parent;
        nodes[i].children = n.children;
        nodes[i].axis = n.axis;
        nodes[i].leaf = n.leaf;
        if (n.plane) nodes[i].split = o.planes[*n.plane].position;
    }
    return nodes;
}

template <int N>
GridSpec<3, double> widen(const GridSpec<N, double>& g) {
    GridSpec<3, double> w;
    for (int a = 0; a < N; ++a) {
        w.lo[a] = g.lo[a];
        w.hi[a] = g.hi[a];
        w.res[a] = g.res[a];
    }
    return w;
}

}  // namespace

int ReferenceRay::walkCount() const {
    int n = 0;
    for (const auto& u : units) n += u.kind != ReferenceUnit::Kind::None;
    return n;
}

Reference Reference::dda(const GridSpec<3, double>& grid, int dims) {
    Reference r;
    r.dims_ = dims;
    r.kind_ = AccelKind::Grid;
    r.grid_ = grid;
    return r;
}

Reference Reference::structure(const AnyStructure& structure, AccelKind kind) {
    Reference r;
    r.structure_ = &structure;
    r.kind_ = kind;
    if (structure.in2D) {
        r.dims_ = 2;
        const auto o = outline(*structure.in2D);
        r.nodes_ = treeNodes(o);
        if (o.grid) r.grid_ = widen(o.grid->spec);
    } else {
        r.dims_ = 3;
        const auto o = outline(*structure.in3D);
        r.nodes_ = treeNodes(o);
        if (o.grid) r.grid_ = widen(o.grid->spec);
    }
    return r;
}

EventLog Reference::record(const StudentRay& ray) const {
    EventLog log;
    if (!structure_) return log;
    if (structure_->in2D) {
        Ray2 r;
        r.origin = {ray.origin[0], ray.origin[1]};
        r.dir = {ray.dir[0], ray.dir[1]};
        traceRay2D(*structure_->in2D, r, log);
    } else {
        Ray r;
        r.origin = {ray.origin[0], ray.origin[1], ray.origin[2]};
        r.dir = {ray.dir[0], ray.dir[1], ray.dir[2]};
        traceRay3D(*structure_->in3D, r, log);
    }
    return log;
}

ReferenceRay Reference::run(const StudentRay& ray) const {
    if (!structure_)
        return dims_ == 2 ? ddaReference<2>(*grid_, ray) : ddaReference<3>(*grid_, ray);
    return fromLog(record(ray), dims_);
}

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
        Comparer c(reference, ray, v.reference, lang, logged);
        v.divergence = c.compare();
        v.passed = !v.divergence;
        if (v.divergence) v.mistake = recognise(reference, ray, v.reference, *v.divergence);
        a.rays.push_back(std::move(v));
    }
    return a;
}

namespace {
/// Where a divergence is, in words: "cell 4", "the tMax of cell 4", "the end of the walk".
std::string place(const Divergence& d, Language lang) {
    const std::string i = std::to_string(std::max(d.index, 0));
    if (d.record == "cell") return trf(lang, "cell record %1", {i});
    if (d.record == "node") return trf(lang, "node record %1", {i});
    if (d.record == "tMax") return trf(lang, "the tMax of cell record %1", {i});
    if (d.record == "test") return tr(lang, "a primitive test");
    if (d.record == "end") return tr(lang, "the end of the walk");
    return tr(lang, "the hit or miss");
}
}  // namespace

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
                   {std::to_string(v.ray), std::to_string(d.line), place(d, lang)}) +
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
