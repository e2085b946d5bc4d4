#pragma once
// `raystep-cli scenes`: the built-in scenes, 3D and 2D, with their sizes and what each shows.
#include <CLI/CLI.hpp>

namespace raystep::cli {

void addScenesCommand(CLI::App& app);
int listScenes();

}  // namespace raystep::cli
