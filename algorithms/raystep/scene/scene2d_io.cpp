#include "raystep/scene/scene2d_io.h"

#include "raystep/base/file_write.h"
#include "raystep/scene/scene_loader.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <system_error>

namespace raystep {

namespace {
/// The shortest decimal that reads back to exactly `v` (to_chars), as JSON writes numbers.
std::string number(double v) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return ec == std::errc() ? std::string(buffer, end) : std::string("NaN");
}

std::string pair(const Vec2& v) {
    std::string s = "[";
    s.append(number(v.x)).append(", ").append(number(v.y)).append("]");
    return s;
}
}  // namespace

std::string scene2DText(const Scene2D& scene, const std::string& path) {
    if (scene.primitiveCount() == 0)
        throw SceneError(path, 0, "", "the scene is empty: give at least one circle or segment");
    std::string t = "{\n  \"dimensions\": 2,\n";
    // JSON's own escaping for the one free text (quotes, control characters, UTF-8 as it is).
    t += "  \"description\": " + nlohmann::json(scene.description).dump() + ",\n";
    if (scene.gridRes)
        t += "  \"grid\": [" + std::to_string(scene.gridRes->x) + ", " +
             std::to_string(scene.gridRes->y) + "],\n";
    if (scene.exampleRay)
        t += "  \"ray\": {\"origin\": " + pair(scene.exampleRay->origin) +
             ", \"dir\": " + pair(scene.exampleRay->dir) + "},\n";
    t += "  \"circles\": [";
    for (std::size_t i = 0; i < scene.circles.size(); ++i)
        t += std::string(i ? "," : "") + "\n    {\"center\": " + pair(scene.circles[i].center) +
             ", \"radius\": " + number(scene.circles[i].radius) + "}";
    t += scene.circles.empty() ? "],\n" : "\n  ],\n";
    t += "  \"segments\": [";
    for (std::size_t i = 0; i < scene.segments.size(); ++i)
        t += std::string(i ? "," : "") + "\n    {\"from\": " + pair(scene.segments[i].a) +
             ", \"to\": " + pair(scene.segments[i].b) + "}";
    t += scene.segments.empty() ? "]\n}\n" : "\n  ]\n}\n";
    // The loader's own checks (radius, zero direction, ranges, non-finite values) decide what may
    // be written: a file this writes always opens again.
    loadScene2DText(t, path);
    return t;
}

void saveScene2D(const Scene2D& scene, const std::string& path) {
    writeFileAtomic(path, scene2DText(scene, path));
}

}  // namespace raystep
