#include "raystep/trace/board.h"

#include "raystep/base/format.h"

#include <cmath>
#include <limits>
#include <map>
#include <type_traits>

namespace raystep {

namespace {

/// Why a node is a leaf, as the board's outcome: the reason's name in English (as in the trace
/// file), its words in Italian (as the inspector's line has them).
std::string leafOutcome(LeafReason reason, Language lang) {
    switch (reason) {
        case LeafReason::FewPrimitives:
            return tr(lang, "leaf (few_primitives)");
        case LeafReason::MaxDepth:
            return tr(lang, "leaf (max_depth)");
        case LeafReason::SahCheaper:
            return tr(lang, "leaf (sah_cheaper)");
        case LeafReason::NoSplit:
            return tr(lang, "leaf (no_split)");
        case LeafReason::NoProgress:
            return tr(lang, "leaf (no_progress)");
    }
    return tr(lang, "leaf");
}

constexpr const char* kAxisNames = "XYZ";
// A cell before any set-up (a log cut short): its tDelta unknown.
constexpr double kNaNDelta = std::numeric_limits<double>::quiet_NaN();
constexpr std::array<double, 3> kNoDelta = {kNaNDelta, kNaNDelta, kNaNDelta};

/// The ray an event names, if it names one.
std::optional<std::uint32_t> rayOf(const Event& event) {
    return std::visit(
        [](const auto& e) -> std::optional<std::uint32_t> {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, RayBegin> || std::is_same_v<E, DdaSetup> ||
                          std::is_same_v<E, DdaCell> || std::is_same_v<E, MailboxSkip> ||
                          std::is_same_v<E, PrimitiveTest> || std::is_same_v<E, NodeEnter> ||
                          std::is_same_v<E, NodeSkip> || std::is_same_v<E, RayHit> ||
                          std::is_same_v<E, RayBlocked> || std::is_same_v<E, RayMiss> ||
                          std::is_same_v<E, ShadingTerm>)
                return e.ray;
            else
                return std::nullopt;
        },
        event);
}

/// The node a build event names, if it is one.
std::optional<std::uint32_t> buildNodeOf(const Event& event) {
    return std::visit(
        [](const auto& e) -> std::optional<std::uint32_t> {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, BuildNode> || std::is_same_v<E, SplitCandidate> ||
                          std::is_same_v<E, SplitChosen> || std::is_same_v<E, LeafMade>)
                return e.node;
            else
                return std::nullopt;
        },
        event);
}

std::string num(double v) {
    return formatNumber(v);
}

std::string axesText(unsigned mask, int dims) {
    std::string out;
    for (int i = 0; i < dims; ++i)
        if (mask & (1u << i)) out += std::string(out.empty() ? "" : "+") + kAxisNames[i];
    return out;
}

/// What a ray's row collects: its primitive tests and mailbox skips.
struct Visits {
    std::vector<PrimitiveTest> tests;
    std::vector<std::uint32_t> skips;
};

std::string testsText(const std::vector<PrimitiveTest>& tests, Language lang) {
    std::string out;
    for (const PrimitiveTest& t : tests) {
        if (!out.empty()) out += ", ";
        const std::string id = std::to_string(t.prim);
        out += t.hit ? trf(lang, "%1 (hit, t = %2)", {id, num(t.t)}) : id;
    }
    return out;
}

std::string idsText(const std::vector<std::uint32_t>& ids) {
    std::string out;
    for (std::uint32_t id : ids) out += (out.empty() ? "" : ", ") + std::to_string(id);
    return out;
}

