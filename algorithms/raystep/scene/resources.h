#pragma once
// Files embedded in the binaries at build time (the built-in scenes, their meshes, the lessons),
// so the tools work from any folder without the source tree.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// Contents of the embedded file `name`: a scene by file name ("whitted.json"), a lesson as
/// "lessons/06-grid-2d-dda.json".
std::optional<std::string_view> embeddedFile(std::string_view name);

/// Names of all embedded files, sorted.
std::vector<std::string> embeddedFileNames();

}  // namespace raystep
