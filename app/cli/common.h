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

}  // namespace raystep::cli
