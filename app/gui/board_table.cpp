// The board dock: the core's board rows (trace/board.h) of the replay at its cursor, in a table.
#include "board_table.h"
#include "file_dialogs.h"

#include "language.h"

#include "course/palette.h"

#include "raystep/base/file_error.h"
#include "raystep/render/image.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QFileDialog>
#include <QFont>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QMessageBox>
#include <QPainter>
#include <QPushButton>
#include <QScrollBar>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>
#include <cctype>

namespace raystep::gui {

namespace {
/// A table view whose Copy key copies the whole board: QTableView takes Ctrl+C for itself (one
/// cell) before any shortcut sees it.
class BoardView : public QTableView {
  public:
    explicit BoardView(QAction* copy) : copy_(copy) { fitRows(); }

  protected:
    void changeEvent(QEvent* e) override {
        QTableView::changeEvent(e);
        if (e->type() == QEvent::FontChange) fitRows();  // the zoom: the rows grow with the text
    }
    /// Rows as tall as a line of text (more of the walk in a short dock), and room for the
    /// header and the current row at least, whatever the zoom.
    void fitRows() {
        const int row = fontMetrics().height() + 6;
        verticalHeader()->setDefaultSectionSize(row);
        // The header by its font too: without a model yet its size hint is its empty one's.
        const int header = std::max(horizontalHeader()->sizeHint().height(), row + 4);
        setMinimumHeight(header + row + 2 * frameWidth() +
                         horizontalScrollBar()->sizeHint().height());
    }
    void keyPressEvent(QKeyEvent* e) override {
        if (e->matches(QKeySequence::Copy)) {
            copy_->trigger();
            e->accept();
            return;
        }
        QTableView::keyPressEvent(e);
    }

  private:
    QAction* copy_;
};

/// The board's cells, with a student's cell that differs from raystep's tinted even in the
/// current (selected) row, where the selection's colour would hide it: that row is the jump's.
class MarkedCellDelegate : public QStyledItemDelegate {
  public:
    MarkedCellDelegate(const BoardModel* model, QObject* parent)
        : QStyledItemDelegate(parent), model_(model) {}
    void paint(QPainter* painter, const QStyleOptionViewItem& option,
               const QModelIndex& index) const override {
        if (!model_->marked(index.row(), index.column()))
            return QStyledItemDelegate::paint(painter, option, index);
        // Unselected, it is drawn on the model's tint (BackgroundRole), in the text's colour.
        QStyleOptionViewItem o(option);
        o.state &= ~QStyle::State_Selected;
        const PaletteColour& c = roleColour(PaletteRole::Tested);
        const auto light = [](int v) { return (v * 11 + 255 * 9) / 20; };  // over white, opaque
        painter->fillRect(o.rect, QColor(light(c.r), light(c.g), light(c.b)));
        QStyledItemDelegate::paint(painter, o, index);
    }

  private:
    const BoardModel* model_;
};

/// A one-line label that elides what does not fit (the whole text is its tooltip): a zoomed
/// caption takes one line of the dock, not two or three of its rows.
class ElidedLabel : public QLabel {
  public:
    void setFullText(const QString& text) {
        full_ = text;
        setToolTip(text);
        elide();
    }
    QString fullText() const { return full_; }
    QSize minimumSizeHint() const override { return {0, QLabel::minimumSizeHint().height()}; }
    QSize sizeHint() const override {
        return {fontMetrics().horizontalAdvance(full_), QLabel::sizeHint().height()};
    }

  protected:
    void resizeEvent(QResizeEvent* e) override {
        QLabel::resizeEvent(e);
        elide();
    }
    void changeEvent(QEvent* e) override {
        QLabel::changeEvent(e);
        if (e->type() == QEvent::FontChange) elide();
    }

  private:
    void elide() { setText(fontMetrics().elidedText(full_, Qt::ElideRight, width())); }
    QString full_;
};
}  // namespace

QString shownText(const std::string& cell) {
    QString text = QString::fromStdString(cell);
    // On screen a number reads as the interface writes it (a decimal comma in Italian, as the
    // inspector and the events); the exports keep the point, as a spreadsheet or LaTeX reads it.
    const std::string_view mark = decimalMark(interfaceLanguage());
    if (mark == ".") return text;
    const QString shownMark = QString::fromUtf8(mark.data(), static_cast<qsizetype>(mark.size()));
    QString out;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const bool decimal = text[i] == QLatin1Char('.') && i > 0 && i + 1 < text.size() &&
                             text[i - 1].isDigit() && text[i + 1].isDigit();
        if (decimal)
            out += shownMark;
        else
            out += text[i];
    }
    return out;
}

int BoardModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(board_.rows.size());
}

int BoardModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(board_.header.size());
}

QVariant BoardModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount({}) || index.column() >= columnCount({}))
        return {};
    const bool current = board_.current && *board_.current == std::size_t(index.row());
    const bool student = markedFrom_ >= 0 && index.column() >= markedFrom_;
    const bool differs = marked(index.row(), index.column());
    switch (role) {
        case Qt::DisplayRole:
        case Qt::ToolTipRole:
            return shownText(board_.rows[index.row()].cells[index.column()]);
        case Qt::BackgroundRole:
            if (differs) {
                // Where the student's walk is not raystep's: the 2D view's tested pink, strong on
                // the first such row (the replay's jump), lighter after it.
                const PaletteColour& c = roleColour(PaletteRole::Tested);
                const bool first = divergent_ && *divergent_ == std::size_t(index.row());
                return QColor(c.r, c.g, c.b, first ? 170 : 90);
            }
            if (student && !current) {
                // The student's columns in the 2D view's colour of their walk, lightly.
                const PaletteColour& c = roleColour(PaletteRole::Chosen);
                return QColor(c.r, c.g, c.b, 30);
            }
            if (current) {
                // The 2D view's colour for the current cell, as a tint the text reads on.
                const PaletteColour& c = roleColour(PaletteRole::Current);
                return QColor(c.r, c.g, c.b, 110);
            }
            return {};
        case Qt::FontRole:
            if (current || differs) {
                QFont f;
                f.setBold(true);
                return f;
            }
            return {};
        case Qt::TextAlignmentRole: {
            // Columns of figures right-aligned, as a table of figures is read; a column of
            // words or lists left, all of it ("8" under "0, 8" reads as a list too).
            return int((numericColumn(index.column()) ? Qt::AlignRight : Qt::AlignLeft) |
                       Qt::AlignVCenter);
        }
        default:
            return {};
    }
}

QVariant BoardModel::headerData(int section, Qt::Orientation o, int role) const {
    if (role != Qt::DisplayRole || o != Qt::Horizontal || section < 0 || section >= columnCount({}))
        return {};
    return QString::fromStdString(board_.header[section]);
}

void BoardModel::setMarks(int first, std::vector<std::vector<bool>> differs,
                          std::optional<std::size_t> divergent) {
    markedFrom_ = first;
    marks_ = std::move(differs);
    divergent_ = divergent;
}

bool BoardModel::marked(int row, int column) const {
    if (markedFrom_ < 0 || column < markedFrom_ || row < 0 || std::size_t(row) >= marks_.size())
        return false;
    const auto& r = marks_[row];
    const std::size_t c = std::size_t(column - markedFrom_);
    return c < r.size() && r[c];
}

bool BoardModel::numericColumn(int c) const {
    if (numeric_.size() != board_.header.size()) numeric_.assign(board_.header.size(), -1);
    if (numeric_[c] < 0) {
        const auto number = [](const std::string& v) {
            return v.empty() || ((std::isdigit(static_cast<unsigned char>(v[0])) || v[0] == '-') &&
                                 v.find_first_of(" ,(") == std::string::npos);
        };
        numeric_[c] = std::all_of(board_.rows.begin(), board_.rows.end(),
                                  [&](const BoardRow& r) { return number(r.cells[c]); });
    }
    return numeric_[c] > 0;
}

void BoardModel::setBoard(Board board) {
    if (board.header != board_.header || board.kind != board_.kind) {
        numeric_.clear();
        beginResetModel();
        board_ = std::move(board);
        endResetModel();
        return;
    }
    // The same columns: the replay stepped; rows come and go at the end, the last may change.
    const int before = rowCount({}), after = static_cast<int>(board.rows.size());
    const std::optional<std::size_t> oldCurrent = board_.current;
    std::vector<bool> wasNumeric;
    for (int c = 0; c < columnCount({}); ++c) wasNumeric.push_back(numericColumn(c));
    numeric_.clear();  // rows come and go: a column's kind is looked at again
    if (after < before) {
        beginRemoveRows({}, after, before - 1);
        board_.rows.resize(after);
        endRemoveRows();
    }
    const int kept = std::min(before, after);
    int firstChanged = kept;
    for (int r = 0; r < kept; ++r)
        if (board_.rows[r].cells != board.rows[r].cells) {
            firstChanged = r;
            break;
        }
    if (after > before) {
        beginInsertRows({}, before, after - 1);
        board_.rows = std::move(board.rows);
        board_.current = board.current;
        endInsertRows();
    } else {
        board_.rows = std::move(board.rows);
        board_.current = board.current;
    }
    board_.ray = board.ray;
    board_.dims = board.dims;
    const int columns = columnCount({});
    for (int c = 0; c < columns; ++c)
        if (numericColumn(c) != wasNumeric[c] && after > 0)  // the whole column realigns
            emit dataChanged(index(0, c), index(after - 1, c), {Qt::TextAlignmentRole});
    if (firstChanged < kept && columns > 0)
        emit dataChanged(index(firstChanged, 0), index(kept - 1, columns - 1));
    // The highlight moved: both rows repaint.
    for (const auto& r : {oldCurrent, board_.current})
        if (r && int(*r) < rowCount({}) && columns > 0)
            emit dataChanged(index(int(*r), 0), index(int(*r), columns - 1));
}

