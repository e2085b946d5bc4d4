#include "raystep/scene/model_import.h"

#include "raystep/base/json_reader.h"
#include "raystep/geometry/kernels.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace raystep {

namespace {

// Same caps as a scene's OBJ mesh (scene_loader.cpp): a model is a mesh by another name.
constexpr std::size_t kMaxModelBytes = detail::kMaxObjFileBytes;
constexpr std::uint64_t kMaxModelTriangles = 10'000'000;

/// A file's bytes held in memory, as assimp reads them.
class StringStream : public Assimp::IOStream {
  public:
    explicit StringStream(std::string bytes) : bytes_(std::move(bytes)) {}
    size_t Read(void* buffer, size_t size, size_t count) override {
        if (size == 0) return 0;
        const size_t n = std::min(count, (bytes_.size() - pos_) / size);
        std::memcpy(buffer, bytes_.data() + pos_, n * size);
        pos_ += n * size;
        return n;
    }
    size_t Write(const void*, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        size_t to = 0;
        if (origin == aiOrigin_SET) {
            to = offset;
        } else if (origin == aiOrigin_CUR) {
            to = pos_ + offset;
        } else {
            if (offset > bytes_.size()) return aiReturn_FAILURE;
            to = bytes_.size() - offset;
        }
        if (to > bytes_.size()) return aiReturn_FAILURE;
        pos_ = to;
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return pos_; }
    size_t FileSize() const override { return bytes_.size(); }
    void Flush() override {}

  private:
    std::string bytes_;
    size_t pos_ = 0;
};

/// A PLY header's element counts must fit what follows it (ASCII: one value a property, a list
/// at least its count; binary: the types' sizes). Assimp reserves memory for what a header
/// declares and looks for every element: 200 bytes declaring 3 million vertices took 0.5 s and
/// 48 MB, then an assert aborted (300 million: 50 s and 3.5 GB); 100,000 vertices declared over
/// 700 KB of blanks took 22 s. The problem in words, or nullopt.
std::optional<std::string> plyHeaderProblem(std::string_view bytes) {
    const std::size_t end = bytes.find("end_header");
    if (bytes.substr(0, 3) != "ply" || end == std::string_view::npos) return std::nullopt;
    const std::size_t body = bytes.find('\n', end);
    const std::uint64_t bodyBytes = body == std::string_view::npos ? 0 : bytes.size() - body - 1;
    const auto typeSize = [](std::string_view t) -> std::uint64_t {
        if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
        if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
        if (t == "double" || t == "float64") return 8;
        return 4;
    };
    bool ascii = true;
    struct Element {
        std::string name;
        std::uint64_t count = 0, minBytes = 0;
    };
    std::vector<Element> elements;
    std::size_t pos = 0;
    while (pos < end) {
        std::size_t eol = bytes.find('\n', pos);
        if (eol == std::string_view::npos || eol > end) eol = end;
        std::vector<std::string_view> words;
        for (std::size_t i = pos; i < eol;) {
            while (i < eol && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r')) ++i;
            const std::size_t from = i;
            while (i < eol && bytes[i] != ' ' && bytes[i] != '\t' && bytes[i] != '\r') ++i;
            if (i > from) words.push_back(bytes.substr(from, i - from));
        }
        pos = eol + 1;
        if (words.size() >= 2 && words[0] == "format") ascii = words[1] == "ascii";
        if (words.size() >= 3 && words[0] == "element") {
            Element e{std::string(words[1]), 0, 0};
            const auto [p, ec] =
                std::from_chars(words[2].data(), words[2].data() + words[2].size(), e.count);
            if (ec != std::errc()) e.count = std::numeric_limits<std::uint64_t>::max();
            elements.push_back(e);
        }
        if (words.size() >= 3 && words[0] == "property" && !elements.empty())
            // ASCII: one value; binary: the type's size (a list: its count's).
            elements.back().minBytes +=
                ascii ? 1 : typeSize(words[1] == "list" && words.size() >= 4 ? words[2] : words[1]);
    }
    // ASCII: the values (blank-separated words) after the header; binary: its bytes.
    std::uint64_t available = bodyBytes;
    if (ascii) {
        available = 0;
        bool inWord = false;
        for (std::size_t i = bytes.size() - bodyBytes; i < bytes.size(); ++i) {
            const bool blank = std::isspace(static_cast<unsigned char>(bytes[i])) != 0;
            available += !blank && !inWord;
            inWord = !blank;
        }
    }
    std::uint64_t needed = 0;
    for (const Element& e : elements) {
        const std::uint64_t each = std::max<std::uint64_t>(e.minBytes, 1);
        if (e.count > (available - std::min(needed, available)) / each)
            return "the PLY header declares " + std::to_string(e.count) + " '" +
                   printable(e.name, 24) + "' elements, more than the " +
                   std::to_string(available) + (ascii ? " values" : " bytes") +
                   " after it can hold";
        needed += e.count * each;
    }
    return std::nullopt;
}

/// Every file assimp opens (the model, a glTF's .bin, an OBJ's .mtl) goes through the core's
/// checked reader: a FIFO or device is refused before it is opened (no hang), size is capped,
/// nothing is written. The first refusal is kept, to name that file in the error.
class CheckedIOSystem : public Assimp::IOSystem {
  public:
    bool Exists(const char* file) const override {
        struct stat st {};
        return ::stat(file, &st) == 0;
    }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+'))
            return nullptr;
        try {
            std::string bytes = detail::readRegularFile(file, kMaxModelBytes);
            if (const auto problem = plyHeaderProblem(bytes)) {
                if (!failure) failure = {file, *problem};
                return nullptr;
            }
            return new StringStream(std::move(bytes));
        } catch (const detail::ReadFailure& f) {
            if (!failure) failure = {file, f.what()};
            return nullptr;
        }
    }
    void Close(Assimp::IOStream* stream) override { delete stream; }

    std::optional<std::pair<std::string, std::string>> failure;  // the file, why
};

bool hasSuffix(std::string_view s, std::string_view suffix) {
    if (s.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i])
            return false;
    return true;
}

