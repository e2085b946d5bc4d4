// Exercises: answers as typed, the right answer read from the recorded trace (never from the
// lesson file, but for a choice), and the check of a student's answer with the explanation, in
// the student's language, and the slip a wrong number betrays. Each kind's own part is its unit
// (course/exercises/<kind>.cpp), found in the registry; here is what every kind shares.
#include "course/exercise.h"

#include "course/exercises/kind_unit.h"
#include "course/lesson_trace.h"

#include "raystep/base/i18n.h"

namespace raystep {

using exercises::unitOf;

std::optional<Answer> parseAnswer(const Exercise& ex, std::string_view text, std::string* why,
                                  Language lang) {
    return unitOf(ex.kind).parse(ex, text, why, lang);
}

std::string formatAnswer(const Exercise& ex, const Answer& a, Language lang) {
    return unitOf(ex.kind).format(ex, a, lang);
}

std::vector<SplitCandidate> splitCandidates(const Exercise& ex, const EventLog& log) {
    std::vector<SplitCandidate> out;
    const auto at = resolvePosition(ex.at, log);
    if (!at) return out;
    const auto node = exercises::nextEvent<BuildNode>(log, *at);
    if (!node) return out;
    for (const Event& e : log.events())
        if (const auto* s = std::get_if<SplitCandidate>(&e); s && s->node == node->second.node)
            out.push_back(*s);
    return out;
}

Answer referenceAnswer(const Exercise& ex, const EventLog& log, const std::string& lessonFile,
                       const std::vector<GridSweepRow>* sweep) {
    return unitOf(ex.kind)
        .reference(exercises::contextOf(ex, log, lessonFile, sweep), Language::En)
        .answer;
}

std::optional<std::size_t> answerEventIndex(const Exercise& ex, const EventLog& log,
                                            const std::string& lessonFile) {
    const exercises::ExerciseKindUnit& unit = unitOf(ex.kind);
    if (!unit.answerInTrace()) return std::nullopt;
    return unit.reference(exercises::contextOf(ex, log, lessonFile, nullptr), Language::En).source;
}

std::string answerPlaceholder(const Exercise& ex, int dims, Language lang) {
    return unitOf(ex.kind).placeholder(ex, dims, lang);
}

AnswerInputSpec answerInput(const Exercise& ex) {
    return unitOf(ex.kind).input(ex);
}

std::string retryAdvice(const Exercise& ex, bool replayHeld, bool hintLeft, Language lang) {
    std::string advice = unitOf(ex.kind).retryAdvice(ex, replayHeld, lang);
    if (hintLeft) {
        advice += ' ';
        advice += tr(lang, "Or ask for a hint.");
    }
    return advice;
}

std::optional<std::size_t> quizLimit(const Exercise& ex, const EventLog& log) {
    if (!unitOf(ex.kind).answerInTrace()) return std::nullopt;
    return resolvePosition(ex.at, log);
}

Verdict checkAnswer(const Exercise& ex, const EventLog& log, const Answer& answer, Language lang,
                    const std::string& lessonFile, const std::vector<GridSweepRow>* sweep,
                    const LessonScene* scene) {
    const exercises::ExerciseKindUnit& unit = unitOf(ex.kind);
    exercises::Context c = exercises::contextOf(ex, log, lessonFile, sweep);
    c.scene = scene;
    const exercises::Reference r = unit.reference(c, lang);
    Verdict v;
    v.expected = unit.format(ex, r.answer, lang);
    v.correct = unit.grade(c, answer, r);
    // What the wrong answer betrays, with the student's own numbers.
    if (!v.correct && !answer.numbers.empty()) v.slip = unit.slip(c, answer, r, v.expected, lang);
    v.feedback = v.slip.empty() ? r.why : v.slip + " " + r.why;
    return v;
}

}  // namespace raystep
