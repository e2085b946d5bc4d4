// The replay app, driven as a user would under Xvfb: stepping the slides' DDA example shows the
// cells and tMax values of the board in the inspector, the views change as the cursor moves,
// clicking a pixel records and replays its ray tree, and --screenshot writes the window.
#include "compare_window.h"
#include "gui_testing.h"
#include "image_view.h"
#include "lesson_panel.h"
#include "main_window.h"
#include "view2d.h"
#include "vtk_view.h"

#include "course/exercise.h"
#include "course/lesson_trace.h"

#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

namespace raystep::gui {
namespace {

/// Puts every exercise of the open lesson away, as a student who chooses to look past them
/// does: no exercise then holds the replay.
void putAwayAll(LessonPanel* p) {
    for (int i = 0; i < static_cast<int>(p->lesson().exercises.size()); ++i) {
        p->selectExercise(i);
        p->closeExercise();
    }
}

/// Distinct colours in an image: a blank (one-colour) view has 1.
std::size_t colours(const QImage& image) {
    std::set<QRgb> seen;
    const QImage i = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < i.height(); y += 2)
        for (int x = 0; x < i.width(); x += 2) seen.insert(i.pixel(x, y));
    return seen.size();
}

QImage grab(QWidget* w) {
    QApplication::processEvents();
    return w->grab().toImage();
}

/// Opens a scene and waits for it (the window opens in the background); true if it opened.
bool open(MainWindow& w, const QString& scene, AccelKind kind, bool render = true) {
    w.openScene(scene, kind, /*quiet=*/true, {}, render);
    return w.waitUntilIdle() && w.lastOpenOk().value_or(false);
}
CompareWindow* compare(MainWindow& w) {
    w.openCompare();
    EXPECT_TRUE(w.waitUntilIdle());
    return w.compareWindow();
}

/// The cursor just after the k-th (from 0) event of a kind.
std::size_t afterNth(const Session& s, std::size_t kind, int k) {
    std::size_t at = 0;
    for (int i = 0; i <= k; ++i) at = s.replay().nextOfKind(i ? at + 1 : 0, kind);
    return at + 1;
}

TEST(App, SteppingTheSlidesDdaShowsTheBoardsValues) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "lecture-grid", AccelKind::Grid));
    Session& s = w.session();
    ASSERT_GT(s.size(), 10u);
    // By hand: origin (0.4, 0.4), direction (0.8, 0.4), cells of 1: tMax (0.75, 1.5) and
    // tDelta (1.25, 2.5) in cell (0, 0); then X to (1, 0) with tMaxX 2; Y to (1, 1) with tMaxY 4;
    // X to (2, 1) with tMaxX 3.25.
    s.setCursor(afterNth(s, variantIndex<DdaCell>(), 0));
    EXPECT_TRUE(w.inspectorText().contains("X = 0   Y = 0")) << w.inspectorText().toStdString();
    EXPECT_TRUE(w.inspectorText().contains("tMaxX = 0.75   tMaxY = 1.5"));
    EXPECT_TRUE(w.inspectorText().contains("tDeltaX = 1.25   tDeltaY = 2.5"));
    const QImage first = grab(w.view2D());
    s.setCursor(afterNth(s, variantIndex<DdaCell>(), 3));
    EXPECT_TRUE(w.inspectorText().contains("X = 2   Y = 1")) << w.inspectorText().toStdString();
    EXPECT_TRUE(w.inspectorText().contains("tMaxX = 3.25   tMaxY = 4"));
    const QImage fourth = grab(w.view2D());
    EXPECT_GT(colours(first), 20u);  // grid, cells, primitives, ray, labels
    EXPECT_NE(first, fourth);        // the current cell and the ray moved
    // Step back and forward: the same picture as before (a pure function of the cursor).
    w.stepBack();
    w.stepForward();
    EXPECT_EQ(grab(w.view2D()), fourth);
    // Jumping to the next primitive test lands on one.
    s.setCursor(0);
    w.jumpToNextOfKind();  // the first kind in the list: DDA step
    EXPECT_TRUE(std::holds_alternative<DdaCell>(s.log().events()[s.cursor() - 1]));
}

TEST(App, TheRobustnessLessonShowsTheSlidesLoopBesideTheExactWalk) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
    ASSERT_TRUE(openLesson(w, "robustness"));
    auto* text = w.lessonPanel()->findChild<QTextBrowser*>();
    ASSERT_NE(text, nullptr);
    // Presenting (in quiz mode the note waits with the step: it names the tie's cell).
    w.setLessonMode(LessonMode::Presenting);
    // Page Down to the third step, as a lecturer would.
    for (int k = 0; k < 2; ++k) w.lessonPanel()->goToStep(k + 1);
    QApplication::processEvents();
    const QString shown = text->toPlainText();
    // The cells by hand: the loop steps Y alone at each vertex tie, the exact walk both axes.
    EXPECT_TRUE(shown.contains("(0, 0) (0, 1) (1, 1) (1, 2)")) << shown.toStdString();
    EXPECT_TRUE(shown.contains("the exact walk through (0, 0) (1, 1) (2, 2)"))
        << shown.toStdString();
    // The first step has no such note.
    w.lessonPanel()->goToStep(0);
    QApplication::processEvents();
    EXPECT_FALSE(text->toPlainText().contains("exact walk through"))
        << text->toPlainText().toStdString();
}

