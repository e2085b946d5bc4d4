#pragma once
// The fast path of the lecture's trade-offs: the scene kept as a float copy (no conversion per test),
// Moller-Trumbore triangles and textbook spheres in float. Less accurate (docs/accuracy.md), and
// what the benchmarks race against Embree. The structures run over it unchanged (same templates).
#include "raystep/scene/prims.h"

#include <vector>

namespace raystep {

class FloatScenePrims {
  public:
    static constexpr int N = 3;
    using RayT = Ray;
    using HitT = Hit;

    explicit FloatScenePrims(const Scene& scene) : scene_(&scene) {
        for (const Sphere& s : scene.spheres)
            spheres_.push_back({glm::vec3(s.center), static_cast<float>(s.radius)});
        for (const Triangle& t : scene.triangles)
            triangles_.push_back({glm::vec3(t.a), glm::vec3(t.b), glm::vec3(t.c)});
    }
    std::uint32_t count() const { return scene_->primitiveCount(); }
    BoxN<3> bounds(std::uint32_t p) const { return scene_->primitiveBounds(p); }
    BoxN<3> clippedBounds(std::uint32_t p, const BoxN<3>& box) const {
        return ScenePrims(*scene_, kernels_).clippedBounds(p, box);
    }
    std::pair<BoxN<3>, BoxN<3>> splitBounds(std::uint32_t p, const BoxN<3>& box, int axis,
                                            double pos) const {
        return ScenePrims(*scene_, kernels_).splitBounds(p, box, axis, pos);
    }
    bool intersect(std::uint32_t p, Ray& ray, Hit& hit) const {
        const glm::vec3 o(ray.origin), d(ray.dir);
        const float tMin = static_cast<float>(ray.tMin), tMax = static_cast<float>(ray.tMax);
        if (p < spheres_.size()) {
            const auto t = intersectSphereTextbook<float>(o, d, spheres_[p].center,
                                                          spheres_[p].radius, tMin, tMax);
            if (!t || !(double(*t) < ray.tMax)) return false;
            ray.tMax = *t;
            hit = Hit{*t, p, 0.0, 0.0};
            return true;
        }
        const FloatTriangle& f = triangles_[p - spheres_.size()];
        const auto h = intersectTriangleMT<float>(o, d, f.a, f.b, f.c, tMin, tMax);
        if (!h || !(double(h->t) < ray.tMax)) return false;
        ray.tMax = h->t;
        hit = Hit{h->t, p, h->u, h->v};
        return true;
    }
    const KernelOptions& kernels() const { return kernels_; }

  private:
    struct FloatSphere {
        glm::vec3 center;
        float radius;
    };
    struct FloatTriangle {
        glm::vec3 a, b, c;
    };
    const Scene* scene_;
    std::vector<FloatSphere> spheres_;
    std::vector<FloatTriangle> triangles_;
    KernelOptions kernels_{Precision::Float, SphereMethod::Textbook,
                           TriangleMethod::MollerTrumbore};
};

}  // namespace raystep
