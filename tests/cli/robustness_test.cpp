// Every defect class of review 3 (robustness.md) as the CLI meets it, each input made here:
// models that crashed, hung or blew up assimp, outputs that overwrote what the input refers
// to, other commands given models, unsupported types, --threads past the cores, a kill during
// the write, and the importer process's own failures. Each bad input: one line naming the file
// (and its line or key), exit code 2, old outputs untouched, nothing new written.
#include "cli_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace {

namespace fs = std::filesystem;
using raystep::testing::CliFolder;
using raystep::testing::CliResult;
const std::string kModels = RAYSTEP_SOURCE_DIR "/tests/data/models/";

std::string binary(std::initializer_list<std::uint32_t> words) {
    std::string s;
    for (const std::uint32_t w : words) s.append(reinterpret_cast<const char*>(&w), 4);
    return s;
}

class Robust : public CliFolder {
  protected:
    /// The folder's files and their bytes.
    std::map<std::string, std::string> folder() {
        std::map<std::string, std::string> files;
        for (const auto& e : fs::directory_iterator(dir))
            files[e.path().filename().string()] = slurp(e.path());
        return files;
    }
    /// Exit 2, one line naming `file` and saying `why`, within 10 s, the folder as it was.
    void expectRefused(const std::string& args, const std::string& file, const std::string& why) {
        SCOPED_TRACE(args);
        const auto before = folder();
        const CliResult r = run(args);
        expectOneLine(r, file, why);
        EXPECT_LT(r.seconds, 10.0) << r.err;  // refused, not hung until the 120 s timeout
        EXPECT_EQ(folder(), before) << "a refused command changed the folder";
    }
};

// Class 1: nesting past raystep's JSON cap (64) is refused by its own parser before assimp's,
// which recursed once a level (200,000 levels: a stack overflow). Also in a glb's JSON chunk.
TEST_F(Robust, DeeplyNestedGltfAndGlbAreRefusedByRaystepsParser) {
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"extras\":" + std::string(200000, '[') +
        std::string(200000, ']') + "}";
    write("deep.gltf", json);
    std::string chunk = json + std::string((4 - json.size() % 4) % 4, ' ');
    write("deep.glb", binary({0x46546C67, 2, std::uint32_t(20 + chunk.size()),
                              std::uint32_t(chunk.size()), 0x4E4F534A}) +
                          chunk);
    expectRefused("render deep.gltf -o o.png", "deep.gltf:1:", "nested deeper than 64 levels");
    expectRefused("render deep.glb -o o.png", "deep.glb:1:", "nested deeper than 64 levels");
}

// Class 2: assimp built a node chain recursively (20,000 crashed). A tree deeper than 256
// levels is refused, naming the node; so is a cycle, and a node with two parents (class 11).
TEST_F(Robust, NodeChainsCyclesAndSharedChildrenAreRefused) {
    std::string nodes;
    for (int i = 0; i < 20000; ++i) nodes += "{\"children\": [" + std::to_string(i + 1) + "]},\n";
    nodes += "{}";
    write("chain.gltf",
          "{\"asset\": {\"version\": \"2.0\"}, \"scene\": 0, \"scenes\": "
          "[{\"nodes\": [0]}],\n\"nodes\": [\n" +
              nodes + "]}\n");
    // nodes[256] is at depth 257 (the root nodes[0] is at 1); its line is 256 + 3.
    expectRefused("render chain.gltf -o o.png", "chain.gltf:259: key 'nodes[256]'",
                  "deeper than 256 levels");
    write("cycle.gltf",
          R"({"asset": {"version": "2.0"}, "nodes": [{}, {"children": [2]}, {"children": [1]}]})");
    expectRefused("render cycle.gltf -o o.png", "key 'nodes[1]'", "its own ancestor");
    // Each node lists the next twice: every level doubles what assimp builds (2^22 at 22).
    std::string dag;
    for (int i = 0; i < 22; ++i)
        dag += "{\"children\": [" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]},";
    write("dag.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [" + dag + "{}]}");
    expectRefused("render dag.gltf -o o.png", "key 'nodes[0].children[1]'",
                  "node 1 has a second parent here");
}

