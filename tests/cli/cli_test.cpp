// raystep-cli end to end, as a lecturer's script would call it: exit codes, one-line errors,
// and no output file at all when the input is bad.
#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace {

namespace fs = std::filesystem;

struct CliRun {
    int code;
    std::string out;
    std::string err;
};

class Cli : public ::testing::Test {
  protected:
    fs::path dir = fs::temp_directory_path() /
                   ("raystep-cli-" + std::to_string(::getpid()) + "-" +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::string runAs;  // a prefix such as "runuser -u nobody -- "
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }

    static std::string slurp(const fs::path& p) {
        std::ifstream in(p);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    /// Runs raystep-cli in the test's folder. Ended after 120 s: a command blocked on a FIFO or
    /// in an endless loop fails its test (exit 124) instead of hanging the suite.
    CliRun run(const std::string& args, const std::string& stdoutTo = "out.txt") {
        const std::string cmd = std::string("cd '") + dir.string() + "' && timeout 120 " + runAs +
                                "'" + RAYSTEP_CLI "' " + args + " > " + stdoutTo +
                                " 2> err.txt < /dev/null";
        const int status = std::system(cmd.c_str());
        CliRun r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "out.txt"),
                 slurp(dir / "err.txt")};
        fs::remove(dir / "out.txt");
        fs::remove(dir / "err.txt");
        return r;
    }
    /// Bad input: exit code 2, exactly one line on stderr containing `expected`, no file written.
    void expectBadInput(const std::string& args, const std::string& expected) {
        const CliRun r = run(args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
        EXPECT_EQ(r.err.rfind("raystep-cli: error: ", 0), 0u) << r.err;
        EXPECT_TRUE(fs::is_empty(dir)) << "bad input left files behind: " << args;
    }
    /// Bad input in a folder that already holds files: nothing new written.
    void expectBadInputKeepFiles(const std::string& args, const std::string& expected) {
        std::size_t before = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++before;
        const CliRun r = run(args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
        std::size_t after = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++after;
        EXPECT_EQ(after, before) << args;
    }
    void write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
    }
    /// The folder's entries, names and contents (symlinks and FIFOs by kind, not followed).
    std::map<std::string, std::string> listing() {
        std::map<std::string, std::string> files;
        for (const auto& e : fs::directory_iterator(dir)) {
            const std::string name = e.path().filename().string();
            if (e.is_symlink())
                files[name] = "symlink to " + fs::read_symlink(e.path()).string();
            else if (e.is_fifo())
                files[name] = "fifo";
            else if (e.is_directory())
                files[name] = "folder";
            else
                files[name] = slurp(e.path());
        }
        return files;
    }
    /// Runs the CLI directly, its output thrown away; the exit code and peak memory in KB.
    static std::pair<int, long> runMeasured(std::vector<std::string> args) {
        const pid_t pid = ::fork();
        if (pid == 0) {
            const int null = ::open("/dev/null", O_WRONLY);
            ::dup2(null, STDOUT_FILENO);
            ::dup2(null, STDERR_FILENO);
            // Under AddressSanitizer freed memory is held back (256 MB) unless told otherwise.
            ::setenv("ASAN_OPTIONS", "quarantine_size_mb=0:detect_leaks=0", 1);
            std::vector<char*> argv{const_cast<char*>(RAYSTEP_CLI)};
            for (std::string& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            ::execv(RAYSTEP_CLI, argv.data());
            ::_exit(127);
        }
        int status = 0;
        rusage usage{};
        ::wait4(pid, &status, 0, &usage);
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, usage.ru_maxrss};
    }
};

TEST_F(Cli, ListsBuiltinScenes) {
    const CliRun r = run("scenes");
    EXPECT_EQ(r.code, 0);
    for (const char* name : {"default", "whitted", "cornell", "stadium"})
        EXPECT_NE(r.out.find(name), std::string::npos) << name;
}

TEST_F(Cli, RendersWithStatsAndHeatmap) {
    const CliRun r =
        run("render whitted -o w.png --width 40 --height 30 --spp 4 --bounces 3 "
            "--stats s.json --heatmap h.png --threads 2 --seed 7 --accel bruteforce");
    ASSERT_EQ(r.code, 0) << r.err;
    int w = 0, h = 0, n = 0;
    ASSERT_TRUE(stbi_info((dir / "w.png").c_str(), &w, &h, &n));
    EXPECT_EQ(w, 40);
    EXPECT_EQ(h, 30);
    ASSERT_TRUE(stbi_info((dir / "h.png").c_str(), &w, &h, &n));
    EXPECT_EQ(w, 40);
    const auto stats = nlohmann::json::parse(slurp(dir / "s.json"));
    EXPECT_EQ(stats["width"], 40);
    EXPECT_EQ(stats["height"], 30);
    EXPECT_EQ(stats["rays"]["primary"], 40 * 30 * 4);
    EXPECT_GT(stats["rays"]["shadow"].get<int>(), 0);
    EXPECT_GT(stats["rays"]["reflection"].get<int>(), 0);
    EXPECT_GT(stats["rays"]["refraction"].get<int>(), 0);
    EXPECT_EQ(stats["rays"]["diffuse"], 0);
    EXPECT_EQ(stats["node_visits"], 0);
    EXPECT_EQ(stats["mailbox_skips"], 0);
    // Brute force over 4 primitives: at least 4 tests per nearest-hit ray.
    EXPECT_GE(stats["primitive_tests"].get<long>(), 4L * 40 * 30 * 4);
    EXPECT_GT(stats["render_ms"].get<double>(), 0.0);
    EXPECT_EQ(stats["seed"], 7);
}

TEST_F(Cli, AWholeImageIsMadeByTheFastPathUnlessAStructureIsAsked) {
    const CliRun r = run("render whitted -o w.png --width 40 --height 30 --stats s.json");
    ASSERT_EQ(r.code, 0) << r.err;
    auto stats = nlohmann::json::parse(slurp(dir / "s.json"));
    EXPECT_EQ(stats["accel"], "fast");
    EXPECT_EQ(stats["precision"], "float");
    EXPECT_GT(stats["fast"]["nodes"].get<int>(), 0);
    // A kernel option asks for the teaching structures' kernels: the old default, brute force.
    const CliRun d =
        run("render whitted -o w.png --width 40 --height 30 --stats s.json "
            "--precision double");
    ASSERT_EQ(d.code, 0) << d.err;
    stats = nlohmann::json::parse(slurp(dir / "s.json"));
    EXPECT_EQ(stats["accel"], "bruteforce");
    EXPECT_EQ(stats["precision"], "double");
}

TEST_F(Cli, DefaultSceneAndOutputName) {
    const CliRun r = run("render --width 16 --height 12");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "default.png"));
    EXPECT_NE(r.out.find("default.png"), std::string::npos);
}

TEST_F(Cli, SceneFileWithMesh) {
    write("tri.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
    write("scene.json", R"({"lights": [{"position": [0, 0, 5]}],
                            "objects": [{"type": "mesh", "file": "tri.obj"}]})");
    const CliRun r = run("render scene.json -o img.png --width 8 --height 8");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "img.png"));
}

TEST_F(Cli, HelpExitsZero) {
    const CliRun r = run("render --help");
    EXPECT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("--diffuse-samples"), std::string::npos);
}

TEST_F(Cli, BadCommandLineValues) {
    expectBadInput("render --width 0", "--width");
    expectBadInput("render --width 9000", "--width");
    expectBadInput("render --height abc", "--height");
    expectBadInput("render --spp nan", "--spp");
    expectBadInput("render --bounces -1", "--bounces");
    expectBadInput("render --threads 0", "--threads");
    expectBadInput("render --seed inf", "--seed");
    expectBadInput("render --no-such-flag", "no-such-flag");
    expectBadInput("frobnicate", "frobnicate");
    expectBadInput("render --accel octree", "--accel octree");
    expectBadInput("render --split octal", "--split octal");
    expectBadInput("render --accel kdtree --c-isect 0", "--c-isect");
    expectBadInput("render --accel kdtree --c-trav nan", "--c-trav");
    expectBadInput("render --accel kdtree --empty-bonus 1.5", "--empty-bonus");
    expectBadInput("render --accel kdtree --max-depth 99", "--max-depth");
    expectBadInput("render --accel bvh --leaf-size 0", "--leaf-size");
    expectBadInput("render --accel bvh --buckets 1", "--buckets");
    expectBadInput("render --accel grid --grid-res 4,4", "--grid-res");
    // Each axis within its limit, the product past the grid's cap of 2^24 cells.
    expectBadInput("render --accel grid --grid-res 512,512,512", "more than the grid's 16777216");
    expectBadInput("build --accel grid --grid-res 300,300,300", "more than the grid's");
    expectBadInput("build --accel kdtree --kd-build quick",
                   "--kd-build quick: expected exact or fast");
    expectBadInput("build --accel kdtree --kd-build fast --bin-above 64",
                   "--bin-above and --kd-build");
    expectBadInput("build --accel octree", "--accel octree");
    expectBadInput("build nosuchscene", "nosuchscene");
    expectBadInput("build --events missing/e.json", "does not exist");
    expectBadInput("trace --pixel 10,10", "--output");
    expectBadInput("trace --pixel 1,x -o t.json", "--pixel 1,x");
    expectBadInput("trace --pixel -1,0 -o t.json", "--pixel");
    expectBadInput("trace --pixel 640,0 -o t.json", "outside the 640x480 image");
    expectBadInput("trace --pixel 0,0 -o missing/t.json", "does not exist");
    expectBadInput("compare --accel grid,octree", "--accel grid,octree: expected a comma list");
    expectBadInput("compare --accel grid,kdtree,grid", "grid twice");
    expectBadInput("compare --accel grid,bvh --split sah,middle", "--split sah,middle");
    expectBadInput("compare --accel grid,", "expected a comma list");
    expectBadInput("render -o picture.jpg", "*.png");
    expectBadInput("render -o missing/dir/x.png", "does not exist");
    expectBadInput("render --stats missing/s.json", "does not exist");
}

