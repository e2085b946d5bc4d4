// Issue 17 in the app, driven with real mouse and key events under Xvfb: quiz mode (an open
// exercise stops the replay at its position), exploring and the one way back to the lesson, the
// lesson's pixel marked on the image, the slides' errata and the hints, the event filter, N
// following the lesson, and the colours of the one palette.
#include "event_list.h"
#include "gui_testing.h"
#include "image_view.h"
#include "lesson_panel.h"
#include "main_window.h"
#include "timeline.h"
#include "view2d.h"
#include "vtk_view.h"

#include "course/lesson_trace.h"
#include "course/palette.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextList>

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

QImage grab(QWidget* w) {
    QApplication::processEvents();
    return w->grab().toImage();
}

/// The index of the `nth` (1-based) event of kind E in the log, counted here by hand.
template <typename E>
std::size_t indexOfNth(const EventLog& log, int nth) {
    int seen = 0;
    for (std::size_t i = 0; i < log.events().size(); ++i)
        if (std::holds_alternative<E>(log.events()[i]) && ++seen == nth) return i;
    ADD_FAILURE() << "no such event";
    return 0;
}

/// Pixels of `image` within `tolerance` of colour (r, g, b) in every channel.
int pixelsNear(const QImage& image, int r, int g, int b, int tolerance = 6) {
    const QImage i = image.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    for (int y = 0; y < i.height(); ++y)
        for (int x = 0; x < i.width(); ++x) {
            const QRgb p = i.pixel(x, y);
            n += std::abs(qRed(p) - r) <= tolerance && std::abs(qGreen(p) - g) <= tolerance &&
                 std::abs(qBlue(p) - b) <= tolerance;
        }
    return n;
}

/// Writes a lesson file in `dir` (lessons of the test's own, so that the content helpers'
/// edits of the built-in lessons do not change what these tests check).

/// The slides' 2D example: the lecture grid (unit cells) and the ray o = (0.4, 0.4),
/// d = (1, 0.75), with mailboxing; a first step at the start, a last one at the end; two
/// exercises: tMaxX after the step to (1, 0), before the 2nd dda_cell, and the cell after
/// (2, 1), before the 5th.
const QByteArray kQuizLesson = R"({
"format": "raystep-lesson", "version": 1, "id": "quiz", "number": 96,
"title": {"en": "Quiz"}, "text": {"en": "The slides' grid."},
"scene": "lecture-grid", "setup": {"accel": "grid", "mailbox": true}, "views": ["2d"],
"trace": {"ray": [0.4, 0.4, 1, 0.75]},
"steps": [{"at": {"after": "dda_setup", "nth": 1}, "text": {"en": "The set-up."}},
          {"at": {"after": "dda_cell", "nth": 1}, "text": {"en": "The first cell."}, "filter": "dda_cell"},
          {"at": "end", "text": {"en": "The end."}}],
"exercises": [
 {"id": "tmax", "type": "value", "quantity": "tMax.x", "at": {"before": "dda_cell", "nth": 2},
  "prompt": {"en": "The DDA steps in X to (1, 0): tMaxX after the step?"},
  "hint": [{"en": "A nudge: what grows by tDeltaX?"}, {"en": "The formula: tMaxX + tDeltaX."},
           {"en": "The first step: tDeltaX = 1 / |dx|."}]},
 {"id": "next", "type": "next_cell", "at": {"before": "dda_cell", "nth": 5},
  "prompt": {"en": "The ray is in (2, 1): which cell comes next?"}}
]})";

