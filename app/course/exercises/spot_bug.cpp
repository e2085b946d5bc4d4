// spot_bug: a DDA walk with one classic mistake in it (assess/mistakes.h), replayed as a trace of
// its own; the student names its first wrong step (0-based, as the board's step column) or
// clicks that cell. The answer is where the walk first departs from raystep's exact walk, found
// and explained by the assessor (assess.h) as for a student's own run.
#include "course/exercises/kind_unit.h"

#include "raystep/assess/assess.h"
#include "raystep/assess/mistakes.h"
#include "raystep/base/i18n.h"
#include "raystep/geometry/kernels.h"
#include "raystep/trace/event_text.h"

#include <algorithm>
#include <cmath>

namespace raystep::exercises {

namespace {

/// A walk that never ends by itself (no exit check, a NaN tMax) is replayed this far past its
/// first wrong cell: enough to see it go on.
constexpr std::size_t kShownPastTheBug = 3;

Mistake mistakeOf(const Exercise& ex) {
    // Checked when the lesson was read.
    return parseMistake(ex.mistake).value_or(Mistake::NegativeDirectionBoundary);
}

template <int N>
void recordWrongWalk(Mistake mistake, const GridRecord& g, const WalkRay& r, EventLog& log) {
    GridSpec<N, double> grid;
    VecN<N, double> o, d;
    int cap = N + 1;  // a walk that leaves the grid visits fewer cells
    for (int a = 0; a < N; ++a) {
        grid.lo[a] = g.lo[a];
        grid.hi[a] = g.hi[a];
        grid.res[a] = g.res[a];
        o[a] = r.o[a];
        d[a] = r.d[a];
        cap += g.res[a];
    }
    std::vector<WalkCell<N>> cells = ddaWithMistake<N>(grid, o, d, mistake, cap);
    Dda<N, double> dda(grid, o, d);
    DdaSetup setup{0, {0, 0, 0}, N, {0.0, 0.0, 0.0}, dda.tEnter(), dda.tGridExit()};
    const unsigned entered = dda.axesTaken();
    for (int a = 0; a < N; ++a) {
        setup.step[a] = static_cast<std::int8_t>(dda.step()[a]);
        setup.tDelta[a] = dda.tDelta()[a];
    }
    if (static_cast<int>(cells.size()) >= cap) {
        // It never ends by itself: kept to a few cells past its first wrong one.
        std::size_t k = 0;
        for (bool in = dda.valid(); in && k < cells.size() && dda.cell() == cells[k].cell;
             in = dda.next())
            ++k;
        cells.resize(std::min(cells.size(), k + 1 + kShownPastTheBug));
    }
    // The step the wrong walk takes on each axis (a parallel axis may step too).
    for (std::size_t k = 1; k < cells.size(); ++k)
        for (int a = 0; a < N; ++a)
            if (const int moved = cells[k].cell[a] - cells[k - 1].cell[a]; moved)
                setup.step[a] = static_cast<std::int8_t>(moved > 0 ? 1 : -1);
    log.setDims(N);
    log.setGrid(g);
    Ray ray;
    ray.origin = Vec3(r.o[0], r.o[1], N == 3 ? r.o[2] : 0.0);
    ray.dir = Vec3(r.d[0], r.d[1], N == 3 ? r.d[2] : 0.0);
    const std::uint32_t id = log.beginRay(ray, RayKind::Primary, 0, kNoId);
    if (!cells.empty()) {
        setup.ray = id;
        log(setup);
    }
    for (std::size_t k = 0; k < cells.size(); ++k) {
        DdaCell e{id, 0, {0, 0, 0}, {0.0, 0.0, 0.0}};
        unsigned axes = k == 0 ? entered : 0u;
        for (int a = 0; a < N; ++a) {
            e.cell[a] = cells[k].cell[a];
            e.tMax[a] = cells[k].tMax[a];
            if (k > 0 && cells[k].cell[a] != cells[k - 1].cell[a]) axes |= 1u << a;
        }
        e.axes = static_cast<std::uint8_t>(axes);
        log(e);
    }
    log(RayMiss{id});
}

/// The replayed walk: its ray, its cells and the events they are, and raystep's verdict on it.
struct Walk {
    StudentRay ray;
    std::vector<DdaCell> cells;
    std::vector<std::size_t> events;
    RayVerdict verdict;
};

Walk walkOf(const Context& c, Language lang) {
    const EventLog& log = c.log;
    if (!log.grid() || log.rays().empty())
        c.fail("its trace holds no replayed walk (a spot_bug exercise is read from its own trace)");
    Walk w;
    const int dims = log.dims() == 3 ? 3 : 2;
    const RayRecord& r = log.rays().front();
    w.ray.dims = dims;
    w.ray.origin = {r.origin.x, r.origin.y, r.origin.z};
    w.ray.dir = {r.dir.x, r.dir.y, r.dir.z};
    for (std::size_t i = 0; i < log.events().size(); ++i)
        if (const auto* e = std::get_if<DdaCell>(&log.events()[i])) {
            w.cells.push_back(*e);
            w.events.push_back(i);
            StudentRecord rec;
            rec.kind = StudentRecordKind::Cell;
            rec.line = static_cast<int>(w.cells.size());
            for (int a = 0; a < dims; ++a) rec.cell[a] = e->cell[a];
            // Cells only: the question is the first wrong cell, not the first wrong tMax.
            w.ray.records.push_back(rec);
        }
    if (w.cells.empty()) c.fail("its ray misses the grid: the walk visits no cell");
    GridSpec<3, double> grid;
    for (int a = 0; a < 3; ++a) {
        grid.lo[a] = log.grid()->lo[a];
        grid.hi[a] = log.grid()->hi[a];
        grid.res[a] = log.grid()->res[a];
    }
    const StudentTrace trace{c.file, {w.ray}};
    Assessment a = assess(trace, raystep::Reference::dda(grid, dims), lang);
    w.verdict = std::move(a.rays.front());
    const std::string name(mistakeInfo(mistakeOf(c.ex)).name);
    if (!w.verdict.divergence)
        c.fail("the mistake " + name +
               " walks this ray as the exact walk does: choose a ray on which it goes wrong");
    if (w.verdict.divergence->index < 0 ||
        static_cast<std::size_t>(w.verdict.divergence->index) >= w.cells.size())
        c.fail("with the mistake " + name +
               " the walk stops early without entering a wrong cell: choose a ray on which it "
               "enters one");
    return w;
}

std::string stepCell(const DdaCell& e, int dims) {
    return cellText(e.cell, dims);
}

/// The step of `given` in the walk: a step number as typed, or the step of a clicked cell.
std::optional<std::size_t> stepOf(const Walk& w, const Answer& given, int dims) {
    if (given.numbers.size() == 1) {
        if (given.numbers[0] < 0) return std::nullopt;
        return static_cast<std::size_t>(given.numbers[0]);
    }
    if (static_cast<int>(given.numbers.size()) != dims) return std::nullopt;
    for (std::size_t k = 0; k < w.cells.size(); ++k) {
        bool same = true;
        for (int a = 0; a < dims; ++a) same = same && w.cells[k].cell[a] == given.numbers[a];
        if (same) return k;
    }
    return std::nullopt;
}

bool sameTime(double a, double b) {
    if (std::isnan(a) || std::isnan(b)) return false;
    if (std::isinf(a) || std::isinf(b)) return a == b;
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

class SpotBug final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::SpotBug; }
    std::string_view name() const override { return "spot_bug"; }
    std::vector<const char*> keys() const override { return {"mistake", "ray"}; }

