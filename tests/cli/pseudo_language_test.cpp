// The pseudo-language "xx": a language added at run time (RAYSTEP_LANGUAGES, base/i18n.h) whose
// every catalogue entry is the English in [[...]] and whose formats differ from both real
// languages (decimal mark "'", list separator " | ", ordinal "N."). Each built-in lesson is
// copied with an "xx" text beside every "en" one, also in [[...]]. The CLI's lesson show, key and
// check (right, wrong, junk and empty answers, one sheet and a class) then run in xx, and every
// word they print must sit inside [[...]]: a word outside is a sentence that skipped the
// catalogue, or a text the lesson file does not carry in every language.
#include "cli_folder.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace raystep::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSource = RAYSTEP_SOURCE_DIR;

/// A catalogue text marked: each stretch between its %N wrapped in [[...]] (the %N stay outside,
/// so a value filled in that skipped the catalogue shows unmarked); stretches without a letter
/// (": ", ".") are left as they are.
std::string markText(const std::string& english) {
    static const std::regex placeholder("%[1-9]");
    std::string out;
    const auto mark = [&](const std::string& part) {
        if (std::none_of(part.begin(), part.end(),
                         [](unsigned char c) { return std::isalpha(c); })) {
            out += part;
            return;
        }
        const std::size_t b = part.find_first_not_of(" \n"), e = part.find_last_not_of(" \n");
        out += part.substr(0, b) + "[[" + part.substr(b, e - b + 1) + "]]" + part.substr(e + 1);
    };
    std::size_t from = 0;
    for (auto it = std::sregex_iterator(english.begin(), english.end(), placeholder);
         it != std::sregex_iterator(); ++it) {
        mark(english.substr(from, it->position() - from));
        out += it->str();
        from = it->position() + it->length();
    }
    mark(english.substr(from));
    return out;
}

/// A lesson's text marked line by line (Markdown's lists and code blocks keep their lines).
json markLines(const json& en) {
    const auto line = [](const std::string& l) {
        return l.find_first_not_of(' ') == std::string::npos ? l : "[[" + l + "]]";
    };
    if (en.is_array()) {
        json out = json::array();
        for (const auto& l : en) out.push_back(line(l.get<std::string>()));
        return out;
    }
    std::string out, s = en.get<std::string>();
    std::istringstream in(s);
    for (std::string l; std::getline(in, l);) out += (out.empty() ? "" : "\n") + line(l);
    return out;
}

/// Every TEXT {"en": ...} of a lesson gets its "xx"; an erratum's plain slide line becomes a
/// TEXT too (a slide quoted as written reads the same in every language, but xx must mark it).
void addPseudoTexts(json& j) {
    if (j.is_object()) {
        if (j.contains("en") && (j["en"].is_string() || j["en"].is_array()) &&
            std::all_of(j.items().begin(), j.items().end(),
                        [](const auto& kv) { return kv.key() == "en" || kv.key() == "it"; })) {
            j["xx"] = markLines(j["en"]);
            return;
        }
        for (auto& [key, v] : j.items()) {
            if ((key == "slide" || key == "correct") && (v.is_string() || v.is_array()))
                v = json{{"en", v}, {"xx", markLines(v)}};
            else
                addPseudoTexts(v);
        }
    } else if (j.is_array()) {
        for (auto& v : j) addPseudoTexts(v);
    }
}

/// What may stand outside [[...]] in xx. Narrow on purpose, each for a reason:
/// - numbers (digits, with xx's decimal mark "'"), punctuation and formula signs: not words;
/// - one-letter names (the axes x, y, z; a formula's A, B, t; a choice's letter a-f);
/// - the lesson's and its exercises' ids, and an exercise's kind in "(count)": internal names
///   a student types or reads as they are (docs/architecture.md: not translated);
/// - the structures as the command line names them (grid, kdtree sah): likewise;
/// - the slides' symbols in a formula (tMaxX, tDelta.x, C_trav, Area(L)), which the lesson
///   text and the slides write the same in every language;
/// - the student's own answer, echoed after "[[given]]:" and in the class table's column of
///   wrong answers ("nonsense", the junk sheet's).
struct Tolerated {
    std::set<std::string> ids;
    std::set<std::string> words{// exercise kinds
                                "next_cell", "value", "pick_split", "count", "hit_or_miss",
                                "choice", "sequence", "sweep_pick", "compute", "overlap",
                                // structures and split methods as the command line names them
                                "grid", "kdtree", "bvh", "bruteforce", "sah", "midpoint", "median",
                                // the slides' symbols
                                "tMax", "tMaxX", "tMaxY", "tMaxZ", "tDelta", "tDeltaX", "tDeltaY",
                                "tDeltaZ", "t0", "t1", "t_enter", "t_exit", "C_trav", "C_isect",
                                "NL", "NR", "AC", "Area",
                                // the junk sheet's answer, echoed
                                "nonsense"};
};

