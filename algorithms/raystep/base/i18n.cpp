// Reads the embedded catalogue once, on first use; its files are ours and a test loads them, so
// a malformed one is a programming error reported by name.
#include "raystep/base/i18n.h"

#include "raystep/base/i18n_catalogue.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace raystep {

std::optional<Language> parseLanguage(std::string_view code) {
    if (code == "en") return Language::En;
    if (code == "it") return Language::It;
    return std::nullopt;
}

std::string_view languageCode(Language lang) {
    return lang == Language::It ? "it" : "en";
}

std::map<std::string, std::map<std::string, std::string>> catalogueFiles(Language lang) {
    std::map<std::string, std::map<std::string, std::string>> files;
    if (lang == Language::En) return files;
    // Italian is the one other language: every embedded file is one of its (i18n/it/*.json).
    for (const std::string& name : embeddedCatalogueNames()) {
        const auto text = embeddedCatalogue(name);
        const auto json = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
        if (!json.is_object())
            throw std::logic_error("i18n catalogue " + name + ": not a JSON object of strings");
        auto& entries = files[name];
        for (const auto& [english, translated] : json.items()) {
            if (!translated.is_string())
                throw std::logic_error("i18n catalogue " + name + ": key '" + english +
                                       "' is not a string");
            entries.emplace(english, translated.get<std::string>());
        }
    }
    return files;
}

const std::map<std::string, std::string, std::less<>>& catalogue(Language lang) {
    static const std::map<std::string, std::string, std::less<>> empty;
    if (lang == Language::En) return empty;
    static const auto italian = [] {
        std::map<std::string, std::string, std::less<>> all;
        for (const auto& [file, entries] : catalogueFiles(Language::It))
            for (const auto& [english, text] : entries) all.emplace(english, text);
        return all;
    }();
    return italian;
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

std::string formatNumber(double v, Language lang, int digits) {
    std::string text = formatNumber(v, digits);
    if (lang == Language::It)
        for (char& c : text)
            if (c == '.') c = ',';
    return text;
}

}  // namespace raystep
