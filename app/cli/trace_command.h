#pragma once
// `raystep-cli trace`: every event of one pixel's ray tree (3D) or of one ray (2D), to a trace
// file the GUI replays.
#include "accel_args.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace raystep::cli {

struct TraceArgs {
    std::string scene = "default";
    AccelArgs accel;
    const CLI::Option* accelOption = nullptr;  // whether --accel was given (models: a tree)
    std::string pixel;
    std::string ray;
    std::string output;
    std::optional<int> width, height, bounces, spp, diffuseSamples;
    std::uint64_t seed = 1;
    std::size_t maxEvents = EventLog::kDefaultCap;
};
void addTraceCommand(CLI::App& app, TraceArgs& a);
int runTrace(const TraceArgs& a);
}  // namespace raystep::cli
