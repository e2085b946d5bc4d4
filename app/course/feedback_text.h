#pragma once
// Private to the course library: the sentences that explain a reference answer from the trace,
// one function per exercise kind, and the words for events and positions they share with
// describePosition (lesson_trace.cpp). Every sentence goes through tr/trf (base/i18n.h), every
// number through formatNumber in the reader's language.
#include "course/lesson.h"

#include "raystep/trace/events.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace raystep::feedback {

const char* axisName(int a);  // "x", "y", "z"

/// "after the 2nd cell visited" / "dopo la 2ª cella visitata": no internal event names.
std::string afterEvent(Language lang, std::size_t kind, const std::string& nth);
std::string beforeEvent(Language lang, std::size_t kind, const std::string& nth);
/// The events of a kind, as a count names them: "Primitive tests" / "Test di primitive".
std::string eventsCounted(Language lang, std::size_t kind);
/// A ray kind as the slides name it, plural: "Shadow rays" / "Raggi d'ombra".
std::string raysOfKind(Language lang, RayKind k);

/// The axes of a step in words, each with `prefix`: "X and Y", "tMaxX and tMaxY" ("X e Y").
std::string axesWords(Language lang, unsigned axes, const std::string& prefix = "");
/// NextCell: where the walk starts (no cell `before`), or which tMax was smallest in `before`.
std::string nextCell(Language lang, const std::optional<DdaCell>& before, const DdaCell& next,
                     int dims);
/// PickSplit: the cheapest of `count` candidates of `node`, with its cost worked out.
std::string pickSplit(Language lang, int count, std::uint32_t node, const SplitCandidate& best);
/// HitOrMiss: the primitive test's verdict.
std::string hitOrMiss(Language lang, const PrimitiveTest& test);

}  // namespace raystep::feedback
