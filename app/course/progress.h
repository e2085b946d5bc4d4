#pragma once
// A student's progress through the lessons: the file the app saves under the user's data folder,
// folding in what another window saved, and the Markdown report for a course.
#include "course/lesson.h"

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
struct Progress {
    std::map<std::string, LessonProgress> lessons;  // by lesson id
};
Progress parseProgress(std::string_view text, const std::string& fileName);
/// Reads the progress file at `path`: nullopt when there is none yet; LessonError when it cannot
/// be read (a folder, a special file, over 8 MB) or parsed.
std::optional<Progress> loadProgressFile(const std::string& path);
std::string progressToJson(const Progress& p);
/// Folds progress saved by another run (another window of the app, open at the same time) into
/// `into`, so that saving `into` loses neither's answers: an exercise right in either is right,
/// its attempts are the larger count (with that run's answer), lessons and exercises only one
/// knows are kept, and `into`'s own steps win. Records already in `into` do not move.
void mergeProgress(Progress& into, const Progress& saved);
/// Records an answer in `lesson` (the app's one rule, so that no caller gets it wrong): until the
/// exercise is first answered right, each answer is an attempt and is kept; once it is right, a
/// later answer, wrong or right, neither counts as an attempt nor replaces the right answer.
/// Returns whether the exercise was solved before this answer.
bool recordAnswer(LessonProgress& lesson, const std::string& exerciseId, const std::string& answer,
                  bool correct);

/// Who the report is for and when it was made (the caller's clock: the report is deterministic).
struct ReportHeader {
    std::string student;  // as the student typed it; empty: not given
    std::string date;     // e.g. "2025-03-14"; empty: not given
};
/// A report for a course (Markdown): the student's name and the date, a table per lesson of
/// exercises done, right and attempts, then per lesson worked on, each exercise: right or not
/// yet, the attempts it took and the last answer given.
std::string progressReport(const Progress& p, const std::vector<Lesson>& lessons, Language lang,
                           const ReportHeader& header = {});

}  // namespace raystep