Board rayBoard(const EventLog& log, std::size_t subject, std::uint32_t ray, std::size_t cursor,
               const BoardOptions& options) {
    const auto& events = log.events();
    const Language lang = options.lang;
    // The ray's events run from its RayBegin to how it ends (RayHit, RayBlocked or RayMiss),
    // before any other ray's.
    std::size_t begin = subject;
    while (begin > 0) {
        const auto* b = std::get_if<RayBegin>(&events[begin]);
        if (b && b->ray == ray) break;
        --begin;
    }
    std::size_t end = begin;
    bool dda = false, tree = false;
    int dims = log.dims();
    for (; end < events.size(); ++end) {
        const Event& e = events[end];
        if (const auto* b = std::get_if<RayBegin>(&e); b && b->ray != ray) break;
        if (rayOf(e) != ray) continue;
        if (const auto* s = std::get_if<DdaSetup>(&e)) {
            dda = true;
            dims = s->dims;
        }
        dda = dda || std::holds_alternative<DdaCell>(e);
        tree = tree || std::holds_alternative<NodeEnter>(e);
        if (std::holds_alternative<RayHit>(e) || std::holds_alternative<RayBlocked>(e) ||
            std::holds_alternative<RayMiss>(e)) {
            ++end;
            break;
        }
    }
    dims = dims == 3 ? 3 : 2;

    Board board;
    board.ray = ray;
    board.dims = dims;
    board.kind = dda ? BoardKind::Dda : tree ? BoardKind::Tree : BoardKind::Tests;
    switch (board.kind) {
        case BoardKind::Dda:
            board.header = ddaHeader(dims, options);
            break;
        case BoardKind::Tree:
            board.header = {tr(lang, "step"), tr(lang, "node"),   "tNear",
                            "tFar",           tr(lang, "tested"), tr(lang, "mailbox skips")};
            break;
        default:
            board.header = {tr(lang, "step"), tr(lang, "primitive"), tr(lang, "result"), "t"};
            break;
    }

    // The rows' own data, turned into text at the end (a row's tests grow after it opens).
    struct Pending {
        std::size_t event;
        std::vector<std::string> lead;  // the cells before the tested and skipped ones
        Visits visits;
    };
    std::vector<Pending> rows;
    std::optional<DdaSetup> setup;
    const std::size_t last = std::min(cursor, end);
    for (std::size_t i = begin; i < last; ++i) {
        const Event& e = events[i];
        if (rayOf(e) != ray) continue;
        if (const auto* s = std::get_if<DdaSetup>(&e)) {
            setup = *s;
        } else if (const auto* c = std::get_if<DdaCell>(&e)) {
            Pending row{
                i, ddaCells(rows.size(), *c, setup ? setup->tDelta : kNoDelta, dims, lang), {}};
            rows.push_back(std::move(row));
        } else if (const auto* n = std::get_if<NodeEnter>(&e)) {
            if (board.kind == BoardKind::Tree)
                rows.push_back({i,
                                {std::to_string(rows.size()), std::to_string(n->node),
                                 num(n->tNear), num(n->tFar)},
                                {}});
        } else if (const auto* t = std::get_if<PrimitiveTest>(&e)) {
            if (board.kind == BoardKind::Tests)
                rows.push_back(
                    {i,
                     {std::to_string(rows.size()), std::to_string(t->prim),
                      t->hit ? tr(lang, "hit") : tr(lang, "miss"), t->hit ? num(t->t) : ""},
                     {}});
            else if (!rows.empty())
                rows.back().visits.tests.push_back(*t);
        } else if (const auto* m = std::get_if<MailboxSkip>(&e)) {
            if (board.kind != BoardKind::Tests && !rows.empty())
                rows.back().visits.skips.push_back(m->prim);
        }
    }
    const bool visitColumns =
        board.kind == BoardKind::Tree || (board.kind == BoardKind::Dda && options.primitives);
    for (Pending& p : rows) {
        BoardRow row{p.event, std::move(p.lead)};
        if (visitColumns) {
            row.cells.push_back(testsText(p.visits.tests, lang));
            row.cells.push_back(idsText(p.visits.skips));
        }
        board.rows.push_back(std::move(row));
    }
    if (!board.rows.empty()) board.current = board.rows.size() - 1;
    return board;
}

