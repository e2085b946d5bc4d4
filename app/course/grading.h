#pragma once
// Grading a course: a lesson checked whole (`raystep-cli lesson validate`), and a student's
// answers file graded against the lesson's trace.
#include "course/lesson.h"

#include "raystep/trace/events.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// Checks what `raystep-cli lesson validate` checks: the scene loads, the trace records, every
/// step's and exercise's position exists in it and every exercise has a reference answer.
/// Throws LessonError on the first problem.
void validateLesson(const Lesson& lesson);

/// A course's answers file: {"lesson": ID, "answers": {exercise id: answer}} where an answer is a
/// number, an array of numbers (a cell), a string as typed in the app, or true/false (hit/miss).
struct AnswerSheet {
    std::string lesson;  // the id, or the number as text
    int lessonLine = 0;
    std::map<std::string, std::string> answers;  // as text, for parseAnswer
    std::map<std::string, int> lines;
};
AnswerSheet loadAnswerSheet(std::string_view text, const std::string& fileName);
/// Reads the answers file at `path` (a regular file of at most 8 MB) and parses it.
AnswerSheet loadAnswerSheetFile(const std::string& path);

/// Grades a sheet: per exercise, correct or not and why; the score is the number right.
struct Grade {
    struct Item {
        std::string exercise;
        bool answered = false, correct = false;
        std::string given, expected, feedback;
    };
    std::vector<Item> items;
    int score = 0;
};
Grade gradeAnswers(const Lesson& lesson, const EventLog& log, const AnswerSheet& sheet,
                   Language lang, const std::string& sheetFile);

}  // namespace raystep
