// The app with bad or huge models and with a progress file that cannot be read or saved: an
// import that never ends is cancelled and Ctrl+Q quits within a second; brute force on a huge
// model is asked about first, bounded in memory and cancelled within a second; an unreadable
// progress file is kept aside under a name of its own, and a save that fails says why, keeps
// the answers and warns at quit.
#include "gui_testing.h"
#include "lesson_controller.h"
#include "lesson_panel.h"
#include "main_window.h"
#include "progress_store.h"

#include <gtest/gtest.h>

#include "course/progress.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLockFile>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>

#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace raystep::gui {
namespace {

namespace fs = std::filesystem;
const QString kModels = RAYSTEP_SOURCE_DIR "/tests/data/models/";

/// Peak and current resident memory of this process, in MB (/proc/self/status).
std::pair<double, double> memoryMb() {
    std::ifstream in("/proc/self/status");
    std::string line;
    double peak = 0, now = 0;
    while (std::getline(in, line)) {
        if (line.rfind("VmHWM:", 0) == 0) peak = std::stod(line.substr(6)) / 1024;
        if (line.rfind("VmRSS:", 0) == 0) now = std::stod(line.substr(6)) / 1024;
    }
    return {peak, now};
}

/// Processes events until `done` or `ms` pass; the longest the GUI thread was away meanwhile
/// (a 10 ms timer's largest gap), in ms.
template <typename F>
double runUntil(F&& done, int ms) {
    QElapsedTimer clock, since;
    clock.start();
    since.start();
    double worst = 0;
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] {
        worst = std::max(worst, double(since.elapsed()));
        since.restart();
    });
    beat.start(10);
    while (!done() && clock.elapsed() < ms) {
        QApplication::processEvents(QEventLoop::AllEvents, 20);
        worst = std::max(worst, double(since.elapsed()));
    }
    return worst;
}

QMessageBox* visibleBox(QWidget& w) {
    for (QMessageBox* b : w.findChildren<QMessageBox*>())
        if (b->isVisible()) return b;
    return nullptr;
}

/// A HOME of its own for one test (the progress file is under it: the tests' QStandardPaths
/// test mode puts the data folder in ~/.qttest), restored after.
class OwnHome {
  public:
    OwnHome() : old_(qgetenv("HOME")) { qputenv("HOME", dir.path().toUtf8()); }
    ~OwnHome() { qputenv("HOME", old_); }
    QString progressPath() const {
        return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/progress.json";
    }
    QTemporaryDir dir;

  private:
    QByteArray old_;
};