Board buildBoard(const EventLog& log, std::size_t cursor, const BoardOptions& options) {
    const Language lang = options.lang;
    const auto& events = log.events();
    Board board;
    board.kind = BoardKind::Build;
    board.dims = log.dims() == 3 ? 3 : 2;
    board.header = {tr(lang, "step"),   tr(lang, "node"),       tr(lang, "parent"),
                    tr(lang, "depth"),  tr(lang, "primitives"), tr(lang, "candidates"),
                    tr(lang, "split"),  tr(lang, "SAH cost"),   tr(lang, "leaf cost"),
                    tr(lang, "outcome")};
    enum Col { Step, Node, Parent, Depth, Prims, Candidates, Split, Sah, Leaf, Outcome };
    std::map<std::uint32_t, std::size_t> rowOf;  // node -> its row
    std::vector<std::size_t> candidates;
    std::uint32_t lastNode = kNoId;
    for (std::size_t i = 0; i < std::min(cursor, events.size()); ++i) {
        const Event& e = events[i];
        const auto node = buildNodeOf(e);
        if (!node) continue;
        lastNode = *node;
        if (const auto* b = std::get_if<BuildNode>(&e)) {
            rowOf[b->node] = board.rows.size();
            candidates.push_back(0);
            BoardRow row{i, std::vector<std::string>(Outcome + 1)};
            row.cells[Step] = std::to_string(board.rows.size());
            row.cells[Node] = std::to_string(b->node);
            row.cells[Parent] = b->parent == kNoId ? "-" : std::to_string(b->parent);
            row.cells[Depth] = std::to_string(b->depth);
            row.cells[Prims] = std::to_string(b->prims);
            row.cells[Candidates] = "0";
            board.rows.push_back(std::move(row));
            continue;
        }
        const auto at = rowOf.find(*node);
        if (at == rowOf.end()) continue;
        std::vector<std::string>& cells = board.rows[at->second].cells;
        if (std::holds_alternative<SplitCandidate>(e)) {
            cells[Candidates] = std::to_string(++candidates[at->second]);
        } else if (const auto* c = std::get_if<SplitChosen>(&e)) {
            cells[Split] = std::string(1, kAxisNames[c->axis % 3]) + " = " + num(c->position);
            cells[Sah] = num(c->sahCost);
            cells[Leaf] = num(c->leafCost);
            cells[Outcome] = tr(lang, "split");
        } else if (const auto* l = std::get_if<LeafMade>(&e)) {
            cells[Leaf] = num(l->leafCost);
            cells[Outcome] = leafOutcome(l->reason, lang);
        }
    }
    if (const auto at = rowOf.find(lastNode); at != rowOf.end()) board.current = at->second;
    return board;
}

}  // namespace

std::vector<std::string> ddaHeader(int dims, const BoardOptions& options) {
    const Language lang = options.lang;
    std::vector<std::string> h{tr(lang, "step")};
    for (int i = 0; i < dims; ++i) h.push_back(std::string(1, kAxisNames[i]));
    for (int i = 0; i < dims; ++i) h.push_back(std::string("tMax") + kAxisNames[i]);
    for (int i = 0; i < dims; ++i) h.push_back(std::string("tDelta") + kAxisNames[i]);
    h.push_back(tr(lang, "stepped"));
    if (options.primitives) {
        h.push_back(tr(lang, "tested"));
        h.push_back(tr(lang, "mailbox skips"));
    }
    return h;
}

std::vector<std::string> ddaCells(std::size_t step, const DdaCell& c,
                                  const std::array<double, 3>& tDelta, int dims, Language lang) {
    std::vector<std::string> cells{std::to_string(step)};
    for (int k = 0; k < dims; ++k) cells.push_back(std::to_string(c.cell[k]));
    for (int k = 0; k < dims; ++k) cells.push_back(num(c.tMax[k]));
    for (int k = 0; k < dims; ++k) cells.push_back(std::isnan(tDelta[k]) ? "" : num(tDelta[k]));
    const std::string axes = axesText(c.axes, dims);
    if (step > 0)
        cells.push_back(axes);
    else  // the first cell: where the ray starts, or the grid face it enters through
        cells.push_back(axes.empty() ? tr(lang, "start") : trf(lang, "enters across %1", {axes}));
    return cells;
}

