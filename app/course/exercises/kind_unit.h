#pragma once
// An exercise kind as one unit (docs/architecture.md, "Exercise kinds"): what is the kind's own —
// its lesson keys, its reference answer read from the trace, the typed answer's form, its grader
// and slips, its feedback, retry advice, placeholder and answer input, and the forms in which a
// text would give its answer away — behind ExerciseKindUnit, listed once in registry.cpp. The
// public functions of course/exercise.h look the kind up there. Internal to raystep_course.
#include "course/answer_leaks.h"
#include "course/exercise.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include "raystep/base/json_reader.h"
#include "raystep/trace/replay.h"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raystep {

using LessonReader = detail::JsonReader<LessonError>;

// The lesson reader's own parts a kind's keys are read with (defined in lesson.cpp).
namespace lesson_reading {
LocalText readText(const LessonReader& r, const detail::json& j, const std::string& path,
                   bool plainAllowed = false);
ReplayPosition readPosition(const LessonReader& r, const detail::json& j, const std::string& path);
/// An event kind by its name in the trace format ("dda_cell"), and every name, for messages.
std::optional<std::size_t> eventKindNamed(std::string_view name);
std::string eventKindList();
}  // namespace lesson_reading

namespace exercises {

using detail::ifPresent;

// ---- what the kinds share ----

std::string_view trim(std::string_view s);
/// A number as typed, with a point or any language's decimal mark ("0.75", "0,75"); nullopt
/// when it is none.
std::optional<double> parseNumber(std::string_view s);
std::optional<long> parseWhole(std::string_view s);
std::vector<std::string_view> splitAny(std::string_view s, std::string_view seps);
std::string lower(std::string_view s);
/// No answer: `why` (when given) says so.
std::optional<Answer> rejected(std::string* why, const std::string& message);
/// One number as typed (value, count, compute).
std::optional<Answer> parseOneNumber(std::string_view text, std::string* why, Language lang);
/// The tolerance check: relative, absolute below 1.
bool close(double answer, double reference, double tolerance);
/// "a".."f" for options 0..5.
std::string letter(int i);
/// A whole number as typed ("3").
std::string whole(double v);
/// Whole numbers as a cell is typed: "3,1" (next_cell, spot_bug).
std::string wholes(const std::vector<double>& numbers);

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

/// An exercise in its trace: the position resolved, and what the grader may use besides.
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
                  const std::vector<GridSweepRow>* sweep);
/// The end of a count's or sequence's range.
std::size_t rangeEnd(const Context& c);

/// The reference answer, the explanation of it, and the event it is read from.
struct Reference {
    Answer answer;
    std::string why;
    std::optional<std::size_t> source;
};

/// The slip a wrong t of a hit betrays (value and hit_or_miss): the far root of a circle or
/// sphere (with the scene), or the root halved or doubled by a missing or extra division.
std::string rootSlip(const Context& c, double given, double right, std::uint32_t ray,
                     std::uint32_t prim, Language lang);

/// The advice of every kind read from the trace while the replay is not held.
std::string stepTheReplayAdvice(Language lang);
/// Whether a held exercise waits before the trace's first event: the inspector shows nothing
/// yet, so its advice points to the data the exercise gives (a practice's set-up questions).
bool heldAtTheStart(const Exercise& ex);

/// Answer-leak forms: a number the texts must not print (whole 0 and 1 are in every formula).
void addLeakNumber(AnswerForms& f, double v);
/// The names a 3D primitive goes by when its material is its own ("mirror", "specchio").
std::vector<std::string> uniqueNames(const Scene& scene, std::uint32_t prim);
/// What an answer-leak search is given.
struct LeakInput {
    const Exercise& ex;
    const EventLog& log;
    const std::string& file;
    const LessonScene* scene;
    const std::vector<GridSweepRow>* sweep;
};

// ---- the unit ----

/// One exercise kind. Every member but the name, the kind, the reference, parse, format and
/// grade has a default that fits a kind without it.
class ExerciseKindUnit {
  public:
    virtual ~ExerciseKindUnit() = default;
    virtual ExerciseKind kind() const = 0;
    /// Its "type" in a lesson file ("next_cell").
    virtual std::string_view name() const = 0;

