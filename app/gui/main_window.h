#pragma once
// The replay app's window: lesson panel, 2D view, 3D view and image side by side, the timeline
// under them, the inspector and the event list on the right. It lays them out, wires them, holds
// the menus, and opens scenes and lessons in the background; each part has a file of its own.
#include "session.h"
#include "task_runner.h"

#include "course/lesson.h"
#include "course/progress.h"

#include "raystep/render/tracer.h"
#include "raystep/scene/camera.h"

#include <functional>
#include <optional>

#include <QImage>
#include <QMainWindow>
#include <QPointer>

class QAction;
class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QSplitter;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QToolBar;

namespace raystep::gui {

/// Saves `image` as a PNG at `path` through the core's writer: regular files only (a FIFO or a
/// device is refused, not opened and waited on), a temporary renamed into place (a failed write
/// leaves the old file whole). The one-line problem, or an empty string.
QString savePng(const QImage& image, const QString& path);

class BoardTable;
class CompareChooser;
class CompareWindow;
class LiveControls;
struct FrameBox;
class EventList;
class ImageView;
class Inspector;
class LessonController;
class LessonPanel;
enum class LessonMode;  // lesson_panel.h
class ShortcutsDialog;
class Live2D;
class Timeline;
class View2D;
class VtkView;

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Session& session() { return session_; }
    /// Every thread the window starts (tests look at it).
    TaskRunner& tasks() { return runner_; }

    /// Starts opening a scene (built-in name or file) with a structure, in the background. The
    /// window shows the current scene until the new one is ready, and keeps it if the new one
    /// cannot be opened (a dialog says why unless quiet). `opened` tells how it ended.
    void openScene(const QString& nameOrPath, AccelKind kind, bool quiet = false,
                   const AccelOptions& options = {}, bool renderImage = true);
    /// The structure chooser: builds the open scene's structure again as `kind` with `split`
    /// (kd-tree and BVH), in the background; in a lesson that is exploring (Esc goes back).
    /// File > Open uses the last choice; before any, a kd-tree with SAH splits.
    void changeStructure(AccelKind kind, SplitMethod split);
    /// The live controls: the open scene's structure built again as `kind` with `options`. A 2D
    /// scene is rebuilt at once and shown with showLive (its walk or build recorded again at the
    /// same step); a 3D one in the background, as changeStructure. Ends with structureChanged.
    void applyStructure(AccelKind kind, const AccelOptions& options);
    /// The board dock's table and the live controls (main_window_board.cpp).
    BoardTable* boardTable() const { return board_; }
    LiveControls* liveControls() const { return liveControls_; }
    /// Help > Keyboard shortcuts (F1, ?): opens the list of every key, made from the window's
    /// actions and shortcuts as they are now; the one open, or null (main_window_presenter.cpp).
    void showShortcuts();
    ShortcutsDialog* shortcutsDialog() const;
    /// Live lecture mode: shows `scene` (the open one edited or rebuilt) at once, recording again
    /// what was replayed at the same step (Session::relive); what ran for the old scene stops.
    void showLive(SceneRef scene);
    /// The 2D view's live editing: its scene edits and their undo stack (main_window_live.cpp).
    Live2D* live2D() const { return live2d_; }
    /// The structure and options File > Open builds (changeStructure's last choice).
    AccelKind openKind() const;
    AccelOptions openOptions() const;
    QComboBox* structureChooser() const { return structureBox_; }
    QComboBox* splitChooser() const { return splitBox_; }
    /// The status bar's "Structure: ..." (what the open scene uses).
    QString structureStatus() const;
    /// Starts opening a lesson (built-in id or number, or a file): its scene, structure and
    /// trace, its views, and the step the user's progress was at; likewise in the background.
    void openLesson(const QString& idOrPath, bool quiet = false);
    /// How the last open ended: nullopt while it runs (or before any), else true or false.
    std::optional<bool> lastOpenOk() const { return lastOpenOk_; }
    QString lastOpenError() const { return lastOpenError_; }