TEST(App, ClickingAPixelRecordsAndReplaysIt) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "default", AccelKind::KdTree));
    ASSERT_TRUE(w.waitUntilIdle());
    ImageView* image = w.imageView();
    ASSERT_FALSE(image->image().isNull());
    EXPECT_GT(colours(image->image()), 100u);  // a rendered picture, not a blank
    // Click the middle of the widget: the pixel under it is traced.
    const QPointF centre(image->width() / 2.0, image->height() / 2.0);
    QMouseEvent press(QEvent::MouseButtonPress, centre, image->mapToGlobal(centre), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(image, &press);
    const Session& s = w.session();
    ASSERT_GT(s.size(), 5u);
    const auto* pixel = std::get_if<PixelResult>(&s.log().events().back());
    ASSERT_NE(pixel, nullptr);
    EXPECT_NEAR(pixel->x, image->image().width() / 2.0, 2.0);
    EXPECT_NEAR(pixel->y, image->image().height() / 2.0, 2.0);
    EXPECT_EQ(s.cursor(), s.size());  // replayed to its end
    // The 3D view draws the scene, and the rays once the cursor has passed them.
    const QImage end = grab(w.view3D());
    EXPECT_GT(colours(end), 20u);
    w.session().setCursor(0);
    EXPECT_NE(grab(w.view3D()), end);
}

TEST(App, ReplayingASahBuildShowsCandidatesAndTheChoice) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "lecture-kdtree", AccelKind::KdTree));
    Session& s = w.session();
    s.recordBuild();
    ASSERT_TRUE(s.showingBuild());
    // The root's first candidate, then its choice: the inspector shows NL, NR, P(L|C) and the
    // cost; the choice is the cheapest candidate.
    s.setCursor(afterNth(s, variantIndex<SplitCandidate>(), 0));
    EXPECT_TRUE(w.inspectorText().contains("NL = ")) << w.inspectorText().toStdString();
    EXPECT_TRUE(w.inspectorText().contains("P(L|C) = "));
    const QImage first = grab(w.view2D());
    s.setCursor(afterNth(s, variantIndex<SplitChosen>(), 0));
    const ReplayState& st = s.state();
    ASSERT_TRUE(st.chosen);
    EXPECT_TRUE(w.inspectorText().contains("chosen: ")) << w.inspectorText().toStdString();
    double cheapest = kInfinity;
    for (const SplitCandidate& c : st.candidates) cheapest = std::min(cheapest, c.sahCost);
    EXPECT_EQ(cheapest, st.chosen->sahCost);
    const QImage chosen = grab(w.view2D());
    EXPECT_NE(first, chosen);  // more candidate planes, the cost curve and the chosen plane
    EXPECT_GT(colours(chosen), 20u);
}

TEST(App, CompareModeShowsThreeTrees) {
    MainWindow w;
    ASSERT_TRUE(open(w, "lecture-kdtree", AccelKind::KdTree));
    CompareWindow* c = compare(w);
    ASSERT_NE(c, nullptr);
    QApplication::processEvents();
    // Three trees of the same scene, built differently, each replaying the same example ray.
    std::set<std::uint32_t> nodes;
    for (int i = 0; i < 3; ++i) {
        const Session& s = c->session(i);
        EXPECT_EQ(s.options().kdtree.split, static_cast<SplitMethod>(i));
        ASSERT_FALSE(s.log().rays().empty());
        EXPECT_EQ(s.log().rays()[0].origin, w.session().log().rays()[0].origin);
        nodes.insert(s.summary().stats.nodes);
        // The table's "nodes" row is that tree's.
        EXPECT_EQ(c->table()->item(1, i)->text().toUInt(), s.summary().stats.nodes);
    }
    EXPECT_EQ(c->table()->columnCount(), 3);
    EXPECT_GE(nodes.size(), 2u);  // midpoint and median agree here; SAH does not
    // Every tree finds the same nearest hit for the ray (the structures must agree).
    const auto hitOf = [&](int i) { return c->session(i).replay().state().nearestT; };
    c->setStep(1 << 20);
    ASSERT_TRUE(hitOf(0));
    EXPECT_EQ(hitOf(0), hitOf(1));
    EXPECT_EQ(hitOf(0), hitOf(2));
    EXPECT_GT(colours(c->grab().toImage()), 30u);
    c->close();
}

// In 3D the build's replay draws the node's box, the candidate plane and the chosen plane.
TEST(App, The3DViewShowsABuildsPlanes) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "default", AccelKind::KdTree, /*render=*/false));
    Session& s = w.session();
    s.recordBuild();
    s.setCursor(afterNth(s, variantIndex<BuildNode>(), 0));
    const QImage node = grab(w.view3D());
    s.setCursor(afterNth(s, variantIndex<SplitCandidate>(), 3));
    const QImage candidate = grab(w.view3D());
    s.setCursor(afterNth(s, variantIndex<SplitChosen>(), 0));
    const QImage chosen = grab(w.view3D());
    EXPECT_NE(node, candidate);
    EXPECT_NE(candidate, chosen);
    // The chosen plane is in the palette's "chosen" blue (0, 114, 178): more such pixels than
    // before it was chosen (the candidate is a lighter sky blue, 86, 180, 233).
    const auto chosenBlue = [](const QImage& i) {
        int n = 0;
        for (int y = 0; y < i.height(); ++y)
            for (int x = 0; x < i.width(); ++x) {
                const QColor c = i.pixelColor(x, y);
                n += c.red() < 50 && c.green() > 80 && c.green() < 150 && c.blue() > 140;
            }
        return n;
    };
    EXPECT_GT(chosenBlue(chosen), chosenBlue(candidate) + 20);
}

