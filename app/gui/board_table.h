#pragma once
// The board dock: the slides' DDA table (or a tree's nodes with [tNear, tFar], or a build's
// nodes) growing row by row as the replay steps, the current row highlighted and scrolled to;
// copied (Ctrl+C, a button) or exported as CSV, Markdown or LaTeX. The rows are the core's
// (trace/board.h), the same `raystep-cli dda --format` prints.
#include "session.h"

#include "raystep/trace/board.h"

#include <QAbstractTableModel>
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTableView;

namespace raystep::gui {

/// A board cell as the table shows it: its numbers with the interface's decimal sign (the
/// exports and Copy keep the board's own text, with points).
QString shownText(const std::string& cell);

/// The board as a table model: rows grow at the end while the replay steps forward.
class BoardModel : public QAbstractTableModel {
  public:
    using QAbstractTableModel::QAbstractTableModel;
    int rowCount(const QModelIndex& parent) const override;
    int columnCount(const QModelIndex& parent) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;
    /// Shows `board`: rows appended or removed at the end when the columns stay, else reset.
    void setBoard(Board board);
    const Board& board() const { return board_; }

  private:
    /// Whether every cell of column `c` is a number (a figure column, right-aligned), cached.
    bool numericColumn(int c) const;
    Board board_;
    mutable std::vector<signed char> numeric_;  // per column: -1 not known yet, 0, 1
};

class BoardTable : public QWidget {
    Q_OBJECT
  public:
    explicit BoardTable(Session& s, QWidget* parent = nullptr);

    const Board& board() const { return model_->board(); }
    /// The board as text in `format` (what Copy and Export write).
    QString text(BoardFormat format) const;
    /// The format the Copy button and Ctrl+C use (the chooser beside them).
    BoardFormat copyFormat() const;
    void setCopyFormat(BoardFormat format);
    /// Copies the board to the clipboard in copyFormat().
    void copy();
    /// Writes the board to `path` in `format`: a regular file, written whole or not at all (a
    /// temporary renamed into place). The one-line problem, or an empty string.
    QString exportTo(const QString& path, BoardFormat format) const;
    /// The highlighted row (-1: none) and the table (tests look at them).
    int currentRow() const;
    QTableView* view() const { return view_; }
    /// The line above the table: whose rows these are.
    QString caption() const;

  protected:
    void showEvent(QShowEvent* e) override;

  private:
    /// The rows at the session's cursor; while hidden only marked stale (a 3D trace's ray may
    /// hold tens of thousands of tests, and the timeline moves the cursor many times a second).
    void refresh();
    void exportDialog();

    Session& session_;
    BoardModel* model_;
    QTableView* view_;
    QLabel* caption_;
    QComboBox* format_;
    QPushButton* copy_;
    QPushButton* export_;
    bool stale_ = false;
};

}  // namespace raystep::gui
