// The "done when", as a lecturer does it with the mouse and keys only: lesson 6 taught
// live (place the ray, move a circle, change the resolution, read the board, undo, back to the
// lesson) and lesson 11 (the build on the board, the split method and the costs changed). The
// walks and the midpoint plane expected are worked out here, not read from the code under test.
#include "board_table.h"
#include "live_controls.h"
#include "main_window.h"
#include "timeline.h"
#include "view2d.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace raystep::gui {
namespace {

using Cells = std::vector<std::array<int, 2>>;

void drag(QWidget* view, QPointF from, QPointF to) {
    const QPoint a = from.toPoint(), b = to.toPoint();
    QTest::mousePress(view, Qt::LeftButton, {}, a);
    for (int k = 1; k <= 5; ++k) QTest::mouseMove(view, a + (b - a) * k / 5);
    QTest::mouseRelease(view, Qt::LeftButton, {}, b);
    QApplication::processEvents();
}

/// The window as the lecturer sees it, to $RAYSTEP_SHOT_DIR/<name>.png when that is set.
void shot(MainWindow& w, const char* name) {
    QApplication::processEvents();
    if (const QByteArray dir = qgetenv("RAYSTEP_SHOT_DIR"); !dir.isEmpty())
        w.grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QString::fromLatin1(name)) +
                      ".png");
}

/// A spin box typed into as a hand does: select what is there, type, Enter.
void type(QAbstractSpinBox* box, const QString& text) {
    box->setFocus();
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
    QApplication::processEvents();
}

/// The replay to its end, by the End key on the timeline's scrubber (where a lecturer's hand is).
void toEnd(MainWindow& w) {
    auto* scrubber = w.timeline()->findChild<QSlider*>();
    ASSERT_TRUE(scrubber);
    scrubber->setFocus();
    QTest::keyClick(scrubber, Qt::Key_End);
    QApplication::processEvents();
    ASSERT_EQ(w.session().cursor(), w.session().size());
}

/// The board's column `name`.
std::vector<std::string> column(const Board& b, const std::string& name) {
    const auto at = std::find(b.header.begin(), b.header.end(), name);
    std::vector<std::string> out;
    if (at == b.header.end()) return out;
    for (const BoardRow& r : b.rows) out.push_back(r.cells[at - b.header.begin()]);
    return out;
}

Cells boardCells(const Board& b) {
    const auto x = column(b, "X"), y = column(b, "Y");
    Cells out;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
        out.push_back({std::stoi(x[i]), std::stoi(y[i])});
    return out;
}

/// The cells o + t d (d > 0 on both axes) crosses in a grid of sx x sy cells from (0, 0), up to
/// the hit at tHit: every grid line's crossing, sorted (not the DDA's increments).
Cells crossingWalk(Vec2 o, Vec2 d, Vec2 size, double tHit) {
    std::vector<std::pair<double, int>> crossings;
    for (int axis = 0; axis < 2; ++axis)
        for (int k = static_cast<int>(std::floor(o[axis] / size[axis])) + 1; k <= 40; ++k)
            crossings.push_back({(k * size[axis] - o[axis]) / d[axis], axis});
    std::sort(crossings.begin(), crossings.end());
    std::array<int, 2> cell{static_cast<int>(std::floor(o.x / size.x)),
                            static_cast<int>(std::floor(o.y / size.y))};
    Cells cells{cell};
    for (const auto& [t, axis] : crossings) {
        if (t >= tHit) break;
        ++cell[axis];
        cells.push_back(cell);
    }
    return cells;
}

/// The primitive ids a board cell lists ("11, 12", a hit with its t after the id).
std::vector<int> ids(const std::string& cell) {
    std::vector<int> out;
    std::size_t at = 0;
    while (at < cell.size()) {
        while (at < cell.size() && !std::isdigit(static_cast<unsigned char>(cell[at]))) ++at;
        if (at == cell.size()) break;
        std::size_t used = 0;
        out.push_back(std::stoi(cell.substr(at), &used));
        at = cell.find(',', at + used);
        if (at == std::string::npos) break;
    }
    return out;
}

