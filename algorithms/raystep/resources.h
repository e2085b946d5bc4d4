#pragma once
// Files embedded in the binaries at build time (the built-in scenes and their meshes),
// so the tools work from any folder without the source tree.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// Contents of the embedded file `name` (a file name under scenes/, e.g. "whitted.json").
std::optional<std::string_view> embeddedFile(std::string_view name);

/// Names of all embedded files, sorted.
std::vector<std::string> embeddedFileNames();

}  // namespace raystep
