#pragma once
// A build's progress and its cancellation, reported to whoever waits for it.
#include <cstdint>
#include <functional>
#include <stdexcept>

namespace raystep {

/// Called now and then with the fraction done; return false to cancel. Calls never overlap.
using ProgressFn = std::function<bool(double fraction)>;

/// Thrown out of a build whose progress callback asked to stop.
class BuildCancelled : public std::runtime_error {
  public:
    BuildCancelled() : std::runtime_error("build cancelled") {}
};

/// A depth-first build's progress: each node owns a share of the work (its primitives' share of
/// its parent's), and a leaf completes its share. Reports every 1%; throws BuildCancelled when
/// the callback says stop.
class BuildProgress {
  public:
    explicit BuildProgress(const ProgressFn& fn) : fn_(fn) {}
    /// Runs `f` (a child's build) as `fraction` of the current node's share.
    template <typename F>
    void child(double fraction, F&& f) {
        const double parent = share_;
        share_ = parent * fraction;
        f();
        share_ = parent;
    }
    void leafDone() {
        done_ += share_;
        if (fn_ && done_ - reported_ >= 0.01) {
            reported_ = done_;
            if (!fn_(done_ < 1.0 ? done_ : 1.0)) throw BuildCancelled();
        }
    }

  private:
    const ProgressFn& fn_;
    double share_ = 1.0, done_ = 0.0, reported_ = 0.0;
};

}  // namespace raystep
