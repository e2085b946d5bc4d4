#pragma once
// Exercises: a student's answer as typed, the right answer read from the recorded trace, and the
// check of one against the other with the trace's explanation.
#include "course/lesson.h"

#include "raystep/trace/events.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// A student's answer. NextCell: the cell's indices; Value and Count: one number; PickSplit:
/// axis (0, 1, 2) and position; HitOrMiss: hit, and t when asked.
struct Answer {
    std::vector<double> numbers;
    std::optional<bool> hit;
};
/// Reads an answer as typed: "2,1" (cell), "0.75" (value, count), "x=2.5" (split),
/// "miss" or "hit 3.55" (hit or miss). nullopt with `why` set when it is not such an answer.
std::optional<Answer> parseAnswer(const Exercise& ex, std::string_view text, std::string* why);
std::string formatAnswer(const Exercise& ex, const Answer& a);

/// The candidates of the split a PickSplit exercise is about (those the app lists).
std::vector<SplitCandidate> splitCandidates(const Exercise& ex, const EventLog& log);

/// The right answer, read from the trace; throws LessonError (naming the exercise's line in
/// `lessonFile`) when the trace does not hold what the exercise asks about.
Answer referenceAnswer(const Exercise& ex, const EventLog& log, const std::string& lessonFile);

struct Verdict {
    bool correct = false;
    std::string expected;  // the reference answer, as text
    std::string feedback;  // why the right answer is right, from the trace
};
Verdict checkAnswer(const Exercise& ex, const EventLog& log, const Answer& answer, Language lang,
                    const std::string& lessonFile);

}  // namespace raystep
