#include "raystep/scene/scene2d.h"

namespace raystep {

namespace {
double cross2(const Vec2& a, const Vec2& b) {
    return a.x * b.y - a.y * b.x;
}
}  // namespace

std::optional<double> intersectSegment(const Ray2& ray, const Segment2& s) {
    const Vec2 e = s.b - s.a;
    const double den = cross2(ray.dir, e);
    if (den == 0.0) return std::nullopt;
    const Vec2 ao = s.a - ray.origin;
    const double t = cross2(ao, e) / den;
    const double u = cross2(ao, ray.dir) / den;
    if (!(u >= 0.0 && u <= 1.0)) return std::nullopt;
    if (!(t > ray.tMin && t < ray.tMax)) return std::nullopt;
    return t;
}

std::optional<double> intersectCircle(const Ray2& ray, const Circle2& c) {
    // |o + t d - c|^2 = r^2:  a t^2 + 2 b t + cc = 0 with a = d.d, b = f.d, cc = f.f - r^2.
    const Vec2 f = ray.origin - c.center;
    const double a = glm::dot(ray.dir, ray.dir);
    const double b = glm::dot(f, ray.dir);
    const double cc = glm::dot(f, f) - c.radius * c.radius;
    // b^2 - a cc written as a (r^2 - |f - (b/a) d|^2): no cancellation far from the circle.
    const Vec2 l = f - (b / a) * ray.dir;
    const double disc = a * (c.radius * c.radius - glm::dot(l, l));
    if (disc < 0.0) return std::nullopt;
    const double q = -b - std::copysign(std::sqrt(disc), b);
    double t0 = q != 0.0 ? cc / q : 0.0, t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > ray.tMin && t0 < ray.tMax) return t0;
    if (t1 > ray.tMin && t1 < ray.tMax) return t1;
    return std::nullopt;
}

BoxN<2> Scene2D::primitiveBounds(std::uint32_t p) const {
    BoxN<2> b;
    if (isCircle(p)) {
        const Circle2& c = circles[p];
        b.extend(c.center - Vec2(c.radius));
        b.extend(c.center + Vec2(c.radius));
    } else {
        const Segment2& s = segments[p - circles.size()];
        b.extend(s.a);
        b.extend(s.b);
    }
    return b;
}

BoxN<2> Scene2D::bounds() const {
    BoxN<2> b;
    for (std::uint32_t p = 0; p < primitiveCount(); ++p) b.extend(primitiveBounds(p));
    return b;
}

bool Scene2D::intersectPrimitive(std::uint32_t p, Ray2& ray, Hit2& hit) const {
    const auto t = isCircle(p) ? intersectCircle(ray, circles[p])
                               : intersectSegment(ray, segments[p - circles.size()]);
    if (!t) return false;
    ray.tMax = *t;
    hit = Hit2{*t, p};
    return true;
}

BoxN<2> Scene2DPrims::clippedBounds(std::uint32_t p, const BoxN<2>& box) const {
    if (scene_->isCircle(p)) return bounds(p).clippedTo(box);
    // Liang-Barsky: the part of the segment a + s (b - a), s in [0, 1], inside the box (widened
    // by a millionth so rounding never drops a segment that touches it).
    const Segment2& seg = scene_->segments[p - scene_->circles.size()];
    const Vec2 pad = 1e-6 * glm::max(box.diagonal(), Vec2(0.0));
    const Vec2 lo = box.lo - pad, hi = box.hi + pad;
    const Vec2 d = seg.b - seg.a;
    double s0 = 0.0, s1 = 1.0;
    for (int i = 0; i < 2; ++i) {
        if (d[i] == 0.0) {
            if (seg.a[i] < lo[i] || seg.a[i] > hi[i]) return {};
            continue;
        }
        double e0 = (lo[i] - seg.a[i]) / d[i], e1 = (hi[i] - seg.a[i]) / d[i];
        if (e0 > e1) std::swap(e0, e1);
        s0 = std::max(s0, e0);
        s1 = std::min(s1, e1);
        if (s0 > s1) return {};
    }
    BoxN<2> out;
    out.extend(seg.a + s0 * d);
    out.extend(seg.a + s1 * d);
    return out.clippedTo(box);
}

}  // namespace raystep
