#pragma once
// Any model a student finds (.obj .ply .stl .gltf .glb), read with assimp into triangles, and the
// scene made around it: a camera framing it, a floor under it, two lights. Its own library
// (raystep_import): only the programs that open models link assimp.
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"
#include "raystep/scene/scene_loader.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace raystep {

/// The extensions importModel reads, lower case with the dot (".obj", ".ply", ...).
const std::vector<std::string>& modelExtensions();
/// True if the path ends in one of modelExtensions(), in any case.
bool isModelPath(std::string_view path);

/// A model's triangles, in its own coordinates (node transforms applied).
struct ImportedModel {
    std::vector<Triangle> triangles;  // material 0
    Bounds3 bounds;
    std::uint64_t droppedDegenerateTriangles = 0;  // zero-area ones, left out as scene meshes do
};

/// Reads a model file; throws SceneError naming the file (and the mesh and vertex or face when
/// the problem is in one) for a missing, unreadable, special, empty, malformed or non-finite one,
/// or one without triangles. Every file assimp opens (a glTF's buffers too) is read through the
/// core's checked reader: regular files only, at most 256 MB. Assimp logs nothing.
ImportedModel importModel(const std::string& path);

/// The scene around a model: its triangles (the default material) first, then a checker floor
/// of two triangles just under it; a camera at a three-quarter view framing the model's bounds;
/// a key and a fill light.
Scene sceneAroundModel(const ImportedModel& model, const std::string& name);

/// importModel then sceneAroundModel.
Scene importModelScene(const std::string& path);

/// A scene file (docs/scene-format.md) for `scene` whose first `meshTriangles` triangles are
/// written as an OBJ mesh referenced as `meshFile` (relative to the scene file's folder); the
/// other primitives and the materials are written in the scene file.
struct SceneFiles {
    std::string sceneJson;
    std::string meshObj;
};
SceneFiles sceneFilesFor(const Scene& scene, std::size_t meshTriangles,
                         const std::string& meshFile);

/// loadAnyScene (scene_loader.h), and a model file by its extension.
std::variant<Scene, Scene2D> loadAnySceneOrModel(const std::string& nameOrPath);

}  // namespace raystep
