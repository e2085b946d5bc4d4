#include "raystep/scene_loader.h"

#include "json_reader.h"
#include "raystep/json_lines.h"
#include "raystep/resources.h"

#include <tiny_obj_loader.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace raystep {

using detail::ifPresent;
using detail::joinNames;
using detail::readWholeFile;
using nlohmann::json;
using Reader = detail::JsonReader<SceneError>;

namespace {

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
    const Vec3 forward = cam.lookAt - cam.eye;
    const double scale = std::max(maxAbsComponent(cam.eye), maxAbsComponent(cam.lookAt));
    if (!(glm::length(forward) > 1e-12 * scale) || !isFinite(glm::normalize(forward)))
        r.fail(JsonLineMap::child(path, "look_at"),
               "the camera has no direction: look_at equals eye");
    const Vec3 side = glm::cross(glm::normalize(forward), cam.up);
    if (!(glm::length(side) > 1e-9 * glm::length(cam.up)))
        r.fail(JsonLineMap::child(path, "up"),
               "up must not be zero nor parallel to the view direction");
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
    ifPresent(j, path, "bounces",
              [&](const json& v, const std::string& p) { s.bounces = r.integer(v, p, 0, 64); });
    ifPresent(j, path, "spp",
              [&](const json& v, const std::string& p) { s.spp = r.integer(v, p, 1, 4096); });
    ifPresent(j, path, "diffuse_samples", [&](const json& v, const std::string& p) {
        s.diffuseSamples = r.integer(v, p, 0, 1024);
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

/// tinyobjloader reads "nan", "inf", "1e999" or "abc" in a vertex without complaint (as 0 or
/// infinity): find the first such coordinate, with its line, before handing the text over.
std::optional<std::pair<int, std::string>> findBadObjVertex(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
        std::istringstream fields(line.substr(2));
        std::string token;
        for (int k = 0; k < 3 && fields >> token; ++k) {
            char* end = nullptr;
            const double v = std::strtod(token.c_str(), &end);
            if (end != token.c_str() + token.size() || !std::isfinite(v))
                return std::make_pair(lineNo, token);
        }
    }
    return std::nullopt;
}

void readMesh(const Reader& r, const json& j, const std::string& path, std::uint32_t material,
              const FileResolver& resolver, Scene& scene) {
    const std::string filePath = JsonLineMap::child(path, "file");
    if (!j.contains("file")) r.fail(filePath, "a mesh needs the OBJ file to load");
    const std::string file = r.string(j["file"], filePath);
    MeshTransform xf;
    ifPresent(j, path, "scale", [&](const json& v, const std::string& p) {
        xf.scale = v.is_number() ? Vec3(r.number(v, p)) : r.vec3(v, p);
        if (xf.scale.x == 0.0 || xf.scale.y == 0.0 || xf.scale.z == 0.0)
            r.fail(p, "scale must not be zero (the mesh would be flat)");
    });
    ifPresent(j, path, "translate",
              [&](const json& v, const std::string& p) { xf.translate = r.vec3(v, p); });

    const std::optional<std::string> text = resolver(file);
    if (!text) r.fail(filePath, "cannot open OBJ file '" + file + "'");
    if (auto bad = findBadObjVertex(*text))
        r.fail(filePath, "OBJ file '" + file + "' line " + std::to_string(bad->first) +
                             ": vertex coordinate '" + bad->second + "' is not a finite number");
    tinyobj::ObjReader obj;
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    if (!obj.ParseFromString(*text, "", config)) {
        std::string err = obj.Error();
        while (!err.empty() && err.back() == '\n') err.pop_back();
        r.fail(filePath, "cannot read OBJ file '" + file + "': " + err);
    }
    const auto& verts = obj.GetAttrib().vertices;
    const auto vertexCount = static_cast<int>(verts.size() / 3);
    const auto vertex = [&](int index) {
        // tinyobjloader only warns about indices past the end; they must not be read.
        if (index < 0 || index >= vertexCount)
            r.fail(filePath, "OBJ file '" + file + "' has a face with a vertex index out of range");
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
                r.fail(filePath, "OBJ file '" + file + "': the scale makes a vertex overflow");
            // Zero-area triangles have no normal and no surface: they are left out (and counted).
            if (glm::length(glm::cross(t.b - t.a, t.c - t.a)) == 0.0) {
                ++scene.droppedDegenerateTriangles;
                continue;
            }
            scene.triangles.push_back(t);
            ++added;
        }
    }
    if (added == 0) r.fail(filePath, "OBJ file '" + file + "' has no triangles");
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
        if (it == materialIds.end()) r.fail(p, "no material named '" + name + "' in 'materials'");
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
        r.fail(typePath, "unknown object type '" + type + "' (expected sphere, triangle or mesh)");
    }
}

}  // namespace

