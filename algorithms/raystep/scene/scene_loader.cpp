#include "raystep/scene/scene_loader.h"

#include "raystep/base/json_lines.h"
#include "raystep/base/json_reader.h"
#include "raystep/geometry/kernels.h"
#include "raystep/scene/obj_text.h"
#include "raystep/scene/resources.h"

#include <tiny_obj_loader.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

namespace raystep {

using detail::ifPresent;
using detail::isObjInteger;
using detail::isObjNumber;
using detail::joinNames;
using detail::kMaxFaceVertices;
using detail::objFields;
using nlohmann::json;
using Reader = detail::JsonReader<SceneError>;

namespace {

constexpr double kMaxCameraLength = 1e150, kMinCameraLength = 1e-150;

void readCamera(const Reader& r, const json& j, const std::string& path, Camera& cam) {
    r.requireObject(j, path);
    r.checkKeys(j, path, {"eye", "look_at", "up", "fov"});
    ifPresent(j, path, "eye", [&](const json& v, const std::string& p) { cam.eye = r.vec3(v, p); });
    ifPresent(j, path, "look_at",
              [&](const json& v, const std::string& p) { cam.lookAt = r.vec3(v, p); });
    ifPresent(j, path, "up", [&](const json& v, const std::string& p) { cam.up = r.vec3(v, p); });
    ifPresent(j, path, "fov", [&](const json& v, const std::string& p) {
        cam.fovDeg = r.positive(v, p);
        if (cam.fovDeg >= 180.0) r.fail(p, "field of view must be below 180 degrees");
    });
    // Relative to the camera's own coordinates, so a scene at 1e-9 or 1e9 passes alike.
    const std::string lookAtPath = JsonLineMap::child(path, "look_at");
    const std::string upPath = JsonLineMap::child(path, "up");
    const Vec3 forward = cam.lookAt - cam.eye;
    const double distance = maxAbsComponent(forward);  // infinity when the difference overflows
    const double scale = std::max(maxAbsComponent(cam.eye), maxAbsComponent(cam.lookAt));
    if (!(distance > 1e-12 * scale))
        r.fail(lookAtPath, "the camera has no direction: look_at equals eye");
    // The camera normalises look_at - eye and forward x up (camera.cpp): their squared lengths
    // must stay inside double's range, so both lengths are kept within 1e-150 to 1e150.
    if (!(distance <= kMaxCameraLength))
        r.fail(lookAtPath, "look_at is too far from eye (" +
                               (std::isfinite(distance) ? Reader::fmt(distance)
                                                        : std::string("past the largest double")) +
                               " apart along an axis; at most 1e150: the camera squares it)");
    if (distance < kMinCameraLength)
        r.fail(lookAtPath, "look_at is too close to eye (" + Reader::fmt(distance) +
                               " apart; at least 1e-150: the camera squares it)");
    const double upLength = maxAbsComponent(cam.up);
    if (upLength != 0.0 && (upLength > kMaxCameraLength || upLength < kMinCameraLength))
        r.fail(upPath,
               "the length of up must be within 1e-150 to 1e150 (the camera squares it), "
               "got a component of " +
                   Reader::fmt(upLength));
    const Vec3 side = glm::cross(glm::normalize(forward), cam.up);
    if (!(glm::length(side) > 1e-9 * glm::length(cam.up)))
        r.fail(upPath, "up must not be zero nor parallel to the view direction");
}

void readRender(const Reader& r, const json& j, const std::string& path, RenderSettings& s) {
    r.requireObject(j, path);
    r.checkKeys(j, path, {"width", "height", "bounces", "spp", "diffuse_samples"});
    ifPresent(j, path, "width", [&](const json& v, const std::string& p) {
        s.width = r.integer(v, p, 1, kMaxImageSide);
    });
    ifPresent(j, path, "height", [&](const json& v, const std::string& p) {
        s.height = r.integer(v, p, 1, kMaxImageSide);
    });
    ifPresent(j, path, "bounces", [&](const json& v, const std::string& p) {
        s.bounces = r.integer(v, p, 0, kMaxBounces);
    });
    ifPresent(j, path, "spp",
              [&](const json& v, const std::string& p) { s.spp = r.integer(v, p, 1, kMaxSpp); });
    ifPresent(j, path, "diffuse_samples", [&](const json& v, const std::string& p) {
        s.diffuseSamples = r.integer(v, p, 0, kMaxDiffuseSamples);
    });
}

Material readMaterial(const Reader& r, const json& j, const std::string& path,
                      const std::string& name) {
    r.requireObject(j, path);
    r.checkKeys(j, path, {"kd", "ks", "n", "reflect", "transparency", "ior", "checker"});
    Material m;
    m.name = name;
    ifPresent(j, path, "kd",
              [&](const json& v, const std::string& p) { m.kd = r.color(v, p, true); });
    ifPresent(j, path, "ks",
              [&](const json& v, const std::string& p) { m.ks = r.color(v, p, true); });
    ifPresent(j, path, "n",
              [&](const json& v, const std::string& p) { m.n = r.nonNegative(v, p); });
    ifPresent(j, path, "reflect",
              [&](const json& v, const std::string& p) { m.reflect = r.color(v, p, true); });
    ifPresent(j, path, "transparency",
              [&](const json& v, const std::string& p) { m.transparency = r.color(v, p, true); });
    ifPresent(j, path, "ior",
              [&](const json& v, const std::string& p) { m.ior = r.positive(v, p); });
    ifPresent(j, path, "checker", [&](const json& v, const std::string& p) {
        r.requireObject(v, p);
        r.checkKeys(v, p, {"color", "size"});
        m.checker.enabled = true;
        ifPresent(v, p, "color", [&](const json& c, const std::string& cp) {
            m.checker.color = r.color(c, cp, true);
        });
        ifPresent(v, p, "size", [&](const json& c, const std::string& cp) {
            m.checker.size = r.positive(c, cp);
        });
    });
    return m;
}

struct MeshTransform {
    Vec3 scale{1.0};
    Vec3 translate{0.0};
};

/// A problem in an OBJ file, at its line (tinyobjloader's count: lines end at LF, CR or CRLF).
struct ObjProblem {
    int line;
    std::string message;
};

// "f 1 2 3" is 8 bytes of file and over 200 of memory (tinyobjloader's face and indices, the
// triangle): 10M such lines took 2.3 GB and 10 s to load; 256 MB of them would take 7 GB.
constexpr std::uint64_t kMaxObjTriangles = 10'000'000;

/// Calls `f(lineNumber, statement)` for each line of OBJ text as tinyobjloader reads lines
/// (tiny_obj_loader.h, LoadObj: a line ends at LF, CR or CRLF; blanks and tabs before the
/// statement are skipped). A NUL byte (where tinyobjloader would stop reading the line) is an
/// ObjProblem.
template <typename F>
void forEachObjLine(std::string_view text, F&& f) {
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        ++lineNo;
        std::size_t end = pos;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        if (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ++pos;
        if (line.find('\0') != std::string_view::npos)
            throw ObjProblem{lineNo, "a NUL byte: not a text file"};
        while (!line.empty() && (line[0] == ' ' || line[0] == '\t')) line.remove_prefix(1);
        f(lineNo, line);
    }
}

/// "v" or "f" (a statement tinyobjloader reads as a vertex or a face: a blank or tab after it).
bool isStatement(std::string_view line, char keyword) {
    return line.size() >= 2 && line[0] == keyword && (line[1] == ' ' || line[1] == '\t');
}

/// Checks every vertex and face of OBJ text, throwing ObjProblem with the line, and returns the
/// text tinyobjloader is then given: only "v x y z" and "f i j k ..." lines, with the same
/// number tokens (so the same values) and absolute 1-based indices. What raystep does not use
/// (normals, texture coordinates, groups, materials, tags, lines, points) is left out, so none of
/// it can cost memory or time. `vertexLines` gets each vertex's OBJ line.
std::string checkedObj(std::string_view text, std::vector<int>& vertexLines) {
    // Forward references are legal (tinyobjloader checks indices against the final count).
    std::uint64_t total = 0;
    forEachObjLine(text, [&](int, std::string_view line) { total += isStatement(line, 'v'); });
    std::string out;
    out.reserve(text.size());
    std::uint64_t vertices = 0;  // so far: a negative index counts back from here
    std::uint64_t triangles = 0;
    forEachObjLine(text, [&](int lineNo, std::string_view line) {
        if (isStatement(line, 'v')) {
            const auto fields = objFields(line.substr(2));
            if (fields.size() < 3)
                throw ObjProblem{lineNo, "a vertex needs 3 coordinates, 'v x y z'"};
            for (const std::string_view f : fields) {
                const std::string token(f);
                if (!isObjNumber(f) || !std::isfinite(std::strtod(token.c_str(), nullptr)))
                    throw ObjProblem{lineNo, "vertex coordinate '" + printable(f, 24) +
                                                 "' is not a finite number"};
            }
            out += "v ";
            for (int k = 0; k < 3; ++k) out.append(fields[k]).append(k < 2 ? " " : "\n");
            vertexLines.push_back(lineNo);
            ++vertices;
            return;
        }
        if (!isStatement(line, 'f')) return;
        const auto fields = objFields(line.substr(2));
        if (fields.size() < 3) throw ObjProblem{lineNo, "a face needs at least 3 vertices"};
        if (fields.size() > kMaxFaceVertices)
            throw ObjProblem{lineNo, "a face has at most " + std::to_string(kMaxFaceVertices) +
                                         " vertices, this one " + std::to_string(fields.size())};
        triangles += fields.size() - 2;
        if (triangles > kMaxObjTriangles)
            throw ObjProblem{lineNo, "more than " + std::to_string(kMaxObjTriangles) +
                                         " triangles, the most raystep reads from one OBJ file"};
        out += 'f';
        for (const std::string_view f : fields) {
            // i, i/j, i//k or i/j/k: only the vertex index i is used.
            std::string_view v, vt, vn;
            if (!detail::splitObjCorner(f, v, vt, vn))
                throw ObjProblem{lineNo, "face vertex '" + printable(f, 24) +
                                             "' is not an index (i, i/j, i//k or i/j/k)"};
            std::int64_t index = 0;
            const auto [ptr, ec] =
                std::from_chars(v.data() + (v[0] == '+'), v.data() + v.size(), index);
            const bool negative = ec == std::errc() && index < 0;
            // Past 2^31 tinyobjloader's atoi would wrap; no such index is ever in range here.
            if (ec != std::errc() || index == 0 ||
                (negative ? static_cast<std::uint64_t>(-(index + 1)) + 1 > vertices
                          : static_cast<std::uint64_t>(index) > total))
                throw ObjProblem{
                    lineNo, "vertex index " + printable(v, 24) + " is out of range (" +
                                std::to_string(negative ? vertices : total) +
                                (negative                          ? " vertices before this line)"
                                 : index == 0 && ec == std::errc() ? " vertices; OBJ counts from 1)"
                                                                   : " vertices)")};
            out += ' ';
            out +=
                std::to_string(negative ? static_cast<std::int64_t>(vertices) + index + 1 : index);
        }
        out += '\n';
    });
    return out;
}

void readMesh(const Reader& r, const json& j, const std::string& path, std::uint32_t material,
              const FileResolver& resolver, Scene& scene) {
    const std::string filePath = JsonLineMap::child(path, "file");
    if (!j.contains("file")) r.fail(filePath, "a mesh needs the OBJ file to load");
    const std::string file = r.string(j["file"], filePath);
    const std::string quoted = "OBJ file '" + printable(file) + "'";
    MeshTransform xf;
    ifPresent(j, path, "scale", [&](const json& v, const std::string& p) {
        xf.scale = v.is_number() ? Vec3(r.number(v, p)) : r.vec3(v, p);
        if (xf.scale.x == 0.0 || xf.scale.y == 0.0 || xf.scale.z == 0.0)
            r.fail(p, "scale must not be zero (the mesh would be flat)");
    });
    ifPresent(j, path, "translate",
              [&](const json& v, const std::string& p) { xf.translate = r.vec3(v, p); });

    std::optional<std::string> text;
    try {
        text = resolver(file);
    } catch (const detail::ReadFailure& f) {
        r.fail(filePath, "cannot read " + quoted + ": " + f.what());
    }
    if (!text) r.fail(filePath, "cannot read " + quoted + ": no such file");
    std::vector<int> vertexLines;
    std::string checked;
    try {
        checked = checkedObj(*text, vertexLines);
    } catch (const ObjProblem& p) {
        r.fail(filePath, quoted + " line " + std::to_string(p.line) + ": " + p.message);
    }
    text.reset();  // the checked copy is all tinyobjloader needs
    tinyobj::ObjReader obj;
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    if (!obj.ParseFromString(checked, "", config)) {
        std::string err = obj.Error();
        while (!err.empty() && err.back() == '\n') err.pop_back();
        r.fail(filePath, "cannot read " + quoted + ": " + printable(err, 200));
    }
    const auto& verts = obj.GetAttrib().vertices;
    if (verts.size() != 3 * vertexLines.size())
        r.fail(filePath, "cannot read " + quoted + ": tinyobjloader read " +
                             std::to_string(verts.size() / 3) + " vertices, not " +
                             std::to_string(vertexLines.size()));
    // tinyobjloader reads a mantissa digit by digit: a long one overflows to infinity where
    // strtod, in the check above, does not.
    for (std::size_t k = 0; k < verts.size(); ++k)
        if (!std::isfinite(verts[k])) {
            const int line = vertexLines[k / 3];
            std::size_t at = 0;
            for (std::size_t v = 0; v < k / 3; ++v) at = checked.find('\n', at) + 1;
            const auto fields = objFields(
                std::string_view(checked).substr(at + 2, checked.find('\n', at) - at - 2));
            r.fail(filePath, quoted + " line " + std::to_string(line) + ": vertex coordinate '" +
                                 printable(fields[k % 3], 24) +
                                 "' overflows to infinity as tinyobjloader reads it");
        }
    const auto vertexCount = verts.size() / 3;
    const auto vertex = [&](int index) {
        // Checked above; kept so that a tinyobjloader surprise is an error, not a read past.
        if (index < 0 || static_cast<std::size_t>(index) >= vertexCount)
            r.fail(filePath, quoted + " has a face with a vertex index out of range");
        const Vec3 v(verts[3 * index], verts[3 * index + 1], verts[3 * index + 2]);
        return v * xf.scale + xf.translate;
    };
    std::size_t added = 0;
    for (const tinyobj::shape_t& shape : obj.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t f = 0; f + 2 < idx.size(); f += 3) {
            Triangle t{vertex(idx[f].vertex_index), vertex(idx[f + 1].vertex_index),
                       vertex(idx[f + 2].vertex_index), material};
            if (!isFinite(t.a) || !isFinite(t.b) || !isFinite(t.c))
                r.fail(filePath, quoted + ": the scale makes a vertex overflow");
            // Zero-area triangles have no normal and no surface: they are left out (and counted).
            if (glm::length(glm::cross(t.b - t.a, t.c - t.a)) == 0.0) {
                ++scene.droppedDegenerateTriangles;
                continue;
            }
            scene.triangles.push_back(t);
            ++added;
        }
    }
    if (added == 0) r.fail(filePath, quoted + " has no triangles");
}

void readObject(const Reader& r, const json& j, const std::string& path,
                const std::unordered_map<std::string, std::uint32_t>& materialIds,
                const FileResolver& resolver, Scene& scene) {
    r.requireObject(j, path);
    const std::string typePath = JsonLineMap::child(path, "type");
    if (!j.contains("type"))
        r.fail(typePath, "every object needs a type: sphere, triangle or mesh");
    const std::string type = r.string(j["type"], typePath);

    std::uint32_t material = 0;  // the default material
    ifPresent(j, path, "material", [&](const json& v, const std::string& p) {
        const std::string name = r.string(v, p);
        const auto it = materialIds.find(name);
        if (it == materialIds.end())
            r.fail(p, "no material named '" + printable(name) + "' in 'materials'");
        material = it->second;
    });

    if (type == "sphere") {
        r.checkKeys(j, path, {"type", "material", "center", "radius"});
        Sphere s;
        s.material = material;
        ifPresent(j, path, "center",
                  [&](const json& v, const std::string& p) { s.center = r.vec3(v, p); });
        const std::string radiusPath = JsonLineMap::child(path, "radius");
        if (!j.contains("radius")) r.fail(radiusPath, "a sphere needs a radius");
        s.radius = r.positive(j["radius"], radiusPath);
        scene.spheres.push_back(s);
    } else if (type == "triangle") {
        r.checkKeys(j, path, {"type", "material", "vertices"});
        const std::string vp = JsonLineMap::child(path, "vertices");
        if (!j.contains("vertices") || !j["vertices"].is_array() || j["vertices"].size() != 3)
            r.fail(vp, "a triangle needs 3 vertices [[x,y,z], [x,y,z], [x,y,z]]");
        Triangle t{r.vec3(j["vertices"][0], JsonLineMap::element(vp, 0)),
                   r.vec3(j["vertices"][1], JsonLineMap::element(vp, 1)),
                   r.vec3(j["vertices"][2], JsonLineMap::element(vp, 2)), material};
        if (glm::length(glm::cross(t.b - t.a, t.c - t.a)) == 0.0)
            r.fail(vp, "the triangle has zero area (its vertices are on one line)");
        scene.triangles.push_back(t);
    } else if (type == "mesh") {
        r.checkKeys(j, path, {"type", "material", "file", "scale", "translate"});
        readMesh(r, j, path, material, resolver, scene);
    } else {
        r.fail(typePath,
               "unknown object type '" + printable(type) + "' (expected sphere, triangle or mesh)");
    }
}

Scene readScene(std::string_view text, const std::string& fileName, const FileResolver& resolver) {
    auto parsed = detail::parseJsonFile<SceneError>(text, fileName);
    const json& root = parsed.root;
    const Reader r(fileName, std::move(parsed.lines));
    if (!root.is_object()) r.fail("", "a scene file holds one JSON object {...}");
    if (root.contains("dimensions") && root["dimensions"] == 2)
        r.fail("dimensions",
               "a 2D scene (segments and circles): use it with build, trace, dda or the app's "
               "2D view, not render");
    r.checkKeys(root, "",
                {"description", "camera", "background", "ambient", "lights", "materials", "objects",
                 "render"});

    Scene scene;
    scene.name = fileName;
    ifPresent(root, "", "description",
              [&](const json& v, const std::string& p) { scene.description = r.string(v, p); });
    ifPresent(root, "", "camera",
              [&](const json& v, const std::string& p) { readCamera(r, v, p, scene.camera); });
    if (!root.contains("camera")) readCamera(r, json::object(), "camera", scene.camera);
    ifPresent(root, "", "render",
              [&](const json& v, const std::string& p) { readRender(r, v, p, scene.settings); });
    ifPresent(root, "", "background", [&](const json& v, const std::string& p) {
        scene.background = r.color(v, p, false);
    });
    ifPresent(root, "", "ambient",
              [&](const json& v, const std::string& p) { scene.ambient = r.color(v, p, false); });

    ifPresent(root, "", "lights", [&](const json& v, const std::string& p) {
        if (!v.is_array()) r.fail(p, "expected an array of lights, got " + Reader::typeName(v));
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string lp = JsonLineMap::element(p, i);
            const json& l = v[i];
            r.requireObject(l, lp);
            r.checkKeys(l, lp, {"position", "color", "intensity"});
            PointLight light;
            if (!l.contains("position"))
                r.fail(JsonLineMap::child(lp, "position"), "a light needs a position");
            light.position = r.vec3(l["position"], JsonLineMap::child(lp, "position"));
            Color color(1.0);
            double intensity = 1.0;
            ifPresent(l, lp, "color",
                      [&](const json& c, const std::string& cp) { color = r.color(c, cp, false); });
            ifPresent(l, lp, "intensity", [&](const json& c, const std::string& cp) {
                intensity = r.nonNegative(c, cp);
            });
            light.intensity = color * intensity;
            scene.lights.push_back(light);
        }
    });