Board makeBoard(const EventLog& log, std::size_t cursor, const BoardOptions& options) {
    const auto& events = log.events();
    cursor = std::min(cursor, events.size());
    // The subject: what the last applied event is about; before any, the log's first subject.
    std::optional<std::size_t> subject;
    for (std::size_t i = cursor; i-- > 0;)
        if (rayOf(events[i]) || buildNodeOf(events[i])) {
            subject = i;
            break;
        }
    for (std::size_t i = 0; !subject && i < events.size(); ++i)
        if (rayOf(events[i]) || buildNodeOf(events[i])) subject = i;
    if (!subject) return {};
    if (const auto ray = rayOf(events[*subject]))
        return rayBoard(log, *subject, *ray, cursor, options);
    return buildBoard(log, cursor, options);
}

std::optional<BoardFormat> parseBoardFormat(std::string_view name) {
    if (name == "csv") return BoardFormat::Csv;
    if (name == "markdown" || name == "md") return BoardFormat::Markdown;
    if (name == "latex" || name == "tex") return BoardFormat::Latex;
    return std::nullopt;
}

std::string csvField(std::string_view text) {
    // RFC 4180: a field holding a comma, a quote or a line break is quoted, its quotes doubled.
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string markdownCell(std::string_view text) {
    // A pipe would end the cell and a line break the row; a backslash must not escape the pipe.
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += "\\|";
        else if (c == '\\')
            out += "\\\\";
        else if (c == '\n' || c == '\r')
            out += ' ';
        else
            out += c;
    }
    return out;
}

std::string latexText(std::string_view text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '\\':
                out += "\\textbackslash{}";
                break;
            case '&':
            case '%':
            case '$':
            case '#':
            case '_':
            case '{':
            case '}':
                out += '\\';
                out += c;
                break;
            case '~':
                out += "\\textasciitilde{}";
                break;
            case '^':
                out += "\\textasciicircum{}";
                break;
            case '\n':
            case '\r':
                out += ' ';
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string formatBoardStart(const std::vector<std::string>& header, BoardFormat format) {
    switch (format) {
        case BoardFormat::Csv:
            return formatBoardLine(header, format);
        case BoardFormat::Markdown: {
            std::string out = formatBoardLine(header, format) + '|';
            for (std::size_t i = 0; i < header.size(); ++i) out += " --- |";
            return out + '\n';
        }
        case BoardFormat::Latex:
            return "\\begin{tabular}{" + std::string(header.size(), 'l') + "}\n\\hline\n" +
                   formatBoardLine(header, format) + "\\hline\n";
    }
    return {};
}

std::string formatBoardLine(const std::vector<std::string>& cells, BoardFormat format) {
    std::string out;
    switch (format) {
        case BoardFormat::Csv:
            for (std::size_t i = 0; i < cells.size(); ++i)
                out += (i ? "," : "") + csvField(cells[i]);
            return out + '\n';
        case BoardFormat::Markdown:
            out += '|';
            for (const std::string& c : cells) out += ' ' + markdownCell(c) + " |";
            return out + '\n';
        case BoardFormat::Latex:
            for (std::size_t i = 0; i < cells.size(); ++i)
                out += (i ? " & " : "") + latexText(cells[i]);
            return out + " \\\\\n";
    }
    return out;
}

std::string formatBoardEnd(BoardFormat format) {
    return format == BoardFormat::Latex ? "\\hline\n\\end{tabular}\n" : "";
}

std::string formatBoard(const Board& board, BoardFormat format) {
    if (board.header.empty()) return {};
    std::string out = formatBoardStart(board.header, format);
    for (const BoardRow& r : board.rows) out += formatBoardLine(r.cells, format);
    return out + formatBoardEnd(format);
}

}  // namespace raystep
