#pragma once
// The board: the table a lecturer writes on the blackboard while following a ray (the slides'
// DDA table), grown to a replay cursor. One row per cell the DDA enters (X, Y[, Z], tMax, tDelta,
// the axis stepped, the primitives tested and those the mailbox skips), per tree node entered
// ([tNear, tFar]), per primitive tested (brute force), or per node made (a build). Written out
// as CSV, Markdown or LaTeX. Qt-free: the app's board dock and `raystep-cli dda --format` print
// the same rows, with numbers as formatNumber writes them.
#include "raystep/base/i18n.h"
#include "raystep/trace/events.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// What the rows are.
enum class BoardKind {
    None,   // nothing to show (an empty log)
    Dda,    // a ray's walk through a grid: a row per cell
    Tree,   // a ray through a kd-tree or BVH: a row per node entered
    Tests,  // a ray with neither (brute force): a row per primitive tested
    Build   // a tree's construction: a row per node made
};

struct BoardRow {
    std::size_t event = 0;           // the log's event that opened the row
    std::vector<std::string> cells;  // one per column of the header
};

struct Board {
    BoardKind kind = BoardKind::None;
    int dims = 2;               // 2 or 3 (the DDA's columns)
    std::uint32_t ray = kNoId;  // the ray shown (kNoId for a build)
    std::vector<std::string> header;
    std::vector<BoardRow> rows;
    /// The row the cursor is in (the last event applied belongs to it), if any.
    std::optional<std::size_t> current;
};

struct BoardOptions {
    Language lang = Language::En;
    /// The tested and mailbox-skip columns of a DDA board (a walk without a scene has none).
    bool primitives = true;
};

/// The board of the log after its first `cursor` events: for the ray the last applied event
/// names (the log's first ray before any), its rows up to the cursor; for a build, its nodes.
Board makeBoard(const EventLog& log, std::size_t cursor, const BoardOptions& options = {});

enum class BoardFormat { Csv, Markdown, Latex };
/// "csv", "markdown" (or "md"), "latex" (or "tex"); nullopt for anything else.
std::optional<BoardFormat> parseBoardFormat(std::string_view name);

/// The board as text: CSV (RFC 4180 quoting), a Markdown pipe table (pipes escaped) or a LaTeX
/// tabular (special characters escaped). Every line ends with '\n'.
std::string formatBoard(const Board& board, BoardFormat format);

/// The pieces of a board, for a writer that streams a long walk row by row (`raystep-cli dda
/// --format`) instead of holding it: makeBoard and formatBoard are made of them.
/// The DDA board's columns, and a row's cells for the `step`-th cell of a walk.
std::vector<std::string> ddaHeader(int dims, const BoardOptions& options);
std::vector<std::string> ddaCells(std::size_t step, const DdaCell& cell,
                                  const std::array<double, 3>& tDelta, int dims, Language lang);
/// The text before the rows (with the header), one row's line, and the text after the rows.
std::string formatBoardStart(const std::vector<std::string>& header, BoardFormat format);
std::string formatBoardLine(const std::vector<std::string>& cells, BoardFormat format);
std::string formatBoardEnd(BoardFormat format);

/// One cell's text as each format writes it (the escaping formatBoard applies).
std::string csvField(std::string_view text);
std::string markdownCell(std::string_view text);
std::string latexText(std::string_view text);

}  // namespace raystep