// Class 3 and 7: a PLY header without an end_header line of its own (assimp looped for ever,
// or read past its buffer), and the four ways past the earlier check: "comment end_header", a
// leading newline, "PLY" in capitals, CR-only line ends.
TEST_F(Robust, PlyHeadersAreReadByRaystepFirst) {
    const std::string elements =
        "format ascii 1.0\nelement vertex 300000000\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    write("noend1.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
          "property float z\n0 0 0\n");
    write("noend2.ply",
          "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float "
          "x\n" +
              std::string(8, '\0'));
    write("twice.ply",
          "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_headerend_header\n0\n");
    write("bypass.ply", "ply\ncomment end_header\n" + elements);
    write("lead.ply", "\nply\n" + elements);
    write("upper.ply", "PLY\n" + elements);
    std::string cr = "ply\n" + elements;
    std::replace(cr.begin(), cr.end(), '\n', '\r');
    write("cr.ply", cr);
    std::string three = elements;
    three.replace(three.find("300000000"), 9, "3000000");
    write("three-million.ply", "ply\ncomment end_header\n" + three);
    expectRefused("render noend1.ply -o o.png", "noend1.ply:7:", "no 'end_header' line");
    expectRefused("render noend2.ply -o o.png", "noend2.ply:5:", "no 'end_header' line");
    expectRefused("render twice.ply -o o.png",
                  "twice.ply:5:", "'end_headerend_header' is no PLY header statement");
    // 300 million vertices: more than the 30 million a model may have (3 per triangle).
    expectRefused("render bypass.ply -o o.png",
                  "bypass.ply:4:", "declares 300000000 'vertex' elements, more than the 30000000");
    expectRefused("render lead.ply -o o.png", "lead.ply:1:", "begins with the line 'ply'");
    expectRefused("render upper.ply -o o.png", "upper.ply:1:", "begins with the line 'ply'");
    expectRefused("render cr.ply -o o.png", "cr.ply:1:", "end with CR alone");
    // 3 million declared, 3 given (it rendered with exit 0 after 6 s): the 4th is missing.
    expectRefused("render three-million.ply -o o.png", "three-million.ply:4:",
                  "declares 3000000 'vertex' elements, but the file ends inside number 4");
}

// Class 6: a texture statement before any newmtl crashed assimp's MTL parser. raystep gives
// assimp no .mtl at all (a model's materials are not used): the model renders. So do a
// missing .mtl and a 6-byte one (class 16e: they made the real error or a good model fail).
TEST_F(Robust, AnObjsMtlIsNeverReadSoItCannotCrashOrFailTheModel) {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    write("model.obj", "mtllib mk.mtl\n" + tri);
    write("mk.mtl", "map_Kd tex.png\n");
    write("missing.obj", "mtllib nosuch.mtl\n" + tri);
    write("small.obj", "mtllib small.mtl\n" + tri);
    write("small.mtl", "newmt\n");
    for (const char* model : {"model.obj", "missing.obj", "small.obj"}) {
        const CliResult r =
            run(std::string("render ") + model + " -o o.png --width 16 --height 12");
        EXPECT_EQ(r.code, 0) << model << ": " << r.err;
        EXPECT_TRUE(fs::exists(dir / "o.png")) << model;
        fs::remove(dir / "o.png");
    }
}

// Class 8: an ASCII list's count was never compared with the words after it (a 120-byte file
// asked for 1.6 GB). A face's count is at most 256; any list's count must be there.
TEST_F(Robust, AsciiPlyListCountsAreCheckedAgainstTheWordsPresent) {
    const std::string head =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n";
    write("count.ply", head +
                           "property list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n"
                           "0 1 0\n200000000 0 1 2\n");
    expectRefused("render count.ply -o o.png",
                  "count.ply:13:", "a face has at most 256 vertices, this one 200000000");
    write("short.ply", head +
                           "property list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n"
                           "0 1 0\n4 0 1 2\n");
    expectRefused("render short.ply -o o.png",
                  "short.ply:7:", "declares 1 'face' elements, but the file ends inside number 0");
    write("index.ply", head +
                           "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n"
                           "0 1 0\n3 0 1 7\n");
    expectRefused("render index.ply -o o.png",
                  "index.ply:13:", "vertex index 7 is out of range (3 vertices)");
}

