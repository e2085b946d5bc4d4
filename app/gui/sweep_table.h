#pragma once
// The lesson panel's sweep table: the grid sweep's rows (course/grid_sweep.h), one a resolution.
#include "course/grid_sweep.h"

#include <QTableWidget>

#include <vector>

namespace raystep::gui {

class SweepTable : public QTableWidget {
    Q_OBJECT
  public:
    explicit SweepTable(QWidget* parent = nullptr);
    /// The sweep's rows, shown.
    void showRows(const std::vector<GridSweepRow>& rows);
};

}  // namespace raystep::gui
