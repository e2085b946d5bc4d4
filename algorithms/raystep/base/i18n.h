#pragma once
// The one translation mechanism of raystep (docs/architecture.md, "Languages"): English text is
// the key, a language's text is looked up in its catalogue i18n/<code>/*.json, embedded in the
// binaries. A language is data: its catalogue and its formats (i18n/<code>/language.json), found
// by what is embedded (or added from a folder), so adding one changes no code.
// The Qt-free code calls tr/trf; the app's Qt tr() reads the same catalogue through a
// QTranslator, so a string is translated once, in one place, whoever shows it.
#include "raystep/base/format.h"

#include <array>
#include <cstddef>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// A language, by its code ("en", "it"): a small value, compared by code. What it says and how
/// it writes numbers is in the registry (languageInfo); a code the registry does not know reads
/// as English. English is the source language and always present.
class Language {
  public:
    constexpr Language() : Language("en") {}
    /// Any code of up to 7 characters; parseLanguage is the checked way from user input.
    constexpr explicit Language(std::string_view code) {
        for (std::size_t i = 0; i < code.size() && i + 1 < code_.size(); ++i) code_[i] = code[i];
    }
    constexpr std::string_view code() const {
        std::size_t n = 0;
        while (n < code_.size() && code_[n]) ++n;
        return {code_.data(), n};
    }
    constexpr bool operator==(const Language&) const = default;

    static const Language En;
    /// Italian, by name, for the tests of its texts; the code asks the registry (languages(),
    /// parseLanguage) and the formats below, and tests for no language but the source.
    static const Language It;

  private:
    std::array<char, 8> code_{};
};
inline constexpr Language Language::En{"en"};
inline constexpr Language Language::It{"it"};

/// What the code decides per language, read from i18n/<code>/language.json (every key optional;
/// docs/architecture.md, "Add a language").
struct LanguageInfo {
    Language lang;
    std::string name;                   // the language's name in itself: "Italiano"
    std::string decimalMark = ".";      // "3,55"
    std::string listSeparator = ", ";   // between numbers of a tuple or a list: "(0,6; 0,8)"
    std::string ordinal;                // "%1" for Italian; empty: English's 1st, 2nd, 3rd, 4th
    std::string locale;                 // Qt's locale of the app's widgets ("it_IT"); empty: system
    std::vector<std::string> hitWords;  // the words an answer may say "hit" with; the first is
    std::vector<std::string> missWords;  // the one written; likewise for "miss"
    /// The words a role is said with, for the lesson checks that read texts ("question": the
    /// words of a question that is not yes-or-no; "outcome", "circle", "material:mirror"...).
    std::map<std::string, std::vector<std::string>, std::less<>> words;
    /// The catalogue: English -> text, all files together, and per file for the tests.
    std::map<std::string, std::string, std::less<>> entries;
    std::map<std::string, std::map<std::string, std::string>> files;
};

/// Every language: English first, then the others by code (the embedded ones and those added
/// with addLanguages or RAYSTEP_LANGUAGES).
std::vector<Language> languages();
/// The codes as a sentence for help and errors: "en or it", "en, it or xx".
std::string languageChoices();
/// The registry's entry; English's for a code it does not know.
const LanguageInfo& languageInfo(Language lang);
/// The words of `role` (LanguageInfo::words) in every language, English's first.
std::vector<std::string> wordsInAnyLanguage(std::string_view role);
/// The language of `code` if the registry has it.
std::optional<Language> parseLanguage(std::string_view code);
std::string_view languageCode(Language lang);  // "en", "it"

/// Adds the languages in `dir`, one folder each (dir/<code>/language.json and any other *.json
/// as its catalogue), over an embedded one of the same code. The binaries call it on the folder
/// the environment variable RAYSTEP_LANGUAGES names, when the registry is first used; tests call
/// it directly. Call it before other threads use the languages, and before anything holds the
/// catalogue or a format of a language it replaces (those change). Throws std::runtime_error
/// naming the file that cannot be read, having added nothing.
void addLanguages(const std::string& dir);

/// `english` in `lang`: itself in English, the catalogue's entry otherwise (the English when the
/// catalogue lacks it; the catalogue test makes sure no source string does).
std::string tr(Language lang, std::string_view english);
/// `english` marked for the catalogue where it is written (a table of names) and translated
/// later with tr or catalogue(): the catalogue test reads trNoop's literals as it reads tr's.
constexpr std::string_view trNoop(std::string_view english) {
    return english;
}
/// `pattern` with %1..%9 replaced by `args` (in order; %% is a percent sign).
std::string substitute(std::string_view pattern, std::initializer_list<std::string_view> args);
/// tr, then substitute: word order may differ between languages, the numbers follow their %N.
std::string trf(Language lang, std::string_view english,
                std::initializer_list<std::string_view> args);

/// The language's decimal mark ("." in English, "," in Italian).
std::string_view decimalMark(Language lang);
/// What parts the numbers of a tuple or a list (", " in English, "; " in Italian, where the
/// comma is the decimal mark).
std::string_view listSeparator(Language lang);
/// "1st", "2nd" in English; the language's "ordinal" pattern otherwise ("%1" in Italian).
std::string ordinal(Language lang, int n);
/// formatNumber in the language's way of writing it: a decimal comma in Italian ("3,55").
std::string formatNumber(double v, Language lang, int digits = kReadableDigits);

/// The whole catalogue of a language (English -> text), for the app's QTranslator and the tests.
/// Empty for English.
const std::map<std::string, std::string, std::less<>>& catalogue(Language lang);
/// Catalogue file names and entries, per file, for the test that checks them.
std::map<std::string, std::map<std::string, std::string>> catalogueFiles(Language lang);

}  // namespace raystep
