// raystep: the replay app. It opens on lesson 1 unless told otherwise. Options for slides and
// tests: --lesson, --scene, --accel, --step, --student-trace, --screenshot.
#include "compare_window.h"
#include "language.h"
#include "lesson_panel.h"
#include "main_window.h"
#include "session.h"

#include "raystep/base/file_error.h"
#include "raystep/scene/model_import.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

#include <cstdio>

namespace {
int fail(const QString& message) {
    // One line whatever the message quotes (an option's value, a file's name).
    std::fprintf(stderr, "raystep: error: %s\n",
                 raystep::printable(message.toStdString(), 4096).c_str());
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
    const QCommandLineOption sceneOpt(
        "scene", "Open a built-in scene, a scene file or a model (.obj .ply .stl .gltf .glb).",
        "name|file");
    const QCommandLineOption lecturerOpt("lecturer",
                                         "Lecturer mode: the exercises show their answers.");
    const QCommandLineOption presentOpt(
        "present",
        "Presenting mode: every step and view free, the exercises questions to the room, an "
        "answer shown when revealed. Without --present or --lecturer, quiz mode (a mode is never "
        "remembered from one run to the next).");
    const QCommandLineOption accelOpt(
        "accel",
        QString::fromStdString("Structure: " + raystep::kindList() +
                               " (default: grid; kdtree for a model)."),
        "kind", "grid");
    const QCommandLineOption stepOpt("step", "Put the replay cursor after N events.", "N");
    const QCommandLineOption replayOpt("replay", "What to replay: ray (the default) or build.",
                                       "ray|build", "ray");
    // The languages (base/i18n.h), with those of a RAYSTEP_LANGUAGES folder: a bad one is bad
    // input.
    std::string languageCodes;
    try {
        for (const raystep::Language l : raystep::languages()) {
            languageCodes += languageCodes.empty() ? "" : "|";
            languageCodes += l.code();
        }
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    const QCommandLineOption langOpt(
        "lang", QString::fromStdString("Interface language: " + raystep::languageChoices() + "."),
        QString::fromStdString(languageCodes), "en");
    const QCommandLineOption compareOpt(
        "compare",
        "Also open compare mode on the scene: the structures --accel lists (grid,kdtree,bvh: "
        "trees by SAH), or a tree's split methods (midpoint, median, SAH), or for one grid the "
        "slides' grid, kd-tree and BVH; --screenshot then saves that window.");
    const QCommandLineOption studentOpt(
        "student-trace",
        "Then open a student's trace (JSON Lines) and check it against the scene's structure, as "
        "File > Open student trace does.",
        "file");
    const QCommandLineOption shotOpt(
        "screenshot", "Show the window, let it paint, save it as PNG, exit.", "file");
    parser.addOptions({lessonOpt, sceneOpt, accelOpt, replayOpt, stepOpt, compareOpt, langOpt,
                       lecturerOpt, presentOpt, studentOpt, shotOpt});
    if (!parser.parse(QApplication::arguments())) return fail(parser.errorText());
    if (parser.isSet("help")) parser.showHelp(0);

    // The interface's language, before any widget takes its texts (language.h).
    const QString lang = parser.value(langOpt);
    const auto language = raystep::parseLanguage(lang.toStdString());
    if (!language)
        return fail("--lang " + lang + ": expected " +
                    QString::fromStdString(raystep::languageChoices()));
    raystep::gui::setInterfaceLanguage(*language);
    // With --compare, --accel may list several structures; the first is the one opened.
    std::vector<raystep::StructureChoice> compared;
    const std::string accelText = parser.value(accelOpt).toStdString();
    if (parser.isSet(compareOpt) && accelText.find(',') != std::string::npos) {
        const auto parsed = raystep::parseStructureChoices(accelText, std::nullopt);
        if (const auto* problem = std::get_if<std::string>(&parsed))
            return fail(QString::fromStdString(*problem));
        compared = std::get<std::vector<raystep::StructureChoice>>(parsed);
    }
    const auto kind = compared.empty() ? raystep::parseAccelKind(accelText) : compared.front().kind;
    if (!kind)
        return fail(
            "--accel " + parser.value(accelOpt) + ": expected " +
            QString::fromStdString(raystep::kindList()) +
            (parser.isSet(compareOpt) ? " (or, with --compare, a comma list of them)" : ""));
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
    if (parser.isSet(lecturerOpt) && parser.isSet(presentOpt))
        return fail("--lecturer and --present: give one of them");

    raystep::gui::MainWindow window;
    window.setLanguage(*language);
    if (parser.isSet(lecturerOpt)) window.setLessonMode(raystep::gui::LessonMode::Lecturer);
    if (parser.isSet(presentOpt)) window.setLessonMode(raystep::gui::LessonMode::Presenting);
    // Slides are made at one size; otherwise the user's own size, or one that fits the screen.
    if (!shot.isEmpty())
        window.resize(1500, 900);
    else
        window.sizeForScreen();
    window.show();

    // Opening runs in the background; what the options ask for follows once it is done.
    const bool quiet = !shot.isEmpty();
    QString opening;
    if (parser.isSet(sceneOpt)) {
        opening = "--scene " + parser.value(sceneOpt);
        // A model is a big mesh more often than not: a kd-tree (SAH) unless --accel says.
        const bool model = raystep::isModelPath(parser.value(sceneOpt).toStdString());
        window.openScene(parser.value(sceneOpt),
                         model && !parser.isSet(accelOpt) ? raystep::AccelKind::KdTree : *kind,
                         quiet);
    } else {
        const QString lesson =
            parser.isSet(lessonOpt) ? parser.value(lessonOpt) : QStringLiteral("1");
        opening = "--lesson " + lesson;
        window.openLesson(lesson, quiet);
    }
    QWidget* shown = &window;
    // From a script a failure is one line and exit 2; interactively the dialog has said it.
    const auto scriptFails = [&](const QString& message) {
        if (shot.isEmpty()) return false;
        fail(message);
        QApplication::exit(2);
        return true;
    };
    const auto screenshot = [&] {
        if (shot.isEmpty()) return;
        const QImage image = shown->grab().toImage();
        if (const QString problem = raystep::gui::savePng(image, shot); !problem.isEmpty()) {
            scriptFails("--screenshot " + problem);
            return;
        }
        std::printf("wrote %s (%dx%d): %s\n", shot.toUtf8().constData(), image.width(),
                    image.height(), shown->windowTitle().toUtf8().constData());
        QApplication::exit(0);
    };
    const auto afterReplay = [&] {
        if (parser.isSet(studentOpt)) {
            const QString problem = window.openStudentTrace(parser.value(studentOpt), quiet);
            if (!problem.isEmpty() && scriptFails("--student-trace " + problem)) return;
        }
        if (step) {
            if (*step > window.session().size()) {
                scriptFails(QStringLiteral("--step %1: the replay has %2 events")
                                .arg(*step)
                                .arg(window.session().size()));
                return;
            }
            window.session().setCursor(*step);
        }
        if (parser.isSet(compareOpt)) {
            if (compared.empty())
                window.openCompare();
            else
                window.openCompare(compared);
        }
        window.whenIdle([&] {
            if (parser.isSet(compareOpt)) {
                if (!window.compareWindow()) {
                    scriptFails("--compare: compare mode could not be opened");
                    return;
                }
                shown = window.compareWindow();
            }
            // Let every view paint before the picture is taken.
            QTimer::singleShot(200, &window, screenshot);
        });
    };
    window.whenIdle([&] {
        if (!window.lastOpenOk().value_or(false)) {
            scriptFails(opening + ": " + window.lastOpenError());
            return;
        }
        if (replay == "build") window.replayBuild();
        window.whenIdle(afterReplay);
    });
    return app.exec();
}
