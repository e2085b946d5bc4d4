#include "raystep/scene.h"

#include "raystep/kernels.h"
#include "raystep/prims.h"

#include <array>

namespace raystep {

Color Material::diffuseAt(const Vec3& p) const {
    if (!checker.enabled) return kd;
    // A tiny shift keeps planes at integer multiples of size (a floor at y = 0) off the
    // boundary between two cubes, where rounding would speckle the pattern.
    const Vec3 q = glm::floor(p / checker.size + 1e-7);
    const auto parity =
        static_cast<long long>(q.x) + static_cast<long long>(q.y) + static_cast<long long>(q.z);
    return (parity & 1) ? checker.color : kd;
}

namespace {

template <typename T>
TVec3<T> cast(const Vec3& v) {
    return TVec3<T>(v);
}

template <typename T>
bool intersectPrimitiveIn(const Scene& scene, std::uint32_t prim, Ray& ray, Hit& hit,
                          const KernelOptions& k) {
    const TVec3<T> o = cast<T>(ray.origin);
    const TVec3<T> d = cast<T>(ray.dir);
    const T tMin = static_cast<T>(ray.tMin);
    const T tMax = static_cast<T>(ray.tMax);
    if (scene.isSphere(prim)) {
        const Sphere& s = scene.spheres[prim];
        const auto t =
            intersectSphere<T>(k.sphere, o, d, cast<T>(s.center), T(s.radius), tMin, tMax);
        // In float, tMax itself was rounded: keep the double interval strict.
        if (!t || !(double(*t) < ray.tMax)) return false;
        ray.tMax = double(*t);
        hit = Hit{double(*t), prim, 0.0, 0.0};
        return true;
    }
    const Triangle& tri = scene.triangle(prim);
    const auto h = intersectTriangle<T>(k.triangle, o, d, cast<T>(tri.a), cast<T>(tri.b),
                                        cast<T>(tri.c), tMin, tMax);
    if (!h || !(double(h->t) < ray.tMax)) return false;
    ray.tMax = double(h->t);
    hit = Hit{double(h->t), prim, double(h->u), double(h->v)};
    return true;
}

template <typename T>
SurfacePoint surfacePointIn(const Scene& scene, const Hit& hit, const Ray& ray) {
    PointWithError<T> pe;
    if (scene.isSphere(hit.prim)) {
        const Sphere& s = scene.spheres[hit.prim];
        pe = spherePoint<T>(cast<T>(ray.origin), cast<T>(ray.dir), T(hit.t), cast<T>(s.center),
                            T(s.radius));
    } else {
        const Triangle& t = scene.triangle(hit.prim);
        pe = trianglePoint<T>(cast<T>(t.a), cast<T>(t.b), cast<T>(t.c), T(hit.u), T(hit.v));
    }
    return {Vec3(pe.p), Vec3(pe.error)};
}

}  // namespace

bool Scene::intersectPrimitive(std::uint32_t prim, Ray& ray, Hit& hit,
                               const KernelOptions& kernels) const {
    if (kernels.precision == Precision::Float)
        return intersectPrimitiveIn<float>(*this, prim, ray, hit, kernels);
    return intersectPrimitiveIn<double>(*this, prim, ray, hit, kernels);
}

SurfacePoint Scene::surfacePoint(const Hit& hit, const Ray& ray, Precision precision) const {
    if (precision == Precision::Float) return surfacePointIn<float>(*this, hit, ray);
    return surfacePointIn<double>(*this, hit, ray);
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
        const Vec3 radial = p - s.center;
        // Only a wrong t (the textbook kernel at its limits) lands on the centre itself.
        return glm::length(radial) > 0.0 ? glm::normalize(radial) : Vec3(0.0, 0.0, 1.0);
    }
    return triangle(hit.prim).normal();
}

BoxN<3> clipTriangleBounds(const Vec3& a, const Vec3& b, const Vec3& c, const BoxN<3>& box) {
    const Vec3 pad = 1e-6 * glm::max(box.diagonal(), Vec3(0.0));
    const Vec3 lo = box.lo - pad, hi = box.hi + pad;
    // A triangle clipped by six planes has at most 9 vertices.
    std::array<Vec3, 12> poly{a, b, c}, next{};
    std::size_t n = 3;
    for (int axis = 0; axis < 3 && n > 0; ++axis) {
        for (int side = 0; side < 2 && n > 0; ++side) {
            const double plane = side == 0 ? lo[axis] : hi[axis];
            const auto inside = [&](const Vec3& p) {
                return side == 0 ? p[axis] >= plane : p[axis] <= plane;
            };
            std::size_t m = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const Vec3& p = poly[i];
                const Vec3& q = poly[(i + 1) % n];
                if (inside(p)) next[m++] = p;
                if (inside(p) != inside(q)) {
                    // The edge crosses the plane: the crossing point, exactly on the plane.
                    Vec3 x = p + (q - p) * ((plane - p[axis]) / (q[axis] - p[axis]));
                    x[axis] = plane;
                    next[m++] = x;
                }
            }
            poly = next;
            n = m;
        }
    }
    BoxN<3> out;
    for (std::size_t i = 0; i < n; ++i) out.extend(poly[i]);
    return n == 0 ? BoxN<3>{} : out.clippedTo(box);
}

Scene transformScene(Scene s, double scale, const Vec3& shift) {
    const auto map = [&](Vec3& p) { p = p * scale + shift; };
    for (Triangle& t : s.triangles) map(t.a), map(t.b), map(t.c);
    for (Sphere& sp : s.spheres) map(sp.center), sp.radius *= scale;
    for (PointLight& l : s.lights) map(l.position);
    for (Material& m : s.materials) m.checker.size *= scale;
    map(s.camera.eye);
    map(s.camera.lookAt);
    return s;
}

}  // namespace raystep