    void read(const LessonReader& r, const detail::json& j, const std::string& path,
              Exercise& ex) const override {
        const std::string mp = JsonLineMap::child(path, "mistake");
        if (!j.contains("mistake")) r.fail(path, "a spot_bug exercise names its \"mistake\"");
        ex.mistake = r.string(j["mistake"], mp);
        const auto m = parseMistake(ex.mistake);
        std::string names;
        for (const MistakeInfo& info : mistakes())
            if (info.dda) names += (names.empty() ? "" : ", ") + std::string(info.name);
        if (!m || !mistakeInfo(*m).dda) r.fail(mp, "expected a mistake of the DDA walk: " + names);
        ifPresent(j, path, "ray", [&](const detail::json& v, const std::string& p) {
            r.requireObject(v, p);
            r.checkKeys(v, p, {"o", "d"});
            WalkRay ray;
            const auto vector = [&](const char* key, std::array<double, 3>& out) {
                const std::string kp = JsonLineMap::child(p, key);
                if (!v.contains(key) || !v[key].is_array() || v[key].size() < 2 ||
                    v[key].size() > 3)
                    r.fail(kp, "expected [X, Y] or [X, Y, Z]");
                for (std::size_t i = 0; i < v[key].size(); ++i)
                    out[i] = r.number(v[key][i], JsonLineMap::element(kp, i));
                return static_cast<int>(v[key].size());
            };
            ray.dims = vector("o", ray.o);
            if (vector("d", ray.d) != ray.dims)
                r.fail(JsonLineMap::child(p, "d"), "the origin and the direction differ in length");
            double reach = 0.0, largest = 0.0;
            for (int a = 0; a < ray.dims; ++a) {
                reach = std::max(reach, std::abs(ray.o[a]));
                largest = std::max(largest, std::abs(ray.d[a]));
            }
            if (largest == 0.0) r.fail(JsonLineMap::child(p, "d"), "must not be zero");
            if (const auto problem = rayRangeProblem(Precision::Double, reach, largest))
                r.fail(p, *problem);
            ex.walkRay = ray;
        });
    }

