#pragma once
// A progress bar on stderr, drawn only when stderr is a terminal.
#include <chrono>
#include <string>

namespace raystep::cli {

class ProgressBar {
  public:
    explicit ProgressBar(std::string label);
    ~ProgressBar();
    /// Redraws when the shown percentage changes; always returns true (never cancels).
    bool update(double fraction);
    void finish();

  private:
    std::string label_;
    bool enabled_;
    int lastPercent_ = -1;
    bool finished_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace raystep::cli
