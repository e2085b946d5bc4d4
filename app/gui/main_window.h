#pragma once
// The replay app's window: lesson panel, 2D view, 3D view and image side by side, the timeline
// under them, the inspector and the event list on the right. It makes its views and its parts
// (each a class owning one job: docs/architecture.md, "The window's parts"), wires them in its
// constructor, and builds the menus from what each part adds to them.
#include "image_render.h"
#include "session.h"
#include "task_runner.h"

#include "lesson_controller.h"

#include "course/lesson.h"
#include "course/progress.h"

#include <functional>
#include <optional>

#include <QImage>
#include <QMainWindow>

class QAction;
class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace raystep::gui {

/// Saves `image` as a PNG at `path` through the core's writer: regular files only (a FIFO or a
/// device is refused, not opened and waited on), a temporary renamed into place (a failed write
/// leaves the old file whole). The one-line problem, or an empty string.
QString savePng(const QImage& image, const QString& path);

class AssessController;
class BoardDocks;
class BoardTable;
class CompareChooser;
class CompareLauncher;
class CompareWindow;
class PracticeController;
class LiveControls;
class LiveEdit;
class EventList;
class ImageView;
class Inspector;
class LessonController;
class LessonPanel;
enum class LessonMode;  // lesson_panel.h
class PresenterControls;
class SceneOpener;
class ShortcutsDialog;
class Live2D;
class Timeline;
class View2D;
class VtkView;
class WindowLayout;

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
    /// File > Open student trace: `path` checked against the open scene's structure, its first
    /// failed ray shown over raystep's run (assess_controller.h). The problem, or empty (a bad
    /// file changes nothing; a message box says why unless quiet).
    QString openStudentTrace(const QString& path, bool quiet = false);
    AssessController* assessController() const { return assess_; }
    /// The board dock's table and the live controls (board_docks.h).
    BoardTable* boardTable() const;
    LiveControls* liveControls() const;
    /// Help > Keyboard shortcuts (F1, ?): opens the list of every key, made from the window's
    /// actions and shortcuts as they are now; the one open, or null (presenter_controls.h).
    void showShortcuts();
    ShortcutsDialog* shortcutsDialog() const;
    /// Live lecture mode: shows `scene` (the open one edited or rebuilt) at once, recording again
    /// what was replayed at the same step (Session::relive); what ran for the old scene stops.
    void showLive(SceneRef scene);
    /// The 2D view's live editing: its scene edits and their undo stack (live_edit.h).
    Live2D* live2D() const;
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
    std::optional<bool> lastOpenOk() const;
    QString lastOpenError() const;

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
    /// with when clicked (image_render.h).
    using ImageFrame = ImageRender::Frame;
    const std::optional<ImageFrame>& imageFrame() const;
    /// View > Ray trace this view (checkable).
    QAction* rayTraceViewAction() const;
    /// `wanted`, made to fit the screen the window is on (a student's laptop is 1366x768).
    QSize fitToScreen(QSize wanted) const;
    /// Whether a window geometry saved by an earlier run was restored.
    bool geometryRestored() const;
    /// At start: the size saved by the last run (Qt clamps it to this screen), else one that
    /// fits the screen.
    void sizeForScreen();
    /// View > Reset layout: the docks back on the right, shown and docked, the docks and the
    /// splitters at their default sizes for the window's width.
    void resetLayout();
    QAction* resetLayoutAction() const;
    /// The default widths for a window `windowWidth` wide: the lesson panel's and the docks'.
    static int defaultLessonWidth(int windowWidth);
    static int defaultDockWidth(int windowWidth);
    /// The board's and live controls' height under the views for a window `windowHeight` high
    /// at `zoomPercent`: above 100% they give the views what the larger chrome takes.
    static int defaultBottomDockHeight(int windowHeight, int zoomPercent);
    /// True once the first show has put the layout in shape (restored or default sizes).
    bool layoutSettled() const;

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
    // The views and docks, the status bar and the window's own actions, made in this order.
    void createViews();
    void createTimeline();
    void createDocks();
    void createStatusBar();
    void createActions();
    /// The menus, in their order: the window's own items and what each part adds.
    void createMenus();
    /// The structure chooser (a tool bar) and the status bar's structure (main_window_models.cpp).
    void createStructureControls();
    /// The chooser's pick, once asked about where it needs asking (brute force on a big scene).
    void buildChosenStructure(AccelKind kind, SplitMethod split);
    /// The chooser and the status bar say what the session's scene uses.
    void syncStructureControls();
    /// The live controls asked for `kind` with `options` (a 2D scene's own grid set aside for
    /// lambda's), built and shown through applyStructure or showLive.
    void applyLive(AccelKind kind, const AccelOptions& options);
    /// A 2D structure built by `build` on this thread and shown live; the status bar and
    /// structureChanged say how it ended (a failed build leaves the scene and the controls).
    void showLiveBuild(const std::function<SceneRef()>& build);
    void openFileDialog();
    /// File > Save scene as: asks where, then saveModelScene (main_window_models.cpp).
    void saveSceneDialog();
    void exportScreenshot(QWidget* w, const QString& what);
    void exportTrace();
    /// openScene's scene is shown: its text, views and title.
    void showOpenedScene(const QString& nameOrPath);
    /// openLesson's scene is shown: its trace, views, docks, text, pixel and title.
    void showOpenedLesson(const LessonController::Opened& o);
    /// The File and View items of one kind of scene (screenshots) enabled with that kind only.
    void syncViewActions();
    /// Which of the 2D view, 3D view and image are shown (a 2D lesson needs no 3D view).
    void showViews(bool view2D, bool view3D, bool image);
    /// Quiz mode: an action that would show another trace, or the held one past its limit (a
    /// pixel click, B, R, C, exporting the trace), while an exercise holds the replay. Refused,
    /// and the lesson panel and the status bar say why (`toWhat`: "replay the build"). True if
    /// refused.
    bool refusedWhileHeld(const QString& toWhat);

