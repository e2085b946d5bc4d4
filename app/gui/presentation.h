#pragma once
// Presenter mode (issue 19): how the app is shown on a projector. One per application, as the
// application's font is: the UI zoom (the whole app's font, and so the views' labels and lines;
// menus, tool bars and buttons up to kChromeZoomCap), presenter
// mode (thicker lines and larger labels in the 2D and 3D views) and the high-contrast palette
// (course/palette.h). Each is remembered in QSettings ("presenter/...") and restored at start.
#include <QFont>
#include <QObject>

#include <algorithm>
#include <array>

class QTextDocument;

namespace raystep::gui {

class Presentation : public QObject {
    Q_OBJECT
  public:
    /// The zoom steps Ctrl++ and Ctrl+- go through, in percent of the system's font.
    static constexpr std::array<int, 11> kZoomSteps{70,  80,  90,  100, 110, 125,
                                                    150, 175, 200, 250, 300};
    static constexpr int kDefaultZoom = 100;
    /// The zoom of the chrome (menus, tool bars, buttons, fields) stops here: past it only the
    /// content grows (the lesson's text and code, the views, the tables), which the room reads.
    static constexpr int kChromeZoomCap = 150;
    /// Presenter mode's factors for the views' line widths and label fonts.
    static constexpr double kPresenterLineScale = 2.0, kPresenterLabelScale = 1.4;

    /// The application's one presentation (made on first use, after the QApplication).
    static Presentation& instance();

    int zoomPercent() const { return zoom_; }
    bool presenterMode() const { return presenter_; }
    bool highContrast() const { return highContrast_; }
    /// What the views multiply their pen widths and marks by: the zoom (above 100%: a zoom for
    /// the back rows enlarges the picture's lines as its labels) and presenter mode's thicker
    /// lines.
    double lineScale() const {
        return (presenter_ ? kPresenterLineScale : 1.0) * std::max(zoom_, kDefaultZoom) / 100.0;
    }
    /// What the views multiply their handles by (a drag's rings, a selection's squares): as the
    /// lines, but with the zoom capped as the chrome's (a handle large enough to grab, not one
    /// that hides the ray's origin).
    double handleScale() const {
        return (presenter_ ? kPresenterLineScale : 1.0) *
               std::clamp(zoom_, kDefaultZoom, kChromeZoomCap) / 100.0;
    }
    /// What the views multiply their label fonts by, over the zoomed application font: larger in
    /// presenter mode, up to the largest zoom's size (past it labels only crowd the picture).
    double labelScale() const {
        const double most = std::max(1.0, double(kZoomSteps.back()) / zoom_);
        return presenter_ ? std::min(kPresenterLabelScale, most) : 1.0;
    }
    /// The application's font at 100% (the system's, as it was before any zoom).
    QFont baseFont() const { return base_; }
    /// The font a view draws its labels in: the zoomed application font times labelScale().
    QFont labelFont() const;
    /// The font of a view's caption and legend, its chrome: labelFont() with the zoom capped.
    QFont captionFont() const;

  public slots:
    /// The next zoom step up or down (at the ends: stays), and back to 100%.
    void zoomIn();
    void zoomOut();
    void resetZoom();
    /// Sets the zoom (clamped to the steps' range) and applies it to the application's font.
    void setZoomPercent(int percent);
    void setPresenterMode(bool on);
    void setHighContrast(bool on);
    /// Reads the three settings from QSettings (defaults where none) and applies them.
    void restore();

  signals:
    /// Any of the three changed (after the application font and the palette are set).
    void changed();

  private:
    Presentation();
    void apply();
    void save() const;

    QFont base_;
    int zoom_ = kDefaultZoom;
    bool presenter_ = false;
    bool highContrast_ = false;
};

/// Makes the code of a document made from Markdown (code spans, code blocks) follow the
/// document's font size: Qt's Markdown reader gives code the system's fixed font at its own
/// point size, which no zoom would change. Call it after each setMarkdown.
void codeFollowsTextSize(QTextDocument& document);

/// Markdown as rich text for a label (an exercise's prompt, its hints) with no font size of its
/// own, code included: the label's font, which the zoom sets, sizes all of it. (A label given
/// Markdown keeps its code at the fixed font's size: tiny beside the text at 150%.)
QString markdownForLabel(const QString& markdown);

/// Presentation::instance().
inline Presentation& presentation() {
    return Presentation::instance();
}

}  // namespace raystep::gui
