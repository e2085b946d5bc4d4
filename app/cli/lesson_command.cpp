#include "lesson_command.h"

#include "common.h"
#include "progress.h"

#include "course/exercise.h"
#include "course/grading.h"
#include "course/grid_sweep.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include "raystep/scene/scene_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace raystep::cli {

void addLessonCommand(CLI::App& app, LessonArgs& a) {
    CLI::App* lesson = app.add_subcommand(
        "lesson", "The lessons: list them, show one, validate a lesson file, grade answers");
    lesson->require_subcommand(1);
    a.list = lesson->add_subcommand("list", "The built-in lessons in the lecture's order");
    a.show = lesson->add_subcommand("show", "A lesson's text, steps and exercises");
    a.show->add_option("LESSON", a.lesson, "Lesson id, number or file")->required();
    a.validate = lesson->add_subcommand(
        "validate", "Load a lesson file, record its trace, check every step and exercise");
    a.validate->add_option("FILE", a.lesson, "Lesson file, id or number")->required();
    a.key = lesson->add_subcommand(
        "key", "The answer key read from the trace, as an answers file (for lecturers)");
    a.key->add_option("LESSON", a.lesson, "Lesson id, number or file")->required();
    a.check = lesson->add_subcommand(
        "check", "Grade an answers file (score and feedback), or a folder of them (a class table)");
    a.check->add_option("LESSON", a.lesson, "Lesson id, number or file")->required();
    a.check
        ->add_option("--answers", a.answers,
                     "Answers: {\"lesson\": ID, \"answers\": {...}}, or a folder of such "
                     "files (*.json)")
        ->check(fileName())
        ->required();
    a.check
        ->add_option("--format", a.format,
                     "The class table per exercise: markdown (the default for a folder) or csv")
        ->check(CLI::IsMember({"markdown", "csv"}));
    a.check->add_flag("--json", a.json, "Print the grade as JSON");
    a.sweep = lesson->add_subcommand(
        "sweep", "Run a lesson's grid sweep: the same rays at each grid resolution, as a table");
    a.sweep->add_option("LESSON", a.lesson, "Lesson id, number or file")->required();
    a.sweep->add_flag("--json", a.json, "Print the rows as JSON");
    for (CLI::App* c : {a.show, a.check, a.key})
        c->add_option("--lang", a.lang, "Language of the texts: " + languageChoices())
            ->capture_default_str();
}

namespace {

int list() {
    for (const Lesson& l : builtinLessons())
        std::printf("%2d  %-22s %-13s %2zu steps %2zu exercises  %s\n", l.number, l.id.c_str(),
                    l.scene.c_str(), l.steps.size(), l.exercises.size(), l.title.en.c_str());
    return 0;
}

/// Errata as a quoted block under the text they belong to.
void printErrata(const std::vector<Erratum>& errata, Language lang) {
    for (const Erratum& e : errata)
        std::printf("\n> **%s**\n>\n> %s %s\n>\n> %s %s\n>\n> %s\n", erratumHeading(lang).c_str(),
                    tr(lang, "Slide:").c_str(), e.slide.in(lang).c_str(),
                    tr(lang, "Correct:").c_str(), e.correct.in(lang).c_str(),
                    e.why.in(lang).c_str());
}

}  // namespace