TEST_F(Cli, BuildReportsTheTree) {
    for (const char* accel : {"kdtree", "bvh"}) {
        for (const char* split : {"midpoint", "median", "sah"}) {
            const CliRun r =
                run(std::string("build default --json --accel ") + accel + " --split " + split);
            ASSERT_EQ(r.code, 0) << r.err;
            const auto j = nlohmann::json::parse(r.out);
            const std::string what = std::string(accel) + " " + split;
            EXPECT_EQ(j["structure"], what);
            // A binary tree: every interior node has two children.
            EXPECT_EQ(j["nodes"].get<int>(), 2 * j["leaves"].get<int>() - 1) << what;
            EXPECT_GE(j["references"].get<int>(), 9) << what;  // 9 primitives, each listed
            EXPECT_GT(j["sah_cost"].get<double>(), 0.0) << what;
            EXPECT_GE(j["build_ms"].get<double>(), 0.0) << what;
            EXPECT_GE(j["max_depth"].get<int>(), 1) << what;
        }
    }
    const CliRun grid = run("build default --accel grid --grid-res 4,5,6 --json");
    ASSERT_EQ(grid.code, 0) << grid.err;
    EXPECT_EQ(nlohmann::json::parse(grid.out)["nodes"], 4 * 5 * 6);
    const CliRun text = run("build stadium --accel kdtree");
    ASSERT_EQ(text.code, 0) << text.err;
    EXPECT_NE(text.out.find("SAH cost"), std::string::npos);
}

TEST_F(Cli, BuildEventsAreATraceFile) {
    const CliRun r = run("build default --accel kdtree --split sah --events b.json --json");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto report = nlohmann::json::parse(r.out);
    const auto t = nlohmann::json::parse(slurp(dir / "b.json"));
    EXPECT_EQ(t["format"], "raystep-trace");
    EXPECT_EQ(t["version"], 1);
    EXPECT_EQ(t["what"], "build");
    std::map<std::string, int> count;
    for (const auto& e : t["events"]) ++count[e["type"].get<std::string>()];
    EXPECT_EQ(count["build_node"], report["nodes"].get<int>());
    EXPECT_EQ(count["leaf_made"], report["leaves"].get<int>());
    EXPECT_EQ(count["split_chosen"], report["nodes"].get<int>() - report["leaves"].get<int>());
    EXPECT_GT(count["split_candidate"], count["split_chosen"]);
    EXPECT_EQ(t["nodes"].size(), report["nodes"].get<std::size_t>());
    // A cap: the file says how much it dropped, and the user is told on one line.
    const CliRun capped = run("build default --accel kdtree --events c.json --max-events 10");
    ASSERT_EQ(capped.code, 0) << capped.err;
    EXPECT_NE(capped.err.find("event cap of 10 reached"), std::string::npos) << capped.err;
    const auto c = nlohmann::json::parse(slurp(dir / "c.json"));
    EXPECT_EQ(c["events"].size(), 10u);
    EXPECT_GT(c["dropped"].get<int>(), 0);
}

TEST_F(Cli, TraceRecordsAPixelsRayTree) {
    const CliRun r = run("trace default --pixel 300,260 --accel grid -o t.json");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto t = nlohmann::json::parse(slurp(dir / "t.json"));
    EXPECT_EQ(t["what"], "pixel");
    EXPECT_EQ(t["pixel"], nlohmann::json::array({300, 260}));
    EXPECT_EQ(t["rays"][0]["kind"], "primary");
    EXPECT_TRUE(t["rays"][0]["parent"].is_null());
    std::map<std::string, int> count;
    for (const auto& e : t["events"]) ++count[e["type"].get<std::string>()];
    EXPECT_GT(count["dda_setup"], 0);
    EXPECT_GT(count["dda_cell"], 0);
    EXPECT_GT(count["primitive_test"], 0);
    EXPECT_EQ(count["pixel_result"], 1);
    EXPECT_EQ(count["ray_begin"], static_cast<int>(t["rays"].size()));
    EXPECT_EQ(t["events"].back()["type"], "pixel_result");
}

TEST_F(Cli, TwoDimensionalLectureScenes) {
    // The slides' DDA example: cells (0,0) (1,0) (1,1) (2,1) (3,1) ..., and the nearest hit found
    // in cell (4,2) after a farther hit in cell (3,2): by hand, the small circle (4.3, 2.3) r 0.25
    // at t = (3.88 - sqrt(0.0484)) / 0.8 = 4.575.
    const CliRun r = run("trace lecture-grid --accel grid -o g.json");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto t = nlohmann::json::parse(slurp(dir / "g.json"));
    std::vector<std::vector<int>> cells;
    for (const auto& e : t["events"])
        if (e["type"] == "dda_cell") cells.push_back({e["cell"][0], e["cell"][1]});
    ASSERT_GE(cells.size(), 5u);
    EXPECT_EQ(cells[0], (std::vector<int>{0, 0}));
    EXPECT_EQ(cells[1], (std::vector<int>{1, 0}));
    EXPECT_EQ(cells[2], (std::vector<int>{1, 1}));
    EXPECT_EQ(cells[3], (std::vector<int>{2, 1}));
    EXPECT_EQ(cells[4], (std::vector<int>{3, 1}));
    EXPECT_EQ(cells.back(), (std::vector<int>{4, 2}));
    EXPECT_EQ(t["events"].back()["type"], "ray_hit");
    EXPECT_NEAR(t["events"].back()["t"].get<double>(), 4.575, 1e-12);
    const CliRun b = run("build lecture-kdtree --split sah --json");
    ASSERT_EQ(b.code, 0) << b.err;
    EXPECT_EQ(nlohmann::json::parse(b.out)["dimensions"], 2);
    const CliRun own = run("trace lecture-kdtree --accel kdtree --ray 0,0,1,1 -o k.json");
    ASSERT_EQ(own.code, 0) << own.err;
    expectBadInputKeepFiles("trace lecture-kdtree --ray 0,0,0,0 -o x.json", "--ray");
    expectBadInputKeepFiles("render lecture-grid -o x.png", "key 'dimensions': a 2D scene");
}

TEST_F(Cli, CompareShowsThreeSplits) {
    const CliRun r = run("compare default --json --width 24 --height 18");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["results"].size(), 3u);
    EXPECT_EQ(j["results"][0]["structure"], "kdtree midpoint");
    EXPECT_EQ(j["results"][1]["structure"], "kdtree median");
    EXPECT_EQ(j["results"][2]["structure"], "kdtree sah");
    for (const auto& row : j["results"]) {
        EXPECT_EQ(row["rays"], j["results"][0]["rays"]);  // the same rays through each tree
        EXPECT_GT(row["primitive_tests_per_ray"].get<double>(), 0.0);
        EXPECT_GT(row["node_visits_per_ray"].get<double>(), 0.0);
    }
    const CliRun text = run("compare default --accel bvh --width 24 --height 18");
    ASSERT_EQ(text.code, 0) << text.err;
    EXPECT_NE(text.out.find("bvh sah"), std::string::npos);
}

// Any set of structures on the same rays: one row each, counted as render --stats counts the
// same rays with the same options, to the last test.
TEST_F(Cli, CompareAnyStructuresAgreesWithRenderStats) {
    const std::string size = " --width 24 --height 18 --bounces 2";
    const CliRun r = run("compare whitted --accel grid,kdtree,bvh,bruteforce --json" + size);
    ASSERT_EQ(r.code, 0) << r.err;
    const auto rows = nlohmann::json::parse(r.out)["results"];
    ASSERT_EQ(rows.size(), 4u);
    const char* kinds[] = {"grid", "kdtree", "bvh", "bruteforce"};
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(kinds[i]);
        const auto& row = rows[i];
        EXPECT_EQ(row["kind"], kinds[i]);
        // A tree in a list gets --split's method (sah by default); grid and brute force none.
        const bool tree = i == 1 || i == 2;
        EXPECT_EQ(row["split"], tree ? nlohmann::json("sah") : nlohmann::json(nullptr));
        EXPECT_EQ(row["sah_cost"].is_null(), !tree);
        ASSERT_EQ(run(std::string("render whitted --accel ") + kinds[i] + size +
                      " -o r.png --stats s.json")
                      .code,
                  0);
        const auto stats = nlohmann::json::parse(slurp(dir / "s.json"));
        EXPECT_EQ(row["accel"], stats["accel"]);
        EXPECT_EQ(row["rays"], stats["rays"]);
        EXPECT_EQ(row["primitive_tests"], stats["primitive_tests"]);
        EXPECT_EQ(row["node_visits"], stats["node_visits"]);
        EXPECT_EQ(row["mailbox_skips"], stats["mailbox_skips"]);
    }
    // Brute force tests every primitive for every nearest-hit ray; a shadow ray stops at its
    // first blocker, so it may test fewer.
    const auto prims = nlohmann::json::parse(r.out)["primitives"].get<std::uint64_t>();
    const auto& bf = rows[3];
    const auto total = bf["rays"]["total"].get<std::uint64_t>(),
               shadow = bf["rays"]["shadow"].get<std::uint64_t>();
    EXPECT_GE(bf["primitive_tests"].get<std::uint64_t>(), prims * (total - shadow));
    EXPECT_LE(bf["primitive_tests"].get<std::uint64_t>(), prims * total);
    // --split lists the trees' methods: each tree once per method, in the order given.
    const CliRun m =
        run("compare whitted --accel kdtree,grid --split median,midpoint --json" + size);
    ASSERT_EQ(m.code, 0) << m.err;
    const auto mrows = nlohmann::json::parse(m.out)["results"];
    ASSERT_EQ(mrows.size(), 3u);
    EXPECT_EQ(mrows[0]["accel"], "kdtree median");
    EXPECT_EQ(mrows[1]["accel"], "kdtree midpoint");
    EXPECT_EQ(mrows[2]["accel"], "grid");
    // The table names each row.
    const CliRun text = run("compare whitted --accel grid,bvh" + size);
    ASSERT_EQ(text.code, 0) << text.err;
    EXPECT_NE(text.out.find("\ngrid "), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("\nbvh sah "), std::string::npos) << text.out;
}

