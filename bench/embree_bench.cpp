// The fast path and the teaching structures against Embree 3 (rtcIntersect1 / rtcOccluded1, one
// thread), on the same triangles and the same rays: the Stanford bunny on its floor (69,668
// triangles) and a 102,400-triangle torus knot; primary rays of a 640x480 camera and random rays
// (origins in the mesh's bounds, uniform directions); build time and bytes per triangle.
// Ratios go to docs/performance.md. Run: build/bench/raystep_bench_embree
#include "meshes.h"
#include "raystep/accel/accel.h"
#include "raystep/base/rng.h"
#include "raystep/fast/wide_bvh.h"
#include "raystep/scene/fast_prims.h"

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

namespace {

using namespace raystep;

// Arg 0 of every benchmark: the mesh. Arg 1 of the ray benchmarks: primary (0) or random (1).
const Scene& mesh(int which) {
    static const Scene bunny = bench::bunnyScene();
    static const Scene knot = bench::knotScene(1600);  // 1600 x 32 quads = 102,400 triangles
    return which == 0 ? bunny : knot;
}

std::vector<Ray> primaryRays(const Scene& s) {
    std::vector<Ray> rays;
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 640; ++x)
            rays.push_back(s.camera.generateRay(x + 0.5, y + 0.5, 640, 480));
    return rays;
}

std::vector<Ray> randomRays(const Scene& s) {
    // The mesh's bounds without the bunny's floor: rays start among the triangles.
    Bounds3 b;
    for (const Triangle& t : s.triangles)
        if (t.material == s.triangles.front().material) {
            b.extend(t.a);
            b.extend(t.b);
            b.extend(t.c);
        }
    Pcg32 rng(42, 7);
    std::vector<Ray> rays;
    for (int i = 0; i < 640 * 480; ++i) {
        const Vec3 o = b.lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * b.diagonal();
        const double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform();
        const double r = std::sqrt(1 - z * z);
        rays.push_back({o, Vec3(r * std::cos(phi), r * std::sin(phi), z)});
    }
    return rays;
}

const std::vector<Ray>& rays(const benchmark::State& state) {
    static const std::vector<Ray> all[2][2] = {{primaryRays(mesh(0)), randomRays(mesh(0))},
                                               {primaryRays(mesh(1)), randomRays(mesh(1))}};
    return all[state.range(0)][state.range(1)];
}

/// Bytes Embree holds, counted by its memory monitor.
std::atomic<long long> embreeBytes{0};
bool countBytes(void*, ssize_t bytes, bool) {
    embreeBytes += bytes;
    return true;
}

