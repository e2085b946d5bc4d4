// The window fits the screen it opens on (ctest runs this file on a 1366x768 laptop screen too),
// remembers its size and docks, View > Reset layout puts the docks and panels back, the compare
// window fits and remembers its size, and the SAH cost chart carries labelled axes.
#include "compare_window.h"
#include "gui_testing.h"
#include "lesson_panel.h"
#include "main_window.h"
#include "timeline.h"
#include "view2d.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QImage>
#include <QListView>
#include <QPushButton>
#include <QScreen>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>

#include <cmath>
#include <functional>

namespace raystep::gui {
namespace {

void forgetLayout() {
    QSettings settings;
    settings.remove("window");
    settings.remove("compare");
}

/// Each test starts from no saved layout and leaves none: the other suites' windows in this
/// process would otherwise open at a test's odd sizes (least size, squeezed panels).
class Layout : public ::testing::Test {
  protected:
    void SetUp() override { forgetLayout(); }
    void TearDown() override { forgetLayout(); }
};
using CostChart = Layout;

QRect screenOf(const QWidget& w) {
    return w.screen()->availableGeometry();
}

/// The widget's rectangle in screen coordinates.
QRect onScreen(const QWidget* w) {
    return QRect(w->mapToGlobal(QPoint(0, 0)), w->size());
}

/// Shows the window as the app does at start and waits until its layout is in shape.
void start(MainWindow& w) {
    w.sizeForScreen();
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
    ASSERT_TRUE(waitFor([&] { return w.layoutSettled(); }));
}

QList<QDockWidget*> docks(const MainWindow& w) {
    // The right column's docks; the board and the live controls, under the views, have their
    // own test (board_test.cpp, LayoutBoard).
    QList<QDockWidget*> right = w.findChildren<QDockWidget*>();
    right.removeIf([](const QDockWidget* d) {
        return d->objectName() == "boardDock" || d->objectName() == "liveControlsDock";
    });
    return right;
}

/// Every part a student needs lies on the screen and is not squeezed below its smallest size.
void expectOnScreen(const MainWindow& w, const char* where) {
    SCOPED_TRACE(where);
    const QRect screen = screenOf(w);
    EXPECT_TRUE(screen.contains(w.frameGeometry()))
        << w.frameGeometry().width() << "x" << w.frameGeometry().height();
    EXPECT_LE(w.minimumSizeHint().width(), screen.width());
    EXPECT_LE(w.minimumSizeHint().height(), screen.height());
    for (const QDockWidget* d : docks(w)) {
        ASSERT_TRUE(d->isVisible()) << d->objectName().toStdString();
        EXPECT_TRUE(screen.contains(onScreen(d))) << d->objectName().toStdString();
        EXPECT_GE(d->width(), 180) << d->objectName().toStdString();
    }
    ASSERT_TRUE(w.timeline()->isVisible());
    EXPECT_TRUE(screen.contains(onScreen(w.timeline())));
    const auto* box = w.findChild<QWidget*>("exerciseBox");
    ASSERT_NE(box, nullptr);
    if (box->isVisible()) {
        EXPECT_TRUE(screen.contains(onScreen(box)));
        EXPECT_GE(box->height(), box->minimumSizeHint().height());
        EXPECT_GE(box->width(), box->minimumSizeHint().width());
    }
}

TEST_F(Layout, TheWindowItsDocksTimelineAndExerciseBoxLieOnTheScreen) {
    forgetLayout();
    MainWindow w;
    start(w);
    ASSERT_TRUE(openLesson(w, "1"));
    expectOnScreen(w, "lesson 1");
    // Lesson 5's pseudo-code is the longest line: it wraps in the panel instead of running off.
    ASSERT_TRUE(openLesson(w, "5"));
    const auto* text = w.findChild<QTextBrowser*>("lessonText");
    ASSERT_NE(text, nullptr);
    EXPECT_EQ(text->horizontalScrollBar()->maximum(), 0);
    ASSERT_TRUE(openLesson(w, "11"));
    w.setLessonMode(LessonMode::Presenting);  // B is refused while an exercise holds (quiz mode)
    w.replayBuild();
    ASSERT_TRUE(w.waitUntilIdle());
    ASSERT_TRUE(w.session().showingBuild());
    expectOnScreen(w, "lesson 11, build replay");
    // The event rows (a candidate's is long) are cut at the dock's edge, whole in their tooltip.
    auto* list = w.findChild<QListView*>("eventList");
    ASSERT_NE(list, nullptr);
    // At the dock's least width, whatever this screen's default is.
    auto* eventsDock = w.findChild<QDockWidget*>("eventsDock");
    ASSERT_NE(eventsDock, nullptr);
    w.resizeDocks({eventsDock}, {1}, Qt::Horizontal);
    ASSERT_TRUE(waitFor([&] { return eventsDock->width() < 200; }));
    ASSERT_GT(list->model()->rowCount(), 2);
    EXPECT_EQ(list->horizontalScrollBar()->maximum(), 0);
    const QModelIndex row = list->model()->index(2, 0);
    EXPECT_EQ(row.data(Qt::ToolTipRole).toString(), row.data().toString());
    EXPECT_GT(list->fontMetrics().horizontalAdvance(row.data().toString()),
              list->viewport()->width());  // long enough to be cut: the test means something
    w.close();
}

TEST_F(Layout, AtItsSmallestTheWindowStillShowsTheWholeExerciseBox) {
    forgetLayout();
    MainWindow w;
    start(w);
    ASSERT_TRUE(openLesson(w, "6"));
    // The longest header, a solved exercise's ("Exercise 1 / 9 (solved)"): tDeltaY = 1 / |0.4|.
    w.lessonPanel()->selectExercise(0);
    w.lessonPanel()->submit("2.5");
    // As small as the layout lets it be (the hint, or more where the tool bars need it): the
    // width has settled, well inside a student's laptop screen.
    w.resize(w.minimumSizeHint());
    int last = -1;
    ASSERT_TRUE(waitFor([&] {
        const bool settled = w.width() == last;
        last = w.width();
        return settled && w.width() < 1366 - 200;
    })) << w.width();
    auto* main = qobject_cast<QSplitter*>(w.centralWidget());
    ASSERT_NE(main, nullptr);
    main->setSizes({0, 100000});  // the lesson panel dragged as narrow as it goes
    const auto* box = w.findChild<QWidget*>("exerciseBox");
    ASSERT_NE(box, nullptr);
    ASSERT_TRUE(waitFor([&] { return box->isVisible() && main->sizes()[0] < 400; }));
    EXPECT_GE(box->width(), box->minimumSizeHint().width());
    w.close();
}

TEST_F(Layout, ASavedSizeIsRestoredAndClampedToTheScreen) {
    forgetLayout();
    QSize saved;
    {
        MainWindow w;
        start(w);
        // Smaller than the screen, larger than the window's least size.
        saved = (screenOf(w).size() * 3 / 4).expandedTo(w.minimumSizeHint() + QSize(20, 20));
        w.resize(saved);
        ASSERT_TRUE(waitFor([&] { return w.size() == saved; }));
        w.close();
    }
    {
        MainWindow w;
        start(w);
        EXPECT_EQ(w.size(), saved);
        // Then a size larger than this screen (saved on a projector, say).
        w.resize(screenOf(w).size() + QSize(600, 400));
        ASSERT_TRUE(waitFor([&] { return w.width() > screenOf(w).width(); }));
        w.close();
    }
    MainWindow w;
    start(w);
    EXPECT_TRUE(screenOf(w).contains(w.frameGeometry()))
        << w.frameGeometry().width() << "x" << w.frameGeometry().height();
    EXPECT_GE(w.width(), screenOf(w).width() / 2);  // clamped, not thrown away
}

TEST_F(Layout, DocksShrunkOnceAreReadableAgainAtTheNextStart) {
    forgetLayout();
    {
        MainWindow w;
        start(w);
        // As far as the layout lets a user drag them.
        w.resizeDocks(docks(w), {1, 1}, Qt::Horizontal);
        ASSERT_TRUE(waitFor([&] { return docks(w)[0]->width() < 200; }));
        w.close();
    }
    MainWindow w;
    start(w);
    // A fifth of the window, as a dock needs to show an event's line (and never about 60 px).
    const auto readable = [&] {
        for (const QDockWidget* d : docks(w))
            if (d->width() < w.width() / 5 - 8) return false;
        return true;
    };
    EXPECT_TRUE(waitFor(readable, 5000))
        << docks(w)[0]->width() << " " << docks(w)[1]->width() << " of " << w.width();
}

TEST_F(Layout, ResetLayoutPutsTheDocksAndPanelsBack) {
    forgetLayout();
    MainWindow w;
    start(w);
    ASSERT_TRUE(openLesson(w, "6"));
    auto* main = qobject_cast<QSplitter*>(w.centralWidget());
    ASSERT_NE(main, nullptr);
    const QList<int> mainSizes = main->sizes();
    const QList<QDockWidget*> ds = docks(w);
    ASSERT_EQ(ds.size(), 2);
    const int dockWidth = ds[0]->width();
    // What a session of dragging leaves: narrow docks, one floating, one closed, a narrow panel.
    w.resizeDocks(ds, {1, 1}, Qt::Horizontal);
    main->setSizes({200, 2000});
    ds[1]->setFloating(true);
    ds[0]->close();
    ASSERT_TRUE(waitFor([&] { return !ds[0]->isVisible() && main->sizes() != mainSizes; }));
    auto* reset = w.findChild<QAction*>("resetLayout");
    ASSERT_NE(reset, nullptr);
    reset->trigger();
    ASSERT_TRUE(waitFor([&] {
        return ds[0]->isVisible() && ds[1]->isVisible() && !ds[1]->isFloating() &&
               std::abs(ds[0]->width() - dockWidth) <= 4 &&
               std::abs(ds[1]->width() - dockWidth) <= 4;
    })) << ds[0]->width()
        << " " << ds[1]->width() << " (wanted " << dockWidth << ")";
    EXPECT_NEAR(main->sizes()[0], mainSizes[0], 4);
    expectOnScreen(w, "after Reset layout");
}

TEST_F(Layout, TheCompareWindowFitsShowsItsTableAndCloseAndRemembersItsSize) {
    forgetLayout();
    MainWindow w;
    start(w);
    w.openScene("lecture-kdtree", AccelKind::KdTree, /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    const auto openCompare = [&]() -> CompareWindow* {
        w.openCompare();
        if (!w.waitUntilIdle() || !w.compareWindow()) return nullptr;
        if (!QTest::qWaitForWindowExposed(w.compareWindow())) return nullptr;
        return w.compareWindow();
    };
    CompareWindow* c = openCompare();
    ASSERT_NE(c, nullptr);
    const QRect screen = screenOf(*c);
    EXPECT_TRUE(screen.contains(c->frameGeometry()))
        << c->frameGeometry().width() << "x" << c->frameGeometry().height();
    QTableWidget* table = c->table();
    EXPECT_TRUE(screen.contains(onScreen(table)));
    int rows = 0;
    for (int r = 0; r < table->rowCount(); ++r) rows += table->rowHeight(r);
    EXPECT_GE(table->viewport()->height(), rows);  // every statistic in sight, no scrolling
    auto* close = c->findChild<QPushButton*>("closeCompare");
    ASSERT_NE(close, nullptr);
    EXPECT_TRUE(close->isVisible());
    EXPECT_TRUE(screen.contains(onScreen(close)));
    // Its size, at the next opening.
    const QSize chosen = (screen.size() * 2 / 3).expandedTo(c->minimumSizeHint() + QSize(20, 20));
    c->resize(chosen);
    ASSERT_TRUE(waitFor([&] { return c->size() == chosen; }));
    QTest::mouseClick(close, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return w.compareWindow() == nullptr; }));
    c = openCompare();
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->size(), chosen);
    c->close();
}

