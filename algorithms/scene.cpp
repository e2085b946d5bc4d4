#include "raystep/scene.h"

#include "raystep/intersect.h"

namespace raystep {

Color Material::diffuseAt(const Vec3& p) const {
    if (!checker.enabled) return kd;
    // A tiny shift keeps planes at integer multiples of size (a floor at y = 0) off the
    // boundary between two cubes, where rounding would speckle the pattern.
    const Vec3 q = glm::floor(p / checker.size + 1e-7);
    const auto parity = static_cast<long long>(q.x) + static_cast<long long>(q.y) +
                        static_cast<long long>(q.z);
    return (parity & 1) ? checker.color : kd;
}

bool Scene::intersectPrimitive(std::uint32_t prim, Ray& ray, Hit& hit) const {
    if (isSphere(prim)) {
        const Sphere& s = spheres[prim];
        const auto t = intersectSphere<double>(ray.origin, ray.dir, s.center, s.radius, ray.tMin,
                                               ray.tMax);
        if (!t) return false;
        ray.tMax = *t;
        hit = Hit{*t, prim, 0.0, 0.0};
        return true;
    }
    const Triangle& tri = triangle(prim);
    const auto h = intersectTriangleMT<double>(ray.origin, ray.dir, tri.a, tri.b, tri.c, ray.tMin,
                                               ray.tMax);
    if (!h) return false;
    ray.tMax = h->t;
    hit = Hit{h->t, prim, h->u, h->v};
    return true;
}

Bounds3 Scene::primitiveBounds(std::uint32_t prim) const {
    Bounds3 b;
    if (isSphere(prim)) {
        const Sphere& s = spheres[prim];
        b.extend(s.center - Vec3(s.radius));
        b.extend(s.center + Vec3(s.radius));
    } else {
        const Triangle& t = triangle(prim);
        b.extend(t.a);
        b.extend(t.b);
        b.extend(t.c);
    }
    return b;
}

Bounds3 Scene::bounds() const {
    Bounds3 b;
    for (std::uint32_t i = 0; i < primitiveCount(); ++i) b.extend(primitiveBounds(i));
    return b;
}

const Material& Scene::materialOf(std::uint32_t prim) const {
    return materials[isSphere(prim) ? spheres[prim].material : triangle(prim).material];
}

Vec3 Scene::normalAt(const Hit& hit, const Vec3& p) const {
    if (isSphere(hit.prim)) {
        const Sphere& s = spheres[hit.prim];
        return glm::normalize(p - s.center);
    }
    return triangle(hit.prim).normal();
}

}  // namespace raystep
