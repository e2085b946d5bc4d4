#pragma once
// raystep-cli build, trace and compare: the acceleration structures from the command line.
#include "accel_args.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <optional>
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

struct TraceArgs {
    std::string scene = "default";
    AccelArgs accel;
    std::string pixel;
    std::string ray;
    std::string output;
    std::optional<int> width, height, bounces, spp, diffuseSamples;
    std::uint64_t seed = 1;
    std::size_t maxEvents = EventLog::kDefaultCap;
};
void addTraceCommand(CLI::App& app, TraceArgs& a);
int runTrace(const TraceArgs& a);

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
