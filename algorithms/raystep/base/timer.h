#pragma once
// A build or render timer: one object per timed block instead of a pair of clock readings.
#include <chrono>

namespace raystep {

/// Writes the milliseconds between its construction and its destruction into `ms` (pbrt-v3's
/// RAII ProfilePhase idea): `ScopedTimer timer(stats_.buildMs);` at the top of the block.
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
