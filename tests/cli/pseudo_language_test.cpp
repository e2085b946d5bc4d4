// The pseudo-language "xx": a language added at run time (RAYSTEP_LANGUAGES, base/i18n.h) whose
// every catalogue entry is the English in [[...]] and whose formats differ from both real
// languages (decimal mark "'", list separator " | ", ordinal "N."). Each built-in lesson is
// copied with an "xx" text beside every "en" one, also in [[...]]. The CLI's lesson show, key and
// check (right, wrong, junk and empty answers, one sheet and a class) then run in xx, and every
// word they print must sit inside [[...]]: a word outside is a sentence that skipped the
// catalogue, or a text the lesson file does not carry in every language.
#include "pseudo_language.h"
#include "cli_folder.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace raystep::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using pseudo::outsideMarks;
using pseudo::Tolerated;
using pseudo::unmarkedWords;

const fs::path kSource = RAYSTEP_SOURCE_DIR;

class PseudoLanguage : public CliFolder {
  protected:
    void SetUp() override {
        CliFolder::SetUp();
        // xx: its formats, and every English key of the real catalogue, marked; the built-in
        // lessons with their xx texts.
        const pseudo::PseudoFolder made = pseudo::writePseudoLanguage(dir, kSource, ok);
        ASSERT_GT(made.entries, 500u);  // the catalogue was read at all
        env = "RAYSTEP_LANGUAGES='" + (dir / "langs").string() + "' ";
        lessons = made.lessons;
        ASSERT_EQ(lessons.size(), 13u);
    }

    /// Runs `args` and fails on each word outside [[...]] in what it printed.
    CliResult expectMarked(const std::string& args) {
        const CliResult r = run(args);
        EXPECT_EQ(r.code, 0) << args << "\n" << r.err;  // a grade, right or wrong, is not an error
        for (const std::string& w : unmarkedWords(r.out + r.err, ok))
            ADD_FAILURE() << args << ": unmarked " << w;
        return r;
    }

    Tolerated ok;
    std::vector<std::string> lessons;
};

TEST_F(PseudoLanguage, IsAChoiceOfLangAndWritesItsOwnFormats) {
    const CliResult help = run("lesson show --help");
    EXPECT_NE(help.out.find("en, it or xx"), std::string::npos) << help.out;
    // Lesson 6's key: tDelta.y is 2.5 (the ray's d.y = 0.4 on cells of 1).
    const CliResult key = run("lesson key lessons/06-grid-2d-dda.json --lang xx");
    EXPECT_NE(key.out.find("\"tdelta-y\": \"2'5\""), std::string::npos) << key.out;
    const CliResult unknown = run("lesson show 6 --lang yy");
    expectOneLine(unknown, "--lang yy", "expected en, it or xx");
}

TEST_F(PseudoLanguage, TheMarkerCatchesAnUnmarkedWord) {
    // The check itself: a word outside the marks is found, the tolerated ones are not.
    const auto words =
        unmarkedWords("[[Step]] 1 (x = 2'5, tMaxX) cell.x\n[[ok]] stray [[a [[b]] c]]", ok);
    ASSERT_EQ(words.size(), 1u);
    EXPECT_NE(words[0].find("'stray'"), std::string::npos) << words[0];
}

TEST_F(PseudoLanguage, LessonShowKeyAndCheckSayNothingUnmarked) {
    for (const std::string& lesson : lessons) {
        SCOPED_TRACE(lesson);
        expectMarked("lesson show " + lesson + " --lang xx");
        // The key in English makes the answer sheets: right, all zero, one off, junk, empty.
        const CliResult key = run("lesson key " + lesson);
        ASSERT_EQ(key.code, 0) << key.err;
        const json right = json::parse(key.out);
        const auto variant = [&](const auto& f) {
            json sheet = right;
            for (auto& [id, v] : sheet["answers"].items()) v = f(v.template get<std::string>());
            return sheet;
        };
        const std::string sheets = "sheets-" + fs::path(lesson).stem().string();
        fs::create_directories(dir / sheets);
        write(sheets + "/right.json", right.dump());
        write(sheets + "/zero.json",
              variant([](const std::string&) { return std::string("0"); }).dump());
        write(sheets + "/junk.json",
              variant([](const std::string&) { return std::string("nonsense"); }).dump());
        write(sheets + "/off.json", variant([](const std::string& v) {
                                        try {
                                            return std::to_string(std::stod(v) + 1);
                                        } catch (...) {
                                            return std::string(v == "a" ? "b" : "a");
                                        }
                                    }).dump());
        write(sheets + "/empty.json",
              json{{"lesson", right["lesson"]}, {"answers", json::object()}}.dump());
        for (const char* s : {"right", "zero", "junk", "off", "empty"})
            expectMarked("lesson check " + lesson + " --answers " + sheets + "/" + s +
                         ".json --lang xx");
        expectMarked("lesson check " + lesson + " --answers " + sheets + " --lang xx");

        // The key's answers in xx: only its values are the student's to read (the keys are ids).
        const CliResult xxKey = run("lesson key " + lesson + " --lang xx");
        ASSERT_EQ(xxKey.code, 0) << xxKey.err;
        const json xxAnswers = json::parse(xxKey.out)["answers"];  // outlives the loop over it
        for (const auto& [id, v] : xxAnswers.items()) {
            const std::string answer = v.get<std::string>();
            for (const std::string& w : unmarkedWords(answer, ok))
                ADD_FAILURE() << lesson << " key " << id << ": unmarked " << w;
            EXPECT_EQ(answer.find('.'), std::string::npos) << id << ": " << answer;
        }
        // ...and read back as xx writes them: the key in xx is a sheet with every answer right.
        write(sheets + "/xx-key.json", xxKey.out);
        const CliResult back =
            run("lesson check " + lesson + " --answers " + sheets + "/xx-key.json --lang xx");
        ASSERT_EQ(back.code, 0) << back.err;
        std::smatch score;
        const std::string first = back.out.substr(0, back.out.find('\n'));
        ASSERT_TRUE(std::regex_search(first, score, std::regex("(\\d+) / (\\d+)$"))) << first;
        EXPECT_EQ(score[1], score[2]) << first;
    }
}

TEST_F(PseudoLanguage, ListsOfNumbersUseTheLanguagesSeparator) {
    // Two numbers, one with xx's decimal mark, parted by English's ", ": a list the language's
    // separator (" | ") did not part.
    static const std::regex englishList("\\d'\\d+, -?\\d|\\d, -?\\d+'\\d");
    for (const std::string& lesson : lessons) {
        const CliResult key = run("lesson key " + lesson);
        ASSERT_EQ(key.code, 0) << key.err;
        json sheet = json::parse(key.out);
        for (auto& [id, v] : sheet["answers"].items()) v = "0";
        write("zero.json", sheet.dump());
        for (const std::string& args :
             {"lesson show " + lesson + " --lang xx",
              "lesson check " + lesson + " --answers zero.json --lang xx"}) {
            const CliResult r = run(args);
            std::istringstream in(r.out);
            for (std::string line; std::getline(in, line);)
                if (std::regex_search(outsideMarks(line), englishList))
                    ADD_FAILURE() << args << ": " << line;
        }
    }
}

}  // namespace
}  // namespace raystep::testing