// Compare mode on a 3D scene: the clicked pixel's ray tree through three kd-trees, in three 3D
// views; every tree finds the same colour (the PixelResult) for it.
TEST(App, CompareModeIn3DReplaysTheClickedPixel) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "whitted", AccelKind::KdTree, /*render=*/false));
    w.session().tracePixel(150, 100, 320, 240);
    CompareWindow* c = compare(w);
    ASSERT_NE(c, nullptr);
    c->resize(1400, 800);
    c->show();
    QApplication::processEvents();
    const auto pixelOf = [](const Session& s) {
        return std::get<PixelResult>(s.log().events().back());
    };
    const PixelResult main = pixelOf(w.session());
    for (int i = 0; i < 3; ++i) {
        const Session& s = c->session(i);
        ASSERT_FALSE(s.is2D());
        EXPECT_EQ(s.options().kdtree.split, static_cast<SplitMethod>(i));
        const PixelResult p = pixelOf(s);
        EXPECT_EQ(p.x, 150u);
        EXPECT_EQ(p.y, 100u);
        EXPECT_EQ(p.rgb, main.rgb);
    }
    c->setStep(1 << 20);
    EXPECT_GT(colours(grab(c)), 50u);
    delete c;
}

TEST(App, BadScenesAreRefusedAndTheCurrentOneKept) {
    MainWindow w;
    ASSERT_TRUE(open(w, "lecture-kdtree", AccelKind::KdTree));
    EXPECT_FALSE(open(w, "no-such-scene", AccelKind::Grid));
    EXPECT_EQ(w.session().name(), "lecture-kdtree");
    EXPECT_GT(w.session().size(), 0u);
}

// A student's lesson: the steps move the replay, the exercise of the slides' DDA is answered by
// clicking a cell of the 2D view, checked against the trace, and the progress is saved.
TEST(App, ALessonsStepsAndExercisesFollowTheTrace) {
    QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                  "/progress.json");
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    ASSERT_TRUE(openLesson(w, "grid-2d-dda"));
    LessonPanel* p = w.lessonPanel();
    ASSERT_TRUE(p->hasLesson());
    putAwayAll(p);  // the student follows the steps, looking past the exercises
    EXPECT_TRUE(w.view2D()->isVisible());
    EXPECT_FALSE(w.view3D()->isVisible());
    // Step 2 is "after the first cell": the board's values, by hand as in the test above.
    p->goToStep(1);
    EXPECT_TRUE(w.inspectorText().contains("tMaxX = 0.75   tMaxY = 1.5"))
        << w.inspectorText().toStdString();
    const QImage step2 = grab(w.view2D());
    p->goToStep(4);  // the slides' last frame
    EXPECT_TRUE(w.inspectorText().contains("X = 2   Y = 1")) << w.inspectorText().toStdString();
    EXPECT_NE(grab(w.view2D()), step2);

    // Exercise 4: the ray is in (2, 1); tMaxX 3.25 < tMaxY 4, so the next cell is (3, 1).
    p->selectExercise(3);
    EXPECT_TRUE(w.inspectorText().contains("X = 2   Y = 1"));  // the replay waits before the step
    QApplication::processEvents();
    QTest::mouseClick(w.view2D(), Qt::LeftButton, {}, w.view2D()->cellCentre(2, 2).toPoint());
    EXPECT_TRUE(p->feedback().startsWith("Not right")) << p->feedback().toStdString();
    QTest::mouseClick(w.view2D(), Qt::LeftButton, {}, w.view2D()->cellCentre(3, 1).toPoint());
    EXPECT_TRUE(p->feedback().startsWith("Right.")) << p->feedback().toStdString();
    EXPECT_TRUE(p->feedback().contains("steps in X")) << p->feedback().toStdString();
    // Typed with an Italian decimal comma, within the tolerance: tDeltaY = 1 / 0.4.
    p->selectExercise(0);
    EXPECT_FALSE(p->submit("2,4"));
    EXPECT_TRUE(p->submit("2,5"));

    // The progress file: written atomically, read back by the core's parser.
    QFile f(w.progressPath());
    ASSERT_TRUE(f.open(QIODevice::ReadOnly)) << w.progressPath().toStdString();
    const Progress saved = parseProgress(f.readAll().toStdString(), "progress.json");
    const auto& rec = saved.lessons.at("grid-2d-dda").exercises;
    EXPECT_EQ(rec.at("next-cell").attempts, 2);
    EXPECT_TRUE(rec.at("next-cell").correct);
    EXPECT_EQ(rec.at("next-cell").answer, "3,1");
    EXPECT_EQ(rec.at("tdelta-y").attempts, 2);
    EXPECT_EQ(saved.lessons.at("grid-2d-dda").step, 4);

    // Reopened, the lesson comes back at the step it was left on.
    MainWindow again;
    ASSERT_TRUE(openLesson(again, "6"));
    EXPECT_EQ(again.lessonPanel()->step(), 4);
}

TEST(App, LecturerModeRevealsAndTheSahExerciseListsTheCandidates) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    ASSERT_TRUE(openLesson(w, "building-kdtree"));
    LessonPanel* p = w.lessonPanel();
    EXPECT_TRUE(w.session().showingBuild());
    // The root's pick (the lesson asks for the costs of named planes first).
    const auto& exercises = p->lesson().exercises;
    const auto pickAt = std::find_if(exercises.begin(), exercises.end(), [](const Exercise& e) {
        return e.kind == ExerciseKind::PickSplit;
    });
    ASSERT_NE(pickAt, exercises.end());
    // The exercises before it put away (their prompts' answers would wait for them).
    for (int e = 0; e < static_cast<int>(pickAt - exercises.begin()); ++e) {
        p->selectExercise(e);
        p->closeExercise();
    }
    p->selectExercise(static_cast<int>(pickAt - exercises.begin()));
    EXPECT_TRUE(p->feedback().isEmpty());  // a student sees no answer
    const LessonRun run = runLesson(p->lesson());
    const Answer ref = referenceAnswer(*pickAt, *run.log, p->lesson().file);
    const QString pick = QStringLiteral("%1=%2")
                             .arg(QChar("xyz"[int(ref.numbers[0])]))
                             .arg(ref.numbers[1], 0, 'g', 17);
    EXPECT_TRUE(p->submit(pick)) << p->feedback().toStdString();
    w.setLecturerMode(true);
    p->selectExercise(1);
    EXPECT_TRUE(p->feedback().startsWith("Answer: ")) << p->feedback().toStdString();
    EXPECT_FALSE(openLesson(w, "no-such-lesson"));
    EXPECT_EQ(p->lesson().id, "building-kdtree");  // the open lesson is kept
}

