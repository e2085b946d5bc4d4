#pragma once
// The replay app's window: lesson panel, 2D view, 3D view and image side by side, the timeline
// under them, the inspector and the event list on the right.
#include "session.h"

#include "raystep/lesson.h"

#include <exception>
#include <functional>

#include <QMainWindow>

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
    /// Opens a scene (built-in name or file) with a structure; false (and a dialog unless quiet)
    /// on a bad scene, with the current one kept.
    bool openScene(const QString& nameOrPath, AccelKind kind, bool quiet = false,
                   const AccelOptions& options = {}, bool renderImage = true);
    /// Opens a lesson (built-in id or number, or a file): its scene, structure and trace, its
    /// views, and the step the user's progress was at. False (and a dialog unless quiet) if not.
    bool openLesson(const QString& idOrPath, bool quiet = false);
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
    /// Opens compare mode for the current 2D scene (null, with a message, for a 3D one).
    CompareWindow* openCompare();
    /// Waits (processing events) until a background render started by openScene is done.
    void waitForRender();

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
    void saveProgress();
    void runSweep();
    void fillLessonsMenu();
    /// Runs `work` on a worker thread behind a progress dialog whose Cancel makes the progress
    /// callback say stop; the window keeps painting. Returns what `work` threw, if anything.
    std::exception_ptr runWithProgress(const QString& label,
                                       const std::function<void(const ProgressFn&)>& work);

    Session session_;
    View2D* view2D_ = nullptr;
    VtkView* view3D_ = nullptr;
    ImageView* imageView_ = nullptr;
    LessonPanel* lesson_ = nullptr;
    QAction* lecturerAction_ = nullptr;
    QMenu* lessonsMenu_ = nullptr;
    bool busy_ = false;  // long work under way (runWithProgress)
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
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
};

}  // namespace raystep::gui
