#pragma once
// `raystep-cli compare`: structures built and traced side by side on one scene's rays: a tree's
// midpoint, median and SAH splits, or any set of kinds (--accel grid,kdtree,bvh,bruteforce).
#include "accel_args.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace raystep::cli {

struct CompareArgs {
    std::string scene = "default";
    AccelArgs accel;
    int width = 320, height = 240;
    std::optional<int> bounces, spp, diffuseSamples;
    int threads = 0;
    bool json = false;
    const CLI::App* command = nullptr;  // whether --split was given (a tree alone: every split)
};
void addCompareCommand(CLI::App& app, CompareArgs& a);
int runCompare(const CompareArgs& a);
}  // namespace raystep::cli