    scene.materials.push_back(Material{});  // id 0: the default material
    std::unordered_map<std::string, std::uint32_t> materialIds;
    ifPresent(root, "", "materials", [&](const json& v, const std::string& p) {
        if (!v.is_object())
            r.fail(p, "expected an object of named materials, got " + Reader::typeName(v));
        for (const auto& [name, m] : v.items()) {
            materialIds[name] = static_cast<std::uint32_t>(scene.materials.size());
            scene.materials.push_back(readMaterial(r, m, JsonLineMap::child(p, name), name));
        }
    });

    if (!root.contains("objects") || !root["objects"].is_array() || root["objects"].empty())
        r.fail("objects", "the scene is empty: 'objects' must list at least one object");
    const json& objects = root["objects"];
    // The intersection kernels are exact within a range of magnitudes (kernels.h): what reaches
    // past it is refused by name, rather than rendered with silent misses.
    const double largest = kernelRange(Precision::Double).largest;
    double scale =
        std::max(maxAbsComponent(scene.camera.eye), maxAbsComponent(scene.camera.lookAt));
    if (const auto problem = kernelRangeProblem(Precision::Double, scale);
        problem && scale > largest)
        r.fail(root.contains("camera") ? "camera" : "", *problem);
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const double m = maxAbsComponent(scene.lights[i].position);
        if (const auto problem = kernelRangeProblem(Precision::Double, m); problem && m > largest)
            r.fail(JsonLineMap::child(JsonLineMap::element("lights", i), "position"), *problem);
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const std::string path = JsonLineMap::element("objects", i);
        const std::size_t spheres = scene.spheres.size(), triangles = scene.triangles.size();
        readObject(r, objects[i], path, materialIds, resolver, scene);
        if (scene.triangles.size() > kMaxObjTriangles)
            r.fail(path, "the scene has more than " + std::to_string(kMaxObjTriangles) +
                             " triangles, the most raystep loads");
        // The object's reach and its smallest part (radius, longest edge of a triangle).
        double m = 0.0, size = std::numeric_limits<double>::infinity();
        for (std::size_t k = spheres; k < scene.spheres.size(); ++k) {
            m = std::max(m, maxAbsComponent(scene.spheres[k].center) + scene.spheres[k].radius);
            size = std::min(size, scene.spheres[k].radius);
        }
        for (std::size_t k = triangles; k < scene.triangles.size(); ++k) {
            const Triangle& t = scene.triangles[k];
            m = std::max({m, maxAbsComponent(t.a), maxAbsComponent(t.b), maxAbsComponent(t.c)});
            const double edge = std::max({maxAbsComponent(t.b - t.a), maxAbsComponent(t.c - t.b),
                                          maxAbsComponent(t.a - t.c)});
            if (edge > 0.0) size = std::min(size, edge);  // a degenerate one is never hit
        }
        if (const auto problem =
                primitiveRangeProblem(Precision::Double, m, std::isinf(size) ? 0.0 : size))
            r.fail(path, *problem);
        scale = std::max(scale, m);
    }
    // A scene too small as a whole: its objects pass their own check only just, near the origin.
    if (const auto problem = kernelRangeProblem(Precision::Double, scale))
        r.fail("objects", *problem);
    return scene;
}