// The voxel-size lesson's sweep runs behind its progress dialog and fills one row a resolution.
// At one cell per axis a primary ray tests at most the Cornell box's 30 primitives (fewer when
// it misses the grid's box).
TEST(App, TheVoxelSizeLessonsSweepFillsItsTable) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    ASSERT_TRUE(openLesson(w, "voxel-size"));
    QPushButton* run = nullptr;
    for (QPushButton* b : w.lessonPanel()->findChildren<QPushButton*>())
        if (b->text() == "Run the sweep") run = b;
    ASSERT_NE(run, nullptr);
    ASSERT_TRUE(run->isVisible());
    run->click();
    ASSERT_TRUE(w.waitUntilIdle());
    QTableWidget* table = w.lessonPanel()->findChild<QTableWidget*>();
    ASSERT_NE(table, nullptr);
    ASSERT_EQ(table->rowCount(),
              static_cast<int>(w.lessonPanel()->lesson().sweep->resolutions.size()));
    EXPECT_EQ(table->item(0, 0)->text(), "1");
    EXPECT_EQ(table->item(0, 4)->text(), "1");  // one cell
    EXPECT_LE(table->item(0, 1)->text().toDouble(), 30.0);
    // Finer grids: fewer tests per ray, more cells per ray.
    const int last = table->rowCount() - 1;
    EXPECT_LT(table->item(last, 1)->text().toDouble(), table->item(0, 1)->text().toDouble());
    EXPECT_GT(table->item(last, 2)->text().toDouble(), table->item(0, 2)->text().toDouble());
}

// The 3D DDA's inspector shows the third axis: Z, tMaxZ, tDeltaZ, stepZ, and where the ray
// enters the grid.
TEST(App, The3DDdaLessonShowsTheThirdAxis) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    ASSERT_TRUE(openLesson(w, "dda-3d"));
    putAwayAll(w.lessonPanel());   // its exercises (t_enter first) would stop the replay
    w.lessonPanel()->goToStep(1);  // after the first voxel
    const QString text = w.inspectorText();
    // The eye is outside the grid: t_enter = (2 - 5.2) / dz with dz = -0.79699 (by hand from the
    // camera, lesson 7's calculation), 4.01512.
    for (const char* part : {"   Z = ", "tMaxZ = ", "tDeltaZ = ", "stepZ = ", "t_enter = 4.01512"})
        EXPECT_TRUE(text.contains(part)) << part << "\n" << text.toStdString();
    w.tasks().cancel(TaskKind::Render);
}

TEST(App, EveryLessonOpensAndEveryStepShows) {
    MainWindow w;
    w.resize(1200, 800);
    w.show();
    for (const Lesson& l : builtinLessons()) {
        SCOPED_TRACE(l.id);
        ASSERT_TRUE(openLesson(w, QString::fromStdString(l.id)));
        // It opens on its first unsolved exercise, open, and every unsolved exercise holds the
        // replay: no step goes past the earliest of their positions.
        LessonPanel* p = w.lessonPanel();
        EXPECT_EQ(p->exerciseOpen(), !p->heldExercises().empty());
        std::optional<std::size_t> limit;
        for (const int e : p->heldExercises())
            if (const auto at = quizLimit(l.exercises[std::size_t(e)], w.session().log()))
                limit = limit ? std::min(*limit, *at) : *at;
        for (std::size_t i = 0; i < l.steps.size(); ++i) {
            p->goToStep(static_cast<int>(i));
            const std::size_t at = *resolvePosition(l.steps[i].at, w.session().log());
            EXPECT_EQ(w.session().cursor(), limit ? std::min(at, *limit) : at);
        }
        // All put away, every step shows its own position.
        putAwayAll(p);
        for (std::size_t i = 0; i < l.steps.size(); ++i) {
            p->goToStep(static_cast<int>(i));
            EXPECT_EQ(w.session().cursor(), *resolvePosition(l.steps[i].at, w.session().log()));
        }
        EXPECT_GT(colours(grab(&w)), 50u);
    }
    w.tasks().cancel(TaskKind::Render);  // the last lesson's image is not needed
}

