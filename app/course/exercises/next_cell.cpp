// next_cell: the cell the DDA visits next, typed as X,Y (or X,Y,Z) or clicked in the 2D view;
// a wrong cell names the entry face's off-by-one, the slides' detour on a tie, or the wrong axis.
#include "course/exercises/kind_unit.h"

#include "course/feedback_text.h"

#include "raystep/base/i18n.h"
#include "raystep/trace/event_text.h"
#include "raystep/trace/replay.h"

namespace raystep::exercises {

using feedback::axisName;

namespace {

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

class NextCell final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::NextCell; }
    std::string_view name() const override { return "next_cell"; }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        const EventLog& log = c.log;
        const auto next = nextEvent<DdaCell>(log, c.at);
        if (!next) c.fail("no DDA cell follows its position in the trace");
        const int dims = log.dims();
        for (int i = 0; i < dims; ++i) a.numbers.push_back(next->second.cell[i]);
        why =
            feedback::nextCell(lang, previousEvent<DdaCell>(log, next->first), next->second, dims);
        ref.source = next->first;
        return ref;
    }

    std::optional<Answer> parse(const Exercise&, std::string_view text, std::string* why,
                                Language lang) const override {
        const auto bad = [&](const std::string& message) -> std::optional<Answer> {
            if (why) *why = message;
            return std::nullopt;
        };
        Answer a;
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

    std::string format(const Exercise&, const Answer& a, Language) const override {
        return wholes(a.numbers);
    }

    bool grade(const Context&, const Answer& given, const Reference& ref) const override {
        return given.numbers == ref.answer.numbers;
    }

    std::string slip(const Context& c, const Answer& given, const Reference& ref,
                     const std::string&, Language lang) const override {
        return nextCellSlip(c, given, *ref.source, lang);
    }

    std::string retryAdvice(const Exercise& ex, bool replayHeld, Language lang) const override {
        if (!replayHeld) return stepTheReplayAdvice(lang);
        // Held before the walk's first cell: there is no current cell on screen to compare.
        const bool beforeTheWalk =
            heldAtTheStart(ex) || (ex.at.mode == ReplayPosition::Mode::BeforeEvent &&
                                   ex.at.eventKind == variantIndex<DdaCell>() && ex.at.nth == 1);
        if (beforeTheWalk)
            return tr(lang,
                      "The replay waits here until you answer, before the walk's first cell: "
                      "work it out from the ray and the grid the exercise gives.");
        // Held at the exercise's position: what is on screen there is what there is to use.
        return tr(lang,
                  "The replay waits here until you answer: compare the "
                  "current cell's tMax in the inspector.");
    }

    std::string placeholder(const Exercise&, int dims, Language lang) const override {
        return dims == 3 ? tr(lang, "X,Y,Z (the voxel's indices)")
                         : tr(lang, "X,Y (or click the cell in the 2D view)");
    }

    AnswerInputSpec input(const Exercise&) const override {
        return {AnswerInputSpec::Widget::Text, AnswerInputSpec::ViewClick::Fills};
    }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        const Answer a = referenceAnswer(in.ex, in.log, in.file, in.sweep);
        addLeakCells(f, a, static_cast<int>(a.numbers.size()));
        f.describe = formatAnswer(in.ex, a);
    }
};

}  // namespace

const ExerciseKindUnit& nextCellUnit() {
    static const NextCell unit;
    return unit;
}

}  // namespace raystep::exercises
