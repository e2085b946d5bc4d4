#pragma once
// Private to the course library: the sentences that explain a reference answer from the trace,
// one function per exercise kind, and the number, cell and axis text they share with the
// answers' own formatting (exercise.cpp).
#include "course/lesson.h"

#include "raystep/trace/events.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace raystep::feedback {

/// A number as the feedback and the answers show it: 6 significant digits, "inf" for infinity.
std::string number(double v);
/// "(2, 1)" or "(2, 1, 0)": the first `dims` indices of a cell.
std::string cell(const std::array<std::int32_t, 3>& c, int dims);
const char* axisName(int a);  // "x", "y", "z"

/// NextCell: where the walk starts (no cell `before`), or which tMax was smallest in `before`.
std::string nextCell(Language lang, const std::optional<DdaCell>& before, const DdaCell& next,
                     int dims);
/// Value: the trace's value and the event it was read from (`source`, e.g. "dda_setup").
std::string value(Language lang, Quantity q, double v, const std::string& source);
/// PickSplit: the cheapest of `count` candidates of `node`, with its cost worked out.
std::string pickSplit(Language lang, int count, std::uint32_t node, const SplitCandidate& best);
/// Count: `n` events of the kind `what` between two positions.
std::string count(Language lang, std::size_t n, const std::string& what, const ReplayPosition& from,
                  const ReplayPosition& to);
/// HitOrMiss: the primitive test's verdict, and why a miss misses.
std::string hitOrMiss(Language lang, const PrimitiveTest& test);

}  // namespace raystep::feedback
