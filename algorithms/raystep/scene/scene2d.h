#pragma once
// The lecture's 2D pictures as scenes: segments and circles in a plane, and the example ray drawn
// on the slides. The grid, the DDA and the kd-tree run on them with the same templates as in 3D.
#include "raystep/base/math.h"
#include "raystep/geometry/kernels.h"
#include "raystep/scene/prims.h"

#include <optional>
#include <string>
#include <vector>

namespace raystep {

using Vec2 = glm::dvec2;

struct Ray2 {
    Vec2 origin{0.0};
    Vec2 dir{1.0, 0.0};
    double tMin = 0.0;
    double tMax = kInfinity;
    Vec2 at(double t) const { return origin + t * dir; }
};

struct Hit2 {
    double t = kInfinity;
    std::uint32_t prim = 0;  // circles first, then segments
};

struct Segment2 {
    Vec2 a, b;
};
struct Circle2 {
    Vec2 center{0.0};
    double radius = 1.0;
};

struct Scene2D {
    std::string name;
    std::string description;
    std::vector<Circle2> circles;
    std::vector<Segment2> segments;
    std::optional<Ray2> exampleRay;   // the ray the slides follow
    std::optional<IVecN<2>> gridRes;  // the grid the slides draw (else Cleary-Wyvill)

    std::uint32_t primitiveCount() const {
        return static_cast<std::uint32_t>(circles.size() + segments.size());
    }
    bool isCircle(std::uint32_t p) const { return p < circles.size(); }
    BoxN<2> primitiveBounds(std::uint32_t p) const;
    BoxN<2> bounds() const;
    /// Updates `hit` and shortens ray.tMax when `p` is hit nearer than ray.tMax.
    bool intersectPrimitive(std::uint32_t p, Ray2& ray, Hit2& hit) const;
};

/// Ray against segment [a, b]: o + t d = a + s (b - a), s in [0, 1]; a ray along the segment's
/// own line meets it nowhere in particular and counts as a miss.
std::optional<double> intersectSegment(const Ray2& ray, const Segment2& s);
/// Ray against circle, with the stable quadratic (Ray Tracing Gems ch. 7) as for spheres.
std::optional<double> intersectCircle(const Ray2& ray, const Circle2& c);

/// A 2D scene as a primitive set for the grid and the trees.
class Scene2DPrims {
  public:
    static constexpr int N = 2;
    using RayT = Ray2;
    using HitT = Hit2;

    explicit Scene2DPrims(const Scene2D& scene) : scene_(&scene) {}
    std::uint32_t count() const { return scene_->primitiveCount(); }
    BoxN<2> bounds(std::uint32_t p) const { return scene_->primitiveBounds(p); }
    /// Bounds of the part of `p` inside `box`; empty if it misses the box.
    BoxN<2> clippedBounds(std::uint32_t p, const BoxN<2>& box) const;
    bool intersect(std::uint32_t p, Ray2& ray, Hit2& hit) const {
        return scene_->intersectPrimitive(p, ray, hit);
    }
    const Scene2D& scene() const { return *scene_; }
    /// 2D primitives have one kernel each, in double.
    const KernelOptions& kernels() const { return kernels_; }

  private:
    const Scene2D* scene_;
    KernelOptions kernels_;
};

}  // namespace raystep