std::string meshName(const aiMesh& mesh, unsigned index) {
    std::string s = "mesh " + std::to_string(index);
    if (mesh.mName.length > 0) s += " '" + printable(mesh.mName.C_Str(), 40) + "'";
    return s;
}

[[noreturn]] void failModel(const std::string& path, const std::string& message) {
    throw SceneError(path, 0, "", message);
}

Vec3 transformed(const aiMatrix4x4& m, const aiVector3D& v) {
    // In double: a float product could overflow where the double one does not.
    const auto row = [&](int r) {
        return double(m[r][0]) * v.x + double(m[r][1]) * v.y + double(m[r][2]) * v.z +
               double(m[r][3]);
    };
    return Vec3(row(0), row(1), row(2));
}

}  // namespace
}  // namespace raystep

// Debian's assimp is built with its internal checks on (ASSIMP_BUILD_DEBUG): a failed one called
// abort() (a 200-byte PLY file stopped the program). This definition takes the place of
// libassimp's own (the program's symbols come first), and makes it an exception, which
// Importer::ReadFile turns into an import error that importModel reports in one line.
namespace Assimp {
void aiAssertViolation(const char* failedExpression, const char* file, int line) {
    const char* base = std::strrchr(file, '/');
    throw std::runtime_error(std::string("assimp's check failed: ") + failedExpression + " (" +
                             (base ? base + 1 : file) + ":" + std::to_string(line) + ")");
}
}  // namespace Assimp

namespace raystep {

const std::vector<std::string>& modelExtensions() {
    static const std::vector<std::string> extensions{".obj", ".ply", ".stl", ".gltf", ".glb"};
    return extensions;
}

bool isModelPath(std::string_view path) {
    return std::any_of(modelExtensions().begin(), modelExtensions().end(),
                       [&](const std::string& e) { return hasSuffix(path, e); });
}

ImportedModel importModel(const std::string& path) {
    const auto fail = [&](const std::string& message) { failModel(path, message); };
    if (!isModelPath(path)) fail("not a model file (expected .obj, .ply, .stl, .gltf or .glb)");
    // The model itself: refused here by name before assimp looks (a FIFO would block its open).
    struct stat st {};
    try {
        if (::stat(path.c_str(), &st) != 0) detail::throwReadFailure(errno);
        detail::requireRegular(st, kMaxModelBytes);
    } catch (const detail::ReadFailure& f) {
        fail(std::string("cannot read the model: ") + f.what());
    }
    if (st.st_size == 0) fail("the model file is empty");

    Assimp::Importer importer;  // no DefaultLogger is created: assimp's NullLogger stays quiet
    auto* io = new CheckedIOSystem;
    importer.SetIOHandler(io);  // the importer owns it
    const aiScene* ai = nullptr;
    try {
        ai = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
    } catch (const std::exception& e) {
        fail(std::string("cannot import the model: ") + e.what());
    }
    // A file assimp could not open (the model changed under us, a glTF buffer that is a FIFO).
    if (!ai && io->failure)
        fail(io->failure->first == path
                 ? io->failure->second
                 : "cannot read '" + printable(io->failure->first) + "': " + io->failure->second);
    if (!ai) {
        std::string why = importer.GetErrorString();
        while (!why.empty() && (why.back() == '\n' || why.back() == '.')) why.pop_back();
        fail("cannot import the model: " + (why.empty() ? std::string("unknown error") : why));
    }
    if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) fail("the model is incomplete (no geometry)");