    Session session_;
    // Declared after the session and everything its work reads: destroyed (joined) first.
    TaskRunner runner_;
    View2D* view2D_ = nullptr;
    VtkView* view3D_ = nullptr;
    ImageView* imageView_ = nullptr;
    LessonPanel* lesson_ = nullptr;
    QWidget* views_ = nullptr;
    Timeline* timeline_ = nullptr;
    Inspector* inspector_ = nullptr;
    EventList* events_ = nullptr;
    // The parts, each owning one job (made and wired by the constructor).
    SceneOpener* opener_ = nullptr;
    LessonController* lessons_ = nullptr;
    PracticeController* practice_ = nullptr;
    ImageRender* image_ = nullptr;
    LiveEdit* live_ = nullptr;
    BoardDocks* board_ = nullptr;
    AssessController* assess_ = nullptr;
    PresenterControls* presenter_ = nullptr;
    CompareLauncher* compare_ = nullptr;
    WindowLayout* layout_ = nullptr;
    /// The window's own actions, made by createActions and placed by createMenus.
    struct Actions {
        QAction *open, *saveScene, *exportTrace, *shotWindow, *shot2D, *shot3D, *shotImage,
            *exportReport, *quit;
        QAction *stepForward, *stepBack, *play, *nextOfKind, *replayBuild, *exampleRay, *first,
            *last;
        QAction *openLessonFile, *quizMode, *presentMode, *lecturer, *backToLesson, *showErrata;
    } actions_{};
    QComboBox* structureBox_ = nullptr;
    QComboBox* splitBox_ = nullptr;
    QLabel* structureLabel_ = nullptr;
    /// The user's last choice in the chooser (File > Open builds it); none: a kd-tree, SAH.
    std::optional<std::pair<AccelKind, SplitMethod>> chosenStructure_;
    QLabel* taskLabel_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
};

}  // namespace raystep::gui
