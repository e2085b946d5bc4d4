// Presenter mode (issue 19), driven by real key events: the UI zoom (Ctrl++ / Ctrl+= / Ctrl+- /
// Ctrl+0, remembered for the next window), full screen (F11), presenter mode's thicker lines, the
// high-contrast palette, and Help > Keyboard shortcuts (F1, ?) listing every key of the window in
// English and Italian. Each test leaves the presenter settings as it found them (HOME is shared).
#include "compare_window.h"
#include "gui_testing.h"
#include "language.h"
#include "lesson_panel.h"
#include "main_window.h"
#include "presentation.h"
#include "shortcuts.h"
#include "view2d.h"

#include "course/palette.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QScreen>
#include <QSettings>
#include <QShortcut>
#include <QTableWidget>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>

#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace raystep::gui {
namespace {

const char* const kKeys[] = {"presenter/zoom", "presenter/mode", "presenter/highContrast"};

/// Saves the presenter settings, starts from none (zoom 100%, modes off), and puts them back.
class Presenter : public ::testing::Test {
  protected:
    void SetUp() override {
        QSettings s;
        for (const char* k : kKeys)
            if (s.contains(k)) saved_[k] = s.value(k);
        s.remove("presenter");
        presentation().restore();
    }
    void TearDown() override {
        {
            QSettings s;
            s.remove("presenter");
            for (const auto& [k, v] : saved_) s.setValue(k, v);
        }
        presentation().restore();
        setInterfaceLanguage(Language::En);
    }
    std::map<QString, QVariant> saved_;
};

/// A font's size in its own unit (points, else pixels).
double sizeOf(const QFont& f) {
    return f.pointSizeF() > 0 ? f.pointSizeF() : f.pixelSize();
}

void showActive(MainWindow& w) {
    w.resize(1400, 900);
    w.show();
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
}

TEST_F(Presenter, ZoomKeysScaleTheAppFontAndTheNextWindowStartsAtTheRememberedZoom) {
    MainWindow w;
    showActive(w);
    const double base = sizeOf(presentation().baseFont());
    ASSERT_GT(base, 0);
    EXPECT_DOUBLE_EQ(sizeOf(QApplication::font()), base);
    const int panelPx = QFontInfo(w.lessonPanel()->font()).pixelSize();
    const int labelPx = QFontInfo(w.view2D()->font()).pixelSize();

    // The steps 100 -> 110 -> 125 -> 110, each a factor of the 100% font.
    QTest::keyClick(&w, Qt::Key_Plus, Qt::ControlModifier);
    EXPECT_NEAR(sizeOf(QApplication::font()), base * 1.10, 0.01);
    // Qt hands the application's font to its widgets by posted events: waited for.
    EXPECT_TRUE(waitFor([&] { return QFontInfo(w.lessonPanel()->font()).pixelSize() > panelPx; }));
    EXPECT_GT(QFontInfo(w.view2D()->font()).pixelSize(), labelPx);  // the views' labels too
    // A label with a style sheet of its own (the quiz cue) grows too.
    const auto* cue = w.findChild<QWidget*>("quizCue");
    ASSERT_NE(cue, nullptr);
    EXPECT_TRUE(waitFor([&] { return QFontInfo(cue->font()).pixelSize() > panelPx; }));
    QTest::keyClick(&w, Qt::Key_Equal, Qt::ControlModifier);
    EXPECT_NEAR(sizeOf(QApplication::font()), base * 1.25, 0.01);
    EXPECT_EQ(QSettings().value("presenter/zoom").toInt(), 125);
    QTest::keyClick(&w, Qt::Key_Minus, Qt::ControlModifier);
    EXPECT_NEAR(sizeOf(QApplication::font()), base * 1.10, 0.01);
    EXPECT_EQ(QSettings().value("presenter/zoom").toInt(), 110);

    // A new window (the next start) reads the zoom the settings hold: here as if another run left
    // 150%, so it cannot be the 110% still in memory.
    QSettings().setValue("presenter/zoom", 150);
    {
        MainWindow again;
        EXPECT_NEAR(sizeOf(QApplication::font()), base * 1.5, 0.01);
        EXPECT_NEAR(sizeOf(again.view2D()->font()), base * 1.5, 0.01);
    }
    // Ctrl+0: the 100% font, remembered too.
    QTest::keyClick(&w, Qt::Key_0, Qt::ControlModifier);
    EXPECT_DOUBLE_EQ(sizeOf(QApplication::font()), base);
    EXPECT_TRUE(waitFor([&] { return QFontInfo(w.lessonPanel()->font()).pixelSize() == panelPx; }));
    EXPECT_EQ(QSettings().value("presenter/zoom").toInt(), 100);
    // Nonsense in the settings is the default, not a 0 or 10,000 point font.
    QSettings().setValue("presenter/zoom", "huge");
    presentation().restore();
    EXPECT_EQ(presentation().zoomPercent(), 100);
    QSettings().setValue("presenter/zoom", 100000);
    presentation().restore();
    EXPECT_EQ(presentation().zoomPercent(), Presentation::kZoomSteps.back());
}

TEST_F(Presenter, F11TogglesFullScreen) {
    MainWindow w;
    showActive(w);
    ASSERT_FALSE(w.isFullScreen());
    QTest::keyClick(&w, Qt::Key_F11);
    EXPECT_TRUE(waitFor([&] { return w.isFullScreen(); }));
    EXPECT_TRUE(w.findChild<QAction*>("fullScreen")->isChecked());
    QTest::keyClick(&w, Qt::Key_F11);
    EXPECT_TRUE(waitFor([&] { return !w.isFullScreen(); }));
    EXPECT_FALSE(w.findChild<QAction*>("fullScreen")->isChecked());
}

/// Lesson 6's grid as the 2D view draws it now: its width on screen, in pixels.
double gridWidthOnScreen(MainWindow& w) {
    const auto* grid = std::get_if<UniformGridT<Scene2DPrims>>(w.session().accel2D());
    if (!grid) return 0;
    const auto& spec = grid->spec();
    return w.view2D()->screenOf(Vec2(spec.hi.x, spec.lo.y)).x() -
           w.view2D()->screenOf(Vec2(spec.lo.x, spec.lo.y)).x();
}

/// The pixel size of a document's first code fragment (a span or a block) and of its first
/// plain fragment, as it is drawn.
std::pair<int, int> codeAndTextPixels(const QTextDocument* doc) {
    int code = 0, plain = 0;
    for (QTextBlock b = doc->begin(); b.isValid() && !(code && plain); b = b.next())
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const QTextCharFormat f = it.fragment().charFormat();
            const bool isCode = f.fontFixedPitch() || f.hasProperty(QTextFormat::FontFamilies);
            const int px = QFontInfo(f.font().resolve(doc->defaultFont())).pixelSize();
            if (isCode && !code) code = px;
            const bool heading = f.hasProperty(QTextFormat::FontSizeAdjustment) ||
                                 f.hasProperty(QTextFormat::FontWeight);
            if (!isCode && !heading && !plain) plain = px;
        }
    return {code, plain};
}

