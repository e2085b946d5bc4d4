// Grading: a lesson checked whole (its scene, trace, positions and reference answers), and a
// student's answers file read and graded against the lesson's trace.
#include "course/grading.h"

#include "course/exercise.h"
#include "course/lesson_trace.h"

#include "raystep/base/json_reader.h"

#include <algorithm>
#include <sstream>

namespace raystep {

using detail::ifPresent;
using detail::json;
using Reader = detail::JsonReader<LessonError>;

void validateLesson(const Lesson& lesson) {
    const LessonRun run = runLesson(lesson);
    if (run.log->events().empty())
        throw LessonError(lesson.file, 0, "trace", "the trace recorded no events");
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& s = lesson.steps[i];
        const std::string key = "steps[" + std::to_string(i) + "]";
        if (!resolvePosition(s.at, *run.log))
            throw LessonError(lesson.file, s.line, key,
                              "its position (" + describePosition(s.at) + ") is not in the trace");
        // A filter that shows nothing leaves the student an empty event list.
        const auto& events = run.log->events();
        if (!s.filter.empty() && std::none_of(events.begin(), events.end(), [&](const Event& e) {
                return eventMatchesFilter(e, run.log->dims(), s.filter);
            }))
            throw LessonError(lesson.file, s.line, key + ".filter",
                              "the filter '" + printable(s.filter) +
                                  "' matches no event of the trace (filter by an event kind: " +
                                  "dda_cell, primitive_test, ray_begin, ...)");
    }
    for (const Exercise& ex : lesson.exercises) referenceAnswer(ex, *run.log, lesson.file);
    Lesson noted = lesson;  // the steps' notes can be made from this lesson's run
    addStepNotes(noted, *run.scene, run.accel2D ? &*run.accel2D : nullptr);
    const bool is2D = std::holds_alternative<Scene2D>(*run.scene);
    for (const LessonView v : lesson.views)
        if ((v == LessonView::View2D) != is2D)
            throw LessonError(lesson.file, 0, "views",
                              std::string(lessonViewName(v)) + " does not fit a " +
                                  (is2D ? "2D" : "3D") + " scene");
}

namespace {
/// A file's text, or a LessonError "PATH: cannot read the WHAT: why".
std::string readLessonFile(const std::string& path, const std::string& what) {
    try {
        return detail::readRegularFile(path, detail::kMaxJsonFileBytes);
    } catch (const detail::ReadFailure& f) {
        throw LessonError(path, 0, "", "cannot read the " + what + ": " + f.what());
    }
}

AnswerSheet readAnswerSheet(std::string_view text, const std::string& fileName) {
    auto parsed = detail::parseJsonFile<LessonError>(text, fileName);
    const json& root = parsed.root;
    const Reader r(fileName, std::move(parsed.lines));
    r.requireObject(root, "");
    r.checkKeys(root, "", {"lesson", "student", "answers"});
    if (!root.contains("lesson") || !root.contains("answers"))
        r.fail("", "an answers file holds {\"lesson\": ID, \"answers\": {EXERCISE: ANSWER}}");
    AnswerSheet sheet;
    // The id or the number (docs/lesson-format.md, "Answers files").
    const json& lesson = root["lesson"];
    if (lesson.is_number())
        sheet.lesson = std::to_string(r.integer(lesson, "lesson", 1, 999));
    else if (lesson.is_string())
        sheet.lesson = lesson.get<std::string>();
    else
        r.fail("lesson", "expected the lesson's id or number, got " + Reader::typeName(lesson));
    sheet.lessonLine = r.lines().lineOf("lesson");
    ifPresent(root, "", "student", [&](const json& v, const std::string& p) {
        if (!v.is_string() && !v.is_number())
            r.fail(p, "expected the student's name or number, got " + Reader::typeName(v));
    });
    r.requireObject(root["answers"], "answers");
    for (const auto& [id, v] : root["answers"].items()) {
        const std::string p = JsonLineMap::child("answers", id);
        std::string t;
        if (v.is_string()) {
            t = v.get<std::string>();
        } else if (v.is_boolean()) {
            t = v.get<bool>() ? "hit" : "miss";
        } else if (v.is_number()) {
            std::ostringstream s;
            s.precision(17);
            s << r.number(v, p);  // finite, checked
            t = s.str();
        } else if (v.is_array()) {
            for (std::size_t i = 0; i < v.size(); ++i) {
                std::ostringstream s;
                s.precision(17);
                s << r.number(v[i], JsonLineMap::element(p, i));
                t += (i ? "," : "") + s.str();
            }
        } else {
            r.fail(p, "expected a number, a list of numbers, a string or true/false");
        }
        sheet.answers[id] = t;
        sheet.lines[id] = r.lines().lineOf(p);
    }
    return sheet;
}
}  // namespace

AnswerSheet loadAnswerSheet(std::string_view text, const std::string& fileName) {
    return detail::guarded<LessonError>(fileName, [&] { return readAnswerSheet(text, fileName); });
}

AnswerSheet loadAnswerSheetFile(const std::string& path) {
    return loadAnswerSheet(readLessonFile(path, "answers file"), path);
}

Grade gradeAnswers(const Lesson& lesson, const EventLog& log, const AnswerSheet& sheet,
                   Language lang, const std::string& sheetFile) {
    if (sheet.lesson != lesson.id && sheet.lesson != std::to_string(lesson.number))
        throw LessonError(sheetFile, sheet.lessonLine, "lesson",
                          "the answers are for lesson '" + printable(sheet.lesson) + "', not '" +
                              lesson.id + "'");
    for (const auto& [id, text] : sheet.answers)
        if (!lesson.exercise(id))
            throw LessonError(sheetFile, sheet.lines.at(id), "answers." + id,
                              "lesson " + lesson.id + " has no exercise of that id");
    Grade g;
    for (const Exercise& ex : lesson.exercises) {
        Grade::Item item;
        item.exercise = ex.id;
        // One check per exercise: an unanswered or unreadable answer is checked as empty, which
        // still gives the expected answer and its explanation.
        std::optional<Answer> given;
        std::string why;
        if (const auto it = sheet.answers.find(ex.id); it != sheet.answers.end()) {
            item.answered = true;
            item.given = it->second;
            given = parseAnswer(ex, it->second, &why);
        }
        const Verdict v = checkAnswer(ex, log, given.value_or(Answer{}), lang, lesson.file);
        item.correct = given.has_value() && v.correct;
        item.expected = v.expected;
        item.feedback = item.answered && !given ? why + ". " + v.feedback : v.feedback;
        g.score += item.correct;
        g.items.push_back(std::move(item));
    }
    return g;
}

}  // namespace raystep
