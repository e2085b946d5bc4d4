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
    fraction = fraction > 0 ? (fraction < 1 ? fraction : 1.0) : 0.0;
    const long shown = static_cast<long>(fraction * 10000.0);  // hundredths of a percent
    const auto now = std::chrono::steady_clock::now();
    // Past 10% whole tenths are enough; below, hundredths show a long render moving.
    const long step = shown >= 1000 ? 10 : 1;
    if (lastShown_ >= 0 && shown / step == lastShown_ / step &&
        now - lastDrawn_ < std::chrono::seconds(1))
        return true;
    lastShown_ = shown;
    lastDrawn_ = now;
    constexpr int kWidth = 40;
    const int filled = static_cast<int>(fraction * kWidth);
    const double seconds = std::chrono::duration<double>(now - start_).count();
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(kWidth - filled), '.');
    // What is left, at the pace so far, once there is a pace to go by.
    char left[48] = "";
    if (fraction > 0 && fraction < 1 && seconds >= 3) {
        const double rest = seconds * (1 - fraction) / fraction;
        if (rest < 120)
            std::snprintf(left, sizeof left, ", about %.0f s left", rest);
        else if (rest < 7200)
            std::snprintf(left, sizeof left, ", about %.0f min left", rest / 60);
        else if (rest < 3 * 86400)
            std::snprintf(left, sizeof left, ", about %.0f h left", rest / 3600);
        else
            std::snprintf(left, sizeof left, ", about %.0f days left", rest / 86400);
    }
    std::fprintf(stderr, "\r%s [%s] %6.2f%% %6.1f s%s\033[K", label_.c_str(), bar.c_str(),
                 shown / 100.0, seconds, left);
    std::fflush(stderr);
    return true;
}

void ProgressBar::finish() {
    if (enabled_ && !finished_ && lastShown_ >= 0) std::fputc('\n', stderr);
    finished_ = true;
}

}  // namespace raystep::cli
