#pragma once
// `raystep-cli render`: a scene or a model (.obj .ply .stl .gltf .glb) to a PNG image, with a heat
// map of the primitive tests and the ray counts as JSON on request.
#include "accel_args.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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
    std::string saveScene;  // a model's scene, written as a scene file
    const CLI::Option* accelOption =
        nullptr;  // whether --accel was given (models default to a tree)
    // --precision, --triangle-method, --sphere-method: whether one was given (the fast path has
    // its own kernels).
    std::vector<const CLI::Option*> kernelOptions;
};

/// The --accel name of the fast path (fast/wide_bvh.h): a wide BVH in float that records nothing.
inline constexpr const char* kFastAccel = "fast";

void addRenderCommand(CLI::App& app, RenderArgs& a);
int runRender(const RenderArgs& a);

}  // namespace raystep::cli
