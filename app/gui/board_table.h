#pragma once
// The board dock: the slides' DDA table (or a tree's nodes with [tNear, tFar], or a build's
// nodes) growing row by row as the replay steps, the current row highlighted and scrolled to;
// copied (Ctrl+C, a button) or exported as CSV, Markdown or LaTeX. The rows are the core's
// (trace/board.h), the same `raystep-cli dda --format` prints.
#include "session.h"

#include "raystep/trace/board.h"

#include <QAbstractTableModel>
#include <QWidget>

#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QTableView;

namespace raystep::gui {

/// A board cell as the table shows it: its numbers with the interface's decimal sign (the
/// exports and Copy keep the board's own text, with points).
QString shownText(const std::string& cell);

/// A student's rows beside the board's (File > Open student trace, assess_controller.h): their
/// own columns after raystep's, the k-th row of theirs beside raystep's k-th, each cell marked
/// where it differs.
struct BoardBeside {
    LogRef log;  // raystep's run of the same ray: the columns are shown while it is replayed
    std::vector<std::string> header;             // "your cell", "your tMax"...
    std::vector<std::vector<std::string>> rows;  // per step of the student's walk
    std::vector<std::vector<bool>> differs;      // per row and column: not raystep's
    std::optional<std::size_t> divergent;        // the assessor's first divergence
    QString caption;                             // what the board's caption says then
};

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
    /// The columns from `first` on are a student's; `differs` marks their cells (per row).
    void setMarks(int first, std::vector<std::vector<bool>> differs,
                  std::optional<std::size_t> divergent);
    /// Whether a cell is a student's that differs from raystep's (shown with a sign and a tint).
    bool marked(int row, int column) const;

  private:
    /// Whether every cell of column `c` is a number (a figure column, right-aligned), cached.
    bool numericColumn(int c) const;
    Board board_;
    mutable std::vector<signed char> numeric_;  // per column: -1 not known yet, 0, 1
    int markedFrom_ = -1;                       // the first student column (-1: none)
    std::vector<std::vector<bool>> marks_;
    std::optional<std::size_t> divergent_;
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
    /// A student's rows beside raystep's while `beside.log` is replayed (none: no more).
    void setBeside(std::optional<BoardBeside> beside);
    /// Whether the student's columns are shown now.
    bool showsBeside() const;
    BoardModel* model() const { return model_; }

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
    std::optional<BoardBeside> beside_;
};

}  // namespace raystep::gui