/// The same of the lesson text, as the text browser draws it.
std::pair<int, int> codeAndTextPixels(const MainWindow& w) {
    const auto* text = w.lessonPanel()->findChild<QTextBrowser*>("lessonText");
    return text ? codeAndTextPixels(text->document()) : std::pair<int, int>{0, 0};
}

/// The exercise's prompt as its label holds it: its text read once, in the label's font then;
/// a zoom gives the document the label's new font without reading the text again.
void readPrompt(const MainWindow& w, QTextDocument& doc) {
    const auto* prompt = w.lessonPanel()->findChild<QLabel*>("prompt");
    ASSERT_NE(prompt, nullptr);
    doc.setDefaultFont(prompt->font());
    if (prompt->textFormat() == Qt::MarkdownText)
        doc.setMarkdown(prompt->text());
    else
        doc.setHtml(prompt->text());
}
std::pair<int, int> promptCodeAndTextPixels(const MainWindow& w, QTextDocument& doc) {
    doc.setDefaultFont(w.lessonPanel()->findChild<QLabel*>("prompt")->font());
    return codeAndTextPixels(&doc);
}

/// Waits until the window's layout stops moving (fonts reach widgets by posted events, then the
/// docks and splitters follow).
void settle(MainWindow& w) {
    QSize last;
    for (int still = 0, k = 0; still < 3 && k < 100; ++k) {
        QTest::qWait(40);
        still = w.view2D()->size() == last ? still + 1 : 0;
        last = w.view2D()->size();
    }
}