// Class 9: a glb's chunk lengths were trusted (0xFFFFFFF0 for the JSON of a 940-byte file made
// assimp touch 4.2 GB). They are compared with the file's size first.
TEST_F(Robust, GlbChunkLengthsAreComparedWithTheFile) {
    const std::string json =
        std::string("{\"asset\":{\"version\":\"2.0\"}}") + std::string(900, ' ');
    write("json-4g.glb",
          binary({0x46546C67, 2, 940, 0xFFFFFFF0, 0x4E4F534A}) + json.substr(0, 920));
    expectRefused("render json-4g.glb -o o.png", "json-4g.glb",
                  "the glb's JSON chunk says 4294967280 bytes, the file has 920");
    write("total.glb", binary({0x46546C67, 2, 100000, 920, 0x4E4F534A}) + json.substr(0, 920));
    expectRefused("render total.glb -o o.png", "total.glb",
                  "the glb's header says 100000 bytes, the file has 940");
    const std::string small = "{\"asset\":{\"version\":\"2.0\"}} ";  // 28 bytes
    write("bin.glb",
          binary({0x46546C67, 2, 56, 28, 0x4E4F534A}) + small + binary({0x7FFFFFFF, 0x004E4942}));
    expectRefused("render bin.glb -o o.png", "bin.glb", "the glb's binary chunk says 2147483647");
    write("v1.glb", binary({0x46546C67, 1, 48, 28, 0x4E4F534A}) + small);
    expectRefused("render v1.glb -o o.png", "v1.glb", "glb version 1: raystep reads glTF 2.0");
}

// Class 10 (a): OBJ polygons of up to 32,767 corners went through assimp's ear clipping (4 s
// each); the scene loader's cap of 256 now holds for models too. (b): a glTF instancing a point
// mesh from many nodes was walked once a node: the nodes' points are counted first.
TEST_F(Robust, ImportTimeIsBoundedBeforeAssimpStarts) {
    std::string poly;
    for (int i = 0; i < 300; ++i)
        poly += "v " + std::to_string(i % 17) + " " + std::to_string(i) + " 0\n";
    poly += "f";
    for (int i = 1; i <= 300; ++i) poly.append(" ").append(std::to_string(i));
    write("bigpoly.obj", poly + "\n");
    expectRefused("render bigpoly.obj -o o.png",
                  "bigpoly.obj:301:", "a face has at most 256 vertices, this one 300");
    // 1,000 nodes x 20,000 points = 20 million points, past the 10 million cap.
    std::string nodes;
    for (int i = 0; i < 1000; ++i) nodes += std::string(i ? "," : "") + "{\"mesh\": 0}";
    std::string roots;
    for (int i = 0; i < 1000; ++i) roots.append(i ? "," : "").append(std::to_string(i));
    write("points.bin", std::string(20000 * 12, '\0'));
    write("points.gltf",
          "{\"asset\": {\"version\": \"2.0\"}, \"scene\": 0, \"scenes\": [{\"nodes\": [" + roots +
              "]}], \"nodes\": [" + nodes +
              "], \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"mode\": "
              "0}]}], \"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": "
              "20000, \"type\": \"VEC3\"}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": "
              "240000}], \"buffers\": [{\"uri\": \"points.bin\", \"byteLength\": 240000}]}");
    expectRefused("render points.gltf -o o.png", "points.gltf",
                  "the model's nodes place more than");
}

// Class 11: memory amplified before the caps. Primitives sharing one accessor (each copies it:
// two of 10 million triangles of zeros, no buffer at all), and buffers naming one big file.
TEST_F(Robust, WhatAssimpWouldBuildIsCountedFirst) {
    write("shared.gltf",
          R"({"asset": {"version": "2.0"},
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1},
                            {"attributes": {"POSITION": 0}, "indices": 1}]}],
 "accessors": [{"componentType": 5126, "count": 3, "type": "VEC3"},
               {"componentType": 5125, "count": 30000000, "type": "SCALAR"}]})");
    // Each primitive: 30,000,000 indices / 3 = 10 million triangles; the second passes the cap.
    expectRefused("render shared.gltf -o o.png", "shared.gltf:3: key 'meshes[0].primitives[1]'",
                  "hold more than 10000000 triangles");
    // 30 buffers of one 10 MB file (a sparse file: no disk used) = 300 MB, past 256 MB.
    std::ofstream(dir / "big.bin").close();
    fs::resize_file(dir / "big.bin", 10 << 20);
    std::string buffers;
    for (int i = 0; i < 30; ++i)
        buffers += std::string(i ? "," : "") + "{\"uri\": \"big.bin\", \"byteLength\": 10485760}";
    write("repeated.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [" + buffers + "]}");
    expectRefused("render repeated.gltf -o o.png", "key 'buffers[25]'",
                  "the buffers add up to 272629760 bytes, more than the 256 MB");
}

