// File > Open student trace, driven as a lecturer would under Xvfb: a student's trace of the
// lecture grid's example ray, written here from a computation by hand (not from raystep's run),
// opened through the File menu's item and its file dialog. The ray they got wrong is replayed
// at the step where the walks part, the board has their column beside raystep's with that row
// marked, the 2D view's legend names both walks; a bad file says where and changes nothing.
#include "assess_controller.h"
#include "board_table.h"
#include "gui_testing.h"
#include "view2d.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QTimer>

#include <algorithm>

namespace raystep::gui {
namespace {

// The slides' grid (6 x 4 unit cells over [0, 6] x [0, 4]) and its example ray
// (0.4, 0.4) + t (0.8, 0.4): tDeltaX = 1 / 0.8 = 1.25, tDeltaY = 1 / 0.4 = 2.5; in (0, 0)
// tMaxX = 0.6 / 0.8 = 0.75 and tMaxY = 0.6 / 0.4 = 1.5. Stepping at the smaller tMax each time:
// (0, 0) X (1, 0) [tMaxX 2] Y (1, 1) [tMaxY 4] X (2, 1) [3.25] X (3, 1) [4.5] Y (3, 2) [6.5]
// X (4, 2), where it hits circle 2 (centre (4.3, 2.3), radius 0.25): |o + t d - c|^2 = r^2 is
// 0.8 t^2 - 7.76 t + 18.7575 = 0, t = (7.76 - sqrt(0.1936)) / 1.6 = 4.575.
// Ray 1 is a student's who stepped in X out of (1, 0) (tMaxX 2 > tMaxY 1.5): wrong at its third
// cell, line 13.
const char* kTrace =
    R"({"ray": {"origin": [0.4, 0.4], "dir": [0.8, 0.4]}}
{"cell": [0, 0], "tMax": [0.75, 1.5]}
{"cell": [1, 0], "tMax": [2, 1.5]}
{"cell": [1, 1], "tMax": [2, 4]}
{"cell": [2, 1]}
{"cell": [3, 1]}
{"cell": [3, 2]}
{"cell": [4, 2]}
{"hit": {"prim": 2, "t": 4.575}}
{"ray": {"origin": [0.4, 0.4], "dir": [0.8, 0.4]}}
{"cell": [0, 0], "tMax": [0.75, 1.5]}
{"cell": [1, 0], "tMax": [2, 1.5]}
{"cell": [2, 0], "tMax": [3.25, 1.5]}
{"cell": [3, 0]}
)";

bool openScene(MainWindow& w, const QString& scene, AccelKind kind) {
    w.openScene(scene, kind, /*quiet=*/true, {}, /*renderImage=*/false);
    return w.waitUntilIdle() && w.lastOpenOk().value_or(false);
}

/// File > Open student trace... as the menu has it, its file dialog answered with `path`.
void openThroughTheMenu(MainWindow& w, const QString& path) {
    QAction* item = nullptr;
    for (QAction* menu : w.menuBar()->actions())
        if (menu->menu() && menu->text() == "&File")
            for (QAction* a : menu->menu()->actions())
                if (a->objectName() == "openStudentTrace") item = a;
    ASSERT_NE(item, nullptr);
    ASSERT_TRUE(item->isEnabled());
    QTimer::singleShot(0, [=] {
        QFileDialog* d = nullptr;
        waitFor([&] { return (d = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())); },
                10000);
        if (!d) return;
        d->selectFile(path);
        QMetaObject::invokeMethod(d, "accept");
    });
    item->trigger();
    QApplication::processEvents();
}

int columnOf(const Board& b, const std::string& name) {
    const auto at = std::find(b.header.begin(), b.header.end(), name);
    return at == b.header.end() ? -1 : int(at - b.header.begin());
}