Scene loadSceneText(std::string_view text, const std::string& fileName,
                    const FileResolver& resolver) {
    const json root = detail::parseJsonFile<SceneError>(text, fileName);
    const Reader r(fileName, text);
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
    for (std::size_t i = 0; i < objects.size(); ++i)
        readObject(r, objects[i], JsonLineMap::element("objects", i), materialIds, resolver, scene);
    return scene;
}

namespace {
Vec2 readVec2(const Reader& r, const json& j, const std::string& path) {
    if (!j.is_array() || j.size() != 2)
        r.fail(path, "expected an array of 2 numbers [x, y], got " + Reader::typeName(j));
    return Vec2(r.number(j[0], JsonLineMap::element(path, 0)),
                r.number(j[1], JsonLineMap::element(path, 1)));
}
}  // namespace

bool isScene2DText(std::string_view text) {
    try {
        const json root = json::parse(text.begin(), text.end(), nullptr, true, true);
        return root.is_object() && root.contains("dimensions") && root["dimensions"] == 2;
    } catch (const json::exception&) {
        return false;
    }
}

Scene2D loadScene2DText(std::string_view text, const std::string& fileName) {
    const json root = detail::parseJsonFile<SceneError>(text, fileName);
    const Reader r(fileName, text);
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
            scene.circles.push_back({readVec2(r, v[i]["center"], JsonLineMap::child(cp, "center")),
                                     r.positive(v[i]["radius"], JsonLineMap::child(cp, "radius"))});
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
            scene.segments.push_back(seg);
        }
    });
    if (scene.primitiveCount() == 0)
        r.fail("segments", "the scene is empty: give at least one circle or segment");
    return scene;
}

Scene loadSceneFile(const std::string& path) {
    const auto text = readWholeFile(path);
    if (!text) throw SceneError(path, 0, "", "cannot open the scene file");
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    return loadSceneText(*text, path,
                         [folder](const std::string& rel) { return readWholeFile(folder / rel); });
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

std::variant<Scene, Scene2D> loadAnyScene(const std::string& nameOrPath) {
    if (const auto text = embeddedFile(nameOrPath + ".json")) {
        if (!isScene2DText(*text)) return loadBuiltinScene(nameOrPath);
        Scene2D s = loadScene2DText(*text, "scenes/" + nameOrPath + ".json");
        s.name = nameOrPath;
        return s;
    }
    if (std::filesystem::exists(nameOrPath)) {
        const auto text = readWholeFile(nameOrPath);
        if (text && isScene2DText(*text)) return loadScene2DText(*text, nameOrPath);
    }
    return loadScene(nameOrPath);
}

Scene loadScene(const std::string& nameOrPath) {
    if (embeddedFile(nameOrPath + ".json")) return loadBuiltinScene(nameOrPath);
    if (!std::filesystem::exists(nameOrPath)) {
        std::string names;
        for (const auto& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
        for (const auto& n : builtinScene2DNames()) names += ", " + n + " (2D)";
        throw SceneError(
            nameOrPath, 0, "",
            "no such scene file, and no built-in scene of that name (built-in: " + names + ")");
    }
    return loadSceneFile(nameOrPath);
}

}  // namespace raystep
