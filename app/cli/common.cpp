// The shared CLI helpers: errors, number parsing, option checks and all-or-none output files.
#include "common.h"

#include "raystep/base/file_error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace raystep::cli {

int fail(const std::string& message) {
    // One line whatever the message quotes (an option's value, a name): escaped as file text is.
    std::cerr << "raystep-cli: error: " << printable(message, 4096) << "\n";
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

std::optional<std::string> checkOutputs(
    const std::vector<std::pair<std::string, std::string>>& optionsAndPaths,
    const std::vector<std::string>& inputs) {
    for (std::size_t i = 0; i < optionsAndPaths.size(); ++i) {
        const auto& [option, path] = optionsAndPaths[i];
        if (path.empty()) continue;
        if (const std::string why = writeProblem(path); !why.empty())
            return option + " " + path + ": " + why;
        for (const std::string& input : inputs)
            if (std::error_code ec;
                std::filesystem::is_regular_file(input, ec) && sameFile(input, path))
                return option + " " + path +
                       ": the command reads this file; writing over it "
                       "would lose it";
        for (std::size_t j = 0; j < i; ++j) {
            const auto& [otherOption, otherPath] = optionsAndPaths[j];
            if (!otherPath.empty() && sameFile(otherPath, path))
                return option + " " + path + ": the same file as " + otherOption;
        }
    }
    return std::nullopt;
}

std::optional<std::string> writeOutputs(const std::vector<FileToWrite>& files) {
    try {
        writeFilesAtomic(files);
    } catch (const std::exception& e) {
        return e.what();
    }
    return std::nullopt;
}

CLI::Validator wholeNumber(std::uint64_t lo, std::uint64_t hi) {
    const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            const char* first = text.data();
            const char* last = text.data() + text.size();
            if (first != last && *first == '+') ++first;  // as parseNumbers takes it
            std::uint64_t value = 0;
            const auto [ptr, ec] = std::from_chars(first, last, value);  // no sign, base 10
            if (first == last || ec != std::errc() || ptr != last || value < lo || value > hi)
                return "'" + text + "' is not a whole number from " + range;
            // CLI11 reads "010" as octal 8 and "0x10" as hex: hand it plain decimal digits.
            text = std::to_string(value);
            return {};
        },
        "INT in [" + range + "]");
}

CLI::Validator fileName() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            return text.empty() ? std::string("an empty file name") : std::string();
        },
        "FILE");
}

CLI::Validator finiteNumber() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const auto v = parseNumbers(text);
            if (!v || v->size() != 1) return "'" + text + "' is not a finite number";
            return {};
        },
        "NUMBER");
}

void addMaxEventsOption(CLI::App* cmd, std::size_t& cap) {
    cmd->add_option("--max-events", cap, "Stop recording after this many events")
        ->transform(wholeNumber(1, 20'000'000))
        ->capture_default_str();
}

std::optional<int> parseInt(const std::string& text, int lo, int hi) {
    int value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    if (value < lo || value > hi) return std::nullopt;
    return value;
}

}  // namespace raystep::cli