// Class 12: an output naming a file the input refers to replaced it (a glTF's .bin by the
// stats, a scene's mesh, an .mtl, a texture). All are refused before the work, untouched.
TEST_F(Robust, NoOutputOverwritesAFileTheInputRefersTo) {
    fs::copy_file(kModels + "external.gltf", dir / "tetra.gltf");
    fs::copy_file(kModels + "external.bin", dir / "external.bin");
    expectRefused("render tetra.gltf -o o.png --stats external.bin", "--stats external.bin",
                  "the command reads this file");
    write("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("scene.json", R"({"objects": [{"type": "mesh", "file": "mesh.obj"}]})");
    expectRefused("render scene.json -o o.png --stats mesh.obj", "--stats mesh.obj",
                  "the command reads this file");
    expectRefused("trace scene.json --pixel 1,1 -o mesh.obj", "-o mesh.obj",
                  "the command reads this file");
    write("model.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("m.mtl", "newmtl a\nmap_Kd tex.png\n");
    write("tex.png", "not really a png");
    expectRefused("render model.obj -o o.png --stats m.mtl", "--stats m.mtl",
                  "the command reads this file");
    expectRefused("render model.obj -o tex.png", "-o tex.png", "the command reads this file");
    expectRefused("build model.obj --events m.mtl", "--events m.mtl",
                  "the command reads this file");
}

// Class 13: "v 2 abc 0" read as 0 by assimp (exit 0) but refused as a scene's mesh: one file,
// one answer, with its line.
TEST_F(Robust, ObjNumbersAreCheckedAsTheSceneLoaderChecksThem) {
    for (const char* junk : {"abc", "1,5", "0abc", "0x10"}) {
        SCOPED_TRACE(junk);
        write("junk.obj", std::string("v 0 0 0\nv 2 ") + junk + " 0\nv 0 1 0\nf 1 2 3\n");
        expectRefused("render junk.obj -o o.png", "junk.obj:2:",
                      std::string("vertex coordinate '") + junk + "' is not a finite number");
        write("s.json", R"({"objects": [{"type": "mesh", "file": "junk.obj"}]})");
        expectRefused("render s.json -o o.png", "line 2: vertex coordinate",
                      "is not a finite number");
        fs::remove(dir / "s.json");
    }
}

// Class 15: build, trace and compare read models as render does (they said "malformed JSON").
TEST_F(Robust, BuildTraceAndCompareTakeModels) {
    const std::string model = "'" + kModels + "tetra.ply'";
    const CliResult b = run("build " + model + " --json");
    ASSERT_EQ(b.code, 0) << b.err;
    // tetra.ply's 4 triangles and the floor's 2.
    EXPECT_EQ(nlohmann::json::parse(b.out)["primitives"], 6);
    const CliResult t = run("trace " + model + " --pixel 320,240 -o t.json");
    ASSERT_EQ(t.code, 0) << t.err;
    // A model is traced with a kd-tree unless --accel says (brute force records every test).
    EXPECT_EQ(nlohmann::json::parse(slurp(dir / "t.json"))["accel"], "kdtree sah");
    const CliResult c = run("compare " + model + " --width 16 --height 12 --json");
    ASSERT_EQ(c.code, 0) << c.err;
    EXPECT_EQ(nlohmann::json::parse(c.out)["results"].size(), 3u);
}

// gui.md 18 and review 3: a type raystep does not read is named as such, not "malformed JSON".
TEST_F(Robust, UnsupportedFileTypesAreNamedAsSuch) {
    write("cat.3ds", std::string("MM\0\0", 4));
    write("jellyfish.jobj", "{}");
    for (const char* cmd : {"render", "build", "compare"})
        for (const char* file : {"cat.3ds", "jellyfish.jobj"})
            expectRefused(std::string(cmd) + " " + file, file,
                          "not a scene or model raystep reads (.json, .obj, .ply, .stl, .gltf, "
                          ".glb)");
}

// Class 16: the model's messages name the line (an index out of range, a non-finite vertex)
// and the real reason (a float overflow is no NaN; a count of -1 or 2^64 is shown as written).
TEST_F(Robust, ModelMessagesNameTheLineAndTheRealReason) {
    write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n");
    expectRefused("render range.obj -o o.png",
                  "range.obj:5:", "vertex index 9 is out of range (3 vertices)");
    write("big.obj", "v 0 0 0\nv 1e308 0 0\nv 0 1 0\nf 1 2 3\n");
    expectRefused("render big.obj -o o.png", "big.obj:2:", "'1e308' is past the largest float");
    write("minus.ply", "ply\nformat ascii 1.0\nelement vertex -1\nproperty float x\nend_header\n");
    expectRefused("render minus.ply -o o.png", "minus.ply:3:", "count '-1' is not a whole number");
    write("huge.ply",
          "ply\nformat ascii 1.0\nelement vertex 18446744073709551616\nproperty float x\n"
          "end_header\n");
    expectRefused("render huge.ply -o o.png", "huge.ply:3:", "count '18446744073709551616'");
}

// Class 19: a strip without POSITION made assimp ask for 64 GB (2^32 - 2 faces).
TEST_F(Robust, APrimitiveWithoutPositionsIsRefused) {
    write("strip.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {}, "mode": 5}]}]})");
    expectRefused("render strip.gltf -o o.png",
                  "strip.gltf:2: key 'meshes[0].primitives[0].attributes'",
                  "no POSITION attribute");
}

// Class 20: --threads past what TBB gives printed TBB's warning, and the stats claimed them.
TEST_F(Robust, ThreadsAreClampedToTheCores) {
    cpu_set_t set;
    CPU_ZERO(&set);
    ASSERT_EQ(::sched_getaffinity(0, sizeof set, &set), 0);
    const int cores = CPU_COUNT(&set);
    const CliResult r =
        run("render default -o x.png --width 32 --height 24 --threads 1024 --stats s.json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(nlohmann::json::parse(slurp(dir / "s.json"))["threads"], cores);
}

// Class 21: a scene inside every cap asks for years of work, and the progress stayed at "0%".
// Its size is said before it starts (8192^2 x 4096 x (1 + 1024) = 2.8e14 rays: at 10 million a
// second, 326 days); the test ends it after 2 s.
TEST_F(Robust, ARenderOfYearsIsSaidBeforeItStarts) {
    write("maxed.json", R"({"render": {"width": 8192, "height": 8192, "spp": 4096,
 "diffuse_samples": 1024, "bounces": 64},
 "objects": [{"type": "sphere", "center": [0, 0, -3], "radius": 1}]})");
    const std::string cmd = "cd '" + dir.string() +
                            "' && timeout -s KILL 2 '" RAYSTEP_CLI
                            "' render maxed.json -o m.png > /dev/null 2> err.txt";
    (void)std::system(cmd.c_str());
    const std::string err = slurp(dir / "err.txt");
    EXPECT_NE(err.find("raystep-cli: warning: maxed.json asks for about 2.8e+14 camera and "
                       "diffuse rays (8192x8192 pixels, 4096 samples, 1024 diffuse rays each): "
                       "at 10 million rays a second, 326 days"),
              std::string::npos)
        << err;
    EXPECT_FALSE(fs::exists(dir / "m.png"));
}

// Class 17: Ctrl+C or SIGTERM while the outputs were being written left *.tmp.PID files. The
// signal now waits for the write. Sent the moment the first temporary is created (inotify),
// the command ends by it, with all three outputs complete and nothing else in the folder; or,
// when the signal came too late or too early, with all three or none: never a temporary.
TEST_F(Robust, ASignalDuringTheWriteLeavesNoTemporary) {
    int deferred = 0;
    for (int run = 0; run < 4; ++run) {
        const int sig = run % 2 ? SIGINT : SIGTERM;
        SCOPED_TRACE(run);
        for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
        const int watch = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
        ASSERT_GE(watch, 0);
        ASSERT_GE(::inotify_add_watch(watch, dir.c_str(), IN_CREATE), 0);
        const std::string d = dir.string();
        std::vector<std::string> args = {RAYSTEP_CLI,    "render",    "default",    "-o",
                                         d + "/out.png", "--width",   "900",        "--height",
                                         "900",          "--bounces", "0",          "--stats",
                                         d + "/st.json", "--heatmap", d + "/hm.png"};
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t fa;
        posix_spawn_file_actions_init(&fa);
        posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
        pid_t pid = 0;
        ASSERT_EQ(::posix_spawn(&pid, RAYSTEP_CLI, &fa, nullptr, argv.data(), environ), 0);
        posix_spawn_file_actions_destroy(&fa);
        bool sent = false;
        int status = 0;
        while (!sent && ::waitpid(pid, &status, WNOHANG) == 0) {
            pollfd p{watch, POLLIN, 0};
            if (::poll(&p, 1, 20) <= 0) continue;
            alignas(inotify_event) char buffer[4096];
            const ssize_t n = ::read(watch, buffer, sizeof buffer);
            for (ssize_t at = 0; n > 0 && at < n && !sent;) {
                const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
                if (e->len > 0 && std::strstr(e->name, ".tmp.")) {
                    ::kill(pid, sig);
                    sent = true;
                }
                at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
            }
        }
        if (sent) {
            ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        }
        ::close(watch);
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename());
        std::sort(names.begin(), names.end());
        const bool all = names == std::vector<std::string>{"hm.png", "out.png", "st.json"};
        EXPECT_TRUE(all || names.empty()) << ::testing::PrintToString(names);
        if (all) {
            EXPECT_TRUE(nlohmann::json::parse(slurp(dir / "st.json")).is_object());
            EXPECT_EQ(slurp(dir / "out.png").substr(1, 3), "PNG");
        }
        if (sent && WIFSIGNALED(status) && WTERMSIG(status) == sig && all) ++deferred;
    }
    // The signal met the write at least once (seen as a temporary), and the write went on.
    EXPECT_GE(deferred, 1);
}

