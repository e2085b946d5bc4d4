#pragma once
// What the hierarchies see of a scene, in any dimension: a numbered set of primitives with
// bounds and a ray test. The 3D scene and the lecture's 2D scenes (segments and circles) both
// provide one, so the kd-tree and the BVH run the same code on both (DESIGN.md: dimension is a
// template parameter, never a copy).
#include "raystep/base/math.h"
#include "raystep/geometry/intersect.h"
#include "raystep/scene/scene.h"

#include <optional>
#include <utility>

namespace raystep {

/// The slab test in N dimensions with the far side widened by 1 + 2 gamma(3) (Ize 2013), so
/// rounding never makes a ray miss a box it touches. [tNear, tFar] within [tMin, tMax], or none.
template <int N>
std::optional<std::pair<double, double>> intersectBoxN(const VecN<N, double>& o,
                                                       const VecN<N, double>& invDir,
                                                       const BoxN<N>& box, double tMin,
                                                       double tMax) {
    double tNear = tMin, tFar = tMax;
    for (int i = 0; i < N; ++i) {
        if (std::isinf(invDir[i])) {  // parallel to this slab: inside it or never
            if (o[i] < box.lo[i] || o[i] > box.hi[i]) return std::nullopt;
            continue;
        }
        double t0 = (box.lo[i] - o[i]) * invDir[i];
        double t1 = (box.hi[i] - o[i]) * invDir[i];
        if (t0 > t1) std::swap(t0, t1);
        t1 *= 1.0 + 2.0 * gamma<double>(3);
        tNear = t0 > tNear ? t0 : tNear;
        tFar = t1 < tFar ? t1 : tFar;
        if (tNear > tFar) return std::nullopt;
    }
    return std::make_pair(tNear, tFar);
}

/// 1 / d per axis, with +-infinity for a zero component (the sign of -0.0 kept).
template <int N>
VecN<N, double> inverseDirection(const VecN<N, double>& d) {
    VecN<N, double> inv;
    for (int i = 0; i < N; ++i) inv[i] = 1.0 / d[i];
    return inv;
}

/// Bounds of the part of triangle abc inside `box` (Sutherland-Hodgman against the six planes):
/// a kd-tree's "perfect split" bounds. Empty when the triangle misses the box. Clipped against
/// the box widened by a millionth of its size, so rounding never drops a triangle that touches it.
BoxN<3> clipTriangleBounds(const Vec3& a, const Vec3& b, const Vec3& c, const BoxN<3>& box);
/// The same for both sides of the plane axis = pos inside `box` at once: one clip to the box,
/// then one pass over the polygon's edges. The kd-tree's split of a straddling triangle.
std::pair<BoxN<3>, BoxN<3>> splitTriangleBounds(const Vec3& a, const Vec3& b, const Vec3& c,
                                                const BoxN<3>& box, int axis, double pos);

/// Tests primitive `p` for the nearest hit, which is defined as the smallest t and, at equal t
/// (a ray through a shared edge), the lowest primitive id: brute force's answer, whatever order a
/// structure meets the primitives in. Shortens ray.tMax and updates `hit` when `p` wins.
template <typename Prims, typename RayT, typename HitT>
bool testForNearest(const Prims& prims, std::uint32_t p, RayT& ray, HitT& hit,
                    const std::optional<HitT>& closest) {
    if (closest && p < closest->prim) {
        // A lower id also wins at exactly the same t: let the test accept t == tMax.
        RayT tie = ray;
        tie.tMax = std::nextafter(ray.tMax, kInfinity);
        if (!prims.intersect(p, tie, hit)) return false;
        ray.tMax = tie.tMax;
        return true;
    }
    return prims.intersect(p, ray, hit);
}

/// The 3D scene as a primitive set, tested with the chosen kernels.
class ScenePrims {
  public:
    static constexpr int N = 3;
    using RayT = Ray;
    using HitT = Hit;

    ScenePrims(const Scene& scene, KernelOptions kernels) : scene_(&scene), kernels_(kernels) {}
    std::uint32_t count() const { return scene_->primitiveCount(); }
    BoxN<3> bounds(std::uint32_t p) const { return scene_->primitiveBounds(p); }
    /// Bounds of the part of `p` inside `box` (exact for triangles, the box's share of a
    /// sphere's bounds otherwise); empty if `p` misses the box.
    BoxN<3> clippedBounds(std::uint32_t p, const BoxN<3>& box) const {
        if (scene_->isSphere(p)) return bounds(p).clippedTo(box);
        const Triangle& t = scene_->triangle(p);
        return clipTriangleBounds(t.a, t.b, t.c, box);
    }
    /// Bounds of the parts of `p` inside `box` on each side of the plane axis = pos.
    std::pair<BoxN<3>, BoxN<3>> splitBounds(std::uint32_t p, const BoxN<3>& box, int axis,
                                            double pos) const {
        if (scene_->isSphere(p)) {
            const auto [l, r] = box.splitAt(axis, pos);
            return {bounds(p).clippedTo(l), bounds(p).clippedTo(r)};
        }
        const Triangle& t = scene_->triangle(p);
        return splitTriangleBounds(t.a, t.b, t.c, box, axis, pos);
    }
    /// Updates `hit` and shortens ray.tMax when `p` is hit nearer.
    bool intersect(std::uint32_t p, Ray& ray, Hit& hit) const {
        return scene_->intersectPrimitive(p, ray, hit, kernels_);
    }
    const Scene& scene() const { return *scene_; }
    const KernelOptions& kernels() const { return kernels_; }

  private:
    const Scene* scene_;
    KernelOptions kernels_;
};

}  // namespace raystep
