// hit_or_miss: the next primitive test's verdict, and its t when asked ("hit 3.55", "miss");
// a wrong t names the far root or the root halved or doubled.
#include "course/exercises/kind_unit.h"

#include "course/feedback_text.h"
#include "course/miss_cause.h"

#include "raystep/base/i18n.h"

namespace raystep::exercises {

namespace {

class HitOrMiss final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::HitOrMiss; }
    std::string_view name() const override { return "hit_or_miss"; }
    std::vector<const char*> keys() const override { return {"with_t"}; }

    void read(const LessonReader& r, const detail::json& j, const std::string& path,
              Exercise& ex) const override {
        ifPresent(j, path, "with_t", [&](const detail::json& v, const std::string& p) {
            if (!v.is_boolean()) r.fail(p, "expected true or false");
            ex.withT = v.get<bool>();
        });
    }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        const EventLog& log = c.log;
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
        return ref;
    }

    std::optional<Answer> parse(const Exercise& ex, std::string_view text, std::string* why,
                                Language lang) const override {
        const auto bad = [&](const std::string& message) { return rejected(why, message); };
        Answer a;
        const auto expected = [&] {
            return bad(ex.withT
                           ? tr(lang, "expected \"hit T\" (T the intersection's t) or \"miss\"")
                           : tr(lang, "expected \"hit\" or \"miss\""));
        };
        const std::string s = lower(text);
        const auto parts = splitAny(s, " \t=:");
        if (parts.empty()) return expected();
        const std::string_view word = parts[0];
        // The words of every language (language.json's "hit" and "miss"), whatever the app's.
        const auto said = [&](const std::vector<std::string> LanguageInfo::*words) {
            for (const Language l : languages())
                for (const std::string& w : languageInfo(l).*words)
                    if (word == w) return true;
            return false;
        };
        if (said(&LanguageInfo::missWords)) {
            if (parts.size() > 1) return bad(tr(lang, "a miss has no t"));
            a.hit = false;
            return a;
        }
        if (!said(&LanguageInfo::hitWords)) return expected();
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

    std::string format(const Exercise&, const Answer& a, Language lang) const override {
        if (!a.hit) return "";
        // The answer's keywords, which parseAnswer reads in any language: a grammar, not a
        // translation (the catalogue's "hit" is the event list's noun, "intersezione"); the
        // language's first word of each (language.json), English's if it has none.
        const auto first = [&](const std::vector<std::string> LanguageInfo::*words,
                               const char* english) {
            const auto& own = languageInfo(lang).*words;
            return own.empty() ? std::string(english) : own.front();
        };
        if (!*a.hit) return first(&LanguageInfo::missWords, "miss");
        const std::string word = first(&LanguageInfo::hitWords, "hit");
        return a.numbers.empty() ? word : word + " " + formatNumber(a.numbers[0], lang);
    }

    bool grade(const Context& c, const Answer& answer, const Reference& r) const override {
        const Answer& ref = r.answer;
        return answer.hit == ref.hit &&
               (!c.ex.withT || !*ref.hit ||
                (answer.numbers.size() == 1 &&
                 close(answer.numbers[0], ref.numbers[0], c.ex.tolerance)));
    }

    std::string slip(const Context& c, const Answer& answer, const Reference& r, const std::string&,
                     Language lang) const override {
        const Answer& ref = r.answer;
        const double given = answer.numbers[0];
        std::string slip;
        if (answer.hit == ref.hit && ref.hit == true && !ref.numbers.empty()) {
            const auto* t = std::get_if<PrimitiveTest>(&c.log.events()[*r.source]);
            slip = t ? rootSlip(c, given, ref.numbers[0], t->ray, t->prim, lang) : "";
            if (slip.empty())
                slip = trf(lang, "It is an intersection, but not at t = %1.",
                           {formatNumber(given, lang)});
        }
        return slip;
    }

    std::string retryAdvice(const Exercise&, bool replayHeld, Language lang) const override {
        if (!replayHeld) return stepTheReplayAdvice(lang);
        return tr(lang,
                  "The replay waits here until you answer: look where the ray "
                  "goes in the views, or solve the test by hand with the "
                  "ray's and the primitive's numbers.");
    }

    std::string placeholder(const Exercise& ex, int, Language lang) const override {
        return ex.withT ? tr(lang, "hit T, or miss") : tr(lang, "hit or miss");
    }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        const Answer a = referenceAnswer(in.ex, in.log, in.file, in.sweep);
        const LessonScene* scene = in.scene;
        AnswerForms::Outcome o;
        o.hit = a.hit.value_or(false);
        if (const auto at = answerEventIndex(in.ex, in.log, in.file))
            if (const auto* t = std::get_if<PrimitiveTest>(&in.log.events()[*at])) o.prim = t->prim;
        if (const auto* s2 = scene ? std::get_if<Scene2D>(scene) : nullptr) {
            o.circle = s2->isCircle(o.prim);
            o.segment = !o.circle;
            o.onlyOfItsKind = (o.circle ? s2->circles.size() : s2->segments.size()) == 1;
        } else if (const auto* s3 = scene ? std::get_if<Scene>(scene) : nullptr) {
            o.sphere = s3->isSphere(o.prim);
            o.triangle = !o.sphere;
            o.onlyOfItsKind = (o.sphere ? s3->spheres.size() : s3->triangles.size()) == 1;
            o.names = uniqueNames(*s3, o.prim);
        }
        f.outcome = o;
        if (o.hit && in.ex.withT && !a.numbers.empty()) addLeakNumber(f, a.numbers[0]);
        f.describe = std::string(o.hit ? "a hit" : "a miss") + " on primitive " +
                     std::to_string(o.prim) +
                     (f.numbers.empty() ? "" : " at t = " + formatNumber(f.numbers[0]));
    }
};

}  // namespace

const ExerciseKindUnit& hitOrMissUnit() {
    static const HitOrMiss unit;
    return unit;
}

}  // namespace raystep::exercises
