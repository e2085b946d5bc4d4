// Grading: a lesson checked whole (its scene, trace, positions and reference answers), and a
// student's answers file read and graded against the lesson's trace.
#include "course/grading.h"

#include "course/answer_leaks.h"
#include "course/compute.h"
#include "course/exercise.h"
#include "course/exercises/kind_unit.h"
#include "course/lesson_trace.h"

#include "raystep/base/json_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

namespace raystep {

using detail::ifPresent;
using detail::json;
using Reader = detail::JsonReader<LessonError>;

void validateLesson(const Lesson& lesson) {
    const LessonRun run = runLesson(lesson);
    const LessonLogs logs = run.logs();
    if (run.log->events().empty())
        throw LessonError(lesson.file, 0, "trace", "the trace recorded no events");
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& s = lesson.steps[i];
        const std::string key = "steps[" + std::to_string(i) + "]";
        const EventLog& log = logs.of(s.setup);  // the step's structure's trace
        if (!resolvePosition(s.at, log))
            throw LessonError(lesson.file, s.line, key,
                              "its position (" + describePosition(s.at) + ") is not in the " +
                                  (s.setup ? s.setup->name() + " " : std::string()) + "trace");
        // A filter that shows nothing leaves the student an empty event list.
        const auto& events = log.events();
        if (!s.filter.empty() && std::none_of(events.begin(), events.end(), [&](const Event& e) {
                return eventMatchesFilter(e, log.dims(), s.filter);
            }))
            throw LessonError(lesson.file, s.line, key + ".filter",
                              "the filter '" + printable(s.filter) +
                                  "' matches no event of the trace (filter by an event kind: " +
                                  "dda_cell, primitive_test, ray_begin, ...)");
    }
    const std::vector<GridSweepRow> sweep = sweepRowsIfNeeded(lesson, run);
    for (const Exercise& ex : lesson.exercises)
        referenceAnswer(ex, logs.of(ex.setup), lesson.file, &sweep);
    checkComputePrompts(lesson);
    Lesson noted = lesson;  // the steps' notes can be made from this lesson's run
    addStepNotes(noted, *run.scene, run.accel2D ? &*run.accel2D : nullptr);
    const bool is2D = std::holds_alternative<Scene2D>(*run.scene);
    for (const LessonView v : lesson.views)
        if (v != LessonView::Board && (v == LessonView::View2D) != is2D)
            throw LessonError(lesson.file, 0, "views",
                              std::string(lessonViewName(v)) + " does not fit a " +
                                  (is2D ? "2D" : "3D") + " scene");
    // Last, so a lesson that fails only here has passed every other check.
    checkNoAnswerGivenAway(noted, logs, run.scene.get(), &sweep);
}

std::vector<GridSweepRow> sweepRowsIfNeeded(const Lesson& lesson, const LessonRun& run) {
    const bool needed =
        std::any_of(lesson.exercises.begin(), lesson.exercises.end(),
                    [](const Exercise& e) { return exercises::unitOf(e.kind).needsSweep(); });
    if (!needed || !lesson.sweep) return {};
    return runGridSweep(*run.scene, *lesson.sweep);
}

void checkComputePrompts(const Lesson& lesson) {
    for (std::size_t i = 0; i < lesson.exercises.size(); ++i) {
        const Exercise& ex = lesson.exercises[i];
        const std::vector<double>* given = exercises::unitOf(ex.kind).givenNumbers(ex);
        if (!given) continue;
        for (const Language lang : languages()) {
            const auto missing = numbersNotInText(*given, ex.prompt.in(lang), lang);
            if (!missing.empty())
                throw LessonError(lesson.file, ex.line,
                                  "exercises[" + std::to_string(i) + "].prompt." +
                                      std::string(languageCode(lang)),
                                  "the prompt does not state the given number " +
                                      formatNumber(missing[0], lang) +
                                      ": a compute exercise's prompt gives all its data");
        }
    }
}

namespace {
/// A text a student may read while an exercise is open: where it is, and whether it is the
/// exercise's own prompt (which may ask what it names, and state a compute's given numbers).
struct Shown {
    std::string place;
    LocalText text;
    bool ownPrompt = false;
    TextRole role = TextRole::Prose;  // how the text names primitives (course/answer_leaks.h)
};

void addErrata(std::vector<Shown>& out, const std::string& at, const std::vector<Erratum>& errata) {
    for (std::size_t k = 0; k < errata.size(); ++k) {
        const std::string e = at + "errata[" + std::to_string(k) + "].";
        out.push_back({e + "slide", errata[k].slide});
        out.push_back({e + "correct", errata[k].correct});
        out.push_back({e + "why", errata[k].why});
    }
}
}  // namespace