// The runner on its own: results reach `done` on the GUI thread, errors and cancels are told
// apart, a newer task of a kind supersedes the older, and shutdown joins every thread at once
// and calls no `done` after it.
TEST(TaskRunner, HandsOverCancelsSupersedesAndJoins) {
    TaskRunner runner;
    const auto guiThread = std::this_thread::get_id();
    int value = 0;
    bool onGuiThread = false;
    ASSERT_TRUE(runner.start<int>(
        TaskKind::Render, "answer", [](const ProgressFn&) { return 42; },
        [&](int&& v, const TaskOutcome& o) {
            EXPECT_TRUE(o.ok());
            value = v;
            onGuiThread = std::this_thread::get_id() == guiThread;
        }));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !runner.busy(); }, 10000));
    EXPECT_EQ(value, 42);
    EXPECT_TRUE(onGuiThread);

    // An error is an error; BuildCancelled thrown by the work is a cancel.
    std::optional<TaskOutcome> failed, stopped;
    runner.start<int>(
        TaskKind::Scene, "fails",
        [](const ProgressFn&) -> int { throw SceneError("bad.json", 3, "camera", "bad"); },
        [&](int&&, const TaskOutcome& o) { failed = o; });
    runner.start<int>(
        TaskKind::Build, "stops", [](const ProgressFn&) -> int { throw BuildCancelled(); },
        [&](int&&, const TaskOutcome& o) { stopped = o; });
    ASSERT_TRUE(QTest::qWaitFor([&] { return !runner.busy(); }, 10000));
    ASSERT_TRUE(failed && stopped);
    EXPECT_TRUE(failed->error && !failed->cancelled);
    EXPECT_TRUE(stopped->cancelled && !stopped->error);

    // Work that runs until told to stop: a second task of its kind supersedes it.
    const auto untilStopped = [](const ProgressFn& progress) {
        while (progress(0.5)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return 1;
    };
    std::vector<std::string> ended;
    runner.start<int>(TaskKind::Sweep, "first", untilStopped, [&](int&&, const TaskOutcome& o) {
        ended.push_back(o.superseded ? "first superseded" : "first");
    });
    runner.start<int>(
        TaskKind::Sweep, "second", [](const ProgressFn&) { return 2; },
        [&](int&&, const TaskOutcome& o) {
            ended.push_back(o.ok() ? "second ok" : "second not ok");
        });
    ASSERT_TRUE(QTest::qWaitFor([&] { return !runner.busy(); }, 10000));
    std::sort(ended.begin(), ended.end());
    EXPECT_EQ(ended, (std::vector<std::string>{"first superseded", "second ok"}));

    // Shutdown: every thread joined before it returns, no `done` after, nothing new starts.
    bool called = false;
    auto alive = std::make_shared<int>(7);
    const std::weak_ptr<int> watch = alive;
    for (TaskKind k : {TaskKind::Render, TaskKind::Compare})
        runner.start<int>(
            k, "long",
            [alive, untilStopped](const ProgressFn& p) { return untilStopped(p) + *alive; },
            [&](int&&, const TaskOutcome&) { called = true; });
    alive.reset();
    EXPECT_EQ(runner.threads(), 2u);
    runner.shutdown();
    EXPECT_EQ(runner.threads(), 0u);
    EXPECT_TRUE(watch.expired());  // what the work held went with it
    EXPECT_FALSE(runner.start<int>(
        TaskKind::Render, "late", [](const ProgressFn&) { return 0; },
        [&](int&&, const TaskOutcome&) { called = true; }));
    QTest::qWait(100);
    EXPECT_FALSE(called);
}

// --- Issue 15: nothing a user does crashes the app or grades against the wrong trace. ---

/// What a student types for an exercise's right answer (the reference is read from a trace the
/// core records on its own, not from the window's).
QString typedAnswer(const Exercise& ex, const Answer& ref) {
    if (ex.kind == ExerciseKind::PickSplit)
        return QStringLiteral("%1=%2")
            .arg(QChar("xyz"[int(ref.numbers[0])]))
            .arg(ref.numbers[1], 0, 'g', 17);
    return QString::fromStdString(formatAnswer(ex, ref));
}

/// A real left click at a widget point.
void click(QWidget* w, QPoint at) {
    QTest::mouseClick(w, Qt::LeftButton, Qt::NoModifier, at);
}

// The answer box has the keyboard most of the time in a lesson: a click on a view must take it,
// or B, R and N typed after it go into the answer instead.
TEST(App, ClickingAViewTakesTheKeysFromTheAnswerBox) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    ASSERT_TRUE(openLesson(w, "3"));
    w.setLessonMode(LessonMode::Presenting);  // B is refused while an exercise holds (quiz mode)
    auto* answer = w.lessonPanel()->findChild<QLineEdit*>("answer");
    ASSERT_NE(answer, nullptr);
    for (QWidget* view :
         {static_cast<QWidget*>(w.view3D()), static_cast<QWidget*>(w.imageView())}) {
        SCOPED_TRACE(view->metaObject()->className());
        // Back from what the last round explored, with the first exercise open.
        QTest::keyClick(&w, Qt::Key_Escape);
        w.lessonPanel()->selectExercise(0);
        answer->setFocus();
        answer->clear();
        QApplication::processEvents();
        // The window's own focus child: it does not depend on the window manager activating us.
        ASSERT_EQ(w.focusWidget(), answer);
        ASSERT_TRUE(view->isVisible());
        click(view, QPoint(view->width() / 3, view->height() / 2));
        ASSERT_EQ(w.focusWidget(), view);
        QTest::keyClick(w.focusWidget(), Qt::Key_B);
        EXPECT_TRUE(w.waitUntilIdle());
        EXPECT_EQ(w.session().logKind(), LogKind::Build);
        EXPECT_TRUE(answer->text().isEmpty()) << answer->text().toStdString();
    }
}

