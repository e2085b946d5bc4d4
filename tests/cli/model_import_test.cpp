// `raystep-cli render MODEL`: models of every format rendered with a tree by default, the scene
// around them saved and loaded back, and bad model files as one line and exit code 2.
#include "cli_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using raystep::testing::CliFolder;
using raystep::testing::CliResult;
const std::string kModels = RAYSTEP_SOURCE_DIR "/tests/data/models/";
const std::string kBunny = "/usr/share/glmark2/models/bunny.obj";

class ModelCli : public CliFolder {
  protected:
    nlohmann::json stats() { return nlohmann::json::parse(slurp(dir / "s.json")); }
    /// Exit code 2, one line on stderr naming `file` and saying `why`, and no file written.
    void expectBad(const std::string& args, const std::string& file, const std::string& why) {
        SCOPED_TRACE(args);
        expectOneLine(run(args), file, why);
        for (const auto& e : fs::directory_iterator(dir))
            EXPECT_FALSE(e.path().extension() == ".png" || e.path().extension() == ".json")
                << "bad input left " << e.path();
    }
};

TEST_F(ModelCli, EveryFormatRendersWithTheFastPathByDefault) {
    // Triangles of each model (worked out by hand, in the files' comments) plus the floor's 2.
    const std::vector<std::pair<std::string, int>> models = {
        {"pyramid.obj", 6},      {"tetra.ply", 4}, {"square.stl", 2},
        {"wedge_binary.stl", 3}, {"quad.gltf", 2}, {"quad.glb", 2}};
    for (const auto& [file, triangles] : models) {
        SCOPED_TRACE(file);
        const CliResult r =
            run("render '" + kModels + file + "' -o m.png --width 64 --height 48 --stats s.json");
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_TRUE(fs::exists(dir / "m.png"));
        const auto s = stats();
        EXPECT_EQ(s["primitives"]["triangles"], triangles + 2);
        EXPECT_EQ(s["accel"], "fast");
        // The model is in the picture: some pixel tested a primitive.
        EXPECT_GT(s["max_primitive_tests_per_pixel"].get<int>(), 0);
    }
}

TEST_F(ModelCli, BunnyRendersWithATreeNotBruteForce) {
    const CliResult r =
        run("render " + kBunny + " -o bunny.png --width 160 --height 120 --stats s.json");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto s = stats();
    EXPECT_EQ(s["primitives"]["triangles"], 69666 + 2);
    EXPECT_EQ(s["accel"], "fast");
    // A tree tests a few dozen triangles a pixel at most; brute force would test all 69,668.
    EXPECT_LT(s["max_primitive_tests_per_pixel"].get<int>(), 5000);
    // With a kernel option and no --accel, a model still gets a kd-tree, not brute force.
    const CliResult k =
        run("render " + kBunny +
            " -o bunny.png --width 40 --height 30 --stats s.json --precision double");
    ASSERT_EQ(k.code, 0) << k.err;
    EXPECT_EQ(stats()["accel"], "kdtree sah");
}

TEST_F(ModelCli, AStructureGivenIsKept) {
    const CliResult r = run("render '" + kModels + "tetra.ply' -o m.png --width 32 --height 24 " +
                            "--accel bruteforce --stats s.json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(stats()["accel"], "bruteforce");
    const CliResult b = run("render '" + kModels + "tetra.ply' -o m.png --width 32 --height 24 " +
                            "--accel bvh --split median --stats s.json");
    ASSERT_EQ(b.code, 0) << b.err;
    EXPECT_EQ(stats()["accel"], "bvh median");
}

TEST_F(ModelCli, SavedSceneRendersTheSamePicture) {
    const CliResult r =
        run("render '" + kModels +
            "quad.glb' -o a.png --width 64 --height 48 --save-scene quad-scene.json");
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_TRUE(fs::exists(dir / "quad-scene.json"));
    ASSERT_TRUE(fs::exists(dir / "quad-scene.mesh.obj"));
    EXPECT_NE(r.out.find("quad-scene.mesh.obj"), std::string::npos) << r.out;
    const CliResult back =
        run("render quad-scene.json -o b.png --width 64 --height 48 --accel kdtree --stats s.json");
    ASSERT_EQ(back.code, 0) << back.err;
    EXPECT_EQ(stats()["primitives"]["triangles"], 4);
    EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
}

TEST_F(ModelCli, BadModelsAreOneLineAndExitTwo) {
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"missing.obj", "no such file"},
        {"empty.stl", "empty"},
        {"truncated.stl", "header says 3 triangles, which take 234 bytes"},
        {"garbage.ply", "not a PLY file"},
        {"nan_vertex.obj", "not a finite number"},
        {"nan_vertex.ply", "not a finite number"},
        {"no_triangles.obj", "no triangles"},
        {"truncated.ply", "declares 5 'face' elements"},
        {"huge_count.ply", "declares 3000000 'vertex' elements"}};
    for (const auto& [file, why] : bad)
        expectBad("render '" + kModels + file + "' -o m.png --save-scene m.json", file, why);
}

TEST_F(ModelCli, FoldersAndFifosAreRefusedWithoutWaiting) {
    fs::create_directories(dir / "folder.obj");
    ASSERT_EQ(::mkfifo((dir / "pipe.glb").c_str(), 0600), 0);
    fs::copy_file(kModels + "external.gltf", dir / "external.gltf");
    ASSERT_EQ(::mkfifo((dir / "external.bin").c_str(), 0600), 0);
    expectBad("render folder.obj -o m.png", "folder.obj", "it is a folder");
    expectBad("render pipe.glb -o m.png", "pipe.glb", "not a regular file");
    expectBad("render external.gltf -o m.png", "external.bin", "not a regular file");
}

TEST_F(ModelCli, SaveSceneIsCheckedBeforeTheWork) {
    expectBad("render default --save-scene s.json", "default", "only a model");
    expectBad("render '" + kModels + "tetra.ply' --save-scene s.png", "s.png", "*.json");
    // The mesh written beside the scene must not be the model itself.
    fs::copy_file(kModels + "pyramid.obj", dir / "p.mesh.obj");
    expectBad("render p.mesh.obj -o m.png --save-scene p.json", "p.mesh.obj", "--save-scene");
    EXPECT_EQ(slurp(dir / "p.mesh.obj"), slurp(kModels + "pyramid.obj"));
}

}  // namespace
