// Presenter mode (presentation.h): the UI zoom, presenter mode and the high-contrast palette,
// applied to the application and kept in QSettings.
#include "presentation.h"

#include "course/palette.h"

#include <QApplication>
#include <QSettings>
#include <QWidget>

#include <algorithm>
#include <cmath>

namespace raystep::gui {

namespace {
constexpr auto kZoomKey = "presenter/zoom";
constexpr auto kModeKey = "presenter/mode";
constexpr auto kContrastKey = "presenter/highContrast";

/// `f` scaled by `factor`, in points when it has a point size, else in pixels.
QFont scaled(QFont f, double factor) {
    if (f.pointSizeF() > 0)
        f.setPointSizeF(f.pointSizeF() * factor);
    else if (f.pixelSize() > 0)
        f.setPixelSize(std::max(1, static_cast<int>(std::lround(f.pixelSize() * factor))));
    return f;
}
}  // namespace

Presentation::Presentation() : base_(QApplication::font()) {
    // At first use (the first view being made), before the window's other widgets are: each is
    // made in the remembered font (a dock's title takes its font once, when it is made).
    restore();
}

Presentation& Presentation::instance() {
    // Made after the QApplication (its font is the 100% one) and gone with the process.
    static Presentation* p = new Presentation;
    return *p;
}

QFont Presentation::labelFont() const {
    return scaled(QApplication::font(), labelScale());
}

void Presentation::zoomIn() {
    const auto next = std::upper_bound(kZoomSteps.begin(), kZoomSteps.end(), zoom_);
    if (next != kZoomSteps.end()) setZoomPercent(*next);
}

void Presentation::zoomOut() {
    const auto at = std::lower_bound(kZoomSteps.begin(), kZoomSteps.end(), zoom_);
    if (at != kZoomSteps.begin()) setZoomPercent(*std::prev(at));
}

void Presentation::resetZoom() {
    setZoomPercent(kDefaultZoom);
}

void Presentation::setZoomPercent(int percent) {
    zoom_ = std::clamp(percent, kZoomSteps.front(), kZoomSteps.back());
    save();
    apply();
}

void Presentation::setPresenterMode(bool on) {
    presenter_ = on;
    save();
    apply();
}

void Presentation::setHighContrast(bool on) {
    highContrast_ = on;
    save();
    apply();
}

void Presentation::restore() {
    const QSettings s;
    bool ok = false;
    const int zoom = s.value(kZoomKey, kDefaultZoom).toInt(&ok);
    // A value edited by hand into nonsense is the default, not a font of 0 or 10,000 points.
    zoom_ = ok ? std::clamp(zoom, kZoomSteps.front(), kZoomSteps.back()) : kDefaultZoom;
    presenter_ = s.value(kModeKey, false).toBool();
    highContrast_ = s.value(kContrastKey, false).toBool();
    apply();
}

void Presentation::apply() {
    setPaletteVariant(highContrast_ ? PaletteVariant::HighContrast : PaletteVariant::Standard);
    const QFont font = scaled(base_, zoom_ / 100.0);
    if (QApplication::font() != font) {
        QApplication::setFont(font);
        // A widget with a style sheet keeps the font it was polished with: given the new one.
        for (QWidget* w : QApplication::allWidgets())
            if (!w->styleSheet().isEmpty() && !w->styleSheet().contains(QLatin1String("font")))
                w->setFont(font);
    }
    emit changed();
}

void Presentation::save() const {
    QSettings s;
    s.setValue(kZoomKey, zoom_);
    s.setValue(kModeKey, presenter_);
    s.setValue(kContrastKey, highContrast_);
}

}  // namespace raystep::gui