// Every lesson with exercises: explore something else first, as a student does (click a pixel
// of the image; R, the example ray; B, the build). While exploring, the steps and exercises wait
// (disabled, with a note saying why; an answer is not graded against the explored trace); one
// action, Esc (Back to the lesson), returns to the lesson's own trace, where every exercise is
// graded right against it.
TEST(AppLifetimes, ExploringDisablesTheExercisesAndEscReturnsToTheLesson) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    // Presenting: in quiz mode a held exercise refuses the three (quiz_test.cpp).
    w.setLessonMode(LessonMode::Presenting);
    int rounds[3] = {0, 0, 0};  // pixel clicks, R, B: each path taken in some lesson
    for (const Lesson& l : builtinLessons()) {
        if (l.exercises.empty()) continue;
        SCOPED_TRACE(l.id);
        ASSERT_TRUE(openLesson(w, QString::fromStdString(l.id)));
        LessonPanel* p = w.lessonPanel();
        const LessonRun run = runLesson(p->lesson());
        const LogRef lessonLog = p->lessonLog();
        // The step the progress was at may be on a structure of its own (lesson 10's BVH).
        ASSERT_TRUE(p->isLessonLog(w.session().logRef()));
        auto* body = p->findChild<QWidget*>("exerciseBox");
        auto* back = p->findChild<QPushButton*>("backToLesson");
        ASSERT_TRUE(body && back);
        // Something else in the replay: the lesson's trace is no longer the session's.
        const auto interactions = [&](int i) {
            if (i == 0 && !w.session().is2D() && w.imageView()->isVisible()) {
                QApplication::processEvents();
                ImageView* image = w.imageView();
                click(image, QPoint(image->width() / 3, image->height() / 2));
                return w.session().logKind() == LogKind::Pixel;
            }
            if (i == 1 && w.session().is2D()) {
                QTest::keyClick(&w, Qt::Key_R);
                return w.session().logKind() == LogKind::ExampleRay;
            }
            if (i == 2 && Session::hasBuild(w.session().kind())) {
                const bool lessonIsBuild = p->lesson().trace.kind == LessonTrace::Kind::Build;
                QTest::keyClick(&w, Qt::Key_B);
                EXPECT_TRUE(w.waitUntilIdle());
                return !lessonIsBuild && w.session().logKind() == LogKind::Build;
            }
            return false;
        };
        for (int i = 0; i < 3; ++i) {
            p->selectExercise(0);
            if (!interactions(i)) continue;
            SCOPED_TRACE(i);
            ++rounds[i];
            EXPECT_NE(w.session().logRef(), lessonLog);
            EXPECT_TRUE(p->exploring());
            EXPECT_FALSE(p->replayNote().isEmpty());  // the panel says the replay is elsewhere
            EXPECT_TRUE(back->isVisible());
            // The exercises wait, saying why; their answers are not graded meanwhile.
            auto* openButton = p->findChild<QPushButton*>("openExercise");
            ASSERT_NE(openButton, nullptr);
            EXPECT_FALSE(openButton->isEnabled());
            EXPECT_TRUE(p->findChild<QLabel*>("exploreNote")->isVisible());
            EXPECT_FALSE(p->submit("1"));
            EXPECT_TRUE(p->feedback().contains("lesson's own trace"))
                << p->feedback().toStdString();
            // One key back: the lesson's trace, its exercises enabled again.
            QTest::keyClick(&w, Qt::Key_Escape);
            EXPECT_EQ(w.session().logRef(), lessonLog);
            EXPECT_FALSE(p->exploring());
            EXPECT_TRUE(p->replayNote().isEmpty());
            EXPECT_TRUE(openButton->isEnabled());
            for (std::size_t e = 0; e < l.exercises.size(); ++e) {
                const Exercise& ex = p->lesson().exercises[e];
                // Graded from the sweep's table, which takes its own run (lesson_gui_test.cpp).
                if (ex.kind == ExerciseKind::SweepPick) continue;
                p->selectExercise(static_cast<int>(e));
                // From the exercise's own structure's trace (lesson 10's BVH, grid, SAH kd-tree).
                const Answer ref = referenceAnswer(ex, run.logs().of(ex.setup), p->lesson().file);
                EXPECT_TRUE(p->submit(typedAnswer(ex, ref)))
                    << ex.id << ": " << p->feedback().toStdString();
            }
        }
    }
    EXPECT_GE(rounds[0], 4);  // lessons 1, 2, 3, 4, 5, 9, 12 show the image
    EXPECT_GE(rounds[1], 3);  // 6, 8, 10, 11, 13 are 2D
    EXPECT_GE(rounds[2], 1);  // a tree whose build is not the lesson's trace
    w.close();
}

// A scene whose render takes minutes (the stadium, brute force): Ctrl+Q while it renders stops
// and joins the render thread before the window's scene and structure are destroyed.
TEST(AppLifetimes, QuittingDuringALongRenderJoinsEveryWorker) {
    for (int round = 0; round < 2; ++round) {
        auto w = std::make_unique<MainWindow>();
        w->resize(1500, 900);
        w->show();
        w->activateWindow();
        ASSERT_TRUE(QTest::qWaitForWindowActive(w.get()));
        w->openScene("stadium", AccelKind::BruteForce, true);
        ASSERT_TRUE(QTest::qWaitFor([&] { return w->lastOpenOk().has_value(); }, 60000));
        ASSERT_TRUE(*w->lastOpenOk());
        ASSERT_TRUE(w->tasks().busy(TaskKind::Render));
        QTest::qWait(round * 300);  // at once, and once well under way
        const std::weak_ptr<const LoadedScene> scene = w->session().sceneRef();
        QTest::keyClick(w.get(), Qt::Key_Q, Qt::ControlModifier);
        EXPECT_FALSE(w->isVisible());
        EXPECT_TRUE(w->tasks().isShutDown());
        EXPECT_EQ(w->tasks().threads(), 0u);  // joined, not detached
        // Nothing starts after close.
        w->renderImage();
        w->openLesson("6", true);
        EXPECT_FALSE(w->tasks().busy());
        w.reset();
        EXPECT_TRUE(scene.expired());  // no worker kept a share of it
    }
}

