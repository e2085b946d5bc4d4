// Help > Keyboard shortcuts (shortcuts.h): the window's keys as they are, and the one table of
// mouse gestures and view keys.
#include "shortcuts.h"

#include <QAction>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QScreen>
#include <QSet>
#include <QShortcut>
#include <QTableWidget>
#include <QVBoxLayout>

#include <array>

namespace raystep::gui {

namespace {
// The gesture table's texts are translated where they are shown (translated, gestureRows).
constexpr std::array kGestures{
    Gesture{QT_TRANSLATE_NOOP("raystep", "Lesson panel"),
            nullptr,
            QT_TRANSLATE_NOOP("raystep", "Previous / next step of the lesson"),
            {Qt::Key_PageUp, Qt::Key_PageDown}},
    Gesture{QT_TRANSLATE_NOOP("raystep", "Lesson panel"),
            nullptr,
            QT_TRANSLATE_NOOP("raystep", "Check the answer typed in the exercise box"),
            {Qt::Key_Return}},
    Gesture{QT_TRANSLATE_NOOP("raystep", "2D view"), QT_TRANSLATE_NOOP("raystep", "Click a cell"),
            QT_TRANSLATE_NOOP("raystep", "Answer a \"next cell\" or \"order the cells\" exercise")},
    Gesture{
        QT_TRANSLATE_NOOP("raystep", "2D view"),
        QT_TRANSLATE_NOOP("raystep", "Drag the ray's origin ring"),
        QT_TRANSLATE_NOOP(
            "raystep", "Move the ray's origin (its direction kept); the walk is recorded again")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "2D view"),
            QT_TRANSLATE_NOOP("raystep", "Drag the ring at the arrow's tip"),
            QT_TRANSLATE_NOOP("raystep",
                              "Turn and stretch the ray's direction d (the tip is at o + d)")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "2D view"), QT_TRANSLATE_NOOP("raystep", "Shift + drag"),
            QT_TRANSLATE_NOOP("raystep",
                              "Draw a new ray: from where the drag starts, towards where it ends")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "2D view"),
            QT_TRANSLATE_NOOP("raystep", "Drag inside a circle, or a segment"),
            QT_TRANSLATE_NOOP("raystep", "Move it; the structure is built again")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "2D view"),
            QT_TRANSLATE_NOOP("raystep", "Drag a circle's rim, or a segment's end"),
            QT_TRANSLATE_NOOP("raystep", "Resize the circle, move the end")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "2D view"), QT_TRANSLATE_NOOP("raystep", "Ctrl + click"),
            QT_TRANSLATE_NOOP("raystep", "Select a circle or a segment (Delete removes it)")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "2D view"), QT_TRANSLATE_NOOP("raystep", "Wheel"),
            QT_TRANSLATE_NOOP("raystep", "Zoom about the mouse")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "2D view"),
            QT_TRANSLATE_NOOP("raystep", "Drag empty space, or middle drag"),
            QT_TRANSLATE_NOOP("raystep", "Pan")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "3D view"), QT_TRANSLATE_NOOP("raystep", "Left drag"),
            QT_TRANSLATE_NOOP("raystep", "Turn the camera about the scene")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "3D view"),
            QT_TRANSLATE_NOOP("raystep", "Middle drag, or Shift + left drag"),
            QT_TRANSLATE_NOOP("raystep", "Move the camera sideways")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "3D view"),
            QT_TRANSLATE_NOOP("raystep", "Wheel, or right drag"),
            QT_TRANSLATE_NOOP("raystep", "Move the camera closer or further")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "3D view"),
            QT_TRANSLATE_NOOP("raystep", "Ctrl + left drag"),
            QT_TRANSLATE_NOOP("raystep", "Roll the camera")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "3D view"),
            QT_TRANSLATE_NOOP("raystep", "Click (without dragging)"),
            QT_TRANSLATE_NOOP("raystep", "Record the ray under the mouse, seen by this camera")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "Image"), QT_TRANSLATE_NOOP("raystep", "Click a pixel"),
            QT_TRANSLATE_NOOP("raystep", "Record the pixel's ray tree and replay it")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "Image"), QT_TRANSLATE_NOOP("raystep", "Wheel"),
            QT_TRANSLATE_NOOP("raystep", "Zoom the image")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "Timeline"),
            QT_TRANSLATE_NOOP("raystep", "Drag the slider"),
            QT_TRANSLATE_NOOP("raystep", "Move the replay to any step")},
    Gesture{QT_TRANSLATE_NOOP("raystep", "Events"), QT_TRANSLATE_NOOP("raystep", "Click an event"),
            QT_TRANSLATE_NOOP("raystep", "Move the replay to that event")},
};

QString translated(const char* english) {
    // i18n: the texts of kGestures above, each marked with QT_TRANSLATE_NOOP.
    return QCoreApplication::translate("raystep", english);
}

/// A menu's or an action's text as read: the mnemonic's & gone ("&&" is a literal &).
QString plain(QString text) {
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QStringLiteral("\x01"), QStringLiteral("&"));
    return text;
}

/// A gesture's keys as a list (the zeros dropped).
QList<QKeySequence> keysOf(const Gesture& g) {
    QList<QKeySequence> keys;
    for (const int k : g.keys)
        if (k) keys << QKeySequence(k);
    return keys;
}

