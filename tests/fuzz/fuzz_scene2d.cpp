// 2D scene files: isScene2DText (which must never throw) and loadScene2DText on the input.
#include "fuzz_support.h"
#include "raystep/scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = raystep::fuzz::asText(data, size);
    try {
        (void)raystep::isScene2DText(text);
    } catch (const std::exception& e) {
        raystep::fuzz::finding("isScene2DText",
                               "threw " + raystep::fuzz::typeName(typeid(e)) + ": " + e.what());
    }
    raystep::fuzz::expectOwnErrorOnly<raystep::SceneError>(
        "loadScene2DText", [&] { (void)raystep::loadScene2DText(text, "fuzz-scene2d.json"); });
    return 0;
}