QByteArray slurp(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void put(const QString& path, const QByteArray& bytes) {
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
}

QMessageBox* boxNamed(QWidget& w, const char* name) {
    QApplication::processEvents();
    QApplication::processEvents();
    auto* box = w.findChild<QMessageBox*>(name);
    return box && box->isVisible() ? box : nullptr;
}

QAbstractButton* buttonWithRole(QMessageBox* box, QMessageBox::ButtonRole role) {
    for (QAbstractButton* b : box->buttons())
        if (box->buttonRole(b) == role) return b;
    return nullptr;
}

// Review 3, class 5: a second unreadable progress file was written over while the app said it
// was kept, since the name it was kept under was taken. Each is kept under a name of its own,
// byte for byte, and the student is told where (a dialog); the first answer then starts a new
// file.
TEST(RobustProgress, EveryUnreadableFileIsKeptAsideUnderANameOfItsOwn) {
    OwnHome home;
    const QString path = home.progressPath();
    const QByteArray broken = "{\"lessons\": {\"raster-vs-raytracing\": {\"step\": 2, ";
    // A newer raystep's file: valid JSON with a key this one does not know.
    const QByteArray newer = "{\"lessons\": {}, \"streak\": 3}\n";
    put(path, broken);
    {
        MainWindow w;
        w.show();
        QMessageBox* box = boxNamed(w, "progressUnreadable");
        ASSERT_NE(box, nullptr);
        EXPECT_TRUE(box->text().contains(path + ".unreadable-1")) << box->text().toStdString();
        box->close();
        EXPECT_EQ(slurp(path + ".unreadable-1"), broken);
        EXPECT_FALSE(QFileInfo::exists(path));
    }
    put(path, newer);
    {
        MainWindow w;
        w.show();
        QMessageBox* box = boxNamed(w, "progressUnreadable");
        ASSERT_NE(box, nullptr);
        EXPECT_TRUE(box->text().contains(path + ".unreadable-2")) << box->text().toStdString();
        box->close();
        EXPECT_EQ(slurp(path + ".unreadable-1"), broken);  // the first one is still there
        EXPECT_EQ(slurp(path + ".unreadable-2"), newer);
        // The first step saves a new file, readable.
        ASSERT_TRUE(openLesson(w, "1"));
        w.lessonPanel()->goToStep(1);
        const Progress saved = parseProgress(slurp(path).toStdString(), "progress.json");
        EXPECT_EQ(saved.lessons.at("raster-vs-raytracing").step, 1);
        EXPECT_FALSE(w.findChild<QLabel*>("progressNote")->isVisible());
    }
}

// A file that becomes unreadable while the window is open (another window, a hand) is kept
// aside at the next save too, not replaced by what this window knows.
TEST(RobustProgress, AFileBrokenMeanwhileIsKeptAsideAtTheNextSave) {
    OwnHome home;
    const QString path = home.progressPath();
    MainWindow w;
    w.show();
    ASSERT_TRUE(openLesson(w, "1"));
    const QByteArray broken = "{\"lessons\": [1, 2";
    put(path, broken);
    w.lessonPanel()->goToStep(1);
    QMessageBox* box = boxNamed(w, "progressUnreadable");
    ASSERT_NE(box, nullptr);
    box->close();
    EXPECT_EQ(slurp(path + ".unreadable-1"), broken);
    EXPECT_EQ(parseProgress(slurp(path).toStdString(), "p").lessons.at("raster-vs-raytracing").step,
              1);
}

// Review 3, class 14: a save that failed said "locked" whatever the reason, the answers were
// dropped at quit without a word, and only the status bar said anything. Now the reason is
// named, a note stays in the status bar, the answers stay in memory, the next answer saves
// them, and quitting with answers unsaved asks first.
TEST(RobustProgress, AFailedSaveSaysWhyKeepsTheAnswersRetriesAndAsksAtQuit) {
    OwnHome home;
    const QString path = home.progressPath();
    MainWindow w;
    w.show();
    ASSERT_TRUE(openLesson(w, "1"));
    QLabel* note = w.findChild<QLabel*>("progressNote");
    ASSERT_NE(note, nullptr);
    EXPECT_FALSE(note->isVisible());
    const QByteArray before = slurp(path);
    // Another window holds the lock (as a stuck one would).
    QLockFile other(path + ".lock");
    ASSERT_TRUE(other.tryLock(0));
    w.lessonPanel()->goToStep(2);
    EXPECT_TRUE(note->isVisible());
    EXPECT_TRUE(note->text().contains("another raystep window holds the lock"))
        << note->text().toStdString();
    EXPECT_EQ(w.studentProgress().lessons.at("raster-vs-raytracing").step, 2);  // in memory
    EXPECT_EQ(slurp(path), before);                                             // untouched
    // Free again: the next step saves everything.
    other.unlock();
    w.lessonPanel()->goToStep(1);
    EXPECT_FALSE(note->isVisible());
    EXPECT_EQ(parseProgress(slurp(path).toStdString(), "p").lessons.at("raster-vs-raytracing").step,
              1);
    // Unsaved at quit: the window asks, and stays until told to quit without saving.
    ASSERT_TRUE(other.tryLock(0));
    w.lessonPanel()->goToStep(2);
    ASSERT_TRUE(note->isVisible());
    EXPECT_FALSE(w.close());
    EXPECT_TRUE(w.isVisible());
    QMessageBox* box = boxNamed(w, "unsavedProgress");
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->text().contains("another raystep window holds the lock"));
    QAbstractButton* quit = buttonWithRole(box, QMessageBox::DestructiveRole);
    ASSERT_NE(quit, nullptr);
    quit->click();
    QApplication::processEvents();
    EXPECT_FALSE(w.isVisible());
    other.unlock();
}

