// The 2D view's live editing (issue 19), driven with real mouse and key events under Xvfb:
// dragging the ray's handles records the walk an independent computation gives for the new ray
// (a tie through a grid vertex included), moving and resizing a circle changes which primitives
// the grid lists, undo and redo bring the scenes back, and the view zooms about the cursor, pans
// and fits while a click on a cell stays a lesson's cell answer at any zoom.
#include "live2d.h"
#include "gui_testing.h"
#include "main_window.h"
#include "view2d.h"

#include "course/palette.h"

#include "raystep/accel/outline.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace raystep::gui {
namespace {

bool openGrid(MainWindow& w, const QString& scene = "lecture-grid") {
    w.openScene(scene, AccelKind::Grid, /*quiet=*/true, {}, /*render=*/false);
    return w.waitUntilIdle() && w.lastOpenOk().value_or(false);
}

QAction* act(MainWindow& w, const char* name) {
    return w.findChild<QAction*>(QString::fromLatin1(name));
}

/// A left-button drag as a hand makes it: press, a few moves on the way, release.
void drag(QWidget* view, QPointF from, QPointF to, Qt::KeyboardModifiers mods = {}) {
    const QPoint a = from.toPoint(), b = to.toPoint();
    QTest::mousePress(view, Qt::LeftButton, mods, a);
    for (int k = 1; k <= 4; ++k) QTest::mouseMove(view, a + (b - a) * k / 4);
    QTest::mouseRelease(view, Qt::LeftButton, mods, b);
    QApplication::processEvents();
}

void wheel(QWidget* view, QPointF at, int notches) {
    QWheelEvent e(at, view->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                  Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &e);
    QApplication::processEvents();
}

std::vector<std::array<int, 2>> recordedCells(const Session& s) {
    std::vector<std::array<int, 2>> cells;
    for (const Event& e : s.log().events())
        if (const auto* c = std::get_if<DdaCell>(&e)) cells.push_back({c->cell[0], c->cell[1]});
    return cells;
}

/// The cells a ray o + t d (d > 0 on both axes) crosses in a grid of 1 x 1 cells from (0, 0),
/// up to the hit at tHit: every grid line's crossing time, sorted (not the DDA's increments).
std::vector<std::array<int, 2>> crossingWalk(Vec2 o, Vec2 d, double tHit) {
    std::vector<std::pair<double, int>> crossings;
    for (int axis = 0; axis < 2; ++axis)
        for (int k = static_cast<int>(std::floor(o[axis])) + 1; k <= 8; ++k)
            crossings.push_back({(k - o[axis]) / d[axis], axis});
    std::sort(crossings.begin(), crossings.end());
    std::array<int, 2> cell{static_cast<int>(std::floor(o.x)), static_cast<int>(std::floor(o.y))};
    std::vector<std::array<int, 2>> cells{cell};
    for (const auto& [t, axis] : crossings) {
        if (t >= tHit) break;
        ++cell[axis];
        cells.push_back(cell);
    }
    return cells;
}

TEST(Live2D, DraggingTheOriginRecordsTheWalkOfTheNewRay) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openGrid(w));
    Session& s = w.session();
    View2D* view = w.view2D();
    ASSERT_TRUE(act(w, "live2dSnapCorners"));
    act(w, "live2dSnapCorners")->setChecked(true);
    // The cursor after the second DDA cell: it stays at that step.
    std::size_t second = 0;
    for (int k = 0; k < 2; ++k)
        second = s.replay().nextOfKind(k ? second + 1 : 0, variantIndex<DdaCell>());
    s.setCursor(second + 1);
    const QPointF fixed = view->screenOf(Vec2(3, 2));
    // The origin (0.4, 0.4) dragged to (0.5, 2.5), a cell's centre with the snap on.
    drag(view, view->screenOf(Vec2(0.4, 0.4)), view->screenOf(Vec2(0.5, 2.5)));
    ASSERT_TRUE(s.scene2D()->exampleRay);
    EXPECT_EQ(s.scene2D()->exampleRay->origin, Vec2(0.5, 2.5));
    EXPECT_EQ(s.scene2D()->exampleRay->dir, Vec2(0.8, 0.4));
    // By hand: x = 1, 2, 3 at t = 0.625, 1.875, 3.125; y = 3, 4 at t = 1, 3.75; the wall
    // y = 3.8 is hit at t = 1.3 / 0.4 = 3.25, at x = 3.1: the walk ends in cell (3, 3).
    const auto expected = crossingWalk(Vec2(0.5, 2.5), Vec2(0.8, 0.4), (3.8 - 2.5) / 0.4);
    EXPECT_EQ(expected, (std::vector<std::array<int, 2>>{{0, 2}, {1, 2}, {1, 3}, {2, 3}, {3, 3}}));
    EXPECT_EQ(recordedCells(s), expected);
    // The replay's cursor is still after the second DDA cell of the new walk.
    ASSERT_GT(s.cursor(), 0u);
    EXPECT_TRUE(std::holds_alternative<DdaCell>(s.log().events()[s.cursor() - 1]));
    std::size_t cellsBefore = 0;
    for (std::size_t i = 0; i < s.cursor(); ++i)
        cellsBefore += std::holds_alternative<DdaCell>(s.log().events()[i]);
    EXPECT_EQ(cellsBefore, 2u);
    // The picture did not jump while the ray moved: the view keeps its transform.
    EXPECT_EQ(view->screenOf(Vec2(3, 2)), fixed);
    // A drag of many frames is one undo entry.
    auto* undo = w.findChild<QUndoStack*>("live2dUndo");
    ASSERT_TRUE(undo);
    EXPECT_EQ(undo->count(), 1);
}

