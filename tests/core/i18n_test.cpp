// The translation mechanism's own rules (base/i18n.h); the catalogue's completeness against the
// sources is checked by the i18n catalogue test.
#include "raystep/base/i18n.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>
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
    for (const Language lang : languages()) {
        const std::string code(lang.code());
        std::size_t total = 0;
        std::map<std::string, std::string> fileOf;
        for (const auto& [file, entries] : catalogueFiles(lang)) {
            total += entries.size();
            // A key in two files would be translated by whichever loads first: refuse it, named.
            for (const auto& [english, text] : entries)
                if (const auto [at, fresh] = fileOf.emplace(english, file); !fresh)
                    ADD_FAILURE() << "\"" << english << "\" is in both i18n/" << code << "/"
                                  << at->second << " and i18n/" << code << "/" << file
                                  << ": keep it in one";
        }
        EXPECT_EQ(total, catalogue(lang).size()) << code;
    }
}

// The formats as the lessons and the slides write them (i18n/<code>/language.json).
TEST(I18n, EachLanguageWritesNumbersListsAndOrdinalsItsWay) {
    EXPECT_EQ(decimalMark(Language::En), ".");
    EXPECT_EQ(decimalMark(Language::It), ",");
    EXPECT_EQ(listSeparator(Language::En), ", ");
    EXPECT_EQ(listSeparator(Language::It), "; ");
    EXPECT_EQ(ordinal(Language::En, 1), "1st");
    EXPECT_EQ(ordinal(Language::En, 12), "12th");
    EXPECT_EQ(ordinal(Language::En, 22), "22nd");
    EXPECT_EQ(ordinal(Language::It, 3), "3");
    EXPECT_EQ(languageInfo(Language::It).name, "Italiano");
    EXPECT_EQ(languageInfo(Language::It).hitWords.front(), "colpita");
    EXPECT_EQ(languageInfo(Language::It).missWords.front(), "mancata");
    EXPECT_EQ(languageInfo(Language::En).missWords.front(), "miss");
    EXPECT_EQ(languageChoices(), "en or it");
    // A code no folder gave reads as English.
    EXPECT_EQ(decimalMark(Language("qq")), ".");
    EXPECT_EQ(tr(Language("qq"), "grid"), "grid");
}

/// A folder of one language, written for a test.
std::filesystem::path languageFolder(const std::string& name, const std::string& languageJson,
                                     const std::string& catalogueJson) {
    const auto root = std::filesystem::temp_directory_path() /
                      ("raystep-i18n-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(root / "zz");
    std::ofstream(root / "zz" / "language.json") << languageJson;
    std::ofstream(root / "zz" / "words.json") << catalogueJson;
    return root;
}

// In a child process (a death test forks): the language added stays out of the other tests.
TEST(I18nDeathTest, ALanguageFolderAddsALanguageWithItsFormats) {
    const auto root = languageFolder("add", R"({"name": "Zed", "decimal_mark": "'",
        "list_separator": " / ", "ordinal": "%1o"})",
                                     R"({"grid": "gr1d"})");
    EXPECT_EXIT(
        {
            addLanguages(root.string());
            const auto zz = parseLanguage("zz");
            const bool ok = zz && languages().back() == *zz && tr(*zz, "grid") == "gr1d" &&
                            formatNumber(2.5, *zz) == "2'5" && listSeparator(*zz) == " / " &&
                            ordinal(*zz, 2) == "2o" && languageChoices() == "en, it or zz" &&
                            languageInfo(*zz).name == "Zed";
            std::exit(ok ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
    std::filesystem::remove_all(root);
}

TEST(I18nDeathTest, ABadLanguageFileIsNamed) {
    const auto root = languageFolder("bad", R"({"decimal_point": ","})", "{}");
    EXPECT_EXIT(
        {
            try {
                addLanguages(root.string());
            } catch (const std::runtime_error& e) {
                std::fprintf(stderr, "%s\n", e.what());
                std::exit(3);
            }
            std::exit(0);
        },
        ::testing::ExitedWithCode(3), "zz/language.json: key 'decimal_point': unknown");
    std::filesystem::remove_all(root);
}

TEST(I18nDeathTest, ALanguageFileThatIsAFifoIsNeverOpened) {
    // Opening a FIFO for reading waits for a writer: the folder's zz must be passed over.
    const auto root = languageFolder("fifo", "{}", "{}");
    std::filesystem::remove(root / "zz" / "language.json");
    ASSERT_EQ(::mkfifo((root / "zz" / "language.json").c_str(), 0600), 0);
    EXPECT_EXIT(
        {
            ::alarm(20);  // a hang ends the child with SIGALRM, not the suite
            addLanguages(root.string());
            std::exit(parseLanguage("zz") ? 1 : 0);
        },
        ::testing::ExitedWithCode(0), "");
    std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace raystep
