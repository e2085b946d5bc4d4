// The build chart's dashed leaf line on lesson 11 with cIsect raised to 20, as its "Try it live"
// step asks, and lowered to 1: at every step of every node, leaves included, it is C_isect N
// (the root at 20: 20 x 15 = 300, the lesson's 15 primitives), worked out here, not read from
// the chart's code.
#include "gui_testing.h"
#include "live_controls.h"
#include "view2d.h"

#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QImage>
#include <QTest>

#include <cmath>
#include <cstdlib>
#include <optional>

namespace raystep::gui {
namespace {

/// A spin box typed into as a hand does: select what is there, type, Enter.
void type(QAbstractSpinBox* box, const QString& text) {
    box->setFocus();
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
    QApplication::processEvents();
}

/// Columns of the plot with a dark neutral pixel (the dashed line's grey) within a pixel of row y.
int greyColumns(const QImage& image, const QRectF& plot, double y) {
    int columns = 0;
    for (int x = static_cast<int>(plot.left()) + 2; x < static_cast<int>(plot.right()) - 2; ++x)
        for (int row = static_cast<int>(std::lround(y)) - 1; row <= std::lround(y) + 1; ++row) {
            if (row < 0 || row >= image.height() || x < 0 || x >= image.width()) continue;
            const QColor c = image.pixelColor(x, row);
            if (qGray(c.rgb()) < 170 && std::abs(c.red() - c.green()) < 16 &&
                std::abs(c.green() - c.blue()) < 16) {
                ++columns;
                break;
            }
        }
    return columns;
}

/// What a walk over every step of a build saw of the chart: how many steps had one, how many
/// of the root's, before a node's choice, and after a leaf was made (a leaf after its candidates).
struct Walk {
    std::size_t charts = 0, root = 0, beforeChoice = 0, afterLeaf = 0;
    std::optional<std::size_t> rootLastCandidate;  // the cursor there
};

/// Every step of the session's build, checking the chart's leaf cost is C_isect N of the node
/// the cursor is in (N from its BuildNode, C_isect the one typed).
Walk walk(Session& s, const View2D& view, double cIsect) {
    Walk out;
    const auto& events = s.log().events();
    std::optional<BuildNode> node;  // the node the cursor is in
    bool chosen = false, leaf = false;
    for (std::size_t cursor = 1; cursor <= events.size(); ++cursor) {
        const Event& e = events[cursor - 1];
        if (const auto* b = std::get_if<BuildNode>(&e)) {
            node = *b;
            chosen = leaf = false;
        }
        chosen = chosen || std::holds_alternative<SplitChosen>(e);
        leaf = leaf || std::holds_alternative<LeafMade>(e);
        s.setCursor(cursor);
        EXPECT_EQ(s.cursor(), cursor);
        const auto chart = view.costChart();
        if (!chart || !node) continue;  // no candidate yet: no chart
        SCOPED_TRACE(cursor);
        ++out.charts;
        EXPECT_DOUBLE_EQ(chart->leafCost, cIsect * node->prims);
        if (node->parent == kNoId) {
            ++out.root;
            if (!chosen) out.rootLastCandidate = cursor;
        }
        out.beforeChoice += !chosen && !leaf;
        out.afterLeaf += leaf;
    }
    return out;
}

TEST(LeafLine, IsTheLeafCostAtTheCIsectInUseAtEveryStepOfEveryNode) {
    MainWindow w;
    w.resize(w.fitToScreen(QSize(1920, 1080)));
    w.show();
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));  // the window's keys need it active
    ASSERT_TRUE(openLesson(w, "11"));
    QTest::keyClick(&w, Qt::Key_L, Qt::ControlModifier);
    Session& s = w.session();
    LiveControls* controls = w.liveControls();
    ASSERT_TRUE(controls);
    View2D* view = w.view2D();

    // The step's "raise cIsect": 20. The root's line is 20 x 15 = 300 from its first candidate,
    // where the chart once drew 5 x 15 = 75 until the choice came.
    type(controls->cIsectBox(), "20");
    ASSERT_TRUE(w.waitUntilIdle());
    ASSERT_EQ(s.options().kdtree.cIsect, 20.0);
    ASSERT_TRUE(s.showingBuild());
    ASSERT_EQ(s.end(), s.size());  // no exercise holds the replay: every step can be seen
    const Walk raised = walk(s, *view, 20.0);
    EXPECT_GT(raised.root, 1u);
    EXPECT_GT(raised.beforeChoice, raised.root);
    EXPECT_GT(raised.charts, raised.root);

    // Drawn where the chart puts it: at the root's last candidate, before the choice, the dashed
    // grey line runs across the plot at 300's height.
    ASSERT_TRUE(raised.rootLastCandidate);
    s.setCursor(*raised.rootLastCandidate);
    QApplication::processEvents();
    const auto chart = view->costChart();
    ASSERT_TRUE(chart);
    EXPECT_DOUBLE_EQ(chart->leafCost, 300.0);
    const double y = chart->at(0, chart->nodeLo[0], 300.0).y();
    ASSERT_TRUE(chart->plot.top() <= y && y <= chart->plot.bottom()) << y;
    const QImage image = view->grab().toImage().convertToFormat(QImage::Format_RGB32);
    EXPECT_GT(greyColumns(image, chart->plot, y), 0.4 * chart->plot.width()) << y;

    // And lowered to 1, where nodes of a few primitives end as leaves after their candidates
    // (the leaf is cheaper): their line is 1 x N all along, the choice never comes to fix it.
    type(controls->cIsectBox(), "1");
    ASSERT_TRUE(w.waitUntilIdle());
    ASSERT_EQ(s.options().kdtree.cIsect, 1.0);
    ASSERT_EQ(s.end(), s.size());
    const Walk lowered = walk(s, *view, 1.0);
    EXPECT_GT(lowered.afterLeaf, 0u);
    w.close();
}

}  // namespace
}  // namespace raystep::gui