TEST_F(Cli, BadSceneFilesNameFileLineAndKey) {
    expectBadInput("render nosuchscene", "nosuchscene: no such scene file");
    write("bad.json", "{\n  \"objects\": [\n    {\"type\": \"sphere\", \"radius\": -2}\n  ]\n}\n");
    const CliRun r = run("render bad.json -o x.png");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("bad.json:3: key 'objects[0].radius': must be greater than 0"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    write("bad.json", "{\"objects\": [");
    EXPECT_EQ(run("render bad.json -o x.png").code, 2);
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST_F(Cli, IntersectTriangleJson) {
    // Down onto z = 0 at (0.25, 0.5): t = 1, weights of b and c are the x and y coordinates.
    for (const char* method : {"plane", "moller-trumbore", "watertight"}) {
        for (const char* precision : {"float", "double"}) {
            const CliRun r = run(std::string("intersect --ray 0.25,0.5,1:0,0,-1 --triangle "
                                             "0,0,0:1,0,0:0,1,0 --json --method ") +
                                 method + " --precision " + precision);
            ASSERT_EQ(r.code, 0) << r.err;
            const auto j = nlohmann::json::parse(r.out);
            EXPECT_EQ(j["hit"], true);
            EXPECT_EQ(j["t"], 1.0);
            EXPECT_EQ(j["u"], 0.25);
            EXPECT_EQ(j["v"], 0.5);
            EXPECT_EQ(j["point"], nlohmann::json::parse("[0.25, 0.5, 0.0]"));
            EXPECT_EQ(j["method"], method);
            EXPECT_EQ(j["precision"], precision);
        }
    }
}

TEST_F(Cli, IntersectMissAndSphere) {
    CliRun r = run("intersect --ray 0.8,0.8,1:0,0,-1 --triangle 0,0,0:1,0,0:0,1,0 --json");
    ASSERT_EQ(r.code, 0);
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["hit"], false);
    EXPECT_TRUE(j["t"].is_null());
    EXPECT_TRUE(j["point"].is_null());
    // A unit sphere 1e8 away: t = 1e8 - 1 (stable), the textbook formula is a radius off.
    r = run("intersect --ray 0,0,0:0,0,1 --sphere 0,0,1e8:1 --json");
    j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["t"].get<double>(), 1e8 - 1, 1e-7);
    r = run("intersect --ray 0,0,0:0,0,1 --sphere 0,0,1e8:1 --json --method textbook");
    j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["t"].get<double>(), 1e8);
    EXPECT_EQ(j["steps"]["discriminant"], 0.0);
}

