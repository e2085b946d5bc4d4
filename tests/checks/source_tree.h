#pragma once
// What the checks of the source tree share: its files, read whole, and a line planted in one
// (their own tests show a planted line is caught at its line).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace raystep::checks {

/// Every .h and .cpp under `root`/`folder` for each folder, sorted.
inline std::vector<std::filesystem::path> sourceFiles(const std::filesystem::path& root,
                                                      const std::vector<std::string>& folders) {
    std::vector<std::filesystem::path> files;
    for (const std::string& folder : folders)
        for (const auto& e : std::filesystem::recursive_directory_iterator(root / folder))
            if (e.is_regular_file() &&
                (e.path().extension() == ".h" || e.path().extension() == ".cpp"))
                files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

inline std::string readWhole(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// `text` with `line` put before its line number `at` (from 1).
inline std::string plantAt(const std::string& text, std::size_t at, const std::string& line) {
    std::size_t offset = 0;
    for (std::size_t k = 1; k < at; ++k) offset = text.find('\n', offset) + 1;
    return text.substr(0, offset) + line + "\n" + text.substr(offset);
}

}  // namespace raystep::checks