/// `line` with its [[...]] (nested: a colour's name inside a lesson's text) blanked out.
std::string outsideMarks(const std::string& line) {
    std::string out;
    int depth = 0;
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (line.compare(i, 2, "[[") == 0) {
            ++depth;
            ++i;
            out += ' ';
        } else if (depth > 0 && line.compare(i, 2, "]]") == 0) {
            --depth;
            ++i;
            out += ' ';
        } else {
            out += depth ? ' ' : line[i];
        }
    }
    return out;
}

/// The words of `text` outside [[...]] that are not tolerated, each with its line.
std::vector<std::string> unmarkedWords(const std::string& text, const Tolerated& ok) {
    static const std::regex word("[A-Za-z_][A-Za-z_0-9]*");
    // "cell.x", "tMax.y": a formula's member of an axis.
    static const std::regex member("\\b(cell|tMax|tDelta|d|o)\\.[xyz]\\b");
    std::vector<std::string> found;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::string rest = line;
        if (const auto given = rest.find("[[given]]:"); given != std::string::npos)
            rest.resize(given);
        rest = std::regex_replace(outsideMarks(rest), member, " ");
        for (auto it = std::sregex_iterator(rest.begin(), rest.end(), word);
             it != std::sregex_iterator(); ++it) {
            const std::string w = it->str();
            // An id may hold '-': compare the whole run of the word, its digits and dashes.
            std::size_t b = it->position(), e = b + w.size();
            while (b > 0 && (std::isalnum(static_cast<unsigned char>(rest[b - 1])) ||
                             rest[b - 1] == '-' || rest[b - 1] == '_'))
                --b;
            while (e < rest.size() && (std::isalnum(static_cast<unsigned char>(rest[e])) ||
                                       rest[e] == '-' || rest[e] == '_'))
                ++e;
            if (w.size() == 1 || ok.words.count(w) || ok.ids.count(rest.substr(b, e - b))) continue;
            found.push_back("'" + w + "' in: " + line);
        }
    }
    return found;
}

class PseudoLanguage : public CliFolder {
  protected:
    void SetUp() override {
        CliFolder::SetUp();
        // xx: its formats, and every English key of the real catalogue, marked.
        fs::create_directories(dir / "langs" / "xx");
        write("langs/xx/language.json",
              R"({"name": "[[Pseudo]]", "decimal_mark": "'", "list_separator": " | ",
                  "ordinal": "%1.", "hit": ["[[hit]]"], "miss": ["[[miss]]"]})");
        json entries = json::object();
        for (const auto& f : fs::directory_iterator(kSource / "i18n" / "it")) {
            if (f.path().extension() != ".json" || f.path().filename() == "language.json") continue;
            std::ifstream in(f.path());
            const json file = json::parse(in);
            for (const auto& [english, italian] : file.items())
                entries[english] = markText(english);
        }
        ASSERT_GT(entries.size(), 500u);  // the catalogue was read at all
        write("langs/xx/all.json", entries.dump());
        env = "RAYSTEP_LANGUAGES='" + (dir / "langs").string() + "' ";
        // The built-in lessons with their xx texts.
        fs::create_directories(dir / "lessons");
        for (const auto& f : fs::directory_iterator(kSource / "lessons")) {
            if (f.path().extension() != ".json") continue;
            std::ifstream in(f.path());
            json lesson = json::parse(in);
            ok.ids.insert(lesson["id"].get<std::string>());
            for (const auto& e : lesson["exercises"]) ok.ids.insert(e["id"].get<std::string>());
            addPseudoTexts(lesson);
            write("lessons/" + f.path().filename().string(), lesson.dump(1));
            lessons.push_back("lessons/" + f.path().filename().string());
        }
        std::sort(lessons.begin(), lessons.end());
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
        for (const auto& [id, v] : json::parse(xxKey.out)["answers"].items()) {
            const std::string answer = v.get<std::string>();
            for (const std::string& w : unmarkedWords(answer, ok))
                ADD_FAILURE() << lesson << " key " << id << ": unmarked " << w;
            EXPECT_EQ(answer.find('.'), std::string::npos) << id << ": " << answer;
        }
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
