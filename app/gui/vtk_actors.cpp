#include "vtk_actors.h"
#include "presentation.h"

#include "course/palette.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

namespace raystep::gui {

void PropSet::addTo(vtkRenderer* r) const {
    for (const auto& p : props) r->AddViewProp(p);
}

void PropSet::removeFrom(vtkRenderer* r) {
    for (const auto& p : props) r->RemoveViewProp(p);
    props.clear();
}

namespace {

/// A palette colour (course/palette.h, the one table) as VTK's cell colour.
struct Rgb {
    unsigned char c[3];
    explicit Rgb(const PaletteColour& p) : c{p.r, p.g, p.b} {}
    Rgb(unsigned char r, unsigned char g, unsigned char b) : c{r, g, b} {}
    operator const unsigned char*() const { return c; }
};

double maxComponent(const Color& c) {
    return std::max({c.x, c.y, c.z});
}

vtkSmartPointer<vtkActor> actorOf(vtkPolyData* poly, bool scalars) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(poly);
    mapper->SetScalarVisibility(scalars);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
}

/// Coloured segments, drawn as wide lines in flat colour: lines of one pixel vanish on a
/// projector, and unlit lines keep the palette's colour exactly (what the legend names).
class Segments {
  public:
    Segments() { colours_->SetNumberOfComponents(3); }
    void add(const Vec3& a, const Vec3& b, const unsigned char* colour) {
        if (!(glm::length(b - a) > 0) || !std::isfinite(glm::length(b - a))) return;
        const vtkIdType ids[2] = {points_->InsertNextPoint(a.x, a.y, a.z),
                                  points_->InsertNextPoint(b.x, b.y, b.z)};
        lines_->InsertNextCell(2, ids);
        colours_->InsertNextTypedTuple(colour);
    }
    void box(const Vec3& lo, const Vec3& hi, const unsigned char* colour) {
        const auto corner = [&](int k) {
            return Vec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        };
        static const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                         {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
        for (const auto& e : edges) add(corner(e[0]), corner(e[1]), colour);
    }
    void loop(const std::array<Vec3, 4>& c, const unsigned char* colour) {
        for (int k = 0; k < 4; ++k) add(c[k], c[(k + 1) % 4], colour);
    }
    /// A circle of radius r about `centre` in the plane spanned by unit vectors u, v.
    void circle(const Vec3& centre, double r, const Vec3& u, const Vec3& v,
                const unsigned char* colour) {
        constexpr int n = 48;
        for (int k = 0; k < n; ++k) {
            const double a0 = 2 * std::numbers::pi * k / n, a1 = 2 * std::numbers::pi * (k + 1) / n;
            add(centre + r * (std::cos(a0) * u + std::sin(a0) * v),
                centre + r * (std::cos(a1) * u + std::sin(a1) * v), colour);
        }
    }
    bool empty() const { return lines_->GetNumberOfCells() == 0; }
    /// Lines `pixels` wide whatever the zoom, shaded as tubes by VTK.
    vtkSmartPointer<vtkActor> tubes(double pixels) const {
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points_);
        poly->SetLines(lines_);
        poly->GetCellData()->SetScalars(colours_);
        auto actor = actorOf(poly, true);
        actor->GetProperty()->SetLineWidth(pixels);
        actor->GetProperty()->SetRenderLinesAsTubes(true);
        actor->GetProperty()->LightingOff();
        return actor;
    }

    /// The same lines as a dark outline `pixels` wide, drawn flat under the tubes: a ray keeps
    /// its edge over a floor of its own colour (the red and yellow checker). Flat lines lie at
    /// the tube's axis, behind its near surface: the tube is drawn over its outline.
    vtkSmartPointer<vtkActor> outline(double pixels) const {
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points_);
        poly->SetLines(lines_);
        auto actor = actorOf(poly, false);
        actor->GetProperty()->SetColor(0.08, 0.08, 0.1);
        actor->GetProperty()->SetLineWidth(pixels);
        actor->GetProperty()->LightingOff();
        return actor;
    }

