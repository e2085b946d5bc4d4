#include "common.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace raystep::cli {

int fail(const std::string& message) {
    std::cerr << "raystep-cli: error: " << message << "\n";
    return kExitBadInput;
}

std::optional<std::vector<double>> parseNumbers(const std::string& text, char separator) {
    std::vector<double> out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = text.find(separator, start);
        const std::string part = text.substr(start, end == std::string::npos ? end : end - start);
        double value = 0.0;
        const char* first = part.data();
        const char* last = part.data() + part.size();
        if (!part.empty() && *first == '+') ++first;  // from_chars takes no leading '+'
        const auto [ptr, ec] = std::from_chars(first, last, value);
        if (part.empty() || ec != std::errc() || ptr != last || !std::isfinite(value))
            return std::nullopt;
        out.push_back(value);
        if (end == std::string::npos) return out;
        start = end + 1;
    }
}

bool hasExtension(const std::string& path, const std::string& ext) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e == ext;
}

std::optional<std::string> checkWritable(const std::string& option, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent))
        return option + " " + path + ": folder '" + parent.string() + "' does not exist";
    if (fs::is_directory(path)) return option + " " + path + ": is a folder";
    return std::nullopt;
}

std::optional<int> parseInt(const std::string& text, int lo, int hi) {
    int value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    if (value < lo || value > hi) return std::nullopt;
    return value;
}

}  // namespace raystep::cli
