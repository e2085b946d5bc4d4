#include "sweep_table.h"

#include "language.h"

#include <QHeaderView>

namespace raystep::gui {

SweepTable::SweepTable(QWidget* parent) : QTableWidget(parent) {
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    verticalHeader()->hide();
}

void SweepTable::showRows(const std::vector<GridSweepRow>& rows) {
    // What the lesson is about first (the panel is narrow): tests against cells against time.
    const QStringList headers = {tr("cells/axis"), tr("tests/ray"), tr("cells/ray"),
                                 tr("trace ms"),   tr("cells"),     tr("refs"),
                                 tr("build ms"),   tr("skips/ray")};
    clear();
    setColumnCount(headers.size());
    setHorizontalHeaderLabels(headers);
    setRowCount(static_cast<int>(rows.size()));
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
        const GridSweepRow& row = rows[r];
        const QStringList cells = {
            QString::number(row.resolution),     numberText(row.testsPerRay, 'f', 1),
            numberText(row.cellsPerRay, 'f', 1), numberText(row.traceMs, 'f', 1),
            QString::number(row.cells),          QString::number(row.references),
            numberText(row.buildMs, 'f', 1),     numberText(row.skipsPerRay, 'f', 1)};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            setItem(r, c, item);
        }
    }
    resizeColumnsToContents();
    show();
}

}  // namespace raystep::gui
