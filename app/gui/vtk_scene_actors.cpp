// The scene as the 3D view's rasterizer draws it: spheres and triangles by material (the checker
// as a texture), the scene's point lights and their glyphs, and the primitives' centres.
#include "vtk_actors.h"
#include "vtk_draw.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <map>
#include <optional>

namespace raystep::gui {

using namespace vtkdraw;

namespace {

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

std::vector<Vec3> primitiveCentres(const Scene& s) {
    std::vector<Vec3> c;
    c.reserve(s.primitiveCount());
    for (const Sphere& sp : s.spheres) c.push_back(sp.center);
    for (const Triangle& t : s.triangles) c.push_back((t.a + t.b + t.c) / 3.0);
    return c;
}

}  // namespace raystep::gui