TEST(Live2D, TheTipSnappedThroughAGridVertexShowsTheTie) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openGrid(w));
    Session& s = w.session();
    View2D* view = w.view2D();
    ASSERT_TRUE(act(w, "live2dSnapCorners"));
    act(w, "live2dSnapCorners")->setChecked(true);
    drag(view, view->screenOf(Vec2(0.4, 0.4)), view->screenOf(Vec2(0.5, 0.5)));
    // The tip handle is at o + d = (1.3, 0.9); dragged to the vertex (2, 2).
    drag(view, view->screenOf(Vec2(1.3, 0.9)), view->screenOf(Vec2(2, 2)));
    ASSERT_TRUE(s.scene2D()->exampleRay);
    EXPECT_EQ(s.scene2D()->exampleRay->dir, Vec2(1.5, 1.5));
    // (0.5, 0.5) + t (1.5, 1.5) meets x = 1 and y = 1 both at t = 1/3: one step on both axes.
    std::vector<const DdaCell*> cells;
    for (const Event& e : s.log().events())
        if (const auto* c = std::get_if<DdaCell>(&e)) cells.push_back(c);
    ASSERT_GE(cells.size(), 3u);
    EXPECT_EQ((std::array<int, 2>{cells[1]->cell[0], cells[1]->cell[1]}),
              (std::array<int, 2>{1, 1}));
    EXPECT_EQ(cells[1]->axes, 3u);  // the tie: X and Y stepped together
    EXPECT_EQ((std::array<int, 2>{cells[2]->cell[0], cells[2]->cell[1]}),
              (std::array<int, 2>{2, 2}));

    // The angle snap alone: the tip dragged to about 37 degrees turns the ray to 30.
    act(w, "live2dSnapCorners")->setChecked(false);
    act(w, "live2dSnapAngle")->setChecked(true);
    const Vec2 o = s.scene2D()->exampleRay->origin;
    const Vec2 tip = o + s.scene2D()->exampleRay->dir;
    drag(view, view->screenOf(tip), view->screenOf(o + Vec2(2.0, 1.5)));
    const Vec2 d = s.scene2D()->exampleRay->dir;
    EXPECT_NEAR(std::atan2(d.y, d.x), std::acos(-1.0) / 6, 1e-12);
    EXPECT_NEAR(glm::length(d), 2.5, 0.05);  // the length where the mouse let go
}

TEST(Live2D, EditingACircleChangesWhatTheGridListsAndUndoBringsItBack) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openGrid(w));
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    Session& s = w.session();
    View2D* view = w.view2D();
    const auto lists = [&](int x, int y, std::uint32_t prim) {
        const auto& grid = std::get<UniformGridT<Scene2DPrims>>(*s.accel2D());
        const auto cell = grid.cell(IVecN<2>(x, y));
        return std::find(cell.begin(), cell.end(), prim) != cell.end();
    };
    // Circle 1, centre (2.5, 0.5), radius 0.3: in cell (2, 0) only.
    ASSERT_TRUE(lists(2, 0, 1));
    ASSERT_FALSE(lists(4, 1, 1));
    ASSERT_TRUE(act(w, "live2dSnapCorners"));
    act(w, "live2dSnapCorners")->setChecked(true);
    drag(view, view->screenOf(Vec2(2.5, 0.5)), view->screenOf(Vec2(4.5, 1.5)));
    EXPECT_EQ(s.scene2D()->circles[1].center, Vec2(4.5, 1.5));
    // Now [4.2, 4.8] x [1.2, 1.8]: cell (4, 1), no longer (2, 0).
    EXPECT_FALSE(lists(2, 0, 1));
    EXPECT_TRUE(lists(4, 1, 1));
    EXPECT_FALSE(lists(3, 0, 1));
    // Its rim (4.8, 1.5) dragged out to (5.3, 1.5): radius 0.8, [3.7, 5.3] x [0.7, 2.3].
    drag(view, view->screenOf(Vec2(4.8, 1.5)), view->screenOf(Vec2(5.3, 1.5)));
    EXPECT_NEAR(s.scene2D()->circles[1].radius, 0.8, 0.02);
    EXPECT_TRUE(lists(3, 0, 1));
    EXPECT_TRUE(lists(5, 2, 1));

    // Undo twice (Ctrl+Z): the scene as the file has it, and its grid lists.
    const auto original = std::get<Scene2D>(loadAnyScene("lecture-grid"));
    const auto sameAsFile = [&] {
        const Scene2D& now = *s.scene2D();
        if (now.circles.size() != original.circles.size()) return false;
        for (std::size_t i = 0; i < now.circles.size(); ++i)
            if (now.circles[i].center != original.circles[i].center ||
                now.circles[i].radius != original.circles[i].radius)
                return false;
        return true;
    };
    EXPECT_FALSE(sameAsFile());
    QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
    QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_TRUE(sameAsFile());
    EXPECT_TRUE(lists(2, 0, 1));
    EXPECT_FALSE(lists(4, 1, 1));
    // Redo (Ctrl+Shift+Z) moves it again.
    QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(s.scene2D()->circles[1].center, Vec2(4.5, 1.5));
    EXPECT_TRUE(lists(4, 1, 1));
}