// A full disk (a 64 KB tmpfs as the data folder, filled): named as such, the old file whole.
// Mounting needs root; skipped otherwise.
TEST(RobustProgress, AFullDiskIsNamedAndTheOldFileStaysWhole) {
    OwnHome home;
    const QString path = home.progressPath();
    const QString folder = QFileInfo(path).absolutePath();
    QDir().mkpath(folder);
    if (::mount("tmpfs", QFile::encodeName(folder).constData(), "tmpfs", 0, "size=64k") != 0)
        GTEST_SKIP() << "mounting a tmpfs needs root";
    struct Unmount {
        QString at;
        ~Unmount() { ::umount2(QFile::encodeName(at).constData(), MNT_DETACH); }
    } unmount{folder};
    MainWindow w;
    w.show();
    ASSERT_TRUE(openLesson(w, "1"));
    const QByteArray before = slurp(path);
    ASSERT_FALSE(before.isEmpty());
    {
        QFile fill(folder + "/fill");
        ASSERT_TRUE(fill.open(QIODevice::WriteOnly));
        const QByteArray block(4096, 'x');
        while (fill.write(block) == block.size() && fill.flush()) {
        }
    }
    w.lessonPanel()->goToStep(2);
    QLabel* note = w.findChild<QLabel*>("progressNote");
    EXPECT_TRUE(note->isVisible());
    EXPECT_TRUE(note->text().contains("the disk is full")) << note->text().toStdString();
    EXPECT_EQ(slurp(path), before);
    EXPECT_EQ(w.studentProgress().lessons.at("raster-vs-raytracing").step, 2);
    // Room again: the next step saves.
    QFile::remove(folder + "/fill");
    w.lessonPanel()->goToStep(1);
    EXPECT_FALSE(note->isVisible());
}

// Not a test of its own: the process the next test kills, saving as fast as it can.
TEST(RobustProgress, DISABLED_SaveForEver) {
    const QByteArray path = qgetenv("RAYSTEP_SAVE_FOREVER");
    if (path.isEmpty()) GTEST_SKIP();
    ProgressStore store{QString::fromUtf8(path)};
    for (int n = 0;; ++n) {
        Progress p;
        // Files of different sizes, so a torn write would show.
        for (int i = 0; i < 1 + n % 50; ++i) p.lessons["lesson-" + std::to_string(i)].step = n;
        ProgressStore::Unreadable u;
        store.save(p, u);
    }
}