TEST(AssessGui, TheFailedRayIsShownWhereTheWalksPart) {
    QSettings().remove("dialogs");
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    ShownWindow sw;
    MainWindow& w = sw.w;
    ASSERT_TRUE(openScene(w, "lecture-grid", AccelKind::Grid));
    const QString path = writeLesson(dir, "run.jsonl", kTrace);
    openThroughTheMenu(w, path);

    AssessController* a = w.assessController();
    ASSERT_TRUE(a->isOpen());
    EXPECT_EQ(a->shownRay(), 1);  // the first that failed
    ASSERT_EQ(a->rayChooser()->count(), 2);
    EXPECT_EQ(a->rayChooser()->currentIndex(), 1);
    EXPECT_TRUE(a->bar()->isVisible());
    const QString verdict = a->verdictText();
    EXPECT_TRUE(verdict.contains("line 13")) << verdict.toStdString();
    EXPECT_TRUE(verdict.contains("tMaxY")) << verdict.toStdString();

    // The replay is raystep's run of that ray, at its third cell: (1, 1), where they part.
    const Session& s = w.session();
    EXPECT_EQ(s.logKind(), LogKind::StudentRay);
    ASSERT_FALSE(s.log().rays().empty());
    EXPECT_EQ(s.log().rays().front().origin.x, 0.4);
    EXPECT_EQ(s.log().rays().front().dir.y, 0.4);
    ASSERT_GT(s.cursor(), 0u);
    const auto* at = std::get_if<DdaCell>(&s.log().events()[s.cursor() - 1]);
    ASSERT_NE(at, nullptr);
    EXPECT_EQ(at->cell[0], 1);
    EXPECT_EQ(at->cell[1], 1);
    int cellsBefore = 0;
    for (std::size_t i = 0; i + 1 < s.cursor(); ++i)
        cellsBefore += std::holds_alternative<DdaCell>(s.log().events()[i]);
    EXPECT_EQ(cellsBefore, 2);

    // The board: their column beside raystep's, the divergent row the current one and marked.
    BoardTable* board = w.boardTable();
    EXPECT_TRUE(board->isVisible());
    EXPECT_TRUE(board->showsBeside());
    const Board& b = board->board();
    const int yours = columnOf(b, "your cell"), theirTMax = columnOf(b, "your tMax");
    ASSERT_GE(yours, 0);
    ASSERT_GE(theirTMax, 0);
    ASSERT_EQ(b.rows.size(), 3u);
    EXPECT_EQ(board->currentRow(), 2);
    EXPECT_EQ(b.rows[0].cells[yours], "(0, 0)");
    EXPECT_EQ(b.rows[1].cells[yours], "(1, 0)");
    EXPECT_EQ(b.rows[2].cells[yours], "\u2260 (2, 0)");
    EXPECT_EQ(b.rows[1].cells[theirTMax], "(2, 1.5)");
    EXPECT_FALSE(board->model()->marked(0, yours));
    EXPECT_FALSE(board->model()->marked(1, yours));
    EXPECT_FALSE(board->model()->marked(1, theirTMax));
    EXPECT_TRUE(board->model()->marked(2, yours));
    EXPECT_TRUE(board->caption().contains("\u2260")) << board->caption().toStdString();

    // The 2D view draws their walk over raystep's, and its legend names both.
    View2D* view = w.view2D();
    EXPECT_TRUE(view->showsStudentWalk());
    const auto rows = view->legendRows(false);
    const auto named = [&](const QString& text) {
        return std::any_of(rows.begin(), rows.end(),
                           [&](const auto& r) { return r.second == text; });
    };
    EXPECT_TRUE(named("raystep (yellow)"));
    EXPECT_TRUE(named("your walk (blue)"));

    // Ray 0, picked in the bar with the keyboard: it passed; the replay at its end, nothing
    // marked.
    a->rayChooser()->setFocus();
    QTest::keyClick(a->rayChooser(), Qt::Key_Up);
    QApplication::processEvents();
    EXPECT_EQ(a->shownRay(), 0);
    EXPECT_EQ(s.cursor(), s.size());
    EXPECT_TRUE(a->verdictText().contains("passed")) << a->verdictText().toStdString();
    const Board& b0 = board->board();
    ASSERT_EQ(b0.rows.size(), 7u);
    for (int r = 0; r < 7; ++r) EXPECT_FALSE(board->model()->marked(r, yours)) << r;
    EXPECT_EQ(b0.rows[6].cells[yours], "(4, 2)");

    // A bad file: one message naming the file, the line and the key; nothing shown changes.
    const LogRef shown = s.logRef();
    const std::size_t cursor = s.cursor();
    const QString bad =
        writeLesson(dir, "bad.jsonl", R"({"ray": {"origin": [0.4, 0.4], "dir": [0.8, 0.4]}}
{"cel": [0, 0]}
)");
    openThroughTheMenu(w, bad);
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor([&] {
        box = w.findChild<QMessageBox*>("assessError");
        return box && box->isVisible();
    }));
    EXPECT_TRUE(box->text().contains("bad.jsonl:2")) << box->text().toStdString();
    EXPECT_TRUE(box->text().contains("cel")) << box->text().toStdString();
    box->close();
    QApplication::processEvents();
    EXPECT_EQ(s.logRef(), shown);
    EXPECT_EQ(s.cursor(), cursor);
    EXPECT_EQ(a->shownRay(), 0);
    EXPECT_TRUE(a->bar()->isVisible());
    EXPECT_TRUE(board->showsBeside());

    // Another trace replayed (R, the example ray): the student's walk is not of it.
    // (Under Xvfb, with no window manager, no window is active once the message box goes.)
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    view->setFocus();
    QTest::keyClick(view, Qt::Key_R);
    QApplication::processEvents();
    EXPECT_EQ(s.logKind(), LogKind::ExampleRay);
    EXPECT_FALSE(a->isOpen());
    EXPECT_FALSE(a->bar()->isVisible());
    EXPECT_FALSE(view->showsStudentWalk());
    EXPECT_FALSE(board->showsBeside());
    EXPECT_EQ(columnOf(board->board(), "your cell"), -1);
    QSettings().remove("dialogs");
}

TEST(AssessGui, ATraceNeedsAScene) {
    MainWindow w;
    QAction* item = w.findChild<QAction*>("openStudentTrace");
    ASSERT_NE(item, nullptr);
    EXPECT_FALSE(item->isEnabled());
}

}  // namespace
}  // namespace raystep::gui
