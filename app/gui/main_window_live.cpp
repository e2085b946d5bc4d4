// The 2D view's live editing: ray handles, scene editing, undo and redo, 2D scene files.
#include "main_window.h"

namespace raystep::gui {

void MainWindow::createLiveLab() {}

}  // namespace raystep::gui
