#pragma once
// A student's progress through the lessons: the file the app saves under the user's data folder,
// folding in what another window saved, and the Markdown report for a course.
#include "course/lesson.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// A student's progress, saved by the app under the user's data folder.
struct LessonProgress {
    struct ExerciseRecord {
        bool correct = false;
        int attempts = 0;
        std::string answer;
    };
    int step = 0;
    std::map<std::string, ExerciseRecord> exercises;
};
/// Practice at one topic and level (docs/practice.md): the instances drawn, in order, each
/// right (every exercise right at its first answer), missed (a wrong answer) or still open.
struct PracticeRecord {
    enum class Result { Open, Right, Missed };
    struct Instance {
        std::uint64_t seed = 0;
        Result result = Result::Open;
        std::string digest;  // practiceDigest of its data: two seeds may draw the same instance
    };
    std::vector<Instance> instances;
    /// The instances right in a row at the end (open ones between do not break it).
    int streak() const;
    /// kMasteryStreak right in a row, at any time: mastery once reached is kept.
    bool mastered() const;
    int right() const;
    bool drawn(std::uint64_t seed) const;
    /// An instance with this digest was given (instances recorded without one never match).
    bool given(std::string_view digest) const;
};
/// Right instances in a row that master a topic at a level.
inline constexpr int kMasteryStreak = 3;

struct Progress {
    std::map<std::string, LessonProgress> lessons;   // by lesson id (practice instances too)
    std::map<std::string, PracticeRecord> practice;  // by "topic/level" (practiceKey)
};
/// "dda-2d/easy": the key of a topic's practice at a level in Progress::practice.
std::string practiceKey(std::string_view topic, std::string_view level);
Progress parseProgress(std::string_view text, const std::string& fileName);
/// Reads the progress file at `path`: nullopt when there is none yet; LessonError when it cannot
/// be read (a folder, a special file, over 8 MB) or parsed.
std::optional<Progress> loadProgressFile(const std::string& path);
std::string progressToJson(const Progress& p);
/// Folds progress saved by another run (another window of the app, open at the same time) into
/// `into`, so that saving `into` loses neither's answers: an exercise right in either is right,
/// its attempts are the larger count (with that run's answer), lessons and exercises only one
/// knows are kept, and `into`'s own steps win. Records already in `into` do not move. Practice
/// instances only `saved` drew are appended; a result decided in either is kept.
void mergeProgress(Progress& into, const Progress& saved);
/// Records an answer in `lesson` (the app's one rule, so that no caller gets it wrong): until the
/// exercise is first answered right, each answer is an attempt and is kept; once it is right, a
/// later answer, wrong or right, neither counts as an attempt nor replaces the right answer.
/// Returns whether the exercise was solved before this answer.
bool recordAnswer(LessonProgress& lesson, const std::string& exerciseId, const std::string& answer,
                  bool correct);

/// What the answers recorded in `progress` make of a practice instance (`lesson`): missed at its
/// first wrong answer, right once every exercise is right at its first answer, else open.
PracticeRecord::Result practiceResult(const Lesson& lesson, const LessonProgress& progress);
/// Records the result of instance `seed` in `record` (appended when new, with `digest`): a
/// decided result is never changed again, so a later answer cannot undo a miss nor a right.
void recordPractice(PracticeRecord& record, std::uint64_t seed, PracticeRecord::Result result,
                    const std::string& digest = {});

/// Who the report is for and when it was made (the caller's clock: the report is deterministic).
struct ReportHeader {
    std::string student;  // as the student typed it; empty: not given
    std::string date;     // e.g. "2025-03-14"; empty: not given
};
/// A report for a course (Markdown): the student's name and the date, a table per lesson of
/// exercises done, right and attempts, then per lesson worked on, each exercise: right or not
/// yet, the attempts it took and the last answer given; then the practice per topic and level:
/// instances, right, the streak and whether mastered.
std::string progressReport(const Progress& p, const std::vector<Lesson>& lessons, Language lang,
                           const ReportHeader& header = {});

}  // namespace raystep
