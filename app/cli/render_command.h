#pragma once
// `raystep-cli render`: a scene to a PNG image, with a heat map of the primitive tests and the
// ray counts as JSON on request.
#include "accel_args.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace raystep::cli {

struct RenderArgs {
    std::string scene = "default";
    std::string output;
    std::optional<int> width, height, bounces, spp, diffuseSamples;
    AccelArgs accel;
    std::string rayOffset = "robust";
    int threads = 0;
    std::uint64_t seed = 1;
    std::string stats;
    std::string heatmap;
};

void addRenderCommand(CLI::App& app, RenderArgs& a);
int runRender(const RenderArgs& a);

}  // namespace raystep::cli
