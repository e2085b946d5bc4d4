#pragma once
// What the course tests share: a small valid lesson to add keys to, and the check that a bad
// lesson's error names the file, the line and the key.
#include "course/lesson.h"

#include <gtest/gtest.h>

#include <string>

namespace raystep::test {

/// A valid lesson over the lecture grid's example ray, with `extra` keys from line 11 on.
inline std::string lessonWith(const std::string& extra) {
    return "{\n\"format\": \"raystep-lesson\",\n\"version\": 1,\n\"id\": \"t\",\n\"number\": 1,\n"
           "\"title\": {\"en\": \"T\"},\n\"text\": {\"en\": \"x\"},\n\"scene\": \"lecture-grid\",\n"
           "\"setup\": {\"accel\": \"grid\"},\n\"trace\": {\"ray\": \"example\"}" +
           extra + "\n}";
}

/// Loading `text` (as "bad.json") fails at `line`, on `key`, with `words` in the message.
inline void expectLessonError(const std::string& text, int line, const std::string& key,
                              const std::string& words) {
    try {
        loadLessonText(text, "bad.json");
        ADD_FAILURE() << "no error for: " << text;
    } catch (const LessonError& e) {
        EXPECT_EQ(e.file(), "bad.json");
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_EQ(e.key(), key) << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

}  // namespace raystep::test
