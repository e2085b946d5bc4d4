#pragma once
// raystep's own checks of a model file before assimp reads it (docs/reliability.md, "Models"):
// where a format is simple enough to read here (a PLY header and its body's counts, an STL's
// size, an OBJ's statements, a glb's chunks, a glTF's JSON and what it declares), a file that
// would crash, hang or blow up assimp is refused with its line or key. What is left is read by
// assimp in a child process with limits (model_process.h).
#include "raystep/scene/scene_loader.h"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep::detail {

/// The most one model may give: the scene loader's caps (a model is a mesh by another name).
constexpr std::uint64_t kMaxModelTriangles = 10'000'000;
/// Vertices a model may declare: three a triangle of the largest mesh without shared corners.
constexpr std::uint64_t kMaxModelVertices = 3 * kMaxModelTriangles;
/// Points and line segments a model may hold (no surface: nothing to render, but assimp's work).
constexpr std::uint64_t kMaxModelPointsAndLines = kMaxModelTriangles;
/// Levels of a glTF node tree: assimp builds it recursively (20,000 overflowed the stack).
constexpr int kMaxGltfNodeDepth = 256;
/// Nodes of a glTF file.
constexpr std::uint64_t kMaxGltfNodes = 1'000'000;

/// Stat of a file a model refers to (a glTF's buffer): its size; throws ReadFailure like
/// readRegularFile for a missing, special or too large file.
using FileSizer = std::function<std::uint64_t(const std::string& path)>;

/// What a checked model lets assimp open besides itself: the glTF buffers it names, resolved
/// against the model's folder (nothing else: an OBJ's .mtl is never read, raystep ignores a
/// model's materials).
struct ModelChecked {
    std::vector<std::string> buffers;
};

/// Checks `bytes`, the content of model file `path` (by its extension: .obj .ply .stl .gltf
/// .glb; a .gltf holding a glb's bytes, and the reverse, is checked as what it holds). Throws
/// SceneError naming the file and its line, element or key.
ModelChecked checkModelBytes(const std::string& path, std::string_view bytes,
                             const FileSizer& sizeOf);

/// An OBJ's text as assimp is given it: every comment that ends a statement ("v 1 2 3 # top",
/// "f 1 2 3 # c": a '#' beginning a field, as the scene loader reads them) blanked out to the
/// end of its line. assimp 5.2.5 read a face's comment as indices ("Invalid face index") and the
/// numbers of a vertex's comment as its colour; a line's length and the lines stay as they were.
void blankObjComments(std::string& text);

/// The files `bytes` (model file `path`) refers to, resolved against its folder: an OBJ's
/// mtllib files and the textures they name, a glTF's external buffers and images. Best effort
/// (what cannot be read is left out); for refusing an output that would overwrite them.
std::vector<std::string> modelReferences(const std::string& path, std::string_view bytes);

/// The same checks one format at a time (for tests).
void checkPly(const std::string& file, std::string_view bytes);
void checkStl(const std::string& file, std::string_view bytes);
void checkObj(const std::string& file, std::string_view text);
/// `folder`: where the buffers are; returns them resolved.
std::vector<std::string> checkGltf(const std::string& file, std::string_view bytes,
                                   const FileSizer& sizeOf);

}  // namespace raystep::detail
