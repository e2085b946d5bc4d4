#pragma once
// The interface's language: one translator that answers every Qt tr() of the app from raystep's
// catalogue (base/i18n.h, the same the core and the course read), the language the app asks the
// core's texts in, and the numbers and names it puts into its sentences.
#include "raystep/accel/accel.h"
#include "raystep/base/i18n.h"

#include <QString>
#include <QTranslator>

#include <string>

namespace raystep::gui {

/// Qt's tr() through raystep's catalogue: the English text is the key and Qt's context is not
/// used (docs/architecture.md, "Languages": one catalogue, one entry per English text).
class CatalogueTranslator : public QTranslator {
  public:
    explicit CatalogueTranslator(Language lang, QObject* parent = nullptr);
    QString translate(const char* context, const char* sourceText,
                      const char* disambiguation = nullptr, int n = -1) const override;
    bool isEmpty() const override;

  private:
    Language lang_;
};

/// Installs the translators of `lang` on the application: raystep's catalogue, and Qt's own
/// qtbase catalogue for its dialogs' buttons where the system has it; English installs none.
/// Call it before the windows are made: widgets take their texts when they are built.
void setInterfaceLanguage(Language lang);
/// What setInterfaceLanguage set (English until then).
Language interfaceLanguage();

/// A number as the interface writes it: QString::number's format, the language's decimal mark.
QString numberText(double v, char format = 'g', int precision = 6);
/// A built-in scene's description in the interface's language (the catalogue's scenes.json; a
/// user's scene file keeps its own words).
std::string sceneDescription(const std::string& english);
/// A structure's name to put in a sentence ("grid", "kd-tree"), in the interface's language.
QString structureName(AccelKind kind);
/// A split method's name ("midpoint", "median", "SAH"), in the interface's language.
QString splitName(SplitMethod split);

}  // namespace raystep::gui
