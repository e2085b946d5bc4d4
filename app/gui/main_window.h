#pragma once
// The replay app's window: lesson panel, 2D view, 3D view and image side by side, the timeline
// under them, the inspector and the event list on the right.
#include "session.h"
#include "task_runner.h"

#include "course/lesson.h"
#include "course/progress.h"

#include <functional>
#include <optional>

#include <QImage>
#include <QMainWindow>
#include <QPointer>

class QComboBox;
class QLabel;
class QMenu;
class QLineEdit;
class QListView;
class QProgressBar;
class QPushButton;
class QSlider;
class QSortFilterProxyModel;
class QSpinBox;
class QTextBrowser;
class QTimer;
class QToolButton;

namespace raystep::gui {

/// Saves `image` as a PNG at `path` through the core's writer: regular files only (a FIFO or a
/// device is refused, not opened and waited on), a temporary renamed into place (a failed write
/// leaves the old file whole). The one-line problem, or an empty string.
QString savePng(const QImage& image, const QString& path);

class CompareWindow;
class ImageView;
class LessonPanel;
class View2D;
class VtkView;
class EventListModel;

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
    /// Starts opening a lesson (built-in id or number, or a file): its scene, structure and
    /// trace, its views, and the step the user's progress was at; likewise in the background.
    void openLesson(const QString& idOrPath, bool quiet = false);
    /// How the last open ended: nullopt while it runs (or before any), else true or false.
    std::optional<bool> lastOpenOk() const { return lastOpenOk_; }
    QString lastOpenError() const { return lastOpenError_; }

    /// B: records the structure's construction in the background, then replays it.
    void replayBuild();
    /// Renders the image of the 3D scene in the background (what the image view shows).
    void renderImage();
    /// Opens compare mode (midpoint, median, SAH) once its three trees are built.
    void openCompare();
    /// The compare window last opened, while it is open.
    CompareWindow* compareWindow() const;

    /// Runs `f` on the GUI thread once no background work is left (at once if none is).
    void whenIdle(std::function<void()> f);
    /// Tests and scripts: processes events until no background work is left; false on timeout.
    bool waitUntilIdle(int timeoutMs = 300000);

    LessonPanel* lessonPanel() const { return lesson_; }
    void setLanguage(Language lang);
    void setLecturerMode(bool on);
    const Progress& studentProgress() const { return studentProgress_; }
    QString progressPath() const { return progressPath_; }
    /// The inspector's text (what tests read).
    QString inspectorText() const;
    View2D* view2D() const { return view2D_; }
    VtkView* view3D() const { return view3D_; }
    ImageView* imageView() const { return imageView_; }
    /// `wanted`, made to fit the screen the window is on (a student's laptop is 1366x768).
    QSize fitToScreen(QSize wanted) const;
    /// Whether a window geometry saved by an earlier run was restored.
    bool geometryRestored() const { return geometryRestored_; }

  signals:
    /// An openScene or openLesson ended: opened, or not (with why; "cancelled" included).
    void opened(bool ok, const QString& error);

  public slots:
    void stepForward();
    void stepBack();
    void jumpToNextOfKind();
    void togglePlay();

  protected:
    void closeEvent(QCloseEvent*) override;

  private:
    void buildUi();
    void updateTimeline();
    void openFileDialog();
    void exportScreenshot(QWidget* w, const QString& what);
    void exportTrace();
    void exportProgressReport();
    void applyStep(int index);
    /// A lesson's steps and exercises are positions in its trace: replay it again if needed.
    void showLessonTrace();
    void saveProgress();
    void runSweep();
    void fillLessonsMenu();
    /// Shows a scene made by a worker: views, text, the first ray to replay, the render.
    void showScene(SceneRef scene, bool renderImage);
    /// An open that did not end well: say why (a dialog unless quiet), keep what is shown.
    void openFailed(const QString& what, const TaskOutcome& outcome, bool quiet);
    void finishOpen(bool ok, const QString& error);
    /// What the replay shows when it is not the lesson's trace ("" when it is).
    QString replayDescription() const;
    /// A warning that does not block the event loop (no nested loop: the window goes on).
    void warn(const QString& title, const QString& text);

    Session session_;
    // Declared after the session and everything its work reads: destroyed (joined) first.
    TaskRunner runner_;
    std::uint64_t generation_ = 0;  // counts the scenes shown: a result for an older one is dropped
    std::optional<bool> lastOpenOk_;
    QString lastOpenError_;
    QPointer<CompareWindow> compare_;
    bool geometryRestored_ = false;
    View2D* view2D_ = nullptr;
    VtkView* view3D_ = nullptr;
    ImageView* imageView_ = nullptr;
    LessonPanel* lesson_ = nullptr;
    QAction* lecturerAction_ = nullptr;
    QMenu* lessonsMenu_ = nullptr;
    Language lang_ = Language::En;
    Progress studentProgress_;
    QString progressPath_;
    QTextBrowser* inspector_ = nullptr;
    QListView* events_ = nullptr;
    EventListModel* eventModel_ = nullptr;
    QSortFilterProxyModel* eventFilter_ = nullptr;
    QLineEdit* filterEdit_ = nullptr;
    QSlider* scrubber_ = nullptr;
    QLabel* position_ = nullptr;
    QComboBox* kindCombo_ = nullptr;
    QSpinBox* speed_ = nullptr;
    QToolButton* play_ = nullptr;
    QTimer* timer_ = nullptr;
    QLabel* taskLabel_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
};

}  // namespace raystep::gui