TEST_F(Cli, IntersectTextShowsTheWorking) {
    CliRun r = run("intersect --ray 0,0,0:0,0,1 --sphere 0,0,5:1 --method textbook");
    ASSERT_EQ(r.code, 0);
    // a = 1, b = 2 d.(o - c) = -10, c = 25 - 1 = 24, b^2 - 4ac = 4, t = (10 - 2) / 2 = 4.
    EXPECT_NE(r.out.find("discriminant         4\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("hit at t = 4\n"), std::string::npos) << r.out;
    r = run("intersect --ray 0.25,0.5,1:0,0,-1 --triangle 0,0,0:1,0,0:0,1,0 --method plane");
    EXPECT_NE(r.out.find("normal               (0, 0, 1)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("barycentric u = 0.25, v = 0.5"), std::string::npos) << r.out;
}

TEST_F(Cli, IntersectBadInput) {
    const std::string tri = " --triangle 0,0,0:1,0,0:0,1,0";
    expectBadInput("intersect --ray 0,0,nan:0,0,1" + tri, "6 finite numbers");
    expectBadInput("intersect --ray 0,0,inf:0,0,1" + tri, "6 finite numbers");
    expectBadInput("intersect --ray 0,0,1e999:0,0,1" + tri, "6 finite numbers");
    expectBadInput("intersect --ray 0,0,1:0,0" + tri, "6 finite numbers");
    expectBadInput("intersect --ray 0,0,1:0,0,0" + tri, "must not be zero");
    expectBadInput("intersect --ray 0,0,1:0,0,-1 --triangle 0,0,0:1,0,0", "9 finite numbers");
    expectBadInput("intersect --ray 0,0,1:0,0,-1 --sphere 0,0,0:-1", "greater than 0");
    expectBadInput("intersect --ray 0,0,1:0,0,-1 --sphere 0,0,0:1 --method watertight",
                   "sphere methods");
    expectBadInput("intersect --ray 0,0,1:0,0,-1" + tri + " --method stable", "triangle methods");
    expectBadInput("intersect --ray 0,0,1:0,0,-1" + tri + " --precision half", "--precision half");
    expectBadInput("intersect --ray 0,0,1:0,0,-1" + tri + " --sphere 0,0,0:1", "excludes");
    expectBadInput("intersect --ray 0,0,1:0,0,-1", "--triangle or --sphere");
}

TEST_F(Cli, RenderNumericOptions) {
    const CliRun r =
        run("render default --width 16 --height 12 --precision float --ray-offset epsilon "
            "--triangle-method moller-trumbore --sphere-method textbook --stats s.json");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto stats = nlohmann::json::parse(slurp(dir / "s.json"));
    EXPECT_EQ(stats["precision"], "float");
    EXPECT_EQ(stats["ray_offset"], "epsilon");
    EXPECT_EQ(stats["triangle_method"], "moller-trumbore");
    EXPECT_EQ(stats["sphere_method"], "textbook");
    fs::remove(dir / "default.png");
    fs::remove(dir / "s.json");
    expectBadInput("render --precision quad", "--precision quad");
    expectBadInput("render --ray-offset none", "--ray-offset none");
    expectBadInput("render --triangle-method fast", "--triangle-method fast");
    expectBadInput("render --sphere-method fast", "--sphere-method fast");
}

TEST_F(Cli, RenderWithTheGrid) {
    const CliRun r =
        run("render default --accel grid --width 24 --height 18 --grid-res 8,2,8 "
            "--stats g.json -o g.png");
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_EQ(run("render default --width 24 --height 18 -o b.png").code, 0);
    EXPECT_EQ(slurp(dir / "g.png"), slurp(dir / "b.png"));  // the same image, byte for byte
    const auto stats = nlohmann::json::parse(slurp(dir / "g.json"));
    EXPECT_EQ(stats["grid"]["cells"], nlohmann::json::parse("[8, 2, 8]"));
    EXPECT_GT(stats["node_visits"].get<long>(), 0);
    EXPECT_GT(stats["mailbox_skips"].get<long>(), 0);
    for (const char* f : {"g.png", "b.png", "g.json"}) fs::remove(dir / f);
    expectBadInput("render --accel grid --grid-res 8,8", "--grid-res 8,8");
    expectBadInput("render --accel grid --grid-res 8,0,8", "whole numbers");
    expectBadInput("render --accel grid --grid-lambda 0", "--grid-lambda");
    expectBadInput("render --accel grid --grid-lambda nan", "--grid-lambda");
    expectBadInput("render --accel grid --mailbox maybe", "--mailbox maybe");
}

TEST_F(Cli, DdaJsonFollowsTheLecture) {
    // 4 x 3 unit cells from (0.5, 0.25) along (1, 0.6): tDelta = (1, 1/0.6); by hand the walk is
    // (0,0) -X-> (1,0) -Y-> (1,1) -X-> (2,1) -X-> (3,1) -Y-> (3,2).
    const CliRun r = run("dda --grid 4,3 --min 0,0 --max 4,3 --origin 0.5,0.25 --dir 1,0.6 --json");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto steps = nlohmann::json::parse(r.out)["steps"];
    ASSERT_EQ(steps.size(), 6u);
    const int cells[6][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {3, 1}, {3, 2}};
    const int axes[6] = {-1, 0, 1, 0, 0, 1};
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(steps[i]["cell"][0], cells[i][0]) << i;
        EXPECT_EQ(steps[i]["cell"][1], cells[i][1]) << i;
        if (axes[i] < 0) {
            EXPECT_TRUE(steps[i]["axis"].is_null());
        } else {
            EXPECT_EQ(steps[i]["axis"], axes[i]) << i;
        }
        EXPECT_EQ(steps[i]["tDelta"][0], 1.0);
        EXPECT_NEAR(steps[i]["tDelta"][1].get<double>(), 1 / 0.6, 1e-15);
    }
    EXPECT_EQ(steps[0]["tMax"][0], 0.5);                                // (1 - 0.5) / 1
    EXPECT_NEAR(steps[0]["tMax"][1].get<double>(), 0.75 / 0.6, 1e-15);  // (1 - 0.25) / 0.6
    EXPECT_EQ(steps[0]["t_enter"], 0.0);
    EXPECT_EQ(steps[0]["t_exit"], 0.5);
    EXPECT_EQ(steps[5]["t_exit"], 3.5);  // leaves through x = 4
}

TEST_F(Cli, DdaTableAndMiss) {
    CliRun r = run("dda --grid 3,3,3 --min 0,0,0 --max 3,3,3 --origin -1,-1,-1 --dir 1,1,1");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("X+Y+Z (tie: through a grid edge or vertex)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("leaves the grid"), std::string::npos);
    r = run("dda --grid 3,3 --min 0,0 --max 3,3 --origin -1,5 --dir 1,0 --json");
    ASSERT_EQ(r.code, 0);
    EXPECT_TRUE(nlohmann::json::parse(r.out)["steps"].empty());
}

// Robustness review, class 1: a path the file system refuses to look up (a symlink loop, a name
// over 255 bytes) aborted with an uncaught filesystem_error (exit 134), as an output or an input.
TEST_F(Cli, PathsTheFileSystemRefusesGetOneLine) {
    fs::create_symlink("loop", dir / "loop");  // a link to itself: every lookup through it fails
    const std::string longName(256, 'a');      // one byte over the 255 a name may have
    const std::string loop = "Too many levels of symbolic links";
    const std::string tooLong = "File name too long";
    expectBadInputKeepFiles("render --width 8 --height 6 -o loop/x.png", "-o loop/x.png: " + loop);
    expectBadInputKeepFiles("render --width 8 --height 6 --stats loop/s.json",
                            "--stats loop/s.json: " + loop);
    expectBadInputKeepFiles("render --width 8 --height 6 --heatmap loop/h.png",
                            "--heatmap loop/h.png: " + loop);
    expectBadInputKeepFiles("trace --pixel 0,0 -o loop/t.json", "-o loop/t.json: " + loop);
    expectBadInputKeepFiles("build --events loop/e.json", "--events loop/e.json: " + loop);
    expectBadInputKeepFiles("render -o " + longName + ".png", tooLong);
    expectBadInputKeepFiles("render -o " + longName + "/x.png", tooLong);
    expectBadInputKeepFiles("trace --pixel 0,0 -o " + longName + ".json", tooLong);
    // Inputs: whichever part reports it, the path is named on one line.
    expectBadInputKeepFiles("render loop/scene.json -o x.png", "loop/scene.json");
    expectBadInputKeepFiles("build " + longName + ".json", longName);
    expectBadInputKeepFiles("trace loop/scene.json -o t.json", "loop/scene.json");
    expectBadInputKeepFiles("compare loop/scene.json", "loop/scene.json");
    expectBadInputKeepFiles("lesson validate loop/lesson.json", "loop/lesson.json");
    expectBadInputKeepFiles("lesson check 6 --answers loop/a.json", "loop/a.json");
    // A folder that cannot be searched, and one that cannot be written: root passes both checks,
    // so as root the CLI runs as nobody (runuser, util-linux).
    fs::create_directory(dir / "locked");
    fs::create_directory(dir / "readonly");
    fs::permissions(dir / "locked", fs::perms::none);
    fs::permissions(dir / "readonly", fs::perms::owner_read | fs::perms::owner_exec |
                                          fs::perms::others_read | fs::perms::others_exec);
    if (::geteuid() == 0) runAs = "runuser -u nobody -- ";
    const std::string denied = "Permission denied";
    expectBadInputKeepFiles("render --width 8 --height 6 -o locked/x.png",
                            "-o locked/x.png: " + denied);
    expectBadInputKeepFiles("trace --pixel 0,0 -o locked/t.json", "-o locked/t.json: " + denied);
    expectBadInputKeepFiles("build --events locked/e.json", "--events locked/e.json: " + denied);
    expectBadInputKeepFiles("build locked/scene.json", "locked/scene.json");
    expectBadInputKeepFiles("lesson show locked/lesson.json", "locked/lesson.json");
    expectBadInputKeepFiles("render --width 8 --height 6 -o readonly/x.png",
                            "-o readonly/x.png: folder 'readonly' is not writable");
    runAs.clear();
    fs::permissions(dir / "locked", fs::perms::owner_all);  // so that TearDown can remove it
}

// Class 2: a write that fails after the checks (here /proc, where no file can be created) aborted
// trace and build (exit 134); a device or FIFO as the output was replaced by a regular file.
TEST_F(Cli, FailedWritesGetOneLine) {
    expectBadInput("trace --pixel 0,0 -o /proc/t.json", "/proc/t.json: cannot write");
    expectBadInput("trace lecture-grid --accel grid -o /proc/g.json", "/proc/g.json: cannot write");
    expectBadInput("build --events /proc/e.json", "/proc/e.json: cannot write");
    expectBadInput("render --width 8 --height 6 -o /proc/x.png", "/proc/x.png: cannot write");
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
    write("t.json", "old trace");
    expectBadInputKeepFiles("trace --pixel 0,0 -o pipe", "-o pipe: is not a regular file");
    expectBadInputKeepFiles("build --events pipe", "--events pipe: is not a regular file");
    expectBadInputKeepFiles("render --stats pipe", "--stats pipe: is not a regular file");
    expectBadInputKeepFiles("trace --pixel 0,0 -o t.json/x.json", "'t.json' is not a folder");
    EXPECT_TRUE(fs::is_fifo(dir / "pipe"));
    EXPECT_EQ(slurp(dir / "t.json"), "old trace");
    // Standard output on a full disk is a failed write too.
    for (const std::string args :
         {"scenes", "lesson list", "build default --json", "compare default --width 8 --height 6",
          "dda --grid 4,3 --min 0,0 --max 4,3 --origin 0.5,0.25 --dir 1,0.6 --json",
          "intersect --ray 0,0,0:0,0,1 --sphere 0,0,5:1"}) {
        const CliRun r = run(args, "/dev/full");
        EXPECT_EQ(r.code, 2) << args;
        EXPECT_EQ(r.err,
                  "raystep-cli: error: standard output: cannot write: No space left on "
                  "device\n")
            << args;
    }
}

// Class 3: render replaced the image, then failed on the stats or the heat map (exit 2). Now all
// the files a command writes are written or none is, and no temporary is left behind.
TEST_F(Cli, RenderWritesAllFilesOrNone) {
    write("w.png", "old image");
    write("h.png", "old heat map");
    write("s.json", "old stats");
    const auto before = listing();
    for (const std::string outputs :
         {"-o w.png --heatmap h.png --stats /proc/s.json", "-o w.png --heatmap /proc/h.png",
          "-o /proc/w.png --heatmap h.png --stats s.json", "-o w.png --heatmap h.png --stats pipe",
          "-o w.png --heatmap ./w.png", "-o w.png --heatmap h.png --stats h.png"}) {
        if (outputs.find("pipe") != std::string::npos) {
            ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
        }
        const CliRun r = run("render --width 8 --height 6 " + outputs);
        EXPECT_EQ(r.code, 2) << outputs;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        fs::remove(dir / "pipe");
        EXPECT_EQ(listing(), before) << outputs;  // byte for byte, and nothing else
    }
    expectBadInputKeepFiles("render -o w.png --heatmap ./w.png",
                            "--heatmap ./w.png: the same file as -o");
    // Success writes all three; an output that is a symlink is written through, the link stays.
    int w = 0, h = 0, n = 0;
    fs::create_symlink("w.png", dir / "link.png");
    fs::create_symlink("new.png", dir / "dangling.png");
    const CliRun r =
        run("render --width 8 --height 6 -o link.png --heatmap dangling.png --stats s.json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(dir / "link.png"));
    EXPECT_TRUE(fs::is_symlink(dir / "dangling.png"));
    EXPECT_TRUE(stbi_info((dir / "new.png").c_str(), &w, &h, &n));
    EXPECT_TRUE(stbi_info((dir / "w.png").c_str(), &w, &h, &n));
    EXPECT_EQ(w, 8);
    EXPECT_EQ(nlohmann::json::parse(slurp(dir / "s.json"))["width"], 8);
    EXPECT_EQ(listing().size(), 6u);  // w, h, s, the two links, new.png: no temporary left
}

// Class 5: --pixel 2^31 was cast to int before the range check (it wrapped to -2^31); every
// whole-number option is now range-checked in 64 bits before it is converted, in decimal.
TEST_F(Cli, NumericOptionsAreCheckedBeforeConversion) {
    for (const std::string pixel : {"2147483648,0", "0,2147483648", "4294967296,5", "0,1e300"})
        expectBadInput("trace --pixel " + pixel + " -o t.json", "outside the 640x480 image");
    const std::vector<std::string> treeOptions = {"--max-depth", "--leaf-size", "--buckets",
                                                  "--bin-above"};
    const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
        {"render", {"--width", "--height", "--bounces", "--spp", "--diffuse-samples", "--threads"}},
        {"trace --pixel 0,0 -o t.json",
         {"--width", "--height", "--bounces", "--spp", "--diffuse-samples", "--max-events"}},
        {"build", {"--max-events"}},
        {"compare", {"--width", "--height", "--bounces", "--threads"}}};
    for (const auto& [command, own] : commands) {
        std::vector<std::string> options = own;
        options.insert(options.end(), treeOptions.begin(), treeOptions.end());
        for (const std::string& option : options)
            for (const std::string value : {"-1", "''", "' 7'", "0x10", "1e3", "1.5", "nan", "inf",
                                            "2147483648", "18446744073709551617"})
                expectBadInput(command + " " + option + " " + value, option + ": '");
    }
    for (const std::string option : {"--c-trav", "--c-isect", "--empty-bonus"})
        for (const std::string value : {"nan", "inf", "-inf", "1e999", "''", "0x1"})
            expectBadInput("build " + option + " " + value, option);
    // CLI11 read a leading 0 as octal: 010 was 8.
    const CliRun r = run("render --width 010 --height 6 -o x.png --stats s.json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(slurp(dir / "s.json"))["width"], 10);
    fs::remove(dir / "x.png");
    fs::remove(dir / "s.json");
    // The grid's size overflowing a double (1e308 - -1e308) is refused, not walked as infinite.
    expectBadInput("dda --grid 3,3 --min -1e308,0 --max 1e308,3 --origin 0,1 --dir 1,0",
                   "--max 1e308,3: the grid's size from --min overflows");
    expectBadInput(
        "dda --grid 3,3 --min -3e38,0 --max 3e38,3 --origin 0,1 --dir 1,0 "
        "--precision float",
        "overflows a float");
}

// Class 6: --seed -1 wrapped to 2^64 - 1, a too-large seed saturated, an empty one was 0.
TEST_F(Cli, SeedIsCheckedAsTheOtherOptions) {
    for (const std::string command : {"render", "trace --pixel 0,0 -o t.json"})
        for (const std::string value :
             {"-1", "''", "18446744073709551616", "99999999999999999999999", "0x10", "1.5", "nan"})
            expectBadInput(command + " --seed " + value, "--seed: '");
    const CliRun r =
        run("render --width 4 --height 4 -o x.png --stats s.json --seed 18446744073709551615");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(slurp(dir / "s.json"))["seed"].get<std::uint64_t>(),
              18446744073709551615ull);
}

// Class 15: dda --json built the whole walk in memory first (about 1.7 KB a step; this walk of
// about 170,000 steps peaked at 267 MB). Streamed, it stays small, and the table likewise.
TEST_F(Cli, DdaStreamsLongWalksInBoundedMemory) {
    const std::vector<std::string> walk = {"dda",       "--grid", "100000,100000", "--min",
                                           "0,0",       "--max",  "1,1",           "--origin",
                                           "5e-6,3e-6", "--dir",  "1,0.7"};
    for (const std::string how : {"--json", "", "--format=csv"}) {
        std::vector<std::string> args = walk;
        if (!how.empty()) args.push_back(how);
        const auto [code, peakKb] = runMeasured(args);
        EXPECT_EQ(code, 0) << how;
        EXPECT_LT(peakKb, 64 * 1024) << how;
    }
    // The stream is the same JSON: by hand, 4 x 3 cells from (0.5, 0.25) along (1, 0.6) visit 6.
    const CliRun r = run("dda --grid 4,3 --min 0,0 --max 4,3 --origin 0.5,0.25 --dir 1,0.6 --json");
    ASSERT_EQ(r.code, 0);
    EXPECT_EQ(nlohmann::json::parse(r.out)["steps"].size(), 6u);
}

// dda --format: the GUI board's table. By hand, 4 x 3 unit cells from (0.5, 0.25) along
// (1, 0.6): tDelta (1, 1/0.6 = 1.66667), cells (0,0) -X-> (1,0) -Y-> (1,1) -X-> (2,1) -X-> (3,1)
// -Y-> (3,2); tMaxX = 0.5, 1.5, 2.5, 3.5 and tMaxY = 0.75/0.6 = 1.25, then 2.91667.
TEST_F(Cli, DdaFormatPrintsTheBoard) {
    const std::string walk = "dda --grid 4,3 --min 0,0 --max 4,3 --origin 0.5,0.25 --dir 1,0.6";
    CliRun r = run(walk + " --format csv");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out,
              "step,X,Y,tMaxX,tMaxY,tDeltaX,tDeltaY,stepped\n"
              "0,0,0,0.5,1.25,1,1.66667,start\n"
              "1,1,0,1.5,1.25,1,1.66667,X\n"
              "2,1,1,1.5,2.91667,1,1.66667,Y\n"
              "3,2,1,2.5,2.91667,1,1.66667,X\n"
              "4,3,1,3.5,2.91667,1,1.66667,X\n"
              "5,3,2,3.5,4.58333,1,1.66667,Y\n");
    r = run(walk + " --format markdown");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.substr(0, r.out.find('\n', r.out.find('\n') + 1) + 1),
              "| step | X | Y | tMaxX | tMaxY | tDeltaX | tDeltaY | stepped |\n"
              "| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    r = run(walk + " --format latex");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("\\begin{tabular}{llllllll}\n", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("5 & 3 & 2 & 3.5 & 4.58333 & 1 & 1.66667 & Y \\\\\n"), std::string::npos)
        << r.out;
    expectBadInput(walk + " --format html", "--format html");
    const CliRun both = run(walk + " --format csv --json");
    EXPECT_EQ(both.code, 2) << both.err;
}

TEST_F(Cli, DdaBadInput) {
    const std::string box = " --min 0,0 --max 3,3 --origin 0.5,0.5 --dir 1,1";
    expectBadInput("dda --grid 3" + box, "NX,NY or NX,NY,NZ");
    expectBadInput("dda --grid 3,0" + box, "whole numbers");
    expectBadInput("dda --grid 3,2.5" + box, "whole numbers");
    expectBadInput("dda --grid 3,3 --min 0,0,0 --max 3,3 --origin 0.5,0.5 --dir 1,1",
                   "--min 0,0,0");
    expectBadInput("dda --grid 3,3 --min 0,0 --max 3,-3 --origin 0.5,0.5 --dir 1,1",
                   "greater than --min");
    expectBadInput("dda --grid 3,3 --min 0,0 --max 3,3 --origin nan,0.5 --dir 1,1",
                   "--origin nan,0.5");
    expectBadInput("dda --grid 3,3 --min 0,0 --max 3,3 --origin 0.5,0.5 --dir 0,0",
                   "must not be zero");
    expectBadInput("dda --grid 3,3 --min 0,0 --max 3,1e999 --origin 0.5,0.5 --dir 1,1", "--max");
    expectBadInput(
        "dda --grid 3,3 --min 0,0 --max 3,1e300 --origin 0.5,0.5 --dir 1,1 --precision float",
        "too large for float");
}

}  // namespace

namespace {
TEST_F(Cli, LessonListShowsTheLecturesThirteen) {
    const CliRun r = run("lesson list");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 13) << r.out;
    EXPECT_NE(r.out.find(" 6  grid-2d-dda"), std::string::npos) << r.out;
    const CliRun it = run("lesson show mailboxing --lang it");
    ASSERT_EQ(it.code, 0) << it.err;
    EXPECT_NE(it.out.find("ogni raggio ha un ID"), std::string::npos) << it.out;
}

// The key read from the trace, graded, scores full marks; a course's sheet with two wrong answers
// scores one, and the JSON says which and why.
TEST_F(Cli, LessonKeyAndCheckGradeACoursesAnswers) {
    const CliRun key = run("lesson key grid-2d-dda");
    ASSERT_EQ(key.code, 0) << key.err;
    write("key.json", key.out);
    const CliRun full = run("lesson check 6 --answers key.json");
    ASSERT_EQ(full.code, 0) << full.err;
    // Every exercise of the lesson has an answer in the key.
    const std::size_t exercises = nlohmann::json::parse(key.out)["answers"].size();
    const std::string all = std::to_string(exercises);
    EXPECT_NE(full.out.find(": " + all + " / " + all), std::string::npos) << full.out;
    // By hand (o = (0.4, 0.4), d = (0.8, 0.4), cells of 1): tDeltaY = 1 / 0.4 = 2.5; in (2, 1)
    // tMaxX = (3 - 0.4) / 0.8 = 3.25 < tMaxY = (2 - 0.4) / 0.4 = 4, so the next cell is (3, 1).
    std::ofstream(dir / "sheet.json") << R"({"lesson": "grid-2d-dda", "student": "ada",
               "answers": {"tdelta-y": "2,5", "tmax-x-after-step": 2, "next-cell": [2, 2]}})";
    const CliRun graded = run("lesson check grid-2d-dda --answers sheet.json --json");
    ASSERT_EQ(graded.code, 0) << graded.err;
    const auto j = nlohmann::json::parse(graded.out);
    EXPECT_EQ(j["score"], 1);
    EXPECT_EQ(j["out_of"], exercises);
    EXPECT_EQ(j["exercises"][0]["correct"], true);
    EXPECT_EQ(j["exercises"][2]["correct"], false);
    EXPECT_EQ(j["exercises"][2]["expected"], "3.25");
    EXPECT_EQ(j["exercises"][3]["expected"], "3,1");
    EXPECT_NE(j["exercises"][3]["feedback"].get<std::string>().find("steps in X"),
              std::string::npos);
}