  private:
    vtkNew<vtkPoints> points_;
    vtkNew<vtkCellArray> lines_;
    vtkNew<vtkUnsignedCharArray> colours_;
};

/// Translucent faces (voxels, planes, the image plane) of one colour and opacity.
class Faces {
  public:
    void quad(const std::array<Vec3, 4>& c) {
        vtkIdType ids[4];
        for (int k = 0; k < 4; ++k) ids[k] = points_->InsertNextPoint(c[k].x, c[k].y, c[k].z);
        polys_->InsertNextCell(4, ids);
    }
    void box(const Vec3& lo, const Vec3& hi) {
        for (int axis = 0; axis < 3; ++axis)
            for (const double at : {lo[axis], hi[axis]}) quad(planeCorners(lo, hi, axis, at));
    }
    /// The same six faces wound with their fronts outwards (planeCorners' turn about +axis),
    /// for an actor that culls fronts: only the far walls are drawn, behind what is inside.
    void boxOutwards(const Vec3& lo, const Vec3& hi) {
        for (int axis = 0; axis < 3; ++axis) {
            auto low = planeCorners(lo, hi, axis, lo[axis]);
            std::swap(low[1], low[3]);
            quad(low);
            quad(planeCorners(lo, hi, axis, hi[axis]));
        }
    }
    static std::array<Vec3, 4> planeCorners(const Vec3& lo, const Vec3& hi, int axis, double at) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        std::array<Vec3, 4> c;
        for (int k = 0; k < 4; ++k) {
            c[k][axis] = at;
            c[k][u] = (k == 1 || k == 2) ? hi[u] : lo[u];
            c[k][v] = (k >= 2) ? hi[v] : lo[v];
        }
        return c;
    }
    bool empty() const { return polys_->GetNumberOfCells() == 0; }
    vtkSmartPointer<vtkActor> actor(const PaletteColour& colour, double opacity) const {
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points_);
        poly->SetPolys(polys_);
        auto a = actorOf(poly, false);
        a->GetProperty()->SetColor(colour.r / 255.0, colour.g / 255.0, colour.b / 255.0);
        a->GetProperty()->SetOpacity(opacity);
        a->GetProperty()->LightingOff();
        return a;
    }

  private:
    vtkNew<vtkPoints> points_;
    vtkNew<vtkCellArray> polys_;
};

vtkSmartPointer<vtkActor> sphereActor(const Vec3& centre, double radius, int resolution) {
    vtkNew<vtkSphereSource> src;
    src->SetCenter(centre.x, centre.y, centre.z);
    src->SetRadius(radius);
    src->SetThetaResolution(2 * resolution);
    src->SetPhiResolution(resolution);
    src->Update();
    return actorOf(src->GetOutput(), false);
}

/// What a rasterizer can honestly say of a material: its colour and Phong highlight; glass as
/// translucent, a mirror as a bright metal (the reflections themselves need the ray tracer).
void applyMaterial(vtkProperty* p, const Material& m) {
    Color base = glm::clamp(m.kd, 0.0, 1.0);
    double specular = std::clamp(maxComponent(m.ks), 0.0, 1.0), power = std::max(m.n, 5.0);
    if (!isBlack(m.transparency)) {
        // A pale blue-white: clear glass on a dark background, never a black ball.
        base = 0.2 * base + 0.7 * glm::clamp(m.transparency, 0.0, 1.0) * Color(0.85, 0.93, 1.0);
        p->SetOpacity(0.4);
        specular = 1.0;
        power = std::max(power, 80.0);
    } else if (!isBlack(m.reflect)) {
        base = 0.3 * base + 0.6 * glm::clamp(m.reflect, 0.0, 1.0);
        specular = 1.0;
        power = std::max(power, 100.0);
    }
    p->SetColor(base.x, base.y, base.z);
    p->SetAmbient(0.3);
    p->SetDiffuse(0.8);
    p->SetSpecular(specular);
    p->SetSpecularPower(power);
    p->SetSpecularColor(1, 1, 1);
}