/// Embree's scene over the same triangles (float vertices, as Embree stores them).
struct EmbreeScene {
    RTCDevice device = rtcNewDevice("threads=1");
    RTCScene scene = nullptr;
    double buildMs = 0.0;
    long long bytes = 0;
    explicit EmbreeScene(const Scene& s) {
        rtcSetDeviceMemoryMonitorFunction(device, countBytes, nullptr);
        const long long before = embreeBytes;
        const auto start = std::chrono::steady_clock::now();
        scene = rtcNewScene(device);
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
        buildMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        bytes = embreeBytes - before;
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

const EmbreeScene& embree(int which) {
    static const EmbreeScene bunny(mesh(0)), knot(mesh(1));
    return which == 0 ? bunny : knot;
}
const WideBvh& fast(int which) {
    static const WideBvh bunny(mesh(0)), knot(mesh(1));
    return which == 0 ? bunny : knot;
}

RTCRay embreeRay(const Ray& r) {
    RTCRay e{};
    e.org_x = float(r.origin.x), e.org_y = float(r.origin.y), e.org_z = float(r.origin.z);
    e.dir_x = float(r.dir.x), e.dir_y = float(r.dir.y), e.dir_z = float(r.dir.z);
    e.tnear = 0.0f;
    e.tfar = std::numeric_limits<float>::infinity();
    e.mask = ~0u;
    return e;
}

void rates(benchmark::State& state, std::uint64_t n, std::uint64_t hits) {
    state.counters["Mrays/s"] = benchmark::Counter(n * 1e-6, benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * hits / std::max<std::uint64_t>(n, 1);
}

void BM_Embree(benchmark::State& state) {
    const EmbreeScene& e = embree(int(state.range(0)));
    const std::vector<Ray>& rs = rays(state);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    std::uint64_t n = 0, hits = 0;
    for (auto _ : state) {
        for (const Ray& r : rs) {
            RTCRayHit rh{};
            rh.ray = embreeRay(r);
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(e.scene, &context, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
        n += rs.size();
    }
    rates(state, n, hits);
}

/// Any hit (shadow rays): Embree's rtcOccluded1 against the structures' occluded().
void BM_Embree_Occluded(benchmark::State& state) {
    const EmbreeScene& e = embree(int(state.range(0)));
    const std::vector<Ray>& rs = rays(state);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    std::uint64_t n = 0, hits = 0;
    for (auto _ : state) {
        for (const Ray& r : rs) {
            RTCRay ray = embreeRay(r);
            rtcOccluded1(e.scene, &context, &ray);
            hits += ray.tfar < 0.0f;
        }
        n += rs.size();
    }
    rates(state, n, hits);
}

template <typename Structure>
void traceAll(benchmark::State& state, const Structure& accel) {
    const std::vector<Ray>& rs = rays(state);
    std::uint64_t n = 0, hits = 0;
    TraversalCounters c;
    for (auto _ : state) {
        for (const Ray& r : rs) hits += accel.intersect(r, c).has_value();
        n += rs.size();
    }
    rates(state, n, hits);
    state.counters["tests/ray"] = double(c.primitiveTests) / std::max<std::uint64_t>(n, 1);
    state.counters["nodes/ray"] = double(c.nodeVisits) / std::max<std::uint64_t>(n, 1);
}

void BM_Fast(benchmark::State& state) {
    traceAll(state, fast(int(state.range(0))));
}
void BM_Fast_Occluded(benchmark::State& state) {
    const WideBvh& f = fast(int(state.range(0)));
    const std::vector<Ray>& rs = rays(state);
    std::uint64_t n = 0, hits = 0;
    TraversalCounters c;
    for (auto _ : state) {
        for (const Ray& r : rs) hits += f.occluded(r, c);
        n += rs.size();
    }
    rates(state, n, hits);
}
// The teaching BVH in float (the same kernels' precision as Embree) and in double (the default).
void BM_BvhSah_Float(benchmark::State& state) {
    static const Bvh<FloatScenePrims> b[2] = {{FloatScenePrims(mesh(0)), BvhOptions{}},
                                              {FloatScenePrims(mesh(1)), BvhOptions{}}};
    traceAll(state, b[state.range(0)]);
}
void BM_BvhSah_Double(benchmark::State& state) {
    static const Bvh3 b[2] = {{ScenePrims(mesh(0), {}), BvhOptions{}},
                              {ScenePrims(mesh(1), {}), BvhOptions{}}};
    traceAll(state, b[state.range(0)]);
}
void BM_KdTreeSah_Double(benchmark::State& state) {
    static const KdTree3 t[2] = {{ScenePrims(mesh(0), {}), KdTreeOptions{}},
                                 {ScenePrims(mesh(1), {}), KdTreeOptions{}}};
    traceAll(state, t[state.range(0)]);
}

/// Build time (one thread each) and the bytes the structure holds, per triangle.
void BM_Build_Embree(benchmark::State& state) {
    const Scene& s = mesh(int(state.range(0)));
    double bytes = 0;
    for (auto _ : state) {
        const EmbreeScene e(s);
        bytes = double(e.bytes);
    }
    state.counters["bytes/tri"] = bytes / double(s.triangles.size());
}
void BM_Build_Fast(benchmark::State& state) {
    const Scene& s = mesh(int(state.range(0)));
    double bytes = 0;
    for (auto _ : state) {
        const WideBvh f(s);
        bytes = double(f.stats().bytes);
        benchmark::DoNotOptimize(f.nodes().data());
    }
    state.counters["bytes/tri"] = bytes / double(s.triangles.size());
}
void BM_Build_BvhSah(benchmark::State& state) {
    const Scene& s = mesh(int(state.range(0)));
    double bytes = 0;
    for (auto _ : state) {
        const Bvh3 b(ScenePrims(s, {}), BvhOptions{});
        bytes = double(b.nodes().size() * sizeof(BvhNode<3>) +
                       b.primIds().size() * sizeof(std::uint32_t));
        benchmark::DoNotOptimize(b.nodes().data());
    }
    state.counters["bytes/tri"] = bytes / double(s.triangles.size());
}

void rayArgs(benchmark::internal::Benchmark* b) {
    b->ArgNames({"mesh", "random"})->Unit(benchmark::kMillisecond);
    for (int m = 0; m < 2; ++m)
        for (int r = 0; r < 2; ++r) b->Args({m, r});
}
void buildArgs(benchmark::internal::Benchmark* b) {
    b->ArgName("mesh")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(5);
}

// mesh 0: the bunny on its floor; mesh 1: the knot.
BENCHMARK(BM_Embree)->Apply(rayArgs);
BENCHMARK(BM_Fast)->Apply(rayArgs);
BENCHMARK(BM_Embree_Occluded)->Apply(rayArgs);
BENCHMARK(BM_Fast_Occluded)->Apply(rayArgs);
BENCHMARK(BM_BvhSah_Float)->Apply(rayArgs);
BENCHMARK(BM_BvhSah_Double)->Apply(rayArgs);
BENCHMARK(BM_KdTreeSah_Double)->Apply(rayArgs);
BENCHMARK(BM_Build_Embree)->Apply(buildArgs);
BENCHMARK(BM_Build_Fast)->Apply(buildArgs);
BENCHMARK(BM_Build_BvhSah)->Apply(buildArgs);

}  // namespace

BENCHMARK_MAIN();
