#include "raystep/json_lines.h"

#include <gtest/gtest.h>

namespace raystep {
namespace {

TEST(JsonLineMap, LinesOfKeysAndElements) {
    const char* text = R"(// line 1: a comment
{
  "a": 1,          /* line 3 */
  "list": [
    {"x": 1},
    /* a comment
       over two lines */
    {"x": 2,
     "y": [0, 1]}
  ],
  "s": "a // not a comment { ["
}
)";
    const JsonLineMap map(text);
    EXPECT_EQ(map.lineOf(""), 1);
    EXPECT_EQ(map.lineOf("a"), 3);
    EXPECT_EQ(map.lineOf("list"), 4);
    EXPECT_EQ(map.lineOf("list[0]"), 5);
    EXPECT_EQ(map.lineOf("list[0].x"), 5);
    EXPECT_EQ(map.lineOf("list[1]"), 8);
    EXPECT_EQ(map.lineOf("list[1].y"), 9);
    EXPECT_EQ(map.lineOf("list[1].y[1]"), 9);
    EXPECT_EQ(map.lineOf("s"), 11);
    // A key that is not there falls back to its nearest ancestor.
    EXPECT_EQ(map.lineOf("list[1].missing"), 8);
    EXPECT_TRUE(map.duplicates().empty());
}

TEST(JsonLineMap, FindsDuplicateKeys) {
    const JsonLineMap map("{\"a\": 1,\n \"b\": {\"c\": 1,\n \"c\": 2}}");
    ASSERT_EQ(map.duplicates().size(), 1u);
    EXPECT_EQ(map.duplicates()[0].first, "b.c");
    EXPECT_EQ(map.duplicates()[0].second, 3);
}

}  // namespace
}  // namespace raystep
