// overlap: two boxes of a BVH that share space, neither inside the other (what a space
// subdivision's cells never do); any such pair is right, read from the trace's node boxes.
#include "course/exercises/kind_unit.h"

#include "raystep/base/i18n.h"

#include <algorithm>

namespace raystep::exercises {

namespace {

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
            if (k) s += listSeparator(lang);
            s += formatNumber(v[k], lang);
        }
        return s + ")";
    };
    return corner(r.lo) + "\u2013" + corner(r.hi);
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

class Overlap final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::Overlap; }
    std::string_view name() const override { return "overlap"; }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        const EventLog& log = c.log;
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
        why = trf(lang,
                  "Node %1's box %2 and node %3's box %4 share space, and neither lies inside "
                  "the other: a ray through the shared space must enter both. The pairs of the "
                  "tree's boxes that overlap: %5.",
                  {std::to_string(pairs[0].first), nodeBoxText(log, pairs[0].first, lang),
                   std::to_string(pairs[0].second), nodeBoxText(log, pairs[0].second, lang), all});
        return ref;
    }

    std::optional<Answer> parse(const Exercise&, std::string_view text, std::string* why,
                                Language lang) const override {
        const auto bad = [&](const std::string& message) { return rejected(why, message); };
        Answer a;
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

    std::string format(const Exercise&, const Answer& a, Language) const override {
        return a.numbers.size() != 2 ? "" : whole(a.numbers[0]) + " " + whole(a.numbers[1]);
    }

    bool grade(const Context& c, const Answer& answer, const Reference&) const override {
        // Any pair of the tree's boxes that overlap is right, in either order.
        if (answer.numbers.size() != 2) return false;
        const auto entered = treeNodes(c);
        const auto in = [&](double v) {
            return std::any_of(entered.begin(), entered.end(),
                               [&](const auto& e) { return double(e.first) == v; });
        };
        return in(answer.numbers[0]) && in(answer.numbers[1]) &&
               partlyOverlap(c.log, static_cast<std::uint32_t>(answer.numbers[0]),
                             static_cast<std::uint32_t>(answer.numbers[1]));
    }

    std::string slip(const Context& c, const Answer& answer, const Reference&, const std::string&,
                     Language lang) const override {
        return overlapSlip(c, answer, lang);
    }

    std::string retryAdvice(const Exercise&, bool, Language lang) const override {
        return tr(lang,
                  "Look at the boxes in the 2D view again: two that share space, neither "
                  "inside the other (a child lies inside its parent).");
    }
    // An overlap's answer is in the structure, drawn whole at every step: nothing to hold.
    bool answerInTrace() const override { return false; }
    std::string placeholder(const Exercise&, int, Language lang) const override {
        return tr(lang, "two node ids, e.g. 3 4");
    }
    bool needsNodeBoxes() const override { return true; }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        const Answer a = referenceAnswer(in.ex, in.log, in.file, in.sweep);
        // Every right pair is an answer: each one written gives the exercise away.
        std::vector<int> ids;
        for (std::size_t id = 0; id < in.log.nodes().size(); ++id) ids.push_back(int(id));
        for (std::size_t j = 0; j < ids.size(); ++j)
            for (std::size_t i = 0; i < ids.size(); ++i) {
                if (i == j) continue;
                Answer pair;
                pair.numbers = {double(ids[i]), double(ids[j])};
                if (checkAnswer(in.ex, in.log, pair, Language::En, in.file).correct)
                    f.nodePairs.push_back({ids[i], ids[j]});
            }
        f.describe = "nodes " + formatAnswer(in.ex, a);
    }
};

}  // namespace

const ExerciseKindUnit& overlapUnit() {
    static const Overlap unit;
    return unit;
}

}  // namespace raystep::exercises