    /// File > Save scene as: the scene made around an opened model, written as a scene file at
    /// `path` (*.json) and its mesh as <name>.mesh.obj beside it, both or neither. The one-line
    /// problem, or an empty string.
    QString saveModelScene(const QString& path);
    /// B: records the structure's construction in the background, then replays it.
    void replayBuild();
    /// Renders the image of the 3D scene in the background (what the image view shows).
    void renderImage();
    /// Opens compare mode on `choices` (each a structure, and a split for a tree) once they are
    /// built: the same ray through each, side by side.
    void openCompare(const std::vector<StructureChoice>& choices);
    /// The same on the comparison made for the structure shown (defaultComparison).
    void openCompare();
    /// View > Compare structures... (Shift+C): asks which (CompareChooser), then opens them.
    void chooseCompare();
    /// The chooser chooseCompare opened, while it is open.
    CompareChooser* compareChooser() const;
    /// The compare window last opened, while it is open.
    CompareWindow* compareWindow() const;

    /// Runs `f` on the GUI thread once no background work is left (at once if none is).
    void whenIdle(std::function<void()> f);
    /// Tests and scripts: processes events until no background work is left; false on timeout.
    bool waitUntilIdle(int timeoutMs = 300000);

    LessonPanel* lessonPanel() const { return lesson_; }
    void setLanguage(Language lang);
    /// Lessons > Quiz / Presenting / Lecturer mode. The menu's pick of quiz or presenting mode
    /// is remembered for the next run; lecturer mode (every answer shown) never is.
    void setLessonMode(LessonMode mode);
    LessonMode lessonMode() const;
    /// Lecturer mode on, or back to quiz mode.
    void setLecturerMode(bool on);
    const Progress& studentProgress() const;
    QString progressPath() const;
    /// The inspector's text (what tests read).
    QString inspectorText() const;
    EventList* eventList() const { return events_; }
    Timeline* timeline() const { return timeline_; }
    /// Lessons > Back to the lesson (Esc) and Show notes on the slides.
    QAction* backToLessonAction() const { return actions_.backToLesson; }
    /// Lessons > Quiz, Presenting and Lecturer mode (one of them checked).
    QAction* modeAction(LessonMode mode) const;
    QAction* showErrataAction() const { return actions_.showErrata; }
    View2D* view2D() const { return view2D_; }
    VtkView* view3D() const { return view3D_; }
    ImageView* imageView() const { return imageView_; }
    /// What the image is (being) made with: the camera, size and settings its pixels are traced
    /// with when clicked.
    struct ImageFrame {
        Camera camera;
        int width = 0, height = 0;
        TraceSettings trace;
        int spp = 1;
        bool ofView = false;  // the 3D view's camera (ray trace this view), else the scene's
    };
    const std::optional<ImageFrame>& imageFrame() const { return imageFrame_; }
    /// View > Ray trace this view (checkable).
    QAction* rayTraceViewAction() const { return rayTraceView_; }
    /// `wanted`, made to fit the screen the window is on (a student's laptop is 1366x768).
    QSize fitToScreen(QSize wanted) const;
    /// Whether a window geometry saved by an earlier run was restored.
    bool geometryRestored() const { return geometryRestored_; }
    /// At start: the size saved by the last run (Qt clamps it to this screen), else one that
    /// fits the screen.
    void sizeForScreen();
    /// View > Reset layout: the docks back on the right, shown and docked, the docks and the
    /// splitters at their default sizes for the window's width.
    void resetLayout();
    QAction* resetLayoutAction() const { return resetLayout_; }
    /// The default widths for a window `windowWidth` wide: the lesson panel's and the docks'.
    static int defaultLessonWidth(int windowWidth);
    static int defaultDockWidth(int windowWidth);
    /// The board's and live controls' height under the views for a window `windowHeight` high
    /// at `zoomPercent`: above 100% they give the views what the larger chrome takes.
    static int defaultBottomDockHeight(int windowHeight, int zoomPercent);
    /// True once the first show has put the layout in shape (restored or default sizes).
    bool layoutSettled() const { return layoutSettled_; }

  signals:
    /// The first show has put the layout in shape (layoutSettled()).
    void layoutReady();
    /// An openScene or openLesson ended: opened, or not (with why; "cancelled" included).
    void opened(bool ok, const QString& error);
    /// A changeStructure ended: the scene shown with the new structure, or not (with why).
    void structureChanged(bool ok, const QString& error);

  public slots:
    // The timeline's (timeline.h), for the tests and scripts that drive the window.
    void stepForward();
    void stepBack();
    void jumpToNextOfKind();
    void togglePlay();

  protected:
    void closeEvent(QCloseEvent*) override;
    void showEvent(QShowEvent*) override;

