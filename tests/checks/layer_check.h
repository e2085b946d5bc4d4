#pragma once
// The layering as a check (docs/architecture.md, "Layers"): the core's floors include only their
// own floor and those under it, the core and the course engine include no Qt, VTK or lesson, and
// no client includes a header internal to a structure's build.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace raystep::checks {

/// One #include the layering forbids: its line (from 1), the header, and the rule it breaks.
struct LayerViolation {
    std::size_t line = 0;
    std::string header;
    std::string rule;
};

/// The core's floors, lowest first: a file under algorithms/raystep/<floor>/ includes
/// "raystep/<floor'>/..." only for a floor' at or below its own.
inline constexpr std::string_view kFloors[] = {"base",  "geometry", "trace",  "scene",
                                               "accel", "fast",     "render", "assess"};

/// Headers that only their own floor's .cpp files include (what a structure's builds or queries
/// share, what the assessor's parts share).
inline constexpr std::string_view kInternalHeaders[] = {
    "raystep/accel/kdtree_build.h", "raystep/accel/query_impl.h", "raystep/assess/divergence.h"};

/// The headers `source` includes, with their lines: `#include "x"` or `#include <x>` at the start
/// of a line (a commented-out include is not one).
std::vector<std::pair<std::size_t, std::string>> includesOf(std::string_view source);

/// What `source` breaks of the layering, as the file at `path` (relative to the repository's
/// root, with forward slashes: "algorithms/raystep/scene/scene.h", "app/gui/view2d.cpp").
std::vector<LayerViolation> findLayerViolations(std::string_view path, std::string_view source);

}  // namespace raystep::checks
