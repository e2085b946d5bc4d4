// The board: the slides' DDA table grown to a cursor, a tree's nodes with [tNear, tFar], a build's
// nodes, and the three text formats. Reference values by hand (the scene file's comment and the
// lesson's numbers), never from the code under test.
#include "raystep/trace/board.h"
#include "raystep/accel/accel.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <sstream>

namespace raystep {
namespace {

std::vector<std::string> column(const Board& b, const std::string& name) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (at < b.header.size() && b.header[at] != name) ++at;
    if (at == b.header.size()) return out;
    for (const BoardRow& r : b.rows) out.push_back(r.cells.at(at));
    return out;
}

using Strings = std::vector<std::string>;

TEST(Board, TheSlidesDdaExampleRowByRow) {
    const Scene2D s = std::get<Scene2D>(loadAnyScene("lecture-grid"));
    const Accelerator2D grid = buildAccelerator2D(s, AccelKind::Grid);
    EventLog log;
    traceRay2D(grid, *s.exampleRay, log);
    const Board b = makeBoard(log, log.events().size());
    ASSERT_EQ(b.kind, BoardKind::Dda);
    EXPECT_EQ(b.header, (Strings{"step", "X", "Y", "tMaxX", "tMaxY", "tDeltaX", "tDeltaY",
                                 "stepped", "tested", "mailbox skips"}));
    // By hand: origin (0.4, 0.4), direction (0.8, 0.4), cells of 1: x lines crossed at
    // t = (k - 0.4) / 0.8 = 0.75, 2, 3.25, 4.5, 5.75; y lines at (k - 0.4) / 0.4 = 1.5, 4, 6.5.
    // The small circle 2 is hit at t = 4.575 in cell (4, 2), whose far side is at 5.75.
    EXPECT_EQ(column(b, "X"), (Strings{"0", "1", "1", "2", "3", "3", "4"}));
    EXPECT_EQ(column(b, "Y"), (Strings{"0", "0", "1", "1", "1", "2", "2"}));
    EXPECT_EQ(column(b, "tMaxX"), (Strings{"0.75", "2", "2", "3.25", "4.5", "4.5", "5.75"}));
    EXPECT_EQ(column(b, "tMaxY"), (Strings{"1.5", "1.5", "4", "4", "4", "6.5", "6.5"}));
    EXPECT_EQ(column(b, "tDeltaX"), Strings(7, "1.25"));
    EXPECT_EQ(column(b, "tDeltaY"), Strings(7, "2.5"));
    EXPECT_EQ(column(b, "stepped"), (Strings{"start", "X", "Y", "X", "X", "Y", "X"}));
    EXPECT_EQ(column(b, "tested").back(), "2 (hit, t = 4.575)");
    ASSERT_TRUE(b.current);
    EXPECT_EQ(*b.current, 6u);
}

/// A ray by hand: two cells, a test in each, a mailbox skip in the second, a hit.
EventLog handLog() {
    EventLog log;
    log.setDims(2);
    log.beginRay(Ray{Vec3(0.5, 0.5, 0.0), Vec3(1.0, 0.0, 0.0)}, RayKind::Primary, 0, kNoId);
    log(DdaSetup{0, {1, 0, 0}, 2, {2.0, kInfinity, 0.0}, 0.0, 4.0});  // 1
    log(DdaCell{0, 0, {0, 3, 0}, {0.5, kInfinity, 0.0}});             // 2
    log(PrimitiveTest{0, 7, false, kInfinity});                       // 3
    log(DdaCell{0, 1, {1, 3, 0}, {2.5, kInfinity, 0.0}});             // 4
    log(MailboxSkip{0, 7});                                           // 5
    log(PrimitiveTest{0, 9, true, 1.25});                             // 6
    log(RayHit{0, 9, 1.25, 0.0, 0.0});                                // 7
    return log;
}

TEST(Board, GrowsWithTheCursorAndTheCurrentRowIsTheLast) {
    const EventLog log = handLog();
    EXPECT_TRUE(makeBoard(log, 0).rows.empty());
    EXPECT_EQ(makeBoard(log, 0).kind, BoardKind::Dda);  // the header is known before any row
    EXPECT_TRUE(makeBoard(log, 2).rows.empty());        // set-up only
    const Board one = makeBoard(log, 3);
    ASSERT_EQ(one.rows.size(), 1u);
    EXPECT_EQ(one.rows[0].event, 2u);
    EXPECT_EQ(one.rows[0].cells[8], "");  // the test at event 3 is not applied yet
    const Board two = makeBoard(log, 6);
    ASSERT_EQ(two.rows.size(), 2u);
    EXPECT_EQ(two.rows[0].cells,
              (Strings{"0", "0", "3", "0.5", "inf", "2", "inf", "start", "7", ""}));
    EXPECT_EQ(two.rows[1].cells, (Strings{"1", "1", "3", "2.5", "inf", "2", "inf", "X", "", "7"}));
    EXPECT_EQ(two.current, 1u);
    const Board all = makeBoard(log, 99);
    EXPECT_EQ(all.rows[1].cells[8], "9 (hit, t = 1.25)");
    // Without the primitive columns (the CLI's walk): no tested, no skips.
    BoardOptions bare;
    bare.primitives = false;
    EXPECT_EQ(makeBoard(log, 99, bare).header.size(), 8u);
}

TEST(Board, ThreeDimensionsHaveTheZColumns) {
    EventLog log;
    log.beginRay(Ray{Vec3(0.5), Vec3(1.0, 1.0, 2.0)}, RayKind::Primary, 0, kNoId);
    log(DdaSetup{0, {1, 1, 1}, 3, {1.0, 1.0, 0.5}, 0.0, 2.0});
    log(DdaCell{0, 0, {0, 0, 0}, {0.5, 0.5, 0.25}});
    log(DdaCell{0, 4, {0, 0, 1}, {0.5, 0.5, 0.75}});
    log(RayMiss{0});
    const Board b = makeBoard(log, log.events().size());
    EXPECT_EQ(b.dims, 3);
    EXPECT_EQ(b.header, (Strings{"step", "X", "Y", "Z", "tMaxX", "tMaxY", "tMaxZ", "tDeltaX",
                                 "tDeltaY", "tDeltaZ", "stepped", "tested", "mailbox skips"}));
    EXPECT_EQ(column(b, "Z"), (Strings{"0", "1"}));
    EXPECT_EQ(column(b, "stepped"), (Strings{"start", "Z"}));
    EXPECT_EQ(column(b, "tDeltaZ"), (Strings{"0.5", "0.5"}));
}

TEST(Board, ATreeShowsTheNodesEnteredWithTheirInterval) {
    EventLog log;
    log.beginRay(Ray{Vec3(0.0), Vec3(1.0, 0.0, 0.0)}, RayKind::Primary, 0, kNoId);
    log(NodeEnter{0, 0, 0.0, 8.0});
    log(NodeEnter{0, 1, 0.0, 3.5});
    log(PrimitiveTest{0, 4, false, kInfinity});
    log(NodeSkip{0, 2, 3.5, 8.0});
    log(NodeEnter{0, 5, 3.5, 8.0});
    log(MailboxSkip{0, 4});
    log(RayMiss{0});
    const Board b = makeBoard(log, log.events().size());
    ASSERT_EQ(b.kind, BoardKind::Tree);
    EXPECT_EQ(b.header, (Strings{"step", "node", "tNear", "tFar", "tested", "mailbox skips"}));
    ASSERT_EQ(b.rows.size(), 3u);
    EXPECT_EQ(b.rows[1].cells, (Strings{"1", "1", "0", "3.5", "4", ""}));
    EXPECT_EQ(b.rows[2].cells, (Strings{"2", "5", "3.5", "8", "", "4"}));
}

TEST(Board, TheLastRayAtTheCursorIsShown) {
    EventLog log = handLog();
    log.beginRay(Ray{Vec3(0.0), Vec3(0.0, 1.0, 0.0)}, RayKind::Shadow, 1, 0);  // event 8
    log(PrimitiveTest{1, 3, true, 0.5});
    log(RayHit{1, 3, 0.5, 0.0, 0.0});
    const Board first = makeBoard(log, 8);
    EXPECT_EQ(first.ray, 0u);
    EXPECT_EQ(first.rows.size(), 2u);
    const Board second = makeBoard(log, 10);
    EXPECT_EQ(second.ray, 1u);
    ASSERT_EQ(second.kind, BoardKind::Tests);  // no grid, no tree: brute force's tests
    ASSERT_EQ(second.rows.size(), 1u);
    EXPECT_EQ(second.rows[0].cells, (Strings{"0", "3", "hit", "0.5"}));
}

TEST(Board, ABuildListsItsNodes) {
    EventLog log;
    log(BuildNode{0, kNoId, 0, 5, 5.0, 25.0});
    log(SplitCandidate{0, 0, 2, 3, 1.5, 0.4, 0.6, 21.0});
    log(SplitCandidate{0, 1, 5, 1, 2.0, 0.5, 0.5, 16.0});
    log(SplitChosen{0, 1, 2.0, 16.0, 25.0});
    log(BuildNode{1, 0, 1, 5, 5.0, 25.0});
    log(LeafMade{1, LeafReason::SahCheaper, 5, 1, 25.0});
    const Board half = makeBoard(log, 3);
    ASSERT_EQ(half.kind, BoardKind::Build);
    ASSERT_EQ(half.rows.size(), 1u);
    EXPECT_EQ(half.rows[0].cells, (Strings{"0", "0", "-", "0", "5", "2", "", "", "", ""}));
    const Board b = makeBoard(log, 6);
    ASSERT_EQ(b.rows.size(), 2u);
    EXPECT_EQ(b.rows[0].cells,
              (Strings{"0", "0", "-", "0", "5", "2", "Y = 2", "16", "25", "split"}));
    EXPECT_EQ(b.rows[1].cells,
              (Strings{"1", "1", "0", "1", "5", "0", "", "", "25", "leaf (sah_cheaper)"}));
    EXPECT_EQ(b.current, 1u);
    EXPECT_EQ(makeBoard(log, 4).current, 0u);  // the chosen split is node 0's
    // In Italian every leaf's reason is in words (lesson 11 sends students to this column).
    BoardOptions it;
    it.lang = Language::It;
    for (auto reason : {LeafReason::FewPrimitives, LeafReason::MaxDepth, LeafReason::SahCheaper,
                        LeafReason::NoSplit, LeafReason::NoProgress}) {
        EventLog leaf;
        leaf(BuildNode{0, kNoId, 0, 2, 5.0, 10.0});
        leaf(LeafMade{0, reason, 2, 0, 10.0});
        const std::string outcome = makeBoard(leaf, 2, it).rows.at(0).cells.back();
        EXPECT_EQ(outcome.rfind("foglia (", 0), 0u) << outcome;
        EXPECT_EQ(outcome.find('_'), std::string::npos) << outcome;
        if (reason == LeafReason::SahCheaper) {
            EXPECT_EQ(outcome, "foglia (la foglia costa meno di ogni taglio)");
        }
    }
}

TEST(Board, ItalianWordsNumbersAsTheCliPrintsThem) {
    BoardOptions it;
    it.lang = Language::It;
    const Board b = makeBoard(handLog(), 99, it);
    EXPECT_EQ(b.header[0], "passo");
    EXPECT_EQ(b.rows[0].cells[3], "0.5");  // a point, as the CLI and the CSV need
}

Board formatSample() {
    Board b;
    b.kind = BoardKind::Tests;
    b.header = {"a|b", "c,d", "e"};
    b.rows.push_back({0, {"x \"y\"", "50% & $#_{}~^\\", "line\nbreak"}});
    return b;
}

TEST(Board, CsvQuotesAsRfc4180Says) {
    EXPECT_EQ(formatBoard(formatSample(), BoardFormat::Csv),
              "a|b,\"c,d\",e\n\"x \"\"y\"\"\",50% & $#_{}~^\\,\"line\nbreak\"\n");
    EXPECT_EQ(csvField("plain"), "plain");
}

TEST(Board, MarkdownEscapesPipes) {
    EXPECT_EQ(formatBoard(formatSample(), BoardFormat::Markdown),
              "| a\\|b | c,d | e |\n| --- | --- | --- |\n"
              "| x \"y\" | 50% & $#_{}~^\\\\ | line break |\n");
}

TEST(Board, LatexEscapesItsSpecialCharacters) {
    EXPECT_EQ(formatBoard(formatSample(), BoardFormat::Latex),
              "\\begin{tabular}{lll}\n\\hline\n"
              "a|b & c,d & e \\\\\n\\hline\n"
              "x \"y\" & 50\\% \\& \\$\\#\\_\\{\\}\\textasciitilde{}\\textasciicircum{}"
              "\\textbackslash{} & line break \\\\\n"
              "\\hline\n\\end{tabular}\n");
}

TEST(Board, FormatNames) {
    EXPECT_EQ(parseBoardFormat("csv"), BoardFormat::Csv);
    EXPECT_EQ(parseBoardFormat("markdown"), BoardFormat::Markdown);
    EXPECT_EQ(parseBoardFormat("latex"), BoardFormat::Latex);
    EXPECT_FALSE(parseBoardFormat("html"));
    EXPECT_EQ(formatBoard(Board{}, BoardFormat::Csv), "");
}

}  // namespace
}  // namespace raystep
