#pragma once
// 2D scene files written (docs/scene-format.md, "2D scenes"): what the app's live 2D editing
// saves, read back by loadScene2DText to the very same scene.
#include "raystep/scene/scene2d.h"

#include <string>

namespace raystep {

/// A 2D scene as scene-file text that loadScene2DText reads back to the same circles, segments,
/// example ray, grid and description (every number in its shortest exact decimal form). Throws
/// SceneError naming `path` for a scene the loader would refuse (no primitive, a zero radius or
/// direction, a value out of range): such a file is never written.
std::string scene2DText(const Scene2D& scene, const std::string& path);

/// Writes scene2DText to `path` atomically (a temporary renamed into place: a failure leaves the
/// old file whole; a folder, FIFO or device is refused). Throws SceneError or
/// std::runtime_error naming the path.
void saveScene2D(const Scene2D& scene, const std::string& path);

}  // namespace raystep