// Lessons picked in quick succession from the picker (real key presses), then Ctrl+Q at once:
// every superseded open is cancelled and joined, and nothing runs after close. Without the
// quit, the last lesson picked is the one shown and no "cancelled" is reported.
TEST(AppLifetimes, SwitchingLessonsQuicklyThenQuittingIsClean) {
    for (bool quit : {true, false}) {
        SCOPED_TRACE(quit);
        auto w = std::make_unique<MainWindow>();
        w->resize(1500, 900);
        w->show();
        w->activateWindow();
        ASSERT_TRUE(QTest::qWaitForWindowActive(w.get()));
        QComboBox* picker = w->lessonPanel()->findChild<QComboBox*>("lessonPicker");
        ASSERT_NE(picker, nullptr);
        picker->setFocus();
        QApplication::processEvents();
        for (int i = 0; i < 13; ++i) {
            QTest::keyClick(picker, Qt::Key_Down);
            QTest::qWait(30);
        }
        if (quit) {
            QTest::keyClick(w.get(), Qt::Key_Q, Qt::ControlModifier);
            EXPECT_EQ(w->tasks().threads(), 0u);
            w.reset();
            continue;
        }
        ASSERT_TRUE(w->waitUntilIdle());
        ASSERT_TRUE(w->lastOpenOk().value_or(false)) << w->lastOpenError().toStdString();
        EXPECT_EQ(w->lessonPanel()->lesson().number, 13);
        EXPECT_EQ(w->session().logRef(), w->lessonPanel()->lessonLog());
        EXPECT_FALSE(w->statusBar()->currentMessage().contains("cancelled"))
            << w->statusBar()->currentMessage().toStdString();
    }
}

// Cancel during a render: the image view says the render was cancelled (not "Rendering..."),
// pixels can still be clicked and traced, and "Render the image again" starts it again.
TEST(AppLifetimes, ACancelledRenderSaysSoAndOffersToRenderAgain) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    w.openScene("stadium", AccelKind::BruteForce, true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return w.lastOpenOk().has_value(); }, 60000));
    ImageView* image = w.imageView();
    ASSERT_EQ(image->state(), ImageView::State::Rendering);
    auto* cancel = w.findChild<QPushButton*>("cancelTask");
    ASSERT_NE(cancel, nullptr);
    ASSERT_TRUE(QTest::qWaitFor([&] { return cancel->isVisible(); }, 5000));
    click(cancel, cancel->rect().center());
    ASSERT_TRUE(w.waitUntilIdle(60000));
    EXPECT_EQ(image->state(), ImageView::State::Cancelled);
    EXPECT_TRUE(image->message().contains("cancelled")) << image->message().toStdString();
    EXPECT_FALSE(image->message().contains("Rendering"));
    EXPECT_TRUE(w.statusBar()->currentMessage().contains("cancelled"));
    // A pixel is still traced and replayed.
    const LogRef before = w.session().logRef();
    click(image, QPoint(image->width() / 2, image->height() / 2));
    EXPECT_NE(w.session().logRef(), before);
    EXPECT_EQ(w.session().logKind(), LogKind::Pixel);
    EXPECT_GT(w.session().size(), 5u);
    // Rendering again, offered on the view.
    QPushButton* again = image->renderButton();
    ASSERT_TRUE(again->isVisible());
    click(again, again->rect().center());
    EXPECT_EQ(image->state(), ImageView::State::Rendering);
    EXPECT_TRUE(w.tasks().busy(TaskKind::Render));
    w.close();
}

// A scene that cannot be opened, with nothing open before (a bad --scene at start-up): the
// window says why and where to go, not "Rendering..." forever.
TEST(AppLifetimes, ABadSceneWithNothingOpenSaysSo) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    EXPECT_FALSE(open(w, "no-such-scene", AccelKind::Grid));
    EXPECT_FALSE(w.lastOpenError().isEmpty());
    EXPECT_FALSE(w.session().hasScene());
    EXPECT_EQ(w.imageView()->state(), ImageView::State::NoScene);
    EXPECT_FALSE(w.imageView()->message().contains("Rendering"));
    auto* text = w.lessonPanel()->findChild<QTextBrowser*>("lessonText");
    ASSERT_NE(text, nullptr);
    EXPECT_TRUE(text->toPlainText().contains("could not be opened"))
        << text->toPlainText().toStdString();
    // Every key a user may press there is harmless.
    for (Qt::Key k : {Qt::Key_B, Qt::Key_R, Qt::Key_N, Qt::Key_C, Qt::Key_End, Qt::Key_Right})
        QTest::keyClick(&w, k);
    EXPECT_TRUE(w.waitUntilIdle());
    EXPECT_FALSE(w.session().hasScene());
}

// Two windows of the app open at once (a student's two sessions): each saves its answers, and
// neither loses the other's.
TEST(AppLifetimes, TwoWindowsSavingProgressLoseNoAnswer) {
    QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                  "/progress.json");
    MainWindow a, b;
    ASSERT_TRUE(openLesson(a, "6"));
    ASSERT_TRUE(openLesson(b, "6"));
    a.lessonPanel()->selectExercise(0);
    EXPECT_TRUE(a.lessonPanel()->submit("2.5"));  // tDeltaY = 1 / 0.4
    putAwayAll(b.lessonPanel());  // exercise 4's prompt waits for the ones before it
    b.lessonPanel()->selectExercise(3);
    EXPECT_FALSE(b.lessonPanel()->submit("2,2"));  // the next cell is (3, 1)
    a.lessonPanel()->goToStep(1);                  // a saves again after b
    QFile f(a.progressPath());
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const Progress saved = parseProgress(f.readAll().toStdString(), "progress.json");
    const auto& ex = saved.lessons.at("grid-2d-dda").exercises;
    ASSERT_TRUE(ex.count("tdelta-y") && ex.count("next-cell"));
    EXPECT_TRUE(ex.at("tdelta-y").correct);
    EXPECT_EQ(ex.at("next-cell").answer, "2,2");
    EXPECT_EQ(saved.lessons.at("grid-2d-dda").step, 1);
}