    ImportedModel model;
    // The node tree, walked without recursion; every instance of a mesh with its transform.
    std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack;
    if (ai->mRootNode) stack.emplace_back(ai->mRootNode, ai->mRootNode->mTransformation);
    std::uint64_t nodes = 0;
    while (!stack.empty()) {
        const auto [node, xf] = stack.back();
        stack.pop_back();
        if (++nodes > 1'000'000) fail("more than a million nodes in the model's node tree");
        for (unsigned c = 0; c < node->mNumChildren; ++c)
            if (node->mChildren[c])
                stack.emplace_back(node->mChildren[c], xf * node->mChildren[c]->mTransformation);
        for (unsigned k = 0; k < node->mNumMeshes; ++k) {
            const unsigned mi = node->mMeshes[k];
            if (mi >= ai->mNumMeshes || !ai->mMeshes[mi]) fail("a node refers to a missing mesh");
            const aiMesh& mesh = *ai->mMeshes[mi];
            for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
                const aiVector3D& p = mesh.mVertices[v];
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                    fail(meshName(mesh, mi) + ", vertex " + std::to_string(v) +
                         ": a coordinate is not a finite number");
            }
            for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
                const aiFace& face = mesh.mFaces[f];
                if (face.mNumIndices != 3) continue;  // points and lines: no surface
                std::array<Vec3, 3> p;
                for (int i = 0; i < 3; ++i) {
                    const unsigned index = face.mIndices[i];
                    if (index >= mesh.mNumVertices)
                        fail(meshName(mesh, mi) + ", face " + std::to_string(f) +
                             ": vertex index " + std::to_string(index) + " is out of range (" +
                             std::to_string(mesh.mNumVertices) + " vertices)");
                    p[i] = transformed(xf, mesh.mVertices[index]);
                    if (!isFinite(p[i]))
                        fail(meshName(mesh, mi) + ", face " + std::to_string(f) +
                             ": the node's transform makes a vertex overflow");
                }
                const Triangle t{p[0], p[1], p[2], 0};
                if (glm::length(glm::cross(t.b - t.a, t.c - t.a)) == 0.0) {
                    ++model.droppedDegenerateTriangles;
                    continue;
                }
                if (model.triangles.size() >= kMaxModelTriangles)
                    fail("more than " + std::to_string(kMaxModelTriangles) +
                         " triangles, the most raystep reads from one model");
                model.triangles.push_back(t);
                for (const Vec3& q : p) model.bounds.extend(q);
            }
        }
    }
    if (model.triangles.empty())
        fail(model.droppedDegenerateTriangles > 0
                 ? "the model has no triangles of non-zero area (" +
                       std::to_string(model.droppedDegenerateTriangles) + " degenerate ones)"
                 : std::string("the model has no triangles"));
    // The kernels' range (kernels.h), as the scene loader checks a mesh.
    double reach = 0.0, size = std::numeric_limits<double>::infinity();
    for (const Triangle& t : model.triangles) {
        reach = std::max({reach, maxAbsComponent(t.a), maxAbsComponent(t.b), maxAbsComponent(t.c)});
        size = std::min(size, std::max({maxAbsComponent(t.b - t.a), maxAbsComponent(t.c - t.b),
                                        maxAbsComponent(t.a - t.c)}));
    }
    if (const auto problem = primitiveRangeProblem(Precision::Double, reach, size)) fail(*problem);
    if (const auto problem = kernelRangeProblem(Precision::Double, reach)) fail(*problem);
    return model;
}