Vec2 readVec2(const Reader& r, const json& j, const std::string& path) {
    if (!j.is_array() || j.size() != 2)
        r.fail(path, "expected an array of 2 numbers [x, y], got " + Reader::typeName(j));
    return Vec2(r.number(j[0], JsonLineMap::element(path, 0)),
                r.number(j[1], JsonLineMap::element(path, 1)));
}

double maxAbs2(const Vec2& v) {
    return std::max(std::abs(v.x), std::abs(v.y));
}

Scene2D readScene2D(std::string_view text, const std::string& fileName) {
    auto parsed = detail::parseJsonFile<SceneError>(text, fileName);
    const json& root = parsed.root;
    const Reader r(fileName, std::move(parsed.lines));
    r.requireObject(root, "");
    r.checkKeys(root, "", {"dimensions", "description", "grid", "ray", "circles", "segments"});
    if (!root.contains("dimensions") || root["dimensions"] != 2)
        r.fail("dimensions", "a 2D scene says \"dimensions\": 2");
    Scene2D scene;
    scene.name = fileName;
    ifPresent(root, "", "description",
              [&](const json& v, const std::string& p) { scene.description = r.string(v, p); });
    ifPresent(root, "", "grid", [&](const json& v, const std::string& p) {
        if (!v.is_array() || v.size() != 2) r.fail(p, "expected [NX, NY]");
        scene.gridRes = IVecN<2>(r.integer(v[0], JsonLineMap::element(p, 0), 1, 512),
                                 r.integer(v[1], JsonLineMap::element(p, 1), 1, 512));
    });
    ifPresent(root, "", "ray", [&](const json& v, const std::string& p) {
        r.requireObject(v, p);
        r.checkKeys(v, p, {"origin", "dir"});
        Ray2 ray;
        if (!v.contains("origin") || !v.contains("dir"))
            r.fail(p, "a ray needs an origin and a dir");
        ray.origin = readVec2(r, v["origin"], JsonLineMap::child(p, "origin"));
        ray.dir = readVec2(r, v["dir"], JsonLineMap::child(p, "dir"));
        if (ray.dir == Vec2(0.0)) r.fail(JsonLineMap::child(p, "dir"), "must not be zero");
        if (const auto problem =
                rayRangeProblem(Precision::Double, maxAbs2(ray.origin), maxAbs2(ray.dir)))
            r.fail(p, *problem);
        scene.exampleRay = ray;
    });
    ifPresent(root, "", "circles", [&](const json& v, const std::string& p) {
        if (!v.is_array()) r.fail(p, "expected an array of circles");
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string cp = JsonLineMap::element(p, i);
            r.requireObject(v[i], cp);
            r.checkKeys(v[i], cp, {"center", "radius"});
            if (!v[i].contains("center") || !v[i].contains("radius"))
                r.fail(cp, "a circle needs a center and a radius");
            const Circle2 c{readVec2(r, v[i]["center"], JsonLineMap::child(cp, "center")),
                            r.positive(v[i]["radius"], JsonLineMap::child(cp, "radius"))};
            if (const auto problem = primitiveRangeProblem(Precision::Double,
                                                           maxAbs2(c.center) + c.radius, c.radius))
                r.fail(cp, *problem);
            scene.circles.push_back(c);
        }
    });
    ifPresent(root, "", "segments", [&](const json& v, const std::string& p) {
        if (!v.is_array()) r.fail(p, "expected an array of segments");
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string sp = JsonLineMap::element(p, i);
            r.requireObject(v[i], sp);
            r.checkKeys(v[i], sp, {"from", "to"});
            if (!v[i].contains("from") || !v[i].contains("to"))
                r.fail(sp, "a segment needs from and to");
            const Segment2 seg{readVec2(r, v[i]["from"], JsonLineMap::child(sp, "from")),
                               readVec2(r, v[i]["to"], JsonLineMap::child(sp, "to"))};
            if (seg.a == seg.b) r.fail(JsonLineMap::child(sp, "to"), "the segment has no length");
            if (const auto problem = primitiveRangeProblem(Precision::Double,
                                                           std::max(maxAbs2(seg.a), maxAbs2(seg.b)),
                                                           maxAbs2(seg.b - seg.a)))
                r.fail(sp, *problem);
            scene.segments.push_back(seg);
        }
    });
    if (scene.primitiveCount() == 0)
        r.fail("segments", "the scene is empty: give at least one circle or segment");
    return scene;
}

