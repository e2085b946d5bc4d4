// The scene loader: every built-in scene loads, good files give the documented defaults, and each
// kind of bad input fails with the file, the line and the key of the problem.
#include "raystep/scene/scene_loader.h"
#include "raystep/trace/trace_io.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <memory>
#include <thread>

namespace raystep {
namespace {

const FileResolver kNoFiles = [](const std::string&) { return std::optional<std::string>(); };

Scene load(const std::string& text, const FileResolver& resolver = kNoFiles) {
    return loadSceneText(text, "test.json", resolver);
}

constexpr const char* kMinimal = R"({"objects": [{"type": "sphere", "radius": 1}]})";

TEST(SceneLoader, EveryBuiltinSceneLoads) {
    const auto names = builtinSceneNames();
    EXPECT_EQ(names, (std::vector<std::string>{"cornell", "default", "lecture-dda3d", "stadium",
                                               "whitted"}));
    for (const auto& name : names) {
        const Scene s = loadBuiltinScene(name);
        EXPECT_EQ(s.name, name);
        EXPECT_FALSE(s.description.empty()) << name;
        EXPECT_GT(s.primitiveCount(), 0u) << name;
        EXPECT_FALSE(s.lights.empty()) << name;
    }
}

TEST(SceneLoader, StadiumIsADenseMeshInALargeRoom) {
    const Scene s = loadBuiltinScene("stadium");
    EXPECT_GE(s.triangles.size(), 50000u);
    EXPECT_EQ(s.droppedDegenerateTriangles, 0u);
    const Bounds3 room = s.bounds();
    Bounds3 knot;
    for (const Triangle& t : s.triangles)
        if (s.materials[t.material].name == "knot") {
            knot.extend(t.a);
            knot.extend(t.b);
            knot.extend(t.c);
        }
    // "Mostly empty": the dense mesh fills well under a thousandth of the room's volume.
    const auto volume = [](const Bounds3& b) {
        const Vec3 d = b.diagonal();
        return d.x * d.y * d.z;
    };
    EXPECT_LT(volume(knot) / volume(room), 1e-3);
}

TEST(SceneLoader, CornellBoxHasRedAndGreenWalls) {
    const Scene s = loadBuiltinScene("cornell");
    int red = 0, green = 0;
    for (const Triangle& t : s.triangles) {
        const Color kd = s.materials[t.material].kd;
        red += kd.r > 3 * kd.g;
        green += kd.g > 3 * kd.r;
    }
    EXPECT_EQ(red, 2);
    EXPECT_EQ(green, 2);
}

TEST(SceneLoader, DefaultsOfAMinimalScene) {
    const Scene s = load(kMinimal);
    ASSERT_EQ(s.spheres.size(), 1u);
    EXPECT_EQ(s.spheres[0].center, Vec3(0.0));
    EXPECT_EQ(s.spheres[0].material, 0u);  // the default material
    EXPECT_EQ(s.materials[0].kd, Color(0.8));
    EXPECT_EQ(s.camera.eye, Vec3(0, 0, 5));
    EXPECT_EQ(s.camera.fovDeg, 45.0);
    EXPECT_EQ(s.settings.width, 640);
    EXPECT_EQ(s.settings.bounces, 5);
    EXPECT_EQ(s.settings.spp, 1);
    EXPECT_EQ(s.settings.diffuseSamples, 0);
    EXPECT_TRUE(s.lights.empty());
}

TEST(SceneLoader, ReadsEveryKey) {
    const Scene s = load(R"(
    // comments are allowed
    {
      "description": "all keys",
      "camera": {"eye": [1, 2, 3], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 60},
      "render": {"width": 32, "height": 16, "bounces": 2, "spp": 9, "diffuse_samples": 4},
      "background": [0.1, 0.2, 0.3],
      "ambient": 0.25,
      "lights": [{"position": [0, 5, 0], "color": [1, 0.5, 0.25], "intensity": 2}],
      "materials": {"m": {"kd": [0.5, 0.4, 0.3], "ks": 0.2, "n": 7, "reflect": 0.3,
                          "transparency": [0.1, 0.2, 0.3], "ior": 1.33,
                          "checker": {"color": 0.05, "size": 0.5}}},
      "objects": [
        {"type": "sphere", "material": "m", "center": [1, 1, 1], "radius": 2},
        /* block comment */
        {"type": "triangle", "material": "m", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
      ]
    })");
    EXPECT_EQ(s.description, "all keys");
    EXPECT_EQ(s.camera.up, Vec3(0, 0, 1));
    EXPECT_EQ(s.camera.fovDeg, 60.0);
    EXPECT_EQ(s.settings.width, 32);
    EXPECT_EQ(s.settings.height, 16);
    EXPECT_EQ(s.settings.spp, 9);
    EXPECT_EQ(s.settings.diffuseSamples, 4);
    EXPECT_EQ(s.background, Color(0.1, 0.2, 0.3));
    EXPECT_EQ(s.ambient, Color(0.25));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].intensity, Color(2, 1, 0.5));
    const Material& m = s.materials[s.spheres[0].material];
    EXPECT_EQ(m.name, "m");
    EXPECT_EQ(m.kd, Color(0.5, 0.4, 0.3));
    EXPECT_EQ(m.ks, Color(0.2));
    EXPECT_EQ(m.n, 7.0);
    EXPECT_EQ(m.reflect, Color(0.3));
    EXPECT_EQ(m.transparency, Color(0.1, 0.2, 0.3));
    EXPECT_EQ(m.ior, 1.33);
    EXPECT_TRUE(m.checker.enabled);
    EXPECT_EQ(m.checker.size, 0.5);
    EXPECT_EQ(s.triangles.size(), 1u);
    EXPECT_EQ(s.primitiveCount(), 2u);
}

TEST(SceneLoader, TinyAndHugeScenesLoadAlike) {
    // The same scene at 1e-12 and 1e12: no absolute tolerance may reject either.
    for (const char* text : {R"({"camera": {"eye": [0, 0, 5e-12], "look_at": [0, 0, 0]},
              "objects": [{"type": "sphere", "radius": 1e-12}]})",
                             R"({"camera": {"eye": [0, 0, 5e12], "look_at": [0, 0, 0]},
              "objects": [{"type": "sphere", "radius": 1e12}]})"}) {
        const Scene s = load(text);
        const Ray r = s.camera.generateRay(32, 24, 64, 48);
        EXPECT_NEAR(r.dir.z, -1.0, 1e-12);
    }
}

