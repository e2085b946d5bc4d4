// Presenter mode (presentation.h): the UI zoom, presenter mode and the high-contrast palette,
// applied to the application and kept in QSettings.
#include "presentation.h"

#include "course/palette.h"

#include <QApplication>
#include <QDockWidget>
#include <QRegularExpression>
#include <QSettings>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QWidget>

#include <algorithm>
#include <cmath>

namespace raystep::gui {

namespace {
constexpr auto kZoomKey = "presenter/zoom";
constexpr auto kModeKey = "presenter/mode";
constexpr auto kContrastKey = "presenter/highContrast";
// The chrome: menus, tool bars, buttons, fields and the status bar (what a lecturer uses, not what
// the room reads). A child of one (a tool bar's combo box) follows it.
// The replay's timeline under the views is made of buttons and their labels: chrome too.
constexpr const char* kChromeClasses[] = {
    "QMenuBar",    "QMenu",        "QToolBar",  "QStatusBar",
    "QToolButton", "QPushButton",  "QComboBox", "QAbstractSpinBox",
    "QCheckBox",   "QRadioButton", "QTabBar",   "raystep::gui::Timeline"};

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

QFont Presentation::captionFont() const {
    return scaled(QApplication::font("QMenuBar"), labelScale());
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
    const QFont chrome = scaled(base_, std::min(zoom_, kChromeZoomCap) / 100.0);
    if (QApplication::font() != font || QApplication::font("QMenuBar") != chrome) {
        // The content (texts, tables, the views' labels) at the zoom; the chrome at most at the
        // cap. Setting the application's font forgets the classes' fonts: they follow it.
        QApplication::setFont(font);
        for (const char* chromeClass : kChromeClasses) QApplication::setFont(chrome, chromeClass);
        // A widget with a style sheet keeps the font it was polished with: given its class's.
        for (QWidget* w : QApplication::allWidgets())
            if (!w->styleSheet().isEmpty() && !w->styleSheet().contains(QLatin1String("font")))
                w->setFont(QApplication::font(w));
    }
    // A dock's title is chrome, what it holds is not: its own font by a style sheet, which its
    // children do not inherit (a font set on it would be theirs too).
    const QString title = QStringLiteral("QDockWidget { font-size: %1pt; }")
                              .arg(chrome.pointSizeF() > 0 ? chrome.pointSizeF() : 9.0);
    for (QWidget* w : QApplication::allWidgets())
        if (auto* dock = qobject_cast<QDockWidget*>(w); dock && dock->styleSheet() != title)
            dock->setStyleSheet(title);
    emit changed();
}

QString markdownForLabel(const QString& markdown) {
    QTextDocument document;
    document.setMarkdown(markdown);
    codeFollowsTextSize(document);
    QString html = document.toHtml();
    // The body's style names the document's default font and size: the label's are meant.
    static const QRegularExpression bodyStyle(QStringLiteral("<body style=\"[^\"]*\""));
    html.replace(bodyStyle, QStringLiteral("<body"));
    return html;
}

void codeFollowsTextSize(QTextDocument& document) {
    // Code (a span is fixed-pitch, a block only names the fixed font's family) carries the size
    // the text had when it was read: removed, so it is the document's (the widget's, which the
    // zoom sets) now and after the next zoom, as the text around it.
    QTextCursor c(&document);
    c.beginEditBlock();
    for (QTextBlock b = document.begin(); b.isValid(); b = b.next())
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const QTextFragment f = it.fragment();
            const QTextCharFormat format = f.charFormat();
            const bool code =
                format.fontFixedPitch() || format.hasProperty(QTextFormat::FontFamilies);
            if (!f.isValid() || !code ||
                !(format.hasProperty(QTextFormat::FontPointSize) ||
                  format.hasProperty(QTextFormat::FontPixelSize)))
                continue;
            QTextCharFormat sized = format;
            sized.clearProperty(QTextFormat::FontPointSize);
            sized.clearProperty(QTextFormat::FontPixelSize);
            c.setPosition(f.position());
            c.setPosition(f.position() + f.length(), QTextCursor::KeepAnchor);
            c.setCharFormat(sized);
        }
    c.endEditBlock();
}

void Presentation::save() const {
    QSettings s;
    s.setValue(kZoomKey, zoom_);
    s.setValue(kModeKey, presenter_);
    s.setValue(kContrastKey, highContrast_);
}

}  // namespace raystep::gui
