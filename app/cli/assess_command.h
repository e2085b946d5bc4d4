#pragma once
// `raystep-cli assess`: a student's own DDA, grid walk or tree traversal, logged as JSON Lines,
// checked against raystep's recorded run (docs/assignment-format.md).
#include "accel_args.h"

#include <CLI/CLI.hpp>

#include <string>

namespace raystep::cli {

struct AssessArgs {
    std::string target;  // "dda" or a scene
    std::string grid, min, max;
    AccelArgs accel;
    std::string trace, classDir, output;
    std::string lang = "en";
    bool json = false;
    bool structure = false;
};

void addAssessCommand(CLI::App& app, AssessArgs& args);
int runAssess(const AssessArgs& args);

}  // namespace raystep::cli
