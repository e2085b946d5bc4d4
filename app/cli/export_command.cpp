#include "export_command.h"

#include "common.h"

#include "course/lesson.h"
#include "course/moodle.h"
#include "course/practice/practice.h"

#include <cstdio>

namespace raystep::cli {

void addExportCommand(CLI::App& app, ExportArgs& a) {
    CLI::App* cmd = app.add_subcommand("export", "Questions for a course's LMS");
    cmd->require_subcommand(1);
    a.moodle = cmd->add_subcommand(
        "moodle",
        "A lesson, or variants of a practice topic, as Moodle XML or GIFT questions "
        "(one category per exercise: a quiz draws one variant from each)");
    a.moodle->add_option("LESSON", a.lesson, "Lesson id, number or file");
    CLI::Option* topic =
        a.moodle->add_option("--topic", a.topic, "A practice topic (`practice list`) instead");
    a.moodle->add_option("--variants", a.variants, "Variants of each exercise (--topic)")
        ->check(CLI::Range(1, 500))
        ->capture_default_str();
    addPracticeOptions(a.moodle, a.seed, UINT64_MAX - 500,
                       "The first variant's seed; the others follow it", a.level,
                       "easy, medium or hard (--topic)", a.lang, "Language of the questions")
        ->capture_default_str();
    a.moodle->add_option("--format", a.format, "xml (Moodle XML, with figures) or gift (text)")
        ->check(CLI::IsMember({"xml", "gift"}))
        ->capture_default_str();
    a.moodle->add_option("-o,--output", a.output, "The file to write")
        ->check(fileName())
        ->required();
    (void)topic;
}

int runExport(const ExportArgs& a) {
    const auto lang = parseLanguage(a.lang);
    if (!lang) return fail("--lang " + a.lang + ": expected " + languageChoices());
    if (a.lesson.empty() == a.topic.empty())
        return fail("export moodle: give a LESSON or --topic TOPIC, not both nor neither");
    if (!a.topic.empty() && !findPracticeTopic(a.topic))
        return fail("--topic " + a.topic + ": unknown topic (expected one of " +
                    practiceTopicList() + ")");
    if (auto problem = checkOutputs({{"-o", a.output}}, {a.lesson})) return fail(*problem);
    std::vector<MoodleSource> sources;
    if (!a.lesson.empty()) {
        Lesson l = loadLesson(a.lesson);
        const std::string category = "raystep/" + l.id;
        sources.push_back({std::move(l), category});
    } else {
        const PracticeLevel level = *parsePracticeLevel(a.level);
        for (int v = 0; v < a.variants; ++v)
            sources.push_back({makePractice(a.topic, a.seed + v, level).lesson,
                               "raystep/" + a.topic + "-" + a.level});
    }
    const MoodleExport out =
        a.format == "xml" ? moodleXml(sources, *lang) : moodleGift(sources, *lang);
    if (auto problem = writeOutputs({{a.output, out.text}})) return fail(*problem);
    for (const std::string& s : out.skipped) std::fprintf(stderr, "skipped %s\n", s.c_str());
    std::printf("%s: %d questions (%s)%s\n", a.output.c_str(), out.questions, a.format.c_str(),
                a.format == "gift" ? ", text only: the figures are in the xml format" : "");
    return 0;
}

}  // namespace raystep::cli