// Review 3: writes survive a kill at any point. A process saving in a loop is killed (SIGKILL)
// twelve times at different moments; the file always reads as a whole progress file.
TEST(RobustProgress, AKillAtAnyPointLeavesAWholeFile) {
    OwnHome home;
    const QString path = home.dir.filePath("progress.json");
    for (int k = 0; k < 12; ++k) {
        QProcess saver;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("RAYSTEP_SAVE_FOREVER", path);
        saver.setProcessEnvironment(env);
        QFile::remove(path);
        saver.start(QCoreApplication::applicationFilePath(),
                    {"--gtest_also_run_disabled_tests",
                     "--gtest_filter=RobustProgress.DISABLED_SaveForEver"});
        ASSERT_TRUE(saver.waitForStarted());
        // Until its first save is there (a loaded machine starts it slowly), then a little
        // more: 0 to 55 ms of saving.
        for (int i = 0; i < 6000 && !QFileInfo::exists(path); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        std::this_thread::sleep_for(std::chrono::milliseconds(5 * k));
        ::kill(static_cast<pid_t>(saver.processId()), SIGKILL);
        saver.waitForFinished();
        ASSERT_TRUE(QFileInfo::exists(path)) << "kill " << k;
        EXPECT_NO_THROW(parseProgress(slurp(path).toStdString(), "progress.json")) << "kill " << k;
    }
    // What a kill can leave beside it (docs/reliability.md): QSaveFile's temporary, the lock.
    const QStringList left = QDir(home.dir.path()).entryList(QDir::Files);
    std::printf("after 12 kills the folder holds: %s\n", left.join(", ").toStdString().c_str());
}

/// RAYSTEP_IMPORTER for one test: the app's importer replaced by a script (one that never
/// ends, or one that crashes), restored after.
class OtherImporter {
  public:
    explicit OtherImporter(const QByteArray& script) {
        path_ = dir_.filePath("importer");
        put(path_, script);
        ::chmod(QFile::encodeName(path_).constData(), 0755);
        qputenv("RAYSTEP_IMPORTER", QFile::encodeName(path_));
    }
    ~OtherImporter() { qunsetenv("RAYSTEP_IMPORTER"); }

  private:
    QTemporaryDir dir_;
    QString path_;
};

// Review 3, class 4: an import that never ended showed "Loading ... 0%" for ever, and neither
// Cancel nor Ctrl+Q ended it (closing joined the loader thread). The importer is a process the
// window kills: both take effect within a second.
TEST(RobustModels, AnImportThatNeverEndsIsCancelledAndQuitWithinASecond) {
    const OtherImporter hangs("#!/bin/sh\nexec sleep 600\n");
    {
        MainWindow w;
        w.show();
        w.openScene(kModels + "tetra.ply", AccelKind::KdTree, true);
        runUntil([] { return false; }, 300);
        ASSERT_TRUE(w.tasks().busy(TaskKind::Scene));
        QElapsedTimer t;
        t.start();
        w.findChild<QPushButton*>("cancelTask")->click();
        runUntil([&] { return !w.tasks().busy(); }, 10000);
        // Killed at once (0.1 s, the importer's poll); the bound leaves room for a loaded CI
        // machine, and an import not killed would hang for 600 s.
        EXPECT_LT(t.elapsed(), 3000);
        EXPECT_FALSE(w.lastOpenOk().value_or(true));
        EXPECT_EQ(w.lastOpenError(), "cancelled");
    }
    MainWindow w;
    w.show();
    w.openScene(kModels + "tetra.ply", AccelKind::KdTree, true);
    runUntil([] { return false; }, 300);
    ASSERT_TRUE(w.tasks().busy(TaskKind::Scene));
    QElapsedTimer t;
    t.start();
    EXPECT_TRUE(w.close());  // Ctrl+Q's action
    EXPECT_LT(t.elapsed(), 3000);
    EXPECT_EQ(w.tasks().threads(), 0u);
}

// An importer that crashes (as assimp did on a PLY header without end_header, or an .mtl
// texture before newmtl) is one line naming the model; the window keeps what it showed.
TEST(RobustModels, AnImporterThatCrashesIsOneLine) {
    MainWindow w;
    w.show();
    w.openScene(kModels + "pyramid.obj", AccelKind::KdTree, true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    const SceneRef shown = w.session().sceneRef();
    const OtherImporter crashes("#!/bin/sh\nkill -SEGV $$\n");
    w.openScene(kModels + "tetra.ply", AccelKind::KdTree, true);
    ASSERT_TRUE(w.waitUntilIdle());
    EXPECT_FALSE(w.lastOpenOk().value_or(true));
    const QString error = w.lastOpenError();
    EXPECT_TRUE(error.contains("tetra.ply")) << error.toStdString();
    EXPECT_TRUE(error.contains("crashed inside assimp (a segmentation fault)"))
        << error.toStdString();
    EXPECT_FALSE(error.contains('\n'));
    EXPECT_EQ(w.session().sceneRef(), shown);
}

/// An OBJ grid of 2 n^2 triangles, in `dir`.
QString gridModel(const QTemporaryDir& dir, int n) {
    const QString path = dir.filePath("grid.obj");
    std::ofstream out(path.toStdString());
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) out << "v " << i << " " << (i * j) % 7 << " " << j << "\n";
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
            out << "f " << a << " " << b << " " << d << "\nf " << a << " " << d << " " << c << "\n";
        }
    return path;
}

