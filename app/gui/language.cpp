// The interface's language (language.h): Qt's translation machinery, fed by raystep's catalogue.
#include "language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>

#include <memory>

namespace raystep::gui {

namespace {
Language gLanguage = Language::En;
// Installed for the life of the application (Qt keeps only a pointer).
std::unique_ptr<CatalogueTranslator> gCatalogue;
std::unique_ptr<QTranslator> gQtBase;
}  // namespace

CatalogueTranslator::CatalogueTranslator(Language lang, QObject* parent)
    : QTranslator(parent), lang_(lang) {}

QString CatalogueTranslator::translate(const char*, const char* sourceText, const char*,
                                       int) const {
    if (!sourceText) return {};
    const auto& table = catalogue(lang_);
    const auto it = table.find(std::string_view(sourceText));
    // A null string tells Qt "not mine": it then shows the English text.
    return it == table.end() ? QString() : QString::fromStdString(it->second);
}

bool CatalogueTranslator::isEmpty() const {
    return catalogue(lang_).empty();
}

void setInterfaceLanguage(Language lang) {
    if (gCatalogue) QCoreApplication::removeTranslator(gCatalogue.get());
    if (gQtBase) QCoreApplication::removeTranslator(gQtBase.get());
    gCatalogue.reset();
    gQtBase.reset();
    gLanguage = lang;
    // Qt's widgets (spin boxes, dialogs) write numbers the language's way too (its "locale",
    // language.json); English, or a language without one, keeps the system's locale.
    const std::string& localeName = languageInfo(lang).locale;
    const QLocale locale =
        localeName.empty() ? QLocale::system() : QLocale(QString::fromStdString(localeName));
    QLocale::setDefault(locale);
    if (lang == Language::En) return;
    gCatalogue = std::make_unique<CatalogueTranslator>(lang);
    QCoreApplication::installTranslator(gCatalogue.get());
    // Qt's own dialogs (file dialogs, message boxes' buttons): Debian's qt6-translations-l10n.
    gQtBase = std::make_unique<QTranslator>();
    if (!localeName.empty() &&
        gQtBase->load(QLocale(locale.language()), QStringLiteral("qtbase"), QStringLiteral("_"),
                      QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(gQtBase.get());
    else
        gQtBase.reset();
}

Language interfaceLanguage() {
    return gLanguage;
}

QString numberText(double v, char format, int precision) {
    QString text = QString::number(v, format, precision);
    const std::string_view mark = decimalMark(gLanguage);
    if (mark != ".")
        text.replace(QLatin1Char('.'),
                     QString::fromUtf8(mark.data(), static_cast<qsizetype>(mark.size())));
    return text;
}

std::string sceneDescription(const std::string& english) {
    // i18n: the built-in scenes' descriptions (scenes/*.json), checked by the catalogue test.
    return tr(gLanguage, english);
}

QString structureName(AccelKind kind) {
    // The table's label, translated by the core from the same catalogue Qt's tr() reads.
    return QString::fromStdString(structureLabel(kind, gLanguage));
}

QString splitName(SplitMethod split) {
    switch (split) {
        case SplitMethod::Midpoint:
            return QString::fromStdString(tr(gLanguage, "midpoint"));
        case SplitMethod::Median:
            return QString::fromStdString(tr(gLanguage, "median"));
        case SplitMethod::Sah:
            break;
    }
    return QString::fromStdString(tr(gLanguage, "SAH"));
}

}  // namespace raystep::gui
