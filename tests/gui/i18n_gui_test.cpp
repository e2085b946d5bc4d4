// The Italian interface is Italian: the window is built once in English and once in Italian, the
// same way, and every menu, action, button, label, tooltip, placeholder, list row and header of
// the Italian one must differ from its English twin, unless its words are the same in both
// languages (a short list below). The inspector and the event list are compared the same way at
// every step of a 2D walk, a 3D pixel's ray tree and a kd-tree's construction.
#include "compare_chooser.h"
#include "compare_window.h"
#include "event_list.h"
#include "inspector.h"
#include "language.h"
#include "lesson_panel.h"
#include "main_window.h"

#include "course/lesson.h"

#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTextBrowser>

#include <functional>
#include <memory>
#include <set>
#include <vector>

namespace raystep::gui {
namespace {

/// One text the user can see, and where it is (for the failure message).
struct Shown {
    QString where, text;
};

/// Words that are the same in English and Italian: names (raystep, SAH, DDA, BVH, kd-tree,
/// mip-mapping, shadow and environment mapping, a built-in scene's file name), "File" and "pixel"
/// (Italian uses them), "mailboxing" (the slides' word), single letters (labels), and the
/// board's symbols the inspector writes as the slides do (tMaxX, tDeltaX, stepX, t_enter, NL).
bool sameInBothLanguages(const QString& text) {
    static const std::set<QString> kWords = {
        "raystep", "pixel", "SAH", "DDA", "BVH", "File", "tMaxX", "tMaxY", "tMaxZ", "tDeltaX",
        "tDeltaY", "tDeltaZ", "stepX", "stepY", "stepZ", "t_enter", "t_exit", "NL", "NR",
        // the board's formats, the SAH's cost symbols
        "CSV", "Markdown", "LaTeX", "cTrav", "cIsect"};
    QString rest = text;
    rest.remove(QLatin1Char('&'));
    // Names of techniques Italian courses use as they are.
    for (const char* term : {"kd-tree", "mip-mapping", "shadow mapping", "environment mapping"})
        rest.remove(QString::fromLatin1(term), Qt::CaseInsensitive);
    rest.remove(QRegularExpression(QStringLiteral("<[^>]*>")));  // rich text's tags
    for (const std::string& name : builtinSceneNames()) rest.remove(QString::fromStdString(name));
    for (const std::string& name : builtinScene2DNames()) rest.remove(QString::fromStdString(name));
    static const QRegularExpression word(QStringLiteral("[A-Za-z_]+"));
    for (auto m = word.globalMatch(rest); m.hasNext();)
        // A single letter is a label ("b)", "x = 2"), not English.
        if (const QString w = m.next().captured();
            w.size() > 1 && !kWords.count(w) && w.toLower() != QStringLiteral("mailboxing"))
            return false;
    return true;  // numbers, symbols and the words above only
}

void add(std::vector<Shown>& out, const QString& where, const QString& text) {
    if (!text.trimmed().isEmpty()) out.push_back({where, text});
}

/// Every text of `root` and its children, in the order Qt keeps them (the same in both builds).
std::vector<Shown> textsOf(QWidget* root) {
    std::vector<Shown> out;
    add(out, "window title", root->windowTitle());
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* w : widgets) {
        const QString name =
            QString::fromUtf8(w->metaObject()->className()) + " " + w->objectName();
        add(out, name + " tooltip", w->toolTip());
        add(out, name + " status tip", w->statusTip());
        if (auto* b = qobject_cast<QAbstractButton*>(w)) add(out, name + " text", b->text());
        if (auto* l = qobject_cast<QLabel*>(w)) add(out, name + " text", l->text());
        if (auto* e = qobject_cast<QLineEdit*>(w))
            add(out, name + " placeholder", e->placeholderText());
        if (auto* d = qobject_cast<QDockWidget*>(w)) add(out, name + " title", d->windowTitle());
        if (auto* g = qobject_cast<QGroupBox*>(w)) add(out, name + " title", g->title());
        if (auto* m = qobject_cast<QMenu*>(w)) add(out, name + " title", m->title());
        if (auto* c = qobject_cast<QComboBox*>(w))
            for (int i = 0; i < c->count(); ++i) add(out, name + " item", c->itemText(i));
        if (auto* t = qobject_cast<QTextBrowser*>(w)) add(out, name + " text", t->toPlainText());
        if (auto* v = qobject_cast<QAbstractItemView*>(w); v && v->model()) {
            const QAbstractItemModel* m = v->model();
            for (int r = 0; r < std::min(m->rowCount(), 200); ++r)
                for (int c = 0; c < m->columnCount(); ++c)
                    add(out, name + " row", m->data(m->index(r, c)).toString());
            for (int c = 0; c < m->columnCount(); ++c)
                add(out, name + " header", m->headerData(c, Qt::Horizontal).toString());
            if (qobject_cast<QTableWidget*>(w))
                for (int r = 0; r < m->rowCount(); ++r)
                    add(out, name + " header", m->headerData(r, Qt::Vertical).toString());
        }
    }
    for (QAction* a : root->findChildren<QAction*>()) {
        add(out, "action " + a->text(), a->text());
        if (a->toolTip() != QString(a->text()).remove(QLatin1Char('&')))
            add(out, "action " + a->text() + " tooltip", a->toolTip());
        add(out, "action " + a->text() + " status tip", a->statusTip());
    }
    return out;
}

/// The texts `show` leaves on screen, in English then in Italian: made anew in each language,
/// as the app is made after --lang.
std::pair<std::vector<Shown>, std::vector<Shown>> inBothLanguages(
    const std::function<std::vector<Shown>(Language)>& show) {
    setInterfaceLanguage(Language::En);
    auto en = show(Language::En);
    setInterfaceLanguage(Language::It);
    auto it = show(Language::It);
    setInterfaceLanguage(Language::En);
    return {std::move(en), std::move(it)};
}

/// A text with its numbers as "#" and "; " as ", ": what is left is its words, so a line that
/// only writes its numbers the Italian way ("t = 0,5") is still seen to be English.
QString wordsOf(QString text) {
    static const QRegularExpression number(
        QStringLiteral("-?[0-9]+(?:[.,][0-9]+)?(?:e[+-]?[0-9]+)?"));
    return text.replace(number, QStringLiteral("#")).replace(QLatin1Char(';'), QLatin1Char(','));
}

/// Fails on each Italian text that is its English twin, numbers aside.
void expectItalian(const std::vector<Shown>& en, const std::vector<Shown>& it) {
    if (en.size() != it.size()) {
        // Where they part: the first widget one language shows and the other does not.
        std::size_t k = 0;
        while (k < en.size() && k < it.size() && en[k].where == it[k].where) ++k;
        FAIL() << "the two languages' windows differ in their widgets (" << en.size() << " in "
               << "English, " << it.size() << " in Italian), first at "
               << (k < en.size() ? en[k].where.toStdString() : std::string("(end)")) << " | "
               << (k < it.size() ? it[k].where.toStdString() + ": " + it[k].text.toStdString()
                                 : std::string("(end)"));
    }
    std::size_t english = 0;
    for (std::size_t i = 0; i < en.size(); ++i)
        if (wordsOf(it[i].text) == wordsOf(en[i].text) && !sameInBothLanguages(it[i].text)) {
            ++english;
            ADD_FAILURE() << it[i].where.toStdString() << ": still English: \""
                          << it[i].text.toStdString() << "\"";
        }
    EXPECT_EQ(english, 0u);
}

bool waitOpen(MainWindow& w) {
    return w.waitUntilIdle() && w.lastOpenOk().value_or(false);
}

TEST(ItalianInterface, EveryMenuActionButtonLabelAndTooltipOfTheWindowIsItalian) {
    // As the app starts: on lesson 1.
    const auto [en, it] = inBothLanguages([](Language lang) {
        MainWindow w;
        w.setLanguage(lang);
        w.openLesson(QStringLiteral("1"), /*quiet=*/true);
        EXPECT_TRUE(waitOpen(w));
        return textsOf(&w);
    });
    EXPECT_GT(en.size(), 80u);  // the walk reached the menus, the timeline and the docks
    expectItalian(en, it);
}

TEST(ItalianInterface, TheCompareWindowAndTheBuildReplayAreItalian) {
    const auto [en, it] = inBothLanguages([](Language lang) {
        MainWindow w;
        w.setLanguage(lang);
        w.openScene(QStringLiteral("lecture-kdtree"), AccelKind::KdTree, /*quiet=*/true);
        EXPECT_TRUE(waitOpen(w));
        w.replayBuild();
        EXPECT_TRUE(w.waitUntilIdle());
        w.session().setCursor(w.session().size() / 2);
        std::vector<Shown> texts = textsOf(&w);
        w.openCompare();
        EXPECT_TRUE(w.waitUntilIdle());
        EXPECT_NE(w.compareWindow(), nullptr);
        if (w.compareWindow())
            for (Shown& s : textsOf(w.compareWindow())) texts.push_back(std::move(s));
        // The slides' grid, kd-tree and BVH side by side, and the chooser that asks for them.
        w.openCompare(std::get<std::vector<StructureChoice>>(
            parseStructureChoices("grid,kdtree,bvh", std::nullopt)));
        EXPECT_TRUE(w.waitUntilIdle());
        if (w.compareWindow())
            for (Shown& s : textsOf(w.compareWindow())) texts.push_back(std::move(s));
        CompareChooser chooser(defaultComparison(AccelKind::Grid));
        for (Shown& s : textsOf(&chooser)) texts.push_back(std::move(s));
        return texts;
    });
    expectItalian(en, it);
}

TEST(ItalianInterface, EveryLessonsStepsAndExercisesAreItalian) {
    // What a lesson's panel shows at each step and each exercise: the lesson's own Italian
    // (English shows where a lesson leaves it out) and the panel's words.
    for (const Lesson& lesson : builtinLessons()) {
        SCOPED_TRACE(lesson.id);
        const auto [en, it] = inBothLanguages([&](Language lang) {
            // Each language's window opens the lesson as a new student does, at its first step
            // (the English walk saved the lesson at its last exercise, on another structure).
            QFile::remove(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                          "/progress.json");
            MainWindow w;
            w.setLanguage(lang);
            // Presenting: every prompt is shown (in quiz mode a later one waits for a held one).
            w.setLessonMode(LessonMode::Presenting);
            w.openLesson(QString::fromStdString(lesson.id), /*quiet=*/true);
            EXPECT_TRUE(waitOpen(w));
            w.tasks().cancel(TaskKind::Render);  // the image is not what is checked
            std::vector<Shown> texts;
            const auto keep = [&](const QString& where) {
                for (Shown& s : textsOf(w.lessonPanel())) {
                    s.where = where + s.where;
                    texts.push_back(std::move(s));
                }
            };
            for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
                w.lessonPanel()->goToStep(static_cast<int>(i));
                keep(QStringLiteral("step %1: ").arg(i + 1));
                // The step's filter, as the event list's box shows it (not "dda_cell").
                add(texts, QStringLiteral("step %1: event filter").arg(i + 1),
                    w.eventList()->filterShown());
            }
            for (std::size_t i = 0; i < lesson.exercises.size(); ++i) {
                w.lessonPanel()->selectExercise(static_cast<int>(i));
                keep(QStringLiteral("exercise %1: ").arg(i + 1));
            }
            return texts;
        });
        expectItalian(en, it);
    }
}

