#pragma once
// File > Open student trace: a student's own run (JSON Lines, docs/assignment-format.md) checked
// against the open scene's structure by the core's assessor (raystep/assess/assess.h). The ray
// they got wrong is replayed as raystep runs it, their cells or nodes drawn over it in the 2D
// view, their rows beside raystep's on the board, the replay at the step where the two part, and
// the verdict (the lecture's explanation, the known mistake) in a bar over the views.
#include "session.h"

#include "raystep/assess/assess.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

class QAction;
class QComboBox;
class QLabel;
class QMainWindow;
class QMenu;
class QPushButton;
class QWidget;

namespace raystep::gui {

class BoardTable;
class View2D;

class AssessController : public QObject {
    Q_OBJECT
  public:
    struct Hooks {
        /// Quiz mode: true, the user told why, when an exercise holds the replay.
        std::function<bool(const QString& toWhat)> refusedWhileHeld;
    };
    AssessController(QMainWindow& window, Session& session, View2D* view, BoardTable* board,
                     Hooks hooks);
    ~AssessController() override;

    /// File > Open student trace... (after File > Open scene).
    void addFileItems(QMenu* file);
    QAction* openAction() const { return open_; }
    /// The bar over the views: the file, its score, the ray shown, the verdict (hidden until a
    /// trace is open).
    QWidget* bar() const { return bar_; }

    /// Reads the trace at `path`, checks it against the open scene's structure and shows the
    /// first ray that failed (ray 0 if all passed). A file that cannot be read changes nothing:
    /// a message box names its file, line and key (unless quiet). The problem, or empty.
    QString open(const QString& path, bool quiet = false);
    /// Shows ray `ray` of the open trace: raystep's run of it replayed, the student's walk over
    /// it, the replay at the step where they part.
    void showRay(int ray);
    /// The bar closed, the student's walk and columns gone (the replayed run stays).
    void close();

    bool isOpen() const { return assessment_.has_value(); }
    const std::optional<Assessment>& assessment() const { return assessment_; }
    /// The ray shown (-1: none).
    int shownRay() const { return shownRay_; }
    /// The bar's verdict of the ray shown, as on screen.
    QString verdictText() const;
    QComboBox* rayChooser() const { return rays_; }

  signals:
    /// A ray of a student's trace is shown (the window shows the board beside it).
    void rayShown();

  private:
    void dialog();
    void syncEnabled();

    QMainWindow& window_;
    Session& session_;
    View2D* view_;
    BoardTable* board_;
    Hooks hooks_;
    QAction* open_ = nullptr;
    QWidget* bar_ = nullptr;
    QLabel* title_ = nullptr;
    QLabel* verdict_ = nullptr;
    QComboBox* rays_ = nullptr;
    QPushButton* closeButton_ = nullptr;
    // The trace checked, against the scene it was checked on (the reference points into its
    // structure, which the SceneRef keeps alive).
    SceneRef scene_;
    std::optional<StudentTrace> trace_;
    std::unique_ptr<Reference> reference_;
    std::optional<Assessment> assessment_;
    LogRef shownLog_;  // raystep's run of the ray shown
    int shownRay_ = -1;
};

}  // namespace raystep::gui