  private:
    // The window's parts, made in this order by the constructor.
    void createViews();
    void createTimeline();
    void createDocks();
    void createStatusBar();
    void createActions();
    void createMenus();
    // Live lecture mode, each part in its own file, made after the menus (issue 19):
    /// The 2D view's editing: ray handles, scene editing, undo/redo (main_window_live.cpp).
    void createLiveLab();
    /// The live controls and the board table docks (main_window_board.cpp).
    void createBoard();
    /// Presenter mode and Help > Keyboard shortcuts (main_window_presenter.cpp).
    void createPresenter();
    /// A 2D structure built by `build` on this thread and shown live; the status bar and
    /// structureChanged say how it ended (a failed build leaves the scene and the controls).
    void showLiveBuild(const std::function<SceneRef()>& build);
    /// The structure chooser (a tool bar) and the status bar's structure (main_window_models.cpp).
    void createStructureControls();
    /// Brute force on a scene so big that a pixel's trace takes more than a moment (every ray
    /// tests every primitive): the pixel is traced in the background, its log capped.
    bool slowPixelTraces() const;
    /// Records pixel (x, y) of a w x h image (the scene's camera and settings unless given: a
    /// click, replayed to its end) and replays it: here and now, or in the background when
    /// slowPixelTraces().
    void tracePixelHereOrInBackground(int x, int y, int w, int h,
                                      const std::optional<Camera>& camera = std::nullopt,
                                      const TraceSettings& settings = {});
    /// The chooser's pick, once asked about where it needs asking (brute force on a big scene).
    void buildChosenStructure(AccelKind kind, SplitMethod split);
    /// The chooser and the status bar say what the session's scene uses.
    void syncStructureControls();
    /// View > Reset layout, and the docks' smallest width (layout: window sizing and memory).
    void addLayoutActions(QMenu* view);
    /// The window's size, docks and splitters as the last run left them (QSettings).
    void restoreLayout();
    void saveLayout();
    /// After the first show: default sizes if nothing was saved, and docks saved narrower than
    /// is readable (a window once shrunk) widened to their default.
    void settleLayout();
    QList<QSplitter*> layoutSplitters() const;
    void openFileDialog();
    /// File > Save scene as: asks where, then saveModelScene (main_window_models.cpp).
    void saveSceneDialog();
    void exportScreenshot(QWidget* w, const QString& what);
    void exportTrace();
    /// Shows a scene made by a worker: views, text, the first ray to replay, the render.
    void showScene(SceneRef scene, bool renderImage);
    /// The render settings control (bounces, diffuse samples, samples per pixel) and the "ray
    /// trace this view" action; a change renders the image again.
    void createRenderSettings();
    /// The View and File items of 3D scenes enabled with a 3D scene only, and the 2D view's
    /// screenshot with a 2D one.
    void syncViewActions();
    /// The control shows the scene's own render settings.
    void syncRenderSettings(const Scene& scene);
    /// Renders the image again once events settle (a camera drag moves it many times).
    void scheduleRender();
    /// Renders again if the image's wanted size changed (the view's own size when it is of the
    /// 3D view's camera; the lesson's frame), unless it was cancelled or failed.
    void followImageSize();
    /// Shows the running render's newest pass, if one came.
    void takeFrame();
    /// A click in the 3D view: records the ray under it, seen by the 3D view's camera.
    void traceViewPoint(QPointF widgetPos);
    /// Which of the 2D view, 3D view and image are shown (a 2D lesson needs no 3D view).
    void showViews(bool view2D, bool view3D, bool image);
    /// An open that did not end well: say why (a dialog unless quiet), keep what is shown.
    void openFailed(const QString& what, const TaskOutcome& outcome, bool quiet);
    /// The same for a failure told by a message (a lesson file that cannot be read).
    void openFailed(const QString& what, const QString& message, bool quiet);
    /// Quiz mode: an action that would show another trace, or the held one past its limit (a
    /// pixel click, B, R, C, exporting the trace), while an exercise holds the replay. Refused,
    /// and the lesson panel and the status bar say why (`toWhat`: "replay the build"). True if
    /// refused.
    bool refusedWhileHeld(const QString& toWhat);
    /// The same for a comparison: also while an unsolved exercise asks about one of `choices`.
    bool refusedWhileAnyHeld(const std::vector<StructureChoice>& choices);
    /// The first unsolved exercise (quiz mode) that asks about one of `choices`, and which.
    std::optional<std::pair<int, StructureChoice>> heldAmong(
        const std::vector<StructureChoice>& choices) const;
    void finishOpen(bool ok, const QString& error);
    /// A warning that does not block the event loop (no nested loop: the window goes on).
    void warn(const QString& title, const QString& text);

