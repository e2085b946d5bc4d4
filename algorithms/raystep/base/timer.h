#pragma once
// Build timers: one object times a scope and writes the milliseconds where the stats keep them.
#include <chrono>

namespace raystep {

/// Writes the milliseconds from its construction to its destruction into `ms`.
class ScopedTimer {
  public:
    explicit ScopedTimer(double& ms) : ms_(ms), start_(std::chrono::steady_clock::now()) {}
    ~ScopedTimer() {
        ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
                  .count();
    }
    ScopedTimer(const ScopedTimer&) = delete;
    ScopedTimer& operator=(const ScopedTimer&) = delete;

  private:
    double& ms_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace raystep
