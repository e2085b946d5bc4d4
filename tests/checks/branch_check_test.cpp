// The branch check itself: a line planted in a real view is caught at its line; each kind of
// branch is caught; comments, strings, defaults and the table's predicates are not branches.
#include "branch_check.h"
#include "source_tree.h"

#include <gtest/gtest.h>

#include <string>

namespace raystep::checks {
namespace {

std::string readSource(const std::string& relative) {
    return readWhole(std::filesystem::path(RAYSTEP_SOURCE_DIR) / relative);
}

TEST(BranchCheck, ALinePlantedInTheTwoDViewIsCaughtAtItsLine) {
    const std::string view = readSource("app/gui/view2d.cpp");
    ASSERT_GT(view.size(), 1000u);
    ASSERT_TRUE(findBranches(view).empty()) << findBranches(view).front().text;
    // Line 40, by hand: the planted line becomes line 40 of the file.
    const auto found =
        findBranches(plantAt(view, 40, "    if (session_.kind() == AccelKind::Grid) return;"));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].line, 40u);
    EXPECT_EQ(found[0].what, "compares a kind");
    EXPECT_EQ(found[0].text, "if (session_.kind() == AccelKind::Grid) return;");
    const auto typed = findBranches(plantAt(
        view, 7, "const auto* g = std::get_if<UniformGridT<Scene2DPrims>>(session_.accel2D());"));
    ASSERT_EQ(typed.size(), 1u);  // two patterns on one line: one report
    EXPECT_EQ(typed[0].line, 7u);
}

TEST(BranchCheck, EveryKindOfBranchIsCaught) {
    const std::string src =
        "int a;\n"                                            // 1
        "if (k != raystep::AccelKind::Bvh) {}\n"              // 2
        "if (AccelKind::KdTree == k) {}\n"                    // 3
        "switch (k) { case AccelKind::Grid: break; }\n"       // 4
        "auto* t = std::get_if<KdTree3>(&accel);\n"           // 5
        "bool b = std::holds_alternative<Bvh3>(accel);\n"     // 6
        "const Bvh<ScenePrims>& bvh = f();\n"                 // 7
        "const UniformGrid& g = std::get<UniformGrid>(a);\n"  // 8
        "if (choice.kind ==\n"                                // 9
        "    AccelKind::Grid) {}\n";                          // 10
    const auto found = findBranches(src);
    std::vector<std::size_t> lines;
    for (const Branch& b : found) lines.push_back(b.line);
    EXPECT_EQ(lines, (std::vector<std::size_t>{2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(BranchCheck, CommentsStringsDefaultsAndTheTablesPredicatesAreNotBranches) {
    const std::string src =
        "// if (kind == AccelKind::Grid) is what the table replaced\n"
        "/* case AccelKind::Bvh: */\n"
        "const char* s = \"kind == AccelKind::Grid\";\n"
        "const char* r = R\"x(get_if<KdTree3>)x\";\n"
        "AccelKind kind = AccelKind::Grid;\n"
        "f(AccelKind::KdTree);\n"
        "if (hasSplit(kind) && testsEveryPrimitive(other)) {}\n"
        "KdTreeOptions o; BvhOptions p; int n = 1'000;\n"
        "if (std::get_if<Scene2D>(&scene)) {}\n";
    const auto found = findBranches(src);
    EXPECT_TRUE(found.empty()) << found.front().line << ": " << found.front().text;
}

}  // namespace
}  // namespace raystep::checks
