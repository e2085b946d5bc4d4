#pragma once
// The one render loop. render() makes the whole image in one pass of every sample (the CLI);
// ProgressiveRender makes it in passes (the app): a coarse picture at once (one ray per 8x8
// block, then 4x4, 2x2 and every pixel, each pass tracing only the new pixels), then more samples
// per pixel up to the wanted spp while nothing moves. Both end on the same image, pixel for pixel:
// each pixel keeps its own random stream, sampled by Tracer::addSamples.
#include "raystep/render/tracer.h"
#include "raystep/scene/camera.h"

#include <cstdint>
#include <vector>

namespace raystep {

struct RenderResult {
    Image image;
    std::vector<std::uint64_t> costPerPixel;  // primitive tests per pixel (the heat map)
    RayCounters counters;
    double renderMs = 0.0;
    bool cancelled = false;
};

/// What a pass made: blocks of `block` x `block` pixels share the ray of their top-left pixel
/// (block 1: every pixel its own), averaged over `samples` samples per pixel.
struct ProgressivePass {
    int block = 1;
    int samples = 1;
};

/// The passes a render makes, in order: the coarse blocks halving down to 1 (one sample each),
/// then the samples per pixel doubling 2, 4 ... up to `spp` when `refine`, else the rest of
/// `spp` at once. firstBlock 1 without refine: one pass of every sample, the whole-image render.
std::vector<ProgressivePass> progressivePlan(int firstBlock, int spp, bool refine = true);

class ProgressiveRender {
  public:
    /// `scene` and what `query` holds (a structure or the fast path) must outlive the render. The
    /// options are checked: width and height in 1..kMaxImageSide, spp >= 1, firstBlock a power of
    /// two, a camera with a view direction (std::invalid_argument otherwise). No camera in the
    /// options: the scene's.
    ProgressiveRender(const Scene& scene, SceneQuery query, RenderOptions options);

    /// Runs the next pass on all the options' threads. Returns false when `progress` asks to stop
    /// (then the render is over: done()), the image left as the previous pass made it; a single
    /// pass writes its pixels as it goes, so a cancelled one leaves them partly written.
    bool nextPass(const ProgressFn& progress = {});
    /// Runs every pass left; false if cancelled.
    bool run(const ProgressFn& progress = {});

    bool done() const { return cancelled_ || next_ >= plan_.size(); }
    bool cancelled() const { return cancelled_; }
    /// The last pass finished (nullptr before the first).
    const ProgressivePass* lastPass() const { return next_ > 0 ? &plan_[next_ - 1] : nullptr; }
    std::size_t passesDone() const { return next_; }
    const std::vector<ProgressivePass>& plan() const { return plan_; }

    /// The picture after the last pass: complete at every pass (blocks filled by their ray).
    const Image& image() const { return image_; }
    /// Primitive tests per pixel, filled the same way (the heat map).
    const std::vector<std::uint64_t>& costPerPixel() const { return cost_; }
    /// Everything traced so far.
    const RayCounters& counters() const { return counters_; }
    const RenderOptions& options() const { return options_; }
    /// Milliseconds each pass took, in order.
    const std::vector<double>& passMs() const { return passMs_; }
    /// The image, the heat map and the counters moved out, with the passes' time added up.
    RenderResult result() &&;

  private:
    /// Adds pixel (x, y)'s samples [from, to) to its sum (the sampling of Tracer::renderPixel).
    void sample(int x, int y, int from, int to, RayCounters& counters);

    const Scene& scene_;
    RenderOptions options_;  // its camera set (the scene's when none was given)
    Tracer tracer_;
    std::vector<ProgressivePass> plan_;
    std::size_t next_ = 0;
    bool cancelled_ = false;
    // One pass writes each pixel once; only passes after passes keep these between them.
    bool onePass_ = false;
    std::vector<Pcg32> rng_;            // each pixel's random stream, kept between its passes
    std::vector<Color> sum_;            // each pixel's sum of samples so far
    std::vector<std::uint64_t> tests_;  // each pixel's primitive tests so far
    int samplesDone_ = 0;  // samples each traced pixel holds (every pixel's from the 1x1 pass on)
    Image image_;
    std::vector<std::uint64_t> cost_;
    RayCounters counters_;
    std::vector<double> passMs_;
    int threads_;  // TBB stays out of this header: Qt's `emit` macro breaks its headers
};

/// The whole image in the passes `options` plans (one, by default) on `options.threads` threads.
/// The image and the counters are the same for any thread count and any passes.
RenderResult render(const Scene& scene, SceneQuery query, const RenderOptions& options,
                    const ProgressFn& progress = {});

}  // namespace raystep