TEST(SceneLoader, CheckerAlternatesInCubes) {
    Material m;
    m.kd = Color(1.0);
    m.checker = {true, Color(0.0), 2.0};
    EXPECT_EQ(m.diffuseAt(Vec3(0.5, 0.0, 0.5)), Color(1.0));   // cube (0,0,0): even
    EXPECT_EQ(m.diffuseAt(Vec3(2.5, 0.0, 0.5)), Color(0.0));   // cube (1,0,0): odd
    EXPECT_EQ(m.diffuseAt(Vec3(2.5, 0.0, 2.5)), Color(1.0));   // cube (1,0,1): even
    EXPECT_EQ(m.diffuseAt(Vec3(-0.5, 0.0, 0.5)), Color(0.0));  // cube (-1,0,0): odd
}

TEST(SceneLoader, MeshFromObjWithTransform) {
    const std::string obj =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "f 1 2 3 4\n"          // a quad: triangulated into two
        "v 2 2 2\nf 1 1 5\n";  // a degenerate triangle: dropped and counted
    const FileResolver resolver = [&](const std::string& name) {
        return name == "quad.obj" ? std::optional<std::string>(obj) : std::nullopt;
    };
    const Scene s = load(R"({"objects": [{"type": "mesh", "file": "quad.obj",
                                          "scale": [2, 3, 1], "translate": [10, 0, 0]}]})",
                         resolver);
    ASSERT_EQ(s.triangles.size(), 2u);
    EXPECT_EQ(s.droppedDegenerateTriangles, 1u);
    // The quad becomes the rectangle [10, 12] x [0, 3]: corners only, total area 2 * 3.
    double area = 0.0;
    for (const Triangle& t : s.triangles) {
        area += 0.5 * glm::length(glm::cross(t.b - t.a, t.c - t.a));
        for (const Vec3& p : {t.a, t.b, t.c}) {
            EXPECT_TRUE(p.x == 10 || p.x == 12) << p.x;
            EXPECT_TRUE(p.y == 0 || p.y == 3) << p.y;
            EXPECT_EQ(p.z, 0.0);
        }
    }
    EXPECT_EQ(area, 6.0);
}

TEST(SceneLoader, FileResolvesMeshesBesideIt) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("raystep-loader-" + std::to_string(::getpid()));
    fs::create_directories(dir / "meshes");
    std::ofstream(dir / "meshes" / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::ofstream(dir / "scene.json")
        << R"({"objects": [{"type": "mesh", "file": "meshes/tri.obj"}]})";
    const Scene s = loadSceneFile((dir / "scene.json").string());
    EXPECT_EQ(s.triangles.size(), 1u);
    const Scene same = loadScene((dir / "scene.json").string());
    EXPECT_EQ(same.triangles.size(), 1u);
    fs::remove_all(dir);
}

TEST(SceneLoader, MissingFileNamesIt) {
    try {
        loadScene("/nonexistent/scene.json");
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.file(), "/nonexistent/scene.json");
        EXPECT_NE(std::string(e.what()).find(
                      "built-in: cornell, default, lecture-dda3d, stadium, whitted"),
                  std::string::npos)
            << e.what();
    }
}

// One bad input, the line and key the error must name, and a word of its message.
struct BadCase {
    const char* name;
    const char* text;
    int line;
    const char* key;
    const char* message;
};

void PrintTo(const BadCase& c, std::ostream* os) {
    *os << c.name;
}

class SceneLoaderBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneLoaderBadInput, FailsWithFileLineAndKey) {
    const BadCase& c = GetParam();
    const FileResolver resolver = [](const std::string& name) {
        if (name == "empty.obj") return std::optional<std::string>("# nothing\n");
        if (name == "nan.obj")
            return std::optional<std::string>("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
        if (name == "inf.obj")
            return std::optional<std::string>("v 0 0 1e999\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        if (name == "index.obj")
            return std::optional<std::string>("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
        return std::optional<std::string>();
    };
    try {
        load(c.text, resolver);
        FAIL() << "expected a SceneError for " << c.name;
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.file(), "test.json");
        EXPECT_EQ(e.line(), c.line) << what;
        EXPECT_EQ(e.key(), c.key) << what;
        EXPECT_NE(what.find(c.message), std::string::npos) << what;
        // One line: "file:line: key 'k': message".
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.rfind("test.json:" + std::to_string(c.line) + ": ", 0), 0u) << what;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SceneLoaderBadInput,
    ::testing::Values(
        BadCase{"MalformedJson", "{\n  \"objects\": [\n    {\"type\": \"sphere\",, }\n  ]\n}", 3,
                "", "malformed JSON"},
        BadCase{"TrailingGarbage", "{\"objects\": []}\n}", 2, "", "malformed JSON"},
        BadCase{"NaNLiteral", "{\"objects\": [\n{\"type\": \"sphere\", \"radius\": NaN}]}", 2, "",
                "malformed JSON"},
        BadCase{"NotAnObject", "[1, 2]", 1, "", "one JSON object"},
        BadCase{"UnknownTopKey",
                "{\n\"objects\": [{\"type\": \"sphere\", \"radius\": 1}],\n\"lihgts\": []}", 3,
                "lihgts", "unknown key"},
        BadCase{"UnknownSphereKey",
                "{\"objects\": [\n{\"type\": \"sphere\",\n \"radius\": 1,\n \"colour\": 1}]}", 4,
                "objects[0].colour", "unknown key"},
        BadCase{"WrongType", "{\"objects\": [{\"type\": \"sphere\",\n\"radius\": \"big\"}]}", 2,
                "objects[0].radius", "expected a number"},
        BadCase{"NegativeRadius", "{\"objects\": [\n\n{\"type\": \"sphere\", \"radius\": -1}]}", 3,
                "objects[0].radius", "greater than 0"},
        BadCase{"ZeroRadius", "{\"objects\": [{\"type\": \"sphere\", \"radius\": 0}]}", 1,
                "objects[0].radius", "greater than 0"},
        BadCase{
            "InfiniteNumber",
            "{\"objects\": [{\"type\": \"sphere\", \"radius\": 1,\n\"center\": [0, 1e999, 0]}]}", 2,
            "", "number '1e999' is out of range"},
        BadCase{"EmptyScene", "{\"objects\": []}", 1, "objects", "empty"},
        BadCase{"NoObjectsKey", "{\"background\": 0.5}", 1, "objects", "empty"},
        BadCase{"CameraWithoutDirection",
                "{\"camera\": {\"eye\": [1, 2, 3],\n \"look_at\": [1, 2, 3]},\n\"objects\": "
                "[{\"type\": "
                "\"sphere\", \"radius\": 1}]}",
                2, "camera.look_at", "no direction"},
        BadCase{"UpParallelToView",
                "{\"camera\": {\"eye\": [0, 5, 0], \"look_at\": [0, 0, 0],\n\"up\": [0, 1, 0]},\n"
                "\"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}",
                2, "camera.up", "parallel"},
        BadCase{
            "FovTooWide",
            "{\"camera\": {\n\"fov\": 180}, \"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}",
            2, "camera.fov", "below 180"},
        BadCase{"ImageOverCap",
                "{\"render\": {\"width\": 100000}, \"objects\": [{\"type\": \"sphere\", "
                "\"radius\": 1}]}",
                1, "render.width", "between 1 and 8192"},
        BadCase{
            "ZeroHeight",
            "{\"render\": {\n\"height\": 0}, \"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}",
            2, "render.height", "between 1 and 8192"},
        BadCase{
            "FractionalSpp",
            "{\"render\": {\"spp\": 2.5}, \"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}", 1,
            "render.spp", "whole number"},
        BadCase{"MissingObj", "{\"objects\": [\n{\"type\": \"mesh\",\n\"file\": \"missing.obj\"}]}",
                3, "objects[0].file", "cannot read OBJ file 'missing.obj': no such file"},
        BadCase{"EmptyObj", "{\"objects\": [{\"type\": \"mesh\", \"file\": \"empty.obj\"}]}", 1,
                "objects[0].file", "no triangles"},
        BadCase{"NanInObj", "{\"objects\": [{\"type\": \"mesh\", \"file\": \"nan.obj\"}]}", 1,
                "objects[0].file", "line 2: vertex coordinate 'nan' is not a finite number"},
        BadCase{"InfinityInObj", "{\"objects\": [{\"type\": \"mesh\", \"file\": \"inf.obj\"}]}", 1,
                "objects[0].file", "line 1: vertex coordinate '1e999'"},
        BadCase{"ObjIndexOutOfRange",
                "{\"objects\": [{\"type\": \"mesh\", \"file\": \"index.obj\"}]}", 1,
                "objects[0].file", "out of range"},
        BadCase{"ZeroMeshScale",
                "{\"objects\": [{\"type\": \"mesh\", \"file\": \"x.obj\",\n\"scale\": 0}]}", 2,
                "objects[0].scale", "must not be zero"},
        BadCase{"UnknownMaterial",
                "{\"objects\": [{\"type\": \"sphere\", \"radius\": 1,\n\"material\": \"gold\"}]}",
                2, "objects[0].material", "no material named 'gold'"},
        BadCase{"KdAboveOne",
                "{\"materials\": {\"m\": {\n\"kd\": [0.5, 1.5, 0.5]}}, \"objects\": [{\"type\": "
                "\"sphere\", \"radius\": 1}]}",
                2, "materials.m.kd", "at most 1"},
        BadCase{"NegativeLightIntensity",
                "{\"lights\": [{\"position\": [0, 1, 0],\n\"intensity\": -2}], \"objects\": "
                "[{\"type\": \"sphere\", \"radius\": 1}]}",
                2, "lights[0].intensity", "negative"},
        BadCase{"LightWithoutPosition",
                "{\"lights\": [\n{}], \"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}", 2,
                "lights[0].position", "needs a position"},
        BadCase{"ZeroCheckerSize",
                "{\"materials\": {\"m\": {\"checker\": {\n\"size\": 0}}}, \"objects\": [{\"type\": "
                "\"sphere\", \"radius\": 1}]}",
                2, "materials.m.checker.size", "greater than 0"},
        BadCase{
            "ZeroAreaTriangle",
            "{\"objects\": [{\"type\": \"triangle\",\n\"vertices\": [[0,0,0],[1,1,1],[2,2,2]]}]}",
            2, "objects[0].vertices", "zero area"},
        BadCase{"TriangleWithTwoVertices",
                "{\"objects\": [{\"type\": \"triangle\", \"vertices\": [[0,0,0],[1,1,1]]}]}", 1,
                "objects[0].vertices", "3 vertices"},
        BadCase{"UnknownType", "{\"objects\": [{\n\"type\": \"cube\"}]}", 2, "objects[0].type",
                "unknown object type 'cube'"},
        BadCase{"DuplicateKey",
                "{\"objects\": [{\"type\": \"sphere\", \"radius\": 1,\n\"radius\": 2}]}", 2,
                "objects[0].radius", "given twice"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace raystep

namespace raystep {
namespace {

TEST(Scene2DLoader, LectureScenesLoad) {
    EXPECT_EQ(builtinScene2DNames(), (std::vector<std::string>{"lecture-grid", "lecture-kdtree"}));
    for (const auto& name : builtinScene2DNames()) {
        const auto any = loadAnyScene(name);
        ASSERT_TRUE(std::holds_alternative<Scene2D>(any)) << name;
        const Scene2D& s = std::get<Scene2D>(any);
        EXPECT_EQ(s.name, name);
        EXPECT_TRUE(s.exampleRay.has_value()) << name;
        EXPECT_GT(s.primitiveCount(), 5u) << name;
    }
    // A 3D command on a 2D scene is told so, with the file and key.
    try {
        loadScene("lecture-grid");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.key(), "dimensions");
        EXPECT_NE(std::string(e.what()).find("a 2D scene"), std::string::npos);
    }
}

// Class 16 in 2D: the circle test squares the direction, which is not normalised; a ray or a
// primitive past the kernels' range is refused naming it.
TEST(Scene2DLoader, GeometryOutsideTheKernelsRangeIsRefusedByName) {
    const auto keyOf = [](const std::string& body) -> std::string {
        try {
            loadScene2DText("{\"dimensions\": 2,\n" + body + "}", "s.json");
            return "(loaded)";
        } catch (const SceneError& e) {
            return e.key() + " | " + e.what();
        }
    };
    const std::string circle = "\"circles\": [{\"center\": [2, 2], \"radius\": 1}]";
    EXPECT_EQ(keyOf(circle), "(loaded)");
    for (const auto& [body, key] : std::vector<std::pair<std::string, std::string>>{
             {circle + ",\n\"ray\": {\"origin\": [0, 0], \"dir\": [1e200, 0]}", "ray"},
             {circle + ",\n\"ray\": {\"origin\": [0, 0], \"dir\": [1e-70, 0]}", "ray"},
             {circle + ",\n\"ray\": {\"origin\": [1e61, 0], \"dir\": [1, 0]}", "ray"},
             {"\"circles\": [{\"center\": [2, 2], \"radius\": 1},\n{\"center\": [1e100, 0], "
              "\"radius\": 1}]",
              "circles[1]"},
             {"\"circles\": [{\"center\": [2, 2], \"radius\": 1e-100}]", "circles[0]"},
             {circle + ",\n\"segments\": [{\"from\": [0, 0], \"to\": [1e-80, 0]}]",
              "segments[0]"}}) {
        const std::string k = keyOf(body);
        EXPECT_EQ(k.substr(0, k.find(" | ")), key) << body << "\n" << k;
    }
}

TEST(Scene2DLoader, BadFilesNameLineAndKey) {
    const auto expectError = [](const std::string& text, int line, const std::string& key,
                                const std::string& message) {
        try {
            loadScene2DText(text, "flat.json");
            FAIL() << text;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.line(), line) << e.what();
            EXPECT_EQ(e.key(), key) << e.what();
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    };
    expectError("{\"dimensions\": 2,\n\"circles\": [{\"center\": [0, 0], \"radius\": -1}]}", 2,
                "circles[0].radius", "greater than 0");
    expectError("{\"dimensions\": 2,\n\"segments\": [\n{\"from\": [1, 1], \"to\": [1, 1]}]}", 3,
                "segments[0].to", "no length");
    expectError("{\"dimensions\": 2,\n\"segments\": [{\"from\": [1, \"x\"], \"to\": [1, 1]}]}", 2,
                "segments[0].from[1]", "expected a number");
    expectError(
        "{\"dimensions\": 2,\n\"ray\": {\"origin\": [0, 0], \"dir\": [0, 0]},\n"
        "\"circles\": [{\"center\": [0, 0], \"radius\": 1}]}",
        2, "ray.dir", "must not be zero");
    expectError(
        "{\"dimensions\": 2,\n\"grid\": [0, 4],\n"
        "\"circles\": [{\"center\": [0, 0], \"radius\": 1}]}",
        2, "grid[0]", "between 1 and 512");
    expectError("{\"dimensions\": 2}", 1, "segments", "the scene is empty");
    expectError("{\"dimensions\": 2,\n\"spheres\": []}", 2, "spheres", "unknown key");
}

}  // namespace
}  // namespace raystep

// ---- Hostile input (robustness review, issue 15): every failure is one SceneError line ----

namespace raystep {
namespace {

namespace fs = std::filesystem;

/// A fresh folder under /tmp, removed with everything in it at the end of the test.
struct TempDir {
    fs::path path = fs::temp_directory_path() /
                    ("raystep-hostile-" + std::to_string(::getpid()) + "-" +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TempDir() { fs::create_directories(path); }
    ~TempDir() { fs::remove_all(path); }
};

/// What `f` throws, run on a thread: "" for no exception, "timed out" when it is still blocked
/// after 10 s (a writer then opens and closes `fifo` so the thread ends instead of hanging the
/// test), the message of a FileError, else "other exception: ...".
std::string errorOf(const std::function<void()>& f, const fs::path& fifo = {}) {
    auto result = std::make_shared<std::promise<std::string>>();
    std::future<std::string> future = result->get_future();
    std::thread([result, f] {
        try {
            f();
            result->set_value("");
        } catch (const FileError& e) {
            result->set_value(e.what());
        } catch (const std::exception& e) {
            result->set_value(std::string("other exception: ") + e.what());
        }
    }).detach();
    if (future.wait_for(std::chrono::seconds(10)) == std::future_status::ready) return future.get();
    if (!fifo.empty())
        if (const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK); fd >= 0) ::close(fd);
    future.wait();
    return "timed out";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// Class 4: a deeply nested value is refused at the cap, before any recursive code sees it, with
// the line of the first bracket past it; exactly 64 levels still parse.
TEST(SceneLoaderHostile, DeepNestingIsRefusedAtTheCap) {
    const auto scene = [](int levels) {
        // The root object is level 1, so `levels - 1` arrays under it.
        return "{\"objects\": [{\"type\": \"sphere\", \"radius\": 1}],\n\"description\": " +
               std::string(levels - 1, '[') + std::string(levels - 1, ']') + "}";
    };
    for (const int levels : {65, 1000, 1'000'000}) {
        try {
            load(scene(levels));
            ADD_FAILURE() << levels << " levels loaded";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.line(), 2) << e.what();
            EXPECT_TRUE(contains(e.what(), "nested deeper than 64 levels")) << e.what();
        }
        try {
            loadScene2DText("{\"dimensions\": 2,\n\"grid\": " + std::string(levels, '[') +
                                std::string(levels, ']') + "}",
                            "flat.json");
            ADD_FAILURE() << levels << " levels loaded";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.line(), 2) << e.what();
            EXPECT_TRUE(contains(e.what(), "nested deeper than 64 levels")) << e.what();
        }
        EXPECT_FALSE(isScene2DText("{\"dimensions\": 2, \"x\": " + std::string(levels, '[') +
                                   std::string(levels, ']') + "}"));
    }
    // 64 levels: past the depth check, the description is refused for its type.
    try {
        load(scene(64));
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.key(), "description");
        EXPECT_TRUE(contains(e.what(), "expected a string")) << e.what();
    }
    // Brackets in strings and comments do not count; a comment that ends at a CR (as nlohmann
    // ends it) does not hide the brackets after it.
    EXPECT_NO_THROW(load("{\"description\": \"" + std::string(100, '[') + "\", // " +
                         std::string(100, '[') + "\n \"objects\": [{\"type\": \"sphere\", " +
                         "\"radius\": 1}]}"));
    try {
        load("{// comment\r\"description\": " + std::string(100, '[') + std::string(100, ']') +
             "}");
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_TRUE(contains(e.what(), "nested deeper than 64 levels")) << e.what();
    }
}

// Class 11: nlohmann compares decoded keys, so must the duplicate check.
TEST(SceneLoaderHostile, ADuplicateKeySpelledWithAnEscapeIsFound) {
    for (const char* spelling : {"r\\u0061dius", "\\u0072adius", "\\u0072\\u0061\\u0064ius"}) {
        try {
            load(std::string("{\"objects\": [{\"type\": \"sphere\", \"radius\": 1,\n\"") +
                 spelling + "\": 2}]}");
            ADD_FAILURE() << spelling;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.line(), 2) << e.what();
            EXPECT_EQ(e.key(), "objects[0].radius") << e.what();
            EXPECT_TRUE(contains(e.what(), "given twice")) << e.what();
        }
    }
    // Keys that differ once decoded are not duplicates, and keep their lines.
    EXPECT_NO_THROW(
        load("{\"materials\": {\"a\\\"b\": {}, \"a\\\\b\": {},\n\"a.b\": {}},\n"
             "\"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}"));
    try {
        load(
            "{\"materials\": {\"a\\\"b\": {},\n \"\\u00e8\": {\"kd\": 2}},\n"
            "\"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}");
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.line(), 2) << e.what();
        EXPECT_EQ(e.key(), "materials.\xc3\xa8.kd") << e.what();
    }
}

// A NUL byte ends nlohmann's input: a scene followed by NUL and garbage was accepted whole, and the
// line map never ended on a NUL inside an unclosed array (both found by fuzz_scene). Every JSON
// reader refuses the byte, naming its line.
TEST(SceneLoaderHostile, ANulByteIsRefusedWithItsLine) {
    const std::string scene = "{\"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}\n";
    for (const std::string& text :
         {scene + std::string(1, '\0') + "garbage", std::string("//\0"
                                                                "1\0\n{\"a\":[0}",
                                                                14)}) {
        try {
            load(text);
            ADD_FAILURE() << "accepted";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.line(), text[0] == '/' ? 1 : 2) << e.what();
            EXPECT_TRUE(contains(e.what(), "NUL byte")) << e.what();
        }
    }
    EXPECT_THROW(loadScene2DText(std::string("{\"dimensions\": 2}\0", 17), "a.json"), SceneError);
    EXPECT_THROW(traceFromJson(std::string("{}\0", 3), "t.json"), TraceError);
    // The course's readers: tests/course/lesson_hostile_test.cpp.
}

// Class 12: text from the file (and the file's name) is quoted escaped and shortened, so the
// message stays one line and a NUL does not cut it.
TEST(SceneLoaderHostile, QuotedTextIsEscapedAndShortened) {
    try {
        loadSceneText("{\"objects\": [{\"type\": \"cu\\nbe\\u0000tail\\u001b[31m\\r\"}]}",
                      "odd\nname\x01.json", kNoFiles);
        ADD_FAILURE();
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find_first_of(std::string("\n\r\x1b\x01\0", 5)), std::string::npos) << what;
        EXPECT_TRUE(contains(what, "odd\\nname\\x01.json:1: ")) << what;
        EXPECT_TRUE(contains(what, "unknown object type 'cu\\nbe\\x00tail\\x1b[31m\\r'")) << what;
        EXPECT_EQ(e.file(), "odd\nname\x01.json");  // the accessor keeps the name as given
    }
    // A long value is cut, with its length; UTF-8 text passes as it is.
    try {
        load("{\"objects\": [{\"type\": \"" + std::string(5000, 'x') + "\"}]}");
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_LT(std::string(e.what()).size(), 300u) << e.what();
        EXPECT_TRUE(contains(e.what(), "... (5000 bytes)")) << e.what();
    }
    try {
        load("{\"objects\": [{\"type\": \"cub\xc3\xa8\"}]}");
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_TRUE(contains(e.what(), "'cub\xc3\xa8'")) << e.what();
    }
    // A 400-digit number is out of range: the message quotes its start, not all of it.
    try {
        load("{\"objects\": [{\"type\": \"sphere\",\n\"radius\": 1" + std::string(400, '0') +
             "}]}");
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.line(), 2) << e.what();
        EXPECT_LT(std::string(e.what()).size(), 200u) << e.what();
        EXPECT_TRUE(contains(e.what(), "out of range")) << e.what();
    }
}