int run(const std::string& args) {
    const int status = std::system((std::string("'" RAYSTEP_APP "' ") + args).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(App, ScreenshotOptionWritesTheWindow) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("raystep-gui-" + std::to_string(getpid()));
    fs::create_directories(dir);
    // The app saves progress as it runs: into the test's folder, not the user's.
    setenv("XDG_DATA_HOME", dir.c_str(), 1);
    const fs::path a = dir / "a.png", b = dir / "b.png";
    ASSERT_EQ(
        run("--scene lecture-grid --step 3 --screenshot '" + a.string() + "' >/dev/null 2>&1"), 0);
    ASSERT_EQ(
        run("--scene lecture-grid --step 12 --screenshot '" + b.string() + "' >/dev/null 2>&1"), 0);
    const QImage ia(QString::fromStdString(a.string())), ib(QString::fromStdString(b.string()));
    ASSERT_FALSE(ia.isNull());
    EXPECT_EQ(ia.size(), QSize(1500, 900));
    EXPECT_GT(colours(ia), 50u);
    EXPECT_NE(ia, ib);  // --step put the cursor elsewhere
    // With no option the app opens on lesson 1.
    const fs::path first = dir / "first.png", said = dir / "said.txt";
    ASSERT_EQ(run("--screenshot '" + first.string() + "' > '" + said.string() + "' 2>/dev/null"),
              0);
    std::ifstream in(said);
    const std::string line((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(line.find("lesson 1: Rasterization and ray tracing"), std::string::npos) << line;
    EXPECT_GT(colours(QImage(QString::fromStdString(first.string()))), 50u);
    // In Italian (--lang it): a different picture of the same replay.
    const fs::path it = dir / "it.png";
    ASSERT_EQ(run("--scene lecture-grid --step 3 --lang it --screenshot '" + it.string() +
                  "' >/dev/null 2>&1"),
              0);
    EXPECT_NE(QImage(QString::fromStdString(it.string())), ia);
    // Bad values: exit 2, no file.
    const fs::path c = dir / "c.png";
    EXPECT_EQ(run("--accel octree --screenshot '" + c.string() + "' 2>/dev/null"), 2);
    EXPECT_EQ(run("--step 99999 --screenshot '" + c.string() + "' 2>/dev/null"), 2);
    EXPECT_EQ(run("--scene nosuch --screenshot '" + c.string() + "' 2>/dev/null"), 2);
    EXPECT_EQ(run("--screenshot '" + (dir / "c.jpg").string() + "' 2>/dev/null"), 2);
    EXPECT_EQ(run("--lang fr --screenshot '" + c.string() + "' 2>/dev/null"), 2);
    EXPECT_EQ(run("--lesson 99 --screenshot '" + c.string() + "' 2>/dev/null"), 2);
    EXPECT_EQ(run("--lesson 6 --scene default --screenshot '" + c.string() + "' 2>/dev/null"), 2);
    EXPECT_FALSE(fs::exists(c));
    // A FIFO as the screenshot: refused in one line, not opened and waited on (it hung); a
    // folder that does not exist: the same, and nothing written.
    const fs::path fifo = dir / "pipe.png", err = dir / "err.txt";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    const int status =
        std::system(("timeout 60 '" RAYSTEP_APP "' --scene lecture-grid --screenshot '" +
                     fifo.string() + "' 2>'" + err.string() + "' </dev/null")
                        .c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2);  // 124: it hung on the FIFO
    std::ifstream errIn(err);
    const std::string message((std::istreambuf_iterator<char>(errIn)),
                              std::istreambuf_iterator<char>());
    // One error line naming the file (Qt may add its own warnings on other lines).
    const std::size_t at = message.find("raystep: error: --screenshot ");
    ASSERT_NE(at, std::string::npos) << message;
    const std::string errLine = message.substr(at, message.find('\n', at) - at);
    EXPECT_NE(errLine.find("pipe.png: cannot write: is not a regular file"), std::string::npos)
        << message;
    EXPECT_EQ(message.find("raystep: error:", at + 1), std::string::npos) << message;
    EXPECT_TRUE(fs::is_fifo(fifo));
    EXPECT_EQ(run("--scene lecture-grid --screenshot '" + (dir / "no" / "x.png").string() +
                  "' 2>/dev/null"),
              2);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace raystep::gui

namespace {
/// Every test starts from the settings a new user has: a window layout, a zoom, a compare
/// choice or a lesson mode saved by the test before must not change what this one measures
/// (the board's selection failed after a presenting test, but only in that order).
class FreshSettings : public ::testing::EmptyTestEventListener {
    void OnTestStart(const ::testing::TestInfo&) override {
        QSettings settings;
        settings.clear();
        settings.sync();
    }
};
}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("raystep-tests");  // keep the user's settings apart
    QStandardPaths::setTestModeEnabled(true);            // and the user's progress
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::UnitTest::GetInstance()->listeners().Append(new FreshSettings);
    return RUN_ALL_TESTS();
}