// A lesson of its own, so the class tests do not follow the built-in lessons' edits: 4 x 4 unit
// cells (the walls x = 0 and y = 0 give the bounds), the ray (0.5, 0.5) + t (1, 0.5). By hand:
// tDeltaY = 1 / 0.5 = 2; in (0, 0) tMaxX = 0.5 < tMaxY = 1, so the second cell is (1, 0); the walk
// (0, 0) (1, 0) (1, 1) (2, 1) (3, 1) (3, 2) leaves at x = 4 (t = 3.5): 6 cells.
void writeClassLesson(const fs::path& dir) {
    std::ofstream(dir / "room.json")
        << R"({"dimensions": 2, "grid": [4, 4], "ray": {"origin": [0.5, 0.5], "dir": [1, 0.5]},
               "segments": [{"from": [0, 0], "to": [4, 0]}, {"from": [0, 4], "to": [0, 0]}]})";
    std::ofstream(dir / "walk.json") << R"({
        "format": "raystep-lesson", "version": 1, "id": "walk", "number": 42,
        "title": {"en": "Walk", "it": "Cammino"}, "text": {"en": "A walk.", "it": "Un cammino."},
        "scene": "room.json", "setup": {"accel": "grid"}, "trace": {"ray": "example"},
        "exercises": [
          {"id": "tdelta-y", "type": "value", "quantity": "tDelta.y", "prompt": {"en": "?"}},
          {"id": "next-cell", "type": "next_cell", "at": {"before": "dda_cell", "nth": 2},
           "prompt": {"en": "?"}},
          {"id": "cells", "type": "count", "count": "dda_cell", "prompt": {"en": "?"}}]})";
}

