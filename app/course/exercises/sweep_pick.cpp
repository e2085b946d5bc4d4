// sweep_pick: the resolution of the grid sweep's row with the lowest metric (the cost, tests or
// cells per ray); graded from the lesson's sweep, not from the trace.
#include "course/exercises/kind_unit.h"

#include "raystep/base/i18n.h"
#include "raystep/base/math.h"

#include <algorithm>

namespace raystep::exercises {

namespace {

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

class SweepPick final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::SweepPick; }
    std::string_view name() const override { return "sweep_pick"; }
    std::vector<const char*> keys() const override { return {"metric"}; }

    void read(const LessonReader& r, const detail::json& j, const std::string& path,
              Exercise& ex) const override {
        ifPresent(j, path, "metric", [&](const detail::json& v, const std::string& p) {
            const std::string name = r.string(v, p);
            std::optional<SweepMetric> m;
            for (const SweepMetric s :
                 {SweepMetric::Cost, SweepMetric::TestsPerRay, SweepMetric::CellsPerRay})
                if (sweepMetricName(s) == name) m = s;
            if (!m) r.fail(p, "expected cost, tests_per_ray or cells_per_ray");
            ex.metric = *m;
        });
    }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        const auto n = [&](double v) { return formatNumber(v, lang); };
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
        return ref;
    }

    std::optional<Answer> parse(const Exercise&, std::string_view text, std::string* why,
                                Language lang) const override {
        const auto bad = [&](const std::string& message) { return rejected(why, message); };
        Answer a;
        const auto v = parseWhole(text);
        if (!v || *v < 1)
            return bad(tr(lang, "expected a resolution: cells per axis, a whole number"));
        a.numbers.push_back(static_cast<double>(*v));
        return a;
    }

    std::string format(const Exercise&, const Answer& a, Language) const override {
        return a.numbers.empty() ? "" : whole(a.numbers[0]);
    }

    bool grade(const Context& c, const Answer& answer, const Reference&) const override {
        // Any resolution as low as the lowest is right.
        if (answer.numbers.size() != 1) return false;
        double best = kInfinity;
        for (const GridSweepRow& row : *c.sweep) best = std::min(best, sweepMetric(c.ex, row));
        bool correct = false;
        for (const GridSweepRow& row : *c.sweep)
            if (row.resolution == answer.numbers[0] &&
                sweepMetric(c.ex, row) <= best * (1.0 + 1e-12))
                correct = true;
        return correct;
    }

    std::string slip(const Context& c, const Answer& answer, const Reference&,
                     const std::string& expected, Language lang) const override {
        const double given = answer.numbers[0];
        std::string list;
        bool listed = false;
        for (const GridSweepRow& row : *c.sweep) {
            list += (list.empty() ? "" : ", ") + std::to_string(row.resolution);
            listed = listed || row.resolution == given;
        }
        return listed ? trf(lang, "At %1 the metric is higher than at %2.",
                            {formatNumber(given, lang), expected})
                      : trf(lang, "%1 is not one of the sweep's resolutions (%2).",
                            {formatNumber(given, lang), list});
    }

    std::string retryAdvice(const Exercise&, bool, Language lang) const override {
        return tr(lang,
                  "Work out the metric for every row of the sweep's table and compare "
                  "them all.");
    }
    bool answerInTrace() const override { return false; }
    AnswerInputSpec input(const Exercise&) const override {
        return {AnswerInputSpec::Widget::SweepRows};
    }
    bool needsSweep() const override { return true; }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        const Answer a = referenceAnswer(in.ex, in.log, in.file, in.sweep);
        f.resolution = static_cast<int>(a.numbers.at(0));
        f.describe = formatAnswer(in.ex, a) + " cells per axis";
    }
};

}  // namespace

const ExerciseKindUnit& sweepPickUnit() {
    static const SweepPick unit;
    return unit;
}

}  // namespace raystep::exercises