/// The cursor just after the k-th (from 0) event of a kind.
std::size_t afterNth(const Session& s, std::size_t kind, int k) {
    std::size_t at = 0;
    for (int i = 0; i <= k; ++i) at = s.replay().nextOfKind(i ? at + 1 : 0, kind);
    return at + 1;
}

template <class T>
std::size_t kindOf() {
    return Event(T{}).index();
}

// Lesson 11's build replay keeps a strip under its scene for the SAH chart. A strip of a fixed
// height left the scene 130 px wide at 1366x768 and a few pixels at 1024x600, where Fit (F) could
// not help: the chart now takes at most a share of the view, and none when too short to read.
TEST_F(Layout, LessonElevensSceneFitsItsViewOnALaptopAfterAResizeAndAFloatedDock) {
    MainWindow w;
    start(w);
    w.setLecturerMode(true);
    ASSERT_TRUE(openLesson(w, "11"));
    Session& s = w.session();
    ASSERT_TRUE(s.showingBuild());
    s.setCursor(afterNth(s, kindOf<SplitCandidate>(), 6));  // candidates: the chart is drawn
    View2D* view = w.view2D();
    // Whole in the view and clear of the chart; at least `share` of the view's height, and most
    // of the room above the chart (or of the view's width, when that is what binds it).
    const auto fits = [&](const char* where, double share) {
        SCOPED_TRACE(where);
        QApplication::processEvents();
        const BoxN<2> b = s.scene2D()->bounds();
        const QRectF r =
            QRectF(view->screenOf(Vec2(b.lo.x, b.hi.y)), view->screenOf(Vec2(b.hi.x, b.lo.y)))
                .normalized();
        const QString size = QStringLiteral("%1x%2 in %3x%4")
                                 .arg(r.width())
                                 .arg(r.height())
                                 .arg(view->width())
                                 .arg(view->height());
        EXPECT_TRUE(QRectF(view->rect()).contains(r)) << size.toStdString();
        double room = view->height();
        if (const auto chart = view->costChart()) {
            EXPECT_LT(r.bottom(), chart->plot.top()) << size.toStdString();
            room = chart->plot.top() - 40;  // the chart's title row over its plot
        }
        EXPECT_GE(r.height(), share * view->height()) << size.toStdString();
        EXPECT_TRUE(r.height() >= 0.6 * room || r.width() >= 0.6 * view->width())
            << size.toStdString() << ", room " << room;
    };
    fits("as opened", 0.35);
    QTest::keyClick(&w, Qt::Key_F);
    fits("Fit", 0.35);
    // A small window: the chart gives way to the scene it is about.
    w.resize(1024, 600);
    ASSERT_TRUE(waitFor([&] { return w.width() <= 1024 && w.height() <= 600; }))
        << w.width() << "x" << w.height() << ", least " << w.minimumSizeHint().width() << "x"
        << w.minimumSizeHint().height();
    QTest::qWait(100);
    QTest::keyClick(&w, Qt::Key_F);
    // The legend, the chart and its axis share the view with the scene at this size: a third.
    fits("1024x600 after Fit", 0.35);
    // The docks under the view floated: the view grows, the scene with it.
    auto* board = w.findChild<QDockWidget*>("boardDock");
    auto* live = w.findChild<QDockWidget*>("liveControlsDock");
    ASSERT_NE(board, nullptr);
    ASSERT_NE(live, nullptr);
    const int before = view->height();
    board->setFloating(true);
    live->setFloating(true);
    ASSERT_TRUE(waitFor([&] { return view->height() > before; }));
    w.activateWindow();
    fits("the board floated", 0.35);
    QTest::keyClick(&w, Qt::Key_F);
    fits("the board floated, Fit", 0.35);
    board->setFloating(false);
    live->setFloating(false);
    w.close();
}

