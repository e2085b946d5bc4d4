#include "raystep/render/render.h"

#include "raystep/base/timer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

namespace raystep {

std::vector<ProgressivePass> progressivePlan(int firstBlock, int spp, bool refine) {
    std::vector<ProgressivePass> plan;
    for (int b = std::max(firstBlock, 1); b >= 2; b /= 2) plan.push_back({b, 1});
    // After coarse passes every pixel first gets its sample 0 (the pixels they traced already
    // have it), then the rest: doubling, or all at once.
    if (refine || firstBlock > 1) plan.push_back({1, 1});
    if (refine)
        for (int s = 2; s < 2 * spp; s *= 2) plan.push_back({1, std::min(s, spp)});
    else if (spp > 1 || firstBlock <= 1)
        plan.push_back({1, spp});
    return plan;
}

namespace {
int threadsOf(int wanted) {
    return wanted > 0 ? wanted : tbb::info::default_concurrency();
}
}  // namespace

ProgressiveRender::ProgressiveRender(const Scene& scene, SceneQuery query, RenderOptions options)
    : scene_(scene),
      options_(options),
      tracer_(scene, query, options.trace),
      threads_(threadsOf(options.threads)) {
    if (options_.width < 1 || options_.height < 1 || options_.width > kMaxImageSide ||
        options_.height > kMaxImageSide)
        throw std::invalid_argument("progressive render: the image size must be 1.." +
                                    std::to_string(kMaxImageSide) + " a side, got " +
                                    std::to_string(options_.width) + "x" +
                                    std::to_string(options_.height));
    if (options_.spp < 1)
        throw std::invalid_argument("progressive render: spp must be at least 1, got " +
                                    std::to_string(options_.spp));
    if (options_.firstBlock < 1 || (options_.firstBlock & (options_.firstBlock - 1)) != 0)
        throw std::invalid_argument(
            "progressive render: the first block must be a power of two, got " +
            std::to_string(options_.firstBlock));
    if (!options_.camera) options_.camera = scene.camera;
    if (!cameraUsable(*options_.camera))
        throw std::invalid_argument("progressive render: the camera has no view direction");
    tracer_.fixCamera(*options_.camera, options_.width, options_.height);
    plan_ = progressivePlan(options_.firstBlock, options_.spp, options_.refine);
    onePass_ = plan_.size() == 1;
    const std::size_t n = static_cast<std::size_t>(options_.width) * options_.height;
    if (!onePass_) {
        rng_.reserve(n);
        // The stream Tracer::renderPixel gives the pixel: the same image whatever the passes.
        for (std::uint64_t i = 0; i < n; ++i) rng_.emplace_back(options_.seed, i);
        sum_.assign(n, Color(0.0));
        tests_.assign(n, 0);
    }
    image_ = Image(options_.width, options_.height);
    cost_.assign(n, 0);
}

void ProgressiveRender::sample(int x, int y, int from, int to, RayCounters& counters) {
    const std::size_t i = static_cast<std::size_t>(y) * options_.width + x;
    RayCounters pixel;
    if (onePass_) {
        Pcg32 rng(options_.seed, i);
        Color sum(0.0);
        tracer_.addSamples(x, y, from, to, options_, rng, sum, pixel);
        image_.pixels[i] = sum / static_cast<double>(to);
        cost_[i] = pixel.traversal.primitiveTests;
    } else {
        tracer_.addSamples(x, y, from, to, options_, rng_[i], sum_[i], pixel);
        tests_[i] += pixel.traversal.primitiveTests;
    }
    counters += pixel;
}

bool ProgressiveRender::nextPass(const ProgressFn& progress) {
    if (done()) return false;
    const ProgressivePass pass = plan_[next_];
    const int w = options_.width, h = options_.height;
    const bool first = next_ == 0;
    // The coarse passes trace each pixel's first sample; the refinements add the next ones.
    const bool coarse = pass.samples == 1;
    const int from = coarse ? 0 : samplesDone_, to = coarse ? 1 : pass.samples;
    // Rows of the pass's lattice: every block-th row; a coarse pass after the first skips the
    // pixels the pass before traced (both coordinates multiples of 2 * block).
    const int b = pass.block;
    const int rows = (h + b - 1) / b;
    const auto traced = [&](int x, int y) {
        if (!coarse) return true;  // refinement: every pixel
        if (x % b != 0 || y % b != 0) return false;
        return first || x % (2 * b) != 0 || y % (2 * b) != 0;
    };

    std::atomic<bool> stop{false};
    std::atomic<int> rowsDone{0};
    std::mutex totalsMutex, progressMutex;
    // Under progressMutex: threads on other rows see other fractions, the user sees them grow.
    double reported = 0.0;
    const auto report = [&](double f) {
        reported = std::max(reported, f);
        return progress(reported);
    };
    double ms = 0.0;
    {
        const ScopedTimer timer(ms);
        tbb::task_arena arena(threads_);
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<int>(0, rows, 1), [&](const tbb::blocked_range<int>& r) {
                    for (int row = r.begin(); row != r.end(); ++row) {
                        if (stop) return;
                        const int y = row * b;
                        RayCounters rowCounters;
                        for (int x = 0; x < w; x += b) {
                            // A row can take seconds (brute force on a million
                            // triangles): a cancel is looked at every 8 pixels
                            // (every pixel, the threads' fight for the mutex cost
                            // the fast path a third of its frame).
                            if (stop) return;
                            if (traced(x, y)) sample(x, y, from, to, rowCounters);
                            if (progress && (x / b) % 8 == 7 && progressMutex.try_lock()) {
                                if (!report((rowsDone + double(x) / w) / rows)) stop = true;
                                progressMutex.unlock();
                            }
                        }
                        {
                            const std::lock_guard lock(totalsMutex);
                            counters_ += rowCounters;
                        }
                        const int done = ++rowsDone;
                        // Reported by whichever worker is free to; the others do not
                        // wait.
                        if (progress && progressMutex.try_lock()) {
                            if (!report(static_cast<double>(done) / rows)) stop = true;
                            progressMutex.unlock();
                        }
                    }
                });
        });
        if (stop) {
            cancelled_ = true;
            return false;
        }
        samplesDone_ = to;
        // The complete picture: each pixel shows its block's traced pixel, averaged (one pass
        // wrote its pixels as it went).
        const double n = static_cast<double>(samplesDone_);
        if (!onePass_)
            arena.execute([&] {
                tbb::parallel_for(0, h, [&](int y) {
                    const int cy = y / b * b;
                    for (int x = 0; x < w; ++x) {
                        const std::size_t c = static_cast<std::size_t>(cy) * w + x / b * b;
                        const std::size_t i = static_cast<std::size_t>(y) * w + x;
                        image_.pixels[i] = sum_[c] / n;
                        cost_[i] = tests_[c];
                    }
                });
            });
    }
    passMs_.push_back(ms);
    ++next_;
    return true;
}

bool ProgressiveRender::run(const ProgressFn& progress) {
    while (!done())
        if (!nextPass(progress)) return false;
    return !cancelled_;
}

RenderResult render(const Scene& scene, SceneQuery query, const RenderOptions& options,
                    const ProgressFn& progress) {
    ProgressiveRender r(scene, query, options);
    const double passes = static_cast<double>(r.plan().size());
    while (!r.done()) {
        const double before = static_cast<double>(r.passesDone());
        ProgressFn pass;  // none asked: none looked at between pixels
        if (progress) pass = [&](double x) { return progress((before + x) / passes); };
        if (!r.nextPass(pass)) break;
    }
    if (progress && !r.cancelled()) progress(1.0);
    return std::move(r).result();
}

RenderResult ProgressiveRender::result() && {
    RenderResult out;
    out.image = std::move(image_);
    out.costPerPixel = std::move(cost_);
    out.counters = counters_;
    for (const double ms : passMs_) out.renderMs += ms;
    out.cancelled = cancelled_;
    return out;
}

}  // namespace raystep