    Session session_;
    // Declared after the session and everything its work reads: destroyed (joined) first.
    TaskRunner runner_;
    std::uint64_t generation_ = 0;  // counts the scenes shown: a result for an older one is dropped
    std::optional<bool> lastOpenOk_;
    QString lastOpenError_;
    QPointer<CompareWindow> compare_;
    QPointer<CompareChooser> chooser_;
    bool geometryRestored_ = false;
    bool stateRestored_ = false;
    bool layoutSettled_ = false;
    QAction* resetLayout_ = nullptr;
    View2D* view2D_ = nullptr;
    VtkView* view3D_ = nullptr;
    ImageView* imageView_ = nullptr;
    LessonPanel* lesson_ = nullptr;
    QWidget* views_ = nullptr;
    Timeline* timeline_ = nullptr;
    Inspector* inspector_ = nullptr;
    EventList* events_ = nullptr;
    LessonController* lessons_ = nullptr;
    /// The menus' actions, made by createActions and placed by createMenus.
    struct Actions {
        QAction *open, *saveScene, *exportTrace, *shotWindow, *shot2D, *shot3D, *shotImage,
            *exportReport, *quit;
        QAction *stepForward, *stepBack, *play, *nextOfKind, *replayBuild, *exampleRay, *first,
            *last;
        QAction *openLessonFile, *quizMode, *presentMode, *lecturer, *backToLesson, *showErrata;
        QAction *compare, *chooseCompare, *renderAgain, *heatmap, *resetCamera;
    } actions_{};
    /// The menu bar's menus, made by createMenus (Edit and Help are filled by the live parts).
    struct Menus {
        QMenu *file, *edit, *replay, *lessons, *view, *help;
    } menus_{};
    // --- live lab (main_window_live.cpp) members go here ---
    Live2D* live2d_ = nullptr;
    /// File > Save 2D scene as: asks where, then Live2D::save.
    void save2DSceneDialog();
    // --- live controls and board (main_window_board.cpp) members go here ---
    BoardTable* board_ = nullptr;
    LiveControls* liveControls_ = nullptr;
    QDockWidget *boardDock_ = nullptr, *liveDock_ = nullptr;
    /// Whether the docks were last shown for a 2D scene (they follow the kind of scene: shown
    /// with the lecture's 2D pictures, hidden beside the 3D view and image, which need the room).
    std::optional<bool> boardFor2D_;
    /// The live controls asked for `kind` with `options` (a 2D scene's own grid set aside for
    /// lambda's), built and shown through applyStructure or showLive.
    void applyLive(AccelKind kind, const AccelOptions& options);
    /// View > Reset layout's part: the board and the live controls under the views, side by side.
    void placeBoardDocks();
    // --- presenter (main_window_presenter.cpp) members go here ---
    /// View > zoom, full screen, presenter mode, high contrast; Help > Keyboard shortcuts.
    struct PresenterActions {
        QAction *zoomIn, *zoomOut, *resetZoom, *fullScreen, *presenterMode, *highContrast,
            *shortcuts;
    } presenterActions_{};
    QPointer<ShortcutsDialog> shortcuts_;
    /// The View menu's checks follow the presentation (changed elsewhere: another window).
    void syncPresenterActions();
    /// After a zoom: the docks under the views at the zoom's height (defaultBottomDockHeight).
    void fitBottomDocksToZoom();
    int dockZoom_ = 100;  // the zoom the docks under the views were last fitted for
    QComboBox* structureBox_ = nullptr;
    QComboBox* splitBox_ = nullptr;
    QLabel* structureLabel_ = nullptr;
    /// The user's last choice in the chooser (File > Open builds it); none: a kd-tree, SAH.
    std::optional<std::pair<AccelKind, SplitMethod>> chosenStructure_;
    QLabel* taskLabel_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    // Ray trace this view: the action, the settings control, and the render under way.
    QAction* rayTraceView_ = nullptr;
    QToolBar* renderBar_ = nullptr;
    QSpinBox *bouncesBox_ = nullptr, *diffuseBox_ = nullptr, *sppBox_ = nullptr;
    std::optional<ImageFrame> imageFrame_;
    std::uint64_t imageGeneration_ = ~std::uint64_t(0);  // the scene the image was made for
    bool renderPending_ = false;
    std::shared_ptr<FrameBox> frames_;  // the running render's newest pass
};

}  // namespace raystep::gui