// The quiz lesson's second exercise asks for the cell after (2, 1): its position is just before
// the 5th dda_cell event, which holds the answer. Opened with the mouse, it stops the timeline's
// buttons, the keys (Right, End, N, Space), the scrubber and the event list at that position;
// the event list has no row past it, the inspector counts only up to it, and the timeline says
// why.
TEST(Quiz, AnOpenExerciseStopsEveryWayOfMovingTheReplay) {
    QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                  "/progress.json");
    QTemporaryDir dir;
    ShownWindow win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openLesson(w, writeLesson(dir, "quiz.json", kQuizLesson)))
        << w.lastOpenError().toStdString();
    LessonPanel* p = w.lessonPanel();
    Session& s = w.session();
    const std::size_t limit = indexOfNth<DdaCell>(s.log(), 5);
    ASSERT_LT(limit + 3, s.size());  // there is something past it to hide

    // The lesson opens on its first exercise, open: End stops at its position (before the
    // second cell). Put away, it stops nothing, but the second exercise, unsolved, still holds
    // the replay at its own position, open or not; with both put away End goes to the end.
    ASSERT_TRUE(p->exerciseOpen());
    ASSERT_EQ(p->exercise(), 0);
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), indexOfNth<DdaCell>(s.log(), 2));
    p->closeExercise();
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), limit);
    EXPECT_FALSE(w.timeline()->quizCue().isEmpty());
    p->selectExercise(1);
    p->closeExercise();
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), s.size());
    EXPECT_TRUE(w.timeline()->quizCue().isEmpty());
    s.setCursor(0);

    // Open the second exercise with the ">" button (it opens the one it shows).
    QPushButton* next = nullptr;
    for (QPushButton* b : p->findChildren<QPushButton*>())
        if (b->text() == ">") next = b;
    ASSERT_NE(next, nullptr);
    QTest::mouseClick(next, Qt::LeftButton);
    ASSERT_EQ(p->exercise(), 1);
    ASSERT_TRUE(p->exerciseOpen());
    EXPECT_EQ(s.cursor(), limit);
    EXPECT_EQ(w.timeline()->quizCue(), "Answer the exercise to see what comes next");

    // Keys: Right at the limit, End, N (the kind combo is on DDA steps), Space (play).
    QTest::keyClick(&w, Qt::Key_Right);
    EXPECT_EQ(s.cursor(), limit);
    QTest::keyClick(&w, Qt::Key_Home);
    EXPECT_EQ(s.cursor(), 0u);
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), limit);
    s.setCursor(limit - 1);
    QTest::keyClick(&w, Qt::Key_N);
    QTest::keyClick(&w, Qt::Key_N);
    EXPECT_EQ(s.cursor(), limit);
    s.setCursor(limit - 2);
    w.timeline()->findChild<QSpinBox*>()->setValue(100);
    QTest::keyClick(&w, Qt::Key_Space);
    QTest::qWait(600);  // 60 events' worth of playing
    EXPECT_EQ(s.cursor(), limit);
    // The scrubber ends at the limit: its End key (and a drag to its end) stops there.
    auto* scrubber = w.timeline()->findChild<QSlider*>();
    ASSERT_NE(scrubber, nullptr);
    EXPECT_EQ(scrubber->maximum(), static_cast<int>(limit));
    QTest::mouseClick(scrubber, Qt::LeftButton, {},
                      QPoint(scrubber->width() - 2, scrubber->height() / 2));
    EXPECT_LE(s.cursor(), limit);

    // The event list: exactly the events before the limit, the last one highlighted.
    EventList* list = w.eventList();
    list->setFilter({});
    EXPECT_EQ(list->rowCount(), static_cast<int>(limit));
    EXPECT_TRUE(list->rowText(list->rowCount() - 1).startsWith(QString::number(limit) + "  "));
    s.setCursor(limit);
    EXPECT_EQ(list->currentRow(), static_cast<int>(limit) - 1);
    // The inspector counts the events it may show.
    EXPECT_TRUE(w.inspectorText().contains(QStringLiteral("step %1 of %1").arg(limit)))
        << w.inspectorText().toStdString();
    // Compare mode (C) would replay whole traces: refused while the exercise is open.
    QTest::keyClick(&w, Qt::Key_C);
    EXPECT_TRUE(w.waitUntilIdle());
    EXPECT_EQ(w.compareWindow(), nullptr);
    EXPECT_TRUE(w.statusBar()->currentMessage().contains("answer the exercise first"))
        << w.statusBar()->currentMessage().toStdString();
    // The 2D view at the limit is the picture of the limit, whatever the keys asked.
    const QImage atLimit = grab(w.view2D());
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(grab(w.view2D()), atLimit);

    // Answered right (clicking the cell, as a student does): the limit lifts.
    QTest::mouseClick(w.view2D(), Qt::LeftButton, {}, w.view2D()->cellCentre(2, 2).toPoint());
    ASSERT_TRUE(p->feedback().startsWith("Right.")) << p->feedback().toStdString();
    EXPECT_TRUE(w.timeline()->quizCue().isEmpty());
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), s.size());
    EXPECT_EQ(list->rowCount(), static_cast<int>(s.size()));
    EXPECT_NE(grab(w.view2D()), atLimit);  // the rest of the walk is drawn
}

// The first exercise (tMaxX after the step from (0, 0) to (1, 0)) sits before the 2nd
// dda_cell: lecturer mode (Ctrl+L) lifts its limit, and turning it off puts it back; putting
// the exercise away lifts it too.
TEST(Quiz, LecturerModeAndPuttingTheExerciseAwayLiftTheLimit) {
    QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                  "/progress.json");
    QTemporaryDir dir;
    ShownWindow win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openLesson(w, writeLesson(dir, "quiz.json", kQuizLesson)));
    LessonPanel* p = w.lessonPanel();
    Session& s = w.session();
    const std::size_t limit = indexOfNth<DdaCell>(s.log(), 2);
    p->selectExercise(0);
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), limit);
    // The event holding the answer (tMaxX after the step) is not in the list.
    EXPECT_EQ(w.eventList()->rowCount(), static_cast<int>(limit));

    QTest::keyClick(&w, Qt::Key_L, Qt::ControlModifier);
    ASSERT_TRUE(p->lecturerMode());
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), s.size());
    QTest::keyClick(&w, Qt::Key_L, Qt::ControlModifier);
    EXPECT_EQ(s.cursor(), limit);  // back at the exercise
    EXPECT_FALSE(w.timeline()->quizCue().isEmpty());

    auto* putAway = p->findChild<QPushButton*>("openExercise");
    ASSERT_NE(putAway, nullptr);
    QTest::mouseClick(putAway, Qt::LeftButton);
    EXPECT_FALSE(p->exerciseOpen());
    // The second exercise, unsolved, holds the replay at its position (before the 5th cell).
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), indexOfNth<DdaCell>(s.log(), 5));
    // A step past the exercise, with the exercise open again, stops at the exercise.
    p->selectExercise(0);
    p->goToStep(static_cast<int>(p->lesson().steps.size()) - 1);  // the last step: the end
    EXPECT_EQ(s.cursor(), limit);
}

