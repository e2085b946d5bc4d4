// The recorded trace as the 3D view draws it at the session's cursor: rays as tubes, hits, the
// eye with its image plane and traced pixels, the structure's boxes, voxels and planes; and the
// points a lecture frames. The scene itself is drawn by vtk_scene_actors.cpp.
#include "vtk_actors.h"
#include "presentation.h"
#include "vtk_draw.h"

#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace raystep::gui {

using namespace vtkdraw;

void PropSet::addTo(vtkRenderer* r) const {
    for (const auto& p : props) r->AddViewProp(p);
}

void PropSet::removeFrom(vtkRenderer* r) {
    for (const auto& p : props) r->RemoveViewProp(p);
    props.clear();
}

namespace {

/// The ray an event ends at a point, and its t: a hit, or what blocks a shadow ray.
std::optional<std::pair<std::uint32_t, double>> endPoint(const Event& e) {
    if (const auto* h = std::get_if<RayHit>(&e)) return std::pair{h->ray, h->t};
    if (const auto* b = std::get_if<RayBlocked>(&e)) return std::pair{b->ray, b->t};
    return std::nullopt;
}

/// Where each recorded ray ends: its hit (or blocker) in the whole log, else its tMax, else
/// `cap` long.
std::vector<double> rayEnds(const EventLog& log, std::size_t upTo, double cap) {
    std::vector<double> ends(log.rays().size(), -1.0);
    for (std::size_t i = 0; i < std::min(upTo, log.events().size()); ++i)
        if (const auto stop = endPoint(log.events()[i]))
            if (stop->first < ends.size()) ends[stop->first] = stop->second;
    for (std::size_t r = 0; r < ends.size(); ++r) {
        const RayRecord& ray = log.rays()[r];
        const double length = glm::length(ray.dir);
        if (!(ends[r] >= 0) || !std::isfinite(ends[r]))
            ends[r] =
                std::isfinite(ray.tMax) && ray.tMax * length < 4 * cap ? ray.tMax : cap / length;
    }
    return ends;
}

/// The eye's frame: forward, right and up (unit).
struct EyeFrame {
    Vec3 f, r, u;
    explicit EyeFrame(const Camera& c) {
        f = glm::normalize(c.lookAt - c.eye);
        r = glm::normalize(glm::cross(f, c.up));
        u = glm::cross(r, f);
    }
};

/// The eye, its frustum up to the image plane, and the traced pixels on that plane.
void eyeProps(const Scene& s, const EventLog& log, double radius, double linePx, PropSet& out) {
    const Camera& cam = s.camera;
    const EyeFrame e(cam);
    const double dist = 0.3 * glm::length(cam.lookAt - cam.eye);
    const double h = dist * std::tan(cam.fovDeg * std::numbers::pi / 360.0);
    const double w = h * s.settings.width / std::max(1, s.settings.height);
    const Vec3 centre = cam.eye + dist * e.f;
    const std::array<Vec3, 4> corners{centre - w * e.r - h * e.u, centre + w * e.r - h * e.u,
                                      centre + w * e.r + h * e.u, centre - w * e.r + h * e.u};
    const Rgb outline(structureColour(StructureRole::GridBox));
    Segments lines;
    lines.loop(corners, outline);
    Segments frustum;
    for (const Vec3& c : corners) frustum.add(cam.eye, c, outline);
    Faces plane;
    plane.quad(corners);
    out.props.push_back(plane.actor(structureColour(StructureRole::GridBox), 0.12));
    out.props.push_back(lines.tubes(std::max(1.5, 0.5 * linePx)));
    out.props.push_back(frustum.tubes(std::max(1.0, 0.3 * linePx)));
    auto eye = sphereActor(cam.eye, 3 * radius, 16);
    eye->GetProperty()->SetColor(1, 1, 1);
    eye->GetProperty()->SetAmbient(0.6);
    out.props.push_back(eye);
    // Each primary ray pierces the image plane at its pixel: a small square there.
    Faces pixels;
    const double side = 0.05 * h;
    int shown = 0;
    for (const RayRecord& ray : log.rays()) {
        if (ray.kind != RayKind::Primary || shown++ >= 256) continue;
        const double along = glm::dot(ray.dir, e.f);
        if (!(along > 0)) continue;
        const Vec3 p = ray.origin + ray.dir * (glm::dot(centre - ray.origin, e.f) / along);
        pixels.quad({p - side * e.r - side * e.u, p + side * e.r - side * e.u,
                     p + side * e.r + side * e.u, p - side * e.r + side * e.u});
    }
    if (!pixels.empty())
        out.props.push_back(pixels.actor(structureColour(StructureRole::HitPoint), 1));
}

/// A tree's walk at the cursor, as the 2D view draws it: every node the ray has entered (by
/// depth: deeper boxes brighter, the root dimmest), the current one in the current node's colour
/// and filled (its far walls), each entered node's split plane (the current one's brighter), the
/// skipped nodes in dim grey (thinner, in their own actor).
void treeWalkProps(const StructureOutline<3>& o, const ReplayState& st, Segments& edges,
                   Segments& skipped, Faces& planes, Faces& currentPlane, Faces& currentNode) {
    const std::uint32_t at = st.node ? st.node->node : kNoId;
    const PaletteColour& box =
        structureColour(o.overlapping ? StructureRole::BvhBox : StructureRole::SplitPlane);
    const double deepest = std::max<std::uint32_t>(1, o.maxDepth);
    const auto shade = [](const PaletteColour& c, double k) {
        const auto f = [k](unsigned char v) { return static_cast<unsigned char>(v * k); };
        return Rgb(f(c.r), f(c.g), f(c.b));
    };
    std::vector<bool> drawn(o.nodes.size(), false);
    for (const std::uint32_t id : st.nodesEntered) {
        if (id >= o.nodes.size() || drawn[id]) continue;
        drawn[id] = true;
        const OutlineNode<3>& n = o.nodes[id];
        if (id == at) {
            edges.box(n.box.lo, n.box.hi, Rgb(structureColour(StructureRole::KdNode)));
            currentNode.boxOutwards(n.box.lo, n.box.hi);
        } else {
            edges.box(n.box.lo, n.box.hi, shade(box, 0.65 + 0.35 * n.depth / deepest));
        }
        if (!n.plane || *n.plane >= o.planes.size()) continue;
        const OutlinePlane<3>& p = o.planes[*n.plane];
        const auto quad = Faces::planeCorners(p.box.lo, p.box.hi, p.axis, p.position);
        (id == at ? currentPlane : planes).quad(quad);
        edges.loop(quad, Rgb(structureColour(StructureRole::SplitPlane)));
    }
    for (const std::uint32_t id : st.nodesSkipped)
        if (id < o.nodes.size() && !drawn[id])
            skipped.box(o.nodes[id].box.lo, o.nodes[id].box.hi,
                        shade(structureColour(StructureRole::BvhBox), 0.8));
}

}  // namespace