BoardTable::BoardTable(Session& s, QWidget* parent) : QWidget(parent), session_(s) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* top = new QHBoxLayout;
    caption_ = new ElidedLabel;
    caption_->setObjectName("boardCaption");
    top->addWidget(caption_, 1);
    format_ = new QComboBox;
    format_->setObjectName("boardFormat");
    format_->addItem(QStringLiteral("CSV"), int(BoardFormat::Csv));
    format_->addItem(QStringLiteral("Markdown"), int(BoardFormat::Markdown));
    format_->addItem(QStringLiteral("LaTeX"), int(BoardFormat::Latex));
    format_->setToolTip(tr("The text Copy puts on the clipboard"));
    copy_ = new QPushButton(tr("Copy"));
    copy_->setObjectName("boardCopy");
    copy_->setToolTip(tr("Copy the board to the clipboard (Ctrl+C in the table)"));
    export_ = new QPushButton(tr("Export..."));
    export_->setObjectName("boardExport");
    export_->setToolTip(tr("Save the board as CSV, Markdown or LaTeX"));
    top->addWidget(format_);
    top->addWidget(copy_);
    top->addWidget(export_);
    layout->addLayout(top);

    // Ctrl+C in the table copies the whole board (not one cell, as a table view would).
    auto* copyKey = new QAction(tr("Copy the board"), this);
    copyKey->setObjectName("boardCopyAction");
    copyKey->setShortcut(QKeySequence::Copy);
    copyKey->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(copyKey, &QAction::triggered, this, [this] { copy(); });
    model_ = new BoardModel(this);
    view_ = new BoardView(copyKey);
    view_->addAction(copyKey);
    view_->setObjectName("boardView");
    view_->setModel(model_);
    view_->setItemDelegate(new MarkedCellDelegate(model_, view_));
    view_->verticalHeader()->hide();
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    view_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    view_->horizontalHeader()->setStretchLastSection(true);
    view_->setWordWrap(false);
    view_->setToolTip(tr("Click a row to go back to that step"));
    layout->addWidget(view_, 1);

    // A row clicked: the replay goes back (or on) to the event that opened it.
    connect(view_, &QTableView::clicked, this, [this](const QModelIndex& i) {
        if (i.isValid() && i.row() < int(board().rows.size()))
            session_.setCursor(board().rows[i.row()].event + 1);
    });
    connect(copy_, &QPushButton::clicked, this, [this] { copy(); });
    connect(export_, &QPushButton::clicked, this, [this] { exportDialog(); });

    connect(&session_, &Session::cursorChanged, this, [this] { refresh(); });
    connect(&session_, &Session::logChanged, this, [this] { refresh(); });
    connect(&session_, &Session::sceneChanged, this, [this] { refresh(); });
    refresh();
}

void BoardTable::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    if (stale_) refresh();
}

