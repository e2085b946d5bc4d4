#pragma once
// Grading a course: a lesson checked whole (`raystep-cli lesson validate`), and a student's
// answers file graded against the lesson's trace.
#include "course/exercise.h"
#include "course/grid_sweep.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

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

/// The rows a sweep_pick exercise is graded from: the lesson's sweep run over its scene; empty
/// when no exercise of the lesson needs it (a sweep takes about a second).
std::vector<GridSweepRow> sweepRowsIfNeeded(const Lesson& lesson, const LessonRun& run);

/// Quiz mode's checks (also in validateLesson): each exercise's answer lies after its own position
/// (the replay stops there while it is open), and no text a student reads before answering gives
/// the answer (course/answer_leaks.h: its number as a text prints it, its cell or cells in order,
/// its node order, its test's outcome named with the primitive, its plane, its resolution). The
/// texts: the lesson's text and errata, the steps at or before the exercise's position with their
/// notes and errata (every step for an exercise the replay does not wait for), every exercise's
/// prompt, hints and options, and the explanations of the exercises before it. Throws LessonError
/// naming the exercise and where its answer shows. Whole answers 0 and 1 are exempt: they are in
/// every formula. `scene` names a tested primitive's kind; `sweep`, a sweep_pick's rows.
/// Each exercise is checked in its own structure's trace (`logs`); a step of another structure
/// than the exercise's is read whatever the exercise's position (their positions are in two
/// traces), so its text is checked too.
void checkNoAnswerGivenAway(const Lesson& lesson, const LessonLogs& logs,
                            const LessonScene* scene = nullptr,
                            const std::vector<GridSweepRow>* sweep = nullptr);

/// A compute exercise's prompt must state its data: every given number is written in the prompt,
/// in both languages. Throws LessonError naming the exercise and the missing number.
void checkComputePrompts(const Lesson& lesson);

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
/// Each exercise against its own structure's trace in `logs`.
Grade gradeAnswers(const Lesson& lesson, const LessonLogs& logs, const AnswerSheet& sheet,
                   Language lang, const std::string& sheetFile,
                   const std::vector<GridSweepRow>* sweep = nullptr,
                   const std::variant<Scene, Scene2D>* scene = nullptr);

/// A class's answers to one lesson, per exercise (`raystep-cli lesson check --answers FOLDER`):
/// how many were right, wrong (an unreadable answer is wrong) or not answered, and the most common
/// wrong answer (answers that read the same, "1,5" and "1.5", count as one) with how many gave it.
struct ClassTable {
    struct Row {
        std::string exercise;
        int right = 0, wrong = 0, notAnswered = 0;
        std::string commonWrong;  // as the first student who gave it wrote it
        int commonWrongCount = 0;
    };
    std::vector<Row> rows;
    int sheets = 0;
};
/// Grades every sheet (`sheets`: file name and sheet) against the lesson; throws the first
/// sheet's LessonError (naming its file, line and key).
ClassTable classTable(const Lesson& lesson, const LessonLogs& logs,
                      const std::vector<std::pair<std::string, AnswerSheet>>& sheets,
                      const std::vector<GridSweepRow>* sweep = nullptr);
/// The table as Markdown (a heading line, then the table) or as CSV (RFC 4180 quoting).
std::string classTableMarkdown(const Lesson& lesson, const ClassTable& table, Language lang);
std::string classTableCsv(const ClassTable& table);

}  // namespace raystep
