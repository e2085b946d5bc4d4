#pragma once
// A built tree's statistics as JSON: `build --json` prints it, `compare` makes its rows of it.
#include "raystep/accel/accel.h"

#include <nlohmann/json.hpp>

namespace raystep::cli {

/// Structure, nodes, leaves, depth, references, SAH cost, build time and why the leaves were made.
nlohmann::ordered_json statsJson(const BuildSummary& b);

}  // namespace raystep::cli