// A step past an unsolved exercise's position waits with the replay: its text (which may name
// what the exercise asks) is replaced by a note until the exercise is answered or put away.
// Page Up/Down step wherever the focus is: at the last step, with the lesson picker focused,
// Page Down does nothing (it used to reach the picker and open the next lesson).
TEST(Quiz, AStepPastAnUnsolvedExerciseWaitsAndPageDownNeverLeavesTheLesson) {
    QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                  "/progress.json");
    QTemporaryDir dir;
    ShownWindow win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openLesson(w, writeLesson(dir, "quiz.json", kQuizLesson)));
    LessonPanel* p = w.lessonPanel();
    auto* text = p->findChild<QTextBrowser*>("lessonText");
    ASSERT_NE(text, nullptr);
    p->goToStep(2);  // "end": past the first exercise (before the 2nd cell)
    EXPECT_FALSE(text->toPlainText().contains("The end."));
    EXPECT_TRUE(text->toPlainText().contains("This step comes after exercise 1"))
        << text->toPlainText().toStdString();
    p->goToStep(1);  // after the 1st cell: before the exercise's position, readable
    EXPECT_TRUE(text->toPlainText().contains("The first cell."));
    putAwayAll(p);
    p->goToStep(2);
    EXPECT_TRUE(text->toPlainText().contains("The end."));

    auto* picker = p->findChild<QComboBox*>("lessonPicker");
    ASSERT_NE(picker, nullptr);
    picker->setFocus();
    QTest::keyClick(picker, Qt::Key_PageDown);
    QTest::keyClick(picker, Qt::Key_PageDown);
    EXPECT_EQ(p->lesson().id, "quiz");
    EXPECT_EQ(p->step(), 2);
    QTest::keyClick(picker, Qt::Key_PageUp);
    EXPECT_EQ(p->lesson().id, "quiz");
    EXPECT_EQ(p->step(), 1);
}

// A pixel lesson of the test's own: pixel (200, 150) of a 320 x 240 image of the whitted
// scene, a step whose filter shows the primitive tests, and an exercise before the first test.
const QByteArray kPixelLesson = R"({
"format": "raystep-lesson", "version": 1, "id": "pixel", "number": 95,
"title": {"en": "Pixel"}, "text": {"en": "A pixel's ray tree."},
"scene": "whitted", "setup": {"accel": "grid"}, "views": ["3d", "image"],
"trace": {"pixel": [200, 150], "image": [320, 240]},
"steps": [{"at": {"after": "ray_begin", "nth": 1}, "text": {"en": "The primary ray."},
           "filter": "primitive_test"},
          {"at": "end", "text": {"en": "The end."}}],
"exercises": [{"id": "first", "type": "hit_or_miss", "at": {"before": "primitive_test", "nth": 1},
               "prompt": {"en": "Does the primary ray's first test hit?"}}]
})";