TEST_F(Presenter, ZoomEnlargesTheContentTheSceneKeepsItsWidthAndCodeGrowsWithTheText) {
    // The window on all of the screen (ctest's is 1600x1000), as a lecturer shows it.
    MainWindow w;
    QSettings().remove("window");
    w.setGeometry(w.screen()->availableGeometry());
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
    ASSERT_TRUE(waitFor([&] { return w.layoutSettled(); }));
    ASSERT_TRUE(openLesson(w, "6"));
    settle(w);
    const double atBase = gridWidthOnScreen(w);
    const auto [code100, text100] = codeAndTextPixels(w);
    ASSERT_GT(atBase, 200);
    ASSERT_GT(code100, 0);
    ASSERT_GT(text100, 0);
    // Exercise 1's prompt: "The ray is `(0.4, 0.4) + t (0.8, 0.4)` ...".
    w.lessonPanel()->selectExercise(0);
    QTextDocument prompt;
    readPrompt(w, prompt);
    const auto [promptCode100, promptText100] = promptCodeAndTextPixels(w, prompt);
    ASSERT_GT(promptCode100, 0);
    ASSERT_GT(promptText100, 0);
    const double lines100 = presentation().lineScale();
    for (int zoom : Presentation::kZoomSteps) {
        if (zoom <= 100) continue;
        SCOPED_TRACE(zoom);
        presentation().setZoomPercent(zoom);
        settle(w);
        // The scene is not made smaller to make room for larger chrome and labels.
        EXPECT_GE(gridWidthOnScreen(w), atBase) << "at 100%: " << atBase;
        // Nothing else on screen is larger than the 2D view.
        const int area = w.view2D()->width() * w.view2D()->height();
        for (QDockWidget* d : w.findChildren<QDockWidget*>())
            if (d->isVisible()) {
                EXPECT_LT(d->width() * d->height(), area) << d->objectName().toStdString();
            }
        EXPECT_LT(w.lessonPanel()->width() * w.lessonPanel()->height(), area);
        // Code and formulas grow with the text they stand in, as far as the zoom goes.
        const auto [code, text] = codeAndTextPixels(w);
        EXPECT_GE(code, code100 * zoom / 100 - 2) << code100;
        EXPECT_NEAR(code, text, std::max(2, text / 8)) << "text " << text;
        // The same in the exercise's prompt (a label: its code kept the fixed font's size).
        const auto [promptCode, promptText] = promptCodeAndTextPixels(w, prompt);
        EXPECT_GE(promptCode, promptCode100 * zoom / 100 - 2) << promptCode100;
        EXPECT_NEAR(promptCode, promptText, std::max(2, promptText / 8)) << promptText;
        // The views' lines too (the 3D view's rays, the 2D view's pens).
        EXPECT_NEAR(presentation().lineScale(), lines100 * zoom / 100.0, 1e-9);
    }
}

/// Where the 2D view draws the solid part of its ray: a point halfway along it, and the screen
/// direction of the ray.
struct RayOnScreen {
    QPointF mid;
    QPointF dir;
};

RayOnScreen rayOnScreen(MainWindow& w) {
    const Session& s = w.session();
    const RayRecord& r = s.log().rays().front();
    const ReplayState& st = s.state();
    // At the end of the walk the solid ray reaches the nearest hit (or the last cell's exit).
    double reached =
        st.nearestT ? *st.nearestT : std::min(st.ddaCell->tMax[0], st.ddaCell->tMax[1]);
    const Vec2 o(r.origin.x, r.origin.y), d(r.dir.x, r.dir.y);
    const QPointF a = w.view2D()->screenOf(o), b = w.view2D()->screenOf(o + reached * d);
    return {(a + b) / 2, b - a};
}

/// The longest run of pixels of `colour` (within a small distance: antialiased edges are not)
/// across the ray at `at`, counted along the screen axis most across the ray.
int runAcross(const QImage& image, QPointF at, QPointF dir, QColor colour) {
    const bool vertical = std::abs(dir.x()) >= std::abs(dir.y());  // a flat ray: scan a column
    int best = 0, run = 0;
    for (int k = -40; k <= 40; ++k) {
        const int x = static_cast<int>(at.x()) + (vertical ? 0 : k);
        const int y = static_cast<int>(at.y()) + (vertical ? k : 0);
        const QColor c = image.pixelColor(x, y);
        const int dr = c.red() - colour.red(), dg = c.green() - colour.green(),
                  db = c.blue() - colour.blue();
        run = dr * dr + dg * dg + db * db < 12 * 12 ? run + 1 : 0;
        best = std::max(best, run);
    }
    return best;
}

