#include "raystep/scene/model_import.h"

#include "raystep/base/file_write.h"
#include "raystep/base/json_reader.h"
#include "raystep/geometry/kernels.h"
#include "raystep/scene/model_checks.h"
#include "raystep/scene/resources.h"

#include <assimp/BaseImporter.h>
#include <assimp/importerdesc.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace raystep {

namespace {

// Same caps as a scene's OBJ mesh (scene_loader.cpp): a model is a mesh by another name.
constexpr std::size_t kMaxModelBytes = detail::kMaxObjFileBytes;
using detail::kMaxGltfNodes;
using detail::kMaxModelPointsAndLines;
using detail::kMaxModelTriangles;

/// A file's bytes held in memory, as assimp reads them (shared: the model's are read once).
class StringStream : public Assimp::IOStream {
  public:
    explicit StringStream(std::shared_ptr<const std::string> bytes) : bytes_(std::move(bytes)) {}
    size_t Read(void* buffer, size_t size, size_t count) override {
        if (size == 0) return 0;
        const size_t n = std::min(count, (bytes_->size() - pos_) / size);
        std::memcpy(buffer, bytes_->data() + pos_, n * size);
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
            if (offset > bytes_->size()) return aiReturn_FAILURE;
            to = bytes_->size() - offset;
        }
        if (to > bytes_->size()) return aiReturn_FAILURE;
        pos_ = to;
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return pos_; }
    size_t FileSize() const override { return bytes_->size(); }
    void Flush() override {}

  private:
    std::shared_ptr<const std::string> bytes_;
    size_t pos_ = 0;
};

/// Every file assimp opens goes through here: the model itself (its bytes, already read and
/// checked by model_checks.h) and the glTF buffers the checks listed, each read through the
/// core's checked reader (regular files only, size capped), nothing else (an OBJ's .mtl is never
/// given: raystep ignores a model's materials, and assimp's MTL parser crashed on a texture
/// statement before any newmtl). The first refusal of a listed file is kept to name it.
class CheckedIOSystem : public Assimp::IOSystem {
  public:
    CheckedIOSystem(const detail::ModelFiles& files, std::string model,
                    std::shared_ptr<const std::string> bytes, std::vector<std::string> buffers)
        : files_(files),
          model_(std::move(model)),
          bytes_(std::move(bytes)),
          buffers_(std::move(buffers)) {}
    bool Exists(const char* file) const override { return allowed(file); }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+'))
            return nullptr;
        if (!allowed(file)) return nullptr;
        // The model: the bytes checked (an OBJ's comments blanked; assimp opens it more than once).
        if (files_.same(file, model_)) return new StringStream(bytes_);
        try {
            return new StringStream(
                std::make_shared<const std::string>(files_.read(file, kMaxModelBytes)));
        } catch (const detail::ReadFailure& f) {
            if (!failure) failure = {file, f.what()};
            return nullptr;
        }
    }
    void Close(Assimp::IOStream* stream) override { delete stream; }

    std::optional<std::pair<std::string, std::string>> failure;  // the file, why

  private:
    bool allowed(const char* file) const {
        if (files_.same(file, model_)) return true;
        return std::any_of(buffers_.begin(), buffers_.end(),
                           [&](const std::string& b) { return files_.same(file, b); });
    }
    const detail::ModelFiles& files_;
    std::string model_;
    std::shared_ptr<const std::string> bytes_;
    std::vector<std::string> buffers_;
};

/// assimp's progress (coarse: the file read, then each step) as a share of the import's.
class ForwardedProgress : public Assimp::ProgressHandler {
  public:
    ForwardedProgress(const ProgressFn& fn, double from, double to)
        : fn_(fn), from_(from), to_(to) {}
    bool Update(float percentage) override {
        if (!fn_ || percentage < 0) return !cancelled;
        if (!fn_(from_ + (to_ - from_) * std::clamp(double(percentage), 0.0, 1.0)))
            cancelled = true;
        return !cancelled;
    }
    bool cancelled = false;

