#pragma once
// What the kd-tree and BVH practices share: a few circles and segments on a half-unit lattice
// (their bounds, the trees' boxes and planes are short decimals), the scene as the lesson's
// inline 2D scene and as `given`, the primitives named as a student reads them, and the checks
// that keep a ray clear of every near tie (a box corner grazed, a circle touched, a segment's end).
#include "course/practice/generator.h"

#include "raystep/accel/accel.h"
#include "raystep/accel/outline.h"
#include "raystep/scene/scene2d.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace raystep::practice::tree2d {

/// Half units drawn as whole numbers and divided once: 2.5 is the double nearest 2.5.
inline double halves(int v) {
    return static_cast<double>(v) / 2.0;
}

/// `count` primitives in [0, w] x [0, h]: circles of radius 0.5 or 1, segments between whole
/// points, never parallel to an axis (a flat box is no box to draw), at most 3 long per axis.
inline Scene2D drawPrims(Random& r, int count, int w, int h) {
    Scene2D s;
    s.name = "practice";
    const int circles = r.between(1, count - 1);
    for (int i = 0; i < circles; ++i) {
        const int rad = r.between(1, 2);  // in halves
        Circle2 c;
        c.radius = halves(rad);
        c.center = {halves(r.between(rad, 2 * w - rad)), halves(r.between(rad, 2 * h - rad))};
        s.circles.push_back(c);
    }
    while (static_cast<int>(s.circles.size() + s.segments.size()) < count) {
        const int ax = r.between(0, w), ay = r.between(0, h);
        const int bx = ax + r.sign() * r.between(1, 3), by = ay + r.sign() * r.between(1, 3);
        if (bx < 0 || bx > w || by < 0 || by > h) continue;
        s.segments.push_back({{double(ax), double(ay)}, {double(bx), double(by)}});
    }
    return s;
}

/// A node of the tree raystep builds, as a prompt and `given` describe it.
struct TreeNode {
    std::uint32_t id = 0;
    BoxN<2> box;
    bool leaf = false;
    int axis = 0;                       // interior: the axis of its split
    double split = 0.0;                 // a kd-tree's interior: its plane's position
    std::uint32_t left = 0, right = 0;  // interior: its children (left: the lower side)
    std::vector<std::uint32_t> prims;   // a leaf's, in the engine's order
};

/// The nodes of the structure `kind` raystep builds over `s`, by id, read from its outline
/// (outline.h) as the views read it: no generator depends on one structure's type.
inline std::vector<TreeNode> treeNodes(const Scene2D& s, AccelKind kind,
                                       const AccelOptions& options) {
    const Accelerator2D accel = buildAccelerator2D(s, kind, options);
    const StructureOutline<2> o = outline(accel, OutlineDetail::Primitives);
    std::vector<TreeNode> out;
    for (std::uint32_t id = 0; id < o.nodes.size(); ++id) {
        const OutlineNode<2>& n = o.nodes[id];
        TreeNode t;
        t.id = id;
        t.box = n.box;
        t.leaf = n.leaf;
        if (n.leaf) {
            const auto ids = o.primitivesOf(id);
            t.prims.assign(ids.begin(), ids.end());
        } else {
            t.axis = n.axis;
            t.left = n.children[0];
            t.right = n.children[1];
            if (n.plane) t.split = o.planes[*n.plane].position;
        }
        out.push_back(std::move(t));
    }
    return out;
}

inline ojson sceneJson(const Scene2D& s, const std::string& description) {
    ojson scene;
    scene["dimensions"] = 2;
    scene["description"] = description;
    ojson circles = ojson::array(), segments = ojson::array();
    for (const Circle2& c : s.circles)
        circles.push_back({{"center", jsonVec({c.center.x, c.center.y})}, {"radius", c.radius}});
    for (const Segment2& g : s.segments)
        segments.push_back({{"from", jsonVec({g.a.x, g.a.y})}, {"to", jsonVec({g.b.x, g.b.y})}});
    if (!circles.empty()) scene["circles"] = circles;
    if (!segments.empty()) scene["segments"] = segments;
    return scene;
}

/// The primitives for `given`: {"circles": [{center, radius}], "segments": [{from, to}]}, the
/// ids the engine gives them (circles first).
inline void addPrims(ojson& given, const Scene2D& s) {
    const ojson scene = sceneJson(s, "");
    given["circles"] = scene.value("circles", ojson::array());
    given["segments"] = scene.value("segments", ojson::array());
}

/// "circle 0" / "il cerchio 0", "segment 3" / "il segmento 3".
inline std::string primName(const Scene2D& s, std::uint32_t p, bool it) {
    const std::string id = std::to_string(p);
    if (s.isCircle(p)) return (it ? "il cerchio " : "circle ") + id;
    return (it ? "il segmento " : "segment ") + id;
}

/// Every primitive with its data, one sentence: "circle 0: centre `(2, 3)`, radius 1; ...".
inline std::string primList(const Scene2D& s, bool it) {
    std::string out;
    for (std::uint32_t p = 0; p < s.primitiveCount(); ++p) {
        out += p ? "; " : "";
        if (s.isCircle(p)) {
            const Circle2& c = s.circles[p];
            out += it ? "cerchio " + std::to_string(p) + " di centro `" +
                            vec({c.center.x, c.center.y}) + "` e raggio " + num(c.radius, true)
                      : "circle " + std::to_string(p) + ", centre `" +
                            vec({c.center.x, c.center.y}) + "`, radius " + num(c.radius);
        } else {
            const Segment2& g = s.segments[p - s.circles.size()];
            out += (it ? "segmento " : "segment ") + std::to_string(p) +
                   (it ? " da `" : " from `") + vec({g.a.x, g.a.y}) + (it ? "` a `" : "` to `") +
                   vec({g.b.x, g.b.y}) + "`";
        }
    }
    return out;
}

