#pragma once
// A progressive render of any camera at any size: a coarse picture at once (one ray per 8x8
// block, then 4x4, 2x2 and every pixel, each pass tracing only the new pixels), then more samples
// per pixel up to the wanted spp while nothing moves. Its last pass is the same image as render()
// of the same camera and settings, pixel for pixel: each pixel keeps its own random stream.
#include "raystep/render/tracer.h"
#include "raystep/scene/camera.h"

#include <cstdint>
#include <vector>

namespace raystep {

struct ProgressiveOptions {
    Camera camera;  // any camera: the scene's, or the 3D view's
    int width = 640;
    int height = 480;
    int spp = 1;  // samples per pixel of the last pass (as RenderOptions::spp)
    TraceSettings trace;
    int threads = 0;  // 0 = all cores
    std::uint64_t seed = 1;
    int firstBlock = 8;  // side of the first pass's blocks (a power of two, 1 = no coarse pass)
};

/// What a pass made: blocks of `block` x `block` pixels share the ray of their top-left pixel
/// (block 1: every pixel its own), averaged over `samples` samples per pixel.
struct ProgressivePass {
    int block = 1;
    int samples = 1;
};

/// The passes a render makes, in order: the coarse blocks halving down to 1 (one sample each),
/// then the samples per pixel doubling up to `spp`.
std::vector<ProgressivePass> progressivePlan(int firstBlock, int spp);

class ProgressiveRender {
  public:
    /// `scene` and `accel` must outlive the render. The options are checked: width and height in
    /// 1..kMaxImageSide, spp >= 1, firstBlock a power of two (std::invalid_argument otherwise).
    ProgressiveRender(const Scene& scene, const Accelerator& accel, ProgressiveOptions options);

    /// Runs the next pass on all the options' threads. Returns false, with the image left as the
    /// previous pass made it, when `progress` asks to stop (then the render is over: done()).
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
    const ProgressiveOptions& options() const { return options_; }
    /// Milliseconds each pass took, in order.
    const std::vector<double>& passMs() const { return passMs_; }

  private:
    /// Adds pixel (x, y)'s samples [from, to) to its sum (the sampling of Tracer::renderPixel).
    void sample(int x, int y, int from, int to, RayCounters& counters);

    const Scene& scene_;
    const Accelerator& accel_;
    ProgressiveOptions options_;
    Tracer tracer_;
    std::vector<ProgressivePass> plan_;
    std::size_t next_ = 0;
    bool cancelled_ = false;
    std::vector<Pcg32> rng_;            // each pixel's random stream, kept between its passes
    std::vector<Color> sum_;            // each pixel's sum of samples so far
    std::vector<std::uint64_t> tests_;  // each pixel's primitive tests so far
    int samplesDone_ = 0;               // samples every pixel holds (0 during the coarse passes)
    Image image_;
    std::vector<std::uint64_t> cost_;
    RayCounters counters_;
    std::vector<double> passMs_;
    int threads_;  // TBB stays out of this header: Qt's `emit` macro breaks its headers
};

}  // namespace raystep
