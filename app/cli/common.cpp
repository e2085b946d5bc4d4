#include "common.h"

#include <charconv>
#include <cmath>
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

}  // namespace raystep::cli