    bool replaysOwnWalk() const override { return true; }

    void recordWalk(const Exercise& ex, const GridRecord& grid, int dims, const WalkRay& ray,
                    EventLog& log) const override {
        if (dims == 3)
            recordWrongWalk<3>(mistakeOf(ex), grid, ray, log);
        else
            recordWrongWalk<2>(mistakeOf(ex), grid, ray, log);
    }

    Reference reference(const Context& c, Language lang) const override {
        const Walk w = walkOf(c, lang);
        const Divergence& d = *w.verdict.divergence;
        const int dims = c.log.dims() == 3 ? 3 : 2;
        const auto k = static_cast<std::size_t>(d.index);
        Reference ref;
        ref.answer.numbers.push_back(static_cast<double>(k));
        ref.source = w.events[k];
        const std::vector<ReferenceUnit>& exact = w.verdict.reference.units;
        const std::string step = std::to_string(k), wrong = stepCell(w.cells[k], dims);
        std::string where =
            k < exact.size()
                ? trf(lang,
                      "At step %1 the replayed walk enters its first wrong cell, %2; the exact "
                      "walk enters %3.",
                      {step, wrong,
                       cellText(
                           {int(exact[k].cell[0]), int(exact[k].cell[1]), int(exact[k].cell[2])},
                           dims)})
                : trf(lang,
                      "At step %1 the replayed walk enters its first wrong cell, %2; the exact "
                      "walk has already left the grid, after %3 cells.",
                      {step, wrong, std::to_string(exact.size())});
        const MistakeInfo& info = mistakeInfo(mistakeOf(c.ex));
        // i18n: the descriptions are marked in mistakes.cpp
        const std::string description = tr(lang, info.description);
        ref.why = where + " " +
                  trf(lang, "Were this walk a student's, raystep's assessment would say: %1",
                      {d.explanation}) +
                  " " + trf(lang, "The bug, %1: %2.", {std::string(info.name), description});
        return ref;
    }

    std::optional<Answer> parse(const Exercise&, std::string_view text, std::string* why,
                                Language lang) const override {
        const std::string expected =
            tr(lang, "expected a step number (0 is the walk's first cell) or a cell X,Y");
        const auto parts = splitAny(text, "(), ;\t");
        Answer a;
        if (parts.size() == 1) {
            const auto v = parseWhole(parts[0]);
            if (!v || *v < 0) return rejected(why, expected);
            a.numbers.push_back(static_cast<double>(*v));
            return a;
        }
        if (parts.size() < 2 || parts.size() > 3) return rejected(why, expected);
        for (const auto p : parts) {
            const auto v = parseWhole(p);
            if (!v) return rejected(why, tr(lang, "cell indices are whole numbers"));
            a.numbers.push_back(static_cast<double>(*v));
        }
        return a;
    }