TEST(Live2D, AddDeleteAndMoveSegmentsWithUndo) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openGrid(w));
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    Session& s = w.session();
    View2D* view = w.view2D();
    const std::size_t circles = s.scene2D()->circles.size();
    const std::size_t segments = s.scene2D()->segments.size();
    ASSERT_TRUE(act(w, "live2dAddCircle"));
    act(w, "live2dAddCircle")->trigger();
    EXPECT_EQ(s.scene2D()->circles.size(), circles + 1);
    act(w, "live2dAddSegment")->trigger();
    EXPECT_EQ(s.scene2D()->segments.size(), segments + 1);
    // The wall (segment 0: (1.2, 3.8) to (5.8, 3.8)) Ctrl+clicked, then deleted with the Del key.
    QTest::mouseClick(view, Qt::LeftButton, Qt::ControlModifier,
                      view->screenOf(Vec2(3.0, 3.8)).toPoint());
    ASSERT_TRUE(view->selected());
    EXPECT_EQ(*view->selected(), circles + 1);  // its id: after the circles, one more now
    QTest::keyClick(&w, Qt::Key_Delete);
    EXPECT_EQ(s.scene2D()->segments.size(), segments);
    EXPECT_NE(s.scene2D()->segments[0].a, Vec2(1.2, 3.8));
    QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);  // the wall back
    EXPECT_EQ(s.scene2D()->segments[0].a, Vec2(1.2, 3.8));
    act(w, "live2dSnapCorners")->setChecked(true);
    drag(view, view->screenOf(Vec2(5.8, 3.8)), view->screenOf(Vec2(5.5, 3.0)));
    EXPECT_EQ(s.scene2D()->segments[0].b, Vec2(5.5, 3.0));
    EXPECT_EQ(s.scene2D()->segments[0].a, Vec2(1.2, 3.8));
    // The whole segment dragged by its middle: both ends move by the same (snapped) amount.
    drag(view, view->screenOf(Vec2(2.0, 0.0)), view->screenOf(Vec2(2.0, 0.5)));
    const Segment2& bottom = s.scene2D()->segments[6];
    EXPECT_NEAR(bottom.b.x - bottom.a.x, 6.0, 1e-12);
    EXPECT_NEAR(bottom.a.y, bottom.b.y, 1e-12);
    EXPECT_GT(bottom.a.y, 0.2);
    // Undo all: the scene as it was opened.
    auto* undo = w.findChild<QUndoStack*>("live2dUndo");
    ASSERT_TRUE(undo);
    while (undo->canUndo()) undo->undo();
    EXPECT_EQ(s.scene2D()->circles.size(), circles);
    EXPECT_EQ(s.scene2D()->segments.size(), segments);
    EXPECT_EQ(s.scene2D()->segments[6].a, Vec2(0.0, 0.0));
    // Another scene opened: a new history.
    ASSERT_TRUE(openGrid(w, "lecture-kdtree"));
    EXPECT_EQ(undo->count(), 0);
}