// Review 3 and gui.md 2: brute force on a big model froze the window for 40 s at 9.5 GB with
// "0%" and no working Cancel. Past 200,000 primitives the chooser asks first; chosen, the first
// pixel is traced in the background and keeps at most 50,000 events; Cancel stops the render
// within a second. 2 x 360^2 = 259,200 triangles (and the floor's 2).
TEST(RobustModels, BruteForceOnABigModelIsAskedAboutBoundedAndCancelled) {
    QTemporaryDir dir;
    MainWindow w;
    w.resize(1200, 800);
    w.show();
    w.openScene(gridModel(dir, 360), AccelKind::Grid, true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false))
        << w.lastOpenError().toStdString();
    ASSERT_EQ(w.session().scene3D()->primitiveCount(), 259202u);
    QComboBox* chooser = w.structureChooser();
    const auto pickBruteForce = [&] {
        const int index = chooser->findText("brute force");
        chooser->setCurrentIndex(index);
        emit chooser->activated(index);
        return boxNamed(w, "bruteForceQuestion");
    };
    bool built = false, answered = false;
    QObject::connect(&w, &MainWindow::structureChanged, [&](bool ok, const QString&) {
        answered = true;
        built = ok;
    });
    // Kept: the grid stays, the chooser says so.
    QMessageBox* ask = pickBruteForce();
    ASSERT_NE(ask, nullptr);
    EXPECT_TRUE(ask->text().contains("259202")) << ask->text().toStdString();
    buttonWithRole(ask, QMessageBox::RejectRole)->click();
    runUntil([&] { return answered; }, 5000);
    EXPECT_FALSE(built);
    EXPECT_EQ(w.session().kind(), AccelKind::Grid);
    EXPECT_EQ(chooser->currentText(), "grid");
    // Chosen: built; the window stays free while its first pixel is traced.
    answered = false;
    ask = pickBruteForce();
    ASSERT_NE(ask, nullptr);
    buttonWithRole(ask, QMessageBox::AcceptRole)->click();
    const double stall =
        runUntil([&] { return answered && !w.tasks().busy(TaskKind::Pixel); }, 120000);
    ASSERT_TRUE(built);
    EXPECT_EQ(w.session().kind(), AccelKind::BruteForce);
    // The centre pixel's three rays test every primitive: 3 x 259,202 events, capped.
    EXPECT_EQ(w.session().size(), 50000u);
    // Traced on the GUI thread it was away about 18 s (82.5 s on 1.2 M triangles); in the
    // background well under a second quiet. The bound leaves room for a loaded CI machine.
    EXPECT_LT(stall, 5000);
    // The image renders by brute force meanwhile: Cancel stops it within a second.
    ASSERT_TRUE(w.tasks().busy(TaskKind::Render));
    QElapsedTimer t;
    t.start();
    w.findChild<QPushButton*>("cancelTask")->click();
    const double away = runUntil([&] { return !w.tasks().busy(TaskKind::Render); }, 30000);
    std::printf("render stopped after %lld ms (the GUI thread away at most %.0f ms)\n",
                (long long)t.elapsed(), away);
    runUntil([&] { return !w.tasks().busy(); }, 30000);
    // Measured 0.3 to 0.8 s here on a loaded machine (docs/reliability.md); a render that did
    // not look at Cancel ran on for minutes. The bound leaves room for a loaded CI machine.
    EXPECT_LT(t.elapsed(), 5000);
}

