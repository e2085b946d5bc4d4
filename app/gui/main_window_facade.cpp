// MainWindow's public API that a part owns (tests and scripts drive the window through it):
// forwarded to the part.
#include "main_window.h"

#include "assess_controller.h"
#include "board_docks.h"
#include "compare_launcher.h"
#include "inspector.h"
#include "live_edit.h"
#include "presenter_controls.h"
#include "scene_opener.h"
#include "timeline.h"
#include "window_layout.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>

namespace raystep::gui {

// Background work, for tests and scripts (task_runner.h; a scheduled render counts).
void MainWindow::whenIdle(std::function<void()> f) {
    if (!runner_.busy()) {
        QTimer::singleShot(0, this, std::move(f));
        return;
    }
    auto once = std::make_shared<QMetaObject::Connection>();
    *once = connect(&runner_, &TaskRunner::idle, this, [once, f = std::move(f)] {
        QObject::disconnect(*once);
        f();
    });
}

bool MainWindow::waitUntilIdle(int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    // A render scheduled (a move, a resize) counts as work: it starts once events settle.
    const auto busy = [this] { return runner_.busy() || image_->pending(); };
    for (;;) {
        while (busy() && clock.elapsed() < timeoutMs)
            QApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents, 20);
        QApplication::processEvents();
        if (!busy()) return true;
        if (clock.elapsed() >= timeoutMs) return false;
    }
}

QString MainWindow::openStudentTrace(const QString& path, bool quiet) {
    return assess_->open(path, quiet);
}

// The views' own, for the tests and scripts that drive the window.
QString MainWindow::inspectorText() const {
    return inspector_->toPlainText();
}

void MainWindow::stepForward() {
    timeline_->stepForward();
}
void MainWindow::stepBack() {
    timeline_->stepBack();
}
void MainWindow::jumpToNextOfKind() {
    timeline_->jumpToNextOfKind();
}
void MainWindow::togglePlay() {
    timeline_->togglePlay();
}

// What is opened and shown (scene_opener.h).
void MainWindow::openScene(const QString& nameOrPath, AccelKind kind, bool quiet,
                           const AccelOptions& options, bool renderImage) {
    opener_->openScene(nameOrPath, kind, quiet, options, renderImage);
}
void MainWindow::openLesson(const QString& idOrPath, bool quiet) {
    opener_->openLesson(idOrPath, quiet);
}
void MainWindow::showLive(SceneRef scene) {
    opener_->showLive(std::move(scene));
}
std::optional<bool> MainWindow::lastOpenOk() const {
    return opener_->lastOpenOk();
}
QString MainWindow::lastOpenError() const {
    return opener_->lastOpenError();
}

// The image (image_render.h).
void MainWindow::renderImage() {
    image_->renderImage();
}
const std::optional<MainWindow::ImageFrame>& MainWindow::imageFrame() const {
    return image_->frame();
}
QAction* MainWindow::rayTraceViewAction() const {
    return image_->rayTraceViewAction();
}

// Compare mode (compare_launcher.h).
void MainWindow::openCompare(const std::vector<StructureChoice>& choices) {
    compare_->open(choices);
}
void MainWindow::openCompare() {
    compare_->open();
}
void MainWindow::chooseCompare() {
    compare_->choose();
}
CompareChooser* MainWindow::compareChooser() const {
    return compare_->chooser();
}
CompareWindow* MainWindow::compareWindow() const {
    return compare_->window();
}

// The live parts (live_edit.h, board_docks.h).
Live2D* MainWindow::live2D() const {
    return live_->live2D();
}
BoardTable* MainWindow::boardTable() const {
    return board_->boardTable();
}
LiveControls* MainWindow::liveControls() const {
    return board_->liveControls();
}

// Presenter mode and the keyboard shortcuts (presenter_controls.h).
void MainWindow::showShortcuts() {
    presenter_->showShortcuts();
}
ShortcutsDialog* MainWindow::shortcutsDialog() const {
    return presenter_->shortcutsDialog();
}

// The layout (window_layout.h).
QSize MainWindow::fitToScreen(QSize wanted) const {
    return layout_->fitToScreen(wanted);
}
bool MainWindow::geometryRestored() const {
    return layout_->geometryRestored();
}
void MainWindow::sizeForScreen() {
    layout_->sizeForScreen();
}
void MainWindow::resetLayout() {
    layout_->reset();
}
QAction* MainWindow::resetLayoutAction() const {
    return layout_->resetLayoutAction();
}
int MainWindow::defaultLessonWidth(int windowWidth) {
    return WindowLayout::defaultLessonWidth(windowWidth);
}
int MainWindow::defaultDockWidth(int windowWidth) {
    return WindowLayout::defaultDockWidth(windowWidth);
}
int MainWindow::defaultBottomDockHeight(int windowHeight, int zoomPercent) {
    return WindowLayout::defaultBottomDockHeight(windowHeight, zoomPercent);
}
bool MainWindow::layoutSettled() const {
    return layout_->settled();
}
void MainWindow::showEvent(QShowEvent* e) {
    QMainWindow::showEvent(e);
    layout_->shown();
}

}  // namespace raystep::gui
