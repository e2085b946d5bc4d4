// Models: raystep's own checks (model_checks.h) and assimp behind them, in this process (the
// importer program's work, importModelTriangles), on files held in memory. The first byte picks
// the format (0 OBJ with its .mtl, 1 PLY, 2 STL, 3 glTF with its .bin, 4 glb); the rest is the
// file, and after a line "--FILE--" the file it names (the .mtl, the .bin). Passing: triangles,
// or a SceneError. What the checks let through to crash or blow up assimp is a finding: the
// importer process would survive it, but the checks are meant to stop the known classes first.
#include "fuzz_support.h"
#include "raystep/base/json_reader.h"
#include "raystep/scene/model_import.h"

#include <array>
#include <filesystem>
#include <map>

namespace {

constexpr std::array<const char*, 5> kModel = {
    "/fuzz/model.obj", "/fuzz/model.ply", "/fuzz/model.stl", "/fuzz/model.gltf", "/fuzz/model.glb"};
constexpr std::array<const char*, 5> kOther = {"/fuzz/model.mtl", "", "", "/fuzz/model.bin",
                                               "/fuzz/model.bin"};

std::string normal(const std::string& p) {
    return std::filesystem::path(p).lexically_normal().string();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::size_t format = data[0] % kModel.size();
    const std::string_view rest = raystep::fuzz::asText(data + 1, size - 1);
    std::map<std::string, std::string> files;
    const std::size_t cut = rest.find("\n--FILE--\n");
    files[kModel[format]] = std::string(rest.substr(0, cut));
    if (cut != std::string_view::npos && *kOther[format])
        files[kOther[format]] = std::string(rest.substr(cut + 10));

    raystep::detail::ModelFiles memory;
    const auto find = [&](const std::string& path) -> const std::string& {
        const auto it = files.find(normal(path));
        if (it == files.end()) throw raystep::detail::ReadFailure("no such file", true);
        return it->second;
    };
    memory.read = [&](const std::string& path, std::size_t maxBytes) {
        const std::string& bytes = find(path);
        if (bytes.size() > maxBytes) throw raystep::detail::ReadFailure("too large", false);
        return bytes;
    };
    memory.size = [&](const std::string& path) -> std::uint64_t { return find(path).size(); };
    memory.same = [](const std::string& a, const std::string& b) { return normal(a) == normal(b); };

    raystep::fuzz::expectOwnErrorOnly<raystep::SceneError>("importModelTriangles", [&] {
        std::uint64_t dropped = 0, triangles = 0;
        raystep::detail::importModelTriangles(
            kModel[format], memory, [&](const raystep::Triangle&) { ++triangles; }, dropped, {});
    });
    return 0;
}