// Review 3, class 12, in the app: File > Save scene as may not write over a file the model
// refers to (here a glTF whose buffer is named like the scene file to be saved).
TEST(RobustModels, SaveSceneAsNeverOverwritesAFileTheModelRefersTo) {
    QTemporaryDir dir;
    QByteArray gltf = slurp(kModels + "external.gltf");
    gltf.replace("external.bin", "saved.json");
    put(dir.filePath("model.gltf"), gltf);
    const QByteArray buffer = slurp(kModels + "external.bin");
    put(dir.filePath("saved.json"), buffer);
    MainWindow w;
    w.openScene(dir.filePath("model.gltf"), AccelKind::KdTree, true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false))
        << w.lastOpenError().toStdString();
    const QString why = w.saveModelScene(dir.filePath("saved.json"));
    EXPECT_TRUE(why.contains("which the model refers to")) << why.toStdString();
    EXPECT_EQ(slurp(dir.filePath("saved.json")), buffer);
    EXPECT_FALSE(QFileInfo::exists(dir.filePath("saved.mesh.obj")));
}

// gui.md 18: glmark2's cat.3ds said "a NUL byte: a JSON file is text"; a type raystep does not
// read is named as such, in one line, and the scene shown stays.
TEST(RobustModels, AnUnsupportedFileTypeIsNamedAsSuch) {
    QTemporaryDir dir;
    put(dir.filePath("cat.3ds"), QByteArray("MM\0\0", 4));
    MainWindow w;
    w.openScene("whitted", AccelKind::KdTree, true);
    ASSERT_TRUE(w.waitUntilIdle() && w.lastOpenOk().value_or(false));
    w.openScene(dir.filePath("cat.3ds"), AccelKind::KdTree, true);
    ASSERT_TRUE(w.waitUntilIdle());
    EXPECT_FALSE(w.lastOpenOk().value_or(true));
    EXPECT_TRUE(w.lastOpenError().endsWith(
        "cat.3ds: not a scene or model raystep reads (.json, .obj, .ply, .stl, .gltf, .glb)"))
        << w.lastOpenError().toStdString();
    EXPECT_EQ(w.session().name(), "whitted");
}

// Pictures of what the student and the lecturer see (not run by ctest): RAYSTEP_SHOTS names
// a folder; the window with the unsaved-progress note, the unreadable-file dialog, the quit
// question, and the brute-force question.
TEST(RobustModels, DISABLED_Screenshots) {
    const QString shots = qEnvironmentVariable("RAYSTEP_SHOTS");
    ASSERT_FALSE(shots.isEmpty());
    OwnHome home;
    const QString path = home.progressPath();
    put(path, "{\"lessons\": ");
    MainWindow w;
    w.resize(1366, 768);
    w.show();
    QMessageBox* box = boxNamed(w, "progressUnreadable");
    ASSERT_NE(box, nullptr);
    box->grab().save(shots + "/progress-unreadable.png");
    box->close();
    ASSERT_TRUE(openLesson(w, "6"));
    QLockFile other(path + ".lock");
    ASSERT_TRUE(other.tryLock(0));
    w.lessonPanel()->goToStep(1);
    runUntil([] { return false; }, 300);
    w.grab().save(shots + "/progress-not-saved.png");
    w.close();
    box = boxNamed(w, "unsavedProgress");
    ASSERT_NE(box, nullptr);
    box->grab().save(shots + "/progress-quit-question.png");
    buttonWithRole(box, QMessageBox::DestructiveRole)->click();
    other.unlock();
    QTemporaryDir dir;
    MainWindow m;
    m.resize(1366, 768);
    m.show();
    m.openScene(gridModel(dir, 360), AccelKind::Grid, true);
    ASSERT_TRUE(m.waitUntilIdle() && m.lastOpenOk().value_or(false));
    QComboBox* chooser = m.structureChooser();
    const int index = chooser->findText("brute force");
    chooser->setCurrentIndex(index);
    emit chooser->activated(index);
    box = boxNamed(m, "bruteForceQuestion");
    ASSERT_NE(box, nullptr);
    box->grab().save(shots + "/brute-force-question.png");
    buttonWithRole(box, QMessageBox::RejectRole)->click();
}

