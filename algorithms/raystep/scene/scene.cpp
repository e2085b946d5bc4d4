#include "raystep/scene/scene.h"

#include "raystep/geometry/kernels.h"
#include "raystep/scene/prims.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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

namespace {
/// A triangle being clipped (Sutherland-Hodgman): a convex polygon of at most 9 vertices after
/// six planes, in two buffers used in turn so a cut never copies the polygon back. Vertices are
/// plain arrays: the clip indexes coordinates by axis, and glm's operator[] is a switch.
class ClipPolygon {
    using P = std::array<double, 3>;
    /// Bounds of points, grown one at a time (the polygon's, and each side's in splitBounds).
    struct Extent {
        P lo{kInfinity, kInfinity, kInfinity}, hi{-kInfinity, -kInfinity, -kInfinity};
        void add(const P& p) {
            for (int a = 0; a < 3; ++a)
                lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
        }
        BoxN<3> box() const { return {Vec3(lo[0], lo[1], lo[2]), Vec3(hi[0], hi[1], hi[2])}; }
    };

  public:
    ClipPolygon(const Vec3& a, const Vec3& b, const Vec3& c) : n_(3) {
        const Vec3* v[3] = {&a, &b, &c};
        for (int i = 0; i < 3; ++i) {
            for (int axis = 0; axis < 3; ++axis) buf_[0][i][axis] = (*v[i])[axis];
            extent_.add(buf_[0][i]);
        }
    }
    /// Keeps the part with p[axis] >= plane (above) or <= plane. A plane the polygon's bounds
    /// lie inside is skipped: in a node much larger than the triangle, most of the six are.
    /// The axis and side are template arguments: p[axis] then needs no index arithmetic.
    template <int axis, bool above>
    void cut(double plane) {
        if (n_ == 0 || (above ? extent_.lo[axis] >= plane : extent_.hi[axis] <= plane)) return;
        if (above ? extent_.hi[axis] < plane : extent_.lo[axis] > plane) {
            n_ = 0;
            return;
        }
        const auto inside = [&](const P& p) { return above ? p[axis] >= plane : p[axis] <= plane; };
        const auto& in = buf_[cur_];
        auto& out = buf_[1 - cur_];
        std::size_t m = 0;
        Extent kept;  // the bounds of what is kept, on the way
        const auto keep = [&](const P& p) {
            out[m++] = p;
            kept.add(p);
        };
        bool pIn = inside(in[0]);
        for (std::size_t i = 0; i < n_; ++i) {
            const P& q = in[i + 1 == n_ ? 0 : i + 1];
            const bool qIn = inside(q);
            if (pIn) keep(in[i]);
            if (pIn != qIn) keep(crossing<axis>(in[i], q, plane));
            pIn = qIn;
        }
        n_ = m;
        cur_ = 1 - cur_;
        extent_ = kept;
    }
    /// The bounds of the parts on each side of the plane axis = pos, each side widened by `pad`
    /// (one pass over the edges: only the bounds are needed, not the two polygons).
    template <int axis>
    std::pair<BoxN<3>, BoxN<3>> splitBounds(double pos, double pad) const {
        const double planeL = pos + pad, planeR = pos - pad;
        const auto& v = buf_[cur_];
        Extent l, r;
        bool pLeft = n_ > 0 && v[0][axis] <= planeL, pRight = n_ > 0 && v[0][axis] >= planeR;
        for (std::size_t i = 0; i < n_; ++i) {
            const P& p = v[i];
            const P& q = v[i + 1 == n_ ? 0 : i + 1];
            const bool qLeft = q[axis] <= planeL, qRight = q[axis] >= planeR;
            if (pLeft) l.add(p);
            if (pRight) r.add(p);
            if (pLeft != qLeft) l.add(crossing<axis>(p, q, planeL));
            if (pRight != qRight) r.add(crossing<axis>(p, q, planeR));
            pLeft = qLeft;
            pRight = qRight;
        }
        return {l.box(), r.box()};
    }
    BoxN<3> bounds() const { return n_ == 0 ? BoxN<3>{} : extent_.box(); }

