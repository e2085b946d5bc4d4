#pragma once
// The scene model: only what the lecture needs (pinhole camera, point lights, spheres,
// triangles, Phong materials with reflection, transparency and a checker texture).
#include "raystep/base/math.h"
#include "raystep/base/ray.h"
#include "raystep/geometry/kernels.h"
#include "raystep/scene/camera.h"

#include <cstdint>
#include <string>
#include <vector>

namespace raystep {

/// Procedural 3D checker: alternates the material's kd with `color` in cubes of side `size`.
struct CheckerTexture {
    bool enabled = false;
    Color color{0.1};
    double size = 1.0;
};

/// Phong material plus the Whitted-style secondary-ray weights.
struct Material {
    std::string name = "default";
    Color kd{0.8};            // diffuse reflectance
    Color ks{0.0};            // specular reflectance
    double n = 32.0;          // Phong exponent
    Color reflect{0.0};       // weight of the mirror reflection ray
    Color transparency{0.0};  // weight of the transmitted (refraction) ray
    double ior = 1.5;         // index of refraction of the inside
    CheckerTexture checker;

    /// kd at point p, after the checker texture.
    Color diffuseAt(const Vec3& p) const;
};

struct PointLight {
    Vec3 position{0.0};
    Color intensity{1.0};  // colour times intensity
};

struct Sphere {
    Vec3 center{0.0};
    double radius = 1.0;
    std::uint32_t material = 0;
};

struct Triangle {
    Vec3 a, b, c;
    std::uint32_t material = 0;
    Vec3 normal() const { return glm::normalize(glm::cross(b - a, c - a)); }
};

/// Render settings a scene file may suggest; the command line overrides each of them.
struct RenderSettings {
    int width = 640;
    int height = 480;
    int bounces = 5;
    int spp = 1;
    int diffuseSamples = 0;
};

/// The render limits, written only here: the scene file, the CLI's options and their help, and
/// the app's render controls all read them (documented in docs/scene-format.md). Each allows a
/// render of years; they only keep a typo from overflowing a counter.
constexpr int kMaxImageSide = 8192;
constexpr int kMaxBounces = 64;
constexpr int kMaxSpp = 4096;
constexpr int kMaxDiffuseSamples = 1024;

/// Intersection with one primitive of the scene.
struct Hit {
    double t = kInfinity;
    std::uint32_t prim = 0;   // primitive id (spheres first, then triangles)
    double u = 0.0, v = 0.0;  // barycentric coordinates on triangles
};

/// A hit point with a conservative bound on each coordinate's absolute error.
struct SurfacePoint {
    Vec3 p;
    Vec3 error;
};

struct Scene {
    std::string name;         // built-in name or file path
    std::string description;  // one line, shown by `raystep-cli scenes`
    Camera camera;
    Color background{0.0};
    Color ambient{0.0};
    std::vector<PointLight> lights;
    std::vector<Material> materials;
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
    RenderSettings settings;
    std::uint64_t droppedDegenerateTriangles = 0;  // zero-area triangles of meshes

    /// Primitive ids run over spheres then triangles.
    std::uint32_t primitiveCount() const {
        return static_cast<std::uint32_t>(spheres.size() + triangles.size());
    }
    bool isSphere(std::uint32_t prim) const { return prim < spheres.size(); }
    const Triangle& triangle(std::uint32_t prim) const { return triangles[prim - spheres.size()]; }

    /// The slides' "r intersects p": updates `hit` when primitive `prim` is hit nearer than
    /// ray.tMax (and shortens ray.tMax), with the chosen kernel and precision.
    bool intersectPrimitive(std::uint32_t prim, Ray& ray, Hit& hit,
                            const KernelOptions& kernels = {}) const;

    /// The hit point with its error bound, computed in the kernels' precision (from the
    /// barycentrics on triangles, reprojected onto spheres).
    SurfacePoint surfacePoint(const Hit& hit, const Ray& ray, Precision precision) const;

    Bounds3 primitiveBounds(std::uint32_t prim) const;
    Bounds3 bounds() const;
    const Material& materialOf(std::uint32_t prim) const;
    /// Geometric (outward) unit normal of `prim` at the hit.
    Vec3 normalAt(const Hit& hit, const Vec3& p) const;
};

/// The scene with every position mapped by p -> p * scale + shift (sizes, checker cubes and the
/// camera follow): the same picture at another scale or far from the origin, for the lecture on
/// numerical robustness and for tests at the extremes.
Scene transformScene(Scene scene, double scale, const Vec3& shift);

/// The largest coordinate in absolute value of the scene's geometry, camera and lights (a sphere
/// counts its radius): what the kernels' range (kernels.h) is measured against.
double largestCoordinate(const Scene& scene);
/// The smallest sphere radius or longest triangle edge of the scene (degenerate triangles left
/// out; 0 if nothing is left): what the kernels' range is measured against from below.
double smallestSize(const Scene& scene);

}  // namespace raystep