    std::string format(const Exercise&, const Answer& a, Language) const override {
        return wholes(a.numbers);
    }

    bool grade(const Context& c, const Answer& given, const Reference& ref) const override {
        // A clicked cell is the step it is in the replayed walk.
        if (given.numbers.size() == 1) return given.numbers == ref.answer.numbers;
        const Walk w = walkOf(c, Language::En);
        const auto k = stepOf(w, given, c.log.dims() == 3 ? 3 : 2);
        return k && static_cast<double>(*k) == ref.answer.numbers[0];
    }

    std::string slip(const Context& c, const Answer& given, const Reference& ref,
                     const std::string&, Language lang) const override {
        const Walk w = walkOf(c, lang);
        const int dims = c.log.dims() == 3 ? 3 : 2;
        const auto k = stepOf(w, given, dims);
        if (!k) {
            if (given.numbers.size() == 1) return "";
            std::array<std::int32_t, 3> cell{0, 0, 0};
            for (int a = 0; a < dims && a < int(given.numbers.size()); ++a)
                cell[a] = static_cast<std::int32_t>(given.numbers[a]);
            return trf(lang, "The replayed walk does not enter %1.", {cellText(cell, dims)});
        }
        const auto right = static_cast<std::size_t>(ref.answer.numbers[0]);
        if (*k >= w.cells.size())
            return trf(lang, "The replayed walk has steps 0 to %1 only.",
                       {std::to_string(w.cells.size() - 1)});
        if (*k > right)
            return trf(lang,
                       "Step %1 is wrong, but not the first wrong one: the walk has already "
                       "parted from the exact walk before it.",
                       {std::to_string(*k)});
        if (*k == right) return "";
        // A right cell before the first wrong one: its tMax may already carry the bug.
        const std::string cell = stepCell(w.cells[*k], dims);
        const ReferenceUnit& exact = w.verdict.reference.units[*k];
        for (int a = 0; a < dims; ++a)
            if (!sameTime(w.cells[*k].tMax[a], exact.tMax[a]))
                return trf(
                    lang,
                    "At step %1 the walk is in %2, the right cell; its tMax%3 = %4 is not "
                    "the exact %5, though: the bug is already made there, and a later "
                    "step goes wrong because of it.",
                    {std::to_string(*k), cell, std::string(1, "XYZ"[a]),
                     formatNumber(w.cells[*k].tMax[a], lang), formatNumber(exact.tMax[a], lang)});
        return trf(lang,
                   "At step %1 the walk is in %2, the right cell: the exact walk enters it too.",
                   {std::to_string(*k), cell});
    }

    std::string retryAdvice(const Exercise&, bool, Language lang) const override {
        // The replay is free: the whole wrong walk is on screen, its answer is no later event.
        return tr(lang,
                  "Step through the replayed walk from its first cell and check each step "
                  "against the exact rule: the smallest tMax says the axis.");
    }
    // The whole wrong walk is what the student studies: quiz mode does not hold its replay.
    bool answerInTrace() const override { return false; }

    std::string placeholder(const Exercise&, int dims, Language lang) const override {
        return dims == 3 ? tr(lang, "a step number (0 is the first voxel)")
                         : tr(lang, "a step number (0 is the first cell), or click the cell");
    }

    AnswerInputSpec input(const Exercise&) const override {
        return {AnswerInputSpec::Widget::Text, AnswerInputSpec::ViewClick::Fills};
    }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        // The step number is exempt, as a count is (a small whole number in every text); the
        // first wrong cell, the answer as clicked, is not.
        const Context c = contextOf(in.ex, in.log, in.file, in.sweep);
        const Walk w = walkOf(c, Language::En);
        const auto k = static_cast<std::size_t>(w.verdict.divergence->index);
        const int dims = in.log.dims() == 3 ? 3 : 2;
        Answer cell;
        for (int a = 0; a < dims; ++a) cell.numbers.push_back(w.cells[k].cell[a]);
        addLeakCells(f, cell, dims);
        f.describe = "step " + std::to_string(k) + ", " + stepCell(w.cells[k], dims);
    }
};

}  // namespace

const ExerciseKindUnit& spotBugUnit() {
    static const SpotBug unit;
    return unit;
}

}  // namespace raystep::exercises
