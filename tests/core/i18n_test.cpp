// The translation mechanism's own rules (base/i18n.h); the catalogue's completeness against the
// sources is checked by the i18n catalogue test.
#include "raystep/base/i18n.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace raystep {
namespace {

TEST(I18n, SubstituteFillsPlaceholdersInAnyOrder) {
    EXPECT_EQ(substitute("%2 before %1", {"a", "b"}), "b before a");
    EXPECT_EQ(substitute("100%% of %1", {"x"}), "100% of x");
    // A placeholder without an argument stays as written, so the slip is visible, not silent.
    EXPECT_EQ(substitute("%1 and %3", {"a"}), "a and %3");
}

TEST(I18n, ItalianNumbersUseADecimalComma) {
    EXPECT_EQ(formatNumber(3.55, Language::It), "3,55");
    EXPECT_EQ(formatNumber(3.55, Language::En), "3.55");
    EXPECT_EQ(formatNumber(1e-5, Language::It), "1e-05");
    EXPECT_EQ(formatNumber(-0.25, Language::It), "-0,25");
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity(), Language::It), "inf");
}

TEST(I18n, EnglishIsTheKeyAndUnknownTextPassesThrough) {
    EXPECT_EQ(tr(Language::En, "anything at all"), "anything at all");
    EXPECT_EQ(tr(Language::It, "a sentence no catalogue holds 7f3a"),
              "a sentence no catalogue holds 7f3a");
    EXPECT_TRUE(catalogue(Language::En).empty());
}

TEST(I18n, LanguagesByCode) {
    EXPECT_EQ(parseLanguage("it"), Language::It);
    EXPECT_EQ(parseLanguage("en"), Language::En);
    EXPECT_FALSE(parseLanguage("IT"));
    EXPECT_FALSE(parseLanguage(""));
    EXPECT_EQ(languageCode(Language::It), "it");
}

TEST(I18n, EveryCatalogueFileLoadsWithoutDuplicates) {
    std::size_t total = 0;
    std::map<std::string, std::string> fileOf;
    for (const auto& [file, entries] : catalogueFiles(Language::It)) {
        total += entries.size();
        // A key in two files would be translated by whichever loads first: refuse it, named.
        for (const auto& [english, italian] : entries)
            if (const auto [at, fresh] = fileOf.emplace(english, file); !fresh)
                ADD_FAILURE() << "\"" << english << "\" is in both i18n/it/" << at->second
                              << " and i18n/it/" << file << ": keep it in one";
    }
    EXPECT_EQ(total, catalogue(Language::It).size());
}

}  // namespace
}  // namespace raystep