void checkNoAnswerGivenAway(const Lesson& lesson, const LessonLogs& logs, const LessonScene* scene,
                            const std::vector<GridSweepRow>* sweep) {
    const bool swept = sweep && !sweep->empty();
    // The explanation of each exercise, shown once it is answered (or after three tries): a
    // student reads it before the exercises after it.
    std::vector<LocalText> explanations(lesson.exercises.size());
    for (std::size_t j = 0; j < lesson.exercises.size(); ++j) {
        const Exercise& ex = lesson.exercises[j];
        const EventLog& log = logs.of(ex.setup);
        if (exercises::unitOf(ex.kind).needsSweep() && !swept) continue;
        if (!resolvePosition(ex.at, log)) continue;  // validateLesson names it
        for (const Language lang : languages())
            explanations[j].set(
                lang, checkAnswer(ex, log, Answer{}, lang, lesson.file, sweep, scene).feedback);
    }
    for (std::size_t i = 0; i < lesson.exercises.size(); ++i) {
        const Exercise& ex = lesson.exercises[i];
        const EventLog& log = logs.of(ex.setup);
        const std::string exKey = lesson.setupOf(ex.setup).key();
        const std::string key = "exercises[" + std::to_string(i) + "]";
        const auto at = resolvePosition(ex.at, log);
        if (!at) continue;  // validateLesson names it
        if (const auto source = answerEventIndex(ex, log, lesson.file); source && *source < *at)
            throw LessonError(lesson.file, ex.line, key + ".at",
                              "the answer's event comes before the exercise's position, so it is "
                              "on screen while the exercise is open");
        if (exercises::unitOf(ex.kind).needsSweep() && !swept) continue;
        const AnswerForms forms = answerForms(ex, log, lesson.file, scene, sweep);
        // Where a student reads before answering: the lesson's text and errata, the steps the
        // replay may show while the exercise holds it (all of them for an exercise that does not
        // hold it), every exercise's prompt, hints and options, the explanations of those before.
        std::vector<Shown> shown{{"text", lesson.text}};
        addErrata(shown, "", lesson.errata);
        const auto limit = quizLimit(ex, log);
        for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
            const LessonStep& s = lesson.steps[k];
            // A step of another structure is shown whatever this exercise holds: its position
            // is in another trace.
            const bool sameTrace = lesson.setupOf(s.setup).key() == exKey;
            const auto stepAt = resolvePosition(s.at, log);
            if (sameTrace && limit && (!stepAt || *stepAt > *limit)) continue;
            const std::string sk = "steps[" + std::to_string(k) + "]";
            shown.push_back({sk + ".text", s.text});
            if (!s.note.en.empty()) shown.push_back({sk + ".note", s.note});
            addErrata(shown, sk + ".", s.errata);
        }
        for (std::size_t j = 0; j < lesson.exercises.size(); ++j) {
            const Exercise& other = lesson.exercises[j];
            const std::string ok = "exercises[" + std::to_string(j) + "]";
            const TextRole role = exercises::unitOf(other.kind).givenNumbers(other)
                                      ? TextRole::GivenData
                                      : TextRole::Exercise;
            shown.push_back({ok + ".prompt", other.prompt, j == i, role});
            for (std::size_t k = 0; k < other.hints.size(); ++k)
                shown.push_back(
                    {ok + ".hint[" + std::to_string(k) + "]", other.hints[k], false, role});
            for (std::size_t k = 0; k < other.choices.size(); ++k) {
                const std::string ck = ok + ".choices[" + std::to_string(k) + "]";
                shown.push_back({ck + ".text", other.choices[k].text, false, role});
                shown.push_back({ck + ".why", other.choices[k].why, false, role});
            }
            if (j < i && !explanations[j].en.empty())
                shown.push_back({ok + "'s explanation", explanations[j]});
        }
        // A compute exercise's own data may equal its answer; its prompt must state them ...
        const std::vector<double>* given = exercises::unitOf(ex.kind).givenNumbers(ex);
        const bool givenEqualsAnswer =
            given && std::any_of(given->begin(), given->end(), [&](double g) {
                return !forms.numbers.empty() && g == forms.numbers[0];
            });
        for (const Shown& s : shown) {
            // ... and so may the other texts that state data: the lesson's text (a practice's
            // states its instance) and the other compute prompts.
            if (givenEqualsAnswer &&
                (s.ownPrompt || s.place == "text" ||
                 (s.role == TextRole::GivenData && s.place.ends_with(".prompt"))))
                continue;
            for (const Language lang : languages()) {
                // A language's text left out shows the English, checked already.
                if (!s.text.has(lang)) continue;
                const auto found = findAnswer(forms, s.text.in(lang), s.role);
                if (!found) continue;
                const bool explanation = s.place.find("explanation") != std::string::npos;
                throw LessonError(lesson.file, ex.line, key,
                                  "its answer " + forms.describe + " is written in " + s.place +
                                      (explanation ? " (" + std::string(languageCode(lang)) + ")"
                                                   : "." + std::string(languageCode(lang))) +
                                      " as \"" + printable(*found, 120) +
                                      "\", which the student reads before answering");
            }
        }
    }
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