std::vector<Vec3> pointsThatMatter(const Session& session) {
    std::vector<Vec3> points;
    const Scene* s = session.scene3D();
    if (!s) return points;
    const auto boxCorners = [&](const Vec3& lo, const Vec3& hi) {
        for (int k = 0; k < 8; ++k)
            points.emplace_back(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    };
    points.push_back(s->camera.eye);
    points.push_back(s->camera.lookAt);
    for (const Sphere& sp : s->spheres)
        for (int axis = 0; axis < 3; ++axis)
            for (const double sign : {-1.0, 1.0}) {
                Vec3 p = sp.center;
                p[axis] += sign * sp.radius;
                points.push_back(p);
            }
    if (const StructureOutline<3>* o = session.outline3D(); o && o->grid)
        boxCorners(o->grid->spec.lo, o->grid->spec.hi);
    Bounds3 b;
    for (const Vec3& p : points) b.extend(p);
    // The whole recorded tree (framing stays put while the cursor moves).
    const EventLog& log = session.log();
    const double cap = std::max(glm::length(b.diagonal()), 1e-9);
    // Up to an open exercise's limit only: what the student may see.
    const std::size_t end = std::min(session.end(), log.events().size());
    const std::vector<double> ends = rayEnds(log, end, cap);
    std::vector<bool> hit(log.rays().size(), false), begun(log.rays().size(), false);
    for (std::size_t i = 0; i < end; ++i) {
        if (const auto stop = endPoint(log.events()[i]))
            if (stop->first < hit.size()) hit[stop->first] = std::isfinite(stop->second);
        if (const auto* rb = std::get_if<RayBegin>(&log.events()[i]))
            if (rb->ray < begun.size()) begun[rb->ray] = true;
    }
    // First what the rays hit; the rays that leave (to a light, or out of the scene) count
    // for at most half the scene's size after, so a far light does not shrink the picture.
    for (std::size_t r = 0; r < log.rays().size(); ++r)
        if (hit[r]) {
            points.push_back(log.rays()[r].origin);
            points.push_back(log.rays()[r].origin + ends[r] * log.rays()[r].dir);
        }
    for (std::size_t i = 2; i < points.size(); ++i) b.extend(points[i]);
    const double core = std::max(glm::length(b.diagonal()), 1e-9);
    const Vec3 pad = 0.1 * b.diagonal() + Vec3(1e-9);
    const Bounds3 near{b.lo - pad, b.hi + pad};
    for (std::size_t r = 0; r < log.rays().size(); ++r) {
        if (hit[r] || !begun[r]) continue;
        const RayRecord& ray = log.rays()[r];
        points.push_back(ray.origin);
        points.push_back(ray.origin +
                         std::min(ends[r], 0.5 * core / glm::length(ray.dir)) * ray.dir);
    }
    // Objects made of triangles (a pyramid, a mesh) count whole; floors and walls, larger than
    // the rest, only where a ray hits them (they would shrink everything else to a corner).
    for (const Triangle& t : s->triangles) {
        Bounds3 tb;
        tb.extend(t.a);
        tb.extend(t.b);
        tb.extend(t.c);
        if (glm::length(tb.diagonal()) < 0.5 * core && !tb.clippedTo(near).empty()) {
            points.push_back(t.a);
            points.push_back(t.b);
            points.push_back(t.c);
        }
    }
    return points;
}

Bounds3 boundsThatMatter(const Session& session) {
    Bounds3 b;
    for (const Vec3& p : pointsThatMatter(session)) b.extend(p);
    return b;
}

void traceProps(const Session& session, double linePx, PropSet& trace, PropSet& eye) {
    // Presenter mode: thicker rays and edges, larger hit points (for a projector's back rows).
    const double presenter = presentation().lineScale();
    linePx *= presenter;
    trace.props.clear();
    eye.props.clear();
    const Scene* s = session.scene3D();
    if (!s) return;
    const EventLog& log = session.log();
    const ReplayState& st = session.state();
    const Bounds3 frame = boundsThatMatter(session);
    const double size = std::max(glm::length(frame.diagonal()), 1e-9);
    const double radius = 0.0035 * size * presenter;  // hit points, the eye: small in the scene
    eyeProps(*s, log, radius, linePx, eye);

    // Each ray that has begun by the cursor, from its origin to its hit (or a scene's length).
    std::vector<bool> begun(log.rays().size(), false);
    for (std::size_t i = 0; i < std::min(st.cursor, log.events().size()); ++i)
        if (const auto* rb = std::get_if<RayBegin>(&log.events()[i]))
            if (rb->ray < begun.size()) begun[rb->ray] = true;
    std::vector<bool> hit(log.rays().size(), false);
    for (std::size_t i = 0; i < std::min(st.cursor, log.events().size()); ++i)
        if (const auto stop = endPoint(log.events()[i]))
            if (stop->first < hit.size()) hit[stop->first] = std::isfinite(stop->second);
    const double cap = std::max(glm::length(s->camera.lookAt - s->camera.eye), size);
    // A ray not yet ended by the cursor runs on (its hit is still to be found).
    const std::vector<double> ends = rayEnds(log, st.cursor, cap);
    Segments rays;
    for (std::size_t r = 0; r < log.rays().size(); ++r) {
        if (!begun[r]) continue;
        const RayRecord& ray = log.rays()[r];
        rays.add(ray.origin, ray.origin + ends[r] * ray.dir, Rgb(rayColour(ray.kind)));
    }
    if (!rays.empty()) {
        trace.props.push_back(rays.outline(linePx + 2 * std::max(2.0, 0.35 * linePx)));
        trace.props.push_back(rays.tubes(linePx));
    }
    // The hit points found so far, as small white spheres.
    const PaletteColour& hitColour = structureColour(StructureRole::HitPoint);
    int spheres = 0;
    for (std::size_t r = 0; r < log.rays().size() && spheres < 400; ++r) {
        if (!begun[r] || !hit[r]) continue;
        const RayRecord& ray = log.rays()[r];
        auto a = sphereActor(ray.origin + ends[r] * ray.dir, 2.2 * radius, 10);
        a->GetProperty()->SetColor(hitColour.r / 255.0, hitColour.g / 255.0, hitColour.b / 255.0);
        a->GetProperty()->SetAmbient(0.5);
        trace.props.push_back(a);
        ++spheres;
    }

    // The structure, from its outline: the grid's box and the current ray's voxels, or the
    // tree's nodes the ray has entered (the kd-tree's with their planes, the BVH's boxes
    // overlapping as they are).
    Segments edges, skippedEdges;
    Faces visited, current, planes, currentPlane, currentNode;
    const Rgb kGrid(structureColour(StructureRole::GridBox)),
        kVoxel(structureColour(StructureRole::Voxel)),
        kCurrent(structureColour(StructureRole::CurrentVoxel)),
        kNode(structureColour(StructureRole::KdNode)),
        kTested(structureColour(StructureRole::TestedPrimitive));
    const StructureOutline<3>* outline = session.outline3D();
    if (const OutlineGrid<3>* grid = outline && outline->grid ? &*outline->grid : nullptr) {
        edges.box(grid->spec.lo, grid->spec.hi, kGrid);
        const std::size_t n = st.visitedCells.size();
        for (std::size_t i = n > 4000 ? n - 4000 : 0; i < n; ++i) {
            const auto& c = st.visitedCells[i];
            const IVecN<3> cell(c[0], c[1], c[2]);
            if (glm::any(glm::lessThan(cell, IVecN<3>(0))) ||
                glm::any(glm::greaterThanEqual(cell, grid->spec.res)))
                continue;  // not one of its cells (a hand-made trace)
            const BoxN<3> b = grid->cellBox(cell);
            if (i + 1 == n) {
                current.box(b.lo, b.hi);
                edges.box(b.lo, b.hi, kCurrent);
            } else {
                visited.box(b.lo, b.hi);
                edges.box(b.lo, b.hi, kVoxel);
            }
        }
    } else if (outline && !outline->nodes.empty() && !session.showingBuild()) {
        treeWalkProps(*outline, st, edges, skippedEdges, planes, currentPlane, currentNode);
    }
    // A build's replay: the node being split, the candidate plane of the sweep, the choice (the
    // 2D view's roles, so both views agree).
    if (session.showingBuild() && st.buildNode && st.buildNode->node < log.nodes().size()) {
        const NodeRecord& n = log.nodes()[st.buildNode->node];
        const Vec3 lo(n.lo[0], n.lo[1], n.lo[2]), hi(n.hi[0], n.hi[1], n.hi[2]);
        edges.box(lo, hi, kNode);
        if (!st.candidates.empty())
            edges.loop(Faces::planeCorners(lo, hi, st.candidates.back().axis,
                                           st.candidates.back().position),
                       Rgb(roleColour(PaletteRole::Candidate)));
        if (st.chosen) {
            const auto quad = Faces::planeCorners(lo, hi, st.chosen->axis, st.chosen->position);
            edges.loop(quad, Rgb(roleColour(PaletteRole::Chosen)));
            currentPlane.quad(quad);
        }
    }
    // The primitives the current ray has tested: white outlines (great circles on spheres).
    if (!session.showingBuild()) {
        std::vector<bool> done(s->primitiveCount(), false);
        for (const PrimitiveTest& t : st.tests) {
            if (t.prim >= done.size() || done[t.prim]) continue;
            done[t.prim] = true;
            if (s->isSphere(t.prim)) {
                const Sphere& sp = s->spheres[t.prim];
                const double rr = sp.radius * 1.01;
                edges.circle(sp.center, rr, Vec3(1, 0, 0), Vec3(0, 0, 1), kTested);
                edges.circle(sp.center, rr, Vec3(1, 0, 0), Vec3(0, 1, 0), kTested);
            } else {
                const Triangle& tri = s->triangle(t.prim);
                edges.add(tri.a, tri.b, kTested);
                edges.add(tri.b, tri.c, kTested);
                edges.add(tri.c, tri.a, kTested);
            }
        }
    }
    if (!visited.empty())
        trace.props.push_back(visited.actor(structureColour(StructureRole::Voxel), 0.12));
    if (!current.empty())
        trace.props.push_back(current.actor(structureColour(StructureRole::CurrentVoxel), 0.35));
    if (!planes.empty())
        trace.props.push_back(planes.actor(structureColour(StructureRole::SplitPlane), 0.15));
    if (!currentPlane.empty())
        trace.props.push_back(currentPlane.actor(structureColour(StructureRole::SplitPlane), 0.35));
    if (!currentNode.empty()) {
        // Its far walls only: the ray and the primitives inside it keep their colours.
        auto fill = currentNode.actor(structureColour(StructureRole::KdNode), 0.15);
        fill->GetProperty()->FrontfaceCullingOn();
        trace.props.push_back(fill);
    }
    // Skipped nodes thinner than the rest: VTK has no dashed tubes.
    if (!skippedEdges.empty())
        trace.props.push_back(skippedEdges.tubes(std::max(1.5, 0.3 * linePx)));
    if (!edges.empty()) trace.props.push_back(edges.tubes(std::max(2.0, 0.6 * linePx)));
}

}  // namespace raystep::gui
