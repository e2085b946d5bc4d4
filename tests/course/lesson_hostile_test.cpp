// Hostile input to the lesson, answers and progress readers (robustness review, issue 15): every
// failure is one LessonError line naming the file, and only regular files are read.
#include "course/exercise.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"
#include "course/progress.h"

#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace raystep {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    fs::path path = fs::temp_directory_path() /
                    ("raystep-lesson-hostile-" + std::to_string(::getpid()) + "-" +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TempDir() { fs::create_directories(path); }
    ~TempDir() { fs::remove_all(path); }
};

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// The message of the LessonError `f` throws; a failure for no error or another exception type.
std::string lessonErrorOf(const std::function<void()>& f) {
    try {
        f();
        ADD_FAILURE() << "no error";
    } catch (const LessonError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        return what;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a LessonError: " << e.what();
    }
    return "";
}

// Class 4, for the lesson, answers and progress readers.
TEST(LessonsHostile, DeepNestingIsRefusedAtTheCap) {
    for (const int levels : {65, 1'000'000}) {
        const std::string deep = std::string(levels, '[') + std::string(levels, ']');
        for (const auto& f : std::vector<std::function<void()>>{
                 [&] {
                     loadLessonText("{\"format\": \"raystep-lesson\",\n\"text\": " + deep + "}",
                                    "l.json");
                 },
                 [&] {
                     loadAnswerSheet("{\"lesson\": \"6\",\n\"answers\": " + deep + "}", "a.json");
                 },
                 [&] {
                     parseProgress("{\"format\": \"raystep-progress\",\n\"x\": " + deep + "}",
                                   "p.json");
                 }}) {
            const std::string what = lessonErrorOf(f);
            EXPECT_TRUE(contains(what, ".json:2: nested deeper than 64 levels")) << what;
        }
    }
}

// Class 11.
TEST(LessonsHostile, ADuplicateKeySpelledWithAnEscapeIsFound) {
    const std::string what = lessonErrorOf([] {
        loadAnswerSheet(
            "{\"lesson\": \"6\", \"answers\": {\"next-cell\": 1,\n\"next\\u002dcell\": 2}}",
            "a.json");
    });
    EXPECT_TRUE(contains(what, "a.json:2: key 'answers.next-cell': key given twice")) << what;
}

// Class 12: quoted file text is escaped and shortened.
TEST(LessonsHostile, QuotedTextIsEscapedAndShortened) {
    const Lesson l = loadLesson("6");
    const LessonRun run = runLesson(l);
    std::string what = lessonErrorOf([&] {
        gradeAnswers(
            l, run.logs(),
            loadAnswerSheet("{\"lesson\": \"6\",\n\"answers\": {\"a\\nb\\u0000c\": 1}}", "a.json"),
            Language::En, "a.json");
    });
    EXPECT_TRUE(contains(what, "key 'answers.a\\nb\\x00c'")) << what;
    what = lessonErrorOf([&] {
        gradeAnswers(
            l, run.logs(),
            loadAnswerSheet("{\"lesson\": \"" + std::string(3000, '7') + "\",\n\"answers\": {}}",
                            "a.json"),
            Language::En, "a.json");
    });
    EXPECT_LT(what.size(), 300u) << what;
}

// Class 18: a lesson number is an id too; a wrong lesson names the line of "lesson"; a
// 400-digit number is quoted short.
TEST(LessonsHostile, AnswerSheetMessages) {
    const AnswerSheet byNumber =
        loadAnswerSheet("{\"lesson\": 6, \"answers\": {\"tdelta-y\": 1}}", "a.json");
    EXPECT_EQ(byNumber.lesson, "6");
    const Lesson l = loadLesson("6");
    const LessonRun run = runLesson(l);
    EXPECT_EQ(gradeAnswers(l, run.logs(), byNumber, Language::En, "a.json").items.size(),
              l.exercises.size());
    std::string what =
        lessonErrorOf([] { loadAnswerSheet("{\"lesson\": 6.5, \"answers\": {}}", "a.json"); });
    EXPECT_TRUE(contains(what, "a.json:1: key 'lesson': ")) << what;
    EXPECT_NO_THROW(
        loadAnswerSheet("{\"lesson\": 6, \"student\": 12345, \"answers\": {}}", "a.json"));
    what = lessonErrorOf(
        [] { loadAnswerSheet("{\"lesson\": 6,\n\"student\": {}, \"answers\": {}}", "a.json"); });
    EXPECT_TRUE(contains(what, "a.json:2: key 'student': ")) << what;
    try {
        gradeAnswers(l, run.logs(),
                     loadAnswerSheet("{\"answers\": {},\n \"lesson\": \"mailboxing\"}", "a.json"),
                     Language::En, "a.json");
        ADD_FAILURE();
    } catch (const LessonError& e) {
        EXPECT_EQ(e.line(), 2) << e.what();
        EXPECT_EQ(e.key(), "lesson") << e.what();
    }
    what = lessonErrorOf([] {
        loadAnswerSheet(
            "{\"lesson\": \"6\",\n\"answers\": {\"x\": 1" + std::string(400, '0') + "}}", "a.json");
    });
    EXPECT_TRUE(contains(what, "a.json:2: ")) << what;
    EXPECT_LT(what.size(), 200u) << what;
}