TEST(Live2D, WheelZoomsAboutTheCursorDragPansFitRestores) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openGrid(w));
    View2D* view = w.view2D();
    const QPointF a0 = view->screenOf(Vec2(3, 2)), b0 = view->screenOf(Vec2(4, 2));
    wheel(view, a0, 2);
    const QPointF a1 = view->screenOf(Vec2(3, 2)), b1 = view->screenOf(Vec2(4, 2));
    EXPECT_NEAR(a1.x(), a0.x(), 1e-6);  // the point under the cursor stays
    EXPECT_NEAR(a1.y(), a0.y(), 1e-6);
    EXPECT_NEAR(b1.x() - a1.x(), 1.44 * (b0.x() - a0.x()), 1e-6);  // 1.2 a notch
    // A drag on empty space pans by the mouse's way.
    const QPointF empty = view->screenOf(Vec2(3.0, 2.6));  // in cell (3, 2), on nothing
    drag(view, empty, empty + QPointF(60, -40));
    const QPointF a2 = view->screenOf(Vec2(3, 2));
    EXPECT_NEAR(a2.x() - a1.x(), 60, 1e-6);
    EXPECT_NEAR(a2.y() - a1.y(), -40, 1e-6);
    EXPECT_EQ(w.session().scene2D()->exampleRay->origin, Vec2(0.4, 0.4));  // nothing moved
    // Fit (F): back to the fitted view.
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    QTest::keyClick(&w, Qt::Key_F);
    EXPECT_EQ(view->screenOf(Vec2(3, 2)), a0);
}

TEST(Live2D, ACellClickStaysACellAnswerAtAnyZoom) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openGrid(w));
    View2D* view = w.view2D();
    QSignalSpy clicked(view, &View2D::cellClicked);
    for (int notches : {0, 3, -5}) {
        wheel(view, view->screenOf(Vec2(2.7, 1.9)), notches);
        clicked.clear();
        QTest::mouseClick(view, Qt::LeftButton, {}, view->cellCentre(2, 2).toPoint());
        ASSERT_EQ(clicked.count(), 1) << notches;
        EXPECT_EQ(clicked[0][0].toInt(), 2);
        EXPECT_EQ(clicked[0][1].toInt(), 2);
        // A cell holding a primitive: still the cell, and nothing selected (no mark drawn).
        clicked.clear();
        QTest::mouseClick(view, Qt::LeftButton, {}, view->screenOf(Vec2(2.5, 0.5)).toPoint());
        ASSERT_EQ(clicked.count(), 1) << notches;
        EXPECT_EQ(clicked[0][0].toInt(), 2);
        EXPECT_EQ(clicked[0][1].toInt(), 0);
        EXPECT_FALSE(view->selected());
    }
    // A click did not move anything.
    EXPECT_EQ(w.session().scene2D()->circles[1].center, Vec2(2.5, 0.5));
}

TEST(Live2D, AnEditedSceneSavedOpensAgainAsEdited) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openGrid(w));
    Session& s = w.session();
    View2D* view = w.view2D();
    act(w, "live2dSnapCorners")->setChecked(true);
    drag(view, view->screenOf(Vec2(2.5, 0.5)), view->screenOf(Vec2(4.5, 1.5)));
    drag(view, view->screenOf(Vec2(0.4, 0.4)), view->screenOf(Vec2(0.5, 1.0)));
    const Scene2D edited = *s.scene2D();
    const QString path = QDir::temp().filePath(
        QStringLiteral("raystep-live2d-%1.json").arg(QCoreApplication::applicationPid()));
    ASSERT_TRUE(w.live2D()->save(path).isEmpty()) << w.live2D()->save(path).toStdString();
    EXPECT_FALSE(w.live2D()->save(path + ".txt").isEmpty());  // a scene file is *.json
    ASSERT_TRUE(openGrid(w, "lecture-kdtree"));
    ASSERT_TRUE(openGrid(w, path));
    EXPECT_TRUE(sameShapes(*s.scene2D(), edited));
    EXPECT_EQ(s.scene2D()->exampleRay->origin, Vec2(0.5, 1.0));
    EXPECT_EQ(s.scene2D()->circles[1].center, Vec2(4.5, 1.5));
    QFile::remove(path);
}

TEST(Live2D, EditingWhileTheBuildIsReplayedRecordsTheBuildAgain) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    w.openScene("lecture-kdtree", AccelKind::KdTree, /*quiet=*/true, {}, /*render=*/false);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    Session& s = w.session();
    s.recordBuild();  // B: lesson 11's build replay
    ASSERT_TRUE(s.showingBuild());
    const std::uint32_t before = s.scene2D()->primitiveCount();
    const auto rootPrims = [&] {
        for (const Event& e : s.log().events())
            if (const auto* b = std::get_if<BuildNode>(&e)) return b->prims;
        return std::uint32_t(0);
    };
    ASSERT_EQ(rootPrims(), before);
    ASSERT_TRUE(act(w, "live2dAddCircle"));
    act(w, "live2dAddCircle")->trigger();
    EXPECT_TRUE(s.showingBuild());  // still the build, recorded again over the new scene
    EXPECT_EQ(rootPrims(), before + 1);
    // The big circle (1.5, 6) r 0.5 dragged by its middle while the build shows.
    w.view2D()->setSnapToCorners(false);
    drag(w.view2D(), w.view2D()->screenOf(Vec2(1.5, 6.0)), w.view2D()->screenOf(Vec2(3.0, 5.0)));
    EXPECT_NEAR(s.scene2D()->circles[10].center.x, 3.0, 0.05);
    EXPECT_TRUE(s.showingBuild());
}

