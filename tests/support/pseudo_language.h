#pragma once
// The pseudo-language "xx" the CLI and GUI tests share (tests/cli/pseudo_language_test.cpp,
// tests/gui/pseudo_language_gui_test.cpp): a language whose every catalogue entry is the English
// in [[...]] and whose formats differ from both real languages (decimal mark "'", list separator
// " | ", ordinal "N."), copies of the built-in lessons with an "xx" text beside every "en" one,
// and the check that finds a word outside [[...]].
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

namespace raystep::testing::pseudo {

namespace fs = std::filesystem;
using nlohmann::json;

/// A catalogue text marked: each stretch between its %N wrapped in [[...]] (the %N stay outside,
/// so a value filled in that skipped the catalogue shows unmarked); stretches without a letter
/// (": ", ".") are left as they are.
inline std::string markText(const std::string& english) {
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
inline json markLines(const json& en) {
    const auto line = [](const std::string& l) {
        // Built by append: GCC 12 warns (-Wrestrict, falsely) on "[[" + l + "]]".
        return l.find_first_not_of(' ') == std::string::npos
                   ? l
                   : std::string("[[").append(l).append("]]");
    };
    if (en.is_array()) {
        json out = json::array();
        for (const auto& l : en) out.push_back(line(l.get<std::string>()));
        return out;
    }
    std::string out, s = en.get<std::string>();
    std::istringstream in(s);
    for (std::string l; std::getline(in, l);) {
        if (!out.empty()) out += '\n';
        out += line(l);
    }
    return out;
}

/// Every TEXT {"en": ...} of a lesson gets its "xx"; an erratum's plain slide line becomes a
/// TEXT too (a slide quoted as written reads the same in every language, but xx must mark it).
inline void addPseudoTexts(json& j) {
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
    // The exercises' ids (the writer adds them) and the DDA mistakes as assess names them.
    std::set<std::string> ids{"start-cell-skipped",     "negative-direction-boundary",
                              "parallel-axis-division", "negative-zero",
                              "tie-one-axis",           "no-entry-clip",
                              "no-exit-check",          "accumulated-tmax"};
    std::set<std::string> words{
        // exercise kinds
        "next_cell", "value", "pick_split", "count", "hit_or_miss", "choice", "sequence",
        "sweep_pick", "compute", "overlap", "spot_bug",
        // structures and split methods as the command line names them
        "grid", "kdtree", "bvh", "bruteforce", "sah", "midpoint", "median",
        // the slides' symbols
        "tMax", "tMaxX", "tMaxY", "tMaxZ", "tDelta", "tDeltaX", "tDeltaY", "tDeltaZ", "t0", "t1",
        "t_enter", "t_exit", "C_trav", "C_isect", "NL", "NR", "AC", "Area",
        // the junk sheet's answer, echoed
        "nonsense"};
};

/// `line` with its [[...]] (nested: a colour's name inside a lesson's text) blanked out.
inline std::string outsideMarks(const std::string& line) {
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
inline std::vector<std::string> unmarkedWords(const std::string& text, const Tolerated& ok) {
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

/// What writePseudoLanguage made.
struct PseudoFolder {
    std::size_t entries = 0;           ///< xx's catalogue entries (the real catalogue's keys)
    std::vector<std::string> lessons;  ///< the xx lessons, relative to the folder, sorted
};

/// Writes into `dir` the language folder `langs` (langs/xx: its formats, and every English key
/// of the catalogue in `source`/i18n/it, marked) and `lessons` (the built-in lessons of
/// `source`/lessons with their xx texts); adds the lessons' and exercises' ids to `ok`.
inline PseudoFolder writePseudoLanguage(const fs::path& dir, const fs::path& source,
                                        Tolerated& ok) {
    const auto write = [&](const std::string& name, const std::string& bytes) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
    };
    PseudoFolder made;
    fs::create_directories(dir / "langs" / "xx");
    write("langs/xx/language.json",
          R"({"name": "[[Pseudo]]", "decimal_mark": "'", "list_separator": " | ",
              "ordinal": "%1.", "hit": ["[[hit]]"], "miss": ["[[miss]]"]})");
    json entries = json::object();
    for (const auto& f : fs::directory_iterator(source / "i18n" / "it")) {
        if (f.path().extension() != ".json" || f.path().filename() == "language.json") continue;
        std::ifstream in(f.path());
        const json file = json::parse(in);
        for (const auto& [english, italian] : file.items()) entries[english] = markText(english);
    }
    made.entries = entries.size();
    write("langs/xx/all.json", entries.dump());
    fs::create_directories(dir / "lessons");
    for (const auto& f : fs::directory_iterator(source / "lessons")) {
        if (f.path().extension() != ".json") continue;
        std::ifstream in(f.path());
        json lesson = json::parse(in);
        ok.ids.insert(lesson["id"].get<std::string>());
        for (const auto& e : lesson["exercises"]) ok.ids.insert(e["id"].get<std::string>());
        addPseudoTexts(lesson);
        write("lessons/" + f.path().filename().string(), lesson.dump(1));
        made.lessons.push_back("lessons/" + f.path().filename().string());
    }
    std::sort(made.lessons.begin(), made.lessons.end());
    return made;
}

}  // namespace raystep::testing::pseudo