Scene sceneAroundModel(const ImportedModel& model, const std::string& name) {
    Scene scene;
    scene.name = name;
    scene.description = "Model " + name + ": " + std::to_string(model.triangles.size()) +
                        " triangles on a floor, two lights";
    scene.background = Color(0.06, 0.08, 0.14);
    scene.ambient = Color(0.06);
    const Vec3 centre = model.bounds.centroid();
    const double radius = 0.5 * glm::length(model.bounds.diagonal());

    // A three-quarter view: 35 degrees round from the front (+z), 20 degrees above, as near as
    // the eight corners of the bounds stay inside 90% of the field of view (both ways), and
    // outside the bounding sphere.
    scene.camera.fovDeg = 40.0;
    const double az = 35.0 * kPi / 180.0, el = 20.0 * kPi / 180.0;
    const Vec3 dir(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
    const Vec3 right = glm::normalize(glm::cross(-dir, Vec3(0, 1, 0)));
    const Vec3 up = glm::cross(right, -dir);
    const double tanY = 0.9 * std::tan(0.5 * scene.camera.fovDeg * kPi / 180.0);
    const double tanX = tanY * scene.settings.width / scene.settings.height;
    const auto fits = [&](double distance) {
        const Vec3 eye = centre + distance * dir;
        for (int c = 0; c < 8; ++c) {
            const Vec3 p((c & 1) ? model.bounds.hi.x : model.bounds.lo.x,
                         (c & 2) ? model.bounds.hi.y : model.bounds.lo.y,
                         (c & 4) ? model.bounds.hi.z : model.bounds.lo.z);
            const Vec3 v = p - eye;
            const double z = -glm::dot(v, dir);
            if (!(z > 0) || std::abs(glm::dot(v, right)) > tanX * z ||
                std::abs(glm::dot(v, up)) > tanY * z)
                return false;
        }
        return true;
    };
    double near = 1.05 * radius, far = 1.1 * radius / std::sin(std::atan(tanY));
    if (fits(near)) far = near;
    for (int i = 0; i < 50 && far - near > 1e-6 * far; ++i) {
        const double mid = 0.5 * (near + far);
        (fits(mid) ? far : near) = mid;
    }
    scene.camera.eye = centre + far * dir;
    scene.camera.lookAt = centre;
    scene.camera.up = Vec3(0, 1, 0);

    scene.lights.push_back({centre + radius * Vec3(2.5, 4.0, 3.0), Color(1.0, 0.97, 0.9) * 0.9});
    scene.lights.push_back({centre + radius * Vec3(-3.5, 2.0, 1.5), Color(0.8, 0.85, 1.0) * 0.4});

    scene.materials.push_back(Material{});  // id 0: the model's, the default material
    Material floor;
    floor.name = "floor";
    floor.kd = Color(0.75);
    floor.checker.enabled = true;
    floor.checker.color = Color(0.12);
    floor.checker.size = radius * 0.5;
    scene.materials.push_back(floor);

    scene.triangles = model.triangles;
    // Just under the model (a face lying on its lowest plane must not meet the floor's).
    const double y = model.bounds.lo.y - 1e-3 * radius, half = 6.0 * radius;
    const Vec3 a(centre.x - half, y, centre.z - half), b(centre.x - half, y, centre.z + half),
        c(centre.x + half, y, centre.z + half), d(centre.x + half, y, centre.z - half);
    scene.triangles.push_back({a, b, c, 1});
    scene.triangles.push_back({a, c, d, 1});
    scene.droppedDegenerateTriangles = model.droppedDegenerateTriangles;
    return scene;
}

Scene importModelScene(const std::string& path) {
    return sceneAroundModel(importModel(path), path);
}

namespace {
std::string number(double v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);  // shortest that reads back
    return std::string(buf, ec == std::errc() ? end : buf);
}
nlohmann::ordered_json vec(const Vec3& v) {
    return nlohmann::ordered_json::array({v.x, v.y, v.z});
}
}  // namespace