// The importer process: whatever ends it is one line naming the model. A crash (as assimp's
// were), an abort, a kill; and it is ended with its parent.
TEST_F(Robust, TheImportersCrashIsOneLineNamingTheModel) {
    const std::vector<std::pair<std::string, std::string>> importers = {
        {"kill -SEGV $$", "crashed inside assimp (a segmentation fault)"},
        {"kill -ABRT $$", "crashed inside assimp (an abort)"},
        {"kill -XCPU $$", "more than 120 s of processor time"},
        {"kill -KILL $$", "was killed (by the system: out of memory?)"},
        {"echo garbage >&3; exit 0", "the model importer's answer is malformed"},
        {"exit 0", "ended without an answer (exit code 0)"}};
    for (const auto& [body, why] : importers) {
        write("importer", "#!/bin/sh\n" + body + "\n");
        fs::permissions(dir / "importer", fs::perms::owner_all);
        env = "RAYSTEP_IMPORTER='" + (dir / "importer").string() + "' ";
        expectRefused("render '" + kModels + "tetra.ply' -o o.png", "tetra.ply", why);
    }
}

// What a library inside the importer prints on its standard output is not its answer (that
// goes on descriptor 3): the real importer behind a script that prints first still answers.
TEST_F(Robust, WhatTheImporterPrintsIsNotItsAnswer) {
    const std::string real = (fs::path(RAYSTEP_CLI).parent_path() / "raystep-import").string();
    ASSERT_TRUE(fs::exists(real)) << real;
    write("importer", "#!/bin/sh\necho 'Info,  T0: Load tetra.ply'\nexec '" + real + "' \"$@\"\n");
    fs::permissions(dir / "importer", fs::perms::owner_all);
    env = "RAYSTEP_IMPORTER='" + (dir / "importer").string() + "' ";
    const CliResult r = run("render '" + kModels + "tetra.ply' -o o.png --width 16 --height 12");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "o.png"));
}

}  // namespace
