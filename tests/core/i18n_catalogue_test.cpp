// No string is left untranslated: every literal the sources pass to tr/trf (the core's and the
// course's, base/i18n.h) or to Qt's tr()/QT_TR_NOOP/QT_TRANSLATE_NOOP has an Italian entry in
// i18n/it/*.json with the same %N placeholders, and every entry is still used by some source.
// It reads the catalogue as the binaries embed it, so what it checks is what a student gets.
#include "raystep/base/i18n.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace raystep {
namespace {

namespace fs = std::filesystem;

struct Token {
    enum Kind { Identifier, Literal, Punct } kind;
    std::string text;  // a literal's decoded value
    int line;
};

/// What a scan of one source finds: the keys, and the calls whose text is not a literal.
struct Found {
    struct Key {
        std::string text;
        int line;
    };
    std::vector<Key> keys;
    std::vector<int> dynamicCalls;  // lines of calls without a literal text and no "i18n:" note
};

/// A C++ literal's escapes, as the compiler reads them (the sources use \n \t \" \\ \').
std::string unescape(const std::string& body) {
    std::string out;
    for (std::size_t i = 0; i < body.size(); ++i) {
        if (body[i] != '\\' || i + 1 == body.size()) {
            out += body[i];
            continue;
        }
        const char c = body[++i];
        out += c == 'n' ? '\n' : c == 't' ? '\t' : c;
    }
    return out;
}

/// Tokens of C++ source with comments dropped; `notes` gets the lines of "i18n:" comments.
std::vector<Token> tokenize(const std::string& src, std::set<int>& notes) {
    std::vector<Token> tokens;
    int line = 1;
    const auto isIdent = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    for (std::size_t i = 0; i < src.size();) {
        const char c = src[i];
        if (c == '\n') {
            ++line;
            ++i;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (src.compare(i, 2, "//") == 0) {
            const std::size_t end = src.find('\n', i);
            const std::string comment = src.substr(i, end - i);
            if (comment.find("i18n:") != std::string::npos) notes.insert(line);
            i = end == std::string::npos ? src.size() : end;
        } else if (src.compare(i, 2, "/*") == 0) {
            const std::size_t end = std::min(src.find("*/", i + 2), src.size());
            line += static_cast<int>(std::count(src.begin() + i, src.begin() + end, '\n'));
            i = end + 2;
        } else if (c == 'R' && src.compare(i, 2, "R\"") == 0) {
            // A raw literal R"delim( ... )delim".
            const std::size_t open = src.find('(', i);
            const std::string close = ")" + src.substr(i + 2, open - i - 2) + "\"";
            const std::size_t end = src.find(close, open);
            tokens.push_back({Token::Literal, src.substr(open + 1, end - open - 1), line});
            line += static_cast<int>(std::count(src.begin() + i, src.begin() + end, '\n'));
            i = end + close.size();
        } else if (c == '"' || c == '\'') {
            std::size_t j = i + 1;
            while (j < src.size() && src[j] != c) j += src[j] == '\\' ? 2 : 1;
            if (c == '"')
                tokens.push_back({Token::Literal, unescape(src.substr(i + 1, j - i - 1)), line});
            i = j + 1;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            // A number, with its digit separators (4'000'000): no quote of a char literal.
            std::size_t j = i;
            while (j < src.size() && (isIdent(src[j]) || src[j] == '.' || src[j] == '\'')) ++j;
            tokens.push_back({Token::Punct, src.substr(i, j - i), line});
            i = j;
        } else if (isIdent(c)) {
            std::size_t j = i;
            while (j < src.size() && isIdent(src[j])) ++j;
            std::string word = src.substr(i, j - i);
            // u8"..." and L"...": the prefix belongs to the literal that follows.
            if (j < src.size() && src[j] == '"' && (word == "u8" || word == "L" || word == "u")) {
                i = j;
                continue;
            }
            tokens.push_back({Token::Identifier, std::move(word), line});
            i = j;
        } else {
            // "::" and "->" as one token, so a call's scope can be read.
            const bool two = src.compare(i, 2, "::") == 0 || src.compare(i, 2, "->") == 0;
            tokens.push_back({Token::Punct, src.substr(i, two ? 2 : 1), line});
            i += two ? 2 : 1;
        }
    }
    return tokens;
}

/// The texts an argument holds: each run of adjacent literals (the compiler joins them) is one,
/// so `hit ? "a" : "b"` gives two and a literal split over lines gives one.
std::vector<std::string> literalsOf(const std::vector<Token>& arg) {
    std::vector<std::string> texts;
    bool joining = false;
    for (const Token& t : arg) {
        if (t.kind == Token::Literal) {
            if (joining)
                texts.back() += t.text;
            else
                texts.push_back(t.text);
            joining = true;
        } else {
            joining = false;
        }
    }
    return texts;
}

Found scan(const std::string& source) {
    Found found;
    std::set<int> notes;
    const std::vector<Token> tokens = tokenize(source, notes);
    // Which argument holds the text: QT_TR_NOOP(text), QT_TRANSLATE_NOOP(context, text),
    // QCoreApplication::translate(context, text); tr/trf below.
    static const std::map<std::string, int> kTextArgument = {{"tr", 0},
                                                             {"trf", 0},
                                                             {"trNoop", 1},
                                                             {"QT_TR_NOOP", 1},
                                                             {"QT_TRANSLATE_NOOP", 2},
                                                             {"QT_TRANSLATE_NOOP3", 2},
                                                             {"translate", 2}};
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
        const Token& name = tokens[i];
        if (name.kind != Token::Identifier || tokens[i + 1].text != "(") continue;
        const auto which = kTextArgument.find(name.text);
        if (which == kTextArgument.end()) continue;
        // translate: only Qt's own (QTranslator::translate is what reads the catalogue).
        if (name.text == "translate" &&
            !(i >= 2 && tokens[i - 1].text == "::" &&
              (tokens[i - 2].text == "QCoreApplication" || tokens[i - 2].text == "QApplication")))
            continue;
        // The arguments, split at the commas outside brackets.
        std::vector<std::vector<Token>> args(1);
        int depth = 0;
        std::size_t j = i + 2;
        for (; j < tokens.size(); ++j) {
            const std::string& t = tokens[j].text;
            if (tokens[j].kind == Token::Punct && (t == "(" || t == "[" || t == "{")) ++depth;
            if (tokens[j].kind == Token::Punct && (t == ")" || t == "]" || t == "}")) {
                if (depth == 0) break;
                --depth;
            }
            if (depth == 0 && tokens[j].kind == Token::Punct && t == ",")
                args.emplace_back();
            else
                args.back().push_back(tokens[j]);
        }
        // Qt's tr(text, ...) has the text first; the core's tr(lang, text) second.
        int index = which->second;
        if (index == 0) index = literalsOf(args[0]).empty() ? 2 : 1;
        const std::vector<std::string> texts = index <= static_cast<int>(args.size())
                                                   ? literalsOf(args[index - 1])
                                                   : std::vector<std::string>{};
        if (texts.empty()) {
            if (!notes.count(name.line) && !notes.count(name.line - 1))
                found.dynamicCalls.push_back(name.line);
        }
        for (const std::string& t : texts) found.keys.push_back({t, name.line});
    }
    return found;
}

/// The %1..%9 a text uses ("%%" is a percent sign, not a placeholder).
std::set<char> placeholders(const std::string& text) {
    std::set<char> found;
    for (std::size_t i = 0; i + 1 < text.size(); ++i)
        if (text[i] == '%') {
            if (text[i + 1] >= '1' && text[i + 1] <= '9') found.insert(text[i + 1]);
            ++i;
        }
    return found;
}

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The mechanism's own code passes its parameters on, not texts.
bool isMechanism(const fs::path& relative) {
    return relative == "algorithms/raystep/base/i18n.h" ||
           relative == "algorithms/raystep/base/i18n.cpp";
}

TEST(I18nExtract, FindsEveryFormOfTranslatedText) {
    const Found f = scan(R"src(
        a = tr(lang, "core text");
        b = trf(lang, "with %1", {x});
        c = tr("Qt text").arg(1);
        d = QObject::tr("Qt's %1", "a disambiguation, not a text");
        e = tr(lang, "joined over "
                     "two lines");
        f = QT_TR_NOOP("marked");
        g = QT_TRANSLATE_NOOP("raystep::gui::Timeline", "in a context");
        h = QCoreApplication::translate("Ctx", "asked of Qt");
        i = trf(lang, hit ? "yes at %1" : "no", {t});
        j = tr(lang, "escaped \"quote\"\n");
        k = tr(lang, u8"prefixed");
        n = 4'000'000 + tr(lang, "after a number");
        // tr(lang, "in a comment") is no call
        /* nor tr("in this one") */
        s = str("not a call of tr");
    )src");
    std::vector<std::string> texts;
    for (const auto& k : f.keys) texts.push_back(k.text);
    EXPECT_EQ(texts, (std::vector<std::string>{
                         "core text", "with %1", "Qt text", "Qt's %1", "joined over two lines",
                         "marked", "in a context", "asked of Qt", "yes at %1", "no",
                         "escaped \"quote\"\n", "prefixed", "after a number"}));
    EXPECT_EQ(f.keys[4].line, 6);
    EXPECT_TRUE(f.dynamicCalls.empty());
}

TEST(I18nExtract, ATextThatIsNotALiteralMustSayWhereItsTextsAre) {
    const Found f = scan(
        "x = tr(lang, name);\n"
        "y = tr(name);  // i18n: marked with QT_TR_NOOP in kNames\n"
        "// i18n: the names are marked above\n"
        "z = tr(lang, other);\n"
        "std::string tr(Language lang, std::string_view english);\n");
    EXPECT_EQ(f.dynamicCalls, (std::vector<int>{1, 5}));
}

TEST(I18nExtract, PlaceholdersAreCountedNotPercentSigns) {
    EXPECT_EQ(placeholders("%2 of %1, 100%% sure"), (std::set<char>{'1', '2'}));
    EXPECT_TRUE(placeholders("50%% off").empty());
}

/// The sources' texts and the built-in scenes' descriptions, each with where it is.
struct SourceTexts {
    std::vector<std::pair<std::string, std::string>> keys;  // text, "file:line"
    std::set<std::string> scenes;
};

SourceTexts sourceTexts(const fs::path& root) {
    SourceTexts out;
    for (const char* top : {"algorithms", "app"})
        for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
            const fs::path ext = entry.path().extension();
            if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
            const fs::path relative = fs::relative(entry.path(), root);
            const Found found = scan(read(entry.path()));
            for (const int line : found.dynamicCalls)
                if (!isMechanism(relative))
                    ADD_FAILURE()
                        << relative.string() << ":" << line
                        << ": the text to translate is not a literal; pass the literal, "
                           "or mark its texts (QT_TR_NOOP, trNoop, a tr call on each) and say "
                           "where in an \"// i18n:\" comment on the call's line or the line before";
            for (const auto& [text, line] : found.keys)
                out.keys.emplace_back(text, relative.string() + ":" + std::to_string(line));
        }
    // The built-in scenes' descriptions: the app shows them in the interface's language.
    std::vector<std::string> scenes = builtinSceneNames();
    for (std::string& name : builtinScene2DNames()) scenes.push_back(std::move(name));
    for (const std::string& name : scenes) {
        const auto scene = loadAnyScene(name);
        const std::string& text = std::visit([](const auto& s) { return s.description; }, scene);
        if (!text.empty()) out.scenes.insert(text);
    }
    return out;
}

