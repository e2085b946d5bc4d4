// Models in the app: File > Open's structure (never the lesson's brute force on a big mesh), the
// structure chooser rebuilding in the background, changing the structure in a lesson as exploring,
// a bad model file as a dialog that keeps the scene, `raystep --scene MODEL`, and File > Save scene
// as.
#include "lesson_panel.h"
#include "main_window.h"

#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace raystep::gui {
namespace {

const QString kModels = RAYSTEP_SOURCE_DIR "/tests/data/models/";
const QString kBunny = "/usr/share/glmark2/models/bunny.obj";

/// What File > Open does once a file is picked (the dialog itself is Qt's).
bool openAsFileOpen(MainWindow& w, const QString& path, bool quiet = true) {
    w.openScene(path, w.openKind(), quiet, w.openOptions());
    return w.waitUntilIdle() && w.lastOpenOk().value_or(false);
}

/// Picks `text` in a chooser as a user does (activated, not a programmatic change) and waits
/// for the structure to be built; true if it was.
bool pick(MainWindow& w, QComboBox* box, const QString& text) {
    QSignalSpy done(&w, &MainWindow::structureChanged);
    const int index = box->findText(text);
    EXPECT_GE(index, 0) << text.toStdString();
    box->setCurrentIndex(index);
    emit box->activated(index);
    if (done.isEmpty() && !done.wait(120000)) return false;
    EXPECT_TRUE(w.waitUntilIdle());
    return done.first().at(0).toBool();
}

TEST(ModelOpen, BunnyFromLessonOneIsNotBruteForced) {
    MainWindow w;
    w.openLesson("1", true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    ASSERT_EQ(w.session().kind(), AccelKind::BruteForce);  // lesson 1 is brute force
    ASSERT_TRUE(openAsFileOpen(w, kBunny)) << w.lastOpenError().toStdString();
    ASSERT_NE(w.session().scene3D(), nullptr);
    EXPECT_EQ(w.session().scene3D()->triangles.size(), 69666u + 2u);  // and the floor's two
    EXPECT_EQ(w.session().kind(), AccelKind::KdTree);
    EXPECT_EQ(w.session().options().kdtree.split, SplitMethod::Sah);
    EXPECT_TRUE(w.structureStatus().contains("kd-tree")) << w.structureStatus().toStdString();
    EXPECT_TRUE(w.structureStatus().contains("69668")) << w.structureStatus().toStdString();
    EXPECT_EQ(w.structureChooser()->currentText(), "kd-tree");
}

TEST(ModelOpen, TheChooserBuildsTheChosenStructure) {
    MainWindow w;
    ASSERT_TRUE(openAsFileOpen(w, kModels + "pyramid.obj"));
    EXPECT_EQ(w.session().kind(), AccelKind::KdTree);
    const SceneRef before = w.session().sceneRef();

    ASSERT_TRUE(pick(w, w.structureChooser(), "BVH"));
    EXPECT_EQ(w.session().kind(), AccelKind::Bvh);
    EXPECT_NE(w.session().sceneRef(), before);
    EXPECT_TRUE(w.structureStatus().contains("BVH")) << w.structureStatus().toStdString();
    EXPECT_TRUE(w.splitChooser()->isEnabled());

    ASSERT_TRUE(pick(w, w.splitChooser(), "median"));
    EXPECT_EQ(w.session().kind(), AccelKind::Bvh);
    EXPECT_EQ(w.session().options().bvh.split, SplitMethod::Median);
    EXPECT_TRUE(w.structureStatus().contains("median")) << w.structureStatus().toStdString();

    ASSERT_TRUE(pick(w, w.structureChooser(), "grid"));
    EXPECT_EQ(w.session().kind(), AccelKind::Grid);
    EXPECT_FALSE(w.splitChooser()->isEnabled());  // a grid has no split planes
    // The same scene, built again: the model's 6 triangles and the floor's 2.
    EXPECT_EQ(w.session().scene3D()->triangles.size(), 8u);

    // File > Open then builds what was chosen; brute force only because it was chosen.
    ASSERT_TRUE(pick(w, w.structureChooser(), "brute force"));
    ASSERT_TRUE(openAsFileOpen(w, kModels + "tetra.ply"));
    EXPECT_EQ(w.session().kind(), AccelKind::BruteForce);
    EXPECT_EQ(w.structureChooser()->currentText(), "brute force");
}

TEST(ModelOpen, ChangingTheStructureInALessonIsExploring) {
    MainWindow w;
    w.openLesson("1", true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    const SceneRef lessonScene = w.session().sceneRef();
    EXPECT_FALSE(w.lessonPanel()->exploring());

    ASSERT_TRUE(pick(w, w.structureChooser(), "kd-tree"));
    EXPECT_EQ(w.session().kind(), AccelKind::KdTree);
    EXPECT_TRUE(w.lessonPanel()->exploring());
    EXPECT_TRUE(w.backToLessonAction()->isEnabled());

    // Esc: the lesson's own scene, structure and trace again.
    w.backToLessonAction()->trigger();
    EXPECT_TRUE(w.waitUntilIdle());
    EXPECT_EQ(w.session().sceneRef(), lessonScene);
    EXPECT_EQ(w.session().kind(), AccelKind::BruteForce);
    EXPECT_EQ(w.session().logRef(), w.lessonPanel()->lessonLog());
    EXPECT_FALSE(w.lessonPanel()->exploring());
    EXPECT_EQ(w.structureChooser()->currentText(), "brute force");
}

TEST(ModelOpen, ABadModelSaysWhyAndKeepsTheScene) {
    MainWindow w;
    w.show();
    ASSERT_TRUE(openAsFileOpen(w, kModels + "pyramid.obj"));
    const SceneRef shown = w.session().sceneRef();
    for (const char* file : {"nan_vertex.obj", "garbage.ply", "truncated.stl", "empty.stl",
                             "no_triangles.obj", "missing.glb"}) {
        SCOPED_TRACE(file);
        EXPECT_FALSE(openAsFileOpen(w, kModels + file, /*quiet=*/false));
        const QString error = w.lastOpenError();
        EXPECT_TRUE(error.contains(file)) << error.toStdString();
        EXPECT_FALSE(error.contains('\n')) << error.toStdString();
        EXPECT_EQ(w.session().sceneRef(), shown);
        // The dialog says it (window-modal, no nested loop): found, checked, closed.
        QMessageBox* box = nullptr;
        for (QMessageBox* b : w.findChildren<QMessageBox*>())
            if (b->isVisible()) box = b;
        ASSERT_NE(box, nullptr);
        EXPECT_EQ(box->text(), error);
        box->close();
        QApplication::processEvents();
    }
    // A FIFO named as a model: refused at once, not opened and waited on.
    const std::string fifo = (std::filesystem::temp_directory_path() /
                              ("raystep-fifo-" + std::to_string(getpid()) + ".stl"))
                                 .string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_FALSE(openAsFileOpen(w, QString::fromStdString(fifo)));
    EXPECT_TRUE(w.lastOpenError().contains("not a regular file"))
        << w.lastOpenError().toStdString();
    ::unlink(fifo.c_str());
    EXPECT_EQ(w.session().sceneRef(), shown);
}

/// Runs the app; its exit code, and its stdout and stderr together.
std::pair<int, std::string> app(const std::string& args) {
    const std::string out =
        (std::filesystem::temp_directory_path() / ("raystep-app-" + std::to_string(getpid())))
            .string();
    const int status = std::system(
        ("timeout 120 '" RAYSTEP_APP "' " + args + " > '" + out + "' 2>&1 < /dev/null").c_str());
    std::ifstream in(out);
    std::stringstream s;
    s << in.rdbuf();
    std::filesystem::remove(out);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, s.str()};
}

TEST(ModelOpen, SceneOptionOpensAModel) {
    const std::string shot = (std::filesystem::temp_directory_path() /
                              ("raystep-model-" + std::to_string(getpid()) + ".png"))
                                 .string();
    const auto [code, out] =
        app("--scene '" + kModels.toStdString() + "quad.glb' --screenshot '" + shot + "'");
    EXPECT_EQ(code, 0) << out;
    EXPECT_TRUE(std::filesystem::exists(shot)) << out;
    std::filesystem::remove(shot);
    const auto [bad, why] =
        app("--scene '" + kModels.toStdString() + "nan_vertex.ply' --screenshot '" + shot + "'");
    EXPECT_EQ(bad, 2) << why;
    EXPECT_NE(why.find("nan_vertex.ply"), std::string::npos) << why;
    EXPECT_NE(why.find("not a finite number"), std::string::npos) << why;
    EXPECT_FALSE(std::filesystem::exists(shot));
}

// File > Save scene as: the pyramid's scene (its 6 triangles, from the file's own comment, then
// the floor's 2) written as a scene file and a mesh, loaded back whole; refused for a built-in
// scene, a name that is not *.json and a folder that does not exist, with nothing written.
TEST(ModelOpen, SaveSceneAsWritesTheSceneAroundTheModel) {
    MainWindow w;
    w.resize(1200, 800);
    w.show();
    ASSERT_TRUE(openAsFileOpen(w, "whitted"));  // a scene file already: nothing to save
    QTemporaryDir dir;
    const QString json = dir.filePath("pyramid-scene.json");
    EXPECT_FALSE(w.saveModelScene(json).isEmpty());
    EXPECT_FALSE(QFileInfo::exists(json));
    ASSERT_TRUE(openAsFileOpen(w, kModels + "pyramid.obj"));
    EXPECT_FALSE(w.saveModelScene(dir.filePath("pyramid-scene.txt")).isEmpty());
    EXPECT_FALSE(w.saveModelScene(dir.filePath("no/such/folder/s.json")).isEmpty());
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    EXPECT_EQ(w.saveModelScene(json), QString());
    EXPECT_TRUE(QFileInfo::exists(dir.filePath("pyramid-scene.mesh.obj")));
    const Scene back = loadSceneFile(json.toStdString());
    ASSERT_EQ(back.triangles.size(), 6u + 2u);
    // The pyramid's apex, vertex 5 of the file, is the top of the first triangles' bounds.
    double top = -1;
    for (std::size_t i = 0; i < 6; ++i)
        for (const Vec3& v : {back.triangles[i].a, back.triangles[i].b, back.triangles[i].c})
            top = std::max(top, v.y);
    EXPECT_DOUBLE_EQ(top, 3.0);
    EXPECT_EQ(back.lights.size(), 2u);
}

}  // namespace
}  // namespace raystep::gui
