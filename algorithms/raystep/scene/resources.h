#pragma once
// Files embedded in the core at build time (the built-in scenes and their meshes;
// cmake/embed_files.cmake), so the tools work from any folder without the source tree.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// Contents of the embedded file `name`, by file name ("whitted.json", "stadium-knot.obj").
std::optional<std::string_view> embeddedFile(std::string_view name);

/// Names of all embedded files, sorted.
std::vector<std::string> embeddedFileNames();

}  // namespace raystep
