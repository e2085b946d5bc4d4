// pick_split: the cheapest of a kd-tree node's split candidates (the SAH), picked from those
// listed; a wrong plane is either not a candidate or costs more, with its cost worked out.
#include "course/exercises/kind_unit.h"

#include "course/feedback_text.h"

#include "raystep/base/i18n.h"
#include "raystep/base/math.h"

#include <algorithm>

namespace raystep::exercises {

using feedback::axisName;

namespace {

class PickSplit final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::PickSplit; }
    std::string_view name() const override { return "pick_split"; }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        const EventLog& log = c.log;
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
        return ref;
    }

    std::optional<Answer> parse(const Exercise&, std::string_view text, std::string* why,
                                Language lang) const override {
        Answer a;
        const std::string s = lower(text);
        const auto eq = s.find('=');
        if (eq == std::string::npos)
            return rejected(why, tr(lang, "expected a split plane as x=POSITION (or y=, z=)"));
        const auto axisPart = splitAny(std::string_view(s).substr(0, eq), " \t");
        if (axisPart.size() != 1 || axisPart[0].size() != 1 ||
            std::string_view("xyz").find(axisPart[0][0]) == std::string_view::npos)
            return rejected(why, tr(lang, "the axis is x, y or z"));
        const auto v = parseNumber(std::string_view(s).substr(eq + 1));
        if (!v) return rejected(why, tr(lang, "expected a number after '='"));
        a.numbers = {static_cast<double>(axisPart[0][0] - 'x'), *v};
        return a;
    }

    std::string format(const Exercise&, const Answer& a, Language lang) const override {
        return a.numbers.size() < 2 ? ""
                                    : std::string(axisName(static_cast<int>(a.numbers[0]))) + "=" +
                                          formatNumber(a.numbers[1], lang);
    }

    bool grade(const Context& c, const Answer& answer, const Reference&) const override {
        // Any candidate as cheap as the cheapest is right (ties happen on symmetric scenes).
        if (answer.numbers.size() != 2) return false;
        const double bestCost = [&] {
            double best = kInfinity;
            for (const SplitCandidate& s : splitCandidates(c.ex, c.log))
                best = std::min(best, s.sahCost);
            return best;
        }();
        bool correct = false;
        for (const SplitCandidate& s : splitCandidates(c.ex, c.log))
            if (s.axis == answer.numbers[0] && close(answer.numbers[1], s.position, 1e-9) &&
                s.sahCost <= bestCost * (1.0 + 1e-12))
                correct = true;
        return correct;
    }

    std::string slip(const Context& c, const Answer& answer, const Reference&, const std::string&,
                     Language lang) const override {
        if (answer.numbers.size() != 2) return "";
        const double given = answer.numbers[0];
        const auto candidates = splitCandidates(c.ex, c.log);
        const std::string plane = std::string(axisName(static_cast<int>(given))) + " = " +
                                  formatNumber(answer.numbers[1], lang);
        const SplitCandidate* mine = nullptr;
        for (const SplitCandidate& s : candidates)
            if (s.axis == given && close(answer.numbers[1], s.position, 1e-9)) mine = &s;
        if (!mine) return trf(lang, "%1 is not one of the candidates listed.", {plane});
        const auto n = [&](double x) { return formatNumber(x, lang); };
        return trf(lang,
                   "%1 costs C_trav + C_isect (%2 · %3 + %4 · %5) = %6, more than the "
                   "cheapest.",
                   {plane, n(mine->pl), std::to_string(mine->nl), n(mine->pr),
                    std::to_string(mine->nr), n(mine->sahCost)});
    }

    std::string retryAdvice(const Exercise&, bool replayHeld, Language lang) const override {
        if (!replayHeld) return stepTheReplayAdvice(lang);
        return tr(lang,
                  "The replay waits here until you answer: compare the costs "
                  "of the candidates listed.");
    }

    AnswerInputSpec input(const Exercise&) const override {
        return {AnswerInputSpec::Widget::SplitPicker};
    }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        const Answer a = referenceAnswer(in.ex, in.log, in.file, in.sweep);
        f.plane = AnswerForms::Plane{static_cast<int>(a.numbers.at(0)), a.numbers.at(1)};
        f.describe = formatAnswer(in.ex, a);
    }
};

}  // namespace

const ExerciseKindUnit& pickSplitUnit() {
    static const PickSplit unit;
    return unit;
}

}  // namespace raystep::exercises