// The lesson's pixel: a ring and cross-hair in yellow (255, 235, 60) where the image view draws
// that pixel. In quiz mode a click while the exercise holds the replay is refused (quiz_test.cpp);
// presenting, a click elsewhere explores that pixel: the steps and exercises wait, the open
// exercise's prompt is put aside, the event list shows every event; Esc comes back to the
// lesson's trace, exercise and filter.
TEST(Explore, TheLessonsPixelIsMarkedAndEscReturnsFromAPixelClick) {
    QTemporaryDir dir;
    ShownWindow win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openLesson(w, writeLesson(dir, "pixel.json", kPixelLesson)))
        << w.lastOpenError().toStdString();
    ASSERT_TRUE(w.waitUntilIdle());
    ImageView* image = w.imageView();
    ASSERT_EQ(image->state(), ImageView::State::Done);
    // Where pixel (200, 150) is drawn, by hand: the 320 x 240 image scaled to fit, centred.
    const double scale = std::min(image->width() / 320.0, image->height() / 240.0);
    const QPointF centre((image->width() - 320 * scale) / 2 + 200.5 * scale,
                         (image->height() - 240 * scale) / 2 + 150.5 * scale);
    EXPECT_NEAR(image->lessonMarkCentre().x(), centre.x(), 0.5);
    EXPECT_NEAR(image->lessonMarkCentre().y(), centre.y(), 0.5);
    const QImage shot = grab(image);
    // The ring (radius 11) crosses the horizontal through the centre: yellow there.
    const QColor ring = shot.pixelColor(QPoint(int(centre.x() + 11), int(centre.y())));
    EXPECT_GT(ring.red(), 200);
    EXPECT_GT(ring.green(), 190);
    EXPECT_LT(ring.blue(), 120);
    EXPECT_GT(pixelsNear(shot, 255, 235, 60, 10), 60);  // a mark, not a dot

    LessonPanel* p = w.lessonPanel();
    const LogRef lessonLog = p->lessonLog();
    w.setLessonMode(LessonMode::Presenting);  // nothing holds the replay
    p->selectExercise(0);
    auto* prompt = p->findChild<QLabel*>("prompt");
    ASSERT_NE(prompt, nullptr);
    EXPECT_TRUE(prompt->isVisible());
    QTest::keyClick(&w, Qt::Key_Escape);  // not exploring: Esc changes nothing
    EXPECT_EQ(w.session().logRef(), lessonLog);
    p->goToStep(0);
    EXPECT_EQ(w.eventList()->filter(), "primitive_test");
    EXPECT_EQ(w.eventList()->filterShown(), "primitive test");  // the interface's words
    // The rows are the kind's, as the lesson's validation counted them (by its trace name).
    const auto events = w.session().shownEvents();
    const auto tests = std::count_if(events.begin(), events.end(), [](const Event& e) {
        return std::holds_alternative<PrimitiveTest>(e);
    });
    EXPECT_EQ(w.eventList()->rowCount(), tests);
    const std::size_t exerciseAt = indexOfNth<PrimitiveTest>(*lessonLog, 1);
    EXPECT_EQ(w.session().cursor(), 1u);  // after the first event, the primary's ray_begin
    ASSERT_GT(exerciseAt, 1u);
    QTest::mouseClick(image, Qt::LeftButton, {}, QPoint(image->width() / 4, image->height() / 3));
    EXPECT_EQ(w.session().logKind(), LogKind::Pixel);
    EXPECT_TRUE(p->exploring());
    EXPECT_TRUE(w.backToLessonAction()->isEnabled());
    // The open exercise's prompt is put aside while exploring (the explored trace may hold
    // its answer).
    EXPECT_FALSE(prompt->isVisible());
    // The step's filter is about the lesson's trace: the explored one shows every event.
    EXPECT_TRUE(w.eventList()->filter().isEmpty());
    EXPECT_EQ(w.eventList()->rowCount(), static_cast<int>(w.session().size()));
    // The steps wait as the exercises do.
    for (QPushButton* b : p->findChildren<QPushButton*>()) {
        if (b->text() == "< Step" || b->text() == "Step >") {
            EXPECT_FALSE(b->isEnabled());
        }
    }
    QTest::keyClick(&w, Qt::Key_Escape);
    EXPECT_EQ(w.session().logRef(), lessonLog);
    EXPECT_EQ(w.session().cursor(), exerciseAt);
    EXPECT_EQ(p->step(), 0);
    EXPECT_TRUE(prompt->isVisible());
    EXPECT_EQ(w.eventList()->filter(), "primitive_test");
    EXPECT_FALSE(p->exploring());
    EXPECT_FALSE(w.backToLessonAction()->isEnabled());
    w.tasks().cancel(TaskKind::Render);
}

/// The quiz lesson with the slides' errata (lesson and its first step).
QString lessonWithErrata(const QTemporaryDir& dir) {
    QJsonObject lesson = QJsonDocument::fromJson(kQuizLesson).object();
    lesson["id"] = "errata-test";
    const auto erratum = [](const char* slide, const char* correct, const char* why) {
        return QJsonObject{{"slide", QJsonObject{{"en", slide}}},
                           {"correct", QJsonObject{{"en", correct}}},
                           {"why", QJsonObject{{"en", why}}}};
    };
    lesson["errata"] = QJsonArray{erratum("tDeltaX = dx / cellWidth", "tDeltaX = cellWidth / |dx|",
                                          "The slide divides the wrong way round.")};
    QJsonArray steps = lesson["steps"].toArray();
    QJsonObject first = steps[0].toObject();
    first["errata"] = QJsonArray{
        erratum("while (X != outX)", "while (t < tExit)", "The loop must stop at the grid's end.")};
    steps[0] = first;
    lesson["steps"] = steps;
    return writeLesson(dir, "errata.json", QJsonDocument(lesson).toJson());
}

