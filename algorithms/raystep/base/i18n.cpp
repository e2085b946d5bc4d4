// The language registry: built once, on first use, from the embedded files ("<code>/<file>",
// i18n_catalogue.h) and then from the folder RAYSTEP_LANGUAGES names. The embedded files are ours
// and a test loads them, so a malformed one is a programming error reported by name.
#include "raystep/base/i18n.h"

#include "raystep/base/i18n_catalogue.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace raystep {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::string_view kLanguageFile = "language.json";

/// A code a folder may carry: 2 to 7 lower-case letters, digits or '-' ("it", "pt-br").
bool validCode(std::string_view code) {
    if (code.size() < 2 || code.size() > 7) return false;
    return std::all_of(code.begin(), code.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
    });
}

std::vector<std::string> stringList(const json& v, const std::string& where) {
    std::vector<std::string> out;
    if (!v.is_array()) throw std::runtime_error(where + ": expected an array of strings");
    for (const auto& w : v) {
        if (!w.is_string()) throw std::runtime_error(where + ": expected an array of strings");
        out.push_back(w.get<std::string>());
    }
    return out;
}

/// language.json: the language's name and formats (LanguageInfo); an unknown key is refused.
void readLanguageFile(LanguageInfo& info, std::string_view text, const std::string& where) {
    const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!j.is_object()) throw std::runtime_error(where + ": not a JSON object");
    for (const auto& item : j.items()) {
        // Named, not a structured binding: clang 14 cannot capture a binding in a lambda.
        const std::string& key = item.key();
        const json& v = item.value();
        const std::string at = where + ": key '" + key + "'";
        const auto text = [&]() {
            if (!v.is_string()) throw std::runtime_error(at + ": expected a string");
            return v.get<std::string>();
        };
        if (key == "name")
            info.name = text();
        else if (key == "decimal_mark")
            info.decimalMark = text();
        else if (key == "list_separator")
            info.listSeparator = text();
        else if (key == "ordinal")
            info.ordinal = text();
        else if (key == "locale")
            info.locale = text();
        else if (key == "hit")
            info.hitWords = stringList(v, at);
        else if (key == "miss")
            info.missWords = stringList(v, at);
        else if (key == "words") {
            if (!v.is_object()) throw std::runtime_error(at + ": expected an object of lists");
            for (const auto& [role, list] : v.items())
                info.words[role] = stringList(list, at + "." + role);
        } else
            throw std::runtime_error(at +
                                     ": unknown (name, decimal_mark, list_separator, "
                                     "ordinal, locale, hit, miss, words)");
    }
    if (info.decimalMark.empty()) throw std::runtime_error(where + ": empty decimal_mark");
}

/// A catalogue file: {"English": "text"}; a later file's entry does not replace an earlier's.
void readCatalogueFile(LanguageInfo& info, const std::string& file, std::string_view text,
                       const std::string& where) {
    const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!j.is_object()) throw std::runtime_error(where + ": not a JSON object of strings");
    auto& entries = info.files[file];
    for (const auto& [english, translated] : j.items()) {
        if (!translated.is_string())
            throw std::runtime_error(where + ": key '" + english + "' is not a string");
        entries.emplace(english, translated.get<std::string>());
        info.entries.emplace(english, translated.get<std::string>());
    }
}

struct Registry {
    // A deque, never reordered: the references catalogue() and languageInfo() hand out stay
    // valid as languages are added (languages() sorts a copy); a replaced language's change.
    std::deque<LanguageInfo> infos;

    LanguageInfo& entry(std::string_view code) {
        for (LanguageInfo& i : infos)
            if (i.lang.code() == code) return i;
        LanguageInfo& added = infos.emplace_back();
        added.lang = Language(code);
        added.name = std::string(code);
        return added;
    }
    const LanguageInfo* find(Language lang) const {
        for (const LanguageInfo& i : infos)
            if (i.lang == lang) return &i;
        return nullptr;
    }
};

std::string readWholeFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw std::runtime_error(p.string() + ": cannot be read");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void addFrom(Registry& r, const std::string& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw std::runtime_error(dir + ": not a folder of languages (<code>/language.json)");
    std::vector<fs::path> folders;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (!e.is_directory()) continue;
        // A language.json that is no regular file (a FIFO, a device) is no language: never opened.
        if (!fs::is_regular_file(e.path() / kLanguageFile, ec)) continue;
        const std::string code = e.path().filename().string();
        if (!validCode(code))
            throw std::runtime_error(e.path().string() +
                                     ": a language's folder is its code (2 to " +
                                     "7 of a-z, 0-9, -)");
        folders.push_back(e.path());
    }
    std::sort(folders.begin(), folders.end());
    // Every folder read whole before any replaces a language of the same code (a folder is a
    // complete language): a file that cannot be read leaves the registry as it was.
    std::vector<LanguageInfo> read;
    for (const fs::path& folder : folders) {
        LanguageInfo& info = read.emplace_back();
        info.lang = Language(folder.filename().string());
        info.name = std::string(info.lang.code());
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(folder))
            if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const fs::path& p : files) {
            const std::string text = readWholeFile(p);
            if (p.filename() == kLanguageFile)
                readLanguageFile(info, text, p.string());
            else
                readCatalogueFile(info, p.filename().string(), text, p.string());
        }
    }
    for (LanguageInfo& info : read) r.entry(info.lang.code()) = std::move(info);
}

