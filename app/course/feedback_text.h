#pragma once
// Private to the course library: the sentences that explain a reference answer from the trace,
// one function per exercise kind, and the axis names they share with the answers'
// own formatting (exercise.cpp); numbers and cells are written by base/format.h and
// trace/event_text.h, as everywhere.
#include "course/lesson.h"

#include "raystep/trace/events.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace raystep::feedback {

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