QColor primary() {
    const PaletteColour& c = rayColour(RayKind::Primary);
    return QColor(c.r, c.g, c.b);
}

TEST_F(Presenter, PresenterModeDrawsTheRayThickerAndHighContrastChangesItsColour) {
    MainWindow w;
    showActive(w);
    ASSERT_TRUE(openLesson(w, "6"));
    w.setLecturerMode(true);  // no exercise holds the replay
    w.session().setCursor(w.session().size());
    QApplication::processEvents();
    const RayOnScreen ray = rayOnScreen(w);
    ASSERT_GT(std::hypot(ray.dir.x(), ray.dir.y()), 60);

    const QImage plain = w.view2D()->grab().toImage();
    const int thin = runAcross(plain, ray.mid, ray.dir, primary());
    // 2.5 px wide: 2 to 4 pixels across whatever its slope in this lesson.
    EXPECT_GE(thin, 2);
    w.findChild<QAction*>("presenterMode")->trigger();
    EXPECT_TRUE(presentation().presenterMode());
    EXPECT_TRUE(QSettings().value("presenter/mode").toBool());
    QApplication::processEvents();
    const QImage thick = w.view2D()->grab().toImage();
    const int wide = runAcross(thick, ray.mid, ray.dir, primary());
    // Twice as wide (Presentation::kPresenterLineScale): allow a pixel of antialiasing each side.
    EXPECT_GE(wide, 2 * thin - 2) << thin << " -> " << wide;
    EXPECT_GT(wide, thin);

    // High contrast: the ray's centre is drawn in the high-contrast shade of its colour.
    const QColor standard = primary();
    w.findChild<QAction*>("highContrast")->trigger();
    EXPECT_TRUE(QSettings().value("presenter/highContrast").toBool());
    QApplication::processEvents();
    const PaletteColour& hc = paletteColours(PaletteVariant::HighContrast)[0];
    ASSERT_EQ(hc.key, "primary");
    const QColor high(hc.r, hc.g, hc.b);
    ASSERT_NE(high, standard);
    const QImage contrast = w.view2D()->grab().toImage();
    EXPECT_GE(runAcross(contrast, ray.mid, ray.dir, high), wide - 1);
    EXPECT_EQ(runAcross(contrast, ray.mid, ray.dir, standard), 0);
    // Off again: the standard colours come back.
    w.findChild<QAction*>("highContrast")->trigger();
    w.findChild<QAction*>("presenterMode")->trigger();
    QApplication::processEvents();
    EXPECT_EQ(runAcross(w.view2D()->grab().toImage(), ray.mid, ray.dir, standard), thin);
}

/// WCAG 2 relative luminance and contrast ratio, as the W3C defines them.
double luminance(int r, int g, int b) {
    const auto lin = [](int c) {
        const double v = c / 255.0;
        return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b);
}
double contrast(const PaletteColour& c, int r, int g, int b) {
    const double a = luminance(c.r, c.g, c.b), bg = luminance(r, g, b);
    return (std::max(a, bg) + 0.05) / (std::min(a, bg) + 0.05);
}