Registry makeRegistry() {
    Registry r;
    r.entry("en");  // the source language, first, whatever is embedded
    for (const std::string& path : embeddedCatalogueNames()) {
        const auto slash = path.find('/');
        const std::string code = path.substr(0, slash);
        const std::string file = slash == std::string::npos ? "" : path.substr(slash + 1);
        if (!validCode(code) || file.empty() || file.find('/') != std::string::npos)
            throw std::logic_error("i18n: embedded file " + path + " is not <code>/<file>.json");
        LanguageInfo& info = r.entry(code);
        const auto text = embeddedCatalogue(path);
        try {
            if (file == kLanguageFile)
                readLanguageFile(info, *text, "i18n/" + path);
            else
                readCatalogueFile(info, file, *text, "i18n/" + path);
        } catch (const std::runtime_error& e) {
            throw std::logic_error(e.what());
        }
    }
    if (const char* dir = std::getenv("RAYSTEP_LANGUAGES"); dir && *dir) addFrom(r, dir);
    return r;
}

Registry& registry() {
    static Registry r = makeRegistry();
    return r;
}

}  // namespace

std::vector<Language> languages() {
    std::vector<Language> out;
    for (const LanguageInfo& i : registry().infos) out.push_back(i.lang);
    // English first (the source language), the others by code.
    std::sort(out.begin() + 1, out.end(),
              [](Language a, Language b) { return a.code() < b.code(); });
    return out;
}

std::string languageChoices() {
    const auto all = languages();
    std::string s;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (i) s += i + 1 == all.size() ? " or " : ", ";
        s += all[i].code();
    }
    return s;
}

const LanguageInfo& languageInfo(Language lang) {
    const Registry& r = registry();
    const LanguageInfo* found = r.find(lang);
    return found ? *found : r.infos.front();
}

std::vector<std::string> wordsInAnyLanguage(std::string_view role) {
    std::vector<std::string> out;
    for (const Language lang : languages()) {
        const auto& words = languageInfo(lang).words;
        if (const auto found = words.find(role); found != words.end())
            out.insert(out.end(), found->second.begin(), found->second.end());
    }
    return out;
}

std::optional<Language> parseLanguage(std::string_view code) {
    for (const Language l : languages())
        if (l.code() == code) return l;
    return std::nullopt;
}

std::string_view languageCode(Language lang) {
    return languageInfo(lang).lang.code();
}

void addLanguages(const std::string& dir) {
    addFrom(registry(), dir);
}

std::map<std::string, std::map<std::string, std::string>> catalogueFiles(Language lang) {
    return languageInfo(lang).files;
}

const std::map<std::string, std::string, std::less<>>& catalogue(Language lang) {
    return languageInfo(lang).entries;
}

std::string tr(Language lang, std::string_view english) {
    if (lang == Language::En) return std::string(english);
    const auto& table = catalogue(lang);
    const auto it = table.find(english);
    return it == table.end() ? std::string(english) : it->second;
}

std::string substitute(std::string_view pattern, std::initializer_list<std::string_view> args) {
    std::string out;
    out.reserve(pattern.size() + 16 * args.size());
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        const char c = pattern[i];
        if (c == '%' && i + 1 < pattern.size()) {
            const char n = pattern[i + 1];
            if (n == '%') {
                out += '%';
                ++i;
                continue;
            }
            if (n >= '1' && n <= '9' && static_cast<std::size_t>(n - '1') < args.size()) {
                out += *(args.begin() + (n - '1'));
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
}

std::string trf(Language lang, std::string_view english,
                std::initializer_list<std::string_view> args) {
    return substitute(tr(lang, english), args);
}

std::string_view decimalMark(Language lang) {
    return languageInfo(lang).decimalMark;
}

std::string_view listSeparator(Language lang) {
    return languageInfo(lang).listSeparator;
}

std::string ordinal(Language lang, int n) {
    const std::string s = std::to_string(n);
    const std::string& pattern = languageInfo(lang).ordinal;
    if (!pattern.empty()) return substitute(pattern, {s});
    const int tens = n % 100, units = n % 10;
    if (tens >= 11 && tens <= 13) return s + "th";
    return s + (units == 1 ? "st" : units == 2 ? "nd" : units == 3 ? "rd" : "th");
}

std::string formatNumber(double v, Language lang, int digits) {
    const std::string text = formatNumber(v, digits);
    const std::string_view mark = decimalMark(lang);
    if (mark == ".") return text;
    std::string out;
    out.reserve(text.size() + mark.size());
    for (const char c : text)
        if (c == '.')
            out += mark;
        else
            out += c;
    return out;
}

}  // namespace raystep