/// The material's 3D checker as a 2x2 texture: texel (a, b) holds kd when a + b is even.
vtkSmartPointer<vtkTexture> checkerTexture(const Material& m) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(2, 2, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            const Color c = glm::clamp((x + y) & 1 ? m.checker.color : m.kd, 0.0, 1.0) * 255.0;
            auto* px = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            px[0] = static_cast<unsigned char>(c.x);
            px[1] = static_cast<unsigned char>(c.y);
            px[2] = static_cast<unsigned char>(c.z);
        }
    auto t = vtkSmartPointer<vtkTexture>::New();
    t->SetInputData(image);
    t->InterpolateOff();
    t->RepeatOn();
    t->EdgeClampOff();
    return t;
}

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

PropSet sceneProps(vtkRenderer* r, const Scene& s) {
    PropSet out;
    for (const Sphere& sp : s.spheres) {
        auto actor = sphereActor(sp.center, sp.radius, 32);
        applyMaterial(actor->GetProperty(), s.materials[sp.material]);
        out.props.push_back(actor);
    }
    // Triangles by material: each group one actor with its material (and its checker texture).
    // A wall (a triangle across much of the scene: a floor, a Cornell box's side) is lit on the
    // side its light is on, seen from either side: from beside the eye the view often looks at
    // a box from outside, where a one-sided wall is black (the green wall of lessons 4 and 9).
    // Two copies, one wound each way, each culled from behind, both with the normal toward the
    // light (VTK turns a normal seen from behind around).
    Bounds3 sceneBox;
    for (const Triangle& t : s.triangles) {
        sceneBox.extend(t.a);
        sceneBox.extend(t.b);
        sceneBox.extend(t.c);
    }
    for (const Sphere& sp : s.spheres) {
        sceneBox.extend(sp.center - Vec3(sp.radius));
        sceneBox.extend(sp.center + Vec3(sp.radius));
    }
    const double wallSize = 0.35 * glm::length(sceneBox.diagonal());
    const std::optional<Vec3> light =
        s.lights.empty() ? std::nullopt : std::optional<Vec3>(s.lights.front().position);
    const auto isWall = [&](const Triangle& t) {
        Bounds3 b;
        b.extend(t.a);
        b.extend(t.b);
        b.extend(t.c);
        return light && glm::length(b.diagonal()) >= wallSize;
    };
    enum class Side { Both, LitFront, LitBack };  // a plain triangle, a wall's two copies
    std::map<std::uint32_t, std::vector<const Triangle*>> groups;
    for (const Triangle& t : s.triangles) groups[t.material].push_back(&t);
    for (const auto& [id, tris] : groups) {
        const Material& m = s.materials[id];
        for (const Side side : {Side::Both, Side::LitFront, Side::LitBack}) {
            vtkNew<vtkPoints> points;
            vtkNew<vtkCellArray> cells;
            vtkNew<vtkFloatArray> tcoords;
            tcoords->SetNumberOfComponents(2);
            vtkNew<vtkFloatArray> normals;
            normals->SetNumberOfComponents(3);
            for (const Triangle* t : tris) {
                if ((side == Side::Both) == isWall(*t)) continue;
                // The checker's cubes cut a plane into squares: texture coordinates along the
                // two axes the plane spans, shifted by one square where the third axis's cube
                // is odd.
                const Vec3 face = glm::cross(t->b - t->a, t->c - t->a);
                const Vec3 n = glm::abs(face);
                const int k = n.x >= n.y && n.x >= n.z ? 0 : (n.y >= n.z ? 1 : 2);
                const int i = (k + 1) % 3, j = (k + 2) % 3;
                const double size = m.checker.size > 0 ? m.checker.size : 1.0;
                const Vec3 centroid = (t->a + t->b + t->c) / 3.0;
                const auto odd = static_cast<long long>(std::floor(centroid[k] / size + 1e-7)) & 1;
                // A wall's normal toward the light; its front (counter-clockwise) that side for
                // the first copy, the other for the second.
                Vec3 toLight = glm::normalize(face);
                const bool facesLight = light && glm::dot(toLight, *light - centroid) >= 0;
                if (!facesLight) toLight = -toLight;
                const bool reverse = side != Side::Both && (facesLight != (side == Side::LitFront));
                vtkIdType ids[3];
                for (int v = 0; v < 3; ++v) {
                    const int at = reverse ? 2 - v : v;
                    const Vec3& p = at == 0 ? t->a : (at == 1 ? t->b : t->c);
                    ids[v] = points->InsertNextPoint(p.x, p.y, p.z);
                    const float uv[2] = {float((p[i] / size + 1e-7 + double(odd)) / 2),
                                         float((p[j] / size + 1e-7) / 2)};
                    tcoords->InsertNextTypedTuple(uv);
                    const float nv[3] = {float(toLight.x), float(toLight.y), float(toLight.z)};
                    normals->InsertNextTypedTuple(nv);
                }
                cells->InsertNextCell(3, ids);
            }
            if (cells->GetNumberOfCells() == 0) continue;
            vtkNew<vtkPolyData> mesh;
            mesh->SetPoints(points);
            mesh->SetPolys(cells);
            auto actor = actorOf(mesh, false);
            applyMaterial(actor->GetProperty(), m);
            if (side != Side::Both) {
                mesh->GetPointData()->SetNormals(normals);
                actor->GetProperty()->BackfaceCullingOn();
            }
            if (m.checker.enabled) {
                mesh->GetPointData()->SetTCoords(tcoords);
                actor->SetTexture(checkerTexture(m));
                actor->GetProperty()->SetColor(1, 1, 1);  // the texture carries both colours
            }
            out.props.push_back(actor);
        }
    }
    // The scene's own point lights, where they are (a headlight would light what the ray tracer
    // leaves dark, and wash the Cornell box's coloured walls out).
    r->RemoveAllLights();
    r->AutomaticLightCreationOff();
    const Camera& cam = s.camera;
    const double glyph = 0.015 * glm::length(cam.lookAt - cam.eye);
    for (const PointLight& l : s.lights) {
        vtkNew<vtkLight> light;
        light->SetLightTypeToSceneLight();
        light->SetPositional(true);
        light->SetConeAngle(180);  // a point light, not a spot
        light->SetPosition(l.position.x, l.position.y, l.position.z);
        light->SetFocalPoint(cam.lookAt.x, cam.lookAt.y, cam.lookAt.z);
        const double m = maxComponent(l.intensity);
        const Color c = m > 0 ? l.intensity / m : Color(1.0);
        light->SetColor(c.x, c.y, c.z);
        light->SetIntensity(std::clamp(m, 0.4, 1.0));
        r->AddLight(light);
        auto bulb = sphereActor(l.position, glyph, 12);
        bulb->GetProperty()->LightingOff();
        bulb->GetProperty()->SetColor(1.0, 0.97, 0.75);
        out.props.push_back(bulb);
    }
    if (s.lights.empty()) {
        vtkNew<vtkLight> head;
        head->SetLightTypeToHeadlight();
        r->AddLight(head);
    }
    return out;
}

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

std::vector<Vec3> primitiveCentres(const Scene& s) {
    std::vector<Vec3> c;
    c.reserve(s.primitiveCount());
    for (const Sphere& sp : s.spheres) c.push_back(sp.center);
    for (const Triangle& t : s.triangles) c.push_back((t.a + t.b + t.c) / 3.0);
    return c;
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
