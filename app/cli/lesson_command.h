#pragma once
// raystep-cli lesson list | show | validate | key | check | sweep: the lessons from the command
// line, and grading a course's answers against the recorded trace.
#include "raystep/base/i18n.h"

#include <CLI/CLI.hpp>

#include <string>

namespace raystep::cli {

struct LessonArgs {
    CLI::App* list = nullptr;
    CLI::App* show = nullptr;
    CLI::App* validate = nullptr;
    CLI::App* key = nullptr;
    CLI::App* check = nullptr;
    CLI::App* sweep = nullptr;
    std::string lesson;   // id, number or file
    std::string answers;  // check: the answers file, or a folder of them (a class)
    std::string format;   // check: "markdown" or "csv", the class table (default for a folder)
    std::string lang = "en";
    bool json = false;
};

void addLessonCommand(CLI::App& app, LessonArgs& args);
int runLesson(CLI::App* lessonCommand, const LessonArgs& args);
}  // namespace raystep::cli

namespace raystep {
struct Lesson;
}

namespace raystep::cli {
/// A lesson's text, steps and exercises as Markdown (`lesson show`; `practice make`).
int showLesson(Lesson lesson, Language lang);

}  // namespace raystep::cli
