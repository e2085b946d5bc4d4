#pragma once
// raystep-cli homework make | grade: a practice sheet per student of a roster, graded for
// Moodle's grade import (docs/practice.md, "Homework").
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace raystep::cli {

struct HomeworkArgs {
    CLI::App* make = nullptr;
    CLI::App* grade = nullptr;
    std::string roster, topics, level = "easy", lang = "en", output;
    std::uint64_t seed = 0;
    std::string dir, answers;
};

void addHomeworkCommand(CLI::App& app, HomeworkArgs& args);
int runHomework(const HomeworkArgs& args);

}  // namespace raystep::cli
