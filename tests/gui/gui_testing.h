#pragma once
// What several GUI test files share.
#include "main_window.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <functional>

namespace raystep::gui {

/// Processes events until `done` holds (false after `ms`): a wait on a condition, not a sleep.
inline bool waitFor(const std::function<bool()>& done, int ms = 20000) {
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (clock.elapsed() > ms) return false;
        QApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents, 20);
    }
    return true;
}

/// A main window of 1500 x 900, shown, active and exposed: where most GUI tests start.
struct ShownWindow {
    MainWindow w;
    ShownWindow() {
        w.resize(1500, 900);
        w.show();
        w.activateWindow();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(&w));
    }
};

/// Opens a lesson (built-in id or number, or a file) and waits for it; false if it failed.
inline bool openLesson(MainWindow& w, const QString& lesson) {
    w.openLesson(lesson, /*quiet=*/true);
    return w.waitUntilIdle() && w.lastOpenOk().value_or(false);
}

/// Writes a lesson (or any file) the test made into `dir`; its path.
inline QString writeLesson(const QTemporaryDir& dir, const QString& name, const QByteArray& json) {
    const QString path = dir.filePath(name);
    QFile out(path);
    EXPECT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(json);
    return path;
}

/// The visible push button of `in` labelled `text`, or null.
inline QPushButton* buttonNamed(QWidget* in, const QString& text) {
    for (QPushButton* b : in->findChildren<QPushButton*>())
        if (b->text() == text && b->isVisible()) return b;
    return nullptr;
}

}  // namespace raystep::gui
