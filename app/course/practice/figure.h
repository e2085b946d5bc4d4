#pragma once
// The figure of a 2D instance, for a printed homework sheet and a Moodle question: the grid
// (or the scene's bounds), its primitives and the ray with its direction as an arrow. No labels:
// the prompt states every number, and the figure only has to show where things are.
#include "course/lesson.h"

#include <optional>
#include <string>

namespace raystep {

/// PNG bytes of the lesson's 2D scene with its ray; nullopt for a 3D scene.
std::optional<std::string> practiceFigurePng(const Lesson& lesson, int widthPx = 480);

}  // namespace raystep
