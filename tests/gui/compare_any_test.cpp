// Compare mode on any set of structures: the slides' grid, kd-tree and BVH (and brute force) on
// the same ray, their counts against an independent trace of each, the chooser, the 3D views
// turning together, and `raystep --compare --accel grid,kdtree,bvh` (its Italian: i18n_gui_test).
#include "compare_chooser.h"
#include "compare_window.h"
#include "gui_testing.h"
#include "language.h"
#include "vtk_view.h"

#include "raystep/accel/accel.h"
#include "raystep/scene/scene_loader.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QRadioButton>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace raystep::gui {
namespace {

bool open(MainWindow& w, const char* scene, AccelKind kind) {
    w.openScene(scene, kind, /*quiet=*/true, {}, /*render=*/false);
    return w.waitUntilIdle() && w.lastOpenOk().value_or(false);
}

std::vector<StructureChoice> choices(const char* kinds) {
    return std::get<std::vector<StructureChoice>>(parseStructureChoices(kinds, std::nullopt));
}

TEST(CompareAny, TheSameRayThroughAGridAKdTreeABvhAndBruteForce) {
    MainWindow w;
    ASSERT_TRUE(open(w, "lecture-kdtree", AccelKind::KdTree));
    w.openCompare(choices("grid,kdtree,bvh,bruteforce"));
    ASSERT_TRUE(w.waitUntilIdle());
    CompareWindow* c = w.compareWindow();
    ASSERT_NE(c, nullptr);
    ASSERT_EQ(c->count(), 4);
    ASSERT_EQ(c->table()->columnCount(), 4);
    const char* headers[] = {"grid", "kd-tree, SAH", "BVH, SAH", "brute force"};
    for (int i = 0; i < 4; ++i) EXPECT_EQ(c->table()->horizontalHeaderItem(i)->text(), headers[i]);
    // An independent count of each: the structure built again here and the same ray traced by
    // traceRay2D, whose counters (not the recorded events the table reads) count the tests.
    const Scene2D scene = std::get<Scene2D>(loadAnyScene("lecture-kdtree"));
    const Ray2 ray = scene.exampleRay.value();
    const AccelKind kinds[] = {AccelKind::Grid, AccelKind::KdTree, AccelKind::Bvh,
                               AccelKind::BruteForce};
    c->setStep(1 << 20);
    std::optional<double> firstT;
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(c->choice(i).kind, kinds[i]);
        EXPECT_EQ(c->choice(i).split.has_value(), hasSplit(kinds[i]));
        AccelOptions o;  // lecture-kdtree's scene sets no option: the defaults, SAH
        const Accelerator2D a = buildAccelerator2D(scene, kinds[i], o);
        EventLog log;
        TraversalCounters n;
        const auto hit = traceRay2D(a, ray, log, &n);
        ASSERT_TRUE(hit);
        const auto cell = [&](CompareWindow::Row r) { return c->table()->item(r, i)->text(); };
        EXPECT_EQ(cell(CompareWindow::RayTests).toULongLong(), n.primitiveTests) << headers[i];
        EXPECT_EQ(cell(CompareWindow::RaySkips).toULongLong(), n.mailboxSkips) << headers[i];
        // Every structure finds the same nearest hit (they must agree).
        const auto t = c->session(i).replay().state().nearestT;
        ASSERT_TRUE(t);
        EXPECT_DOUBLE_EQ(*t, hit->t);
        if (!firstT) firstT = t;
        EXPECT_DOUBLE_EQ(*t, *firstT) << headers[i];
    }
    // Brute force tests every primitive once; only a tree has a SAH cost.
    EXPECT_EQ(c->table()->item(CompareWindow::RayTests, 3)->text().toUInt(),
              scene.primitiveCount());
    EXPECT_EQ(c->table()->item(CompareWindow::SahCost, 0)->text(), "-");
    EXPECT_NE(c->table()->item(CompareWindow::SahCost, 2)->text(), "-");
    // One legend under the four 2D views, and how far each replay has come.
    auto* legend = c->findChild<QLabel*>("compareLegend");
    ASSERT_NE(legend, nullptr);
    EXPECT_TRUE(legend->text().contains("nearest hit")) << legend->text().toStdString();
    c->setStep(3);
    EXPECT_EQ(c->progressText(0), QStringLiteral("event 3 of %1").arg(c->session(0).size()));
    c->close();
}