// The slides' errata: a marked box under the lesson's text and one under the step's, headed
// "Note on the slides"; Lessons > Show notes on the slides hides them, and the choice is
// remembered by the next window. The Hint button reveals one more hint each press.
TEST(Lesson, ErrataBoxesShowAndHideAndHintsComeOneAPress) {
    QSettings().remove("lessons/showErrata");
    QTemporaryDir dir;
    const QString path = lessonWithErrata(dir);
    {
        ShownWindow win;
        MainWindow& w = win.w;
        ASSERT_TRUE(openLesson(w, path)) << w.lastOpenError().toStdString();
        auto* text = w.lessonPanel()->findChild<QTextBrowser*>("lessonText");
        ASSERT_NE(text, nullptr);
        ASSERT_TRUE(w.showErrataAction()->isChecked());  // on by default
        w.lessonPanel()->goToStep(0);
        QString shown = text->toPlainText();
        EXPECT_EQ(shown.count("Note on the slides"), 2) << shown.toStdString();
        EXPECT_TRUE(shown.contains("tDeltaX = cellWidth / |dx|"));
        EXPECT_TRUE(shown.contains("while (X != outX)"));
        // The lesson's box comes before the step, the step's after the step's text.
        EXPECT_LT(shown.indexOf("tDeltaX = dx / cellWidth"), shown.indexOf("Step 1 / "));
        EXPECT_GT(shown.indexOf("while (X != outX)"), shown.indexOf("Step 1 / "));
        // On the next step, the lesson's box only.
        w.lessonPanel()->goToStep(1);
        EXPECT_EQ(text->toPlainText().count("Note on the slides"), 1);
        w.showErrataAction()->trigger();  // what the menu item does
        EXPECT_FALSE(text->toPlainText().contains("Note on the slides"));

        // Hints: one more each press of the button.
        LessonPanel* p = w.lessonPanel();
        p->selectExercise(0);
        QPushButton* hint = nullptr;
        for (QPushButton* b : p->findChildren<QPushButton*>())
            if (b->text() == "Hint") hint = b;
        ASSERT_NE(hint, nullptr);
        EXPECT_TRUE(p->hintsText().isEmpty());
        QTest::mouseClick(hint, Qt::LeftButton);
        EXPECT_TRUE(p->hintsText().contains("A nudge"));
        EXPECT_FALSE(p->hintsText().contains("The formula"));
        EXPECT_TRUE(hint->isEnabled());
        QTest::mouseClick(hint, Qt::LeftButton);
        EXPECT_TRUE(p->hintsText().contains("The formula"));
        EXPECT_FALSE(p->hintsText().contains("The first step"));
        QTest::mouseClick(hint, Qt::LeftButton);
        EXPECT_TRUE(p->hintsText().contains("The first step: tDeltaX = 1 / |dx|."));
        EXPECT_FALSE(hint->isEnabled());  // no more
        // Another exercise starts from no hint.
        p->selectExercise(1);
        EXPECT_TRUE(p->hintsText().isEmpty());
    }
    ShownWindow again;
    EXPECT_FALSE(again.w.showErrataAction()->isChecked());  // remembered
    QSettings().remove("lessons/showErrata");
}

// A lesson text ending in a list: the step that follows it is not drawn as one more, empty, bullet
// (the block inserted after the list used to inherit the list's format).
TEST(Lesson, NoEmptyBulletAfterALessonTextThatEndsInAList) {
    ShownWindow win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openLesson(w, "2")) << w.lastOpenError().toStdString();
    auto* text = w.lessonPanel()->findChild<QTextBrowser*>("lessonText");
    ASSERT_NE(text, nullptr);
    int items = 0;
    for (QTextBlock b = text->document()->begin(); b.isValid(); b = b.next()) {
        if (!b.textList()) continue;
        ++items;
        EXPECT_FALSE(b.text().trimmed().isEmpty())
            << "an empty list item after: " << b.previous().text().toStdString();
    }
    EXPECT_GT(items, 5);  // lesson 2's text holds its lists
}

// The filter matches the trace's kind names (what lessons use) as well as the shown text, and
// after a change of filter the highlighted row is the cursor's event, not a stale row.
TEST(EventListFilter, MatchesKindNamesAndTheHighlightFollowsTheCursor) {
    ShownWindow win;
    MainWindow& w = win.w;
    w.openScene("lecture-grid", AccelKind::Grid, true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    Session& s = w.session();
    int cells = 0;
    for (const Event& e : s.log().events()) cells += std::holds_alternative<DdaCell>(e);
    ASSERT_GT(cells, 3);
    // The cursor after the 3rd cell; then type the kind's name in the filter.
    const std::size_t third = indexOfNth<DdaCell>(s.log(), 3);
    s.setCursor(third + 1);
    auto* edit = w.eventList()->findChild<QLineEdit*>("eventFilter");
    ASSERT_NE(edit, nullptr);
    QTest::keyClicks(edit, "dda_cell");
    EventList* list = w.eventList();
    EXPECT_EQ(list->rowCount(), cells);
    for (int r = 0; r < list->rowCount(); ++r)
        EXPECT_TRUE(list->rowText(r).contains("cell (")) << list->rowText(r).toStdString();
    // The highlight is the 3rd cell's row (row 2), with its event number.
    EXPECT_EQ(list->currentRow(), 2);
    EXPECT_TRUE(list->rowText(2).startsWith(QString::number(third + 1) + "  "));
    // A filter on the shown text works too; the highlight is the last shown row before the
    // cursor (the cursor's own event is hidden).
    edit->clear();
    QTest::keyClicks(edit, "test");
    ASSERT_GT(list->rowCount(), 0);
    for (int r = 0; r < list->rowCount(); ++r)
        EXPECT_TRUE(list->rowText(r).contains("test")) << list->rowText(r).toStdString();
    const int row = list->currentRow();
    if (row >= 0) {
        EXPECT_LE(list->rowText(row).section("  ", 0, 0).toInt(), static_cast<int>(third + 1));
        if (row + 1 < list->rowCount()) {
            EXPECT_GT(list->rowText(row + 1).section("  ", 0, 0).toInt(),
                      static_cast<int>(third + 1));
        }
    }
}

// N jumps to the kind the lesson is about, not always "DDA step": a build lesson to the next
// built node; the quiz lesson (first step after its one dda_setup) to the next DDA step.
TEST(TimelineKind, FollowsTheLesson) {
    QTemporaryDir dir;
    ShownWindow win;
    MainWindow& w = win.w;
    auto* combo = w.timeline()->findChild<QComboBox*>("jumpKind");
    ASSERT_NE(combo, nullptr);
    combo->setCurrentIndex(combo->findText("hit"));  // whatever the user had before
    const QByteArray build = R"({
"format": "raystep-lesson", "version": 1, "id": "build", "number": 94,
"title": {"en": "Build"}, "text": {"en": "A build."},
"scene": "lecture-kdtree", "setup": {"accel": "kdtree", "split": "sah"}, "views": ["2d"],
"trace": {"build": true},
"steps": [{"at": {"after": "build_node", "nth": 2}, "text": {"en": "The second node."}}]
})";
    ASSERT_TRUE(openLesson(w, writeLesson(dir, "build.json", build)))
        << w.lastOpenError().toStdString();
    EXPECT_EQ(w.timeline()->jumpKind(), variantIndex<BuildNode>());
    EXPECT_EQ(combo->currentText(), "build node");
    Session& s = w.session();
    s.setCursor(0);
    QTest::keyClick(&w, Qt::Key_N);
    QTest::keyClick(&w, Qt::Key_N);
    EXPECT_EQ(s.cursor(), indexOfNth<BuildNode>(s.log(), 2) + 1);
    ASSERT_TRUE(openLesson(w, writeLesson(dir, "quiz.json", kQuizLesson)));
    EXPECT_EQ(w.timeline()->jumpKind(), variantIndex<DdaCell>());  // not its one dda_setup
}

