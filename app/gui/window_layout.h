#pragma once
// The window's layout: its size and docks remembered between runs (QSettings), sized for the
// screen it opens on (a student's 1366x768 laptop, a 1920x1080 projector), settled after the
// first show, and View > Reset layout.
#include <QObject>
#include <QSize>

#include <functional>

class QAction;
class QDockWidget;
class QMainWindow;
class QMenu;
class QSplitter;
class QWidget;

namespace raystep::gui {

class WindowLayout : public QObject {
    Q_OBJECT
  public:
    /// `splitters`: the lesson panel beside the views, the 2D view beside the 3D view and image,
    /// those two. `bottomDocks` are placed by `placeBottomDocks`; every other dock on the right.
    WindowLayout(QMainWindow& window, QList<QSplitter*> splitters, QWidget* lessonPanel,
                 QList<QDockWidget*> bottomDocks, std::function<void()> placeBottomDocks);

    /// The default widths for a window `windowWidth` wide: the lesson panel's and the docks'.
    static int defaultLessonWidth(int windowWidth);
    static int defaultDockWidth(int windowWidth);
    /// The board's and live controls' height under the views for a window `windowHeight` high
    /// at `zoomPercent`: above 100% they give the views what the larger chrome takes.
    static int defaultBottomDockHeight(int windowHeight, int zoomPercent);

    /// View > Reset layout.
    void addViewItems(QMenu* view);
    QAction* resetLayoutAction() const { return reset_; }
    /// `wanted`, made to fit the screen the window is on (a student's laptop is 1366x768).
    QSize fitToScreen(QSize wanted) const;
    /// At start: the size saved by the last run (Qt clamps it to this screen), else one that
    /// fits the screen.
    void sizeForScreen();
    /// The window's size, docks and splitters as the last run left them (QSettings).
    void restore();
    void save();
    /// The window was shown: once the event loop has laid it out, the docks' sizes follow.
    void shown();
    /// The docks back on the right, shown and docked, the docks and the splitters at their
    /// default sizes for the window's width.
    void reset();
    /// Whether a window geometry saved by an earlier run was restored.
    bool geometryRestored() const { return geometryRestored_; }
    /// True once the first show has put the layout in shape (restored or default sizes).
    bool settled() const { return settled_; }

  signals:
    /// The first show has put the layout in shape (settled()).
    void ready();

  private:
    /// After the first show: default sizes if nothing was saved, and docks saved narrower than
    /// is readable (a window once shrunk) widened to their default.
    void settle();

    QMainWindow& window_;
    QList<QSplitter*> splitters_;
    QList<QDockWidget*> bottomDocks_;
    std::function<void()> placeBottomDocks_;
    QAction* reset_ = nullptr;
    bool geometryRestored_ = false;
    bool stateRestored_ = false;
    bool settled_ = false;
};

}  // namespace raystep::gui
