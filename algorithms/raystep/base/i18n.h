#pragma once
// The one translation mechanism of raystep (docs/architecture.md, "Languages"): English text is
// the key, the Italian is looked up in the catalogue i18n/it/*.json, embedded in the binaries.
// The Qt-free code calls tr/trf; the app's Qt tr() reads the same catalogue through a
// QTranslator, so a string is translated once, in one place, whoever shows it.
#include "raystep/base/format.h"

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace raystep {

enum class Language { En, It };
std::optional<Language> parseLanguage(std::string_view code);  // "en", "it"
std::string_view languageCode(Language lang);                  // "en", "it"

/// `english` in `lang`: itself in English, the catalogue's entry otherwise (the English when the
/// catalogue lacks it; the catalogue test makes sure no source string does).
std::string tr(Language lang, std::string_view english);
/// `pattern` with %1..%9 replaced by `args` (in order; %% is a percent sign).
std::string substitute(std::string_view pattern, std::initializer_list<std::string_view> args);
/// tr, then substitute: word order may differ between languages, the numbers follow their %N.
std::string trf(Language lang, std::string_view english,
                std::initializer_list<std::string_view> args);

/// formatNumber in the language's way of writing it: a decimal comma in Italian ("3,55").
std::string formatNumber(double v, Language lang, int digits = kReadableDigits);

/// The whole catalogue of a language (English -> text), for the app's QTranslator and the tests.
/// Empty for English.
const std::map<std::string, std::string, std::less<>>& catalogue(Language lang);
/// Catalogue file names and entries, per file, for the test that checks them.
std::map<std::string, std::map<std::string, std::string>> catalogueFiles(Language lang);

}  // namespace raystep
