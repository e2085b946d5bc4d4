#pragma once
// raystep-cli export moodle: lessons and practice variants as Moodle XML or GIFT questions.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace raystep::cli {

struct ExportArgs {
    CLI::App* moodle = nullptr;
    std::string lesson;  // a lesson id, number or file
    std::string topic;   // or a practice topic's variants
    int variants = 20;
    std::uint64_t seed = 1;
    std::string level = "easy";
    std::string lang = "en";
    std::string format = "xml";
    std::string output;
};

void addExportCommand(CLI::App& app, ExportArgs& args);
int runExport(const ExportArgs& args);

}  // namespace raystep::cli
