#pragma once
// What several GUI test files share.
#include <QApplication>
#include <QElapsedTimer>

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

}  // namespace raystep::gui