QString keysText(const QList<QKeySequence>& keys) {
    QStringList out;
    for (const QKeySequence& k : keys) {
        if (k.isEmpty()) continue;
        QString text = k.toString(QKeySequence::NativeText);
        // Qt's Italian writes Home as an arrow (a Mac keyboard's): the key's word reads better.
        text.replace(QChar(0x2196), translated(QT_TRANSLATE_NOOP("raystep", "Home")));
        out << text;
    }
    return out.join(QStringLiteral(", "));
}

/// Where an action or shortcut outside the menus works: its dock's title, else the window.
QString placeOf(const QObject* o) {
    for (const QObject* p = o; p; p = p->parent())
        if (const auto* dock = qobject_cast<const QDockWidget*>(p)) return dock->windowTitle();
    return QCoreApplication::translate("raystep", "Window");
}

void addMenu(const QMenu* menu, const QString& path, QList<ShortcutRow>& rows,
             QSet<const QAction*>& seen) {
    for (const QAction* a : menu->actions()) {
        if (a->menu()) {
            addMenu(a->menu(), path + QStringLiteral(" > ") + plain(a->menu()->title()), rows,
                    seen);
            continue;
        }
        if (a->isSeparator() || a->shortcuts().isEmpty() || seen.contains(a)) continue;
        seen.insert(a);
        rows.push_back({keysText(a->shortcuts()), plain(a->text()), path});
    }
}

QTableWidget* table(const QList<ShortcutRow>& rows, const QString& first) {
    auto* t = new QTableWidget(rows.size(), 3);
    t->setHorizontalHeaderLabels({first, QCoreApplication::translate("raystep", "What it does"),
                                  QCoreApplication::translate("raystep", "Where")});
    t->verticalHeader()->hide();
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionBehavior(QAbstractItemView::SelectRows);
    t->setWordWrap(true);
    for (int r = 0; r < rows.size(); ++r) {
        t->setItem(r, 0, new QTableWidgetItem(rows[r].keys));
        t->setItem(r, 1, new QTableWidgetItem(rows[r].what));
        t->setItem(r, 2, new QTableWidgetItem(rows[r].where));
    }
    t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    t->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    t->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    t->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    return t;
}
}  // namespace

std::span<const Gesture> mouseAndViewKeys() {
    return kGestures;
}

QList<ShortcutRow> keyRows(const QWidget& window) {
    QList<ShortcutRow> rows;
    QSet<const QAction*> seen;
    // The menus first, in their order, each action under its menu's path.
    if (const auto* bar = window.findChild<QMenuBar*>())
        for (const QAction* m : bar->actions())
            if (m->menu()) addMenu(m->menu(), plain(m->menu()->title()), rows, seen);
    // Then every other action with a key (a dock's, a tool bar's): none is left out.
    for (const QAction* a : window.findChildren<QAction*>()) {
        if (a->shortcuts().isEmpty() || seen.contains(a)) continue;
        seen.insert(a);
        const QString what = a->text().isEmpty() ? a->toolTip() : plain(a->text());
        rows.push_back({keysText(a->shortcuts()), what, placeOf(a)});
    }
    // QShortcuts, unless the gesture table says what their key does.
    QSet<QString> described;
    for (const Gesture& g : kGestures)
        for (const QKeySequence& k : keysOf(g)) described.insert(keysText({k}));
    for (const QShortcut* s : window.findChildren<QShortcut*>()) {
        const QString keys = keysText(s->keys());
        if (keys.isEmpty() || described.contains(keys)) continue;
        rows.push_back({keys, s->whatsThis(), placeOf(s)});
    }
    return rows;
}

QList<ShortcutRow> gestureRows() {
    QList<ShortcutRow> rows;
    for (const Gesture& g : kGestures)
        rows.push_back({g.input ? translated(g.input) : keysText(keysOf(g)), translated(g.what),
                        translated(g.where)});
    return rows;
}

ShortcutsDialog::ShortcutsDialog(const QWidget& window, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Keyboard shortcuts"));
    setObjectName("shortcutsDialog");
    auto* layout = new QVBoxLayout(this);
    auto* keysTitle = new QLabel(QStringLiteral("<b>%1</b>").arg(tr("Keys")));
    keys_ = table(keyRows(window), tr("Key"));
    keys_->setObjectName("shortcutKeys");
    auto* gesturesTitle = new QLabel(QStringLiteral("<b>%1</b>").arg(tr("Mouse and view keys")));
    gestures_ = table(gestureRows(), tr("Mouse or key"));
    gestures_->setObjectName("shortcutGestures");
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(keysTitle);
    layout->addWidget(keys_, 3);
    layout->addWidget(gesturesTitle);
    layout->addWidget(gestures_, 2);
    layout->addWidget(buttons);
    // As large as the rows need, within the screen (a laptop's 1366x768 included).
    const QFontMetrics fm(font());
    QSize want(fm.horizontalAdvance(QLatin1Char('x')) * 110,
               (keys_->rowCount() + gestures_->rowCount() + 8) * (fm.height() + 8));
    if (const QScreen* s = window.screen())
        want = want.boundedTo(s->availableGeometry().size() * 0.9);
    resize(want);
}

}  // namespace raystep::gui
