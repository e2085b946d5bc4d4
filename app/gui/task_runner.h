#pragma once
// The app's background work, designed once: every worker thread belongs to the runner, which
// cancels and joins it before anything the work reads is destroyed, hands the result to the GUI
// thread, and starts nothing after shutdown. Work reads only what it holds a share of (a
// std::shared_ptr it captured), never what the window may replace while it runs.
//
// There is no nested event loop: the window starts a task and goes on; the result arrives later
// through the task's `done`, called from the runner's timer on the GUI thread.
#include "raystep/accel/query.h"
#include "raystep/base/progress.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

class QTimer;

namespace raystep::gui {

/// What a task does. A new task of a kind supersedes the running one of that kind (a second
/// lesson picked while the first loads, a render of the new scene while the old one renders).
/// Structure: the open scene's structure built again as the user chose it (the chooser).
/// Pixel: a pixel's trace that takes more than a moment (brute force on a big scene).
enum class TaskKind { Scene, Render, Build, Compare, Sweep, Structure, Pixel };

/// How a task ended, as its `done` sees it.
struct TaskOutcome {
    bool cancelled = false;    // Cancel pressed, superseded, or the work threw BuildCancelled
    bool superseded = false;   // a newer task of the same kind replaced it: nobody waits for it
    std::exception_ptr error;  // what the work threw, BuildCancelled aside
    bool ok() const { return !cancelled && !error; }
    /// The error's message (what() of the exception thrown), "unknown error" for anything else,
    /// empty without an error.
    QString errorText() const;
};

class TaskRunner : public QObject {
    Q_OBJECT
  public:
    explicit TaskRunner(QObject* parent = nullptr);
    ~TaskRunner() override;

    /// Runs `work` on a thread of its own; `done` runs later on the GUI thread with what it
    /// returned (default-constructed when it threw or was cancelled) and how it ended. The work
    /// reports progress (0..1) through the ProgressFn, which answers false once it should stop.
    /// Returns false, running nothing, after shutdown().
    template <typename T>
    bool start(TaskKind kind, const QString& label, std::function<T(const ProgressFn&)> work,
               std::function<void(T&&, const TaskOutcome&)> done) {
        auto result = std::make_shared<std::optional<T>>();
        return launch(
            kind, label,
            [work = std::move(work), result](const ProgressFn& progress) {
                result->emplace(work(progress));
            },
            [done = std::move(done), result](const TaskOutcome& outcome) {
                T value = result->has_value() ? std::move(**result) : T{};
                if (done) done(std::move(value), outcome);
            });
    }

    /// Asks the running task of a kind (or every task) to stop; its `done` still runs.
    void cancel(TaskKind kind);
    void cancelAll();
    /// Cancels every task and joins every thread, here and now; no `done` runs after it and no
    /// task starts. The window calls it before anything a task could read is destroyed.
    void shutdown();
    bool isShutDown() const { return shutDown_; }
    /// A task started whose `done` has not run yet.
    bool busy() const { return !tasks_.empty(); }
    bool busy(TaskKind kind) const;
    /// The running task of a kind: how far it is (0-100; 0 when none runs).
    int percent(TaskKind kind) const;
    /// How many worker threads exist right now (tests: none after shutdown).
    std::size_t threads() const { return tasks_.size(); }

  signals:
    /// The newest task still running: its label and percent (label empty when none runs).
    void progressChanged(const QString& label, int percent);
    /// Every started task has finished and had its `done` called.
    void idle();

  private:
    struct State {
        std::atomic<bool> cancel{false};
        std::atomic<bool> finished{false};
        std::atomic<int> percent{0};
        bool workCancelled = false;  // written by the worker before `finished`
        std::exception_ptr error;    // likewise
    };
    struct Task {
        TaskKind kind;
        QString label;
        std::shared_ptr<State> state;
        std::function<void(const TaskOutcome&)> finish;
        bool superseded = false;
        std::thread thread;
    };

    bool launch(TaskKind kind, const QString& label, std::function<void(const ProgressFn&)> work,
                std::function<void(const TaskOutcome&)> finish);
    /// The GUI thread's side: join finished workers, call their `done`, report progress.
    void poll();

    std::vector<std::unique_ptr<Task>> tasks_;
    QTimer* timer_ = nullptr;
    bool shutDown_ = false;
};

}  // namespace raystep::gui