void BoardTable::refresh() {
    stale_ = !isVisible();
    if (stale_) return;
    BoardOptions options;
    options.lang = interfaceLanguage();
    Board made = makeBoard(session_.log(), session_.cursor(), options);
    const bool beside =
        showsBeside() && (made.kind == BoardKind::Dda || made.kind == BoardKind::Tree);
    if (beside) {
        // The student's k-th step beside raystep's k-th; past raystep's last row (a walk that
        // goes on), theirs alone, once the replay has reached raystep's end.
        const int first = int(made.header.size());
        made.header.insert(made.header.end(), beside_->header.begin(), beside_->header.end());
        const std::size_t ours = made.rows.size();
        std::size_t rows = ours;
        if (session_.cursor() >= session_.size()) rows = std::max(ours, beside_->rows.size());
        const std::size_t lastEvent = session_.size() > 0 ? session_.size() - 1 : 0;
        std::vector<std::vector<bool>> marks(rows);
        for (std::size_t r = 0; r < rows; ++r) {
            if (r >= ours)
                made.rows.push_back({lastEvent, std::vector<std::string>(std::size_t(first))});
            auto& cells = made.rows[r].cells;
            if (r < beside_->rows.size()) {
                cells.insert(cells.end(), beside_->rows[r].begin(), beside_->rows[r].end());
                marks[r] = beside_->differs[r];
            } else {
                cells.resize(made.header.size());
            }
        }
        model_->setMarks(first, std::move(marks), beside_->divergent);
    } else {
        model_->setMarks(-1, {}, std::nullopt);
    }
    model_->setBoard(std::move(made));
    const Board& b = board();
    QString what;
    const QString ray = QString::number(b.ray);
    switch (b.kind) {
        case BoardKind::None:
            what = tr("Nothing recorded yet: R traces the example ray, B replays a build.");
            break;
        case BoardKind::Dda:
            what = tr("Ray %1 walks the grid: a row per cell, as on the slides.").arg(ray);
            break;
        case BoardKind::Tree:
            what = tr("Ray %1 through the tree: a row per node entered, [tNear, tFar].").arg(ray);
            break;
        case BoardKind::Tests:
            what = tr("Ray %1: a row per primitive tested (no structure to walk).").arg(ray);
            break;
        case BoardKind::Build:
            what = tr("The build: a row per node made, with its split or why it is a leaf.");
            break;
    }
    if (beside && !beside_->caption.isEmpty()) what = beside_->caption;
    static_cast<ElidedLabel*>(caption_)->setFullText(what);
    copy_->setEnabled(!b.header.empty());
    export_->setEnabled(!b.header.empty());
    const int row = currentRow();
    if (row >= 0) {
        // Not selectRow: it reads the keyboard's modifiers, so with Ctrl held (Ctrl+Shift+L, a
        // Ctrl+key step) it toggled the row off, and with Shift extended the selection.
        const QModelIndex at = model_->index(row, 0);
        view_->selectionModel()->setCurrentIndex(
            at, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        view_->scrollTo(at);
    } else {
        view_->clearSelection();
    }
}

void BoardTable::setBeside(std::optional<BoardBeside> beside) {
    beside_ = std::move(beside);
    refresh();
}

bool BoardTable::showsBeside() const {
    return beside_ && beside_->log && beside_->log == session_.logRef();
}

int BoardTable::currentRow() const {
    const Board& b = board();
    return b.current ? static_cast<int>(*b.current) : -1;
}

QString BoardTable::caption() const {
    return static_cast<ElidedLabel*>(caption_)->fullText();
}

QString BoardTable::text(BoardFormat format) const {
    return QString::fromStdString(formatBoard(board(), format));
}

BoardFormat BoardTable::copyFormat() const {
    return static_cast<BoardFormat>(format_->currentData().toInt());
}

void BoardTable::setCopyFormat(BoardFormat format) {
    format_->setCurrentIndex(format_->findData(int(format)));
}

void BoardTable::copy() {
    QApplication::clipboard()->setText(text(copyFormat()));
}

QString BoardTable::exportTo(const QString& path, BoardFormat format) const {
    if (board().header.empty()) return tr("The board is empty: there is nothing to export.");
    try {
        // The core's writer: a FIFO or a device is refused, a failed write keeps the old file.
        writeFileAtomic(path.toStdString(), formatBoard(board(), format));
    } catch (const std::exception& e) {
        return QString::fromStdString(printable(e.what(), 4096));
    }
    return {};
}

void BoardTable::exportDialog() {
    const QString csv = tr("CSV (*.csv)"), md = tr("Markdown (*.md)"), tex = tr("LaTeX (*.tex)");
    QString filter;
    const QString path =
        saveFileName(this, tr("Export the board"), csv + ";;" + md + ";;" + tex, &filter);
    if (path.isEmpty()) return;
    // The file's extension decides; without one, the filter chosen in the dialog.
    BoardFormat format = filter == md    ? BoardFormat::Markdown
                         : filter == tex ? BoardFormat::Latex
                                         : BoardFormat::Csv;
    if (path.endsWith(QLatin1String(".md"), Qt::CaseInsensitive))
        format = BoardFormat::Markdown;
    else if (path.endsWith(QLatin1String(".tex"), Qt::CaseInsensitive))
        format = BoardFormat::Latex;
    else if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive))
        format = BoardFormat::Csv;
    if (const QString problem = exportTo(path, format); !problem.isEmpty())
        QMessageBox::warning(this, tr("Cannot export"), problem);
}

}  // namespace raystep::gui