  private:
    /// Where edge pq crosses the plane, exactly on it.
    template <int axis>
    static P crossing(const P& p, const P& q, double plane) {
        const double t = (plane - p[axis]) / (q[axis] - p[axis]);
        P x;
        for (int a = 0; a < 3; ++a) x[a] = p[a] + (q[a] - p[a]) * t;
        x[axis] = plane;
        return x;
    }

    std::array<std::array<P, 10>, 2> buf_;
    Extent extent_;  // the polygon's bounds
    int cur_ = 0;
    std::size_t n_;
};

/// The triangle clipped to `box` widened by a millionth of its size (so rounding never drops a
/// triangle that touches the box).
ClipPolygon clipToBox(const Vec3& a, const Vec3& b, const Vec3& c, const BoxN<3>& box) {
    const Vec3 pad = 1e-6 * glm::max(box.diagonal(), Vec3(0.0));
    ClipPolygon poly(a, b, c);
    poly.cut<0, true>(box.lo[0] - pad[0]);
    poly.cut<0, false>(box.hi[0] + pad[0]);
    poly.cut<1, true>(box.lo[1] - pad[1]);
    poly.cut<1, false>(box.hi[1] + pad[1]);
    poly.cut<2, true>(box.lo[2] - pad[2]);
    poly.cut<2, false>(box.hi[2] + pad[2]);
    return poly;
}

/// The clipped polygon's bounds on each side of the plane axis = pos, each clipped to its side
/// of `box`. With the axis a template argument the sides' boxes stay in registers (box.splitAt
/// with a run-time axis sent them through memory, a stall a clip).
template <int axis>
std::pair<BoxN<3>, BoxN<3>> splitClipped(const ClipPolygon& poly, const BoxN<3>& box, double pos) {
    const double pad = 1e-6 * std::max(box.hi[axis] - box.lo[axis], 0.0);
    const auto [l, r] = poly.splitBounds<axis>(pos, pad);
    BoxN<3> left = l.clippedTo(box), right = r.clippedTo(box);
    left.hi[axis] = glm::min(l.hi[axis], pos);
    right.lo[axis] = glm::max(r.lo[axis], pos);
    return {left, right};
}
}  // namespace

BoxN<3> clipTriangleBounds(const Vec3& a, const Vec3& b, const Vec3& c, const BoxN<3>& box) {
    return clipToBox(a, b, c, box).bounds().clippedTo(box);
}

std::pair<BoxN<3>, BoxN<3>> splitTriangleBounds(const Vec3& a, const Vec3& b, const Vec3& c,
                                                const BoxN<3>& box, int axis, double pos) {
    const ClipPolygon poly = clipToBox(a, b, c, box);
    return axis == 0   ? splitClipped<0>(poly, box, pos)
           : axis == 1 ? splitClipped<1>(poly, box, pos)
                       : splitClipped<2>(poly, box, pos);
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

double largestCoordinate(const Scene& scene) {
    double m = std::max(maxAbsComponent(scene.camera.eye), maxAbsComponent(scene.camera.lookAt));
    for (const PointLight& l : scene.lights) m = std::max(m, maxAbsComponent(l.position));
    for (const Sphere& s : scene.spheres) m = std::max(m, maxAbsComponent(s.center) + s.radius);
    for (const Triangle& t : scene.triangles)
        m = std::max({m, maxAbsComponent(t.a), maxAbsComponent(t.b), maxAbsComponent(t.c)});
    return m;
}

double smallestSize(const Scene& scene) {
    double size = std::numeric_limits<double>::infinity();
    for (const Sphere& s : scene.spheres) size = std::min(size, s.radius);
    for (const Triangle& t : scene.triangles) {
        const double edge = std::max(
            {maxAbsComponent(t.b - t.a), maxAbsComponent(t.c - t.b), maxAbsComponent(t.a - t.c)});
        if (edge > 0.0) size = std::min(size, edge);
    }
    return std::isinf(size) ? 0.0 : size;
}

}  // namespace raystep
