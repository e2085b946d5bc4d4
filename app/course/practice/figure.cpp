// Drawn by distance: each pixel takes the colour of the nearest stroke within its half width,
// sampled 3 x 3 for smooth edges. A few strokes over a small image: no rasteriser library needed.
#include "course/practice/figure.h"

#include "course/lesson_trace.h"

#include "raystep/accel/outline.h"
#include "raystep/render/image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace raystep {

namespace {

struct Stroke {
    Vec2 a, b;         // a segment (a == b: a dot)
    double halfWidth;  // in pixels
    std::array<double, 3> colour;
    bool circle = false;  // a circle's outline: centre a, radius b.x
};

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double s = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + s * ab));
}

}  // namespace

std::optional<std::string> practiceFigurePng(const Lesson& lesson, int widthPx) {
    const auto any = loadLessonScene(lesson);
    const auto* scene = std::get_if<Scene2D>(&any);
    if (!scene) return std::nullopt;
    const BoxN<2> box = scene->bounds();
    const std::optional<Ray2> ray = lesson.trace.kind == LessonTrace::Kind::Ray2D
                                        ? std::optional<Ray2>(lesson.trace.ray)
                                        : scene->exampleRay;
    // The view: the box and the ray's origin, with a margin.
    Vec2 lo = box.lo, hi = box.hi;
    if (ray) {
        lo = glm::min(lo, ray->origin);
        hi = glm::max(hi, ray->origin);
    }
    const double margin = 0.08 * std::max(hi.x - lo.x, hi.y - lo.y);
    lo -= Vec2(margin);
    hi += Vec2(margin);
    const double scale = widthPx / (hi.x - lo.x);
    const int w = widthPx, h = std::max(1, static_cast<int>(std::lround((hi.y - lo.y) * scale)));
    const auto toPx = [&](const Vec2& p) {
        return Vec2((p.x - lo.x) * scale, (hi.y - p.y) * scale);
    };

    std::vector<Stroke> strokes;
    const std::array<double, 3> gridGrey{0.75, 0.75, 0.75}, ink{0.15, 0.15, 0.15},
        vermillion{0.84, 0.37, 0.0};  // Okabe and Ito's, the app's primary ray
    // The structure as the views draw it (outline.h): the grid's lines, a kd-tree's planes,
    // a BVH's boxes, whatever the lesson builds.
    const Accelerator2D accel = buildAccelerator2D(*scene, lesson.accel, lesson.options);
    const StructureOutline<2> outlined = outline(accel);
    if (outlined.grid)
        for (int a = 0; a < 2; ++a) {
            const std::vector<double>& lines = outlined.grid->lines[a];
            for (std::size_t k = 0; k < lines.size(); ++k) {
                Vec2 p = outlined.bounds.lo, q = outlined.bounds.hi;
                p[a] = q[a] = lines[k];
                const bool edge = k == 0 || k + 1 == lines.size();
                strokes.push_back({toPx(p), toPx(q), edge ? 1.2 : 0.7, edge ? ink : gridGrey});
            }
        }
    for (const OutlinePlane<2>& plane : outlined.planes) {
        const auto [p, q] = plane.extent();
        strokes.push_back({toPx(p), toPx(q), 0.7, gridGrey});
    }
    const bool tree = !outlined.nodes.empty() && !outlined.nodes.front().leaf;  // not one leaf
    for (const OutlineNode<2>& node : outlined.nodes) {
        if (!tree || (!outlined.overlapping && node.parent != kNoId)) continue;  // kd: the root
        const Vec2 c[4] = {node.box.lo, Vec2(node.box.hi.x, node.box.lo.y), node.box.hi,
                           Vec2(node.box.lo.x, node.box.hi.y)};
        for (int k = 0; k < 4; ++k)
            strokes.push_back({toPx(c[k]), toPx(c[(k + 1) % 4]), node.parent == kNoId ? 1.2 : 0.7,
                               node.parent == kNoId ? ink : gridGrey});
    }
    for (const Circle2& c : scene->circles)
        strokes.push_back({toPx(c.center), Vec2(c.radius * scale, 0), 1.0, ink, true});
    for (const Segment2& s : scene->segments) strokes.push_back({toPx(s.a), toPx(s.b), 1.2, ink});
    if (ray) {
        // The ray across the view, then its direction d as an arrow from the origin.
        const Vec2 o = toPx(ray->origin);
        const Vec2 dir = glm::normalize(Vec2(ray->dir.x, -ray->dir.y));
        strokes.push_back({o, o + dir * double(w + h) * 2.0, 0.8, vermillion});
        const Vec2 tip = toPx(ray->origin + ray->dir);
        strokes.push_back({o, tip, 1.8, vermillion});
        const Vec2 back = -glm::normalize(tip - o) * 9.0, side(-back.y * 0.5, back.x * 0.5);
        strokes.push_back({tip, tip + back + side, 1.8, vermillion});
        strokes.push_back({tip, tip + back - side, 1.8, vermillion});
        strokes.push_back({o, o, 3.5, vermillion});
    }

    // Stroke by stroke over its own bounding box (later strokes draw over earlier ones): a
    // roster's hundreds of sheets are drawn in seconds, not minutes.
    const std::array<double, 3> white{1, 1, 1};
    std::vector<const std::array<double, 3>*> sample(static_cast<std::size_t>(w) * h * 9, &white);
    for (const Stroke& s : strokes) {
        const double reach = s.halfWidth + (s.circle ? s.b.x : 0.0);
        const Vec2 lo = s.circle ? s.a - Vec2(reach) : glm::min(s.a, s.b) - Vec2(reach);
        const Vec2 hi = s.circle ? s.a + Vec2(reach) : glm::max(s.a, s.b) + Vec2(reach);
        const int x0 = std::max(0, static_cast<int>(std::floor(lo.x)));
        const int x1 = std::min(w - 1, static_cast<int>(std::ceil(hi.x)));
        const int y0 = std::max(0, static_cast<int>(std::floor(lo.y)));
        const int y1 = std::min(h - 1, static_cast<int>(std::ceil(hi.y)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                for (int k = 0; k < 9; ++k) {
                    const Vec2 p(x + (k % 3 + 0.5) / 3, y + (k / 3 + 0.5) / 3);
                    const double dist = s.circle ? std::abs(glm::length(p - s.a) - s.b.x)
                                                 : distanceToSegment(p, s.a, s.b);
                    if (dist <= s.halfWidth)
                        sample[(static_cast<std::size_t>(y) * w + x) * 9 + k] = &s.colour;
                }
    }
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
    for (std::size_t px = 0; px < static_cast<std::size_t>(w) * h; ++px) {
        std::array<double, 3> sum{0, 0, 0};
        for (int k = 0; k < 9; ++k)
            for (int c = 0; c < 3; ++c) sum[c] += (*sample[px * 9 + k])[c] / 9;
        for (int c = 0; c < 3; ++c)
            rgb[px * 3 + c] = static_cast<std::uint8_t>(std::lround(255 * sum[c]));
    }
    return encodePng(lesson.id + ".png", rgb, w, h);
}

}  // namespace raystep
