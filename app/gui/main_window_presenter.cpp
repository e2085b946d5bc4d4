// Presenter mode (UI zoom, fullscreen, thicker lines, high contrast) and Help > Keyboard shortcuts.
#include "main_window.h"

namespace raystep::gui {

void MainWindow::createPresenter() {}

}  // namespace raystep::gui