TEST(Live2D, ShiftDragGivesASceneWithoutARayItsExampleRay) {
    // A scene file with no ray: one segment across cells of 1 x 1, from (0, 0) to (4, 2).
    const QString path = QDir::temp().filePath(
        QStringLiteral("raystep-noray-%1.json").arg(QCoreApplication::applicationPid()));
    {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(
            R"({"dimensions": 2, "grid": [4, 2], "segments": [{"from": [0, 0], "to": [4, 2]}]})");
    }
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openGrid(w, path));
    Session& s = w.session();
    ASSERT_FALSE(s.scene2D()->exampleRay);
    EXPECT_TRUE(w.statusBar()->currentMessage().contains("Shift+drag"));
    View2D* view = w.view2D();
    act(w, "live2dSnapCorners")->setChecked(true);
    // From the centre of cell (0, 1) to the corner (2, 0): o = (0.5, 1.5), d = (1.5, -1.5).
    drag(view, view->screenOf(Vec2(0.5, 1.5)), view->screenOf(Vec2(2.0, 0.0)), Qt::ShiftModifier);
    ASSERT_TRUE(s.scene2D()->exampleRay);
    EXPECT_EQ(s.scene2D()->exampleRay->origin, Vec2(0.5, 1.5));
    EXPECT_EQ(s.scene2D()->exampleRay->dir, Vec2(1.5, -1.5));
    // By hand: x = 1 and y = 1 both at t = 1/3 (a tie, to (1, 0)); the segment y = x / 2 is hit
    // where 1.5 - 1.5 t = (0.5 + 1.5 t) / 2, t = 5/9, x = 4/3: in cell (1, 0), the walk ends.
    EXPECT_EQ(recordedCells(s), (std::vector<std::array<int, 2>>{{0, 1}, {1, 0}}));
    QFile::remove(path);
}

/// The window as a lecturer sees it, written to $RAYSTEP_SHOT_DIR/<name>.png when that is set
/// (to look at by hand, at each screen size); the checks hold either way.
QImage shot(MainWindow& w, const char* name) {
    QApplication::processEvents();
    const QImage image = w.grab().toImage();
    if (const QByteArray dir = qgetenv("RAYSTEP_SHOT_DIR"); !dir.isEmpty())
        image.save(QDir(QString::fromLocal8Bit(dir)).filePath(QString::fromLatin1(name) + ".png"));
    return image;
}

/// The ray the session replays now (its log's first ray), in 2D.
Ray2 replayedRay(const Session& s) {
    const RayRecord& r = s.log().rays().front();
    return {Vec2(r.origin.x, r.origin.y), Vec2(r.dir.x, r.dir.y)};
}

/// Whether screen vectors a and b point the same way (within a pixel's worth of angle).
bool sameDirection(QPointF a, QPointF b) {
    const double cross = a.x() * b.y() - a.y() * b.x(), dot = QPointF::dotProduct(a, b);
    return dot > 0 && std::abs(cross) <= 0.01 * std::hypot(a.x(), a.y()) * std::hypot(b.x(), b.y());
}

