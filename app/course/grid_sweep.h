#pragma once
// The grid sweep of the lesson on voxel size: the same rays through grids of growing resolution,
// and what each grid cost to build and what its rays paid.
#include "raystep/base/progress.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"

#include <cstdint>
#include <variant>
#include <vector>

namespace raystep {

/// The resolutions to sweep and the rays to send at each.
struct GridSweepSpec {
    std::vector<int> resolutions;  // cells per axis
    int width = 64, height = 48;   // the camera's primary rays (3D); 2D: a fan of rays
};

/// One resolution of a grid sweep: what the structure cost and what the rays paid.
struct GridSweepRow {
    int resolution = 0;
    std::uint64_t cells = 0, references = 0;
    double buildMs = 0.0, traceMs = 0.0;
    double testsPerRay = 0.0, cellsPerRay = 0.0, skipsPerRay = 0.0;
};
/// Runs the sweep (3D: the camera's primary rays; 2D: a fan of rays from the example ray's
/// origin). `progress` may cancel (BuildCancelled).
std::vector<GridSweepRow> runGridSweep(const std::variant<Scene, Scene2D>& scene,
                                       const GridSweepSpec& spec, const ProgressFn& progress = {});

}  // namespace raystep