TEST_F(Presenter, HighContrastPaletteKeepsEveryNameAndADistinctColourPerRole) {
    const auto standard = paletteColours(PaletteVariant::Standard);
    const auto high = paletteColours(PaletteVariant::HighContrast);
    ASSERT_EQ(standard.size(), high.size());
    for (std::size_t i = 0; i < high.size(); ++i) {
        SCOPED_TRACE(std::string(high[i].key));
        // The lessons' "{colour:KEY}" words stay true: same key, same name in both languages.
        EXPECT_EQ(high[i].key, standard[i].key);
        EXPECT_EQ(high[i].en, standard[i].en);
        EXPECT_EQ(high[i].name(Language::It), standard[i].name(Language::It));
    }
    presentation().setHighContrast(true);
    EXPECT_EQ(paletteVariant(), PaletteVariant::HighContrast);
    // Within the 3D view's rays, and within the 2D view's roles with its (primary) ray: no two
    // share a colour; every one of them changed shade.
    std::vector<PaletteColour> rays, view2D{rayColour(RayKind::Primary)};
    for (int k = 0; k < kRayKindCount; ++k) rays.push_back(rayColour(static_cast<RayKind>(k)));
    for (int r = 0; r < kPaletteRoleCount; ++r)
        view2D.push_back(roleColour(static_cast<PaletteRole>(r)));
    for (const auto* group : {&rays, &view2D}) {
        std::set<std::tuple<int, int, int>> rgb;
        for (const PaletteColour& c : *group) {
            EXPECT_TRUE(rgb.insert({c.r, c.g, c.b}).second) << c.key;
            const auto s = paletteColour(c.key);  // the active (high contrast) entry
            ASSERT_TRUE(s);
            for (const PaletteColour& o : standard) {
                if (o.key == c.key) {
                    EXPECT_NE(std::tie(o.r, o.g, o.b), std::tie(c.r, c.g, c.b)) << c.key;
                }
            }
        }
    }
    // No structure of the 3D view takes a ray's colour.
    for (int r = 0; r < kStructureRoleCount; ++r) {
        const PaletteColour& s = structureColour(static_cast<StructureRole>(r));
        for (const PaletteColour& ray : rays)
            EXPECT_FALSE(s.r == ray.r && s.g == ray.g && s.b == ray.b) << s.key << " " << ray.key;
    }
    // Higher contrast where each is drawn: the 2D roles and ray on the 2D view's page (white in
    // high contrast, 250,250,247 otherwise), the rays and structures on the 3D view's background
    // (black in high contrast, 31,33,41 otherwise).
    for (std::size_t i = 0; i < high.size(); ++i) {
        SCOPED_TRACE(std::string(high[i].key));
        const bool on2D = i == 0 || (i >= std::size_t(kRayKindCount) &&
                                     i < std::size_t(kRayKindCount + kPaletteRoleCount));
        if (on2D) {
            EXPECT_GT(contrast(high[i], 255, 255, 255), contrast(standard[i], 250, 250, 247));
        }
        if (!on2D || i == 0) {
            EXPECT_GE(contrast(high[i], 0, 0, 0), contrast(standard[i], 31, 33, 41));
        }
    }
    presentation().setHighContrast(false);
    EXPECT_EQ(paletteVariant(), PaletteVariant::Standard);
}

/// A colour's hue in degrees and its saturation (HSV), by the usual formulas.
std::pair<double, double> hueAndSaturation(const PaletteColour& c) {
    const double r = c.r, g = c.g, b = c.b;
    const double hi = std::max({r, g, b}), lo = std::min({r, g, b}), span = hi - lo;
    if (span == 0) return {0, 0};
    double h = hi == r   ? std::fmod((g - b) / span, 6.0)
               : hi == g ? (b - r) / span + 2
                         : (r - g) / span + 4;
    h *= 60;
    if (h < 0) h += 360;
    return {h, span / hi};
}

// lessons.md F16: the current kd node was orange beside the primary ray's orange-red, the BVH's
// boxes blue beside the reflection ray's sky blue. Every 3D structure is a grey (or white) or
// keeps 45 degrees of hue from every ray, in both palettes. By hand: vermilion (213, 94, 0) is at
// 26.5 degrees, orange (230, 159, 0) at 41.5; sky blue (86, 180, 233) and blue (0, 114, 178)
// both at 201.6.
TEST_F(Presenter, TheThreeDStructuresKeepClearOfTheRaysHues) {
    for (const bool high : {false, true}) {
        SCOPED_TRACE(high);
        presentation().setHighContrast(high);
        for (int r = 0; r < kStructureRoleCount; ++r) {
            const PaletteColour& s = structureColour(static_cast<StructureRole>(r));
            const auto [hue, saturation] = hueAndSaturation(s);
            if (saturation < 0.15) continue;  // a grey or white: no hue to mistake
            for (int k = 0; k < kRayKindCount; ++k) {
                const PaletteColour& ray = rayColour(static_cast<RayKind>(k));
                const double apart = std::abs(hue - hueAndSaturation(ray).first);
                EXPECT_GE(std::min(apart, 360 - apart), 45) << s.key << " / " << ray.key;
            }
        }
    }
    presentation().setHighContrast(false);
}

/// The dialog's rows as (keys, what) pairs of text.
std::vector<std::pair<QString, QString>> rowsOf(const QTableWidget* t) {
    std::vector<std::pair<QString, QString>> rows;
    for (int r = 0; r < t->rowCount(); ++r)
        rows.emplace_back(t->item(r, 0)->text(), t->item(r, 1)->text());
    return rows;
}

