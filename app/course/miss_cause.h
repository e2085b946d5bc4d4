#pragma once
// Private to the course library: why a primitive test missed, from the scene's geometry, so a
// hit_or_miss exercise names the actual cause (a negative discriminant, behind the origin, beyond
// the nearest intersection so far, outside the triangle or segment) rather than a list of four.
#include "raystep/base/i18n.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <cstddef>
#include <string>
#include <variant>

namespace raystep::feedback {

/// The cause of the miss of event `testIndex` of `log` (a PrimitiveTest that misses), in `lang`;
/// empty when the event is not such a test or its ray or primitive is not in the scene.
std::string missCause(const std::variant<Scene, Scene2D>& scene, const EventLog& log,
                      std::size_t testIndex, Language lang);

}  // namespace raystep::feedback
