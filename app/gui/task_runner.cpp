#include "task_runner.h"

#include <QTimer>

#include <algorithm>

namespace raystep::gui {

QString TaskOutcome::errorText() const {
    if (!error) return {};
    try {
        std::rethrow_exception(error);
    } catch (const std::exception& e) {
        return QString::fromUtf8(e.what());
    } catch (...) {
        return QObject::tr("unknown error");
    }
}

TaskRunner::TaskRunner(QObject* parent) : QObject(parent), timer_(new QTimer(this)) {
    // Polling keeps every hand-over on the GUI thread: a worker never calls into a QObject.
    timer_->setInterval(15);
    connect(timer_, &QTimer::timeout, this, [this] { poll(); });
}

TaskRunner::~TaskRunner() {
    shutdown();
}

bool TaskRunner::launch(TaskKind kind, const QString& label,
                        std::function<void(const ProgressFn&)> work,
                        std::function<void(const TaskOutcome&)> finish) {
    if (shutDown_) return false;
    for (auto& t : tasks_)
        if (t->kind == kind && !t->superseded) {
            t->superseded = true;
            t->state->cancel = true;
        }
    auto task = std::make_unique<Task>();
    task->kind = kind;
    task->label = label;
    task->state = std::make_shared<State>();
    task->finish = std::move(finish);
    // The thread holds the state and the work (and so whatever the work captured) by value.
    task->thread = std::thread([state = task->state, work = std::move(work)] {
        const ProgressFn progress = [&state](double f) {
            state->percent = static_cast<int>(std::clamp(f, 0.0, 1.0) * 100.0);
            return !state->cancel.load();
        };
        try {
            work(progress);
        } catch (const BuildCancelled&) {
            state->workCancelled = true;
        } catch (...) {
            state->error = std::current_exception();
        }
        state->finished.store(true, std::memory_order_release);
    });
    tasks_.push_back(std::move(task));
    if (!timer_->isActive()) timer_->start();
    emit progressChanged(label, 0);
    return true;
}

bool TaskRunner::busy(TaskKind kind) const {
    for (const auto& t : tasks_)
        if (t->kind == kind) return true;
    return false;
}

int TaskRunner::percent(TaskKind kind) const {
    for (auto it = tasks_.rbegin(); it != tasks_.rend(); ++it)
        if ((*it)->kind == kind && !(*it)->superseded) return (*it)->state->percent;
    return 0;
}

void TaskRunner::cancel(TaskKind kind) {
    for (auto& t : tasks_)
        if (t->kind == kind) t->state->cancel = true;
}

void TaskRunner::cancelAll() {
    for (auto& t : tasks_) t->state->cancel = true;
}

void TaskRunner::shutdown() {
    shutDown_ = true;
    timer_->stop();
    cancelAll();
    for (auto& t : tasks_)
        if (t->thread.joinable()) t->thread.join();
    // Their `done` would touch a window that is going away: dropped, with what they captured.
    tasks_.clear();
}

void TaskRunner::poll() {
    if (shutDown_) return;
    // Take the finished tasks out first: a `done` may start new work (and so change tasks_).
    std::vector<std::unique_ptr<Task>> finished;
    for (auto it = tasks_.begin(); it != tasks_.end();) {
        if ((*it)->state->finished.load(std::memory_order_acquire)) {
            (*it)->thread.join();
            finished.push_back(std::move(*it));
            it = tasks_.erase(it);
        } else {
            ++it;
        }
    }
    for (auto& t : finished) {
        if (shutDown_) break;  // a `done` closed the window
        TaskOutcome outcome;
        outcome.superseded = t->superseded;
        outcome.cancelled = t->state->cancel || t->state->workCancelled;
        outcome.error = outcome.cancelled ? nullptr : t->state->error;
        t->finish(outcome);
    }
    if (shutDown_) return;
    const Task* newest = nullptr;
    for (const auto& t : tasks_)
        if (!t->superseded) newest = t.get();
    if (newest)
        emit progressChanged(newest->label, newest->state->percent);
    else if (!finished.empty())
        emit progressChanged(QString(), 100);
    if (tasks_.empty()) {
        timer_->stop();
        if (!finished.empty()) emit idle();
    }
}

}  // namespace raystep::gui
