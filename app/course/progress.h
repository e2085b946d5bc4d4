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
/// A report for a course: per lesson, exercises done, right, attempts (Markdown).
std::string progressReport(const Progress& p, const std::vector<Lesson>& lessons, Language lang);

}  // namespace raystep