// Lessons 8 and 13 trace a ray of their own, not lecture-grid's example ray (0.4, 0.4) + t (0.8,
// 0.4): the rings sit on that ray, a drag edits it, and a live control keeps it.
TEST(Live2D, TheHandlesSitOnTheRayALessonReplaysAndADragEditsThatRay) {
    struct Case {
        const char* lesson;
        Vec2 origin, dir;  // the lesson file's "trace": {"ray": [ox, oy, dx, dy]}
        Vec2 to;           // where the test drags the origin ring
    };
    for (const Case& c : {Case{"8", {1.0, 3.6}, {1.0, 0.02}, {1.5, 2.5}},
                          Case{"13", {0.4, 0.4}, {1.0, 1.0}, {2.5, 0.5}}}) {
        SCOPED_TRACE(c.lesson);
        MainWindow w;
        w.resize(1400, 860);
        w.show();
        w.setLecturerMode(true);  // every step free: the drag is the lecturer's
        w.openLesson(c.lesson, /*quiet=*/true);
        ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
        Session& s = w.session();
        View2D* view = w.view2D();
        QApplication::processEvents();
        ASSERT_FALSE(s.log().rays().empty());
        EXPECT_EQ(replayedRay(s).origin, c.origin);
        EXPECT_EQ(replayedRay(s).dir, c.dir);
        // The rings: the origin's on the ray's origin, the tip's along the ray's direction.
        const auto shown = view->shownRay();
        ASSERT_TRUE(shown);
        EXPECT_EQ(shown->origin, c.origin);
        ASSERT_TRUE(view->tipHandle());
        const QPointF o = view->screenOf(c.origin);
        EXPECT_TRUE(sameDirection(*view->tipHandle() - o, view->screenOf(c.origin + c.dir) - o))
            << view->tipHandle()->x() << "," << view->tipHandle()->y();
        // The origin ring is drawn there, in the ray's colour: a pixel on its rim.
        const PaletteColour& p = rayColour(RayKind::Primary);
        const QImage image = view->grab().toImage();
        int ringPixels = 0;
        for (int dx = -9; dx <= 9; ++dx)
            for (int dy = -9; dy <= 9; ++dy) {
                const QColor px = image.pixelColor((o + QPointF(dx, dy)).toPoint());
                ringPixels += std::abs(px.red() - p.r) + std::abs(px.green() - p.g) +
                                  std::abs(px.blue() - p.b) <
                              30;
            }
        EXPECT_GT(ringPixels, 20);
        // The scene's own example ray's origin, elsewhere in lesson 8, has no ring.
        if (c.origin != Vec2(0.4, 0.4)) {
            const QPointF e = view->screenOf(Vec2(0.4, 0.4));
            int there = 0;
            for (int dx = -9; dx <= 9; ++dx)
                for (int dy = -9; dy <= 9; ++dy) {
                    const QColor px = image.pixelColor((e + QPointF(dx, dy)).toPoint());
                    there += std::abs(px.red() - p.r) + std::abs(px.green() - p.g) +
                                 std::abs(px.blue() - p.b) <
                             30;
                }
            EXPECT_EQ(there, 0);
        }
        // Dragging the origin ring moves the lesson's ray: its direction stays the lesson's.
        act(w, "live2dSnapCorners")->setChecked(true);
        drag(view, o, view->screenOf(c.to));
        EXPECT_EQ(replayedRay(s).origin, c.to);
        EXPECT_EQ(replayedRay(s).dir, c.dir);
        // A live control rebuilds the structure: the ray traced again is the edited one.
        auto* mailbox = w.findChild<QCheckBox*>("liveMailbox");
        ASSERT_TRUE(mailbox);
        mailbox->click();
        ASSERT_TRUE(w.waitUntilIdle());
        EXPECT_EQ(replayedRay(s).origin, c.to);
        EXPECT_EQ(replayedRay(s).dir, c.dir);
        // Undo: the lesson's own ray again (not the scene's example ray).
        act(w, "live2dUndoAction")->trigger();
        QApplication::processEvents();
        EXPECT_EQ(replayedRay(s).origin, c.origin);
        EXPECT_EQ(replayedRay(s).dir, c.dir);
    }
}

// The 2D BVH (the live controls offer it), drawn from its outline as the kd-tree's cells are: at
// a step of the example ray's walk the node being entered is filled, a node it skipped is not.
TEST(View2DBvh, TheNodeBeingEnteredIsFilledASkippedOneIsNot) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    w.setLecturerMode(true);
    w.openScene("lecture-kdtree", AccelKind::Bvh, /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    QApplication::processEvents();
    Session& s = w.session();
    ASSERT_EQ(s.kind(), AccelKind::Bvh);
    const StructureOutline<2> o = outline(*s.accel2D());
    ASSERT_GT(o.nodes.size(), 3u);
    View2D* view = w.view2D();
    const auto screenBox = [&](std::uint32_t id) {
        const BoxN<2>& b = o.nodes[id].box;
        return QRectF(view->screenOf(Vec2(b.lo.x, b.hi.y)), view->screenOf(Vec2(b.hi.x, b.lo.y)))
            .normalized();
    };
    // The first step entering a node after one was skipped whose box lies apart from it.
    std::optional<std::uint32_t> current, skipped;
    for (std::size_t c = 1; c <= s.size() && !current; ++c) {
        s.setCursor(c);
        const ReplayState& st = s.state();
        if (!st.node || !std::holds_alternative<NodeEnter>(s.log().events()[c - 1])) continue;
        for (const std::uint32_t k : st.nodesSkipped)
            if (!screenBox(k).intersects(screenBox(st.node->node))) {
                current = st.node->node;
                skipped = k;
                break;
            }
    }
    ASSERT_TRUE(current && skipped) << "the example ray skips no box apart from one it enters";
    QApplication::processEvents();
    const QImage image = view->grab().toImage();
    // The fill: the palette's current colour at alpha 110 over the view's background.
    const PaletteColour& c = roleColour(PaletteRole::Current);
    const double a = 110.0 / 255.0;
    const QColor fill(int(std::lround(250 * (1 - a) + c.r * a)),
                      int(std::lround(250 * (1 - a) + c.g * a)),
                      int(std::lround(247 * (1 - a) + c.b * a)));
    const auto filledShare = [&](QRectF r) {
        r.adjust(4, 4, -4, -4);  // inside the box's edge lines
        int filled = 0, all = 0;
        for (int y = int(r.top()); y < int(r.bottom()); ++y)
            for (int x = int(r.left()); x < int(r.right()); ++x) {
                const QColor p = image.pixelColor(x, y);
                ++all;
                filled += std::abs(p.red() - fill.red()) + std::abs(p.green() - fill.green()) +
                              std::abs(p.blue() - fill.blue()) <
                          24;
            }
        return all ? double(filled) / all : 0.0;
    };
    EXPECT_GT(filledShare(screenBox(*current)), 0.6) << "node " << *current;
    EXPECT_LT(filledShare(screenBox(*skipped)), 0.05) << "node " << *skipped;
}

