// A lesson step or exercise on its own structure (docs/lesson-format.md, "setup" on a step or an
// exercise): the window switches to that structure and its trace of the lesson's ray, holds it
// as the lesson's, and a step without a setup returns to the lesson's structure.
#include "compare_window.h"
#include "gui_testing.h"
#include "lesson_panel.h"
#include "main_window.h"

#include "raystep/trace/events.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

namespace raystep::gui {
namespace {

// lecture-kdtree's example ray through the midpoint kd-tree (the lesson's) and a BVH (SAH). On
// the BVH the ray enters nodes 0, 22, 23, 24, 27 and tests one primitive; on the kd-tree
// 0, 1, 2, 14 (lesson 10's test computes both by hand).
const QByteArray kStructuresLesson = R"({
"format": "raystep-lesson", "version": 1, "id": "structures", "number": 94,
"title": {"en": "Structures"}, "text": {"en": "One ray, two trees."},
"scene": "lecture-kdtree", "setup": {"accel": "kdtree", "split": "midpoint"}, "views": ["2d"],
"trace": {"ray": "example"},
"steps": [{"at": {"after": "node_enter", "nth": 1}, "text": {"en": "The kd-tree's root."}},
          {"at": {"after": "node_enter", "nth": 2}, "text": {"en": "The BVH's second node."},
           "setup": {"accel": "bvh", "split": "sah"}},
          {"at": "end", "text": {"en": "Compare them."},
           "compare": {"accel": "kdtree,bvh", "split": "sah"}}],
"exercises": [
 {"id": "kd-nodes", "type": "sequence", "of": "node_enter",
  "prompt": {"en": "The kd-tree's nodes in order?"}},
 {"id": "bvh-tests", "type": "count", "count": "primitive_test",
  "at": {"after": "node_enter", "nth": 1}, "setup": {"accel": "bvh", "split": "sah"},
  "prompt": {"en": "The BVH's primitive tests from here?"}}
]})";

/// The ids of the nodes the log's ray enters, in order.
std::vector<std::uint32_t> entered(const EventLog& log) {
    std::vector<std::uint32_t> ids;
    for (const Event& e : log.events())
        if (const auto* n = std::get_if<NodeEnter>(&e)) ids.push_back(n->node);
    return ids;
}

/// A fresh progress file, before the window reads it: the lesson opens at its first step.
bool clearProgress() {
    QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                  "/progress.json");
    return true;
}

struct Opened {
    QTemporaryDir dir;
    bool cleared = clearProgress();
    MainWindow w;
    Opened() {
        w.resize(1500, 900);
        w.show();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(&w));
        EXPECT_TRUE(openLesson(w, writeLesson(dir, "structures.json", kStructuresLesson)));
    }
};

TEST(LessonStructure, AStepsOwnStructureIsShownAndAStepWithoutOneGoesBack) {
    Opened o;
    MainWindow& w = o.w;
    LessonPanel* p = w.lessonPanel();
    p->setLecturerMode(true);  // no exercise holds: the steps alone move the replay
    const std::vector<std::uint32_t> kd{0, 1, 2, 14}, bvh{0, 22, 23, 24, 27};
    p->goToStep(0);
    EXPECT_EQ(w.session().kind(), AccelKind::KdTree);
    EXPECT_EQ(w.session().logRef(), p->lessonLog());
    EXPECT_EQ(entered(w.session().log()), kd);

    p->goToStep(1);
    QApplication::processEvents();
    EXPECT_EQ(w.session().kind(), AccelKind::Bvh);
    EXPECT_EQ(w.session().options().bvh.split, SplitMethod::Sah);
    EXPECT_NE(w.session().logRef(), p->lessonLog());
    EXPECT_EQ(entered(w.session().log()), bvh);
    // After the 2nd node_enter: ray_begin, enter 0, enter 22.
    EXPECT_EQ(w.session().cursor(), 3u);
    EXPECT_FALSE(p->exploring()) << "the BVH's trace is the lesson's own";
    EXPECT_TRUE(p->replayNote().isEmpty()) << p->replayNote().toStdString();

    p->goToStep(2);  // no setup: the lesson's kd-tree again
    QApplication::processEvents();
    EXPECT_EQ(w.session().kind(), AccelKind::KdTree);
    EXPECT_EQ(w.session().logRef(), p->lessonLog());
    EXPECT_EQ(w.session().cursor(), w.session().size());
    // Its compare list offers the button; pressing it asks the window to compare the two.
    QPushButton* compare = p->findChild<QPushButton*>("compareStructures");
    ASSERT_NE(compare, nullptr);
    EXPECT_TRUE(compare->isVisible());
    QSignalSpy asked(p, &LessonPanel::compareRequested);
    QTest::mouseClick(compare, Qt::LeftButton);
    ASSERT_EQ(asked.size(), 1);
    const auto choices = asked[0][0].value<std::vector<StructureChoice>>();
    EXPECT_EQ(choices, (std::vector<StructureChoice>{{AccelKind::KdTree, SplitMethod::Sah},
                                                     {AccelKind::Bvh, SplitMethod::Sah}}));
    w.waitUntilIdle();
    p->goToStep(1);
    EXPECT_FALSE(compare->isVisible()) << "a step without a compare list has no button";
}