// A class of four sheets: per exercise, right, wrong, not answered and the most common wrong
// answer; "-2" and "-2,0" read the same and count as one, "1|0" cannot be read and is wrong.
TEST_F(Cli, LessonCheckOverAFolderGivesTheClassTable) {
    writeClassLesson(dir);
    const CliRun key = run("lesson key walk.json");
    ASSERT_EQ(key.code, 0) << key.err;
    const auto j = nlohmann::json::parse(key.out);
    EXPECT_EQ(j["answers"]["tdelta-y"], "2");
    EXPECT_EQ(j["answers"]["next-cell"], "1,0");
    EXPECT_EQ(j["answers"]["cells"], "6");
    fs::create_directories(dir / "class");
    write("class/ada.json", R"({"lesson": "walk", "answers": {"tdelta-y": "2",
        "next-cell": "1,0", "cells": 6}})");
    write("class/bo.json", R"({"lesson": "walk", "answers": {"tdelta-y": "-2",
        "next-cell": "0,1"}})");
    write("class/cy.json", R"({"lesson": "walk", "answers": {"tdelta-y": "-2,0",
        "next-cell": [0, 1], "cells": "5"}})");
    write("class/di.json", R"({"lesson": 42, "answers": {"tdelta-y": "0.5",
        "next-cell": "1|0", "cells": "6"}})");
    write("class/notes.txt", "not a sheet: only *.json files are read");
    const CliRun md = run("lesson check walk.json --answers class");
    ASSERT_EQ(md.code, 0) << md.err;
    EXPECT_NE(md.out.find("Lesson 42. Walk: 4 answer sheets"), std::string::npos) << md.out;
    EXPECT_NE(md.out.find("| exercise | right answers | wrong answers | not answered | most "
                          "common wrong answer | how many |"),
              std::string::npos)
        << md.out;
    EXPECT_NE(md.out.find("| tdelta-y | 1 | 3 | 0 | -2 | 2 |"), std::string::npos) << md.out;
    EXPECT_NE(md.out.find("| next-cell | 1 | 3 | 0 | 0,1 | 2 |"), std::string::npos) << md.out;
    EXPECT_NE(md.out.find("| cells | 2 | 1 | 1 | 5 | 1 |"), std::string::npos) << md.out;
    const CliRun csv = run("lesson check walk.json --answers class --format csv");
    ASSERT_EQ(csv.code, 0) << csv.err;
    EXPECT_EQ(csv.out,
              "exercise,right,wrong,not_answered,most_common_wrong,how_many\n"
              "tdelta-y,1,3,0,-2,2\n"
              "next-cell,1,3,0,\"0,1\",2\n"
              "cells,2,1,1,5,1\n");
    const CliRun it = run("lesson check walk.json --answers class --lang it");
    ASSERT_EQ(it.code, 0) << it.err;
    EXPECT_NE(it.out.find("Lezione 42. Cammino: 4 fogli di risposte"), std::string::npos) << it.out;
    EXPECT_NE(it.out.find("| esercizio | risposte giuste | risposte sbagliate | senza risposta |"),
              std::string::npos)
        << it.out;
    // One sheet as a table, too.
    const CliRun one = run("lesson check walk.json --answers class/bo.json --format csv");
    ASSERT_EQ(one.code, 0) << one.err;
    EXPECT_NE(one.out.find("cells,0,0,1,,\n"), std::string::npos) << one.out;
}

// A bad sheet anywhere in the folder: one line naming its file, line and key, exit 2, and no
// table at all (nothing half written).
TEST_F(Cli, LessonCheckOverAFolderStopsAtABadSheet) {
    writeClassLesson(dir);
    fs::create_directories(dir / "class");
    write("class/a.json", R"({"lesson": "walk", "answers": {"next-cell": "1,0"}})");
    write("class/b.json", "{\"lesson\": \"walk\",\n \"answers\": {\n \"next-cel\": [1, 0]}}");
    write("class/c.json", R"({"lesson": "walk", "answers": {"next-cell": "0,1"}})");
    const CliRun r = run("lesson check walk.json --answers class");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("class/b.json:3: key 'answers.next-cel': lesson walk has no exercise"),
              std::string::npos)
        << r.err;
    write("class/b.json", "{\"lesson\": \"walk\",\n \"answers\": {\"next-cell\": {}}}");
    const CliRun parse = run("lesson check walk.json --answers class --format csv");
    EXPECT_EQ(parse.code, 2);
    EXPECT_EQ(parse.out, "");
    EXPECT_NE(parse.err.find("class/b.json:2: key 'answers.next-cell'"), std::string::npos)
        << parse.err;
    write("class/b.json", R"({"lesson": "7", "answers": {}})");
    const CliRun other = run("lesson check walk.json --answers class");
    EXPECT_EQ(other.code, 2);
    EXPECT_NE(other.err.find("class/b.json:1: key 'lesson'"), std::string::npos) << other.err;
    const CliRun format = run("lesson check walk.json --answers class/a.json --format html");
    EXPECT_NE(format.code, 0);
    EXPECT_EQ(format.out, "");
}

// Why a test misses, named from the scene. By hand, the ray (0.5, 0.5) + t (1, 0) through brute
// force, primitives in id order: circle 0 at (2, 0.5), r 0.5, is hit at t = 1; circle 1 at
// (4.5, 0.5), r 0.2, at t = 3.8, beyond it; circle 2 at (2.5, 3), r 0.5: B^2 - 4AC = 16 - 40 =
// -24; segment 3 (x = 1.5, y 1 to 2) is met at y = 0.5, s = -0.5; segment 4 (x = 0.2) at
// t = -0.3, behind the origin.
TEST_F(Cli, AMissedTestNamesItsCause) {
    write("misses.json", R"({"dimensions": 2, "grid": [4, 2],
        "ray": {"origin": [0.5, 0.5], "dir": [1, 0]},
        "circles": [{"center": [2, 0.5], "radius": 0.5}, {"center": [4.5, 0.5], "radius": 0.2},
                    {"center": [2.5, 3], "radius": 0.5}],
        "segments": [{"from": [1.5, 1], "to": [1.5, 2]}, {"from": [0.2, 0], "to": [0.2, 1]}]})");
    std::string exercises;
    for (int k = 2; k <= 5; ++k)
        exercises += std::string(k > 2 ? "," : "") + R"({"id": "t)" + std::to_string(k) +
                     R"(", "type": "hit_or_miss", "at": {"before": "primitive_test", "nth": )" +
                     std::to_string(k) + R"(}, "prompt": {"en": "?"}})";
    write("m.json", R"({"format": "raystep-lesson", "version": 1, "id": "m", "number": 43,
        "title": {"en": "M"}, "text": {"en": "M."}, "scene": "misses.json",
        "trace": {"ray": "example"}, "exercises": [)" +
                        exercises + "]}");
    write("a.json", R"({"lesson": "m", "answers": {"t2": "hit", "t3": "hit", "t4": "hit",
        "t5": "hit"}})");
    const CliRun r = run("lesson check m.json --answers a.json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("Its intersection, t = 3.8, lies beyond the nearest one found so far "
                         "(t = 1)."),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("The discriminant B² − 4AC = -24 is negative"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("outside the segment (at s = -0.5 of it"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("behind the origin (t = -0.3)"), std::string::npos) << r.out;
    const CliRun it = run("lesson check m.json --answers a.json --lang it");
    EXPECT_NE(it.out.find("Il discriminante B² − 4AC = -24 è negativo"), std::string::npos)
        << it.out;
}

