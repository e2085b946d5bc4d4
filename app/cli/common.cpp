// The shared CLI helpers: errors, number parsing, option checks and all-or-none output files.
#include "common.h"

#include "progress.h"

#include "raystep/base/file_error.h"
#include "raystep/base/i18n.h"
#include "raystep/scene/model_import.h"

#include <tbb/info.h>

#include <signal.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>

namespace raystep::cli {

int fail(const std::string& message) {
    // One line whatever the message quotes (an option's value, a name): escaped as file text is.
    std::cerr << "raystep-cli: error: " << printable(message, 4096) << "\n";
    return kExitBadInput;
}

std::vector<std::string> splitList(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string::npos ? end : end - start));
        if (end == std::string::npos) return parts;
        start = end + 1;
    }
}

std::optional<std::vector<double>> parseNumbers(const std::string& text, char separator) {
    std::vector<double> out;
    for (const std::string& part : splitList(text, separator)) {
        double value = 0.0;
        const char* first = part.data();
        const char* last = part.data() + part.size();
        if (!part.empty() && *first == '+') ++first;  // from_chars takes no leading '+'
        const auto [ptr, ec] = std::from_chars(first, last, value);
        if (part.empty() || ec != std::errc() || ptr != last || !std::isfinite(value))
            return std::nullopt;
        out.push_back(value);
    }
    return out;
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

std::vector<std::string> inputsOf(const std::string& sceneOrModel) {
    return inputFilesOf(sceneOrModel);
}

namespace {
std::string& current() {
    static std::string input;
    return input;
}
}  // namespace

const std::string& currentInput() {
    return current();
}

void setCurrentInput(const std::string& nameOrPath) {
    current() = nameOrPath;
}

std::variant<Scene, Scene2D> loadInput(const std::string& nameOrPath) {
    setCurrentInput(nameOrPath);
    if (!isModelPath(nameOrPath)) return loadAnyScene(nameOrPath);
    ProgressBar bar("import " + nameOrPath);
    auto scene = loadAnySceneOrModel(nameOrPath, [&](double f) { return bar.update(f); });
    bar.finish();
    return scene;
}

int threadCount(int asked) {
    const int available = std::max(1, tbb::info::default_concurrency());
    return asked > 0 ? std::min(asked, available) : available;
}

namespace {
volatile std::sig_atomic_t deferredSignal = 0;
extern "C" void deferSignal(int sig) {
    deferredSignal = sig;
}
}  // namespace

std::optional<std::string> writeOutputs(const std::vector<FileToWrite>& files) {
    // Ctrl+C, a kill (SIGTERM), a closed terminal while the files are written wait for the
    // write to end (every file in place, or none and no temporary), then end the program as they
    // would have: a handler, not a blocked mask, since any thread (TBB's too) may receive them.
    // SIGKILL cannot wait (docs/reliability.md says what it can leave).
    constexpr std::array<int, 4> kSignals = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
    std::array<struct sigaction, kSignals.size()> previous{};
    struct sigaction defer {};
    defer.sa_handler = deferSignal;
    defer.sa_flags = SA_RESTART;  // the write's system calls go on
    sigfillset(&defer.sa_mask);
    deferredSignal = 0;
    for (std::size_t i = 0; i < kSignals.size(); ++i)
        ::sigaction(kSignals[i], &defer, &previous[i]);
    std::optional<std::string> problem;
    try {
        writeFilesAtomic(files);
    } catch (const std::exception& e) {
        problem = e.what();
    }
    for (std::size_t i = 0; i < kSignals.size(); ++i)
        ::sigaction(kSignals[i], &previous[i], nullptr);
    if (const int sig = deferredSignal) std::raise(sig);
    return problem;
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

CLI::Option* addPracticeOptions(CLI::App* cmd, std::uint64_t& seed, std::uint64_t maxSeed,
                                const std::string& seedHelp, std::string& level,
                                const std::string& levelHelp, std::string& lang,
                                const std::string& langHelp) {
    CLI::Option* s = cmd->add_option("--seed", seed, seedHelp)->check(wholeNumber(0, maxSeed));
    cmd->add_option("--level", level, levelHelp)
        ->check(CLI::IsMember({"easy", "medium", "hard"}))
        ->capture_default_str();
    cmd->add_option("--lang", lang, langHelp + ": " + languageChoices())->capture_default_str();
    return s;
}

std::optional<int> parseInt(const std::string& text, int lo, int hi) {
    int value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    if (value < lo || value > hi) return std::nullopt;
    return value;
}

}  // namespace raystep::cli
