#pragma once
// The benchmarks' meshes: the stadium's torus-knot tube (see scripts/make_stadium_mesh.py),
// tessellated to any size, and the Stanford bunny on a floor.
#include "raystep/scene/scene.h"
#include "raystep/scene/scene_loader.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace raystep::bench {

inline Vec3 knotCurve(double phi) {
    const double s = 1.5 + 0.6 * std::cos(2 * phi);
    return {s * std::cos(3 * phi), s * std::sin(3 * phi), 0.6 * std::sin(2 * phi)};
}

/// A (3,2) torus-knot tube of `along` x `around` quads (2 along x around triangles), radius 0.22,
/// with a camera looking at it from +z and one light.
inline Scene knotScene(int along, int around = 32) {
    Scene s;
    s.name = "knot-" + std::to_string(2 * along * around);
    s.materials.push_back(Material{});
    s.lights.push_back({Vec3(-30, 40, 40), Color(1.0)});
    s.camera.eye = Vec3(0, 0, 7);
    s.camera.lookAt = Vec3(0, 0, 0);
    s.camera.fovDeg = 45;
    std::vector<Vec3> v(static_cast<std::size_t>(along) * around);
    for (int i = 0; i < along; ++i) {
        const double phi = 2 * kPi * i / along;
        const Vec3 c = knotCurve(phi);
        const Vec3 tangent = glm::normalize(knotCurve(phi + 1e-4) - knotCurve(phi - 1e-4));
        const Vec3 radial = glm::normalize(Vec3(c.x, c.y, 0.0));
        const Vec3 normal = glm::normalize(glm::cross(glm::cross(tangent, radial), tangent));
        const Vec3 binormal = glm::cross(tangent, normal);
        for (int j = 0; j < around; ++j) {
            const double theta = 2 * kPi * j / around;
            v[static_cast<std::size_t>(i) * around + j] =
                c + 0.22 * (std::cos(theta) * normal + std::sin(theta) * binormal);
        }
    }
    const auto at = [&](int i, int j) {
        return v[static_cast<std::size_t>(i % along) * around + (j % around)];
    };
    for (int i = 0; i < along; ++i)
        for (int j = 0; j < around; ++j) {
            s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), 0});
            s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1), 0});
        }
    return s;
}

inline constexpr const char* kBunnyPath = "/usr/share/glmark2/models/bunny.obj";  // glmark2-data

/// The bunny (69,666 triangles) on a floor, lit by two lights, the camera framing it (the mesh
/// spans about [-1, 1] x [-0.99, 0.99] x [-0.78, 0.78]).
inline Scene bunnyScene() {
    const std::string text = R"({
      "camera": {"eye": [0.6, 0.5, 3.4], "look_at": [0, -0.1, 0], "up": [0, 1, 0], "fov": 40},
      "background": [0.1, 0.12, 0.16], "ambient": 0.1,
      "lights": [{"position": [3, 4, 4], "intensity": 0.8},
                 {"position": [-4, 3, 2], "color": [0.6, 0.7, 1.0], "intensity": 0.5}],
      "materials": {"clay": {"kd": [0.8, 0.7, 0.55], "ks": 0.2, "n": 20},
                    "floor": {"kd": 0.6, "checker": {"color": 0.3, "size": 0.5}}},
      "objects": [
        {"type": "mesh", "file": "bunny.obj", "material": "clay"},
        {"type": "triangle", "material": "floor",
         "vertices": [[-6, -0.992, -6], [-6, -0.992, 6], [6, -0.992, 6]]},
        {"type": "triangle", "material": "floor",
         "vertices": [[-6, -0.992, -6], [6, -0.992, 6], [6, -0.992, -6]]}]})";
    return loadSceneText(text, "bunny.json", [](const std::string&) -> std::optional<std::string> {
        std::ifstream in(kBunnyPath, std::ios::binary);
        if (!in) return std::nullopt;
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    });
}

}  // namespace raystep::bench