// Another lesson is a new history, even on the same scene (lessons 10 and 11): an edit undone
// in lesson 10 leaves its scene as lesson 11 opens it, and a redo there would bring it back.
TEST(Live2D, AnotherLessonOnTheSameSceneStartsANewHistory) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    w.setLecturerMode(true);
    w.openLesson("10", /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    QApplication::processEvents();
    View2D* view = w.view2D();
    const auto shown = view->shownRay();
    ASSERT_TRUE(shown);
    drag(view, view->screenOf(shown->origin), view->screenOf(shown->origin + Vec2(0.5, 0.5)));
    auto* undo = w.findChild<QUndoStack*>("live2dUndo");
    ASSERT_TRUE(undo);
    ASSERT_EQ(undo->count(), 1);
    act(w, "live2dUndoAction")->trigger();
    QApplication::processEvents();
    ASSERT_TRUE(undo->canRedo());
    w.openLesson("11", /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    EXPECT_EQ(undo->count(), 0);
    EXPECT_FALSE(undo->canRedo());
}

// The DDA's labels on the ray: never over each other nor out of the view (lesson 8's ray runs
// under the top wall), one label for a tie (lesson 13's ray through the grid's vertices), and
// each tDelta bracket spans a whole cell's worth of t, ending at tMax (behind the origin where
// the first boundary is nearer than a cell: lesson 6's first tDeltaY ran from t = 0 to 1.5).
TEST(Live2D, TheDdaLabelsStayApartInTheViewAndEachTDeltaSpansAWholeCell) {
    struct Case {
        const char* lesson;
        Vec2 tDelta;  // by hand: cell size 1 over |d| per axis
        bool ties;    // every tMaxX equals tMaxY
    };
    // Lesson 6: d = (0.8, 0.4); lesson 8: d = (1, 0.02); lesson 13: d = (1, 1).
    for (const Case& c : {Case{"6", {1.25, 2.5}, false}, Case{"8", {1.0, 50.0}, false},
                          Case{"13", {1.0, 1.0}, true}}) {
        SCOPED_TRACE(c.lesson);
        MainWindow w;
        w.resize(1400, 860);
        w.show();
        w.setLecturerMode(true);
        w.openLesson(c.lesson, /*quiet=*/true);
        ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
        Session& s = w.session();
        View2D* view = w.view2D();
        int cells = 0;
        for (std::size_t i = 0; i < s.log().events().size(); ++i) {
            const auto* cell = std::get_if<DdaCell>(&s.log().events()[i]);
            if (!cell) continue;
            ++cells;
            s.setCursor(i + 1);
            view->grab();  // a paint places the labels
            SCOPED_TRACE(i);
            const auto& labels = view->ddaLabels();
            int tMaxLabels = 0;
            for (std::size_t a = 0; a < labels.size(); ++a) {
                tMaxLabels += labels[a].text.startsWith("tMax");
                EXPECT_TRUE(QRectF(view->rect()).contains(labels[a].box))
                    << labels[a].text.toStdString();
                for (std::size_t b = a + 1; b < labels.size(); ++b)
                    EXPECT_FALSE(labels[a].box.intersects(labels[b].box))
                        << labels[a].text.toStdString() << " / " << labels[b].text.toStdString();
            }
            EXPECT_EQ(tMaxLabels, c.ties ? 1 : 2);
            if (c.ties) {
                EXPECT_TRUE(std::any_of(labels.begin(), labels.end(), [](const auto& l) {
                    return l.text.startsWith("tMaxX = tMaxY = ");
                }));
            }
            for (int axis = 0; axis < 2; ++axis) {
                const auto& span = view->tDeltaSpans()[axis];
                ASSERT_TRUE(span);
                EXPECT_NEAR((*span)[1] - (*span)[0], c.tDelta[axis], 1e-12);
                EXPECT_EQ((*span)[1], cell->tMax[axis]);
            }
        }
        EXPECT_GE(cells, 3);
    }
}

/// Answers the next file dialog: notes the folder it opened in, then chooses `path` in it.
void answerNextFileDialog(QString* openedIn, const QString& path) {
    QTimer::singleShot(0, [=] {
        QFileDialog* d = nullptr;
        waitFor([&] { return (d = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())); },
                10000);
        if (!d) return;
        *openedIn = d->directory().absolutePath();
        d->selectFile(path);
        QMetaObject::invokeMethod(d, "accept");  // as the Save button does
    });
}

