// "Ray trace this view" on a big mesh: after a camera move, how soon the first (coarse) picture
// and the full 640x480 image at 1 spp are there, on the Stanford bunny (69,666 triangles) with the
// SAH kd-tree and the SAH BVH. Run: build/bench/raystep_bench_progressive (docs/performance.md).
#include "raystep/render/render.h"
#include "raystep/scene/scene_loader.h"

#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

namespace {

using namespace raystep;

constexpr const char* kBunnyPath = "/usr/share/glmark2/models/bunny.obj";  // glmark2-data

/// The bunny on a floor, lit by two lights, the camera framing it (the mesh spans about
/// [-1, 1] x [-0.99, 0.99] x [-0.78, 0.78]).
Scene bunnyScene() {
    const std::string text = R"({
      "camera": {"eye": [0.6, 0.5, 3.4], "look_at": [0, -0.1, 0], "up": [0, 1, 0], "fov": 40},
      "background": [0.1, 0.12, 0.16], "ambient": 0.1,
      "lights": [{"position": [3, 4, 4], "intensity": 0.8},
                 {"position": [-4, 3, 2], "color": [0.6, 0.7, 1.0], "intensity": 0.5}],
      "materials": {"clay": {"kd": [0.8, 0.7, 0.55], "ks": 0.2, "n": 20},
                    "floor": {"kd": 0.6, "checker": {"color": 0.3, "size": 0.5}}},
      "objects": [
        {"type": "mesh", "file": "bunny.obj", "material": "clay"},
        {"type": "triangle", "material": "floor",
         "vertices": [[-6, -0.992, -6], [-6, -0.992, 6], [6, -0.992, 6]]},
        {"type": "triangle", "material": "floor",
         "vertices": [[-6, -0.992, -6], [6, -0.992, 6], [6, -0.992, -6]]}]})";
    return loadSceneText(text, "bunny.json", [](const std::string&) -> std::optional<std::string> {
        std::ifstream in(kBunnyPath, std::ios::binary);
        if (!in) return std::nullopt;
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    });
}

/// The scene and its structure, built once per structure (the build is not what is measured).
struct Prepared {
    const Scene& scene;  // the structure points into it
    Accelerator accel;
};
const Prepared& prepared(AccelKind kind) {
    static const Scene scene = bunnyScene();
    static Prepared kd{scene, buildAccelerator(scene, AccelKind::KdTree)};
    static Prepared bvh{scene, buildAccelerator(scene, AccelKind::Bvh)};
    return kind == AccelKind::KdTree ? kd : bvh;
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
void firstImage(benchmark::State& state, AccelKind kind) {
    const Prepared& p = prepared(kind);
    int step = 0;
    for (auto _ : state) {
        ProgressiveRender r(p.scene, p.accel, options(p.scene, ++step, int(state.range(0))));
        r.nextPass();
        benchmark::DoNotOptimize(r.image().pixels.data());
    }
    state.counters["triangles"] = double(p.scene.triangles.size());
}

/// From the camera move to the full 640x480 image at 1 spp: all four passes.
void fullImage(benchmark::State& state, AccelKind kind) {
    const Prepared& p = prepared(kind);
    int step = 0;
    std::uint64_t rays = 0;
    for (auto _ : state) {
        ProgressiveRender r(p.scene, p.accel, options(p.scene, ++step, int(state.range(0))));
        r.run();
        benchmark::DoNotOptimize(r.image().pixels.data());
        rays += r.counters().totalRays();
    }
    state.counters["Mrays"] = benchmark::Counter(rays * 1e-6, benchmark::Counter::kIsRate);
}

/// The same image in one plain render(): what the progressive passes cost on top.
void plainRender(benchmark::State& state, AccelKind kind) {
    const Prepared& p = prepared(kind);
    int step = 0;
    for (auto _ : state) {
        RenderOptions o = options(p.scene, ++step, int(state.range(0)));
        o.firstBlock = 1;  // one pass
        o.refine = false;
        const RenderResult img = render(p.scene, p.accel, o);
        benchmark::DoNotOptimize(img.image.pixels.data());
    }
}

void BM_Bunny_FirstImage_KdTree(benchmark::State& s) {
    firstImage(s, AccelKind::KdTree);
}
void BM_Bunny_FirstImage_Bvh(benchmark::State& s) {
    firstImage(s, AccelKind::Bvh);
}
void BM_Bunny_Full640x480_KdTree(benchmark::State& s) {
    fullImage(s, AccelKind::KdTree);
}
void BM_Bunny_Full640x480_Bvh(benchmark::State& s) {
    fullImage(s, AccelKind::Bvh);
}
void BM_Bunny_PlainRender640x480_KdTree(benchmark::State& s) {
    plainRender(s, AccelKind::KdTree);
}
void BM_Bunny_PlainRender640x480_Bvh(benchmark::State& s) {
    plainRender(s, AccelKind::Bvh);
}

#define RAYSTEP_BUNNY_BENCH(name) \
    BENCHMARK(name)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()
RAYSTEP_BUNNY_BENCH(BM_Bunny_FirstImage_KdTree);
RAYSTEP_BUNNY_BENCH(BM_Bunny_FirstImage_Bvh);
RAYSTEP_BUNNY_BENCH(BM_Bunny_Full640x480_KdTree);
RAYSTEP_BUNNY_BENCH(BM_Bunny_Full640x480_Bvh);
RAYSTEP_BUNNY_BENCH(BM_Bunny_PlainRender640x480_KdTree);
RAYSTEP_BUNNY_BENCH(BM_Bunny_PlainRender640x480_Bvh);

}  // namespace

BENCHMARK_MAIN();
