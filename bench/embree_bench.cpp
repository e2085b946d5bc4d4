// The uninstrumented fast path against Embree 3 (rtcIntersect1, one thread), on the same
// 102,400-triangle mesh and the same rays: primary rays of a 512x384 camera and random rays
// (origins in the mesh's bounds, uniform directions). Ratios go to docs/performance.md.
// Run: build/bench/raystep_bench_embree
#include "meshes.h"
#include "raystep/accel/accel.h"
#include "raystep/base/rng.h"
#include "raystep/scene/fast_prims.h"

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <cmath>
#include <limits>

namespace {

using namespace raystep;

const Scene& mesh() {
    static const Scene s = bench::knotScene(1600);  // 1600 x 32 quads = 102,400 triangles
    return s;
}

std::vector<Ray> primaryRays() {
    const Scene& s = mesh();
    std::vector<Ray> rays;
    for (int y = 0; y < 384; ++y)
        for (int x = 0; x < 512; ++x)
            rays.push_back(s.camera.generateRay(x + 0.5, y + 0.5, 512, 384));
    return rays;
}

std::vector<Ray> randomRays() {
    const Bounds3 b = mesh().bounds();
    Pcg32 rng(42, 7);
    std::vector<Ray> rays;
    for (int i = 0; i < 512 * 384; ++i) {
        const Vec3 o = b.lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * b.diagonal();
        const double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform();
        const double r = std::sqrt(1 - z * z);
        rays.push_back({o, Vec3(r * std::cos(phi), r * std::sin(phi), z)});
    }
    return rays;
}

const std::vector<Ray>& rays(int which) {
    static const std::vector<Ray> primary = primaryRays();
    static const std::vector<Ray> random = randomRays();
    return which == 0 ? primary : random;
}

/// Embree's scene over the same triangles (float vertices, as Embree stores them).
struct EmbreeScene {
    RTCDevice device = rtcNewDevice("threads=1");
    RTCScene scene = rtcNewScene(device);
    EmbreeScene() {
        const Scene& s = mesh();
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              3 * s.triangles.size()));
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), s.triangles.size()));
        for (std::size_t i = 0; i < s.triangles.size(); ++i) {
            const Triangle& t = s.triangles[i];
            for (int k = 0; k < 3; ++k) {
                const Vec3& p = k == 0 ? t.a : (k == 1 ? t.b : t.c);
                v[9 * i + 3 * k + 0] = static_cast<float>(p.x);
                v[9 * i + 3 * k + 1] = static_cast<float>(p.y);
                v[9 * i + 3 * k + 2] = static_cast<float>(p.z);
                idx[3 * i + k] = static_cast<unsigned>(3 * i + k);
            }
        }
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene);
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

void BM_Embree(benchmark::State& state) {
    static EmbreeScene e;
    const std::vector<Ray>& rs = rays(static_cast<int>(state.range(0)));
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    std::uint64_t n = 0, hits = 0;
    for (auto _ : state) {
        for (const Ray& r : rs) {
            RTCRayHit rh{};
            rh.ray.org_x = float(r.origin.x), rh.ray.org_y = float(r.origin.y);
            rh.ray.org_z = float(r.origin.z);
            rh.ray.dir_x = float(r.dir.x), rh.ray.dir_y = float(r.dir.y),
            rh.ray.dir_z = float(r.dir.z);
            rh.ray.tnear = 0.0f;
            rh.ray.tfar = std::numeric_limits<float>::infinity();
            rh.ray.mask = ~0u;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(e.scene, &context, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
        n += rs.size();
    }
    state.counters["Mrays/s"] = benchmark::Counter(n * 1e-6, benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * hits / std::max<std::uint64_t>(n, 1);
}

template <typename Structure>
void traceAll(benchmark::State& state, const Structure& accel) {
    const std::vector<Ray>& rs = rays(static_cast<int>(state.range(0)));
    std::uint64_t n = 0, hits = 0;
    TraversalCounters c;
    for (auto _ : state) {
        for (const Ray& r : rs) hits += accel.intersect(r, c).has_value();
        n += rs.size();
    }
    state.counters["Mrays/s"] = benchmark::Counter(n * 1e-6, benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * hits / std::max<std::uint64_t>(n, 1);
    state.counters["tests/ray"] = double(c.primitiveTests) / std::max<std::uint64_t>(n, 1);
    state.counters["nodes/ray"] = double(c.nodeVisits) / std::max<std::uint64_t>(n, 1);
}

void BM_KdTreeSah_Float(benchmark::State& state) {
    static const KdTree<FloatScenePrims> t(FloatScenePrims(mesh()), KdTreeOptions{});
    traceAll(state, t);
}
void BM_BvhSah_Float(benchmark::State& state) {
    static const Bvh<FloatScenePrims> b(FloatScenePrims(mesh()), BvhOptions{});
    traceAll(state, b);
}
// The accurate defaults on the same rays: double, watertight, for the price of accuracy.
void BM_KdTreeSah_Double(benchmark::State& state) {
    static const KdTree3 t(ScenePrims(mesh(), {}), KdTreeOptions{});
    traceAll(state, t);
}
void BM_BvhSah_Double(benchmark::State& state) {
    static const Bvh3 b(ScenePrims(mesh(), {}), BvhOptions{});
    traceAll(state, b);
}

// Arg 0: primary rays; 1: random rays.
BENCHMARK(BM_Embree)->Arg(0)->Arg(1)->ArgName("random")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_KdTreeSah_Float)->Arg(0)->Arg(1)->ArgName("random")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BvhSah_Float)->Arg(0)->Arg(1)->ArgName("random")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_KdTreeSah_Double)->Arg(0)->Arg(1)->ArgName("random")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BvhSah_Double)->Arg(0)->Arg(1)->ArgName("random")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