// Class 18: a camera too far from what it looks at is refused for that, not for its up vector.
TEST(SceneLoaderHostile, ACameraOutOfTheArithmeticsRangeNamesTheRealProblem) {
    for (const char* eye : {"[0, 0, 1.34e154]", "[0, 0, 1e300]", "[-1e308, 0, 0]"}) {
        try {
            load(std::string("{\"camera\": {\"eye\": ") + eye +
                 ",\n\"look_at\": [1e308, 0, 0]},\n"
                 "\"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}");
            ADD_FAILURE() << eye;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.key(), "camera.look_at") << e.what();
            EXPECT_TRUE(contains(e.what(), "too far")) << e.what();
        }
    }
    try {
        load(
            "{\"camera\": {\"up\": [0, 1e200, 0]},\n"
            "\"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}");
        ADD_FAILURE();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.key(), "camera.up") << e.what();
        EXPECT_TRUE(contains(e.what(), "length")) << e.what();
    }
    // Far but within the kernels' range: loads, and the camera's rays are unit vectors.
    const Scene s = load(
        "{\"camera\": {\"eye\": [0, 0, 1e55], \"look_at\": [0, 0, 0]},"
        "\"objects\": [{\"type\": \"sphere\", \"radius\": 1e54}]}");
    EXPECT_NEAR(s.camera.generateRay(1, 1, 4, 4).dir.z, -1.0, 0.1);
}