int showLesson(Lesson l, Language lang) {
    // Steps with a computed note (the slides' DDA loop beside the exact walk) need the lesson run.
    if (std::any_of(l.steps.begin(), l.steps.end(),
                    [](const LessonStep& s) { return s.textbookDda; })) {
        const LessonRun run = raystep::runLesson(l);  // the course's, not this command's
        addStepNotes(l, *run.scene, run.accel2D ? &*run.accel2D : nullptr);
    }
    std::printf("# %d. %s\n\n%s\n", l.number, l.title.in(lang).c_str(), l.text.in(lang).c_str());
    printErrata(l.errata, lang);
    for (std::size_t i = 0; i < l.steps.size(); ++i) {
        const LessonStep& s = l.steps[i];
        // A step of its own structure names it, as the app switches to it.
        const std::string on = s.setup ? ", " + trf(lang, "on the %1", {s.setup->name()}) : "";
        std::printf("\n## %s %zu (%s%s)\n\n%s\n", tr(lang, "Step").c_str(), i + 1,
                    describePosition(s.at, lang).c_str(), on.c_str(), s.text.in(lang).c_str());
        if (!s.compare.empty()) {
            std::string names;
            for (const StructureChoice& c : s.compare)
                names += (names.empty() ? "" : ", ") + choiceName(c);
            std::printf("\n[%s: %s]\n", tr(lang, "Compare these structures on this ray").c_str(),
                        names.c_str());
        }
        if (!l.steps[i].note.en.empty()) std::printf("\n> %s\n", l.steps[i].note.in(lang).c_str());
        printErrata(l.steps[i].errata, lang);
    }
    for (const Exercise& ex : l.exercises) {
        // A replayed walk (spot_bug) is a trace of its own on the lesson's grid.
        const std::string on = !ex.setup ? ""
                               : ex.setup->replay.empty()
                                   ? ", " + trf(lang, "on the %1", {ex.setup->name()})
                                   : ", " + trf(lang, "its own walk on the %1", {ex.setup->name()});
        std::printf("\n## %s %s (%s%s)\n\n%s\n", tr(lang, "Exercise").c_str(), ex.id.c_str(),
                    std::string(exerciseKindName(ex.kind)).c_str(), on.c_str(),
                    ex.prompt.in(lang).c_str());
        for (std::size_t i = 0; i < ex.choices.size(); ++i)
            std::printf("%s%c) %s\n", i ? "" : "\n", static_cast<char>('a' + i),
                        ex.choices[i].text.in(lang).c_str());
    }
    return 0;
}

namespace {

/// The answer key; in Italian the numbers with a decimal comma, as a student there types them.
int key(const Lesson& l, Language lang) {
    const LessonRun run = runLesson(l);
    const std::vector<GridSweepRow> sweep = sweepRowsIfNeeded(l, run);
    nlohmann::ordered_json answers = nlohmann::ordered_json::object();
    for (const Exercise& ex : l.exercises)
        answers[ex.id] =
            formatAnswer(ex, referenceAnswer(ex, run.logs().of(ex.setup), l.file, &sweep), lang);
    const nlohmann::ordered_json out = {{"lesson", l.id}, {"answers", answers}};
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
}

/// The answer sheets of a folder (its *.json files, by name) or the one file `path`.
std::vector<std::pair<std::string, AnswerSheet>> loadSheets(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_directory(path, ec)) return {{path, loadAnswerSheetFile(path)}};
    std::vector<std::string> files;
    for (std::filesystem::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".json") files.push_back(it->path().string());
    if (ec) throw LessonError(path, 0, "", "cannot list the folder of answers: " + ec.message());
    if (files.empty())
        throw LessonError(path, 0, "", "no answer sheets (*.json files) in the folder");
    std::sort(files.begin(), files.end());
    std::vector<std::pair<std::string, AnswerSheet>> sheets;
    for (const std::string& f : files) sheets.emplace_back(f, loadAnswerSheetFile(f));
    return sheets;
}