/// The inspector's lines and the event list's rows at every step of what `record` replays.
std::vector<Shown> everyStep(Session& s) {
    std::vector<Shown> out;
    EventListModel list(s, nullptr);
    for (std::size_t i = 0; i <= s.size(); ++i) {
        s.setCursor(i);
        const QString where = QStringLiteral("step %1: ").arg(i);
        for (const QString& line : describeState(s).split('\n'))
            add(out, where + "inspector", line);
        if (i < s.size())
            add(out, where + "event list",
                list.data(list.index(static_cast<int>(i)), Qt::DisplayRole).toString());
    }
    return out;
}

TEST(ItalianInterface, TheInspectorAndTheEventListAreItalianAtEveryStep) {
    const auto walk = [](const std::function<void(Session&)>& record) {
        return inBothLanguages([&](Language) {
            Session s;
            record(s);
            return everyStep(s);
        });
    };
    // The slides' DDA walk (cells, tests, mailbox skips, the hit).
    const auto [en2, it2] = walk([](Session& s) {
        s.load("lecture-grid", AccelKind::Grid);
        s.traceExampleRay();
    });
    expectItalian(en2, it2);
    // A pixel of Whitted's scene: reflection and refraction rays, shadow rays, shading terms.
    const auto [en3, it3] = walk([](Session& s) {
        s.load("whitted", AccelKind::KdTree);
        s.tracePixel(200, 120, 320, 240);  // through the glass sphere
    });
    bool sawShadowRay = false, sawRefraction = false;
    for (const Shown& line : it3) {
        sawShadowRay |= line.text.contains(QStringLiteral("raggio d'ombra"));
        sawRefraction |= line.text.contains(QStringLiteral("raggio di trasparenza"));
    }
    EXPECT_TRUE(sawShadowRay && sawRefraction) << "the pixel must exercise those events";
    expectItalian(en3, it3);
    // A pixel of the floor: a triangle's hit (the inspector shows its u, v).
    const auto [enF, itF] = walk([](Session& s) {
        s.load("whitted", AccelKind::Grid);
        s.tracePixel(60, 225, 320, 240);
    });
    expectItalian(enF, itF);
    // A kd-tree's construction: candidates, the chosen plane, leaves.
    const auto [enB, itB] = walk([](Session& s) {
        s.load("lecture-kdtree", AccelKind::KdTree);
        s.recordBuild();
    });
    expectItalian(enB, itB);
}

