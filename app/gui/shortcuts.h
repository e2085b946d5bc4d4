#pragma once
// Help > Keyboard shortcuts (F1 and ?): every key the window understands, read from its QActions
// and QShortcuts when the dialog opens (a key added later is never missing), and the mouse
// gestures and view keys that are neither, from the one table below; in the interface's language.
#include <QDialog>
#include <QList>
#include <QString>

#include <array>
#include <span>

class QTableWidget;
class QWidget;

namespace raystep::gui {

/// A mouse gesture or a key a view handles itself, in English (shown through tr()).
struct Gesture {
    const char* where;          // the view or panel: "2D view"
    const char* input;          // "Click a cell", "Wheel"; null for a key (then `keys` names it)
    const char* what;           // what it does
    std::array<int, 2> keys{};  // the keys (Qt::Key | modifiers) a panel's QShortcuts take
};

/// THE table of mouse gestures and view keys (each view's, in one place: add a new view's here).
std::span<const Gesture> mouseAndViewKeys();

/// One row of the dialog: the keys or gesture, what it does, and where (the menu or the view).
struct ShortcutRow {
    QString keys, what, where;
};

/// Every QAction with a shortcut among `window`'s children (in menu order, then the rest), then
/// every QShortcut whose key the gesture table does not describe already.
QList<ShortcutRow> keyRows(const QWidget& window);
/// mouseAndViewKeys(), translated.
QList<ShortcutRow> gestureRows();

class ShortcutsDialog : public QDialog {
    Q_OBJECT
  public:
    explicit ShortcutsDialog(const QWidget& window, QWidget* parent = nullptr);
    QTableWidget* keysTable() const { return keys_; }
    QTableWidget* gesturesTable() const { return gestures_; }

  private:
    QTableWidget* keys_ = nullptr;
    QTableWidget* gestures_ = nullptr;
};

}  // namespace raystep::gui