TEST(I18nCatalogue, TheEmbeddedLanguagesAreTheFolders) {
    const fs::path root = RAYSTEP_SOURCE_DIR;
    // A folder added since the build would go unchecked: rebuild.
    std::set<std::string> onDisk, embedded;
    for (const auto& entry : fs::directory_iterator(root / "i18n"))
        if (fs::exists(entry.path() / "language.json"))
            onDisk.insert(entry.path().filename().string());
    for (const Language l : languages()) embedded.insert(std::string(l.code()));
    EXPECT_EQ(embedded, onDisk);
    EXPECT_TRUE(onDisk.count("en") && onDisk.count("it"));
    EXPECT_EQ(languages().front(), Language::En);  // the source language comes first
}

TEST(I18nCatalogue, EverySourceTextIsTranslatedAndEveryEntryIsUsed) {
    const fs::path root = RAYSTEP_SOURCE_DIR;
    const SourceTexts sources = sourceTexts(root);
    EXPECT_GT(sources.keys.size(), 100u);  // the scan found the sources' texts at all
    for (const Language lang : languages()) {
        if (lang == Language::En) continue;  // the key: complete by construction
        const std::string code(lang.code());
        // The embedded files are the folder's: a file added since the build would go unchecked.
        const auto files = catalogueFiles(lang);
        std::set<std::string> onDisk, embedded;
        for (const auto& entry : fs::directory_iterator(root / "i18n" / code))
            if (entry.path().extension() == ".json" && entry.path().filename() != "language.json")
                onDisk.insert(entry.path().filename().string());
        for (const auto& [file, entries] : files) embedded.insert(file);
        EXPECT_EQ(embedded, onDisk) << "rebuild: the catalogue embedded is not i18n/" << code;

        std::map<std::string, std::string> fileOf;  // English -> the catalogue file that has it
        for (const auto& [file, entries] : files)
            for (const auto& [english, translated] : entries) fileOf[english] = file;
        const auto& table = catalogue(lang);
        std::set<std::string> used;
        for (const auto& [text, where] : sources.keys) {
            used.insert(text);
            const auto it = table.find(text);
            if (it == table.end()) {
                ADD_FAILURE() << where << ": no " << code << " text for \"" << text
                              << "\" (add it to i18n/" << code << "/<area>.json)";
                continue;
            }
            EXPECT_EQ(placeholders(it->second), placeholders(text))
                << where << ": the placeholders differ between \"" << text << "\" and its " << code
                << " \"" << it->second << "\" (" << fileOf[text] << ")";
        }
        for (const std::string& text : sources.scenes) {
            used.insert(text);
            if (!table.count(text))
                ADD_FAILURE() << "a built-in scene: no " << code << " text for the description \""
                              << text << "\" (add it to i18n/" << code << "/scenes.json)";
        }
        for (const auto& [english, file] : fileOf)
            if (!used.count(english))
                ADD_FAILURE() << "i18n/" << code << "/" << file << ": \"" << english
                              << "\" is used by no source (remove it, or the source lost its tr)";
    }
}

}  // namespace
}  // namespace raystep
