// The layering check itself: an include planted in a real file is caught at its line with its
// rule; what the layering allows is not flagged; a commented-out include is no include.
#include "layer_check.h"
#include "source_tree.h"

#include <gtest/gtest.h>

#include <string>

namespace raystep::checks {
namespace {

std::string readSource(const std::string& relative) {
    return readWhole(std::filesystem::path(RAYSTEP_SOURCE_DIR) / relative);
}

TEST(LayerCheck, TheSceneIncludingTheStructuresIsCaughtAtItsLine) {
    const std::string path = "algorithms/raystep/scene/scene.h";
    const std::string scene = readSource(path);
    ASSERT_GT(scene.size(), 1000u);
    ASSERT_TRUE(findLayerViolations(path, scene).empty());
    const auto found =
        findLayerViolations(path, plantAt(scene, 5, "#include \"raystep/accel/accel.h\""));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].line, 5u);
    EXPECT_EQ(found[0].header, "raystep/accel/accel.h");
    EXPECT_EQ(found[0].rule, "scene/ includes a floor above it (accel/)");
    const auto render =
        findLayerViolations(path, plantAt(scene, 3, "#  include \"raystep/render/image.h\""));
    ASSERT_EQ(render.size(), 1u);
    EXPECT_EQ(render[0].line, 3u);
}

TEST(LayerCheck, AFloorMayIncludeItselfAndTheFloorsUnderIt) {
    EXPECT_TRUE(findLayerViolations("algorithms/raystep/render/tracer.cpp",
                                    "#include \"raystep/accel/accel.h\"\n"
                                    "#include \"raystep/scene/scene.h\"\n"
                                    "#include \"raystep/render/image.h\"\n"
                                    "#include <tbb/parallel_for.h>\n")
                    .empty());
    const auto base = findLayerViolations("algorithms/raystep/base/math.h",
                                          "#include <cmath>\n#include \"raystep/geometry/x.h\"\n");
    ASSERT_EQ(base.size(), 1u);
    EXPECT_EQ(base[0].line, 2u);
    EXPECT_EQ(base[0].rule, "base/ includes a floor above it (geometry/)");
}

TEST(LayerCheck, QtAndVtkStayOutOfTheCoreAndTheCourseEngine) {
    const auto core = findLayerViolations("algorithms/raystep/trace/replay.cpp",
                                          "#include <QString>\n#include <vtkActor.h>\n");
    ASSERT_EQ(core.size(), 2u);
    EXPECT_EQ(core[0].rule, "the core includes Qt or VTK");
    EXPECT_EQ(core[1].line, 2u);
    const auto course = findLayerViolations("app/course/exercise.cpp", "#include <QtCore/QFile>\n");
    ASSERT_EQ(course.size(), 1u);
    EXPECT_EQ(course[0].rule, "the course engine includes Qt or VTK");
    EXPECT_EQ(
        findLayerViolations("algorithms/raystep/base/i18n.cpp", "#include \"course/lesson.h\"")
            .at(0)
            .rule,
        "the core includes the course engine");
    // The app is where Qt and VTK live.
    EXPECT_TRUE(findLayerViolations("app/gui/view2d.cpp", "#include <QPainter>\n").empty());
}

TEST(LayerCheck, NoClientIncludesAStructuresInternalHeader) {
    const std::string path = "app/gui/view2d.cpp";
    const std::string view = readSource(path);
    ASSERT_TRUE(findLayerViolations(path, view).empty());
    const auto found =
        findLayerViolations(path, plantAt(view, 9, "#include \"raystep/accel/kdtree_build.h\""));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].line, 9u);
    EXPECT_EQ(found[0].rule, "a client includes a structure's internal header");
    // The structure's own files and the tests may.
    EXPECT_TRUE(findLayerViolations("algorithms/raystep/accel/kdtree_fast.cpp",
                                    "#include \"raystep/accel/kdtree_build.h\"")
                    .empty());
    EXPECT_TRUE(
        findLayerViolations("tests/core/kdtree_test.cpp", "#include \"raystep/accel/query_impl.h\"")
            .empty());
}

TEST(LayerCheck, ACommentedOutIncludeIsNoInclude) {
    const auto inc = includesOf(
        "// #include \"raystep/accel/accel.h\"\n  #include <vector>\n#define X \"#include <a>\"\n"
        "\t#\tinclude \"b.h\"");
    ASSERT_EQ(inc.size(), 2u);
    EXPECT_EQ(inc[0], (std::pair<std::size_t, std::string>{2, "vector"}));
    EXPECT_EQ(inc[1], (std::pair<std::size_t, std::string>{4, "b.h"}));
}

}  // namespace
}  // namespace raystep::checks
