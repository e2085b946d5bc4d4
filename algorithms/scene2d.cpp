#include "raystep/scene2d.h"

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
    // The discriminant as a r^2 - a |f - (b/a) d|^2: no cancellation far from the circle.
    const Vec2 l = f - (b / a) * ray.dir;
    const double disc = a * (c.radius * c.radius - glm::dot(l, l));
    if (disc < 0.0) return std::nullopt;
    const double q = -b - std::copysign(std::sqrt(a * disc), b);
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

}  // namespace raystep