QString withoutMnemonic(QString text) {
    text.replace("&&", "\x01");
    text.remove('&');
    return text.replace("\x01", "&");
}

/// Every QAction of `w` with a key is in the dialog, with its text, each of its keys named.
void expectEveryAction(MainWindow& w, const ShortcutsDialog& d) {
    const auto rows = rowsOf(d.keysTable());
    int withKeys = 0;
    for (const QAction* a : w.findChildren<QAction*>()) {
        if (a->shortcuts().isEmpty()) continue;
        ++withKeys;
        for (const QKeySequence& k : a->shortcuts()) {
            QString key = k.toString(QKeySequence::NativeText);
            // Qt's Italian names Home by an arrow; the dialog writes the key's word, by hand here.
            if (interfaceLanguage() == Language::It) key.replace(QChar(0x2196), "Inizio");
            const bool listed = std::any_of(rows.begin(), rows.end(), [&](const auto& row) {
                return row.first.split(", ").contains(key) &&
                       row.second == withoutMnemonic(a->text());
            });
            EXPECT_TRUE(listed) << key.toStdString() << " " << a->text().toStdString();
        }
    }
    EXPECT_GE(withKeys, 18);  // the menus' keys at least (File, Replay, Lessons, View, Help)
    // The gesture table, whole.
    EXPECT_EQ(d.gesturesTable()->rowCount(), static_cast<int>(mouseAndViewKeys().size()));
}

TEST_F(Presenter, ShortcutsDialogListsEveryKeyOfTheWindowAsItIsWhenItOpens) {
    MainWindow w;
    showActive(w);
    ASSERT_TRUE(openLesson(w, "6"));
    // A key added after the window was made (as a later part of the app may) is listed too.
    auto* late = new QAction(QStringLiteral("&Late action"), &w);
    late->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_T));
    w.addAction(late);
    ASSERT_EQ(w.shortcutsDialog(), nullptr);
    QTest::keyClick(&w, Qt::Key_F1);
    ASSERT_TRUE(waitFor([&] { return w.shortcutsDialog() && w.shortcutsDialog()->isVisible(); }));
    expectEveryAction(w, *w.shortcutsDialog());
    EXPECT_EQ(w.shortcutsDialog()->windowTitle(), QStringLiteral("Keyboard shortcuts"));
    // The lesson panel's QShortcuts (Page Up / Page Down) are named in the gesture table.
    const auto gestures = rowsOf(w.shortcutsDialog()->gesturesTable());
    const QString pageKeys = QKeySequence(Qt::Key_PageUp).toString(QKeySequence::NativeText);
    EXPECT_TRUE(std::any_of(gestures.begin(), gestures.end(), [&](const auto& row) {
        return row.first.contains(pageKeys) &&
               row.second == QStringLiteral("Previous / next step of the lesson");
    }));
    w.shortcutsDialog()->close();
    ASSERT_TRUE(waitFor([&] { return w.shortcutsDialog() == nullptr; }));

    // ? typed in the answer box is a ?, not the dialog; F1 there opens it.
    w.setLecturerMode(false);
    w.lessonPanel()->selectExercise(0);
    auto* answer = w.lessonPanel()->findChild<QLineEdit*>("answer");
    ASSERT_NE(answer, nullptr);
    ASSERT_TRUE(answer->isVisible());
    answer->setFocus();
    answer->clear();
    QApplication::processEvents();
    ASSERT_EQ(w.focusWidget(), answer);
    QTest::keyClick(answer, Qt::Key_Question, Qt::NoModifier);
    QTest::keyClick(answer, Qt::Key_Question, Qt::ShiftModifier);  // as a US keyboard sends it
    EXPECT_EQ(answer->text(), QStringLiteral("??"));
    QApplication::processEvents();
    EXPECT_EQ(w.shortcutsDialog(), nullptr);
    QTest::keyClick(answer, Qt::Key_F1);
    ASSERT_TRUE(waitFor([&] { return w.shortcutsDialog() != nullptr; }));
    w.shortcutsDialog()->close();
    ASSERT_TRUE(waitFor([&] { return w.shortcutsDialog() == nullptr; }));
    answer->clear();
    // Elsewhere, ? opens it.
    w.view2D()->setFocus();
    QApplication::processEvents();
    QTest::keyClick(w.view2D(), Qt::Key_Question);
    ASSERT_TRUE(waitFor([&] { return w.shortcutsDialog() != nullptr; }));
    expectEveryAction(w, *w.shortcutsDialog());
}