// The legend on the 3D view shows each kind of ray in the palette's colour, and the rays drawn
// are in those colours; the 2D view's tested, skipped and hit primitives use the palette's roles.
TEST(Palette, TheViewsAndTheLegendUseThePalette) {
    QTemporaryDir dir;
    ShownWindow win;
    MainWindow& w = win.w;
    w.openScene("whitted", AccelKind::Grid, /*quiet=*/true, {}, /*renderImage=*/false);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    Session& s = w.session();
    s.tracePixel(200, 150, 320, 240);
    w.view3D()->orbit(40, 25, 1.0);  // the scene's camera sees the primary ray end-on
    s.setCursor(s.size());
    const QImage three = grab(w.view3D());
    for (int k = 0; k < kRayKindCount; ++k) {
        const PaletteColour& c = rayColour(RayKind(k));
        SCOPED_TRACE(std::string(c.key));
        EXPECT_GT(pixelsNear(three, c.r, c.g, c.b, 2), 30);  // at least its legend stroke
    }
    // The legend names the colours as the lessons' {colour:KEY} do, in the app's language.
    EXPECT_TRUE(rayKindLabel(RayKind::Shadow, Language::En).endsWith("(yellow)"));
    EXPECT_TRUE(rayKindLabel(RayKind::Shadow, Language::It).endsWith("(giallo)"));
    // The primary ray is drawn in the primary's colour beyond the legend: more such pixels
    // with the rays than before any ray began.
    const PaletteColour& primary = rayColour(RayKind::Primary);
    const int withRays = pixelsNear(three, primary.r, primary.g, primary.b, 12);
    s.setCursor(0);
    EXPECT_GT(withRays, pixelsNear(grab(w.view3D()), primary.r, primary.g, primary.b, 12) + 20);

    // The quiz lesson (mailboxing on) at its end: a primitive tested, one skipped, the hit.
    ASSERT_TRUE(openLesson(w, writeLesson(dir, "quiz.json", kQuizLesson)));
    putAwayAll(w.lessonPanel());  // the lesson's exercises would hold the replay
    QTest::keyClick(&w, Qt::Key_End);
    ASSERT_FALSE(w.session().state().mailboxSkips.empty());
    const QImage two = grab(w.view2D());
    const PaletteColour& tested = roleColour(PaletteRole::Tested);
    const PaletteColour& skipped = roleColour(PaletteRole::Skipped);
    const PaletteColour& hit = roleColour(PaletteRole::Hit);
    EXPECT_GT(pixelsNear(two, tested.r, tested.g, tested.b, 2), 100);  // swatch and primitives
    EXPECT_GT(pixelsNear(two, skipped.r, skipped.g, skipped.b, 2), 100);
    EXPECT_GT(pixelsNear(two, hit.r, hit.g, hit.b, 2), 100);
}

// A ray that ends on a triangle: the inspector shows that hit's barycentric u and v, as the
// event has them (lesson 12 asks for v).
TEST(Inspector, ATriangleHitShowsItsBarycentricUV) {
    ShownWindow win;
    MainWindow& w = win.w;
    w.openScene("whitted", AccelKind::Grid, /*quiet=*/true, {}, /*renderImage=*/false);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    Session& s = w.session();
    s.tracePixel(160, 230, 320, 240);  // a floor pixel, below the spheres
    std::size_t at = 0;
    const RayHit* hit = nullptr;
    for (std::size_t i = 0; i < s.log().events().size() && !hit; ++i)
        if (const auto* h = std::get_if<RayHit>(&s.log().events()[i]);
            h && h->prim != kNoId && !s.scene3D()->isSphere(h->prim))
            hit = h, at = i;
    ASSERT_NE(hit, nullptr);
    s.setCursor(at + 1);
    const QString text = w.inspectorText();
    EXPECT_TRUE(text.contains(QStringLiteral("hit on triangle %1").arg(hit->prim)))
        << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("u = %1").arg(hit->u, 0, 'g', 6)))
        << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("v = %1").arg(hit->v, 0, 'g', 6)))
        << text.toStdString();
    EXPECT_GT(hit->u + hit->v, 0.0);  // a real barycentric pair, not the zeros of a sphere
}