TEST(CompareAny, TheChooserGivesATreesSplitsOrAnySetAndRemembersIt) {
    // Opened on a kd-tree's split methods: three columns of one tree.
    CompareChooser a(defaultComparison(AccelKind::KdTree));
    EXPECT_TRUE(a.splitsMode()->isChecked());
    EXPECT_EQ(a.choices(), choices("kdtree"));
    a.tree()->setCurrentIndex(a.tree()->findData(static_cast<int>(AccelKind::Bvh)));
    EXPECT_EQ(a.choices(), choices("bvh"));
    // The other mode: the boxes ticked, the trees by the split chosen, in the table's order.
    a.structuresMode()->setChecked(true);
    a.kindBox(AccelKind::Grid)->setChecked(false);
    a.kindBox(AccelKind::BruteForce)->setChecked(true);
    a.split()->setCurrentIndex(a.split()->findData(static_cast<int>(SplitMethod::Median)));
    const std::vector<StructureChoice> want{{AccelKind::BruteForce, std::nullopt},
                                            {AccelKind::KdTree, SplitMethod::Median},
                                            {AccelKind::Bvh, SplitMethod::Median}};
    EXPECT_EQ(a.choices(), want);
    EXPECT_EQ(CompareChooser::toText(want), "bruteforce,kdtree,bvh|median");
    EXPECT_EQ(CompareChooser::fromText(CompareChooser::toText(want)), want);
    EXPECT_EQ(CompareChooser::fromText("octree|"), std::nullopt);
    EXPECT_EQ(CompareChooser::fromText("nonsense"), std::nullopt);
    // Nothing ticked: nothing to compare.
    for (const StructureInfo& s : structures()) a.kindBox(s.kind)->setChecked(false);
    EXPECT_TRUE(a.choices().empty());
    EXPECT_FALSE(a.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    // A grid shown: the slides' comparison, grid against the two trees.
    CompareChooser b(defaultComparison(AccelKind::Grid));
    EXPECT_TRUE(b.structuresMode()->isChecked());
    EXPECT_EQ(b.choices(), choices("grid,kdtree,bvh"));
}

TEST(CompareAny, ShiftCAsksWhichAndCComparesAtOnce) {
    MainWindow w;
    w.resize(1366, 740);
    w.show();
    w.activateWindow();  // a window's shortcuts reach the active window only
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    ASSERT_TRUE(open(w, "lecture-kdtree", AccelKind::KdTree));
    // C: the structure shown's own comparison, a kd-tree's three splits.
    QTest::keyClick(&w, Qt::Key_C);
    ASSERT_TRUE(w.waitUntilIdle());
    ASSERT_NE(w.compareWindow(), nullptr) << w.statusBar()->currentMessage().toStdString();
    EXPECT_EQ(w.compareWindow()->count(), 3);
    EXPECT_EQ(w.compareWindow()->choice(2), (StructureChoice{AccelKind::KdTree, SplitMethod::Sah}));
    w.compareWindow()->close();
    // Shift+C: the chooser, not modal to the event loop; the slides' comparison ticked, then OK.
    QTest::keyClick(&w, Qt::Key_C, Qt::ShiftModifier);
    CompareChooser* chooser = w.compareChooser();
    ASSERT_NE(chooser, nullptr);
    EXPECT_TRUE(chooser->isVisible());
    QTest::mouseClick(chooser->structuresMode(), Qt::LeftButton);
    ASSERT_TRUE(chooser->structuresMode()->isChecked());
    EXPECT_EQ(chooser->choices(), choices("grid,kdtree,bvh"));
    QTest::mouseClick(chooser->buttons()->button(QDialogButtonBox::Ok), Qt::LeftButton);
    ASSERT_TRUE(w.waitUntilIdle());
    ASSERT_TRUE(waitFor([&] { return w.compareWindow() != nullptr; }));
    EXPECT_EQ(w.compareWindow()->count(), 3);
    EXPECT_EQ(w.compareWindow()->choice(0).kind, AccelKind::Grid);
    EXPECT_EQ(w.compareWindow()->choice(2).kind, AccelKind::Bvh);
    w.compareWindow()->close();
    // The next chooser opens on what was chosen.
    QTest::keyClick(&w, Qt::Key_C, Qt::ShiftModifier);
    ASSERT_NE(w.compareChooser(), nullptr);
    EXPECT_EQ(w.compareChooser()->choices(), choices("grid,kdtree,bvh"));
    w.compareChooser()->reject();
}

TEST(CompareAny, The3DViewsTurnTogether) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "whitted", AccelKind::Grid));
    w.session().tracePixel(150, 100, 320, 240);
    w.openCompare(choices("grid,kdtree,bvh"));
    ASSERT_TRUE(w.waitUntilIdle());
    CompareWindow* c = w.compareWindow();
    ASSERT_NE(c, nullptr);
    c->resize(1366, 740);
    c->show();
    QApplication::processEvents();
    const auto cam = [&](int i) { return static_cast<VtkView*>(c->view(i))->currentCamera(); };
    const auto same = [](const Camera& a, const Camera& b) {
        return glm::length(a.eye - b.eye) < 1e-9 && glm::length(a.lookAt - b.lookAt) < 1e-9 &&
               std::abs(a.fovDeg - b.fovDeg) < 1e-9;
    };
    for (int i = 1; i < 3; ++i) EXPECT_TRUE(same(cam(0), cam(i))) << i;
    // Turning the last view turns the others the same way.
    const Camera before = cam(0);
    static_cast<VtkView*>(c->view(2))->orbit(40, 20, 1.2);
    EXPECT_FALSE(same(cam(0), before));
    for (int i = 0; i < 2; ++i) EXPECT_TRUE(same(cam(i), cam(2))) << i;
    // One pair of camera buttons for all: from the eye puts every view at the scene's camera.
    auto* eye = c->findChild<QPushButton*>("compareFromEye");
    ASSERT_NE(eye, nullptr);
    eye->click();
    const Camera& sceneCam = w.session().scene3D()->camera;
    for (int i = 0; i < 3; ++i) EXPECT_LT(glm::length(cam(i).eye - sceneCam.eye), 1e-9) << i;
    delete c;
}

