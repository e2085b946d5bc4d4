// Exercises: answers as typed, the right answer read from the recorded trace (never from the
// lesson file, but for a choice), and the check of a student's answer with the explanation, in
// the student's language, and the slip a wrong number betrays.
#include "course/exercise.h"

#include "feedback_text.h"
#include "miss_cause.h"

#include "course/compute.h"
#include "course/lesson_trace.h"

#include "raystep/base/math.h"
#include "raystep/trace/event_text.h"
#include "raystep/trace/replay.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace raystep {

using feedback::axisName;

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::optional<double> parseNumber(std::string_view s) {
    s = trim(s);
    if (s.empty()) return std::nullopt;
    std::string copy(s);
    std::replace(copy.begin(), copy.end(), ',', '.');  // "0,75" as Italian students write it
    double v = 0.0;
    const auto [end, ec] = std::from_chars(copy.data(), copy.data() + copy.size(), v);
    if (ec != std::errc() || end != copy.data() + copy.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<long> parseWhole(std::string_view s) {
    const auto v = parseNumber(s);
    if (!v || *v != std::floor(*v) || std::abs(*v) > 1e9) return std::nullopt;
    return static_cast<long>(*v);
}

std::vector<std::string_view> splitAny(std::string_view s, std::string_view seps) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= s.size(); ++i)
        if (i == s.size() || seps.find(s[i]) != std::string_view::npos) {
            if (i > start) parts.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    return parts;
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool close(double answer, double reference, double tolerance) {
    return std::abs(answer - reference) <= tolerance * std::max(1.0, std::abs(reference));
}

/// The first event of type E at or after `from`, with its index.
template <typename E>
std::optional<std::pair<std::size_t, E>> nextEvent(const EventLog& log, std::size_t from) {
    const auto& ev = log.events();
    for (std::size_t i = from; i < ev.size(); ++i)
        if (const E* e = std::get_if<E>(&ev[i])) return std::pair{i, *e};
    return std::nullopt;
}
/// The last event of type E before `before`.
template <typename E>
std::optional<E> previousEvent(const EventLog& log, std::size_t before) {
    const auto& ev = log.events();
    for (std::size_t i = std::min(before, ev.size()); i-- > 0;)
        if (const E* e = std::get_if<E>(&ev[i])) return *e;
    return std::nullopt;
}

/// An option's text before its why: without its own full stop ("... the nearest one.: The").
std::string optionText(std::string text) {
    while (!text.empty() && (text.back() == '.' || text.back() == ' ')) text.pop_back();
    return text;
}

/// "a".."f" for options 0..5.
std::string letter(int i) {
    return std::string(1, static_cast<char>('a' + i));
}

struct Context {
    const Exercise& ex;
    const EventLog& log;
    const std::string& file;
    std::size_t at;
    const std::vector<GridSweepRow>* sweep;
    const LessonScene* scene = nullptr;
    [[noreturn]] void fail(const std::string& message) const {
        throw LessonError(file, ex.line, "exercises." + ex.id, message);
    }
};

Context contextOf(const Exercise& ex, const EventLog& log, const std::string& file,
                  const std::vector<GridSweepRow>* sweep) {
    Context c{ex, log, file, 0, sweep};
    const auto at = resolvePosition(ex.at, log);
    if (!at) c.fail("its position (" + describePosition(ex.at) + ") is not in the trace");
    c.at = *at;
    return c;
}

/// The end of a count's or sequence's range.
std::size_t rangeEnd(const Context& c) {
    if (!c.ex.until) return c.log.events().size();
    const auto u = resolvePosition(*c.ex.until, c.log);
    if (!u || *u < c.at)
        c.fail("its end (" + describePosition(*c.ex.until) +
               ") is not in the trace after its start");
    return *u;
}

/// A Count's range in words: "after the 1st intersection found", or both ends joined.
std::string rangeText(const Exercise& ex, Language lang) {
    std::vector<std::string> parts;
    if (ex.at.mode != ReplayPosition::Mode::Start) parts.push_back(describePosition(ex.at, lang));
    if (ex.until && ex.until->mode != ReplayPosition::Mode::End)
        parts.push_back(describePosition(*ex.until, lang));
    if (parts.empty()) return tr(lang, "in the whole trace");
    // Only the end given: the range runs from the start up to it, not after it.
    if (parts.size() == 1 && ex.at.mode == ReplayPosition::Mode::Start)
        return trf(lang, "from the start until %1", {parts[0]});
    if (parts.size() == 1) return parts[0];
    return trf(lang, "%1 and %2", {parts[0], parts[1]});
}

/// Whether `e` is an event a Count exercise counts; `filtered`: with its ray kind and depth.
bool counted(const Exercise& ex, const Event& e, bool filtered) {
    if (e.index() != ex.countKind) return false;
    if (const auto* b = std::get_if<RayBegin>(&e); b && filtered) {
        if (ex.rayKind && b->kind != *ex.rayKind) return false;
        if (ex.rayDepth && b->depth != *ex.rayDepth) return false;
    }
    return true;
}

/// The reference answer, the explanation of it, and the event it is read from.
struct Reference {
    Answer answer;
    std::string why;
    std::optional<std::size_t> source;
};

/// The sweep's metric of one row.
double sweepMetric(const Exercise& ex, const GridSweepRow& r) {
    switch (ex.metric) {
        case SweepMetric::Cost:
            return ex.given.cTrav * r.cellsPerRay + ex.given.cIsect * r.testsPerRay;
        case SweepMetric::TestsPerRay:
            return r.testsPerRay;
        case SweepMetric::CellsPerRay:
            return r.cellsPerRay;
    }
    return 0.0;
}

/// The nodes an overlap exercise is about: every node of the tree (the trace's node boxes),
/// with no event of their own (the structure is drawn whole, whatever the replay's step).
std::vector<std::pair<std::uint32_t, std::size_t>> treeNodes(const Context& c) {
    std::vector<std::pair<std::uint32_t, std::size_t>> out;
    for (std::size_t id = 0; id < c.log.nodes().size(); ++id)
        out.emplace_back(static_cast<std::uint32_t>(id), 0);
    return out;
}

/// Whether the boxes of nodes `a` and `b` (the trace's node boxes) share space, neither inside
/// the other: what a space subdivision's cells never do, and a BVH's may.
bool partlyOverlap(const EventLog& log, std::uint32_t a, std::uint32_t b) {
    if (a == b || a >= log.nodes().size() || b >= log.nodes().size()) return false;
    const NodeRecord &p = log.nodes()[a], &q = log.nodes()[b];
    bool share = true, pInQ = true, qInP = true;
    for (int k = 0; k < log.dims(); ++k) {
        // A positive length on every axis: boxes that only touch share no space.
        share = share && std::max(p.lo[k], q.lo[k]) < std::min(p.hi[k], q.hi[k]);
        pInQ = pInQ && q.lo[k] <= p.lo[k] && p.hi[k] <= q.hi[k];
        qInP = qInP && p.lo[k] <= q.lo[k] && q.hi[k] <= p.hi[k];
    }
    return share && !pInQ && !qInP;
}

/// A node's box as the feedback writes it: "(0.8, 3.5)–(2.6, 6.5)".
std::string nodeBoxText(const EventLog& log, std::uint32_t node, Language lang) {
    const NodeRecord& r = log.nodes().at(node);
    const auto corner = [&](const std::array<double, 3>& v) {
        std::string s = "(";
        for (int k = 0; k < log.dims(); ++k) {
            if (k) s += lang == Language::It ? "; " : ", ";
            s += formatNumber(v[k], lang);
        }
        return s + ")";
    };
    return corner(r.lo) + "\u2013" + corner(r.hi);
}

Reference reference(const Context& c, Language lang) {
    Reference ref;
    Answer& a = ref.answer;
    std::string& why = ref.why;
    const EventLog& log = c.log;
    const auto n = [&](double v) { return formatNumber(v, lang); };
    switch (c.ex.kind) {
        case ExerciseKind::NextCell: {
            const auto next = nextEvent<DdaCell>(log, c.at);
            if (!next) c.fail("no DDA cell follows its position in the trace");
            const int dims = log.dims();
            for (int i = 0; i < dims; ++i) a.numbers.push_back(next->second.cell[i]);
            why = feedback::nextCell(lang, previousEvent<DdaCell>(log, next->first), next->second,
                                     dims);
            ref.source = next->first;
            break;
        }
        case ExerciseKind::Value: {
            const Quantity q = c.ex.quantity;
            double v = 0.0;
            if (q >= Quantity::TMaxX && q <= Quantity::TMaxZ) {
                const auto e = nextEvent<DdaCell>(log, c.at);
                if (!e) c.fail("no DDA cell follows its position");
                const int axis = static_cast<int>(q) - static_cast<int>(Quantity::TMaxX);
                v = e->second.tMax[axis];
                ref.source = e->first;
                if (e->second.ray < log.rays().size() && std::isfinite(v)) {
                    const RayRecord& r = log.rays()[e->second.ray];
                    const double o = r.origin[axis], d = r.dir[axis];
                    why = trf(lang,
                              "tMax.%1 is the t at which the ray crosses the next %1 boundary "
                              "after cell %2: (%3 − %4) / %5 = %6.",
                              {axisName(axis), cellText(e->second.cell, log.dims()), n(o + v * d),
                               n(o), n(d), n(v)});
                }
            } else if (q >= Quantity::TDeltaX && q <= Quantity::TExit) {
                const auto e = nextEvent<DdaSetup>(log, c.at);
                if (!e) c.fail("no DDA set-up follows its position");
                ref.source = e->first;
                if (q == Quantity::TEnter) {
                    v = e->second.tEnter;
                    why = trf(lang,
                              "t_enter is where the ray enters the grid: the largest of the slabs' "
                              "entry times, or 0 when the origin is inside: %1.",
                              {n(v)});
                } else if (q == Quantity::TExit) {
                    v = e->second.tGridExit;
                    why = trf(lang,
                              "t_exit is where the ray leaves the grid: the smallest of the slabs' "
                              "exit times: %1.",
                              {n(v)});
                } else {
                    const int axis = static_cast<int>(q) - static_cast<int>(Quantity::TDeltaX);
                    v = e->second.tDelta[axis];
                    if (e->second.ray < log.rays().size() && std::isfinite(v)) {
                        const double d = log.rays()[e->second.ray].dir[axis];
                        why = trf(lang,
                                  "tDelta.%1 is the t the ray takes to cross one cell along %1: "
                                  "cell size / |d.%1| = %2 / |%3| = %4.",
                                  {axisName(axis), n(v * std::abs(d)), n(d), n(v)});
                    }
                }
            } else if (q >= Quantity::HitT && q <= Quantity::HitV) {
                const auto e = nextEvent<RayHit>(log, c.at);
                if (!e) c.fail("no hit follows its position");
                ref.source = e->first;
                v = q == Quantity::HitT   ? e->second.t
                    : q == Quantity::HitU ? e->second.u
                                          : e->second.v;
                why = q == Quantity::HitT
                          ? trf(lang,
                                "The nearest intersection of the ray is with primitive %1, at t = "
                                "%2.",
                                {std::to_string(e->second.prim), n(v)})
                          // Only the coordinate asked: the other may be the next exercise's.
                          : trf(lang,
                                "On primitive %1 the intersection has the barycentric coordinate "
                                "%2 = %3 (the point is (1 − u − v) a + u b + v c).",
                                {std::to_string(e->second.prim), q == Quantity::HitU ? "u" : "v",
                                 n(v)});
            } else if (q == Quantity::TestT) {
                std::optional<std::pair<std::size_t, PrimitiveTest>> hit;
                for (std::size_t i = c.at; i < log.events().size() && !hit; ++i)
                    if (const auto* t = std::get_if<PrimitiveTest>(&log.events()[i]); t && t->hit)
                        hit = std::pair{i, *t};
                if (!hit) c.fail("no primitive test that hits follows its position");
                v = hit->second.t;
                ref.source = hit->first;
                why = feedback::hitOrMiss(lang, hit->second);
            } else if (q == Quantity::NodeTNear || q == Quantity::NodeTFar) {
                const auto e = nextEvent<NodeEnter>(log, c.at);
                if (!e) c.fail("no node is entered after its position");
                ref.source = e->first;
                v = q == Quantity::NodeTNear ? e->second.tNear : e->second.tFar;
                why = trf(lang,
                          "Node %1 is entered over [tNear, tFar] = [%2, %3]: the part of the ray "
                          "inside its box (the slab test), clipped to the parent's.",
                          {std::to_string(e->second.node), n(e->second.tNear), n(e->second.tFar)});
            } else {
                const auto e = nextEvent<SplitCandidate>(log, c.at);
                if (!e) c.fail("no split candidate follows its position");
                ref.source = e->first;
                const SplitCandidate& s = e->second;
                v = q == Quantity::CandidatePL   ? s.pl
                    : q == Quantity::CandidatePR ? s.pr
                                                 : s.sahCost;
                why = trf(lang,
                          "Candidate %1 = %2: NL = %3, NR = %4, P(L|C) = Area(L) / Area(C) = %5, "
                          "P(R|C) = %6, cost = C_trav + C_isect (P(L|C) NL + P(R|C) NR) = %7.",
                          {axisName(s.axis), n(s.position), std::to_string(s.nl),
                           std::to_string(s.nr), n(s.pl), n(s.pr), n(s.sahCost)});
            }
            if (!std::isfinite(v))
                c.fail("the trace's value is not finite (the ray never crosses)");
            a.numbers.push_back(v);
            break;
        }
        case ExerciseKind::PickSplit: {
            const auto node = nextEvent<BuildNode>(log, c.at);
            if (!node) c.fail("no node is built after its position");
            std::optional<SplitCandidate> best;
            int count = 0;
            for (std::size_t i = 0; i < log.events().size(); ++i)
                if (const auto* s = std::get_if<SplitCandidate>(&log.events()[i]);
                    s && s->node == node->second.node) {
                    ++count;
                    if (!best || s->sahCost < best->sahCost) best = *s;
                }
            if (!best) c.fail("node " + std::to_string(node->second.node) + " has no candidates");
            a.numbers = {static_cast<double>(best->axis), best->position};
            why = feedback::pickSplit(lang, count, node->second.node, *best);
            ref.source = node->first;
            break;
        }
        case ExerciseKind::Count: {
            std::size_t total = 0;
            const std::size_t end = rangeEnd(c);
            std::vector<std::string> items;
            std::optional<DdaCell> cell;  // the cell the walk is in, for skips and tests
            for (std::size_t i = 0; i < end; ++i) {
                const Event& e = log.events()[i];
                if (const auto* dc = std::get_if<DdaCell>(&e)) cell = *dc;
                if (const auto* rb = std::get_if<RayBegin>(&e); rb) cell.reset();
                if (i < c.at || !counted(c.ex, e, true)) continue;
                if (!ref.source) ref.source = i;
                ++total;
                // What was counted, item by item (the first dozen).
                if (items.size() >= 12) continue;
                // Built piece by piece: GCC 12 warns (-Wrestrict, falsely) on " " + string here.
                std::string in;
                if (cell) {
                    in = ' ';
                    in += trf(lang, "in cell %1", {cellText(cell->cell, log.dims())});
                }
                if (const auto* s = std::get_if<MailboxSkip>(&e))
                    items.push_back(trf(lang, "primitive %1", {std::to_string(s->prim)}) + in);
                else if (const auto* t = std::get_if<PrimitiveTest>(&e))
                    items.push_back(trf(lang, "primitive %1", {std::to_string(t->prim)}) + in);
                else if (const auto* b = std::get_if<RayBegin>(&e))
                    items.push_back(trf(lang, "ray %1", {std::to_string(b->ray)}));
                else if (const auto* d = std::get_if<DdaCell>(&e))
                    items.push_back(cellText(d->cell, log.dims()));
                else if (const auto* ne = std::get_if<NodeEnter>(&e))
                    items.push_back(trf(lang, "node %1", {std::to_string(ne->node)}));
            }
            a.numbers.push_back(static_cast<double>(total));
            std::string what = c.ex.rayKind ? feedback::raysOfKind(lang, *c.ex.rayKind)
                                            : feedback::eventsCounted(lang, c.ex.countKind);
            if (c.ex.rayDepth)
                what = trf(lang, "%1 of depth %2", {what, std::to_string(*c.ex.rayDepth)});
            why = trf(lang, "%1 %2: %3.", {what, rangeText(c.ex, lang), std::to_string(total)});
            if (!items.empty()) {
                std::string list;
                for (const auto& s : items) {
                    if (!list.empty()) list += ", ";
                    list += s;
                }
                if (total > items.size()) list += ", …";
                // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on " " + string.
                why += ' ';
                why += trf(lang, "Counted: %1.", {list});
            }
            break;
        }
        case ExerciseKind::HitOrMiss: {
            const auto t = nextEvent<PrimitiveTest>(log, c.at);
            if (!t) c.fail("no primitive test follows its position");
            a.hit = t->second.hit;
            if (t->second.hit && c.ex.withT) a.numbers.push_back(t->second.t);
            const std::string cause =
                c.scene ? feedback::missCause(*c.scene, log, t->first, lang) : std::string();
            why = cause.empty() ? feedback::hitOrMiss(lang, t->second)
                                : trf(lang, "The test of primitive %1 fails. %2",
                                      {std::to_string(t->second.prim), cause});
            ref.source = t->first;
            break;
        }
        case ExerciseKind::Choice: {
            a.numbers.push_back(c.ex.answer);
            const ChoiceOption& right = c.ex.choices.at(static_cast<std::size_t>(c.ex.answer));
            why = trf(lang, "The right answer is %1) %2: %3",
                      {letter(c.ex.answer), optionText(right.text.in(lang)), right.why.in(lang)});
            break;
        }
        case ExerciseKind::Sequence: {
            const std::size_t end = rangeEnd(c);
            const int dims = log.dims();
            for (std::size_t i = c.at; i < end; ++i) {
                if (c.ex.length && a.numbers.size() / (c.ex.ofNodes ? 1 : dims) >=
                                       static_cast<std::size_t>(*c.ex.length))
                    break;
                const Event& e = log.events()[i];
                if (c.ex.ofNodes) {
                    if (const auto* ne = std::get_if<NodeEnter>(&e)) {
                        a.numbers.push_back(ne->node);
                        if (!ref.source) ref.source = i;
                    }
                } else if (const auto* dc = std::get_if<DdaCell>(&e)) {
                    for (int k = 0; k < dims; ++k) a.numbers.push_back(dc->cell[k]);
                    if (!ref.source) ref.source = i;
                }
            }
            if (a.numbers.empty())
                c.fail(c.ex.ofNodes ? "no node is entered in its range"
                                    : "no DDA cell is visited in its range");
            a.perItem = c.ex.ofNodes ? 1 : dims;
            why = c.ex.ofNodes ? trf(lang,
                                     "TestTree enters the nodes in this order, the nearer child "
                                     "first: %1.",
                                     {formatAnswer(c.ex, a, lang)})
                               : trf(lang, "The DDA visits the cells in this order: %1.",
                                     {formatAnswer(c.ex, a, lang)});
            break;
        }
        case ExerciseKind::SweepPick: {
            if (!c.sweep || c.sweep->empty())
                c.fail("a sweep_pick is graded from the lesson's sweep, which has not been run");
            const GridSweepRow* best = nullptr;
            std::string table;
            for (const GridSweepRow& r : *c.sweep) {
                if (!best || sweepMetric(c.ex, r) < sweepMetric(c.ex, *best)) best = &r;
                table += (table.empty() ? "" : "; ") + std::to_string(r.resolution) + ": " +
                         n(sweepMetric(c.ex, r));
            }
            a.numbers.push_back(best->resolution);
            const std::string metric =
                c.ex.metric == SweepMetric::Cost
                    ? trf(lang,
                          "the cost C_trav × cells per ray + C_isect × tests per ray (C_trav = "
                          "%1, C_isect = %2)",
                          {n(c.ex.given.cTrav), n(c.ex.given.cIsect)})
                : c.ex.metric == SweepMetric::TestsPerRay ? tr(lang, "the tests per ray")
                                                          : tr(lang, "the cells per ray");
            why = trf(lang, "Per resolution (cells per axis), %1: %2. The lowest is at %3.",
                      {metric, table, std::to_string(best->resolution)});
            break;
        }
        case ExerciseKind::Compute: {
            a.numbers.push_back(computeAnswer(c.ex, c.file));
            why = computeWorking(c.ex, lang);
            break;
        }
        case ExerciseKind::Overlap: {
            if (log.nodes().empty())
                c.fail("an overlap exercise needs a tree: its trace has no node boxes");
            const auto entered = treeNodes(c);
            // Every pair that overlaps, by the later node's id.
            std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
            for (std::size_t j = 1; j < entered.size(); ++j)
                for (std::size_t i = 0; i < j; ++i)
                    if (partlyOverlap(log, entered[i].first, entered[j].first))
                        pairs.emplace_back(entered[i].first, entered[j].first);
            if (pairs.empty())
                c.fail("no two boxes of the tree overlap (a space subdivision's cells never do)");
            a.numbers = {double(pairs[0].first), double(pairs[0].second)};
            std::string all;
            for (const auto& [p, q] : pairs)
                all += (all.empty() ? "" : "; ") +
                       trf(lang, "%1 and %2", {std::to_string(p), std::to_string(q)});
            why = trf(
                lang,
                "Node %1's box %2 and node %3's box %4 share space, and neither lies inside "
                "the other: a ray through the shared space must enter both. The pairs of the "
                "tree's boxes that overlap: %5.",
                {std::to_string(pairs[0].first), nodeBoxText(log, pairs[0].first, lang),
                 std::to_string(pairs[0].second), nodeBoxText(log, pairs[0].second, lang), all});
            break;
        }
    }
    return ref;
}

/// Why two nodes given for an overlap are not a right pair.
std::string overlapSlip(const Context& c, const Answer& given, Language lang) {
    if (given.numbers.size() != 2) return "";
    const auto entered = treeNodes(c);
    const auto id = [](double v) { return std::to_string(static_cast<long long>(v)); };
    for (const double v : given.numbers)
        if (std::none_of(entered.begin(), entered.end(),
                         [&](const auto& e) { return double(e.first) == v; }))
            return trf(lang, "The tree has no node %1.", {id(v)});
    const auto a = static_cast<std::uint32_t>(given.numbers[0]),
               b = static_cast<std::uint32_t>(given.numbers[1]);
    const NodeRecord &p = c.log.nodes().at(a), &q = c.log.nodes().at(b);
    bool pInQ = true, qInP = true;
    for (int k = 0; k < c.log.dims(); ++k) {
        pInQ = pInQ && q.lo[k] <= p.lo[k] && p.hi[k] <= q.hi[k];
        qInP = qInP && p.lo[k] <= q.lo[k] && q.hi[k] <= p.hi[k];
    }
    if (pInQ || qInP)
        return trf(lang,
                   "Node %1's box lies inside node %2's (a child inside its parent): that is "
                   "the hierarchy, not two boxes overlapping.",
                   {id(pInQ ? a : b), id(pInQ ? b : a)});
    return trf(lang, "Node %1's box %2 and node %3's box %4 share no space.",
               {id(a), nodeBoxText(c.log, a, lang), id(b), nodeBoxText(c.log, b, lang)});
}

/// The near and far roots of ray `ray` against primitive `prim` when it is a circle or a sphere
/// of the scene (a = d.d, b = (o - c).d, c' = |o - c|^2 - r^2, t = (-b -+ sqrt(b^2 - a c')) / a).
std::optional<std::pair<double, double>> roundRoots(const Context& c, std::uint32_t ray,
                                                    std::uint32_t prim) {
    if (!c.scene || ray >= c.log.rays().size()) return std::nullopt;
    const RayRecord& r = c.log.rays()[ray];
    Vec3 center{0.0};
    double radius = 0.0;
    if (const auto* s2 = std::get_if<Scene2D>(c.scene); s2 && s2->isCircle(prim)) {
        center = Vec3(s2->circles[prim].center.x, s2->circles[prim].center.y, 0.0);
        radius = s2->circles[prim].radius;
    } else if (const auto* s3 = std::get_if<Scene>(c.scene); s3 && s3->isSphere(prim)) {
        center = s3->spheres[prim].center;
        radius = s3->spheres[prim].radius;
    } else {
        return std::nullopt;
    }
    const Vec3 oc = r.origin - center;
    const double a = glm::dot(r.dir, r.dir), b = glm::dot(oc, r.dir);
    const double disc = b * b - a * (glm::dot(oc, oc) - radius * radius);
    if (!(a > 0.0) || disc < 0.0) return std::nullopt;
    return std::pair{(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a};
}

/// The slip a wrong t of a hit betrays: the far root of a circle or sphere (with the scene), or
/// the root halved or doubled by a missing or extra division.
std::string rootSlip(const Context& c, double given, double right, std::uint32_t ray,
                     std::uint32_t prim, Language lang) {
    const auto n = [&](double v) { return formatNumber(v, lang); };
    const auto near = [&](double v) { return close(given, v, c.ex.tolerance); };
    if (const auto roots = roundRoots(c, ray, prim);
        roots && !near(right) && near(roots->second) && roots->second != right) {
        if (std::holds_alternative<Scene2D>(*c.scene))
            return trf(lang,
                       "%1 is the far root, where the ray leaves the circle: the intersection is "
                       "the near one.",
                       {n(given)});
        return trf(lang,
                   "%1 is the far root, where the ray leaves the sphere: the intersection is the "
                   "near one.",
                   {n(given)});
    }
    if (right == 0.0) return "";
    if (near(right / 2))
        return trf(lang,
                   "%1 is half the root: one division by 2 too many. The root is (−B − √(B² − "
                   "4AC)) / 2A, or with the half-b form, b = B/2, (−b − √(b² − AC)) / A.",
                   {n(given)});
    if (near(2 * right))
        return trf(lang,
                   "%1 is twice the root: the root (−B − √(B² − 4AC)) / 2A divides by 2A (the "
                   "slide leaves out /2A); with the half-b form, b = B/2, it divides by A alone.",
                   {n(given)});
    return "";
}

/// The slip a wrong next cell betrays: a cell outside the grid on the entry face, the slides'
/// detour on a tie, one axis of a tie alone, or a step along an axis whose tMax is not the least.
std::string nextCellSlip(const Context& c, const Answer& given, std::size_t source, Language lang) {
    const int dims = c.log.dims();
    const auto* next = std::get_if<DdaCell>(&c.log.events()[source]);
    if (!next || static_cast<int>(given.numbers.size()) != dims) return "";
    std::array<std::int32_t, 3> mine{0, 0, 0};
    for (int i = 0; i < dims; ++i) mine[i] = static_cast<std::int32_t>(given.numbers[i]);
    const auto setup = previousEvent<DdaSetup>(c.log, source);
    if (!setup || setup->ray != next->ray) return "";
    const auto moved = [&](const std::array<std::int32_t, 3>& from, int axis, int by) {
        std::array<std::int32_t, 3> to = from;
        to[axis] += by;
        return to;
    };
    const std::string cell = cellText(mine, dims);
    const auto before = previousEvent<DdaCell>(c.log, source);
    if (!before || before->ray != next->ray) {
        // The first cell, entered through a face (axes): the one on the face's outside is off.
        const RayRecord* r = next->ray < c.log.rays().size() ? &c.log.rays()[next->ray] : nullptr;
        for (int a = 0; r && a < dims; ++a)
            if ((next->axes >> a & 1u) && mine == moved(next->cell, a, -setup->step[a]))
                return trf(lang,
                           "%1 lies outside the grid, off by one on the entry face: the ray comes "
                           "in through the face %2 = %3, so the first cell is the one on its "
                           "inside.",
                           {cell, axisName(a),
                            formatNumber(r->origin[a] + setup->tEnter * r->dir[a], lang)});
        return "";
    }
    unsigned tied = 0;
    for (int a = 0; a < dims; ++a) tied += next->axes >> a & 1u;
    for (int a = 0; a < dims; ++a) {
        if (mine != moved(before->cell, a, setup->step[a])) continue;
        if (tied > 1 && (next->axes >> a & 1u)) {
            if (dims == 2 && a == 1)
                return trf(lang,
                           "%1 is the slides' conservative detour: on a tie their `if (tMaxX < "
                           "tMaxY)` is false and steps Y alone, into a cell the ray only touches "
                           "at a corner. The exact walk does not enter it.",
                           {cell});
            return trf(lang,
                       "%1 is a step along %2 alone: on a tie the ray leaves the cell through a "
                       "corner, and the exact walk steps along every tied axis at once.",
                       {cell, std::string(1, "XYZ"[a])});
        }
        if (tied == 1 && !(next->axes >> a & 1u)) {
            return trf(lang,
                       "%1 is a step along %2, but in %3 tMax%2 = %4 is not the smallest tMax: "
                       "the walk steps along the axis whose boundary comes first.",
                       {cell, std::string(1, "XYZ"[a]), cellText(before->cell, dims),
                        formatNumber(before->tMax[a], lang)});
        }
    }
    return "";
}

/// Counts of all events of the kind in the range, and of the right kind in the whole trace.
std::string countSlip(const Context& c, double given, double right, Language lang) {
    const std::size_t end = rangeEnd(c);
    std::size_t unfiltered = 0, everywhere = 0;
    for (std::size_t i = 0; i < c.log.events().size(); ++i) {
        const Event& e = c.log.events()[i];
        if (i >= c.at && i < end && counted(c.ex, e, false)) ++unfiltered;
        if (counted(c.ex, e, true)) ++everywhere;
    }
    if ((c.ex.rayKind || c.ex.rayDepth) && given == unfiltered && unfiltered != right)
        return trf(lang, "%1 counts every ray in the range, of any kind and depth.",
                   {formatNumber(given, lang)});
    if (given == everywhere && everywhere != right)
        return trf(lang, "%1 counts the whole trace, not only the range asked.",
                   {formatNumber(given, lang)});
    return "";
}

/// The slip a wrong Value betrays, read from the trace around its source event.
std::string valueSlip(const Context& c, double given, double right, std::size_t source,
                      Language lang) {
    const auto n = [&](double v) { return formatNumber(v, lang); };
    const Quantity q = c.ex.quantity;
    const auto near = [&](double v) { return close(given, v, c.ex.tolerance); };
    const auto negativeAlong = [&](int axis) {
        const auto* setup = std::get_if<DdaSetup>(&c.log.events()[source]);
        return setup && setup->ray < c.log.rays().size() && c.log.rays()[setup->ray].dir[axis] < 0;
    };
    if (q >= Quantity::TDeltaX && q <= Quantity::TDeltaZ && right != 0.0 && near(-right) &&
        negativeAlong(static_cast<int>(q) - static_cast<int>(Quantity::TDeltaX)))
        return trf(lang,
                   "%1 is cell size / d without the abs: d is negative along this axis, but "
                   "tDelta is a distance along the ray, cell size / |d|.",
                   {n(given)});
    if (q >= Quantity::TMaxX && q <= Quantity::TMaxZ) {
        const auto* cell = std::get_if<DdaCell>(&c.log.events()[source]);
        const int axis = static_cast<int>(q) - static_cast<int>(Quantity::TMaxX);
        for (int k = 0; cell && k < c.log.dims(); ++k)
            if (k != axis && near(cell->tMax[k]))
                return trf(lang, "%1 is tMax.%2, not tMax.%3.",
                           {n(given), axisName(k), axisName(axis)});
        if (const auto setup = previousEvent<DdaSetup>(c.log, source); setup) {
            const double delta = setup->tDelta[axis];
            if (near(right - delta))
                return trf(lang,
                           "%1 is the tMax.%2 of the cell before: after a step along %2, tMax.%2 "
                           "grows by tDelta.%2 = %3.",
                           {n(given), axisName(axis), n(delta)});
        }
        // One step too far: the next cell's tMax, once the walk has left this one.
        if (const auto next = cell ? nextEvent<DdaCell>(c.log, source + 1) : std::nullopt;
            next && next->second.ray == cell->ray && next->second.tMax[axis] != right &&
            near(next->second.tMax[axis]))
            return trf(lang,
                       "%1 is tMax.%2 one step later, once the walk has left this cell: in %3, "
                       "tMax.%2 is where the ray crosses this cell's own far %2 boundary.",
                       {n(given), axisName(axis), cellText(cell->cell, c.log.dims())});
    }
    if (q == Quantity::HitU || q == Quantity::HitV) {
        const auto* hit = std::get_if<RayHit>(&c.log.events()[source]);
        const double other = hit ? (q == Quantity::HitU ? hit->v : hit->u) : right;
        if (hit && other != right && near(other))
            return q == Quantity::HitU
                       ? trf(lang,
                             "%1 is v, not u: u weighs corner b, v corner c (p = (1 − u − v) a + "
                             "u b + v c).",
                             {n(given)})
                       : trf(lang,
                             "%1 is u, not v: u weighs corner b, v corner c (p = (1 − u − v) a + "
                             "u b + v c).",
                             {n(given)});
    }
    if (q == Quantity::HitT || q == Quantity::TestT) {
        const auto* hit = std::get_if<RayHit>(&c.log.events()[source]);
        const auto* test = std::get_if<PrimitiveTest>(&c.log.events()[source]);
        if (hit || test) {
            const std::uint32_t ray = hit ? hit->ray : test->ray;
            const std::uint32_t prim = hit ? hit->prim : test->prim;
            if (const std::string s = rootSlip(c, given, right, ray, prim, lang); !s.empty())
                return s;
        }
    }
    if (q == Quantity::HitT) {
        // The slide's grid loop stops at the first hit found: a farther one, when cells overlap.
        const auto* hit = std::get_if<RayHit>(&c.log.events()[source]);
        for (std::size_t i = 0; hit && i < source; ++i)
            if (const auto* t = std::get_if<PrimitiveTest>(&c.log.events()[i]);
                t && t->ray == hit->ray && t->hit && t->prim != hit->prim && near(t->t))
                return trf(lang,
                           "%1 is primitive %2's intersection: found before the nearest one but "
                           "farther along the ray. Stopping at the first intersection found (the "
                           "slide's `break`) gives it; the nearest is primitive %3's.",
                           {n(given), std::to_string(t->prim), std::to_string(hit->prim)});
    }
    if (q == Quantity::NodeTNear || q == Quantity::NodeTFar) {
        const auto* e = std::get_if<NodeEnter>(&c.log.events()[source]);
        if (e && near(q == Quantity::NodeTNear ? e->tFar : e->tNear))
            return trf(lang, "%1 is the other end of the node's interval: tNear ≤ tFar.",
                       {n(given)});
    }
    if (q == Quantity::CandidatePL || q == Quantity::CandidatePR) {
        const auto* s = std::get_if<SplitCandidate>(&c.log.events()[source]);
        if (s && near(q == Quantity::CandidatePL ? s->pr : s->pl))
            return trf(lang, "%1 is the other side's probability: P(L|C) belongs to the left box.",
                       {n(given)});
        if (s && near(right * right))
            return trf(lang,
                       "%1 takes the probability as Area²/Area² (the slide's slip): P(L|C) is "
                       "Area(L) / Area(C), not squared.",
                       {n(given)});
    }
    if (right != 0.0 && near(-right)) return trf(lang, "%1 has the wrong sign.", {n(given)});
    return "";
}

/// Where a student's order departs from the trace's, and why.
std::string sequenceSlip(const Context& c, const Answer& given, const Answer& right,
                         Language lang) {
    const int per = right.perItem;
    if (given.perItem != per && !given.numbers.empty())
        return trf(lang, "Each cell has %1 indices here.", {std::to_string(per)});
    const std::size_t items = right.numbers.size() / per, gave = given.numbers.size() / per;
    const auto item = [&](const Answer& a, std::size_t k) {
        std::array<std::int32_t, 3> cell{0, 0, 0};
        for (int i = 0; i < per; ++i) cell[i] = static_cast<std::int32_t>(a.numbers[k * per + i]);
        return c.ex.ofNodes ? trf(lang, "node %1", {std::to_string(cell[0])})
                            : cellText(cell, c.log.dims());
    };
    std::size_t k = 0;
    while (k < items && k < gave && item(given, k) == item(right, k)) ++k;
    if (k == items && k == gave) return "";
    if (k == gave && gave == 1)
        return trf(lang, "Your order stops after 1 item; the trace goes on with %1.",
                   {item(right, k)});
    if (k == gave)
        return trf(lang, "Your order stops after %1 items; the trace goes on with %2.",
                   {std::to_string(gave), item(right, k)});
    if (k == items)
        return trf(lang, "The trace has only %1 here; %2 is not in it.",
                   {std::to_string(items), item(given, k)});
    // The k-th event of the range: the reason it comes next.
    const std::string place = feedback::ordinal(lang, static_cast<int>(k + 1));
    std::size_t seen = 0;
    std::optional<DdaCell> prevCell;
    for (std::size_t i = c.at; i < c.log.events().size(); ++i) {
        const Event& e = c.log.events()[i];
        if (c.ex.ofNodes) {
            const auto* ne = std::get_if<NodeEnter>(&e);
            if (!ne || seen++ != k) continue;
            return trf(lang,
                       "Your order departs from the trace's at the %1 item: the trace enters node "
                       "%2 there, over [tNear, tFar] = [%3, %4], the nearest interval still to "
                       "visit; you wrote %5.",
                       {place, std::to_string(ne->node), formatNumber(ne->tNear, lang),
                        formatNumber(ne->tFar, lang), item(given, k)});
        }
        const auto* dc = std::get_if<DdaCell>(&e);
        if (!dc) continue;
        if (seen++ != k) {
            prevCell = *dc;
            continue;
        }
        const std::string why = feedback::nextCell(
            lang, prevCell ? prevCell : previousEvent<DdaCell>(c.log, i), *dc, c.log.dims());
        return trf(lang, "Your order departs from the trace's at the %1 item (you wrote %2): %3",
                   {place, item(given, k), why});
    }
    return "";
}

}  // namespace

std::optional<Answer> parseAnswer(const Exercise& ex, std::string_view text, std::string* why,
                                  Language lang) {
    const auto bad = [&](const std::string& message) -> std::optional<Answer> {
        if (why) *why = message;
        return std::nullopt;
    };
    Answer a;
    switch (ex.kind) {
        case ExerciseKind::NextCell: {
            const auto parts = splitAny(text, "(), ;\t");
            if (parts.size() < 2 || parts.size() > 3)
                return bad(tr(lang, "expected a cell as X,Y or X,Y,Z (whole numbers)"));
            for (const auto p : parts) {
                const auto v = parseWhole(p);
                if (!v) return bad(tr(lang, "cell indices are whole numbers"));
                a.numbers.push_back(static_cast<double>(*v));
            }
            return a;
        }
        case ExerciseKind::Value:
        case ExerciseKind::Compute:
        case ExerciseKind::Count: {
            const auto v = parseNumber(text);
            if (!v) return bad(tr(lang, "expected a number"));
            if (ex.kind == ExerciseKind::Count && (*v < 0 || *v != std::floor(*v)))
                return bad(tr(lang, "a count is a whole number, 0 or more"));
            a.numbers.push_back(*v);
            return a;
        }
        case ExerciseKind::PickSplit: {
            const std::string s = lower(text);
            const auto eq = s.find('=');
            if (eq == std::string::npos)
                return bad(tr(lang, "expected a split plane as x=POSITION (or y=, z=)"));
            const auto axisPart = splitAny(std::string_view(s).substr(0, eq), " \t");
            if (axisPart.size() != 1 || axisPart[0].size() != 1 ||
                std::string_view("xyz").find(axisPart[0][0]) == std::string_view::npos)
                return bad(tr(lang, "the axis is x, y or z"));
            const auto v = parseNumber(std::string_view(s).substr(eq + 1));
            if (!v) return bad(tr(lang, "expected a number after '='"));
            a.numbers = {static_cast<double>(axisPart[0][0] - 'x'), *v};
            return a;
        }
        case ExerciseKind::HitOrMiss: {
            const auto expected = [&] {
                return bad(ex.withT
                               ? tr(lang, "expected \"hit T\" (T the intersection's t) or \"miss\"")
                               : tr(lang, "expected \"hit\" or \"miss\""));
            };
            const std::string s = lower(text);
            const auto parts = splitAny(s, " \t=:");
            if (parts.empty()) return expected();
            const std::string_view word = parts[0];
            // The words of both languages, whatever the app's language.
            for (const char* no :
                 {"miss", "false", "no", "manca", "mancata", "mancato", "falso", "nessuna"})
                if (word == no) {
                    if (parts.size() > 1) return bad(tr(lang, "a miss has no t"));
                    a.hit = false;
                    return a;
                }
            bool yes = false;
            for (const char* w :
                 {"hit", "true", "yes", "colpisce", "colpita", "colpito", "sì", "si", "vero"})
                yes = yes || word == w;
            if (!yes) return expected();
            a.hit = true;
            std::size_t i = 1;
            if (i < parts.size() && parts[i] == "t") ++i;
            if (i < parts.size()) {
                const auto v = parseNumber(parts[i]);
                if (!v || i + 1 != parts.size()) return expected();
                a.numbers.push_back(*v);
            }
            if (ex.withT && a.numbers.empty())
                return bad(tr(lang, "give the intersection's t too: \"hit T\""));
            return a;
        }
        case ExerciseKind::Choice: {
            std::string s = lower(trim(text));
            while (!s.empty() && (s.front() == '(' || s.back() == ')' || s.back() == '.')) {
                if (s.front() == '(') s.erase(0, 1);
                if (!s.empty() && (s.back() == ')' || s.back() == '.')) s.pop_back();
            }
            const int options = static_cast<int>(ex.choices.size());
            int index = -1;
            if (s.size() == 1 && s[0] >= 'a' && s[0] < 'a' + options) index = s[0] - 'a';
            if (const auto v = parseWhole(s); v && *v >= 1 && *v <= options)
                index = static_cast<int>(*v) - 1;
            if (index < 0)
                return bad(trf(lang, "expected a letter (a to %1) or a number (1 to %2)",
                               {letter(std::max(options, 1) - 1), std::to_string(options)}));
            a.numbers.push_back(index);
            return a;
        }
        case ExerciseKind::Sequence: {
            if (ex.ofNodes) {
                for (const auto p : splitAny(text, " ,;\t")) {
                    const auto v = parseWhole(p);
                    if (!v || *v < 0)
                        return bad(
                            tr(lang, "expected node ids in order, as 0 1 4 (whole numbers)"));
                    a.numbers.push_back(static_cast<double>(*v));
                }
                if (a.numbers.empty())
                    return bad(tr(lang, "expected node ids in order, as 0 1 4 (whole numbers)"));
                return a;
            }
            std::string s(text);
            const bool grouped = s.find_first_of(";)") != std::string::npos;
            for (char& ch : s)
                if (ch == ')') ch = ';';
            s.erase(std::remove(s.begin(), s.end(), '('), s.end());
            const auto cells = splitAny(s, grouped ? ";" : " \t");
            int per = 0;
            for (const auto cell : cells) {
                const auto parts = splitAny(cell, ", \t");
                if (parts.empty()) continue;
                if (parts.size() < 2 || parts.size() > 3 ||
                    (per && per != static_cast<int>(parts.size())))
                    return bad(tr(lang, "expected cells in order, as 0,0; 1,0; 1,1"));
                per = static_cast<int>(parts.size());
                for (const auto p : parts) {
                    const auto v = parseWhole(p);
                    if (!v) return bad(tr(lang, "cell indices are whole numbers"));
                    a.numbers.push_back(static_cast<double>(*v));
                }
            }
            if (!per) return bad(tr(lang, "expected cells in order, as 0,0; 1,0; 1,1"));
            a.perItem = per;
            return a;
        }
        case ExerciseKind::SweepPick: {
            const auto v = parseWhole(text);
            if (!v || *v < 1)
                return bad(tr(lang, "expected a resolution: cells per axis, a whole number"));
            a.numbers.push_back(static_cast<double>(*v));
            return a;
        }
        case ExerciseKind::Overlap: {
            const std::string s = lower(text);
            for (const auto p : splitAny(s, " ,;\t")) {
                if (p == "and" || p == "e") continue;  // "3 and 4", "3 e 4"
                const auto v = parseWhole(p);
                if (!v || *v < 0) return bad(tr(lang, "expected two node ids, as 3 4"));
                a.numbers.push_back(static_cast<double>(*v));
            }
            if (a.numbers.size() != 2) return bad(tr(lang, "expected two node ids, as 3 4"));
            if (a.numbers[0] == a.numbers[1])
                return bad(tr(lang, "two different nodes: a box always overlaps itself"));
            return a;
        }
    }
    return bad("unknown exercise kind");
}

std::string formatAnswer(const Exercise& ex, const Answer& a, Language lang) {
    const auto whole = [](double v) { return std::to_string(static_cast<long long>(v)); };
    switch (ex.kind) {
        case ExerciseKind::NextCell: {
            std::string s;
            // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "," + to_string here.
            for (std::size_t i = 0; i < a.numbers.size(); ++i) {
                if (i) s += ',';
                s += whole(a.numbers[i]);
            }
            return s;
        }
        case ExerciseKind::Value:
        case ExerciseKind::Compute:
            return a.numbers.empty() ? "" : formatNumber(a.numbers[0], lang);
        case ExerciseKind::Count:
        case ExerciseKind::SweepPick:
            return a.numbers.empty() ? "" : whole(a.numbers[0]);
        case ExerciseKind::PickSplit:
            return a.numbers.size() < 2 ? ""
                                        : std::string(axisName(static_cast<int>(a.numbers[0]))) +
                                              "=" + formatNumber(a.numbers[1], lang);
        case ExerciseKind::HitOrMiss: {
            if (!a.hit) return "";
            // The answer's keywords, which parseAnswer reads in either language: a grammar, not
            // a translation (the catalogue's "hit" is the event list's noun, "intersezione").
            const bool it = lang == Language::It;
            if (!*a.hit) return it ? "mancata" : "miss";
            const std::string word = it ? "colpita" : "hit";
            return a.numbers.empty() ? word : word + " " + formatNumber(a.numbers[0], lang);
        }
        case ExerciseKind::Choice:
            return a.numbers.empty() ? "" : letter(static_cast<int>(a.numbers[0]));
        case ExerciseKind::Overlap:
            return a.numbers.size() != 2 ? "" : whole(a.numbers[0]) + " " + whole(a.numbers[1]);
        case ExerciseKind::Sequence: {
            std::string s;
            const std::size_t per = static_cast<std::size_t>(std::max(a.perItem, 1));
            for (std::size_t i = 0; i < a.numbers.size(); ++i) {
                if (i) s += ex.ofNodes ? " " : (i % per ? "," : "; ");
                s += whole(a.numbers[i]);
            }
            return s;
        }
    }
    return "";
}

std::vector<SplitCandidate> splitCandidates(const Exercise& ex, const EventLog& log) {
    std::vector<SplitCandidate> out;
    const auto at = resolvePosition(ex.at, log);
    if (!at) return out;
    const auto node = nextEvent<BuildNode>(log, *at);
    if (!node) return out;
    for (const Event& e : log.events())
        if (const auto* s = std::get_if<SplitCandidate>(&e); s && s->node == node->second.node)
            out.push_back(*s);
    return out;
}

Answer referenceAnswer(const Exercise& ex, const EventLog& log, const std::string& lessonFile,
                       const std::vector<GridSweepRow>* sweep) {
    return reference(contextOf(ex, log, lessonFile, sweep), Language::En).answer;
}

std::optional<std::size_t> answerEventIndex(const Exercise& ex, const EventLog& log,
                                            const std::string& lessonFile) {
    if (ex.kind == ExerciseKind::Choice || ex.kind == ExerciseKind::Compute ||
        ex.kind == ExerciseKind::SweepPick || ex.kind == ExerciseKind::Overlap)
        return std::nullopt;
    return reference(contextOf(ex, log, lessonFile, nullptr), Language::En).source;
}

std::string answerPlaceholder(const Exercise& ex, int dims, Language lang) {
    if (ex.kind == ExerciseKind::NextCell)
        return dims == 3 ? tr(lang, "X,Y,Z (the voxel's indices)")
                         : tr(lang, "X,Y (or click the cell in the 2D view)");
    if (ex.kind == ExerciseKind::Overlap) return tr(lang, "two node ids, e.g. 3 4");
    if (ex.kind != ExerciseKind::Sequence) return "";
    if (ex.ofNodes) return tr(lang, "node ids in order, e.g. 0 1 4");
    return dims == 3 ? tr(lang, "voxels in order, e.g. 0,0,0; 1,0,0")
                     : tr(lang, "cells in order, e.g. 0,0; 1,0 (or click them in the 2D view)");
}

std::string retryAdvice(const Exercise& ex, bool replayHeld, bool hintLeft, Language lang) {
    std::string advice;
    switch (ex.kind) {
        case ExerciseKind::Compute:
            advice = tr(lang,
                        "Work it again by hand from the data the prompt gives: the trace does "
                        "not hold them.");
            break;
        case ExerciseKind::Choice:
            advice = tr(lang,
                        "Read each option again and ask what the lecture's algorithm does in "
                        "that case.");
            break;
        case ExerciseKind::SweepPick:
            advice = tr(lang,
                        "Work out the metric for every row of the sweep's table and compare "
                        "them all.");
            break;
        case ExerciseKind::Overlap:
            advice = tr(lang,
                        "Look at the boxes in the 2D view again: two that share space, neither "
                        "inside the other (a child lies inside its parent).");
            break;
        default:
            if (!replayHeld) {
                advice = tr(lang, "Step the replay and look at the inspector.");
                break;
            }
            // Held at the exercise's position: what is on screen there is what there is to use.
            switch (ex.kind) {
                case ExerciseKind::NextCell:
                    advice = tr(lang,
                                "The replay waits here until you answer: compare the "
                                "current cell's tMax in the inspector.");
                    break;
                case ExerciseKind::Sequence:
                    advice = ex.ofNodes ? tr(lang,
                                             "The replay waits here until you answer: work out "
                                             "each node's [tNear, tFar] by hand, the nearer "
                                             "child first.")
                                        : tr(lang,
                                             "The replay waits here until you answer: work out the "
                                             "walk by hand, comparing the tMax at every cell.");
                    break;
                case ExerciseKind::Value:
                    advice = tr(lang,
                                "The replay waits here until you answer: put the ray's "
                                "numbers from the inspector into the formula.");
                    break;
                case ExerciseKind::Count:
                    advice = tr(lang,
                                "The replay waits here until you answer: work out from the "
                                "scene in the view what the rest of the trace must hold.");
                    break;
                case ExerciseKind::HitOrMiss:
                    advice = tr(lang,
                                "The replay waits here until you answer: look where the ray "
                                "goes in the views, or solve the test by hand with the "
                                "ray's and the primitive's numbers.");
                    break;
                case ExerciseKind::PickSplit:
                    advice = tr(lang,
                                "The replay waits here until you answer: compare the costs "
                                "of the candidates listed.");
                    break;
                default:
                    break;
            }
    }
    if (hintLeft) {
        advice += ' ';
        advice += tr(lang, "Or ask for a hint.");
    }
    return advice;
}

std::optional<std::size_t> quizLimit(const Exercise& ex, const EventLog& log) {
    // An overlap's answer is in the structure, drawn whole at every step: nothing to hold.
    if (ex.kind == ExerciseKind::Choice || ex.kind == ExerciseKind::Compute ||
        ex.kind == ExerciseKind::SweepPick || ex.kind == ExerciseKind::Overlap)
        return std::nullopt;
    return resolvePosition(ex.at, log);
}

Verdict checkAnswer(const Exercise& ex, const EventLog& log, const Answer& answer, Language lang,
                    const std::string& lessonFile, const std::vector<GridSweepRow>* sweep,
                    const LessonScene* scene) {
    Context c = contextOf(ex, log, lessonFile, sweep);
    c.scene = scene;
    const Reference r = reference(c, lang);
    const Answer& ref = r.answer;
    Verdict v;
    v.expected = formatAnswer(ex, ref, lang);
    switch (ex.kind) {
        case ExerciseKind::NextCell:
        case ExerciseKind::Count:
        case ExerciseKind::Choice:
            v.correct = answer.numbers == ref.numbers;
            break;
        case ExerciseKind::Sequence:
            v.correct = answer.numbers == ref.numbers &&
                        (answer.perItem == ref.perItem || answer.numbers.empty());
            break;
        case ExerciseKind::Overlap: {
            // Any pair of the tree's boxes that overlap is right, in either order.
            if (answer.numbers.size() != 2) break;
            const auto entered = treeNodes(c);
            const auto in = [&](double v) {
                return std::any_of(entered.begin(), entered.end(),
                                   [&](const auto& e) { return double(e.first) == v; });
            };
            v.correct = in(answer.numbers[0]) && in(answer.numbers[1]) &&
                        partlyOverlap(log, static_cast<std::uint32_t>(answer.numbers[0]),
                                      static_cast<std::uint32_t>(answer.numbers[1]));
            break;
        }
        case ExerciseKind::Value:
        case ExerciseKind::Compute:
            v.correct = answer.numbers.size() == 1 &&
                        close(answer.numbers[0], ref.numbers[0], ex.tolerance);
            break;
        case ExerciseKind::PickSplit: {
            // Any candidate as cheap as the cheapest is right (ties happen on symmetric scenes).
            if (answer.numbers.size() != 2) break;
            const double bestCost = [&] {
                double best = kInfinity;
                for (const SplitCandidate& s : splitCandidates(ex, log))
                    best = std::min(best, s.sahCost);
                return best;
            }();
            for (const SplitCandidate& s : splitCandidates(ex, log))
                if (s.axis == answer.numbers[0] && close(answer.numbers[1], s.position, 1e-9) &&
                    s.sahCost <= bestCost * (1.0 + 1e-12))
                    v.correct = true;
            break;
        }
        case ExerciseKind::HitOrMiss:
            v.correct =
                answer.hit == ref.hit && (!ex.withT || !*ref.hit ||
                                          (answer.numbers.size() == 1 &&
                                           close(answer.numbers[0], ref.numbers[0], ex.tolerance)));
            break;
        case ExerciseKind::SweepPick: {
            // Any resolution as low as the lowest is right.
            if (answer.numbers.size() != 1) break;
            double best = kInfinity;
            for (const GridSweepRow& row : *sweep) best = std::min(best, sweepMetric(ex, row));
            for (const GridSweepRow& row : *sweep)
                if (row.resolution == answer.numbers[0] &&
                    sweepMetric(ex, row) <= best * (1.0 + 1e-12))
                    v.correct = true;
            break;
        }
    }
    // What the wrong answer betrays, with the student's own numbers.
    if (!v.correct && !answer.numbers.empty()) {
        const double given = answer.numbers[0];
        switch (ex.kind) {
            case ExerciseKind::Value:
                v.slip = valueSlip(c, given, ref.numbers[0], *r.source, lang);
                break;
            case ExerciseKind::Compute:
                v.slip = computeSlip(ex, given, lang);
                break;
            case ExerciseKind::Count:
                v.slip = countSlip(c, given, ref.numbers[0], lang);
                break;
            case ExerciseKind::NextCell:
                v.slip = nextCellSlip(c, answer, *r.source, lang);
                break;
            case ExerciseKind::Sequence:
                v.slip = sequenceSlip(c, answer, ref, lang);
                break;
            case ExerciseKind::Overlap:
                v.slip = overlapSlip(c, answer, lang);
                break;
            case ExerciseKind::Choice: {
                if (given < 0 || given >= static_cast<double>(ex.choices.size())) break;
                const auto& chosen = ex.choices[static_cast<std::size_t>(given)];
                v.slip = trf(lang, "%1) %2: %3",
                             {letter(static_cast<int>(given)), optionText(chosen.text.in(lang)),
                              chosen.why.in(lang)});
                break;
            }
            case ExerciseKind::SweepPick: {
                std::string list;
                bool listed = false;
                for (const GridSweepRow& row : *sweep) {
                    list += (list.empty() ? "" : ", ") + std::to_string(row.resolution);
                    listed = listed || row.resolution == given;
                }
                v.slip = listed ? trf(lang, "At %1 the metric is higher than at %2.",
                                      {formatNumber(given, lang), v.expected})
                                : trf(lang, "%1 is not one of the sweep's resolutions (%2).",
                                      {formatNumber(given, lang), list});
                break;
            }
            case ExerciseKind::PickSplit: {
                if (answer.numbers.size() != 2) break;
                const auto candidates = splitCandidates(ex, log);
                const std::string plane = std::string(axisName(static_cast<int>(given))) + " = " +
                                          formatNumber(answer.numbers[1], lang);
                const SplitCandidate* mine = nullptr;
                for (const SplitCandidate& s : candidates)
                    if (s.axis == given && close(answer.numbers[1], s.position, 1e-9)) mine = &s;
                if (!mine) {
                    v.slip = trf(lang, "%1 is not one of the candidates listed.", {plane});
                    break;
                }
                const auto n = [&](double x) { return formatNumber(x, lang); };
                v.slip = trf(lang,
                             "%1 costs C_trav + C_isect (%2 · %3 + %4 · %5) = %6, more than the "
                             "cheapest.",
                             {plane, n(mine->pl), std::to_string(mine->nl), n(mine->pr),
                              std::to_string(mine->nr), n(mine->sahCost)});
                break;
            }
            case ExerciseKind::HitOrMiss:
                if (answer.hit == ref.hit && ref.hit == true && !ref.numbers.empty()) {
                    const auto* t = std::get_if<PrimitiveTest>(&log.events()[*r.source]);
                    v.slip = t ? rootSlip(c, given, ref.numbers[0], t->ray, t->prim, lang) : "";
                    if (v.slip.empty())
                        v.slip = trf(lang, "It is an intersection, but not at t = %1.",
                                     {formatNumber(given, lang)});
                }
                break;
            default:
                break;
        }
    }
    v.feedback = v.slip.empty() ? r.why : v.slip + " " + r.why;
    return v;
}

}  // namespace raystep
