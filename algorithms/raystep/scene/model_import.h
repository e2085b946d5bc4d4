#pragma once
// Any model a student finds (.obj .ply .stl .gltf .glb), read with assimp into triangles, and the
// scene made around it: a camera framing it, a floor under it, two lights. Its own library
// (raystep_import): only the programs that open models link assimp.
#include "raystep/base/progress.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"
#include "raystep/scene/scene_loader.h"

#include <cstdint>
#include <functional>
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

/// What the importer process may use (docs/reliability.md, "Models"): past a limit it is ended,
/// and the import fails in one line naming the model and the limit.
struct ImportLimits {
    std::uint64_t memoryBytes = 0;  // address space (RLIMIT_AS); 0: no limit
    double cpuSeconds = 0;          // processor time (RLIMIT_CPU); 0: no limit
    double wallSeconds = 0;         // time on the clock, waited by the caller; 0: no limit
    std::uint64_t stackBytes = 0;   // the main thread's stack (RLIMIT_STACK); 0: as inherited
    /// 4 GB or half the memory, whichever is less (at least 1 GB); 120 s of processor time,
    /// 180 s on the clock; an 8 MB stack.
    static ImportLimits defaults();
};

struct ImportOptions {
    ProgressFn progress;  // 0..1; false cancels (the importer is killed, BuildCancelled thrown)
    ImportLimits limits = ImportLimits::defaults();
    std::string importer;  // the importer program; empty: raystep-import beside this program
};

/// Reads a model file; throws SceneError naming the file (and its line, element or key, or the
/// mesh and vertex or face, when the problem is in one) for a missing, unreadable, special,
/// empty, malformed or non-finite one, or one without triangles. raystep's own checks come first
/// (model_checks.h); then assimp reads it in a child process (the importer program, raystep-
/// import) under `options.limits`, whose crash, kill or limit is one line too. Its triangles
/// are read back with the caps (10 million). Assimp logs nothing.
ImportedModel importModel(const std::string& path, const ImportOptions& options = {});

/// The same in this process, without limits: the importer program, the fuzz target and tests.
ImportedModel importModelInProcess(const std::string& path, const ProgressFn& progress = {});

/// The files a scene or model refers to, itself first (a scene file's meshes; an OBJ model's
/// .mtl files and their textures; a glTF's buffers and images), resolved; a built-in scene has
/// none. Best effort, never throws: for refusing an output that would overwrite one of them.
std::vector<std::string> inputFilesOf(const std::string& nameOrPath);

/// The scene around a model: its triangles (the default material) first, then a checker floor
/// of two triangles just under it; a camera at a three-quarter view framing the model's bounds;
/// a key and a fill light.
Scene sceneAroundModel(const ImportedModel& model, const std::string& name);

/// importModel then sceneAroundModel.
Scene importModelScene(const std::string& path, const ImportOptions& options = {});

/// A scene file (docs/scene-format.md) for `scene` whose first `meshTriangles` triangles are
/// written as an OBJ mesh referenced as `meshFile` (relative to the scene file's folder); the
/// other primitives and the materials are written in the scene file.
struct SceneFiles {
    std::string sceneJson;
    std::string meshObj;
};
SceneFiles sceneFilesFor(const Scene& scene, std::size_t meshTriangles,
                         const std::string& meshFile);

/// loadAnyScene (scene_loader.h), and a model file by its extension (importModel, reporting
/// its progress and cancelled through `progress`).
std::variant<Scene, Scene2D> loadAnySceneOrModel(const std::string& nameOrPath,
                                                 const ProgressFn& progress = {});

namespace detail {
/// Where a model's files come from: the disk (readRegularFile, stat), or memory (fuzzing).
struct ModelFiles {
    std::function<std::string(const std::string& path, std::size_t maxBytes)> read;
    std::function<std::uint64_t(const std::string& path)> size;
    std::function<bool(const std::string& a, const std::string& b)> same;
};
ModelFiles diskFiles();
/// importModelInProcess with the files from `files`, each triangle given to `sink` as it is
/// found (the importer streams them to its parent). `bound`, when given, gets an upper bound
/// of the triangles before the first one.
void importModelTriangles(const std::string& path, const ModelFiles& files,
                          const std::function<void(const Triangle&)>& sink,
                          std::uint64_t& droppedDegenerate, const ProgressFn& progress,
                          const std::function<void(std::uint64_t)>& bound = {});
/// The kernels' range and the triangle count of a model read, as importModel checks them.
void checkImportedModel(const std::string& path, const ImportedModel& model);
}  // namespace detail

}  // namespace raystep
