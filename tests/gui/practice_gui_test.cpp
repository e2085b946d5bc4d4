// Lessons > Practice in the app, driven as a student does: the bar's topic and level, New
// exercise by mouse and Ctrl+Shift+N, every answer typed and checked with Return; three right in
// a row master the topic, a wrong first answer starts the streak again, no instance comes twice,
// and the progress file and the report keep it all.
#include "gui_testing.h"
#include "lesson_panel.h"
#include "main_window.h"

#include "course/practice/practice.h"
#include "course/progress.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <set>

namespace raystep::gui {
namespace {

QString progressPath() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/progress.json";
}

QString status(MainWindow& w) {
    auto* label = w.findChild<QLabel*>("practiceStatus");
    return label ? label->text() : QString();
}

/// The practice instance the panel shows (its id names it).
PracticeKey shownKey(LessonPanel* p) {
    const auto key = parsePracticeLessonId(p->lesson().id);
    EXPECT_TRUE(key) << p->lesson().id;
    return key.value_or(PracticeKey{});
}

/// Types `text` into the answer box and presses Return.
void answer(LessonPanel* p, const QString& text) {
    auto* box = p->findChild<QLineEdit*>("answer");
    ASSERT_NE(box, nullptr);
    ASSERT_TRUE(box->isVisible());
    box->setFocus();
    box->selectAll();
    QTest::keyClick(box, Qt::Key_Backspace);
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
}

/// Answers every exercise of the shown instance right at its first answer (the engine's key,
/// as `practice make --json` gives it), moving on with the exercise box's ">" button.
void answerAllRight(LessonPanel* p) {
    const PracticeKey key = shownKey(p);
    const auto exercises = makePractice(key.topic, key.seed, key.level).toJson()["exercises"];
    ASSERT_EQ(exercises.size(), p->lesson().exercises.size());
    for (std::size_t i = 0; i < exercises.size(); ++i) {
        if (i > 0) QTest::mouseClick(buttonNamed(p, ">"), Qt::LeftButton);
        ASSERT_EQ(p->exercise(), static_cast<int>(i));
        answer(p, QString::fromStdString(exercises[i]["answer"].get<std::string>()));
        EXPECT_TRUE(p->feedback().startsWith("Right.")) << i << ": " << p->feedback().toStdString();
    }
}

}  // namespace

TEST(Practice, ThreeRightInARowMasterATopicAndAWrongFirstAnswerStartsAgain) {
    QFile::remove(progressPath());
    QSettings().remove("practice");
    ShownWindow win;
    MainWindow& w = win.w;
    LessonPanel* p = w.lessonPanel();
    auto* bar = w.findChild<QWidget*>("practiceBar");
    ASSERT_NE(bar, nullptr);

    // Lessons > Practice...: the first topic at its first level, the DDA in 2D, easy.
    auto* practice = w.findChild<QAction*>("practice");
    ASSERT_NE(practice, nullptr);
    practice->trigger();
    ASSERT_TRUE(w.waitUntilIdle());
    ASSERT_TRUE(w.lastOpenOk().value_or(false)) << w.lastOpenError().toStdString();
    EXPECT_TRUE(bar->isVisible());
    EXPECT_EQ(shownKey(p).topic, "dda-2d");
    EXPECT_EQ(shownKey(p).level, PracticeLevel::Easy);
    EXPECT_EQ(status(w), "Right in a row: 0 of 3");
    EXPECT_TRUE(
        w.findChild<QLabel*>("practiceSeed")->text().contains(QString::number(shownKey(p).seed)));

    std::set<std::uint64_t> seeds;
    for (int round = 1; round <= 3; ++round) {
        seeds.insert(shownKey(p).seed);
        answerAllRight(p);
        if (round < 3) {
            EXPECT_TRUE(status(w).startsWith(QString("Right in a row: %1 of 3").arg(round)))
                << status(w).toStdString();
            EXPECT_TRUE(status(w).contains("press New exercise")) << status(w).toStdString();
            // The bar's button once, the shortcut once.
            if (round == 1)
                QTest::mouseClick(buttonNamed(bar, "New exercise"), Qt::LeftButton);
            else
                QTest::keyClick(&w, Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
            ASSERT_TRUE(w.waitUntilIdle());
            ASSERT_TRUE(w.lastOpenOk().value_or(false)) << w.lastOpenError().toStdString();
        }
    }
    EXPECT_TRUE(status(w).startsWith("Mastered at this level (3 right of 3)"))
        << status(w).toStdString();
    EXPECT_EQ(seeds.size(), 3u);  // three instances, none twice

    // The level by keyboard: medium, a new instance at once; its first answer wrong.
    auto* levels = w.findChild<QComboBox*>("practiceLevel");
    ASSERT_NE(levels, nullptr);
    levels->setFocus();
    QTest::keyClick(levels, Qt::Key_Down);
    ASSERT_TRUE(w.waitUntilIdle());
    EXPECT_EQ(shownKey(p).level, PracticeLevel::Medium);
    EXPECT_EQ(status(w), "Right in a row: 0 of 3");
    answer(p, "99,99");
    EXPECT_TRUE(p->feedback().startsWith("Not right yet")) << p->feedback().toStdString();
    EXPECT_TRUE(status(w).contains("the streak starts again")) << status(w).toStdString();

    // The file keeps every instance and its result; the report shows the mastery.
    QFile f(progressPath());
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const Progress saved = parseProgress(f.readAll().toStdString(), "progress.json");
    ASSERT_EQ(saved.practice.count("dda-2d/easy"), 1u);
    const PracticeRecord& easy = saved.practice.at("dda-2d/easy");
    EXPECT_EQ(easy.instances.size(), 3u);
    EXPECT_EQ(easy.right(), 3);
    EXPECT_TRUE(easy.mastered());
    std::set<std::string> digests;
    for (const PracticeRecord::Instance& in : easy.instances) digests.insert(in.digest);
    EXPECT_EQ(digests.size(), 3u);  // three different instances, not only three seeds
    EXPECT_EQ(digests.count(""), 0u);
    ASSERT_EQ(saved.practice.count("dda-2d/medium"), 1u);
    EXPECT_EQ(saved.practice.at("dda-2d/medium").instances.back().result,
              PracticeRecord::Result::Missed);
    const std::string report = progressReport(saved, builtinLessons(), Language::En);
    EXPECT_NE(report.find("| easy | 3 | 3 | 3 | yes |"), std::string::npos) << report;
    EXPECT_NE(report.find("| medium | 1 | 0 | 0 | not yet |"), std::string::npos) << report;

    // A built-in lesson hides the bar; the topic picked by keyboard opens it again.
    ASSERT_TRUE(openLesson(w, "6"));
    EXPECT_FALSE(bar->isVisible());
    auto* topics = w.findChild<QComboBox*>("practiceTopic");
    ASSERT_NE(topics, nullptr);
    practice->trigger();
    ASSERT_TRUE(w.waitUntilIdle());
    EXPECT_TRUE(bar->isVisible());
    topics->setFocus();
    QTest::keyClick(topics, Qt::Key_Down);
    ASSERT_TRUE(w.waitUntilIdle());
    ASSERT_TRUE(w.lastOpenOk().value_or(false)) << w.lastOpenError().toStdString();
    EXPECT_EQ(shownKey(p).topic, practiceTopics()[1].name);
    EXPECT_EQ(shownKey(p).level, PracticeLevel::Medium);  // the level stays
}

}  // namespace raystep::gui
