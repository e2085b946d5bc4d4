#pragma once
// Scene files (JSON with comments, docs/scene-format.md) and the built-in scenes.
#include "raystep/base/file_error.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace raystep {

/// A scene that cannot be loaded: which file, which line, which key, and why.
class SceneError : public FileError {
  public:
    using FileError::FileError;
};

/// Returns the text of a file a scene refers to (an OBJ mesh), or nullopt when it does not exist.
using FileResolver = std::function<std::optional<std::string>(const std::string& relativePath)>;

/// Parses scene text; `fileName` is used in messages and as the scene's name.
Scene loadSceneText(std::string_view text, const std::string& fileName,
                    const FileResolver& resolver);

/// Loads a scene file from disk; meshes are resolved relative to the file's folder.
Scene loadSceneFile(const std::string& path);

/// A built-in scene by name ("default", "whitted", "cornell", "stadium").
Scene loadBuiltinScene(const std::string& name);

/// A built-in name, else a file path; the error for neither names both possibilities.
Scene loadScene(const std::string& nameOrPath);

/// The built-in 3D scenes, and the 2D ones (the lecture's pictures).
std::vector<std::string> builtinSceneNames();
std::vector<std::string> builtinScene2DNames();

/// True if the text is a 2D scene ("dimensions": 2).
bool isScene2DText(std::string_view text);
/// Parses a 2D scene (docs/scene-format.md, "2D scenes").
Scene2D loadScene2DText(std::string_view text, const std::string& fileName);
/// A built-in name or a file, 3D or 2D. A file whose extension is neither .json nor none is
/// refused by its type (a model's: "a model file ...", any other: "not a scene or model ...").
std::variant<Scene, Scene2D> loadAnyScene(const std::string& nameOrPath);

/// The file types raystep opens, for messages: "(.json, .obj, .ply, .stl, .gltf, .glb)".
std::string_view sceneOrModelTypes();
/// Why a path's extension is no scene file's (a model, or a type raystep does not read), or
/// nullopt for .json and a name without one.
std::optional<std::string> unreadableTypeProblem(const std::string& path);

}  // namespace raystep
