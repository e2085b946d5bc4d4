#pragma once
// The built-in lessons, embedded in the binaries at build time (cmake/embed_files.cmake), so the
// tools work from any folder without the source tree.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// Contents of the embedded lesson file `name` ("06-grid-2d-dda.json").
std::optional<std::string_view> embeddedLesson(std::string_view name);

/// Names of all embedded lesson files, sorted.
std::vector<std::string> embeddedLessonNames();

}  // namespace raystep