TEST(ItalianInterface, QtsOwnDialogsSpeakItalianToo) {
    // The buttons of Qt's message boxes and file dialogs come from Qt's qtbase_it, not ours.
    setInterfaceLanguage(Language::It);
    const QString discard = QCoreApplication::translate("QPlatformTheme", "Discard");
    const QString apply = QCoreApplication::translate("QPlatformTheme", "Apply");
    setInterfaceLanguage(Language::En);
    EXPECT_NE(discard, QStringLiteral("Discard"));
    EXPECT_NE(apply, QStringLiteral("Apply"));
    EXPECT_EQ(QCoreApplication::translate("QPlatformTheme", "Discard"), QStringLiteral("Discard"));
}

TEST(ItalianInterface, SameWordsAreAllowedOnlyFromTheShortList) {
    EXPECT_TRUE(sameInBothLanguages("raystep - %1"));
    EXPECT_TRUE(sameInBothLanguages("&File"));
    EXPECT_TRUE(sameInBothLanguages("tMaxX = 0,6   tMaxY = 0,8"));
    EXPECT_TRUE(sameInBothLanguages("kd-tree SAH"));
    EXPECT_TRUE(sameInBothLanguages("12 / 40"));
    EXPECT_TRUE(sameInBothLanguages("<b>kd-tree SAH</b>"));
    EXPECT_TRUE(sameInBothLanguages("raystep - lecture-grid"));
    EXPECT_TRUE(sameInBothLanguages("8. Mailboxing"));
    EXPECT_TRUE(sameInBothLanguages("x = 2,6   (NL 3, NR 13, P(L|C) 0,6413, P(R|C) 0,852)"));
    EXPECT_FALSE(sameInBothLanguages("Step >"));
    EXPECT_FALSE(sameInBothLanguages("nodes"));
    EXPECT_TRUE(sameInBothLanguages("c) Mip-mapping"));
    EXPECT_FALSE(sameInBothLanguages("b) Shadow rays"));
    // Numbers written the Italian way do not make a line Italian.
    EXPECT_EQ(wordsOf("hit at t = 0,5; u = -1,25e-05"), wordsOf("hit at t = 0.5, u = -1.25e-05"));
    EXPECT_NE(wordsOf("intersezione a t = 0,5"), wordsOf("hit at t = 0.5"));
}

}  // namespace
}  // namespace raystep::gui

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("raystep-tests");  // keep the user's settings apart
    QStandardPaths::setTestModeEnabled(true);            // and the user's progress
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
