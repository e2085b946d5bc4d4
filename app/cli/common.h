#pragma once
// What every raystep-cli command shares: the one-line error and strict number parsing.
#include <optional>
#include <string>
#include <vector>

namespace raystep::cli {

constexpr int kExitBadInput = 2;

/// Prints "raystep-cli: error: <message>" on one line; returns the exit code for bad input.
int fail(const std::string& message);

/// Splits "1,2,3" into finite numbers; nullopt if any part is not one (nan, inf, 1e999, "x", "").
std::optional<std::vector<double>> parseNumbers(const std::string& text, char separator = ',');

/// True if `path` ends in `ext` (".png"), in any case.
bool hasExtension(const std::string& path, const std::string& ext);

/// Checks that a file can be created at `path` before any long work is done; the problem if not.
std::optional<std::string> checkWritable(const std::string& option, const std::string& path);

/// Whole number from text, within [lo, hi]; nullopt otherwise.
std::optional<int> parseInt(const std::string& text, int lo, int hi);

}  // namespace raystep::cli