int run(const std::string& args) {
    const int status = std::system(("timeout 120 '" RAYSTEP_APP "' " + args).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CompareAny, TheAppOpensAListFromTheCommandLine) {
    namespace fs = std::filesystem;
    QTemporaryDir dir;
    setenv("XDG_DATA_HOME", dir.path().toUtf8().constData(), 1);
    const fs::path shot = fs::path(dir.path().toStdString()) / "c.png",
                   said = fs::path(dir.path().toStdString()) / "said.txt";
    ASSERT_EQ(run("--scene lecture-kdtree --compare --accel grid,kdtree,bvh --screenshot '" +
                  shot.string() + "' > '" + said.string() + "' 2>/dev/null"),
              0);
    QFile out(QString::fromStdString(said.string()));
    ASSERT_TRUE(out.open(QIODevice::ReadOnly));
    EXPECT_TRUE(out.readAll().contains("compare grid | kd-tree, SAH | BVH, SAH"));
    EXPECT_FALSE(QImage(QString::fromStdString(shot.string())).isNull());
    // A list without --compare, an unknown name, a kind twice: exit 2, nothing written.
    const fs::path bad = fs::path(dir.path().toStdString()) / "bad.png";
    for (const char* accel : {"grid,kdtree", "grid,octree", "bvh,bvh"}) {
        const std::string compare = std::string(accel) == "grid,kdtree" ? "" : " --compare";
        EXPECT_EQ(run("--scene lecture-kdtree" + compare + " --accel " + accel + " --screenshot '" +
                      bad.string() + "' 2>/dev/null"),
                  2)
            << accel;
    }
    EXPECT_FALSE(fs::exists(bad));
}

}  // namespace
}  // namespace raystep::gui