  private:
    const ProgressFn& fn_;
    double from_, to_;
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

namespace detail {

ModelFiles diskFiles() {
    ModelFiles files;
    files.read = [](const std::string& path, std::size_t maxBytes) {
        return readRegularFile(path, maxBytes);
    };
    files.size = [](const std::string& path) -> std::uint64_t {
        struct stat st {};
        if (::stat(path.c_str(), &st) != 0) throwReadFailure(errno);
        requireRegular(st, kMaxModelBytes);
        return static_cast<std::uint64_t>(st.st_size);
    };
    files.same = [](const std::string& a, const std::string& b) { return sameFile(a, b); };
    return files;
}

void importModelTriangles(const std::string& path, const ModelFiles& files,
                          const std::function<void(const Triangle&)>& sink,
                          std::uint64_t& droppedDegenerate, const ProgressFn& progress,
                          const std::function<void(std::uint64_t)>& bound) {
    const auto fail = [&](const std::string& message) { failModel(path, message); };
    const auto report = [&](double f) {
        if (progress && !progress(f)) throw BuildCancelled();
    };
    if (!isModelPath(path)) fail("not a model file (expected .obj, .ply, .stl, .gltf or .glb)");
    std::string ext = std::filesystem::path(path).extension().string().substr(1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    // The model itself: refused by name before anything looks (a FIFO would block its open).
    std::string text;
    try {
        text = files.read(path, kMaxModelBytes);
    } catch (const ReadFailure& f) {
        fail(std::string("cannot read the model: ") + f.what());
    }
    if (text.empty()) fail("the model file is empty");
    report(0.02);
    const ModelChecked checked = checkModelBytes(path, text, files.size);
    // An OBJ's statements without their comments, as the checks read them (in place: no copy).
    if (ext == "obj") blankObjComments(text);
    const auto bytes = std::make_shared<const std::string>(std::move(text));
    report(0.1);

    Assimp::Importer importer;  // no DefaultLogger is created: assimp's NullLogger stays quiet
    // The one reader of the extension: assimp would otherwise pick one by the content too (a .obj
    // holding a PLY header would reach the PLY parser unchecked).
    // (glTF: the 2.0 reader, not the 1.0 one, which claims the same extensions.)
    Assimp::BaseImporter* kept = nullptr;
    for (std::size_t i = 0; i < importer.GetImporterCount() && !kept; ++i) {
        const aiImporterDesc* info = importer.GetImporterInfo(i);
        if (!info || !info->mFileExtensions) continue;
        const std::string list = std::string(" ") + info->mFileExtensions + " ";
        const bool gltf2 =
            std::string(info->mName ? info->mName : "").find("glTF2") != std::string::npos;
        if (list.find(" " + ext + " ") != std::string::npos &&
            ((ext != "gltf" && ext != "glb") || gltf2))
            kept = importer.GetImporter(i);
    }
    if (!kept) fail("assimp has no reader for ." + ext);
    std::vector<Assimp::BaseImporter*> others;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i)
        if (importer.GetImporter(i) != kept) others.push_back(importer.GetImporter(i));
    for (Assimp::BaseImporter* other : others) {
        importer.UnregisterLoader(other);
        delete other;  // unregistered, the importer no longer owns it
    }
    auto* io = new CheckedIOSystem(files, path, bytes, checked.buffers);
    importer.SetIOHandler(io);  // the importer owns it
    auto* forwarded = new ForwardedProgress(progress, 0.1, 0.6);
    importer.SetProgressHandler(forwarded);  // and this
    const aiScene* ai = nullptr;
    try {
        ai = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
    } catch (const std::exception& e) {
        fail(std::string("cannot import the model: ") + e.what());
    }
    if (forwarded->cancelled) throw BuildCancelled();
    // A file assimp could not open (the model changed under us, a glTF buffer that is a FIFO).
    if (!ai && io->failure)
        fail(files.same(io->failure->first, path)
                 ? io->failure->second
                 : "cannot read '" + printable(io->failure->first) + "': " + io->failure->second);
    if (!ai) {
        std::string why = importer.GetErrorString();
        // Out of the importer's memory (its limit): said so by the importer program.
        if (why.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
        while (!why.empty() && (why.back() == '\n' || why.back() == '.')) why.pop_back();
        fail("cannot import the model: " + (why.empty() ? std::string("unknown error") : why));
    }
    if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) fail("the model is incomplete (no geometry)");

    // The node tree, walked without recursion; every instance of a mesh with its transform.
    struct Instance {
        const aiMesh* mesh;
        unsigned index;
        aiMatrix4x4 xf;
    };
    std::vector<Instance> instances;
    std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack;
    if (ai->mRootNode) stack.emplace_back(ai->mRootNode, ai->mRootNode->mTransformation);
    std::uint64_t nodes = 0, faces = 0;
    while (!stack.empty()) {
        const auto [node, xf] = stack.back();
        stack.pop_back();
        if (++nodes > kMaxGltfNodes) fail("more than a million nodes in the model's node tree");
        for (unsigned c = 0; c < node->mNumChildren; ++c)
            if (node->mChildren[c])
                stack.emplace_back(node->mChildren[c], xf * node->mChildren[c]->mTransformation);
        for (unsigned k = 0; k < node->mNumMeshes; ++k) {
            const unsigned mi = node->mMeshes[k];
            if (mi >= ai->mNumMeshes || !ai->mMeshes[mi]) fail("a node refers to a missing mesh");
            instances.push_back({ai->mMeshes[mi], mi, xf});
            // Points, lines and zero-area triangles cost the walk too.
            faces += ai->mMeshes[mi]->mNumFaces;
            if (faces > kMaxModelTriangles + kMaxModelPointsAndLines)
                fail("the model's nodes place more than " +
                     std::to_string(kMaxModelTriangles + kMaxModelPointsAndLines) +
                     " faces, lines and points");
        }
    }
    if (bound) bound(std::min<std::uint64_t>(faces, kMaxModelTriangles));
    // Each mesh's vertices are checked once, however many nodes place it.
    std::vector<bool> checkedMesh(ai->mNumMeshes, false);
    std::uint64_t walked = 0, found = 0;
    for (const Instance& in : instances) {
        const aiMesh& mesh = *in.mesh;
        if (!checkedMesh[in.index]) {
            checkedMesh[in.index] = true;
            for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
                const aiVector3D& p = mesh.mVertices[v];
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                    fail(meshName(mesh, in.index) + ", vertex " + std::to_string(v) +
                         ": a coordinate is not a finite number");
            }
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            if ((++walked & 0xffff) == 0) report(0.6 + 0.4 * double(walked) / double(faces));
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines: no surface
            std::array<Vec3, 3> p;
            for (int i = 0; i < 3; ++i) {
                const unsigned index = face.mIndices[i];
                if (index >= mesh.mNumVertices)
                    fail(meshName(mesh, in.index) + ", face " + std::to_string(f) +
                         ": vertex index " + std::to_string(index) + " is out of range (" +
                         std::to_string(mesh.mNumVertices) + " vertices)");
                p[i] = transformed(in.xf, mesh.mVertices[index]);
                if (!isFinite(p[i]))
                    fail(meshName(mesh, in.index) + ", face " + std::to_string(f) +
                         ": the node's transform makes a vertex overflow");
            }
            const Triangle t{p[0], p[1], p[2], 0};
            if (glm::length(glm::cross(t.b - t.a, t.c - t.a)) == 0.0) {
                ++droppedDegenerate;
                continue;
            }
            if (++found > kMaxModelTriangles)
                fail("more than " + std::to_string(kMaxModelTriangles) +
                     " triangles, the most raystep reads from one model");
            sink(t);
        }
    }
    report(1.0);
}

void checkImportedModel(const std::string& path, const ImportedModel& model) {
    const auto fail = [&](const std::string& message) { failModel(path, message); };
    if (model.triangles.size() > kMaxModelTriangles)
        fail("more than " + std::to_string(kMaxModelTriangles) +
             " triangles, the most raystep reads from one model");
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
}

}  // namespace detail