// Class 16: geometry past the range where the intersection kernels are exact (their squares
// overflow, or their products underflow) used to load and render with silent misses; it is
// refused naming the object, light or camera that leaves the range.
TEST(SceneLoaderHostile, GeometryOutsideTheKernelsRangeIsRefusedByName) {
    const auto keyOf = [](const std::string& text) -> std::string {
        try {
            load(text);
            return "(loaded)";
        } catch (const SceneError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
            return e.key() + " | " + what;
        }
    };
    const std::string unit = "{\"type\": \"sphere\", \"radius\": 1}";
    const std::string camera = "\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n";
    // A sphere far away, a triangle with one far vertex, a huge radius: each named by its index.
    for (const std::string& far :
         {std::string("{\"type\": \"sphere\", \"center\": [1e200, 0, 0], \"radius\": 1}"),
          std::string("{\"type\": \"triangle\", \"vertices\": [[0,0,0],[1,0,0],[0,-1e61,0]]}"),
          std::string("{\"type\": \"sphere\", \"radius\": 2e60}")}) {
        const std::string k = keyOf("{" + camera + "\"objects\": [" + unit + ",\n" + far + "]}");
        EXPECT_EQ(k.substr(0, k.find(" | ")), "objects[1]") << k;
        EXPECT_TRUE(contains(k, "beyond 1e+60")) << k;
    }
    // A light far away.
    std::string k =
        keyOf("{" + camera +
              "\"lights\": [{\"position\": [0, 0, 0]}, {\"position\": [0, 3e100, 0]}],\n"
              "\"objects\": [" +
              unit + "]}");
    EXPECT_EQ(k.substr(0, k.find(" | ")), "lights[1].position") << k;
    // A whole scene below the range: camera and sphere within 1e-70 of the origin.
    k = keyOf(
        "{\"camera\": {\"eye\": [0, 0, 5e-71], \"look_at\": [0, 0, 0]},\n"
        "\"objects\": [{\"type\": \"sphere\", \"radius\": 1e-71}]}");
    EXPECT_EQ(k.substr(0, k.find(" | ")), "objects[0]") << k;
    EXPECT_TRUE(contains(k, "underflow")) << k;
    // A primitive too small for its squares: a sphere of radius 1e-165 just ahead of the eye
    // filled the whole image (r^2 and the ray's distance^2 both underflow to 0); a triangle with
    // edges of 1e-70. Each named by its index, whatever the size of the rest of the scene.
    for (const std::string& tiny :
         {std::string("{\"type\": \"sphere\", \"center\": [0, 0, 4.9999], \"radius\": 1e-165}"),
          std::string("{\"type\": \"triangle\", \"vertices\": [[0,0,0],[1e-70,0,0],[0,1e-70,0]]}"),
          std::string("{\"type\": \"sphere\", \"radius\": 1e-200}")}) {
        k = keyOf("{" + camera + "\"objects\": [" + unit + ",\n" + tiny + "]}");
        EXPECT_EQ(k.substr(0, k.find(" | ")), "objects[1]") << k;
        EXPECT_TRUE(contains(k, "underflow")) << k;
    }
    // Scenes near both ends of the range load.
    EXPECT_EQ(keyOf("{\"camera\": {\"eye\": [0, 0, 5e59], \"look_at\": [0, 0, 0]},\n"
                    "\"objects\": [{\"type\": \"sphere\", \"radius\": 1e59}]}"),
              "(loaded)");
    EXPECT_EQ(keyOf("{\"camera\": {\"eye\": [0, 0, 5e-59], \"look_at\": [0, 0, 0]},\n"
                    "\"objects\": [{\"type\": \"sphere\", \"radius\": 1e-59}]}"),
              "(loaded)");
}

