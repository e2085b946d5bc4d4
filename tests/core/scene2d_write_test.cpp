// 2D scene files written by the app's live editing (scene2d_io.h): read back, they are the same
// scene to the last bit; a scene the loader would refuse is never written; a bad path is one
// error naming it, and nothing is left half written.
#include "raystep/scene/scene2d_io.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace raystep {
namespace {

namespace fs = std::filesystem;

std::string fileText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void expectSameScene(const Scene2D& a, const Scene2D& b) {
    EXPECT_EQ(a.description, b.description);
    ASSERT_EQ(a.gridRes.has_value(), b.gridRes.has_value());
    if (a.gridRes) {
        EXPECT_EQ(*a.gridRes, *b.gridRes);
    }
    ASSERT_EQ(a.exampleRay.has_value(), b.exampleRay.has_value());
    if (a.exampleRay) {
        EXPECT_EQ(a.exampleRay->origin, b.exampleRay->origin);
        EXPECT_EQ(a.exampleRay->dir, b.exampleRay->dir);
    }
    ASSERT_EQ(a.circles.size(), b.circles.size());
    for (std::size_t i = 0; i < a.circles.size(); ++i) {
        EXPECT_EQ(a.circles[i].center, b.circles[i].center) << i;
        EXPECT_EQ(a.circles[i].radius, b.circles[i].radius) << i;
    }
    ASSERT_EQ(a.segments.size(), b.segments.size());
    for (std::size_t i = 0; i < a.segments.size(); ++i) {
        EXPECT_EQ(a.segments[i].a, b.segments[i].a) << i;
        EXPECT_EQ(a.segments[i].b, b.segments[i].b) << i;
    }
}

/// Values no short decimal holds: 0.1 + 0.2, 1/3, a subnormal-free tiny and a large one.
Scene2D awkward() {
    Scene2D s;
    s.description = "quotes \" and \\ and a tab\t and UTF-8: \xc3\xa8";
    s.gridRes = IVecN<2>(7, 3);
    s.exampleRay = Ray2{Vec2(0.1 + 0.2, 1.0 / 3.0), Vec2(std::nextafter(0.8, 1.0), -0.4)};
    s.circles = {{Vec2(2.5, 0.5), 0.3}, {Vec2(-1e-3 / 3.0, 12345.678901234567), 2.0 / 7.0}};
    s.segments = {{Vec2(0.0, 0.0), Vec2(6.0, 0.0)}, {Vec2(1.0 / 9.0, -2.0), Vec2(3.0, 1e3 / 7.0)}};
    return s;
}

TEST(Scene2DWrite, TheTextReadsBackToTheSameSceneToTheLastBit) {
    const Scene2D s = awkward();
    const std::string text = scene2DText(s, "edited.json");
    EXPECT_TRUE(isScene2DText(text));
    expectSameScene(loadScene2DText(text, "edited.json"), s);
    // The built-in lecture scenes, written and read back, are the same too.
    for (const std::string name : {"lecture-grid", "lecture-kdtree"}) {
        const Scene2D lecture = std::get<Scene2D>(loadAnyScene(name));
        expectSameScene(loadScene2DText(scene2DText(lecture, "x.json"), "x.json"), lecture);
    }
    // Without a ray or a grid: none is written, none read.
    Scene2D bare;
    bare.segments = {{Vec2(0.0, 0.0), Vec2(1.0, 1.0)}};
    const Scene2D back = loadScene2DText(scene2DText(bare, "bare.json"), "bare.json");
    EXPECT_FALSE(back.exampleRay);
    EXPECT_FALSE(back.gridRes);
    EXPECT_TRUE(back.circles.empty());
}

TEST(Scene2DWrite, ASceneTheLoaderWouldRefuseIsNotWritten) {
    const auto refused = [](Scene2D s, const std::string& why) {
        try {
            scene2DText(s, "out.json");
            ADD_FAILURE() << "written: " << why;
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find("out.json"), std::string::npos) << e.what();
        }
    };
    refused(Scene2D{}, "empty");
    Scene2D nan = awkward();
    nan.circles[0].center.x = std::numeric_limits<double>::quiet_NaN();
    refused(nan, "NaN");
    Scene2D inf = awkward();
    inf.segments[1].b.y = std::numeric_limits<double>::infinity();
    refused(inf, "infinity");
    Scene2D zero = awkward();
    zero.circles[1].radius = 0.0;
    refused(zero, "zero radius");
    Scene2D noDir = awkward();
    noDir.exampleRay->dir = Vec2(0.0);
    refused(noDir, "zero direction");
    Scene2D huge = awkward();
    huge.circles[0].center.x = 1e300;
    refused(huge, "out of range");
}

TEST(Scene2DWrite, SavedAtomicallyBadPathsNamedNothingHalfWritten) {
    const fs::path dir =
        fs::temp_directory_path() / ("raystep-scene2d-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path good = dir / "edited.json";
    saveScene2D(awkward(), good.string());
    expectSameScene(std::get<Scene2D>(loadAnyScene(good.string())), awkward());
    // A refused scene leaves the file there as it was.
    const std::string before = fileText(good);
    EXPECT_THROW(saveScene2D(Scene2D{}, good.string()), SceneError);
    EXPECT_EQ(fileText(good), before);
    // A folder, a FIFO, a missing folder: one error naming the path, nothing written.
    const fs::path fifo = dir / "pipe.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const fs::path& bad : {dir, fifo, dir / "missing" / "x.json"}) {
        try {
            saveScene2D(awkward(), bad.string());
            ADD_FAILURE() << "written to " << bad;
        } catch (const std::exception& e) {
            EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    }
    EXPECT_FALSE(fs::exists(dir / "missing"));
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        (void)entry;
        ++files;
    }
    EXPECT_EQ(files, 2u);  // edited.json and the FIFO: no temporary left behind
    fs::remove_all(dir);
}

}  // namespace
}  // namespace raystep