// A lesson file with errata and the new kinds: show prints the errata as a quoted block and the
// options; key and check grade them. By hand: the sphere c = (0, 0, 0), R = 1 from o = (0, 0, 5)
// along (0, 0, -1): A = 1, B = -10, C = 24, disc = 4, t = (10 - 2) / 2 = 4.
TEST_F(Cli, ALessonWithErrataAndTheNewKinds) {
    write("new.json", R"({
        "format": "raystep-lesson", "version": 1, "id": "new", "number": 41,
        "title": {"en": "New", "it": "Nuova"}, "text": {"en": "Text.", "it": "Testo."},
        "errata": [{"slide": "C = ||dir - c||^2", "correct": "C = |o - c|^2 - R^2",
                    "why": {"en": "The origin, not the direction.", "it": "L'origine."}}],
        "scene": "lecture-grid", "setup": {"accel": "grid"}, "trace": {"ray": "example"},
        "steps": [{"text": {"en": "The {colour:primary} ray.", "it": "Il raggio {colour:primary}."},
                   "filter": "dda_cell"}],
        "exercises": [
          {"id": "disc", "type": "compute", "quantity": "discriminant",
           "prompt": {"en": "o = (0, 0, 5), d = (0, 0, -1), c = (0, 0, 0), R = 1: the discriminant?",
                      "it": "o = (0; 0; 5), d = (0; 0; -1), c = (0; 0; 0), R = 1: il discriminante?"},
           "given": {"ray": {"o": [0, 0, 5], "d": [0, 0, -1]}, "sphere": {"c": [0, 0, 0], "r": 1}}},
          {"id": "why", "type": "choice", "prompt": {"en": "Which?", "it": "Quale?"},
           "choices": [{"text": {"en": "One", "it": "Uno"}, "why": {"en": "No.", "it": "No."}},
                       {"text": {"en": "Two", "it": "Due"}, "why": {"en": "Yes.", "it": "Sì."}}],
           "answer": 1}]})");
    const CliRun v = run("lesson validate new.json");
    ASSERT_EQ(v.code, 0) << v.err;
    const CliRun show = run("lesson show new.json --lang it");
    ASSERT_EQ(show.code, 0) << show.err;
    EXPECT_NE(show.out.find("> **Nota sulle slide**"), std::string::npos) << show.out;
    EXPECT_NE(show.out.find("> Slide: C = ||dir - c||^2"), std::string::npos) << show.out;
    EXPECT_NE(show.out.find("> L'origine."), std::string::npos) << show.out;
    EXPECT_NE(show.out.find("Il raggio rosso arancio."), std::string::npos) << show.out;
    EXPECT_NE(show.out.find("a) Uno\nb) Due"), std::string::npos) << show.out;
    const CliRun key = run("lesson key new.json");
    ASSERT_EQ(key.code, 0) << key.err;
    const auto j = nlohmann::json::parse(key.out);
    EXPECT_EQ(j["answers"]["disc"], "4");
    EXPECT_EQ(j["answers"]["why"], "b");
    write("sheet.json", R"({"lesson": "new", "answers": {"disc": "2", "why": "a"}})");
    const CliRun graded = run("lesson check new.json --answers sheet.json --lang it");
    ASSERT_EQ(graded.code, 0) << graded.err;
    EXPECT_NE(graded.out.find("0 / 2"), std::string::npos) << graded.out;
    EXPECT_NE(graded.out.find("Δ = B² − 4AC = (-10)² − 4 · 1 · 24 = 4"), std::string::npos)
        << graded.out;
    // The prompt must state the data: drop R = 1 from the Italian and validation names it.
    std::string text = slurp(dir / "new.json");
    text.replace(text.find("c = (0; 0; 0), R = 1"), 20, "c = (0; 0; 0)");
    write("new.json", text);
    const CliRun bad = run("lesson validate new.json");
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.err.find("key 'exercises[0].prompt.it': the prompt does not state the given "
                           "number 1"),
              std::string::npos)
        << bad.err;
}

// A lecturer's own lesson beside its own scene file: the scene path is relative to the lesson.
TEST_F(Cli, ALessonFileWithItsOwnScene) {
    fs::create_directories(dir / "course");
    std::ofstream(dir / "course" / "room.json")
        << R"({"dimensions": 2, "grid": [2, 1], "ray": {"origin": [0.5, 0.5], "dir": [1, 0]},
               "segments": [{"from": [1.5, 0], "to": [1.5, 1]}]})";
    std::ofstream(dir / "course" / "mine.json") << R"({
        "format": "raystep-lesson", "version": 1, "id": "mine", "number": 40,
        "title": {"en": "Mine"}, "text": {"en": "Two cells."}, "scene": "room.json",
        "setup": {"accel": "grid"}, "trace": {"ray": "example"},
        "exercises": [{"id": "second", "type": "next_cell", "at": {"before": "dda_cell", "nth": 2},
                       "prompt": {"en": "Next?"}},
                      {"id": "t", "type": "value", "quantity": "hit.t", "prompt": {"en": "t?"}}]})";
    const CliRun v = run("lesson validate course/mine.json");
    ASSERT_EQ(v.code, 0) << v.err;
    const CliRun key = run("lesson key course/mine.json");
    ASSERT_EQ(key.code, 0) << key.err;
    // By hand: from (0.5, 0.5) along +x the walk goes (0, 0), (1, 0); the wall x = 1.5 at t = 1.
    const auto j = nlohmann::json::parse(key.out);
    EXPECT_EQ(j["answers"]["second"], "1,0");
    EXPECT_EQ(j["answers"]["t"], "1");
}

TEST_F(Cli, LessonBadInput) {
    std::ofstream(dir / "bad.json") << "{\"lesson\": \"6\",\n \"answers\": {\"next-cel\": [2, 2]}}";
    expectBadInputKeepFiles(
        "lesson check 6 --answers bad.json",
        "bad.json:2: key 'answers.next-cel': lesson grid-2d-dda has no exercise");
    std::ofstream(dir / "lesson.json") << "{\"format\": \"raystep-lesson\", \"version\": 1,\n"
                                          "\"id\": \"x y\"}";
    expectBadInputKeepFiles("lesson validate lesson.json", "lesson.json:1: ");
    expectBadInputKeepFiles("lesson show 99", "no built-in lesson of that id or number");
    expectBadInputKeepFiles("lesson check 6 --answers missing.json", "missing.json");
    expectBadInputKeepFiles("lesson show 6 --lang fr", "--lang fr: expected en or it");
}
// ---- The readers on hostile files (robustness review, issue 15) ----