/// Loads a scene of one mesh whose OBJ text is `obj`; returns the error ("" if none).
std::string objError(const std::string& obj, std::size_t* triangles = nullptr) {
    const FileResolver resolver = [&](const std::string&) { return std::optional(obj); };
    try {
        const Scene s =
            load("{\"objects\": [{\"type\": \"mesh\", \"file\": \"m.obj\"}]}", resolver);
        if (triangles) *triangles = s.triangles.size();
        return "";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.key(), "objects[0].file");
        return e.what();
    }
}

// Class 9: the OBJ check reads lines as tinyobjloader does (leading blanks and tabs; LF, CRLF and
// CR-only line ends) and names the OBJ line of a bad vertex or face index.
TEST(SceneLoaderHostile, ObjLinesAreCheckedAsTinyobjloaderReadsThem) {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const std::pair<std::string, std::string> cases[] = {
        {"v 0 0 0\n  v 1 0 nan\nv 0 1 0\nf 1 2 3\n",
         "OBJ file 'm.obj' line 2: vertex coordinate 'nan' is not a finite number"},
        {"v 0 0 0\n\tv\t1\tabc\t0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 'abc'"},
        {"v 0 0 0\rv 1 0 0\rv 0 1 inf\rf 1 2 3\r", "line 3: vertex coordinate 'inf'"},
        {"v 0 0 0\r\nv 1 0 0\r\nv 0 1 0x1p3\r\nf 1 2 3\r\n", "line 3: vertex coordinate '0x1p3'"},
        {"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "line 2: a vertex needs 3 coordinates"},
        {"v 0 0 0\nv \nv 0 1 0\nf 1 2 3\n", "line 2: a vertex needs 3 coordinates"},
        // tinyobjloader reads the mantissa digit by digit: past 1e308 it is infinity, whatever
        // the exponent says.
        {"v 0 0 0\nv 1" + std::string(400, '0') + "e-300 0 0\nv 0 1 0\nf 1 2 3\n",
         "line 2: vertex coordinate '1000"},
        {tri + "f 1 2 4294967297\n",
         "line 4: vertex index 4294967297 is out of range (3 vertices)"},
        {tri + " f 1/1/1 2/2/2 7/7/7\n", "line 4: vertex index 7 is out of range (3 vertices)"},
        {tri + "f -1 -2 -4\n", "line 4: vertex index -4 is out of range (3 vertices"},
        {tri + "f 1 2 0\n", "line 4: vertex index 0 is out of range"},
        {tri + "f 1 2 x\n", "line 4: face vertex 'x' is not an index"},
        {tri + "f 1 2 3/1/1/1\n", "line 4: face vertex '3/1/1/1' is not an index"},
        {tri + "f 1 2\n", "line 4: a face needs at least 3 vertices"},
        {tri + "f 1 2 3\nf 1 2 4\n", "line 5: vertex index 4 is out of range (3 vertices)"},
        {std::string("v 0 0 0\nv 1 0 0\nv 0 1\0 0\nf 1 2 3\n", 33), "line 3: a NUL byte"},
    };
    for (const auto& [obj, message] : cases) {
        const std::string what = objError(obj);
        EXPECT_TRUE(contains(what, message)) << what << "\nfor: " << obj;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_LT(what.size(), 300u) << what;
    }
    std::string polygon = tri;
    for (int i = 0; i < 300; ++i)
        polygon += "v " + std::to_string(std::cos(i * 0.02)) + " " +
                   std::to_string(std::sin(i * 0.02)) + " 0\n";
    polygon += "f";
    for (int i = 4; i <= 303; ++i) (polygon += ' ') += std::to_string(i);  // GCC 12: no -Wrestrict
    EXPECT_TRUE(contains(objError(polygon + "\n"), "line 304: a face has at most 256 vertices"));
    // 254 triangles a face: the 39,371st face passes 10M.
    std::string face = "f";
    for (int i = 0; i < 256; ++i) face += i % 2 ? " 2" : " 1";
    std::string many = tri;
    for (int i = 0; i < 39371; ++i) many += face + "\n";
    EXPECT_TRUE(contains(objError(many), "line 39374: more than 10000000 triangles"));

    // What tinyobjloader reads and the check must let through: forward and relative indices,
    // v/vt/vn, a vertex colour, a trailing comment, groups and other statements.
    for (const std::string& obj : std::vector<std::string>{
             "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", tri + "f -3 -2 -1\n",
             tri + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n", tri + "f 1//1 2//1 3//1\n",
             "v 0 0 0 1 0 0\nv 1 0 0 # corner\nv +0 .1e1 -0.\no thing\ng a b\ns off\n"
             "usemtl x\nmtllib none.mtl\nl 1 2\np 1\nt tag 1/0/0 7\nf\t1 2 3 \n"}) {
        std::size_t triangles = 0;
        EXPECT_EQ(objError(obj, &triangles), "") << obj;
        EXPECT_EQ(triangles, 1u) << obj;
    }
}

// Class 1: paths the file system refuses to resolve are one SceneError each, not an abort.
TEST(SceneLoaderHostile, UnresolvablePathsAreSceneErrors) {
    const TempDir dir;
    fs::create_symlink(dir.path / "b", dir.path / "a");
    fs::create_symlink(dir.path / "a", dir.path / "b");
    const std::string loop = (dir.path / "a").string();
    const std::string longName = (dir.path / std::string(300, 'x')).string() + "/scene.json";
    const std::string underFile = (dir.path / "file.json").string() + "/scene.json";
    std::ofstream(dir.path / "file.json") << kMinimal;
    for (const std::string& path : {loop, longName, underFile}) {
        SCOPED_TRACE(path);
        for (const auto& f : std::vector<std::function<void()>>{[&] { loadScene(path); },
                                                                [&] { loadSceneFile(path); },
                                                                [&] { loadAnyScene(path); }}) {
            const std::string what = errorOf(f);
            EXPECT_FALSE(contains(what, "other exception")) << what;
            EXPECT_FALSE(what.empty());
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
    EXPECT_TRUE(contains(errorOf([&] { loadScene(loop); }), "symbolic links"));
    EXPECT_TRUE(contains(errorOf([&] { loadScene(longName); }), "too long"));
    // A mesh behind such a path names the scene's key and the mesh.
    std::ofstream(dir.path / "scene.json")
        << "{\"objects\": [\n{\"type\": \"mesh\", \"file\": \"a\"}]}";
    const std::string what = errorOf([&] { loadSceneFile((dir.path / "scene.json").string()); });
    EXPECT_TRUE(contains(what, "scene.json:2: key 'objects[0].file': cannot read OBJ file 'a'"))
        << what;
}

// Class 13: special files are refused before they are read (no hang, no unbounded memory), and
// a file over the cap is refused by its size.
TEST(SceneLoaderHostile, OnlyRegularFilesOfBoundedSizeAreRead) {
    const TempDir dir;
    const fs::path fifo = dir.path / "fifo.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const std::string& path : {std::string("/dev/zero"), std::string("/dev/urandom"),
                                    fifo.string(), dir.path.string()}) {
        SCOPED_TRACE(path);
        for (const auto& f : std::vector<std::function<void()>>{[&] { loadScene(path); },
                                                                [&] { loadSceneFile(path); },
                                                                [&] { loadAnyScene(path); }}) {
            const std::string what = errorOf(f, fifo);
            EXPECT_TRUE(contains(what, path + ": cannot read the scene file: ")) << what;
            EXPECT_TRUE(
                contains(what, path == dir.path.string() ? "a folder" : "not a regular file"))
                << what;
        }
        // The same file as a mesh.
        std::ofstream(dir.path / "mesh.json")
            << "{\"objects\": [\n{\"type\": \"mesh\", \"file\": \"" + path + "\"}]}";
        const std::string what =
            errorOf([&] { loadSceneFile((dir.path / "mesh.json").string()); }, fifo);
        EXPECT_TRUE(contains(what, "mesh.json:2: key 'objects[0].file': cannot read OBJ file"))
            << what;
    }
    // Sparse files over the caps: refused by their size, nothing is read.
    std::ofstream(dir.path / "big.json").close();
    fs::resize_file(dir.path / "big.json", (8u << 20) + 1);
    std::string what = errorOf([&] { loadScene((dir.path / "big.json").string()); });
    EXPECT_TRUE(contains(what, "big.json: cannot read the scene file: larger than 8 MB")) << what;
    std::ofstream(dir.path / "big.obj").close();
    fs::resize_file(dir.path / "big.obj", (256u << 20) + 1);
    std::ofstream(dir.path / "mesh.json")
        << "{\"objects\": [\n{\"type\": \"mesh\", \"file\": \"big.obj\"}]}";
    what = errorOf([&] { loadSceneFile((dir.path / "mesh.json").string()); });
    EXPECT_TRUE(contains(what, "cannot read OBJ file 'big.obj': larger than 256 MB")) << what;
}

}  // namespace
}  // namespace raystep
