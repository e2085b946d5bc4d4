// Scene files: loadSceneText on the input, with meshes served from a fixed set of small OBJ files
// (any other name is refused, as a missing file would be).
#include "fuzz_support.h"
#include "raystep/scene/scene_loader.h"

#include <map>
#include <optional>

namespace {

const std::map<std::string, std::string, std::less<>>& meshes() {
    static const std::map<std::string, std::string, std::less<>> m = {
        {"tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"},
        {"quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n"},
        {"flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"},  // only a degenerate triangle
    };
    return m;
}

std::optional<std::string> serveMesh(const std::string& relativePath) {
    const auto it = meshes().find(relativePath);
    if (it == meshes().end()) return std::nullopt;
    return it->second;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = raystep::fuzz::asText(data, size);
    raystep::fuzz::expectOwnErrorOnly<raystep::SceneError>(
        "loadSceneText", [&] { (void)raystep::loadSceneText(text, "fuzz-scene.json", serveMesh); });
    return 0;
}
