// Whole renders: the figures of docs/performance.md. Run: build/bench/raystep_bench_render
#include "raystep/render/render.h"
#include "raystep/scene/scene_loader.h"

#include <benchmark/benchmark.h>

namespace {

using namespace raystep;

/// One full render per iteration; reports ms per frame and, as rates, millions of rays (all kinds),
/// of primary rays and of primitive tests a second.
void renderScene(benchmark::State& state, const char* sceneName, int width, int height, int bounces,
                 int spp, int diffuseSamples, bool fastKernels = false,
                 AccelKind kind = AccelKind::BruteForce) {
    const Scene scene = loadBuiltinScene(sceneName);
    // The fast choices: float, Moller-Trumbore, textbook spheres, fixed epsilon (docs/accuracy.md).
    const KernelOptions kernels = fastKernels
                                      ? KernelOptions{Precision::Float, SphereMethod::Textbook,
                                                      TriangleMethod::MollerTrumbore}
                                      : KernelOptions{};
    const Accelerator accel = buildAccelerator(scene, kind, kernels);
    RenderOptions opt;
    opt.trace.rayOffset = fastKernels ? RayOffsetMethod::Epsilon : RayOffsetMethod::Robust;
    opt.width = width;
    opt.height = height;
    opt.spp = spp;
    opt.trace.bounces = bounces;
    opt.trace.diffuseSamples = diffuseSamples;
    opt.threads = static_cast<int>(state.range(0));
    std::uint64_t rays = 0, primary = 0, tests = 0;
    for (auto _ : state) {
        const RenderResult r = render(scene, accel, opt);
        benchmark::DoNotOptimize(r.image.pixels.data());
        rays += r.counters.totalRays();
        primary += r.counters[RayKind::Primary];
        tests += r.counters.traversal.primitiveTests;
    }
    state.counters["Mrays"] = benchmark::Counter(rays * 1e-6, benchmark::Counter::kIsRate);
    state.counters["primary_Mrays"] =
        benchmark::Counter(primary * 1e-6, benchmark::Counter::kIsRate);
    state.counters["Mtests"] = benchmark::Counter(tests * 1e-6, benchmark::Counter::kIsRate);
    state.counters["rays/frame"] =
        benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kAvgIterations);
}

// The reference point: default scene, 800x600, 1 spp, 2 bounces, brute force.
void BM_Default800x600_BruteForce(benchmark::State& state) {
    renderScene(state, "default", 800, 600, 2, 1, 0);
}
BENCHMARK(BM_Default800x600_BruteForce)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The teapot in a stadium: brute force pays for every one of its 51,212 primitives per ray.
// The same with the fast numerical choices: the price of the accurate defaults, in one run.
void BM_Default800x600_BruteForce_FastKernels(benchmark::State& state) {
    renderScene(state, "default", 800, 600, 2, 1, 0, true);
}
BENCHMARK(BM_Default800x600_BruteForce_FastKernels)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_Stadium64x48_BruteForce_FastKernels(benchmark::State& state) {
    renderScene(state, "stadium", 64, 48, 1, 1, 0, true);
}
BENCHMARK(BM_Stadium64x48_BruteForce_FastKernels)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_Stadium64x48_BruteForce(benchmark::State& state) {
    renderScene(state, "stadium", 64, 48, 1, 1, 0);
}
BENCHMARK(BM_Stadium64x48_BruteForce)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The uniform grid on the same frames (Cleary-Wyvill, lambda 4, mailbox on).
void BM_Default800x600_Grid(benchmark::State& state) {
    renderScene(state, "default", 800, 600, 2, 1, 0, false, AccelKind::Grid);
}
BENCHMARK(BM_Default800x600_Grid)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_Stadium64x48_Grid(benchmark::State& state) {
    renderScene(state, "stadium", 64, 48, 1, 1, 0, false, AccelKind::Grid);
}
BENCHMARK(BM_Stadium64x48_Grid)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The hierarchies on the same frames (SAH, the defaults).
void BM_Default800x600_KdTree(benchmark::State& state) {
    renderScene(state, "default", 800, 600, 2, 1, 0, false, AccelKind::KdTree);
}
BENCHMARK(BM_Default800x600_KdTree)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
void BM_Default800x600_Bvh(benchmark::State& state) {
    renderScene(state, "default", 800, 600, 2, 1, 0, false, AccelKind::Bvh);
}
BENCHMARK(BM_Default800x600_Bvh)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
void BM_Stadium64x48_KdTree(benchmark::State& state) {
    renderScene(state, "stadium", 64, 48, 1, 1, 0, false, AccelKind::KdTree);
}
BENCHMARK(BM_Stadium64x48_KdTree)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
void BM_Stadium64x48_Bvh(benchmark::State& state) {
    renderScene(state, "stadium", 64, 48, 1, 1, 0, false, AccelKind::Bvh);
}
BENCHMARK(BM_Stadium64x48_Bvh)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// The stadium at a real size, where only the hierarchies are usable.
void BM_Stadium640x480_KdTree(benchmark::State& state) {
    renderScene(state, "stadium", 640, 480, 1, 1, 0, false, AccelKind::KdTree);
}
BENCHMARK(BM_Stadium640x480_KdTree)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
void BM_Stadium640x480_Bvh(benchmark::State& state) {
    renderScene(state, "stadium", 640, 480, 1, 1, 0, false, AccelKind::Bvh);
}
BENCHMARK(BM_Stadium640x480_Bvh)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Colour bleeding's price: the Cornell box with 16 diffuse samples.
void BM_Cornell128_Diffuse16(benchmark::State& state) {
    renderScene(state, "cornell", 128, 128, 3, 1, 16);
}
BENCHMARK(BM_Cornell128_Diffuse16)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
