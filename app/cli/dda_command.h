#pragma once
// `raystep-cli dda`: the cells a ray walks through in a regular grid, with the lecture's
// variables (X, Y, Z, tMax, tDelta, step), as the table a lecturer writes on the board or as JSON.
#include <CLI/CLI.hpp>

#include <string>

namespace raystep::cli {

struct DdaArgs {
    std::string grid, min, max, origin, dir;
    std::string precision = "double";
    bool json = false;
    std::string format;  // csv, markdown or latex: the board's table (trace/board.h)
};

void addDdaCommand(CLI::App& app, DdaArgs& args);
int runDda(const DdaArgs& args);

}  // namespace raystep::cli
