#include "raystep/base/json_lines.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

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

// Keys are compared and found decoded, as nlohmann gives them: "\u0061" is "a".
TEST(JsonLineMap, KeysAreDecoded) {
    const JsonLineMap dup("{\"a\": 1,\n \"\\u0061\": 2}");
    ASSERT_EQ(dup.duplicates().size(), 1u);
    EXPECT_EQ(dup.duplicates()[0].first, "a");
    EXPECT_EQ(dup.duplicates()[0].second, 2);
    // A surrogate pair is one character (U+1F600, UTF-8 F0 9F 98 80); escapes of quotes and
    // backslashes; keys holding '.' and '[' are still found.
    const JsonLineMap map(
        "{\"\\ud83d\\ude00\": 1,\n \"q\\\"b\\\\\": {\n \"x\": 2},\n \"a.b\": {\"c[1]\": [\n 5]},\n"
        " \"a\": {\"b\": 3}}");
    EXPECT_TRUE(map.duplicates().empty());
    EXPECT_EQ(map.lineOf("\xf0\x9f\x98\x80"), 1);
    EXPECT_EQ(map.lineOf("q\"b\\.x"), 3);
    EXPECT_EQ(map.lineOf("a.b.c[1][0]"), 5);
    // "a.b" is both the key "a.b" and "b" in "a": the shorter key first.
    EXPECT_EQ(map.lineOf("a.b"), 6);
}

// The depth cap: the line of the first bracket past it, brackets in strings and comments not
// counted; at the cap the map is built as usual.
TEST(JsonLineMap, DepthIsCappedBeforeAnythingIsBuilt) {
    const std::string deep =
        std::string(kMaxJsonDepth + 1, '[') + "\n" + std::string(kMaxJsonDepth + 1, ']');
    EXPECT_EQ(JsonLineMap("{\"a\":\n" + deep + "}").tooDeepLine(), 2);
    EXPECT_EQ(JsonLineMap("\n\n" + std::string(1'000'000, '[')).tooDeepLine(), 3);
    const std::string atCap = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
    const JsonLineMap ok("/* [[[[ */ \"[[[[\", // [[[[\n" + atCap);
    EXPECT_EQ(ok.tooDeepLine(), 0);
    const JsonLineMap nested(atCap);
    EXPECT_EQ(nested.tooDeepLine(), 0);
    std::string path;
    for (int i = 1; i < kMaxJsonDepth; ++i) path += "[0]";
    EXPECT_EQ(nested.lineOf(path), 1);
}

// On any bytes the scan ends, and lineOf answers: the fuzzers will feed it worse.
TEST(JsonLineMap, AnyBytesAreSafe) {
    std::mt19937 rng(7);
    const std::string alphabet = "{}[]\",:/*\\\n\r\t u0aA1.e-x";
    for (int n = 0; n < 20000; ++n) {
        std::string text(rng() % 40, ' ');
        for (char& c : text) c = alphabet[rng() % alphabet.size()];
        const JsonLineMap map(text);
        EXPECT_GE(map.lineOf("a.b[0]"), 1);
        EXPECT_GE(map.lineOf("[0].x"), 1);
        EXPECT_LE(map.lineOf("[1]"),
                  1 + static_cast<int>(std::count(text.begin(), text.end(), '\n')));
    }
}

// The two inputs the first fuzz sessions found (docs/reliability.md): the line map's array loop
// never moved past a '}' it met after a NUL byte (nlohmann stops at one, the map read on), nor
// after a // comment ended by a CR (nlohmann ends it there, the map only at a LF). Both must end,
// and a reader must refuse them as its own error.
TEST(JsonLineMap, TheFuzzersFindingsEnd) {
    const std::string nul(
        "//\0"
        "1\0\n{\"a\":[0}",
        14);
    const std::string cr = "{\"a\": [2//\r],\n\"b\": {}}";
    for (const std::string& text : {nul, cr}) {
        const JsonLineMap map(text);
        EXPECT_GE(map.lineOf("a[0]"), 1);
        const FileResolver noFiles = [](const std::string&) {
            return std::optional<std::string>();
        };
        EXPECT_THROW(loadSceneText(text, "f.json", noFiles), SceneError);
    }
    // The course's reader: tests/course/lesson_hostile_test.cpp.
}

}  // namespace
}  // namespace raystep