TEST(LessonStructure, AnExerciseOnTheBvhHoldsTheBvhsTrace) {
    Opened o;
    MainWindow& w = o.w;
    LessonPanel* p = w.lessonPanel();
    // Quiz mode: the lesson opens on its first exercise, the kd-tree's, held at its start.
    EXPECT_EQ(w.session().kind(), AccelKind::KdTree);
    EXPECT_TRUE(w.session().held());
    EXPECT_EQ(w.session().end(), 0u);

    // The kd-tree's exercise put away (else the next one's prompt waits for it), the BVH's.
    p->closeExercise();
    p->selectExercise(1);
    QApplication::processEvents();
    EXPECT_EQ(w.session().kind(), AccelKind::Bvh);
    EXPECT_EQ(entered(w.session().log()), (std::vector<std::uint32_t>{0, 22, 23, 24, 27}));
    // Held after the BVH's first node_enter (ray_begin, enter 0): nothing past it is shown.
    EXPECT_TRUE(w.session().held());
    EXPECT_EQ(w.session().end(), 2u);
    EXPECT_EQ(w.session().shownEvents().size(), 2u);
    w.session().setCursor(w.session().size());
    EXPECT_EQ(w.session().cursor(), 2u);
    // Answered right (one test: the short segment in leaf 27), the hold on the BVH lifts.
    auto* answer = p->findChild<QLineEdit*>("answer");
    ASSERT_NE(answer, nullptr);
    answer->setText("1");
    QPushButton* check = buttonNamed(p, QStringLiteral("Check"));
    ASSERT_NE(check, nullptr);
    QTest::mouseClick(check, Qt::LeftButton);
    QApplication::processEvents();
    EXPECT_EQ(w.session().limit(), std::nullopt);
    EXPECT_EQ(w.session().kind(), AccelKind::Bvh);

    // Back to the kd-tree's exercise: its structure and its hold come back.
    p->selectExercise(0);
    QApplication::processEvents();
    EXPECT_EQ(w.session().kind(), AccelKind::KdTree);
    EXPECT_EQ(w.session().logRef(), p->lessonLog());
    EXPECT_TRUE(w.session().held());
    EXPECT_EQ(w.session().end(), 0u);
}

// Lesson 10 reopened where it was left, on a BVH exercise: going back to a step on the lesson's own
// kd-tree shows the lesson's trace, not "exploring the example ray" (the i18n test found it).
TEST(LessonStructure, ReopenedOnAStepOfAnotherStructureTheFirstStepIsTheLessons) {
    clearProgress();
    for (int run = 0; run < 2; ++run) {
        SCOPED_TRACE(run ? "reopened on a BVH exercise" : "opened afresh");
        MainWindow w;
        w.setLessonMode(LessonMode::Presenting);
        ASSERT_TRUE(openLesson(w, "hierarchies"));  // not shown: as the i18n test walks it
        w.tasks().cancel(TaskKind::Render);
        LessonPanel* p = w.lessonPanel();
        for (const int step : {0, 9, 0, 7, 1}) {
            p->goToStep(step);
            QApplication::processEvents();
            EXPECT_TRUE(p->replayNote().isEmpty())
                << "step " << step + 1 << ": " << p->replayNote().toStdString();
            EXPECT_TRUE(p->isLessonLog(w.session().logRef())) << "step " << step + 1;
            EXPECT_EQ(w.session().kind(), step >= 6 ? AccelKind::Bvh : AccelKind::KdTree);
        }
        for (int step = 0; step < 10; ++step) p->goToStep(step);
        for (int e = 0; e < 10; ++e) p->selectExercise(e);  // the last, tests-bvh, on the BVH
        QApplication::processEvents();
    }
}

// Quiz mode: the compare window would replay and count the BVH's whole trace, which the BVH's
// unsolved exercise asks about, even while the kd-tree is shown: refused until it is answered.
TEST(LessonStructure, CompareWaitsForAnExerciseOnAStructureItShows) {
    Opened o;
    MainWindow& w = o.w;
    LessonPanel* p = w.lessonPanel();
    p->closeExercise();  // the kd-tree's exercise put away: the kd-tree's trace is free
    p->goToStep(2);
    QApplication::processEvents();
    ASSERT_EQ(w.session().kind(), AccelKind::KdTree);
    ASSERT_FALSE(w.session().held());
    QPushButton* compare = p->findChild<QPushButton*>("compareStructures");
    ASSERT_NE(compare, nullptr);
    QTest::mouseClick(compare, Qt::LeftButton);
    EXPECT_TRUE(w.waitUntilIdle());
    EXPECT_EQ(w.compareWindow(), nullptr);
    EXPECT_TRUE(w.statusBar()->currentMessage().startsWith(
        "Exercise 2 asks about the BVH, SAH: answer it first"))
        << w.statusBar()->currentMessage().toStdString();
    // The BVH's exercise answered (one test), the comparison opens.
    p->selectExercise(1);
    QApplication::processEvents();
    auto* answer = p->findChild<QLineEdit*>("answer");
    ASSERT_NE(answer, nullptr);
    answer->setText("1");
    QTest::mouseClick(buttonNamed(p, QStringLiteral("Check")), Qt::LeftButton);
    QApplication::processEvents();
    p->goToStep(2);
    QApplication::processEvents();
    QTest::mouseClick(compare, Qt::LeftButton);
    EXPECT_TRUE(w.waitUntilIdle());
    ASSERT_TRUE(waitFor([&] { return w.compareWindow() != nullptr; }));
    EXPECT_EQ(w.compareWindow()->count(), 2);
    w.compareWindow()->close();
}

}  // namespace
}  // namespace raystep::gui
