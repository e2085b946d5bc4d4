#pragma once
// Test meshes of any size for the benchmarks: the stadium's torus-knot tube (see
// scripts/make_stadium_mesh.py), tessellated to about `triangles` triangles.
#include "raystep/scene/scene.h"

#include <cmath>

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

}  // namespace raystep::bench