TEST(Lecture, LessonSixTaughtLiveFromTheApp) {
    MainWindow w;
    w.resize(w.fitToScreen(QSize(1920, 1080)));
    w.show();
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));  // the window's keys need it active
    w.openLesson("6", /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    // The lecturer's mode (Ctrl+L): the exercises do not hold the replay.
    QTest::keyClick(&w, Qt::Key_L, Qt::ControlModifier);
    Session& s = w.session();
    const SceneRef lessonScene = s.sceneRef();
    View2D* view = w.view2D();
    BoardTable* board = w.boardTable();
    LiveControls* controls = w.liveControls();
    ASSERT_TRUE(board && controls);
    EXPECT_TRUE(board->isVisible());
    EXPECT_TRUE(controls->isVisible());
    shot(w, "lecture6_start");

    // Place the ray: its origin dragged to a cell's centre (the snap makes it exact).
    auto* snap = w.findChild<QAction*>("live2dSnapCorners");
    ASSERT_TRUE(snap);
    snap->setChecked(true);
    drag(view, view->screenOf(Vec2(0.4, 0.4)), view->screenOf(Vec2(0.5, 2.5)));
    ASSERT_EQ(s.scene2D()->exampleRay->origin, Vec2(0.5, 2.5));
    // Move a circle into the ray's second cell: circle 1, from (2.5, 0.5) to (1.5, 2.5). Its
    // distance to the ray's line, |(1, 0) x (0.8, 0.4)| / |(0.8, 0.4)| = 0.447, is above its
    // radius 0.3: listed in cell (1, 2), tested there, missed.
    drag(view, view->screenOf(Vec2(2.5, 0.5)), view->screenOf(Vec2(1.5, 2.5)));
    ASSERT_EQ(s.scene2D()->circles[1].center, Vec2(1.5, 2.5));
    toEnd(w);
    // The wall y = 3.8 is hit at t = (3.8 - 2.5) / 0.4 = 3.25.
    const double tWall = (3.8 - 2.5) / 0.4;
    const Cells unit = crossingWalk(Vec2(0.5, 2.5), Vec2(0.8, 0.4), Vec2(1, 1), tWall);
    ASSERT_EQ(unit, (Cells{{0, 2}, {1, 2}, {1, 3}, {2, 3}, {3, 3}}));
    EXPECT_EQ(boardCells(board->board()), unit);
    const auto tested = column(board->board(), "tested");
    ASSERT_EQ(tested.size(), unit.size());
    const std::vector<int> inCell12 = ids(tested[1]);
    EXPECT_NE(std::find(inCell12.begin(), inCell12.end(), 1), inCell12.end()) << tested[1];
    shot(w, "lecture6_ray_and_circle_moved");

    // Smaller cells in x: 10 columns of 0.6 over the scene's 6 units.
    type(controls->cellsBox(0), "10");
    ASSERT_EQ(s.options().grid.res.value_or(std::array<int, 3>{})[0], 10);
    toEnd(w);
    const Cells fine = crossingWalk(Vec2(0.5, 2.5), Vec2(0.8, 0.4), Vec2(0.6, 1), tWall);
    EXPECT_GT(fine.size(), unit.size());
    EXPECT_EQ(boardCells(board->board()), fine);
    shot(w, "lecture6_ten_columns");

    // Undo twice on the 2D view's tool bar (Ctrl+Z would undo the typing in the spin box that
    // has the focus): the circle, then the ray, as the lesson had them.
    QToolButton* undo = nullptr;
    for (QToolButton* b : w.findChildren<QToolButton*>())
        if (b->defaultAction() && b->defaultAction()->objectName() == "live2dUndoAction") undo = b;
    ASSERT_TRUE(undo);
    QTest::mouseClick(undo, Qt::LeftButton);
    QTest::mouseClick(undo, Qt::LeftButton);
    QApplication::processEvents();
    EXPECT_EQ(s.scene2D()->circles[1].center, Vec2(2.5, 0.5));
    EXPECT_EQ(s.scene2D()->exampleRay->origin, Vec2(0.4, 0.4));
    // Esc: the lesson's own scene and trace again.
    w.view2D()->setFocus();
    QTest::keyClick(w.view2D(), Qt::Key_Escape);
    ASSERT_TRUE(w.waitUntilIdle());
    EXPECT_EQ(s.sceneRef(), lessonScene);
}