/// A number as the sheet writes it: the shortest text that reads back as it (0.4, not
/// 0.40000000000000002), so a report echoes what the student gave.
std::string shortest(double v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::to_string(v);
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
            t = shortest(r.number(v, p));  // finite, checked
        } else if (v.is_array()) {
            for (std::size_t i = 0; i < v.size(); ++i)
                t += (i ? "," : "") + shortest(r.number(v[i], JsonLineMap::element(p, i)));
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

Grade gradeAnswers(const Lesson& lesson, const LessonLogs& logs, const AnswerSheet& sheet,
                   Language lang, const std::string& sheetFile,
                   const std::vector<GridSweepRow>* sweep,
                   const std::variant<Scene, Scene2D>* scene) {
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
            given = parseAnswer(ex, it->second, &why, lang);
        }
        const Verdict v = checkAnswer(ex, logs.of(ex.setup), given.value_or(Answer{}), lang,
                                      lesson.file, sweep, scene);
        item.correct = given.has_value() && v.correct;
        item.expected = v.expected;
        item.feedback = item.answered && !given ? why + ". " + v.feedback : v.feedback;
        g.score += item.correct;
        g.items.push_back(std::move(item));
    }
    return g;
}

ClassTable classTable(const Lesson& lesson, const LessonLogs& logs,
                      const std::vector<std::pair<std::string, AnswerSheet>>& sheets,
                      const std::vector<GridSweepRow>* sweep) {
    ClassTable table;
    table.sheets = static_cast<int>(sheets.size());
    // Per exercise: each wrong answer as it reads (its canonical form), its first spelling, count.
    struct Wrong {
        std::string firstSpelling;
        int count = 0;
        std::size_t firstSeen = 0;
    };
    std::vector<std::map<std::string, Wrong>> wrongs(lesson.exercises.size());
    for (const Exercise& ex : lesson.exercises) {
        table.rows.emplace_back();
        table.rows.back().exercise = ex.id;
    }
    std::size_t seen = 0;
    for (const auto& [file, sheet] : sheets) {
        const Grade g = gradeAnswers(lesson, logs, sheet, Language::En, file, sweep);
        for (std::size_t i = 0; i < g.items.size(); ++i) {
            const Grade::Item& item = g.items[i];
            ClassTable::Row& row = table.rows[i];
            if (!item.answered) {
                ++row.notAnswered;
            } else if (item.correct) {
                ++row.right;
            } else {
                ++row.wrong;
                const auto parsed = parseAnswer(lesson.exercises[i], item.given, nullptr);
                const std::string key = parsed ? formatAnswer(lesson.exercises[i], *parsed)
                                               : "\x01" + item.given;  // unreadable: as typed
                Wrong& w = wrongs[i][key];
                if (w.count++ == 0) {
                    w.firstSpelling = item.given;
                    w.firstSeen = seen++;
                }
            }
        }
    }
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const Wrong* best = nullptr;
        for (const auto& [key, w] : wrongs[i])
            if (!best || w.count > best->count ||
                (w.count == best->count && w.firstSeen < best->firstSeen))
                best = &w;
        if (best) {
            table.rows[i].commonWrong = best->firstSpelling;
            table.rows[i].commonWrongCount = best->count;
        }
    }
    return table;
}

namespace {
/// A student's answer inside a Markdown table cell: one line, no cell break.
std::string markdownCell(const std::string& text) {
    std::string out;
    for (const char c : printable(text, 80)) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out;
}
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}
}  // namespace

std::string classTableMarkdown(const Lesson& lesson, const ClassTable& table, Language lang) {
    std::string out =
        trf(lang, "Lesson %1. %2: %3 answer sheets",
            {std::to_string(lesson.number), lesson.title.in(lang), std::to_string(table.sheets)}) +
        "\n\n| " + tr(lang, "exercise") + " | " + tr(lang, "right answers") + " | " +
        tr(lang, "wrong answers") + " | " + tr(lang, "not answered") + " | " +
        tr(lang, "most common wrong answer") + " | " + tr(lang, "how many") +
        " |\n|---|---:|---:|---:|---|---:|\n";
    for (const ClassTable::Row& r : table.rows)
        out += "| " + r.exercise + " | " + std::to_string(r.right) + " | " +
               std::to_string(r.wrong) + " | " + std::to_string(r.notAnswered) + " | " +
               (r.commonWrongCount ? markdownCell(r.commonWrong) : "") + " | " +
               (r.commonWrongCount ? std::to_string(r.commonWrongCount) : "") + " |\n";
    return out;
}

std::string classTableCsv(const ClassTable& table) {
    std::string out = "exercise,right,wrong,not_answered,most_common_wrong,how_many\n";
    for (const ClassTable::Row& r : table.rows)
        out += csvField(r.exercise) + "," + std::to_string(r.right) + "," +
               std::to_string(r.wrong) + "," + std::to_string(r.notAnswered) + "," +
               (r.commonWrongCount ? csvField(r.commonWrong) : "") + "," +
               (r.commonWrongCount ? std::to_string(r.commonWrongCount) : "") + "\n";
    return out;
}

}  // namespace raystep
