#include "progress.h"

#include <unistd.h>

#include <cstdio>

namespace raystep::cli {

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)),
      enabled_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    finish();
}

bool ProgressBar::update(double fraction) {
    if (!enabled_ || finished_) return true;
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == lastPercent_) return true;
    lastPercent_ = percent;
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(kWidth - filled), '.');
    std::fprintf(stderr, "\r%s [%s] %3d%% %6.1f s", label_.c_str(), bar.c_str(), percent, seconds);
    std::fflush(stderr);
    return true;
}

void ProgressBar::finish() {
    if (enabled_ && !finished_ && lastPercent_ >= 0) std::fputc('\n', stderr);
    finished_ = true;
}

}  // namespace raystep::cli