TEST(Lecture, LessonElevenTaughtLiveFromTheApp) {
    MainWindow w;
    w.resize(w.fitToScreen(QSize(1920, 1080)));
    w.show();
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));  // the window's keys need it active
    w.openLesson("11", /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    QTest::keyClick(&w, Qt::Key_L, Qt::ControlModifier);
    Session& s = w.session();
    BoardTable* board = w.boardTable();
    LiveControls* controls = w.liveControls();
    ASSERT_TRUE(board && controls);
    toEnd(w);
    // The build on the board: a row per node made.
    std::size_t nodes = 0;
    for (const Event& e : s.log().events()) nodes += std::holds_alternative<BuildNode>(e);
    ASSERT_GT(nodes, 1u);
    EXPECT_EQ(board->board().rows.size(), nodes);
    shot(w, "lecture11_sah");

    // The split method, by keys on the control: SAH -> the one above it until midpoint.
    QComboBox* split = controls->splitBox();
    const int midpoint = split->findData(static_cast<int>(SplitMethod::Midpoint));
    ASSERT_GE(midpoint, 0);
    split->setFocus();
    for (int guard = 0; split->currentIndex() != midpoint && guard < 4; ++guard)
        QTest::keyClick(split, split->currentIndex() > midpoint ? Qt::Key_Up : Qt::Key_Down);
    QApplication::processEvents();
    ASSERT_EQ(s.options().kdtree.split, SplitMethod::Midpoint);
    // The build was recorded again: the root's plane is the middle of the scene's longest axis,
    // the scene's bounds worked out here from its circles and segments.
    const Scene2D& scene = *s.scene2D();
    Vec2 lo(1e300), hi(-1e300);
    for (const Circle2& c : scene.circles) {
        lo = glm::min(lo, c.center - Vec2(c.radius));
        hi = glm::max(hi, c.center + Vec2(c.radius));
    }
    for (const Segment2& g : scene.segments) {
        lo = glm::min(lo, glm::min(g.a, g.b));
        hi = glm::max(hi, glm::max(g.a, g.b));
    }
    const int axis = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
    const SplitChosen* root = nullptr;
    for (const Event& e : s.log().events())
        if ((root = std::get_if<SplitChosen>(&e))) break;
    ASSERT_TRUE(root);
    EXPECT_EQ(root->axis, axis);
    EXPECT_NEAR(root->position, (lo[axis] + hi[axis]) / 2, 1e-9);
    toEnd(w);
    std::size_t midpointNodes = 0;
    for (const Event& e : s.log().events()) midpointNodes += std::holds_alternative<BuildNode>(e);
    EXPECT_EQ(board->board().rows.size(), midpointNodes);
    shot(w, "lecture11_midpoint");

    // Back to SAH, then a dearer primitive test: cIsect 5 -> 20 makes a leaf dearer than its
    // splits, so the tree grows (or stays) and the root's SAH cost is the new one.
    split->setFocus();
    const int sah = split->findData(static_cast<int>(SplitMethod::Sah));
    for (int guard = 0; split->currentIndex() != sah && guard < 4; ++guard)
        QTest::keyClick(split, split->currentIndex() > sah ? Qt::Key_Up : Qt::Key_Down);
    ASSERT_EQ(s.options().kdtree.split, SplitMethod::Sah);
    const QString before = controls->statistics();
    type(controls->cIsectBox(), "20");
    EXPECT_EQ(s.options().kdtree.cIsect, 20.0);
    EXPECT_NE(controls->statistics(), before);
    for (const Event& e : s.log().events())
        if (const auto* c = std::get_if<SplitChosen>(&e)) {
            // Not splitting the root costs C_isect N = 20 x 15 primitives.
            EXPECT_DOUBLE_EQ(c->leafCost, 20.0 * 15);
            break;
        }
    shot(w, "lecture11_cisect20");
}

TEST(Lecture, LessonSevenPutsTheThirdAxisOnTheBoard) {
    MainWindow w;
    w.resize(w.fitToScreen(QSize(1920, 1080)));
    w.show();
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    w.openLesson("7", /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    QTest::keyClick(&w, Qt::Key_L, Qt::ControlModifier);
    // The lesson lists the board beside its 3D view and image; the live controls are 2D's.
    BoardTable* board = w.boardTable();
    ASSERT_TRUE(board);
    EXPECT_TRUE(board->isVisible());
    EXPECT_FALSE(w.liveControls()->isVisible());
    // The first ray's walk: the cursor after its last DDA cell.
    const Session& s = w.session();
    std::size_t lastCell = 0;
    std::vector<std::array<int, 3>> cells;
    std::uint32_t ray = kNoId;
    for (std::size_t i = 0; i < s.log().events().size(); ++i)
        if (const auto* c = std::get_if<DdaCell>(&s.log().events()[i])) {
            if (ray == kNoId) ray = c->ray;
            if (c->ray != ray) break;
            cells.push_back({c->cell[0], c->cell[1], c->cell[2]});
            lastCell = i;
        }
    ASSERT_GT(cells.size(), 1u);
    w.session().setCursor(lastCell + 1);
    QApplication::processEvents();
    const Board& b = board->board();
    for (const char* name : {"Z", "tMaxZ", "tDeltaZ"})
        EXPECT_NE(std::find(b.header.begin(), b.header.end(), name), b.header.end()) << name;
    const auto x = column(b, "X"), y = column(b, "Y"), z = column(b, "Z");
    ASSERT_EQ(z.size(), cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) {
        EXPECT_EQ(std::stoi(x[i]), cells[i][0]) << i;
        EXPECT_EQ(std::stoi(y[i]), cells[i][1]) << i;
        EXPECT_EQ(std::stoi(z[i]), cells[i][2]) << i;
    }
    shot(w, "lecture7_board");
    // Another lesson without the board beside its 3D scene: the board goes.
    w.openLesson("9", /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    EXPECT_FALSE(board->isVisible());
}

}  // namespace
}  // namespace raystep::gui
