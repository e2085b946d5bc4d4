// sequence: the cells the DDA visits, or the nodes TestTree enters, in order; a wrong order is
// answered where it departs from the trace's, with why the trace goes there.
#include "course/exercises/kind_unit.h"

#include "course/feedback_text.h"

#include "raystep/base/i18n.h"
#include "raystep/trace/event_text.h"

#include <algorithm>

namespace raystep::exercises {

namespace {

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
    const std::string place = ordinal(lang, static_cast<int>(k + 1));
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

class Sequence final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::Sequence; }
    std::string_view name() const override { return "sequence"; }
    std::vector<const char*> keys() const override { return {"of", "length", "until"}; }

    void read(const LessonReader& r, const detail::json& j, const std::string& path,
              Exercise& ex) const override {
        ifPresent(j, path, "until", [&](const detail::json& v, const std::string& p) {
            ex.until = lesson_reading::readPosition(r, v, p);
        });
        if (!j.contains("of")) r.fail(path, "a sequence exercise names what it orders: \"of\"");
        const std::string op = JsonLineMap::child(path, "of");
        const std::string of = r.string(j["of"], op);
        if (of != "dda_cell" && of != "node_enter")
            r.fail(op, "expected \"dda_cell\" (the cells in order) or \"node_enter\" (the nodes)");
        ex.ofNodes = of == "node_enter";
        ifPresent(j, path, "length", [&](const detail::json& v, const std::string& p) {
            ex.length = r.integer(v, p, 1, 10'000);
        });
    }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        const EventLog& log = c.log;
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
        return ref;
    }

    std::optional<Answer> parse(const Exercise& ex, std::string_view text, std::string* why,
                                Language lang) const override {
        const auto bad = [&](const std::string& message) { return rejected(why, message); };
        Answer a;
        if (ex.ofNodes) {
            for (const auto p : splitAny(text, " ,;\t")) {
                const auto v = parseWhole(p);
                if (!v || *v < 0)
                    return bad(tr(lang, "expected node ids in order, as 0 1 4 (whole numbers)"));
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

    std::string format(const Exercise& ex, const Answer& a, Language) const override {
        std::string s;
        const std::size_t per = static_cast<std::size_t>(std::max(a.perItem, 1));
        for (std::size_t i = 0; i < a.numbers.size(); ++i) {
            if (i) s += ex.ofNodes ? " " : (i % per ? "," : "; ");
            s += whole(a.numbers[i]);
        }
        return s;
    }

    bool grade(const Context&, const Answer& answer, const Reference& r) const override {
        const Answer& ref = r.answer;
        return answer.numbers == ref.numbers &&
               (answer.perItem == ref.perItem || answer.numbers.empty());
    }

    std::string slip(const Context& c, const Answer& answer, const Reference& r, const std::string&,
                     Language lang) const override {
        return sequenceSlip(c, answer, r.answer, lang);
    }

    std::string retryAdvice(const Exercise& ex, bool replayHeld, Language lang) const override {
        if (!replayHeld) return stepTheReplayAdvice(lang);
        return ex.ofNodes ? tr(lang,
                               "The replay waits here until you answer: work out "
                               "each node's [tNear, tFar] by hand, the nearer "
                               "child first.")
                          : tr(lang,
                               "The replay waits here until you answer: work out the "
                               "walk by hand, comparing the tMax at every cell.");
    }

    std::string placeholder(const Exercise& ex, int dims, Language lang) const override {
        if (ex.ofNodes) return tr(lang, "node ids in order, e.g. 0 1 4");
        return dims == 3 ? tr(lang, "voxels in order, e.g. 0,0,0; 1,0,0")
                         : tr(lang, "cells in order, e.g. 0,0; 1,0 (or click them in the 2D view)");
    }

    AnswerInputSpec input(const Exercise& ex) const override {
        return {AnswerInputSpec::Widget::Text, ex.ofNodes ? AnswerInputSpec::ViewClick::None
                                                          : AnswerInputSpec::ViewClick::Appends};
    }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        const Answer a = referenceAnswer(in.ex, in.log, in.file, in.sweep);
        if (in.ex.ofNodes) {
            for (const double n : a.numbers) f.nodes.push_back(static_cast<int>(n));
        } else {
            addLeakCells(f, a, std::max(a.perItem, 1));
        }
        f.describe = formatAnswer(in.ex, a);
    }
};

}  // namespace

const ExerciseKindUnit& sequenceUnit() {
    static const Sequence unit;
    return unit;
}

}  // namespace raystep::exercises