/// A lesson over the lecture grid and the ray o = (0.4, 0.4), d = (1, 0.75), with a
/// choice, a sequence of cells and a compute exercise.
QString lessonWithNewKinds(const QTemporaryDir& dir) {
    const QByteArray text = R"({
"format": "raystep-lesson", "version": 1, "id": "new-kinds", "number": 98,
"title": {"en": "New kinds"}, "text": {"en": "The slides' grid."},
"scene": "lecture-grid", "setup": {"accel": "grid"}, "views": ["2d"],
"trace": {"ray": [0.4, 0.4, 1, 0.75]},
"exercises": [
 {"id": "why", "type": "choice", "prompt": {"en": "Why a grid?"},
  "choices": [{"text": {"en": "It sorts the primitives"}, "why": {"en": "It does not sort them."}},
              {"text": {"en": "A ray visits few cells"}, "why": {"en": "Yes: only its cells."}},
              {"text": {"en": "It makes the image sharper"}, "why": {"en": "Sharpness is the camera's."}}],
  "answer": 1},
 {"id": "order", "type": "sequence", "of": "dda_cell", "at": {"before": "dda_cell", "nth": 2},
  "length": 3, "prompt": {"en": "The next three cells, in order."}},
 {"id": "t0", "type": "compute", "quantity": "t0",
  "given": {"ray": {"o": [1, 2, 10], "d": [0, 0, -2]}, "sphere": {"c": [1, 1, 0], "r": 3}},
  "prompt": {"en": "o = (1, 2, 10), d = (0, 0, -2), c = (1, 1, 0), R = 3: the smaller root t0?",
             "it": "o = (1, 2, 10), d = (0, 0, -2), c = (1, 1, 0), R = 3: la radice minore t0?"}}
]})";
    const QString path = dir.filePath("new-kinds.json");
    QFile out(path);
    EXPECT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(text);
    return path;
}

// A choice answered with its radio buttons: the chosen option's why, and no quiz limit of its
// own (its answer is not in the trace). A sequence answered by clicking cells in order in the 2D
// view, with Clear to start again; it stops the replay where the order starts. A compute exercise
// in a number box (a letter cannot be typed), graded with the slip a wrong number betrays.
TEST(NewKinds, ChoiceSequenceAndComputeAreAnsweredAsAStudentWould) {
    QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                  "/progress.json");
    QTemporaryDir dir;
    ShownWindow win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openLesson(w, lessonWithNewKinds(dir))) << w.lastOpenError().toStdString();
    LessonPanel* p = w.lessonPanel();
    Session& s = w.session();

    // Choice: three radio buttons; c) is wrong, b) is right.
    p->selectExercise(0);
    QTest::keyClick(&w, Qt::Key_End);
    // The choice holds nothing (no event gives a concept away): End stops only where the
    // unsolved sequence exercise starts.
    EXPECT_EQ(s.cursor(), indexOfNth<DdaCell>(s.log(), 2));
    auto* c = p->findChild<QAbstractButton*>("choice2");
    auto* b = p->findChild<QAbstractButton*>("choice1");
    ASSERT_TRUE(c && b);
    EXPECT_TRUE(b->isVisible());
    EXPECT_TRUE(b->text().contains("A ray visits few cells"));
    QTest::mouseClick(c, Qt::LeftButton, {}, QPoint(8, c->height() / 2));
    QTest::mouseClick(buttonNamed(p, "Check"), Qt::LeftButton);
    EXPECT_TRUE(p->feedback().startsWith("Not right")) << p->feedback().toStdString();
    QTest::mouseClick(b, Qt::LeftButton, {}, QPoint(8, b->height() / 2));
    QTest::mouseClick(buttonNamed(p, "Check"), Qt::LeftButton);
    EXPECT_TRUE(p->feedback().startsWith("Right.")) << p->feedback().toStdString();
    EXPECT_TRUE(p->feedback().contains("only its cells")) << p->feedback().toStdString();

    // Sequence: the cells after (0, 0), by hand: tMax (0.6, 0.8) steps X to (1, 0); then
    // (1.6, 0.8) steps Y to (1, 1); then (1.6, 2.133) steps X to (2, 1).
    p->selectExercise(1);
    const std::size_t limit = indexOfNth<DdaCell>(s.log(), 2);
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), limit);
    auto* answer = p->findChild<QLineEdit*>("answer");
    ASSERT_NE(answer, nullptr);
    View2D* view = w.view2D();
    const QImage before = grab(view);
    QTest::mouseClick(view, Qt::LeftButton, {}, view->cellCentre(1, 0).toPoint());
    QTest::mouseClick(view, Qt::LeftButton, {}, view->cellCentre(2, 0).toPoint());
    EXPECT_EQ(answer->text(), "1,0; 2,0");
    EXPECT_NE(grab(view), before);  // the clicked cells are numbered on the grid
    QTest::mouseClick(buttonNamed(p, "Clear the cells"), Qt::LeftButton);
    EXPECT_TRUE(answer->text().isEmpty());
    EXPECT_EQ(grab(view), before);
    for (const QPoint cell : {QPoint(1, 0), QPoint(1, 1), QPoint(2, 1)})
        QTest::mouseClick(view, Qt::LeftButton, {}, view->cellCentre(cell.x(), cell.y()).toPoint());
    EXPECT_EQ(answer->text(), "1,0; 1,1; 2,1");
    QTest::mouseClick(buttonNamed(p, "Check"), Qt::LeftButton);
    EXPECT_TRUE(p->feedback().startsWith("Right.")) << p->feedback().toStdString();
    QTest::keyClick(&w, Qt::Key_End);
    EXPECT_EQ(s.cursor(), s.size());  // answered: the rest of the walk shows

    // Compute: f = o - c = (0, 1, 10); A = 4, B = -40, C = 101 - 9 = 92; disc = 1600 - 1472 =
    // 128; t0 = (40 - sqrt 128) / 8 = 3.5858, t1 = 6.4142.
    p->selectExercise(2);
    answer->setFocus();
    QTest::keyClicks(answer, "x6,4142");
    EXPECT_EQ(answer->text(), "6,4142");  // a number box: the letter is refused
    QTest::keyClick(answer, Qt::Key_Return);
    EXPECT_TRUE(p->feedback().startsWith("Not right yet")) << p->feedback().toStdString();
    EXPECT_TRUE(p->feedback().contains("other root")) << p->feedback().toStdString();
    answer->clear();
    QTest::keyClicks(answer, "3,5858");
    QTest::keyClick(answer, Qt::Key_Return);
    EXPECT_TRUE(p->feedback().startsWith("Right.")) << p->feedback().toStdString();

    // Lecturer mode shows each kind's answer: b), the three cells, t0.
    w.setLecturerMode(true);
    const char* answers[] = {"b", "1,0; 1,1; 2,1", "3.58579"};
    for (int e = 0; e < 3; ++e) {
        p->selectExercise(e);
        EXPECT_TRUE(p->feedback().startsWith("Answer: ")) << p->feedback().toStdString();
        EXPECT_TRUE(p->feedback().contains(answers[e])) << p->feedback().toStdString();
    }
}

