// "Ray trace this view" on a big mesh: after a camera move, how soon the first (coarse) picture
// and the full 640x480 image at 1 spp are there, on the Stanford bunny (69,666 triangles) with the
// SAH kd-tree, the SAH BVH and the fast path (fast/wide_bvh.h). Run:
// build/bench/raystep_bench_progressive (docs/performance.md).
#include "meshes.h"
#include "raystep/render/render.h"

#include <benchmark/benchmark.h>

namespace {

using namespace raystep;

/// The scene and its structure, built once per structure (the build is not what is measured).
struct Prepared {
    const Scene& scene;  // the structures point into it
    SceneQuery query;
};
/// The fast path stands in for a structure kind of its own here.
constexpr int kFast = -1;
const Prepared& prepared(int kind) {
    static const Scene scene = bench::bunnyScene();
    static const Accelerator kdTree = buildAccelerator(scene, AccelKind::KdTree);
    static const Accelerator bvhTree = buildAccelerator(scene, AccelKind::Bvh);
    static const WideBvh wide(scene);
    static const Prepared kd{scene, kdTree}, bvh{scene, bvhTree}, fast{scene, wide};
    if (kind == kFast) return fast;
    return kind == int(AccelKind::KdTree) ? kd : bvh;
}

/// A camera moved by `step` degrees around the bunny: each iteration a new view.
Camera movedCamera(const Scene& s, int step) {
    Camera c = s.camera;
    const double a = glm::radians(7.0 * (step % 50));
    const Vec3 d = c.eye - c.lookAt;
    c.eye = c.lookAt + Vec3(d.x * std::cos(a) + d.z * std::sin(a), d.y,
                            -d.x * std::sin(a) + d.z * std::cos(a));
    return c;
}

RenderOptions options(const Scene& s, int step, int threads) {
    RenderOptions o;
    o.firstBlock = 8;  // the app's passes
    o.refine = true;
    o.camera = movedCamera(s, step);
    o.width = 640;
    o.height = 480;
    o.spp = 1;
    o.trace.bounces = 2;
    o.threads = threads;
    return o;
}

/// From the camera move to the first complete (8x8-block) picture: the set-up and one pass.
void firstImage(benchmark::State& state, int kind) {
    const Prepared& p = prepared(kind);
    int step = 0;
    for (auto _ : state) {
        ProgressiveRender r(p.scene, p.query, options(p.scene, ++step, int(state.range(0))));
        r.nextPass();
        benchmark::DoNotOptimize(r.image().pixels.data());
    }
    state.counters["triangles"] = double(p.scene.triangles.size());
}

/// From the camera move to the full 640x480 image at 1 spp: all four passes.
void fullImage(benchmark::State& state, int kind) {
    const Prepared& p = prepared(kind);
    int step = 0;
    std::uint64_t rays = 0;
    for (auto _ : state) {
        ProgressiveRender r(p.scene, p.query, options(p.scene, ++step, int(state.range(0))));
        r.run();
        benchmark::DoNotOptimize(r.image().pixels.data());
        rays += r.counters().totalRays();
    }
    state.counters["Mrays"] = benchmark::Counter(rays * 1e-6, benchmark::Counter::kIsRate);
}

/// The same image in one plain render(): what the progressive passes cost on top.
void plainRender(benchmark::State& state, int kind) {
    const Prepared& p = prepared(kind);
    int step = 0;
    for (auto _ : state) {
        RenderOptions o = options(p.scene, ++step, int(state.range(0)));
        o.firstBlock = 1;  // one pass
        o.refine = false;
        const RenderResult img = render(p.scene, p.query, o);
        benchmark::DoNotOptimize(img.image.pixels.data());
    }
}

void BM_Bunny_FirstImage_KdTree(benchmark::State& s) {
    firstImage(s, int(AccelKind::KdTree));
}
void BM_Bunny_FirstImage_Bvh(benchmark::State& s) {
    firstImage(s, int(AccelKind::Bvh));
}
void BM_Bunny_Full640x480_KdTree(benchmark::State& s) {
    fullImage(s, int(AccelKind::KdTree));
}
void BM_Bunny_Full640x480_Bvh(benchmark::State& s) {
    fullImage(s, int(AccelKind::Bvh));
}
void BM_Bunny_PlainRender640x480_KdTree(benchmark::State& s) {
    plainRender(s, int(AccelKind::KdTree));
}
void BM_Bunny_PlainRender640x480_Bvh(benchmark::State& s) {
    plainRender(s, int(AccelKind::Bvh));
}

void BM_Bunny_FirstImage_Fast(benchmark::State& s) {
    firstImage(s, kFast);
}
void BM_Bunny_Full640x480_Fast(benchmark::State& s) {
    fullImage(s, kFast);
}
void BM_Bunny_PlainRender640x480_Fast(benchmark::State& s) {
    plainRender(s, kFast);
}
/// What "Ray trace this view" follows the camera with: primary and shadow rays (no bounce).
void BM_Bunny_Live640x480_Fast(benchmark::State& state) {
    const Prepared& p = prepared(kFast);
    int step = 0;
    std::uint64_t rays = 0;
    for (auto _ : state) {
        RenderOptions o = options(p.scene, ++step, int(state.range(0)));
        o.firstBlock = 1;
        o.refine = false;
        o.trace.bounces = 0;
        const RenderResult img = render(p.scene, p.query, o);
        rays += img.counters.totalRays();
        benchmark::DoNotOptimize(img.image.pixels.data());
    }
    state.counters["Mrays"] = benchmark::Counter(rays * 1e-6, benchmark::Counter::kIsRate);
    state.counters["fps"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

#define RAYSTEP_BUNNY_BENCH(name) \
    BENCHMARK(name)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()
RAYSTEP_BUNNY_BENCH(BM_Bunny_FirstImage_KdTree);
RAYSTEP_BUNNY_BENCH(BM_Bunny_FirstImage_Bvh);
RAYSTEP_BUNNY_BENCH(BM_Bunny_Full640x480_KdTree);
RAYSTEP_BUNNY_BENCH(BM_Bunny_Full640x480_Bvh);
RAYSTEP_BUNNY_BENCH(BM_Bunny_PlainRender640x480_KdTree);
RAYSTEP_BUNNY_BENCH(BM_Bunny_PlainRender640x480_Bvh);
RAYSTEP_BUNNY_BENCH(BM_Bunny_FirstImage_Fast);
RAYSTEP_BUNNY_BENCH(BM_Bunny_Full640x480_Fast);
RAYSTEP_BUNNY_BENCH(BM_Bunny_PlainRender640x480_Fast);
RAYSTEP_BUNNY_BENCH(BM_Bunny_Live640x480_Fast);

}  // namespace

BENCHMARK_MAIN();