int check(const Lesson& l, const LessonArgs& a, Language lang) {
    std::error_code ec;
    const bool folder = std::filesystem::is_directory(a.answers, ec);
    // Every sheet is read and graded before anything is printed: a bad one stops all.
    const auto sheets = loadSheets(a.answers);
    const LessonRun run = runLesson(l);
    const std::vector<GridSweepRow> sweep = sweepRowsIfNeeded(l, run);
    if (folder || !a.format.empty()) {
        if (a.json) return fail("--json grades one answers file; a class table is --format");
        const ClassTable table = classTable(l, run.logs(), sheets, &sweep);
        const std::string out =
            a.format == "csv" ? classTableCsv(table) : classTableMarkdown(l, table, lang);
        std::fwrite(out.data(), 1, out.size(), stdout);
        return 0;
    }
    const std::string& answersPath = a.answers;
    const bool json = a.json;
    const AnswerSheet& sheet = sheets.front().second;
    const Grade g = gradeAnswers(l, run.logs(), sheet, lang, answersPath, &sweep, run.scene.get());
    if (json) {
        nlohmann::ordered_json items = nlohmann::ordered_json::array();
        for (const auto& i : g.items)
            items.push_back({{"exercise", i.exercise},
                             {"answered", i.answered},
                             {"correct", i.correct},
                             {"given", i.given},
                             {"expected", i.expected},
                             {"feedback", i.feedback}});
        const nlohmann::ordered_json out = {
            {"lesson", l.id}, {"score", g.score}, {"out_of", g.items.size()}, {"exercises", items}};
        std::printf("%s\n", out.dump(2).c_str());
        return 0;
    }
    std::printf("%s\n", trf(lang, "Lesson %1. %2: %3 / %4",
                            {std::to_string(l.number), l.title.in(lang), std::to_string(g.score),
                             std::to_string(g.items.size())})
                            .c_str());
    for (const auto& i : g.items) {
        const std::string mark = !i.answered ? tr(lang, "no answer")
                                 : i.correct ? tr(lang, "right")
                                             : tr(lang, "wrong");
        std::printf("  %-16s %-14s", i.exercise.c_str(), mark.c_str());
        // The answer is the student's text: escaped, so it cannot forge a line of the report.
        if (i.answered)
            std::printf(" %s: %s", tr(lang, "given").c_str(), printable(i.given, 200).c_str());
        std::printf("\n      %s\n", printable(i.feedback, 2000).c_str());
    }
    return 0;
}

int sweep(const Lesson& l, bool json) {
    if (!l.sweep) return fail(l.file + ": lesson " + l.id + " has no sweep");
    std::variant<Scene, Scene2D> scene;
    try {
        scene = loadLessonScene(l);
    } catch (const LessonError& e) {
        return fail(e.what());
    }
    ProgressBar bar("sweep");
    const auto rows = runGridSweep(scene, *l.sweep, [&](double f) { return bar.update(f); });
    bar.finish();
    if (json) {
        nlohmann::ordered_json out = nlohmann::ordered_json::array();
        for (const GridSweepRow& r : rows)
            out.push_back({{"resolution", r.resolution},
                           {"cells", r.cells},
                           {"references", r.references},
                           {"build_ms", r.buildMs},
                           {"trace_ms", r.traceMs},
                           {"tests_per_ray", r.testsPerRay},
                           {"cells_per_ray", r.cellsPerRay},
                           {"skips_per_ray", r.skipsPerRay}});
        std::printf("%s\n", out.dump(2).c_str());
        return 0;
    }
    std::printf("%10s %10s %10s %9s %10s %10s %10s %9s\n", "cells/axis", "cells", "refs",
                "build ms", "tests/ray", "cells/ray", "skips/ray", "trace ms");
    for (const GridSweepRow& r : rows)
        std::printf("%10d %10llu %10llu %9.1f %10.1f %10.1f %10.1f %9.1f\n", r.resolution,
                    static_cast<unsigned long long>(r.cells),
                    static_cast<unsigned long long>(r.references), r.buildMs, r.testsPerRay,
                    r.cellsPerRay, r.skipsPerRay, r.traceMs);
    return 0;
}

}  // namespace

int runLesson(CLI::App* /*lessonCommand*/, const LessonArgs& a) {
    const auto lang = parseLanguage(a.lang);
    if (!lang) return fail("--lang " + a.lang + ": expected " + languageChoices());
    try {
        if (a.list->parsed()) return list();
        const Lesson l = loadLesson(a.lesson);
        if (a.show->parsed()) return showLesson(l, *lang);
        if (a.validate->parsed()) {
            validateLesson(l);
            std::printf(
                "%s: lesson %d '%s' is valid: %zu steps, %zu exercises, each with a "
                "reference answer in its trace\n",
                a.lesson.c_str(), l.number, l.id.c_str(), l.steps.size(), l.exercises.size());
            return 0;
        }
        if (a.key->parsed()) return key(l, *lang);
        if (a.sweep->parsed()) return sweep(l, a.json);
        return check(l, a, *lang);
    } catch (const FileError& e) {
        return fail(e.what());
    }
}

}  // namespace raystep::cli
