// OBJ meshes: the input is the OBJ file of a fixed scene's one mesh, read through loadSceneText
// (the vertex check, tinyobjloader, the index and overflow checks).
#include "fuzz_support.h"
#include "raystep/scene/scene_loader.h"

namespace {
// A scale other than 1 so the overflow check after scaling is reachable.
constexpr std::string_view kScene = R"({
  "objects": [{"type": "mesh", "file": "fuzz.obj", "scale": 1e3, "translate": [0, 0, -5]}]
})";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string obj(raystep::fuzz::asText(data, size));
    raystep::fuzz::expectOwnErrorOnly<raystep::SceneError>("loadSceneText (OBJ mesh)", [&] {
        (void)raystep::loadSceneText(kScene, "fuzz-obj-scene.json",
                                     [&](const std::string& path) -> std::optional<std::string> {
                                         if (path == "fuzz.obj") return obj;
                                         return std::nullopt;
                                     });
    });
    return 0;
}