// gui.md 16: with the compare window in front, Ctrl+Q and the window's keys did nothing (a
// lecturer's second Ctrl+Q, every run of the reviewer's monkey). Esc closes it.
TEST_F(Presenter, TheWindowsKeysWorkFromTheCompareWindow) {
    auto* w = new MainWindow;
    QPointer<MainWindow> alive(w);
    w->setAttribute(Qt::WA_DeleteOnClose);
    showActive(*w);
    ASSERT_TRUE(openLesson(*w, "10"));
    w->setLecturerMode(true);
    w->openCompare();
    ASSERT_TRUE(w->waitUntilIdle());
    QPointer<CompareWindow> compare = w->compareWindow();
    ASSERT_TRUE(compare);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(compare));
    // In front: the keys go to it, not to the app's window behind.
    const auto inFront = [&] {
        return waitFor([&] {
            if (QApplication::activeWindow() != compare) compare->activateWindow();
            return QApplication::activeWindow() == compare;
        });
    };
    ASSERT_TRUE(inFront());
    // Ctrl++ there zooms (the application's font), F1 there lists the keys.
    QTest::keyClick(compare, Qt::Key_Plus, Qt::ControlModifier);
    EXPECT_EQ(presentation().zoomPercent(), 110);
    QTest::keyClick(compare, Qt::Key_0, Qt::ControlModifier);
    EXPECT_EQ(presentation().zoomPercent(), 100);
    QTest::keyClick(compare, Qt::Key_F1);
    ASSERT_TRUE(waitFor([&] { return w->shortcutsDialog() != nullptr; }));
    w->shortcutsDialog()->close();
    ASSERT_TRUE(waitFor([&] { return w->shortcutsDialog() == nullptr; }));
    // Esc closes the compare window; opened again, Ctrl+Q in it quits the app's window.
    ASSERT_TRUE(inFront());
    QTest::keyClick(compare, Qt::Key_Escape);
    ASSERT_TRUE(waitFor([&] { return !compare; }));
    w->openCompare();
    ASSERT_TRUE(w->waitUntilIdle());
    compare = w->compareWindow();
    ASSERT_TRUE(compare);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(compare));
    ASSERT_TRUE(inFront());
    QTest::keyClick(compare, Qt::Key_Q, Qt::ControlModifier);
    EXPECT_TRUE(waitFor([&] { return !alive && !compare; }));
    delete alive.data();
}

TEST_F(Presenter, ShortcutsDialogInItalian) {
    setInterfaceLanguage(Language::It);
    MainWindow w;
    w.setLanguage(Language::It);
    showActive(w);
    QTest::keyClick(&w, Qt::Key_F1);
    ASSERT_TRUE(waitFor([&] { return w.shortcutsDialog() != nullptr; }));
    const ShortcutsDialog& d = *w.shortcutsDialog();
    expectEveryAction(w, d);
    // Written here by hand, as an Italian reader expects them.
    EXPECT_EQ(d.windowTitle(), QStringLiteral("Scorciatoie da tastiera"));
    EXPECT_EQ(d.keysTable()->horizontalHeaderItem(1)->text(), QStringLiteral("Che cosa fa"));
    const auto rows = rowsOf(d.keysTable());
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [](const auto& row) {
        return row.second == QStringLiteral("Ingrandisci");
    }));
    const auto gestures = rowsOf(d.gesturesTable());
    EXPECT_TRUE(std::any_of(gestures.begin(), gestures.end(), [](const auto& row) {
        return row.first == QStringLiteral("Rotellina") &&
               row.second == QStringLiteral("Ingrandisce o riduce l'immagine");
    }));
    // The Home key by its Italian word, not Qt's arrow.
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [](const auto& row) {
        return row.first == QStringLiteral("Inizio") &&
               row.second == QStringLiteral("Primo evento");
    }));
    for (const auto& row : rows)
        EXPECT_FALSE(row.first.contains(QChar(0x2196))) << row.first.toStdString();
    // No gesture is left in English.
    for (std::size_t i = 0; i < mouseAndViewKeys().size(); ++i)
        EXPECT_NE(gestures[i].second.toStdString(), mouseAndViewKeys()[i].what);
}

}  // namespace
}  // namespace raystep::gui
