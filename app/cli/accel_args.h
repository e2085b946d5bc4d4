#pragma once
// The options that choose and tune an acceleration structure and the intersection kernels,
// shared by render, build, trace and compare.
#include "raystep/accel/accel.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace raystep::cli {

struct AccelArgs {
    std::string accel = "bruteforce";
    std::string split = "sah";
    std::string kdBuild = "exact";
    std::optional<double> cTrav, cIsect, emptyBonus;
    std::optional<int> maxDepth, leafSize, buckets, binAbove;
    double gridLambda = 4.0;
    std::string gridRes;
    std::string mailbox = "on";
    std::string precision = "double";
    std::string triangleMethod = "watertight";
    std::string sphereMethod = "stable";
};

/// Adds --accel, --split, the tree costs, the grid's options and the kernels to `cmd`.
void addAccelOptions(CLI::App* cmd, AccelArgs& a);

struct AccelChoice {
    AccelKind kind = AccelKind::BruteForce;
    KernelOptions kernels;
    AccelOptions options;
};

/// Checks every value; on a bad one, the one-line message for fail().
std::optional<std::string> resolveAccel(const AccelArgs& a, AccelChoice& out);
/// The scene loader checks a scene against the double kernels' range; with --precision float the
/// narrower float range is checked here (the message names the scene).
std::optional<std::string> checkKernelRange(const std::string& sceneName, const Scene& scene,
                                            const AccelChoice& choice);

/// "kdtree sah", "grid", "bvh median": what the structure is, for tables and trace files.
std::string describeAccel(const AccelChoice& c);

}  // namespace raystep::cli