inline std::string corners(const BoxN<2>& b, bool it) {
    return (it ? "da `" : "from `") + vec({b.lo[0], b.lo[1]}) + (it ? "` a `" : "` to `") +
           vec({b.hi[0], b.hi[1]}) + "`";
}

inline ojson boxJson(const BoxN<2>& b, ojson out = ojson::object()) {
    out["min"] = jsonVec({b.lo[0], b.lo[1]});
    out["max"] = jsonVec({b.hi[0], b.hi[1]});
    return out;
}

/// A ray from outside `box`, through a point inside it on the quarter lattice, with directions
/// whose reciprocals are short decimals (0.5, 1, 2 per axis, either sign).
inline Ray2 drawRay(Random& r, const BoxN<2>& box) {
    for (;;) {
        Ray2 ray;
        const auto inside = [&](int a) {
            const int lo = static_cast<int>(std::lround(box.lo[a] * 4)) + 1;
            const int hi = static_cast<int>(std::lround(box.hi[a] * 4)) - 1;
            return static_cast<double>(r.between(lo, hi)) / 4.0;
        };
        const Vec2 target{inside(0), inside(1)};
        ray.dir = {r.pick(std::vector<double>{0.5, 1.0, 2.0}) * r.sign(),
                   r.pick(std::vector<double>{0.5, 1.0, 2.0}) * r.sign()};
        ray.origin = target - static_cast<double>(r.between(2, 4)) * ray.dir;
        const bool in = ray.origin.x >= box.lo[0] && ray.origin.x <= box.hi[0] &&
                        ray.origin.y >= box.lo[1] && ray.origin.y <= box.hi[1];
        if (!in) return ray;
    }
}

/// The t where the ray crosses x = c (axis 0) or y = c (axis 1).
inline double crossing(const Ray2& ray, int axis, double c) {
    return (c - ray.origin[axis]) / ray.dir[axis];
}

/// The ray keeps 0.05 (in t) from every tie a student's arithmetic could decide either way: no
/// x line crossed at nearly the t of a y line (a box corner or a plane's end grazed), no circle
/// nearly touched, no segment met near its end, no two primitives met at nearly one t, and the
/// nearest hit away from every line. `xs`, `ys`: the lines that bound the boxes and cells.
inline bool rayClear(const Scene2D& s, const Ray2& ray, std::vector<double> xs,
                     std::vector<double> ys) {
    constexpr double kGap = 0.05;
    std::vector<double> tx, ty, lines, hits;
    for (double x : xs) tx.push_back(crossing(ray, 0, x));
    for (double y : ys) ty.push_back(crossing(ray, 1, y));
    for (double a : tx)
        for (double b : ty)
            if (std::abs(a - b) < kGap) return false;
    lines = tx;
    lines.insert(lines.end(), ty.begin(), ty.end());
    const double len = std::hypot(ray.dir.x, ray.dir.y);
    for (const Circle2& c : s.circles) {
        const Vec2 f = c.center - ray.origin;
        const double along = (f.x * ray.dir.x + f.y * ray.dir.y) / len;
        const double dist = std::abs(f.x * ray.dir.y - f.y * ray.dir.x) / len;
        if (std::abs(dist - c.radius) < 0.1) return false;
        if (dist < c.radius) {
            const double t = (along - std::sqrt(c.radius * c.radius - dist * dist)) / len;
            if (t < 0.1) return false;  // the origin in or next to a circle
            hits.push_back(t);
        }
    }
    for (const Segment2& g : s.segments) {
        const Vec2 e = g.b - g.a, f = g.a - ray.origin;
        const double den = ray.dir.x * e.y - ray.dir.y * e.x;
        if (std::abs(den) < 1e-9) continue;  // parallel: a miss, but keep it clear
        const double t = (f.x * e.y - f.y * e.x) / den;
        const double u = (f.x * ray.dir.y - f.y * ray.dir.x) / den;
        const double el = std::hypot(e.x, e.y);
        if (std::abs(u) * el < 0.1 || std::abs(1 - u) * el < 0.1) return false;
        if (u > 0 && u < 1) {
            if (std::abs(t) < 0.1) return false;
            if (t > 0) hits.push_back(t);
        }
    }
    std::sort(hits.begin(), hits.end());
    for (std::size_t i = 1; i < hits.size(); ++i)
        if (hits[i] - hits[i - 1] < kGap) return false;
    if (!hits.empty())
        for (double t : lines)
            if (std::abs(t - hits[0]) < kGap) return false;
    return true;
}

/// A ray from outside `box` clear of every near tie with the nodes' boxes and the primitives
/// (rayClear), drawn up to 20 times; nullopt if none is.
inline std::optional<Ray2> clearRay(Random& r, const Scene2D& s, const BoxN<2>& box,
                                    const std::vector<TreeNode>& nodes) {
    std::vector<double> xs, ys;
    for (const TreeNode& n : nodes) {
        xs.push_back(n.box.lo[0]);
        xs.push_back(n.box.hi[0]);
        ys.push_back(n.box.lo[1]);
        ys.push_back(n.box.hi[1]);
    }
    for (int tries = 0; tries < 20; ++tries) {
        const Ray2 ray = drawRay(r, box);
        if (rayClear(s, ray, xs, ys)) return ray;
    }
    return std::nullopt;
}

}  // namespace raystep::practice::tree2d