    /// Its own lesson keys, in the order the reader checks them (docs/lesson-format.md); a key
    /// two kinds take is named, in a kind that takes none, after the first in the registry.
    virtual std::vector<const char*> keys() const { return {}; }
    /// Reads its keys of `j` (an exercise at `path`) into `ex`, failing as the lesson reader does.
    virtual void read(const LessonReader&, const detail::json&, const std::string&,
                      Exercise&) const {}

    /// The right answer from the trace, with why it is right and its event.
    virtual Reference reference(const Context& c, Language lang) const = 0;
    /// The answer as typed; nullopt with `why` (in `lang`) when it is not one.
    virtual std::optional<Answer> parse(const Exercise& ex, std::string_view text, std::string* why,
                                        Language lang) const = 0;
    virtual std::string format(const Exercise& ex, const Answer& a, Language lang) const = 0;
    /// Whether `given` is right.
    virtual bool grade(const Context& c, const Answer& given, const Reference& ref) const = 0;
    /// The slip a wrong answer (with numbers) betrays, with the student's numbers; `expected` is
    /// the reference as text.
    virtual std::string slip(const Context&, const Answer&, const Reference&,
                             const std::string& /*expected*/, Language) const {
        return "";
    }

    /// What a wrong answer's feedback advises (course/exercise.h, retryAdvice), before the hint.
    virtual std::string retryAdvice(const Exercise& ex, bool replayHeld, Language lang) const = 0;
    /// The answer is read from an event at or after `at`: quiz mode holds the replay there and
    /// answerEventIndex names the event.
    virtual bool answerInTrace() const { return true; }
    virtual std::string placeholder(const Exercise&, int /*dims*/, Language) const { return ""; }
    virtual AnswerInputSpec input(const Exercise&) const { return {}; }

    /// The forms of its answer a text would give away (course/answer_leaks.h); none by default.
    virtual void answerForms(const LeakInput&, AnswerForms&) const {}
    /// The numbers its prompt must state (a compute's given data); nullptr for the others.
    virtual const std::vector<double>* givenNumbers(const Exercise&) const { return nullptr; }
    /// It is graded from the lesson's sweep (which the lesson must have).
    virtual bool needsSweep() const { return false; }
    /// Its answer is in the tree's node boxes, which the trace must carry.
    virtual bool needsNodeBoxes() const { return false; }
    /// Its trace is a walk of its own (spot_bug's wrong walk), recorded by recordWalk on its
    /// structure's grid instead of the lesson's trace (LessonSetup::replay names the exercise).
    virtual bool replaysOwnWalk() const { return false; }
    /// Records that walk of `ray` on `grid` (`dims` 2 or 3) into `log`.
    virtual void recordWalk(const Exercise&, const GridRecord& /*grid*/, int /*dims*/,
                            const WalkRay& /*ray*/, EventLog&) const {}
};

/// A kind whose answer is one number, right within the exercise's tolerance (value, compute).
class OneNumberUnit : public ExerciseKindUnit {
  public:
    std::optional<Answer> parse(const Exercise&, std::string_view text, std::string* why,
                                Language lang) const override {
        return parseOneNumber(text, why, lang);
    }
    std::string format(const Exercise&, const Answer& a, Language lang) const override {
        return a.numbers.empty() ? "" : formatNumber(a.numbers[0], lang);
    }
    bool grade(const Context& c, const Answer& given, const Reference& ref) const override {
        return given.numbers.size() == 1 &&
               close(given.numbers[0], ref.answer.numbers[0], c.ex.tolerance);
    }
};

/// The cells of an answer, `per` indices each, as the leak check looks for them.
void addLeakCells(AnswerForms& f, const Answer& a, int per);

/// Every kind, one unit each, in the order of ExerciseKind.
const std::vector<const ExerciseKindUnit*>& kindUnits();
/// The unit of `kind` (every ExerciseKind has one: the course tests check it).
const ExerciseKindUnit& unitOf(ExerciseKind kind);

}  // namespace exercises
}  // namespace raystep
