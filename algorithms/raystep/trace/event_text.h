#pragma once
// Events as text: one line per event and the numbers in it, as the lecture writes them on the
// board. The app's event list and inspector and the lessons' explanations all write through here.
#include "raystep/trace/events.h"

#include <array>
#include <cstdint>
#include <string>

namespace raystep {

/// A number as the lecture's texts show it: formatNumber (6 significant digits, printf's %g,
/// "inf" for an infinity), with -0 as "0".
std::string numberText(double v);
/// The first `dims` coordinates in brackets: "(2, 1)" in 2D, "(2, 1, 0)" in 3D.
std::string cellText(const std::array<std::int32_t, 3>& cell, int dims);
std::string tupleText(const std::array<double, 3>& v, int dims);
/// The axes of a DDA step as letters: "X", or "XY" on a tie; "" for none (the first cell).
std::string axesText(unsigned axes);
/// One line describing `e`, an event of a log of `dims` dimensions (EventLog::dims()).
std::string eventText(const Event& e, int dims);

}  // namespace raystep
