// count: how many events of a kind (rays of a kind and depth, for ray_begin) a range holds; a
// wrong count that counts every ray, or the whole trace, says so.
#include "course/exercises/kind_unit.h"

#include "course/feedback_text.h"
#include "course/lesson_trace.h"

#include "raystep/base/i18n.h"
#include "raystep/base/names.h"
#include "raystep/trace/event_text.h"

#include <cmath>

namespace raystep::exercises {

using lesson_reading::eventKindList;
using lesson_reading::eventKindNamed;

namespace {

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

class Count final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::Count; }
    std::string_view name() const override { return "count"; }
    std::vector<const char*> keys() const override {
        return {"count", "ray_kind", "ray_depth", "until"};
    }

    void read(const LessonReader& r, const detail::json& j, const std::string& path,
              Exercise& ex) const override {
        ifPresent(j, path, "until", [&](const detail::json& v, const std::string& p) {
            ex.until = lesson_reading::readPosition(r, v, p);
        });
        if (!j.contains("count")) r.fail(path, "a count exercise names the event it counts");
        const std::string p = JsonLineMap::child(path, "count");
        const auto k = eventKindNamed(r.string(j["count"], p));
        if (!k) r.fail(p, "unknown event kind (expected one of " + eventKindList() + ")");
        ex.countKind = *k;
        ifPresent(j, path, "ray_kind", [&](const detail::json& v, const std::string& rp) {
            const std::string name = r.string(v, rp);
            for (int i = 0; i < kRayKindCount; ++i)
                if (kRayKindNames[i] == name) ex.rayKind = static_cast<RayKind>(i);
            if (!ex.rayKind)
                r.fail(rp, "expected primary, shadow, reflection, refraction or diffuse");
            if (ex.countKind != variantIndex<RayBegin>())
                r.fail(rp, "only a count of ray_begin events can name a ray kind");
        });
        ifPresent(j, path, "ray_depth", [&](const detail::json& v, const std::string& rp) {
            ex.rayDepth = r.integer(v, rp, 0, 64);
            if (ex.countKind != variantIndex<RayBegin>())
                r.fail(rp, "only a count of ray_begin events can name a ray depth");
        });
    }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        const EventLog& log = c.log;
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
        return ref;
    }

    std::optional<Answer> parse(const Exercise&, std::string_view text, std::string* why,
                                Language lang) const override {
        auto a = parseOneNumber(text, why, lang);
        if (a && (a->numbers[0] < 0 || a->numbers[0] != std::floor(a->numbers[0])))
            return rejected(why, tr(lang, "a count is a whole number, 0 or more"));
        return a;
    }

    std::string format(const Exercise&, const Answer& a, Language) const override {
        return a.numbers.empty() ? "" : whole(a.numbers[0]);
    }

    bool grade(const Context&, const Answer& given, const Reference& ref) const override {
        return given.numbers == ref.answer.numbers;
    }

    std::string slip(const Context& c, const Answer& given, const Reference& ref,
                     const std::string&, Language lang) const override {
        return countSlip(c, given.numbers[0], ref.answer.numbers[0], lang);
    }

    std::string retryAdvice(const Exercise&, bool replayHeld, Language lang) const override {
        if (!replayHeld) return stepTheReplayAdvice(lang);
        return tr(lang,
                  "The replay waits here until you answer: work out from the "
                  "scene in the view what the rest of the trace must hold.");
    }

    std::string placeholder(const Exercise&, int, Language lang) const override {
        return tr(lang, "a whole number");
    }
    // No answer forms: a count is one small whole number among many in every text.
};

}  // namespace

const ExerciseKindUnit& countUnit() {
    static const Count unit;
    return unit;
}

}  // namespace raystep::exercises