/// A scene file's text; the message for a missing one lists the built-in scenes when `orBuiltin`
/// (the name could have been either).
std::string readSceneFile(const std::string& path, bool orBuiltin) {
    try {
        return detail::readRegularFile(path, detail::kMaxJsonFileBytes);
    } catch (const detail::ReadFailure& f) {
        if (f.missing() && orBuiltin) {
            std::string names;
            for (const auto& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
            for (const auto& n : builtinScene2DNames()) names += ", " + n + " (2D)";
            throw SceneError(
                path, 0, "",
                "no such scene file, and no built-in scene of that name (built-in: " + names + ")");
        }
        throw SceneError(path, 0, "", std::string("cannot read the scene file: ") + f.what());
    }
}

/// Meshes beside the scene file; a file that is there but cannot be read throws ReadFailure.
FileResolver filesBeside(const std::string& scenePath) {
    const std::filesystem::path folder = std::filesystem::path(scenePath).parent_path();
    return [folder](const std::string& rel) -> std::optional<std::string> {
        try {
            return detail::readRegularFile((folder / rel).string(), detail::kMaxObjFileBytes);
        } catch (const detail::ReadFailure& f) {
            if (f.missing()) return std::nullopt;
            throw;
        }
    };
}

}  // namespace

Scene loadSceneText(std::string_view text, const std::string& fileName,
                    const FileResolver& resolver) {
    return detail::guarded<SceneError>(fileName,
                                       [&] { return readScene(text, fileName, resolver); });
}

