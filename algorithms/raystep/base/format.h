#pragma once
// Numbers as text for messages, tables, lessons and the GUI: one rule, so a value reads the same
// wherever the course shows it.
#include <cstdio>
#include <limits>
#include <string>

namespace raystep {

/// Significant digits of a number a person reads: 0.1, 3.14159, 1e-05.
constexpr int kReadableDigits = 6;

/// Significant digits that read back to the very same float (9) or double (17): for checking
/// homework by hand, where the last bit of the answer matters.
template <typename T>
constexpr int kRoundTripDigits = std::numeric_limits<T>::max_digits10;

/// `v` to `digits` significant digits as printf's %g writes it: trailing zeros dropped, an
/// exponent for very large or small values, and inf, -inf and nan as those words.
inline std::string formatNumber(double v, int digits = kReadableDigits) {
    char text[64];  // %.17g of the longest double takes 24 characters
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

}  // namespace raystep