// Measured, not run by ctest (a 1.2 M-triangle model is no unit test): scripts/measure_huge.sh
// makes the model and runs this with --gtest_also_run_disabled_tests, printing the figures.
TEST(RobustModels, DISABLED_BruteForceOnAHugeModel) {
    const char* path = std::getenv("RAYSTEP_HUGE_MODEL");
    ASSERT_NE(path, nullptr) << "RAYSTEP_HUGE_MODEL names the model";
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QElapsedTimer t;
    t.start();
    w.openScene(path, AccelKind::KdTree, true);
    const double openStall = runUntil(
        [&] { return w.lastOpenOk().has_value() && !w.tasks().busy(TaskKind::Scene); }, 600000);
    ASSERT_TRUE(w.lastOpenOk().value_or(false)) << w.lastOpenError().toStdString();
    std::printf(
        "open (import + kd-tree): %.1f s, GUI thread away at most %.0f ms, memory %.0f MB "
        "(peak %.0f MB)\n",
        t.elapsed() / 1000.0, openStall, memoryMb().second, memoryMb().first);
    runUntil([&] { return !w.tasks().busy(); }, 120000);

    // The user picks brute force.
    t.restart();
    QComboBox* box = w.structureChooser();
    const int index = box->findText("brute force");
    box->setCurrentIndex(index);
    emit box->activated(index);
    QApplication::processEvents();
    if (QMessageBox* ask = visibleBox(w)) {
        std::printf("asked first: %s\n", ask->text().toStdString().c_str());
        for (QAbstractButton* b : ask->buttons())
            if (ask->buttonRole(b) == QMessageBox::AcceptRole) b->click();
    } else {
        std::printf("not asked first\n");
    }
    bool changed = false;
    QObject::connect(&w, &MainWindow::structureChanged,
                     [&](bool ok, const QString&) { changed = ok; });
    const double stall = runUntil([&] { return changed; }, 600000);
    std::printf(
        "brute force built and shown: %.1f s, GUI thread away at most %.0f ms, memory "
        "%.0f MB (peak %.0f MB), replay of %zu events\n",
        t.elapsed() / 1000.0, stall, memoryMb().second, memoryMb().first, w.session().size());
    // Its first pixel, traced in the background.
    t.restart();
    const double pixelStall = runUntil([&] { return !w.tasks().busy(TaskKind::Pixel); }, 600000);
    std::printf(
        "first pixel traced: %.1f s more, GUI thread away at most %.0f ms, memory %.0f MB "
        "(peak %.0f MB), replay of %zu events\n",
        t.elapsed() / 1000.0, pixelStall, memoryMb().second, memoryMb().first, w.session().size());
    // The image renders by brute force meanwhile: Cancel, and how long until it stops.
    runUntil([] { return false; }, 2000);
    t.restart();
    w.findChild<QPushButton*>("cancelTask")->click();
    const double cancelStall = runUntil([&] { return !w.tasks().busy(); }, 600000);
    std::printf(
        "Cancel: stopped after %.2f s (GUI thread away at most %.0f ms); memory %.0f MB "
        "(peak %.0f MB)\n",
        t.elapsed() / 1000.0, cancelStall, memoryMb().second, memoryMb().first);
    EXPECT_LT(t.elapsed(), 1000);
}

}  // namespace
}  // namespace raystep::gui