class CliReaders : public Cli {
  protected:
    /// Exit code 2, one "raystep-cli: error:" line containing `expected`, no new file.
    void expectOneLine(const std::string& args, const std::string& expected) {
        std::size_t before = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++before;
        const CliRun r = run(args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(r.err.rfind("raystep-cli: error: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
        std::size_t after = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++after;
        EXPECT_EQ(after, before) << args;
    }
};

TEST_F(CliReaders, AnswersFileThatIsAFolderOrMissing) {
    fs::create_directories(dir / "answers");
    // A folder is a class's sheets: one without any is named.
    expectOneLine("lesson check 6 --answers answers",
                  "answers: no answer sheets (*.json files) in the folder");
    expectOneLine("lesson check 6 --answers none.json",
                  "none.json: cannot read the answers file: no such file");
}

TEST_F(CliReaders, ALessonNumberInTheAnswersFile) {
    // In (2, 1) tMaxX = 3.25 < tMaxY = 4 (lesson 6 by hand): the next cell is (3, 1).
    write("a.json", "{\"lesson\": 6, \"answers\": {\"next-cell\": [3, 1]}}");
    const CliRun r = run("lesson check 6 --answers a.json --json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["score"], 1);
}

TEST_F(CliReaders, SymlinkLoopsAndOverlongNames) {
    fs::create_symlink("b.json", dir / "a.json");
    fs::create_symlink("a.json", dir / "b.json");
    for (const char* args : {"render a.json -o x.png", "lesson validate a.json",
                             "lesson check 6 --answers a.json", "trace a.json -o t.json"})
        expectOneLine(args, "a.json: cannot read the ");
    const std::string longName(300, 'x');
    expectOneLine("render " + longName + "/s.json -o x.png", "the name is too long");
}

TEST_F(CliReaders, SpecialFilesAreRefusedWithoutReading) {
    ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
    for (const std::string file : {"fifo.json", "/dev/zero", "/dev/urandom"}) {
        expectOneLine("render " + file + " -o x.png", "not a regular file");
        expectOneLine("lesson validate " + file, "not a regular file");
        expectOneLine("lesson check 6 --answers " + file, "not a regular file");
    }
    write("mesh.json", "{\"objects\": [\n{\"type\": \"mesh\", \"file\": \"fifo.json\"}]}");
    expectOneLine("render mesh.json -o x.png",
                  "mesh.json:2: key 'objects[0].file': cannot read OBJ file 'fifo.json': not a "
                  "regular file");
}

TEST_F(CliReaders, DeepNestingAndControlCharactersStayOneLine) {
    write("deep.json",
          "{\"objects\":\n" + std::string(200000, '[') + std::string(200000, ']') + "}");
    expectOneLine("render deep.json -o x.png", "deep.json:2: nested deeper than 64 levels");
    write("bad\nname.json", "{\"objects\": [{\"type\": \"cu\\nbe\\u0000x\"}]}");
    expectOneLine("render 'bad\nname.json' -o x.png",
                  "bad\\nname.json:1: key 'objects[0].type': unknown object type 'cu\\nbe\\x00x'");
}

// Values typed on the command line are quoted escaped too: every message is one line, whatever
// an option or a built-in name carries (a newline, an escape sequence).
TEST_F(Cli, ControlCharactersInOptionsStayOneLine) {
    expectBadInput("render 'no\nsuch' -o x.png", "no\\nsuch");
    // (sh has no $'...': printf makes the bytes.)
    expectBadInput("render default --accel \"$(printf 'oct\\033[31mree')\" -o x.png",
                   "oct\\x1b[31mree");
    expectBadInput(
        "dda --grid \"$(printf '4,\\r3')\" --min 0,0 --max 4,3 --origin 0.5,0.2 --dir 1,0.6",
        "--grid 4,\\r3");
}

// --------------------------------------------------------------------------------------------
// Numbers at the extremes: the grid's lambda, the DDA's crossing times, the kernels' range.

TEST_F(Cli, GridLambdaIsMonotonicAndCapped) {
    // lambda is cells per primitive: more lambda, never fewer cells, never past the cap (a huge
    // lambda used to wrap through int to a one-cell grid).
    long last = 0;
    for (const char* lambda : {"0.001", "1", "4", "1e6", "2147483648", "1e300", "1.7e308"}) {
        const CliRun r = run(std::string("render default --width 8 --height 6 --accel grid "
                                         "--grid-lambda ") +
                             lambda + " --stats s.json");
        ASSERT_EQ(r.code, 0) << lambda << ": " << r.err;
        const auto cells = nlohmann::json::parse(slurp(dir / "s.json"))["grid"]["cells"];
        const long total = cells[0].get<long>() * cells[1].get<long>() * cells[2].get<long>();
        EXPECT_GE(total, last) << lambda;
        EXPECT_LE(total, 1L << 24) << lambda;
        last = total;
    }
    EXPECT_GT(last, 1L << 20);
    const CliRun help = run("render --help");
    EXPECT_NE(help.out.find("cells per primitive"), std::string::npos) << help.out;
    EXPECT_EQ(help.out.find("primitives a cell"), std::string::npos) << help.out;
    EXPECT_EQ(help.out.find("primitives per cell"), std::string::npos) << help.out;
}

TEST_F(Cli, GridRenderOfAHugeSceneIsRefusedByItsObject) {
    // A floor 2e307 wide seen from nearby: the DDA's crossing times overflowed double and it
    // aborted. The scene is past the kernels' range, so the loader refuses it naming the floor
    // (the DDA's own overflow cases are checked in dda_test.cpp).
    write("huge.json", R"({
        "camera": {"eye": [0, 3, 10], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 45},
        "lights": [{"position": [0, 100, 0], "color": [1, 1, 1], "intensity": 1}],
        "materials": {"m": {"kd": 0.5}},
        "objects": [
          {"type": "triangle", "material": "m",
           "vertices": [[-1e307, 0, -1e307], [-1e307, 0, 1e307], [1e307, 0, 1e307]]},
          {"type": "sphere", "material": "m", "center": [0, 1, 0], "radius": 1}]})");
    const CliRun r = run("render huge.json -o h.png --width 16 --height 12 --accel grid");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("huge.json:6: key 'objects[0]': coordinates reach 1e+307"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "h.png"));
}

TEST_F(Cli, FloatKernelsRefuseAScenePastTheirRange) {
    // Coordinates of 1e10 are fine for double and past float's exact range (1e8): every command
    // that traces with --precision float refuses the scene by name, before writing anything.
    write("far.json", R"({
        "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "sphere", "radius": 1},
                    {"type": "sphere", "center": [1e10, 0, 0], "radius": 1}]})");
    for (const char* cmd : {"render far.json -o f.png --precision float",
                            "trace far.json --pixel 1,1 -o t.json --precision float",
                            "compare far.json --precision float",
                            "build far.json --accel kdtree --precision float"}) {
        const CliRun r = run(cmd);
        EXPECT_EQ(r.code, 2) << cmd << "\n" << r.err;
        EXPECT_NE(r.err.find("far.json: --precision float: coordinates reach 1e+10"),
                  std::string::npos)
            << cmd << "\n"
            << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "f.png"));
    EXPECT_FALSE(fs::exists(dir / "t.json"));
    // The default (the fast path, in float) gives way to the accurate path, and says so.
    const CliRun ok = run("render far.json -o f.png --width 8 --height 6");
    EXPECT_EQ(ok.code, 0) << ok.err;
    EXPECT_NE(ok.err.find("rendered with bruteforce in double"), std::string::npos) << ok.err;
    const CliRun fast = run("render far.json -o f.png --width 8 --height 6 --accel fast");
    EXPECT_EQ(fast.code, 2) << fast.err;
}

TEST_F(Cli, TwoDimensionalRaysOutsideTheKernelsRangeAreRefused) {
    // The circle test squares the direction: at 1e200 it overflowed, the circle was missed and
    // the floor segment reported instead, exit 0.
    expectBadInput("trace lecture-grid --ray 2.5,3,0,-1e200 -o t.json", "--ray 2.5,3,0,-1e200: ");
    expectBadInput("trace lecture-grid --ray 2.5,3,0,-1e-70 -o t.json", "direction");
    const CliRun ok = run("trace lecture-grid --ray 2.5,3,0,-1 -o t.json");
    EXPECT_EQ(ok.code, 0) << ok.err;
}

TEST_F(Cli, OutputsNeverOverwriteTheInputOrHaveNoName) {
    // Writing a command's output over the scene it reads would lose the scene.
    write("my.json", R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "sphere", "radius": 1}]})");
    const std::string scene = slurp(dir / "my.json");
    for (const char* cmd :
         {"trace my.json --pixel 0,0 -o my.json", "build my.json --events my.json",
          "render my.json -o x.png --stats my.json --width 4 --height 4",
          "render my.json -o x.png --stats ./my.json --width 4 --height 4"}) {
        const CliRun r = run(cmd);
        EXPECT_EQ(r.code, 2) << cmd << "\n" << r.err;
        EXPECT_NE(r.err.find("the command reads this file"), std::string::npos) << r.err;
        EXPECT_EQ(slurp(dir / "my.json"), scene) << cmd;
        EXPECT_FALSE(fs::exists(dir / "x.png")) << cmd;
    }
    // An empty file name given on purpose is refused before any work, not taken as "none".
    for (const char* cmd :
         {"build --events ''", "trace --pixel 0,0 -o ''", "render -o ''", "render --stats ''",
          "render --heatmap ''", "lesson check 6 --answers ''"}) {
        const CliRun r = run(cmd);
        EXPECT_EQ(r.code, 2) << cmd << "\n" << r.err;
        EXPECT_NE(r.err.find("empty file name"), std::string::npos) << cmd << "\n" << r.err;
    }
}

TEST_F(Cli, DdaRefusesAGridThatFloatCannotHold) {
    // In float, --max rounds onto --min: the walk has no grid, which is bad input, not a miss.
    expectBadInput(
        "dda --grid 4,4 --min 1,0 --max 1.00000001,1 --origin 0,0.5 --dir 1,0 "
        "--precision float",
        "not above its lower corner");
}

TEST_F(Cli, LessonCheckPrintsAStudentsAnswerAsOneEscapedLine) {
    // An answer holding a newline or an escape sequence must not forge a line of the report.
    write("a.json", "{\"lesson\": 6, \"answers\": {\"tdelta-y\": \"1\\n      right\\u001b[2J\"}}");
    const CliRun r = run("lesson check 6 --answers a.json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.find("\n      right"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << r.out;
}

TEST_F(Cli, IntersectFarAheadAndOutOfRange) {
    // A unit triangle straight ahead at t = 1e18: a hit (the watertight test's bound missed it).
    CliRun r = run("intersect --ray 0.25,0.25,1e18:0,0,-1 --triangle 0,0,0:1,0,0:0,1,0 --json");
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["hit"], true);
    EXPECT_EQ(j["t"], 1e18);
    // Squares past double's range (every method missed, silently) and products below it (the
    // stable sphere hit a sphere missed by 4% of its radius): refused in one line.
    const std::string far = "intersect --ray 0,0,0:0,0,1 --sphere 0,0,5e160:1e160";
    expectBadInput(far, "left the range it is exact in");
    expectBadInput(far + " --method textbook", "a result overflowed");
    expectBadInput(
        "intersect --ray 0,0,0:0,0,1 --triangle -1e160,-1e160,1e160:1e160,-1e160,"
        "1e160:0,1e160,1e160",
        "left the range it is exact in");
    expectBadInput(
        "intersect --ray 0,0,0:2.0340072443528589e-142,0,9.7909557516066899e-142 "
        "--sphere 0,0,5e-141:1e-141",
        "a result underflowed");
    // In float, the numbers themselves must be floats.
    expectBadInput("intersect --ray 0,0,0:0,0,1 --sphere 0,0,5:1e-50 --precision float",
                   "--sphere 0,0,5:1e-50: 1e-50 is not a normal float");
    expectBadInput("intersect --ray 0,0,1e39:0,0,1 --sphere 0,0,5:1 --precision float",
                   "--ray 0,0,1e39:0,0,1: 1e+39 is not a normal float");
    // Inside the range nothing is refused, however far in float (the sphere is a miss there).
    r = run("intersect --ray 0,0,0:0,0,1 --sphere 0,0,1e8:1 --precision float --json");
    EXPECT_EQ(r.code, 0) << r.err;
}
}  // namespace