ImportedModel importModelInProcess(const std::string& path, const ProgressFn& progress) {
    ImportedModel model;
    detail::importModelTriangles(
        path, detail::diskFiles(),
        [&](const Triangle& t) {
            model.triangles.push_back(t);
            model.bounds.extend(t.a);
            model.bounds.extend(t.b);
            model.bounds.extend(t.c);
        },
        model.droppedDegenerateTriangles, progress,
        [&](std::uint64_t bound) { model.triangles.reserve(bound); });
    detail::checkImportedModel(path, model);
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

Scene importModelScene(const std::string& path, const ImportOptions& options) {
    return sceneAroundModel(importModel(path, options), path);
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

std::variant<Scene, Scene2D> loadAnySceneOrModel(const std::string& nameOrPath,
                                                 const ProgressFn& progress) {
    if (isModelPath(nameOrPath)) {
        ImportOptions options;
        options.progress = progress;
        return importModelScene(nameOrPath, options);
    }
    return loadAnyScene(nameOrPath);
}

std::vector<std::string> inputFilesOf(const std::string& nameOrPath) {
    std::vector<std::string> files;
    try {
        if (embeddedFile(nameOrPath + ".json")) return files;  // a built-in scene
        files.push_back(nameOrPath);
        if (isModelPath(nameOrPath)) {
            const std::string bytes = detail::readRegularFile(nameOrPath, kMaxModelBytes);
            for (std::string& f : detail::modelReferences(nameOrPath, bytes))
                files.push_back(std::move(f));
            return files;
        }
        // A scene file: its meshes, beside it.
        const std::string text = detail::readRegularFile(nameOrPath, detail::kMaxJsonFileBytes);
        if (JsonLineMap::tooDeepLine(text)) return files;
        const auto root = nlohmann::json::parse(text, nullptr, false, true);
        if (!root.is_object() || !root.contains("objects") || !root["objects"].is_array())
            return files;
        const std::filesystem::path folder = std::filesystem::path(nameOrPath).parent_path();
        for (const auto& o : root["objects"])
            if (o.is_object() && o.contains("file") && o["file"].is_string())
                files.push_back((folder / o["file"].get<std::string>()).string());
    } catch (const std::exception&) {
        // Unreadable: the command's own read says why.
    }
    return files;
}

}  // namespace raystep
