#include "practice_command.h"

#include "common.h"
#include "lesson_command.h"

#include "course/lesson.h"
#include "course/practice/figure.h"
#include "course/practice/practice.h"

#include <cstdio>

namespace raystep::cli {

void addPracticeCommand(CLI::App& app, PracticeArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "practice", "Generated exercises: a fresh instance of a topic for every seed");
    cmd->require_subcommand(1);
    a.list = cmd->add_subcommand("list", "The practice topics and their levels");
    a.make = cmd->add_subcommand(
        "make",
        "One instance: its exercises (Markdown), its data and answers (--json), or its "
        "lesson file (-o)");
    a.make->add_option("TOPIC", a.topic, "A topic of `practice list`")->required();
    addPracticeOptions(a.make, a.seed, UINT64_MAX, "The instance: the same seed gives the same one",
                       a.level, "easy, medium or hard", a.lang, "Language of the texts")
        ->required();
    a.make->add_flag("--json", a.json,
                     "Print {\"format\": \"raystep-practice\", \"given\", \"answers\", ...}");
    a.make
        ->add_option("-o,--output", a.output,
                     "Write the instance as a lesson file (the app and `lesson check` open it)")
        ->check(fileName());
    a.make->add_option("--figure", a.figure, "Draw a 2D instance (grid, ray, d) as a PNG file")
        ->check(fileName());
}

int runPractice(const PracticeArgs& a) {
    if (a.list->parsed()) {
        for (const PracticeTopic& t : practiceTopics())
            std::printf("%-13s %s\n              %s\n", t.name.c_str(), t.title.en.c_str(),
                        t.about.en.c_str());
        return 0;
    }
    const auto lang = parseLanguage(a.lang);
    if (!lang) return fail("--lang " + a.lang + ": expected " + languageChoices());
    if (!findPracticeTopic(a.topic))
        return fail("practice make " + a.topic + ": unknown topic (expected one of " +
                    practiceTopicList() + ")");
    if (auto problem = checkOutputs({{"-o", a.output}, {"--figure", a.figure}}))
        return fail(*problem);
    const PracticeInstance p = makePractice(a.topic, a.seed, *parsePracticeLevel(a.level));
    std::vector<FileToWrite> files;
    if (!a.output.empty()) files.push_back({a.output, p.lessonText});
    std::optional<std::string> png;
    if (!a.figure.empty()) {
        png = practiceFigurePng(p.lesson);
        if (!png)
            return fail("--figure: " + a.topic + " is a 3D topic; only 2D instances are drawn");
        files.push_back({a.figure, *png});
    }
    if (auto problem = writeOutputs(files)) return fail(*problem);
    if (a.json) {
        std::printf("%s\n", p.toJson().dump(2).c_str());
        return 0;
    }
    if (!a.figure.empty() && a.output.empty()) {
        std::printf("%s: the figure of %s\n", a.figure.c_str(), p.lesson.id.c_str());
        return 0;
    }
    if (!a.output.empty()) {
        std::printf("%s: %s, %s, seed %llu\n", a.output.c_str(), a.topic.c_str(), a.level.c_str(),
                    static_cast<unsigned long long>(a.seed));
        return 0;
    }
    return showLesson(p.lesson, *lang);
}

}  // namespace raystep::cli