bool isScene2DText(std::string_view text) {
    // Nesting past the cap is not looked at (the 3D loader then names the problem).
    if (JsonLineMap::tooDeepLine(text)) return false;
    try {
        const json root = json::parse(text.begin(), text.end(), nullptr, true, true);
        return root.is_object() && root.contains("dimensions") && root["dimensions"] == 2;
    } catch (const json::exception&) {
        return false;
    }
}

Scene2D loadScene2DText(std::string_view text, const std::string& fileName) {
    return detail::guarded<SceneError>(fileName, [&] { return readScene2D(text, fileName); });
}

Scene loadSceneFile(const std::string& path) {
    return loadSceneText(readSceneFile(path, false), path, filesBeside(path));
}

namespace {
std::vector<std::string> builtinNames(bool twoD) {
    std::vector<std::string> names;
    for (const std::string& f : embeddedFileNames())
        if (f.find('/') == std::string::npos && f.ends_with(".json") &&
            isScene2DText(*embeddedFile(f)) == twoD)
            names.push_back(f.substr(0, f.size() - 5));
    return names;
}
}  // namespace

std::vector<std::string> builtinSceneNames() {
    return builtinNames(false);
}
std::vector<std::string> builtinScene2DNames() {
    return builtinNames(true);
}

Scene loadBuiltinScene(const std::string& name) {
    const auto text = embeddedFile(name + ".json");
    if (!text) throw SceneError(name, 0, "", "no built-in scene of that name");
    Scene scene = loadSceneText(*text, "scenes/" + name + ".json", [](const std::string& rel) {
        const auto data = embeddedFile(rel);
        return data ? std::optional<std::string>(std::string(*data)) : std::nullopt;
    });
    scene.name = name;
    return scene;
}