SceneFiles sceneFilesFor(const Scene& scene, std::size_t meshTriangles,
                         const std::string& meshFile) {
    using J = nlohmann::ordered_json;
    SceneFiles out;
    J j;
    if (!scene.description.empty()) j["description"] = scene.description;
    j["camera"] = {{"eye", vec(scene.camera.eye)},
                   {"look_at", vec(scene.camera.lookAt)},
                   {"up", vec(scene.camera.up)},
                   {"fov", scene.camera.fovDeg}};
    j["render"] = {{"width", scene.settings.width},
                   {"height", scene.settings.height},
                   {"bounces", scene.settings.bounces},
                   {"spp", scene.settings.spp},
                   {"diffuse_samples", scene.settings.diffuseSamples}};
    j["background"] = vec(scene.background);
    j["ambient"] = vec(scene.ambient);
    j["lights"] = J::array();
    for (const PointLight& l : scene.lights)
        j["lights"].push_back({{"position", vec(l.position)}, {"color", vec(l.intensity)}});
    j["materials"] = J::object();
    for (std::size_t i = 1; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        J jm = {{"kd", vec(m.kd)},
                {"ks", vec(m.ks)},
                {"n", m.n},
                {"reflect", vec(m.reflect)},
                {"transparency", vec(m.transparency)},
                {"ior", m.ior}};
        if (m.checker.enabled)
            jm["checker"] = {{"color", vec(m.checker.color)}, {"size", m.checker.size}};
        j["materials"][m.name] = jm;
    }
    const auto material = [&](J& o, std::uint32_t id) {
        if (id != 0) o["material"] = scene.materials[id].name;
    };
    j["objects"] = J::array();
    meshTriangles = std::min(meshTriangles, scene.triangles.size());
    if (meshTriangles > 0) {
        J o = {{"type", "mesh"}, {"file", meshFile}};
        material(o, scene.triangles[0].material);
        j["objects"].push_back(o);
    }
    for (const Sphere& s : scene.spheres) {
        J o = {{"type", "sphere"}, {"center", vec(s.center)}, {"radius", s.radius}};
        material(o, s.material);
        j["objects"].push_back(o);
    }
    for (std::size_t i = meshTriangles; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        J o = {{"type", "triangle"}, {"vertices", J::array({vec(t.a), vec(t.b), vec(t.c)})}};
        material(o, t.material);
        j["objects"].push_back(o);
    }
    // One key a line, and one light, material or object a line: readable, and diffable.
    std::string text = "{\n";
    bool first = true;
    for (const auto& [key, value] : j.items()) {
        text += std::string(first ? "" : ",\n") + "  " + J(key).dump() + ": ";
        first = false;
        if (value.is_array() && !value.empty() && value[0].is_object()) {
            text += "[\n";
            for (std::size_t i = 0; i < value.size(); ++i)
                text += "    " + value[i].dump() + (i + 1 < value.size() ? ",\n" : "\n");
            text += "  ]";
        } else if (key == "materials" && !value.empty()) {
            text += "{\n";
            std::size_t i = 0;
            for (const auto& [name, m] : value.items())
                text +=
                    "    " + J(name).dump() + ": " + m.dump() + (++i < value.size() ? ",\n" : "\n");
            text += "  }";
        } else {
            text += value.dump();
        }
    }
    out.sceneJson = text + "\n}\n";

    // The mesh: each distinct vertex once (by its exact bits), faces by 1-based index.
    struct Key {
        std::array<std::uint64_t, 3> bits;
        bool operator==(const Key&) const = default;
    };
    struct Hash {
        std::size_t operator()(const Key& k) const {
            return std::hash<std::uint64_t>()(k.bits[0] * 0x9e3779b97f4a7c15ull ^ k.bits[1] * 31 ^
                                              k.bits[2]);
        }
    };
    std::unordered_map<Key, std::size_t, Hash> ids;
    std::string vertices, faces;
    const auto id = [&](const Vec3& p) {
        Key k{};
        for (int i = 0; i < 3; ++i) std::memcpy(&k.bits[i], &p[i], sizeof(double));
        const auto [it, added] = ids.emplace(k, ids.size() + 1);
        if (added) vertices += "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
        return it->second;
    };
    for (std::size_t i = 0; i < meshTriangles; ++i) {
        const Triangle& t = scene.triangles[i];
        const std::size_t a = id(t.a), b = id(t.b), c = id(t.c);
        faces +=
            "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
    }
    out.meshObj = "# written by raystep: " + std::to_string(meshTriangles) + " triangles\n" +
                  vertices + faces;
    return out;
}

std::variant<Scene, Scene2D> loadAnySceneOrModel(const std::string& nameOrPath) {
    if (isModelPath(nameOrPath)) return importModelScene(nameOrPath);
    return loadAnyScene(nameOrPath);
}

}  // namespace raystep
