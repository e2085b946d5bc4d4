#pragma once
// A progress bar on stderr, drawn only when stderr is a terminal.
#include <chrono>
#include <string>

namespace raystep::cli {

class ProgressBar {
  public:
    explicit ProgressBar(std::string label);
    ~ProgressBar();
    /// Redraws when the shown percentage changes (to 0.01% below 10%, so a render of hours
    /// moves), or a second has passed; always returns true (never cancels).
    bool update(double fraction);
    void finish();

  private:
    std::string label_;
    bool enabled_;
    long lastShown_ = -1;  // in hundredths of a percent
    std::chrono::steady_clock::time_point lastDrawn_;
    bool finished_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace raystep::cli
