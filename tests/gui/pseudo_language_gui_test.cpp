// The pseudo-language "xx" in the app (tests/support/pseudo_language.h; the CLI's half is
// tests/cli/pseudo_language_test.cpp): the window in xx opens xx copies of built-in lessons and
// every text the lesson panel shows (the lesson's text at each step, each exercise's prompt, its
// hints and the feedback on a wrong answer, the panel's buttons and labels) must sit inside
// [[...]]. A word outside is a sentence that skipped the catalogue, or a text the lesson file does
// not carry in every language.
#include "gui_testing.h"
#include "language.h"
#include "lesson_panel.h"
#include "main_window.h"
#include "pseudo_language.h"

#include "raystep/base/i18n.h"

#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QLabel>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTextDocumentFragment>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace raystep::gui {
namespace {

namespace fs = std::filesystem;
namespace pseudo = raystep::testing::pseudo;

const fs::path kSource = RAYSTEP_SOURCE_DIR;
const Language kXx{"xx"};

class PseudoLanguageGui : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        const fs::path root = dir_.path().toStdString();
        made_ = pseudo::writePseudoLanguage(root, kSource, ok_);
        ASSERT_GT(made_.entries, 500u);  // the catalogue was read at all
        ASSERT_EQ(made_.lessons.size(), 13u);
        addLanguages((root / "langs").string());
        ASSERT_TRUE(parseLanguage("xx"));
        // As the app's main does: the translators before any widget takes its texts.
        setInterfaceLanguage(kXx);
        window_ = std::make_unique<MainWindow>();
        window_->setLanguage(kXx);
        window_->resize(1500, 900);
        window_->show();
        window_->activateWindow();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
    }

    void TearDown() override {
        if (window_) window_->waitUntilIdle();
        window_.reset();
        setInterfaceLanguage(Language::En);
        // The registry cannot forget a language: xx stays, but as English writes (its formats
        // the defaults, an empty catalogue), so the tests after this one (and the next
        // --gtest_repeat) read every lesson as they did before it.
        const fs::path neutral = fs::path(dir_.path().toStdString()) / "neutral";
        fs::create_directories(neutral / "xx");
        std::ofstream(neutral / "xx" / "language.json") << "{}";
        addLanguages(neutral.string());
    }

    /// Fails on each word of `text` outside [[...]] (rich text read as the widget shows it).
    void expectMarked(const QString& text, const std::string& where) {
        const QString plain =
            Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText() : text;
        for (const std::string& w : pseudo::unmarkedWords(plain.toStdString(), ok_))
            ADD_FAILURE() << where << ": unmarked " << w;
    }

    /// Every button's and label's text under the lesson panel, shown or not yet.
    void expectPanelWidgetsMarked(const std::string& where) {
        LessonPanel* p = window_->lessonPanel();
        for (QAbstractButton* b : p->findChildren<QAbstractButton*>())
            expectMarked(b->text(), where + ", button " + b->objectName().toStdString());
        for (QLabel* l : p->findChildren<QLabel*>())
            expectMarked(l->text(), where + ", label " + l->objectName().toStdString());
    }

    /// Opens the xx lesson `file` and checks what its steps and exercises show.
    void checkLesson(const std::string& file) {
        SCOPED_TRACE(file);
        const QString path = QString::fromStdString(
            (fs::path(dir_.path().toStdString()) / "lessons" / file).string());
        MainWindow& w = *window_;
        ASSERT_TRUE(openLesson(w, path)) << w.lastOpenError().toStdString();
        LessonPanel* p = w.lessonPanel();
        ASSERT_TRUE(p->hasLesson());
        auto* text = p->findChild<QTextBrowser*>("lessonText");
        ASSERT_NE(text, nullptr);
        expectMarked(text->toPlainText(), file + " text");
        expectPanelWidgetsMarked(file);
        for (int s = 0; s < static_cast<int>(p->lesson().steps.size()); ++s) {
            p->goToStep(s);
            ASSERT_TRUE(w.waitUntilIdle());
            const std::string at = file + " step " + std::to_string(s + 1);
            expectMarked(text->toPlainText(), at + " text");
            expectPanelWidgetsMarked(at);
        }
        for (int e = 0; e < static_cast<int>(p->lesson().exercises.size()); ++e) {
            p->selectExercise(e);
            ASSERT_TRUE(w.waitUntilIdle());
            const std::string at = file + " exercise " + p->lesson().exercises[e].id;
            expectMarked(p->exerciseText(), at + " prompt");
            // Every hint, one press of the button each.
            for (int h = 0; h < 5; ++h) {
                QPushButton* hint = buttonNamed(p, "[[Hint]]");
                if (!hint) hint = buttonNamed(p, "[[Next hint]]");
                if (!hint || !hint->isEnabled()) break;
                QTest::mouseClick(hint, Qt::LeftButton);
            }
            expectMarked(p->hintsText(), at + " hints");
            // Wrong answers: a number, and junk.
            for (const char* answer : {"0", "nonsense"}) {
                p->submit(answer);
                ASSERT_TRUE(w.waitUntilIdle());
                EXPECT_FALSE(p->feedback().isEmpty()) << at << ": " << answer;
                expectMarked(p->feedback(), at + " feedback on " + answer);
                expectMarked(text->toPlainText(), at + " text");
                expectPanelWidgetsMarked(at + " after " + answer);
            }
            // Put away, as a student who looks past it does: the next exercise's prompt and
            // hints do not wait for this one's answer then.
            p->closeExercise();
            ASSERT_TRUE(w.waitUntilIdle());
        }
    }

    QTemporaryDir dir_;
    pseudo::Tolerated ok_;
    pseudo::PseudoFolder made_;
    std::unique_ptr<MainWindow> window_;
};

TEST_F(PseudoLanguageGui, TheMarkerCatchesAnUnmarkedWord) {
    const auto words =
        pseudo::unmarkedWords("[[Step]] 1 (x = 2'5, tMaxX) stray [[a [[b]] c]]", ok_);
    ASSERT_EQ(words.size(), 1u);
    EXPECT_NE(words[0].find("'stray'"), std::string::npos) << words[0];
    // The window took xx's translator: its lesson panel's buttons say [[...]].
    bool marked = false;
    for (QAbstractButton* b : window_->lessonPanel()->findChildren<QAbstractButton*>())
        marked = marked || b->text().startsWith("[[");
    EXPECT_TRUE(marked);
}

TEST_F(PseudoLanguageGui, TheLessonPanelShowsNothingUnmarked) {
    for (const char* file :
         {"06-grid-2d-dda.json", "11-building-kdtree.json", "12-intersections.json"})
        checkLesson(file);
}

}  // namespace
}  // namespace raystep::gui
