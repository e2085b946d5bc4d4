// Why a primitive test missed: the slides' kernels re-run on the recorded ray without its
// interval, and the interval then compared (feedback/miss_cause.h).
#include "miss_cause.h"

#include "raystep/geometry/intersect.h"

#include <cmath>
#include <limits>

namespace raystep::feedback {

namespace {
double cross2(double ax, double ay, double bx, double by) {
    return ax * by - ay * bx;
}
}  // namespace

std::string missCause(const std::variant<Scene, Scene2D>& scene, const EventLog& log,
                      std::size_t testIndex, Language lang) {
    const auto& events = log.events();
    if (testIndex >= events.size()) return "";
    const auto* test = std::get_if<PrimitiveTest>(&events[testIndex]);
    if (!test || test->hit || test->ray >= log.rays().size()) return "";
    const RayRecord& ray = log.rays()[test->ray];
    // The interval at this test: the ray's, shortened by every hit of this ray found before it.
    double tMax = ray.tMax;
    for (std::size_t i = 0; i < testIndex; ++i)
        if (const auto* t = std::get_if<PrimitiveTest>(&events[i]);
            t && t->ray == test->ray && t->hit)
            tMax = std::min(tMax, t->t);
    const auto n = [&](double v) { return formatNumber(v, lang); };
    // Roots or a parameter found: say which end of the interval excludes them.
    const auto outside = [&](double t) -> std::string {
        if (!(t > ray.tMin))
            return trf(lang, "The intersection with its surface lies behind the origin (t = %1).",
                       {n(t)});
        if (!(t < tMax))
            return trf(lang,
                       "Its intersection, t = %1, lies beyond the nearest one found so far (t = "
                       "%2).",
                       {n(t), n(tMax)});
        return "";
    };
    const auto roots = [&](double a, double b, double c) -> std::string {
        const double disc = b * b - 4 * a * c;
        if (disc < 0)
            return trf(lang,
                       "The discriminant B² − 4AC = %1 is negative: the ray passes beside it.",
                       {n(disc)});
        const double sq = std::sqrt(disc);
        const double t0 = (-b - sq) / (2 * a), t1 = (-b + sq) / (2 * a);
        if (!(t1 > ray.tMin))
            return trf(lang, "Both roots, t0 = %1 and t1 = %2, lie behind the origin.",
                       {n(t0), n(t1)});
        return outside(t0 > ray.tMin ? t0 : t1);
    };
    if (const auto* s2 = std::get_if<Scene2D>(&scene)) {
        const double ox = ray.origin.x, oy = ray.origin.y, dx = ray.dir.x, dy = ray.dir.y;
        if (s2->isCircle(test->prim)) {
            const Circle2& c = s2->circles[test->prim];
            const double fx = ox - c.center.x, fy = oy - c.center.y;
            return roots(dx * dx + dy * dy, 2 * (fx * dx + fy * dy),
                         fx * fx + fy * fy - c.radius * c.radius);
        }
        const std::size_t k = test->prim - s2->circles.size();
        if (k >= s2->segments.size()) return "";
        const Segment2& s = s2->segments[k];
        // o + t d = a + s (b - a), by Cramer's rule.
        const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y;
        const double den = cross2(dx, dy, ex, ey);
        if (den == 0.0) return tr(lang, "The ray is parallel to the segment.");
        const double px = s.a.x - ox, py = s.a.y - oy;
        const double t = cross2(px, py, ex, ey) / den, along = cross2(px, py, dx, dy) / den;
        if (along < 0.0 || along > 1.0)
            return trf(lang,
                       "The ray meets the segment's line outside the segment (at s = %1 of it, "
                       "where 0 to 1 is the segment).",
                       {n(along)});
        return outside(t);
    }
    const Scene& s3 = std::get<Scene>(scene);
    if (test->prim >= s3.spheres.size() + s3.triangles.size()) return "";
    if (s3.isSphere(test->prim)) {
        const Sphere& sp = s3.spheres[test->prim];
        const Vec3 f = ray.origin - sp.center;
        return roots(glm::dot(ray.dir, ray.dir), 2 * glm::dot(f, ray.dir),
                     glm::dot(f, f) - sp.radius * sp.radius);
    }
    const Triangle& tri = s3.triangle(test->prim);
    StepLog steps;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    intersectTrianglePlane<double>(ray.origin, ray.dir, tri.a, tri.b, tri.c, -kInf, kInf, steps);
    double t = std::numeric_limits<double>::quiet_NaN(), u = t, v = t;
    for (const auto& st : steps.steps) {
        const std::string name = st.name;
        if (name == "t") t = st.v[0];
        if (name == "u") u = st.v[0];
        if (name == "v") v = st.v[0];
    }
    if (std::isnan(t)) return tr(lang, "The ray is parallel to the triangle's plane.");
    if (!std::isnan(u) && (u < 0 || v < 0 || u + v > 1))
        return trf(
            lang,
            "The ray meets the triangle's plane outside the triangle: u = %1, v = %2 (inside "
            "needs u ≥ 0, v ≥ 0, u + v ≤ 1).",
            {n(u), n(v)});
    return outside(t);
}

}  // namespace raystep::feedback
