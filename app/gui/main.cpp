// raystep: the replay app. It opens on lesson 1 unless told otherwise. Options for slides and
// tests: --lesson, --scene, --accel, --step, --screenshot.
#include "compare_window.h"
#include "main_window.h"
#include "session.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>
#include <QTranslator>

#include <cstdio>

namespace {
int fail(const QString& message) {
    std::fprintf(stderr, "raystep: error: %s\n", message.toUtf8().constData());
    return 2;
}
}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("raystep");
    QApplication::setApplicationName("raystep");

    QCommandLineParser parser;
    parser.setApplicationDescription("raystep: replay every step of the lecture's algorithms");
    parser.addHelpOption();
    const QCommandLineOption lessonOpt("lesson", "Open a lesson: id, number or file (default 1).",
                                       "id|file");
    const QCommandLineOption sceneOpt("scene", "Open a built-in scene or scene file instead.",
                                      "name|file");
    const QCommandLineOption lecturerOpt("lecturer",
                                         "Lecturer mode: the exercises show their answers.");
    const QCommandLineOption accelOpt("accel", "Structure: bruteforce, grid, kdtree or bvh.",
                                      "kind", "grid");
    const QCommandLineOption stepOpt("step", "Put the replay cursor after N events.", "N");
    const QCommandLineOption replayOpt("replay", "What to replay: ray (the default) or build.",
                                       "ray|build", "ray");
    const QCommandLineOption langOpt("lang", "Interface language: en or it.", "en|it", "en");
    const QCommandLineOption compareOpt(
        "compare",
        "Also open compare mode (midpoint, median, SAH) on the scene; "
        "--screenshot then saves that window.");
    const QCommandLineOption shotOpt(
        "screenshot", "Show the window, let it paint, save it as PNG, exit.", "file");
    parser.addOptions({lessonOpt, sceneOpt, accelOpt, replayOpt, stepOpt, compareOpt, langOpt,
                       lecturerOpt, shotOpt});
    if (!parser.parse(QApplication::arguments())) return fail(parser.errorText());
    if (parser.isSet("help")) parser.showHelp(0);

    // The Italian interface: the translation compiled next to the binary (app/gui/i18n).
    const QString lang = parser.value(langOpt);
    QTranslator translator;
    if (lang == "it") {
        const QString qm = QCoreApplication::applicationDirPath() + "/raystep_it.qm";
        if (!translator.load(qm)) return fail("--lang it: cannot load " + qm);
        QApplication::installTranslator(&translator);
    } else if (lang != "en") {
        return fail("--lang " + lang + ": expected en or it");
    }
    const auto kind = raystep::parseAccelKind(parser.value(accelOpt).toStdString());
    if (!kind)
        return fail("--accel " + parser.value(accelOpt) +
                    ": expected bruteforce, grid, kdtree or bvh");
    const QString replay = parser.value(replayOpt);
    if (replay != "ray" && replay != "build")
        return fail("--replay " + replay + ": expected ray or build");
    std::optional<std::size_t> step;
    if (parser.isSet(stepOpt)) {
        bool ok = false;
        const qlonglong n = parser.value(stepOpt).toLongLong(&ok);
        if (!ok || n < 0)
            return fail("--step " + parser.value(stepOpt) + ": expected a whole number, 0 or more");
        step = static_cast<std::size_t>(n);
    }
    const QString shot = parser.value(shotOpt);
    if (!shot.isEmpty() && !shot.endsWith(".png", Qt::CaseInsensitive))
        return fail("--screenshot " + shot + ": the screenshot is written as PNG; name it *.png");

    if (parser.isSet(lessonOpt) && parser.isSet(sceneOpt))
        return fail("--lesson and --scene: give one of them");

    raystep::gui::MainWindow window;
    window.setLanguage(lang == "it" ? raystep::Language::It : raystep::Language::En);
    window.setLecturerMode(parser.isSet(lecturerOpt));
    if (parser.isSet(sceneOpt)) {
        if (!window.openScene(parser.value(sceneOpt), *kind, /*quiet=*/!shot.isEmpty()) &&
            !shot.isEmpty())  // from a script: one line; interactively the dialog has said it
            return fail("--scene " + parser.value(sceneOpt) + ": cannot be opened");
    } else {
        const QString lesson =
            parser.isSet(lessonOpt) ? parser.value(lessonOpt) : QStringLiteral("1");
        if (!window.openLesson(lesson, /*quiet=*/!shot.isEmpty()) && !shot.isEmpty()) {
            try {
                raystep::loadLesson(lesson.toStdString());
            } catch (const raystep::LessonError& e) {
                return fail(QString::fromUtf8(e.what()));
            }
            return fail("--lesson " + lesson + ": cannot be opened");
        }
    }
    if (replay == "build") window.session().recordBuild();
    if (step) {
        if (*step > window.session().size())
            return fail(QStringLiteral("--step %1: the replay has %2 events")
                            .arg(*step)
                            .arg(window.session().size()));
        window.session().setCursor(*step);
    }
    window.resize(1500, 900);
    window.show();
    QWidget* shown = &window;
    if (parser.isSet(compareOpt)) {
        shown = window.openCompare();
        if (!shown) return fail("--compare: compare mode could not be opened");
    }
    if (shot.isEmpty()) return app.exec();

    // Slides and tests: let every view paint (and a 3D render finish), then save the window.
    QTimer::singleShot(200, &window, [&] {
        window.waitForRender();
        const QImage image = shown->grab().toImage();
        if (!image.save(shot, "PNG")) {
            fail("--screenshot " + shot + ": cannot write the file");
            QApplication::exit(2);
            return;
        }
        std::printf("wrote %s (%dx%d): %s\n", shot.toUtf8().constData(), image.width(),
                    image.height(), shown->windowTitle().toUtf8().constData());
        QApplication::exit(0);
    });
    return app.exec();
}
