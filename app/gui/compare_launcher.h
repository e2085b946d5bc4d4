#pragma once
// Compare mode from the window: View > Compare on this ray (C) and Compare structures (Shift+C),
// the structures built in the background, then the same ray through each in a window of its own.
// Refused while an exercise holds the replay, or asks about one of the structures (quiz mode).
#include "session.h"
#include "task_runner.h"

#include <QObject>
#include <QPointer>
#include <QSize>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

class QAction;
class QMainWindow;
class QMenu;

namespace raystep::gui {

class CompareChooser;
class CompareWindow;
class LessonPanel;

class CompareLauncher : public QObject {
    Q_OBJECT
  public:
    /// What compare mode asks of the rest of the window.
    struct Hooks {
        /// Quiz mode: true, the user told why, when an exercise holds the replay.
        std::function<bool(const QString& toWhat)> refusedWhileHeld;
        std::function<QSize(QSize)> fitToScreen;
        /// The window's own keys that work in the compare window too (Quit, zoom, shortcuts).
        QList<QAction*> windowKeys;
    };
    /// `generation` counts the scenes the window has shown: a comparison for an older one is
    /// dropped.
    CompareLauncher(QMainWindow& window, Session& session, TaskRunner& runner,
                    const std::uint64_t& generation, LessonPanel* lesson, Hooks hooks);

    /// View > Compare on this ray, Compare structures...
    void addViewItems(QMenu* view);
    /// Opens compare mode on `choices` (each a structure, and a split for a tree) once they are
    /// built: the same ray through each, side by side.
    void open(const std::vector<StructureChoice>& choices);
    /// The same on the comparison made for the structure shown (defaultComparison).
    void open();
    /// Asks which (CompareChooser), then opens them.
    void choose();
    /// The compare window closes: its trees are of a scene no longer shown, or the window goes.
    void close();
    CompareChooser* chooser() const;
    CompareWindow* window() const;

  private:
    /// The same refusal for a comparison: also while an unsolved exercise asks about one of
    /// `choices`. True if refused.
    bool refusedWhileAnyHeld(const std::vector<StructureChoice>& choices);
    /// The first unsolved exercise (quiz mode) that asks about one of `choices`, and which.
    std::optional<std::pair<int, StructureChoice>> heldAmong(
        const std::vector<StructureChoice>& choices) const;

    QMainWindow& window_;
    Session& session_;
    TaskRunner& runner_;
    const std::uint64_t& generation_;
    LessonPanel* lesson_;
    Hooks hooks_;
    QAction *compare_ = nullptr, *chooseCompare_ = nullptr;
    QPointer<CompareWindow> compareWindow_;
    QPointer<CompareChooser> chooser_;
};

}  // namespace raystep::gui
