#pragma once
// `raystep-cli compare`: midpoint, median and SAH splits of one tree on one scene, built and
// traced side by side.
#include "accel_args.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace raystep::cli {

struct CompareArgs {
    std::string scene = "default";
    AccelArgs accel;
    int width = 320, height = 240;
    std::optional<int> bounces;
    int threads = 0;
    bool json = false;
};
void addCompareCommand(CLI::App& app, CompareArgs& a);
int runCompare(const CompareArgs& a);
}  // namespace raystep::cli