/// Dark (text) pixels in a rectangle of the image.
int inkIn(const QImage& image, QRect r, int grey = 110) {
    int n = 0;
    r = r.intersected(image.rect());
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x) n += qGray(image.pixel(x, y)) < grey;
    return n;
}

TEST_F(CostChart, ItsAxesCarryTickValuesSpanningTheCandidatesCostsUnderTheNode) {
    forgetLayout();
    MainWindow w;
    start(w);
    w.openScene("lecture-kdtree", AccelKind::KdTree, /*quiet=*/true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    Session& s = w.session();
    s.recordBuild();
    ASSERT_TRUE(s.showingBuild());
    for (const int k : {4, 30}) {
        SCOPED_TRACE(k);
        s.setCursor(afterNth(s, kindOf<SplitCandidate>(), k));
        // The node being split and its candidates so far, read from the log itself.
        const auto& events = s.log().events();
        std::uint32_t node = 0;
        double lo = INFINITY, hi = -INFINITY;
        for (std::size_t i = 0; i < s.cursor(); ++i) {
            if (const auto* b = std::get_if<BuildNode>(&events[i])) {
                node = b->node;
                lo = INFINITY, hi = -INFINITY;
            } else if (const auto* c = std::get_if<SplitCandidate>(&events[i])) {
                lo = std::min(lo, c->sahCost), hi = std::max(hi, c->sahCost);
            }
        }
        ASSERT_LT(lo, hi);
        const auto chart = w.view2D()->costChart();
        ASSERT_TRUE(chart);
        EXPECT_LE(chart->costLo, lo);
        EXPECT_GE(chart->costHi, hi);
        // Round values, evenly spaced by 1, 2 or 5 times a power of ten, spanning the range.
        const auto& ticks = chart->costTicks;
        ASSERT_GE(ticks.size(), 3u);
        const double step = ticks[1] - ticks[0];
        const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
        EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 ||
                    std::abs(mantissa - 5) < 1e-6)
            << step;
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            EXPECT_NEAR(ticks[i], ticks[0] + i * step, 1e-9 * std::abs(step) * (i + 1));
            EXPECT_NEAR(std::remainder(ticks[i], step), 0.0, 1e-6 * step);
        }
        EXPECT_GE(ticks.front(), chart->costLo);
        EXPECT_LE(ticks.back(), chart->costHi);
        EXPECT_LT(ticks.front() - chart->costLo, step);
        EXPECT_LT(chart->costHi - ticks.back(), step);
        EXPECT_LT(ticks.back() - ticks.front(), 2 * (hi - lo) + 2 * step);  // a tight axis

        const QImage image = w.view2D()->grab().toImage().convertToFormat(QImage::Format_RGB32);
        // The position axis at the view's scale: the node's left and right edges, as the
        // orange box above is drawn in the image, are where the chart puts them.
        const NodeRecord& n = s.log().nodes()[node];
        const QColor orange(230, 159, 0);
        const int row = static_cast<int>(
            w.view2D()->screenOf(Vec2((n.lo[0] + n.hi[0]) / 2, (n.lo[1] + n.hi[1]) / 2)).y());
        int left = -1, right = -1;
        for (int x = 0; x < image.width(); ++x) {
            const QColor p = image.pixelColor(x, row);
            if (std::abs(p.red() - orange.red()) + std::abs(p.green() - orange.green()) +
                    std::abs(p.blue() - orange.blue()) <
                40) {
                if (left < 0) left = x;
                right = x;
            }
        }
        ASSERT_GE(left, 0) << "no node box on row " << row;
        EXPECT_NEAR(chart->at(0, n.lo[0], chart->costLo).x(), left + 0.5, 2.5);
        EXPECT_NEAR(chart->at(0, n.hi[0], chart->costLo).x(), right + 0.5, 2.5);
        for (double v : chart->positionTicks[0]) {
            EXPECT_GE(v, n.lo[0]);
            EXPECT_LE(v, n.hi[0]);
        }
        // Every cost tick's value is written left of the plot, every x tick's under it.
        for (double v : ticks) {
            const QPointF p = chart->at(0, n.lo[0], v);
            EXPECT_GT(inkIn(image, QRect(int(p.x()) - 60, int(p.y()) - 7, 52, 14)), 6) << v;
        }
        ASSERT_FALSE(chart->positionTicks[0].empty());
        for (double v : chart->positionTicks[0]) {
            const QPointF p = chart->at(0, v, chart->costLo);
            // Written in the curve's colour (vermilion, lighter than black).
            EXPECT_GT(inkIn(image, QRect(int(p.x()) - 20, int(chart->plot.bottom()) + 3, 40, 16),
                            /*grey=*/170),
                      6)
                << v;
        }
    }
}

}  // namespace
}  // namespace raystep::gui