// Class 10: where a lesson came from decides whether it is built in, not its path's text.
TEST(LessonsHostile, ALecturersLessonUnderLessonsFindsItsSceneBesideIt) {
    const std::string text =
        "{\"format\": \"raystep-lesson\", \"version\": 1, \"id\": \"mine\", \"number\": 40,\n"
        "\"title\": {\"en\": \"T\"}, \"text\": {\"en\": \"x\"}, \"scene\": \"room.json\",\n"
        "\"setup\": {\"accel\": \"grid\"}, \"trace\": {\"ray\": \"example\"}}";
    EXPECT_EQ(lessonScenePath(loadLessonText(text, "lessons/my.json")), "lessons/room.json");
    EXPECT_EQ(lessonScenePath(loadLessonText(text, "./lessons/my.json")), "./lessons/room.json");
    // Built-in lessons name built-in scenes.
    for (const Lesson& b : builtinLessons()) EXPECT_EQ(lessonScenePath(b), b.scene);
    // On disk, relative to the working folder, as a lecturer types it.
    const TempDir dir;
    fs::create_directories(dir.path / "lessons");
    std::ofstream(dir.path / "lessons" / "room.json")
        << R"({"dimensions": 2, "grid": [2, 1], "ray": {"origin": [0.5, 0.5], "dir": [1, 0]},
               "segments": [{"from": [1.5, 0], "to": [1.5, 1]}]})";
    std::ofstream(dir.path / "lessons" / "my.json") << text;
    const fs::path before = fs::current_path();
    fs::current_path(dir.path);
    EXPECT_NO_THROW(validateLesson(loadLesson("lessons/my.json")));
    fs::current_path(before);
}

// Classes 1 and 13: paths that cannot be resolved, folders and special files are LessonErrors
// naming the file, for lessons, answers and progress files.
TEST(LessonsHostile, OnlyRegularFilesAreRead) {
    const TempDir dir;
    fs::create_symlink(dir.path / "b", dir.path / "a");
    fs::create_symlink(dir.path / "a", dir.path / "b");
    const std::string loop = (dir.path / "a").string();
    const std::string longName = (dir.path / std::string(300, 'x')).string() + "/l.json";
    for (const std::string& path : {loop, longName, dir.path.string(), std::string("/dev/zero")}) {
        SCOPED_TRACE(path);
        for (const auto& f : std::vector<std::function<void()>>{[&] { loadLesson(path); },
                                                                [&] { loadAnswerSheetFile(path); },
                                                                [&] { loadProgressFile(path); }}) {
            const std::string what = lessonErrorOf(f);
            EXPECT_EQ(what.rfind(path + ": cannot read the ", 0), 0u) << what;
        }
    }
    EXPECT_TRUE(contains(lessonErrorOf([&] { loadAnswerSheetFile(dir.path.string()); }),
                         "cannot read the answers file: it is a folder"));
    // A missing progress file is no progress yet; a missing answers file is an error.
    EXPECT_FALSE(loadProgressFile((dir.path / "none.json").string()).has_value());
    EXPECT_TRUE(
        contains(lessonErrorOf([&] { loadAnswerSheetFile((dir.path / "none.json").string()); }),
                 "none.json: cannot read the answers file: no such file"));
    std::ofstream(dir.path / "p.json") << progressToJson(Progress{});
    EXPECT_TRUE(loadProgressFile((dir.path / "p.json").string()).has_value());
}

// A NUL byte ends nlohmann's input: the lesson reader refuses it like every JSON reader of the core
// (moved from SceneLoaderHostile.ANulByteIsRefusedWithItsLine).
TEST(LessonsHostile, ANulByteIsRefused) {
    EXPECT_THROW(loadLessonText(std::string("{}\0", 3), "l.json"), LessonError);
}

// The line map's two fuzz findings (JsonLineMap.TheFuzzersFindingsEnd, whose lesson half this is)
// end in the lesson reader too, as its own error.
TEST(LessonsHostile, TheLineMapsFuzzFindingsEndAsALessonError) {
    const std::string nul(
        "//\0"
        "1\0\n{\"a\":[0}",
        14);
    const std::string cr = "{\"a\": [2//\r],\n\"b\": {}}";
    for (const std::string& text : {nul, cr})
        EXPECT_THROW(loadLessonText(text, "f.json"), LessonError);
}

}  // namespace
}  // namespace raystep
