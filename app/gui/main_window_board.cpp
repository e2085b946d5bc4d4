// The live controls (structure and its parameters, with the statistics) and the board table.
#include "main_window.h"

namespace raystep::gui {

void MainWindow::createBoard() {}

}  // namespace raystep::gui
