#pragma once
// raystep-cli practice list | make: generated exercises (docs/practice.md).
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace raystep::cli {

struct PracticeArgs {
    CLI::App* list = nullptr;
    CLI::App* make = nullptr;
    std::string topic;
    std::uint64_t seed = 0;
    std::string level = "easy";
    std::string lang = "en";
    std::string output;  // -o: the lesson file
    std::string figure;  // --figure: a 2D instance drawn as a PNG
    bool json = false;
};

void addPracticeCommand(CLI::App& app, PracticeArgs& args);
int runPractice(const PracticeArgs& args);

}  // namespace raystep::cli