// A sweep_pick is graded from the sweep's table: checked before the sweep has run, it starts
// it; then the resolution with the fewest tests per ray (read from the table the app shows) is
// right, and another one is not.
TEST(NewKinds, ASweepPickIsGradedFromTheSweepsTable) {
    QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                  "/progress.json");
    QFile in(QStringLiteral(RAYSTEP_SOURCE_DIR "/lessons/09-voxel-size.json"));
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    QJsonObject lesson = QJsonDocument::fromJson(in.readAll()).object();
    lesson["id"] = "sweep-pick";
    lesson["number"] = 97;
    lesson["exercises"] = QJsonArray{QJsonObject{
        {"id", "fewest-tests"},
        {"type", "sweep_pick"},
        {"metric", "tests_per_ray"},
        {"prompt", QJsonObject{{"en", "Which resolution gives the fewest tests per ray?"}}}}};
    QTemporaryDir dir;
    const QString path = dir.filePath("sweep-pick.json");
    QFile out(path);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(lesson).toJson());
    out.close();

    ShownWindow win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openLesson(w, path)) << w.lastOpenError().toStdString();
    LessonPanel* p = w.lessonPanel();
    p->selectExercise(0);
    auto* picker = p->findChild<QComboBox*>("sweepPicker");
    ASSERT_NE(picker, nullptr);
    ASSERT_TRUE(picker->isVisible());
    EXPECT_EQ(picker->count(), static_cast<int>(p->lesson().sweep->resolutions.size()));
    QTest::mouseClick(buttonNamed(p, "Check"), Qt::LeftButton);
    EXPECT_TRUE(p->feedback().contains("sweep")) << p->feedback().toStdString();
    ASSERT_TRUE(w.waitUntilIdle());
    auto* table = p->findChild<QTableWidget*>();
    ASSERT_NE(table, nullptr);
    ASSERT_EQ(table->rowCount(), picker->count());
    int best = 0;
    for (int r = 1; r < table->rowCount(); ++r)
        if (table->item(r, 1)->text().toDouble() < table->item(best, 1)->text().toDouble())
            best = r;
    const int other = best == 0 ? 1 : 0;
    picker->setCurrentIndex(other);
    QTest::mouseClick(buttonNamed(p, "Check"), Qt::LeftButton);
    EXPECT_TRUE(p->feedback().startsWith("Not right")) << p->feedback().toStdString();
    picker->setCurrentIndex(picker->findData(table->item(best, 0)->text().toInt()));
    QTest::mouseClick(buttonNamed(p, "Check"), Qt::LeftButton);
    EXPECT_TRUE(p->feedback().startsWith("Right.")) << p->feedback().toStdString();
    w.tasks().cancel(TaskKind::Render);
}

}  // namespace
}  // namespace raystep::gui