std::string_view sceneOrModelTypes() {
    return "(.json, .obj, .ply, .stl, .gltf, .glb)";
}

std::optional<std::string> unreadableTypeProblem(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    // No extension: a scene file named without one (or a built-in scene's name) is read as JSON.
    if (ext.empty() || ext == ".json") return std::nullopt;
    for (const char* model : {".obj", ".ply", ".stl", ".gltf", ".glb"})
        if (ext == model)
            return std::string(
                "a model file: render, build, trace and compare read models, and the app; a "
                "lesson's or a command's scene here is a scene file (.json)");
    return "not a scene or model raystep reads " + std::string(sceneOrModelTypes());
}

namespace {
/// A scene path whose extension says it is no scene file: refused by its type, not as bad JSON.
void requireSceneType(const std::string& path) {
    if (auto problem = unreadableTypeProblem(path)) throw SceneError(path, 0, "", *problem);
}
}  // namespace

std::variant<Scene, Scene2D> loadAnyScene(const std::string& nameOrPath) {
    if (const auto text = embeddedFile(nameOrPath + ".json")) {
        if (!isScene2DText(*text)) return loadBuiltinScene(nameOrPath);
        Scene2D s = loadScene2DText(*text, "scenes/" + nameOrPath + ".json");
        s.name = nameOrPath;
        return s;
    }
    requireSceneType(nameOrPath);
    const std::string text = readSceneFile(nameOrPath, true);
    if (isScene2DText(text)) return loadScene2DText(text, nameOrPath);
    return loadSceneText(text, nameOrPath, filesBeside(nameOrPath));
}

Scene loadScene(const std::string& nameOrPath) {
    if (embeddedFile(nameOrPath + ".json")) return loadBuiltinScene(nameOrPath);
    requireSceneType(nameOrPath);
    return loadSceneText(readSceneFile(nameOrPath, true), nameOrPath, filesBeside(nameOrPath));
}

}  // namespace raystep
