#pragma once
// `raystep-cli build`: build an acceleration structure on a 3D or 2D scene and report its size,
// depth and SAH cost, or record every build event to a trace file.
#include "accel_args.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

namespace raystep::cli {

struct BuildArgs {
    std::string scene = "default";
    AccelArgs accel;
    bool json = false;
    std::string events;
    std::size_t maxEvents = EventLog::kDefaultCap;
};
void addBuildCommand(CLI::App& app, BuildArgs& a);
int runBuild(const BuildArgs& a);
}  // namespace raystep::cli