// gui.md 17 and 18: a render's "Rendered in ... click a pixel" stayed on beside a 2D lesson; the
// title kept the old scene after Save 2D scene as; every dialog opened in the working directory.
TEST(Live2D, StatusTitleAndTheFileDialogsFollowWhatWasDone) {
    QSettings().remove("dialogs");
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    w.openLesson("1", /*quiet=*/true);  // 3D: its image is rendered
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    ASSERT_TRUE(waitFor([&] { return w.statusBar()->currentMessage().startsWith("Rendered in"); }));
    w.openLesson("6", /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    EXPECT_FALSE(w.statusBar()->currentMessage().startsWith("Rendered in"))
        << w.statusBar()->currentMessage().toStdString();
    // Save 2D scene as: the first dialog starts where the app runs; the title names the file.
    QString openedIn;
    const QString saved = QDir(dir.path()).filePath("edited.json");
    answerNextFileDialog(&openedIn, saved);
    act(w, "live2dSave")->trigger();
    EXPECT_EQ(openedIn, QDir::currentPath());
    ASSERT_TRUE(QFile::exists(saved));
    EXPECT_TRUE(w.windowTitle().contains(saved)) << w.windowTitle().toStdString();
    // The next dialog, another one (the board's export), opens in that folder.
    w.session().setCursor(w.session().size());
    openedIn.clear();
    answerNextFileDialog(&openedIn, QDir(dir.path()).filePath("board.csv"));
    auto* exportButton = w.findChild<QPushButton*>("boardExport");
    ASSERT_NE(exportButton, nullptr);
    exportButton->click();
    EXPECT_EQ(openedIn, QDir(dir.path()).absolutePath());
    EXPECT_TRUE(QFile::exists(QDir(dir.path()).filePath("board.csv")));
    QSettings().remove("dialogs");
}

TEST(Live2D, LessonSixWhileDraggingAndEditing) {
    MainWindow w;
    w.resize(w.fitToScreen(QSize(1920, 1080)));
    w.show();
    w.openLesson("6", /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    Session& s = w.session();
    View2D* view = w.view2D();
    const QColor ray(rayColour(RayKind::Primary).r, rayColour(RayKind::Primary).g,
                     rayColour(RayKind::Primary).b);
    // The origin handle is drawn over the ray's origin, in the ray's colour.
    const auto rayAt = [&](Vec2 p) {
        const QImage v = view->grab().toImage();
        const QPoint at = view->screenOf(p).toPoint();
        return QColor(v.pixel(at)) == ray;
    };
    EXPECT_TRUE(rayAt(s.scene2D()->exampleRay->origin));
    shot(w, "l6_start");
    // Mid-drag (the button still down): the walk is recorded again already.
    const QPoint from = view->screenOf(Vec2(0.4, 0.4)).toPoint();
    const QPoint to = view->screenOf(Vec2(0.5, 1.6)).toPoint();
    QTest::mousePress(view, Qt::LeftButton, {}, from);
    QTest::mouseMove(view, (from + to) / 2);
    QTest::mouseMove(view, to);
    EXPECT_NEAR(s.scene2D()->exampleRay->origin.y, 1.6, 0.05);
    EXPECT_TRUE(rayAt(s.scene2D()->exampleRay->origin));
    shot(w, "l6_dragging_origin");
    QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    // Editing: the circle in cell (2, 0) dragged up into (2, 1), then a new circle added.
    drag(view, view->screenOf(Vec2(2.5, 0.5)), view->screenOf(Vec2(2.5, 1.5)));
    ASSERT_TRUE(act(w, "live2dAddCircle"));
    act(w, "live2dAddCircle")->trigger();
    wheel(view, view->screenOf(Vec2(2.5, 1.5)), 2);
    ASSERT_TRUE(view->selected());
    const QImage edited = shot(w, "l6_edited_zoomed");
    EXPECT_FALSE(edited.isNull());
    EXPECT_EQ(s.scene2D()->circles.size(), 6u);
}

}  // namespace
}  // namespace raystep::gui
