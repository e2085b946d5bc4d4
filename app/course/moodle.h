#pragma once
// Lessons and practice instances as Moodle questions (docs/practice.md, "Moodle"): Moodle XML
// (numerical with a tolerance, short answer with every spelling raystep accepts, multiple choice,
// per-answer feedback from raystep's slips, 2D figures embedded as PNG) or GIFT (text only).
// Every right answer and every slip is raystep's engine's: the writer only asks it.
#include "course/lesson.h"

#include <string>
#include <vector>

namespace raystep {

/// One lesson's questions in one category ("raystep/dda-2d/tdelta-x": a quiz's random question
/// then draws one variant of that exercise from it).
struct MoodleSource {
    Lesson lesson;
    std::string category;  // the category of each question: category + "/" + exercise id
};

struct MoodleExport {
    std::string text;                  // the file
    int questions = 0;                 // written
    std::vector<std::string> skipped;  // "lesson/exercise: why" (a kind Moodle has no type for)
};

MoodleExport moodleXml(const std::vector<MoodleSource>& sources, Language lang);
MoodleExport moodleGift(const std::vector<MoodleSource>& sources, Language lang);

}  // namespace raystep
