#pragma once
// The window's presenter controls: View > zoom, full screen, presenter mode (thicker lines,
// larger labels) and high contrast, and Help > Keyboard shortcuts. The presentation itself
// (zoom, palette) is presentation.h's, shared by every window.
#include <QObject>
#include <QPointer>

class QAction;
class QMainWindow;
class QMenu;

namespace raystep::gui {

class ShortcutsDialog;

class PresenterControls : public QObject {
    Q_OBJECT
  public:
    explicit PresenterControls(QMainWindow& window);

    /// View > Zoom in, out, actual size, Full screen; Presenter mode, High contrast.
    void addViewItems(QMenu* view);
    /// Help > Keyboard shortcuts.
    void addHelpItems(QMenu* help);
    /// The keys another window of the app answers too: the zoom and the keyboard shortcuts.
    QList<QAction*> sharedKeys() const;

    /// Help > Keyboard shortcuts (F1, ?): opens the list of every key, made from the window's
    /// actions and shortcuts as they are now.
    void showShortcuts();
    /// The one open, or null.
    ShortcutsDialog* shortcutsDialog() const;

  private:
    /// The View menu's checks follow the presentation (changed elsewhere: another window).
    void syncActions();

    QMainWindow& window_;
    QAction *zoomIn_ = nullptr, *zoomOut_ = nullptr, *resetZoom_ = nullptr, *fullScreen_ = nullptr,
            *presenterMode_ = nullptr, *highContrast_ = nullptr, *shortcutsAction_ = nullptr;
    QPointer<ShortcutsDialog> shortcuts_;
};

}  // namespace raystep::gui
