// Speed of each intersection kernel in each precision: the other side of docs/accuracy.md.
// The same 4096 (ray, primitive) pairs for every kernel. `rays_reused:1` gives every test its own
// ray (the worst case for the per-ray set-up of the watertight test); `rays_reused:16` tests each
// ray against 16 triangles in a row, as brute force and tree leaves do.
#include "raystep/base/rng.h"
#include "raystep/geometry/kernels.h"
#include "raystep/scene/scene_loader.h"

#include <benchmark/benchmark.h>

namespace {

using namespace raystep;
using D3 = glm::dvec3;

constexpr int kPairs = 4096;

template <typename T>
struct TrianglePairs {
    std::vector<TVec3<T>> o, d, a, b, c;
};

/// Triangles of the stadium's knot, each with a ray aimed near its centroid.
template <typename T>
const TrianglePairs<T>& trianglePairs() {
    static const TrianglePairs<T> pairs = [] {
        const Scene s = loadBuiltinScene("stadium");
        TrianglePairs<T> p;
        Pcg32 rng(3, 3);
        for (int i = 0; i < kPairs; ++i) {
            const Triangle& t = s.triangles[static_cast<std::size_t>(rng.uniform() * 51200)];
            const D3 centroid = (t.a + t.b + t.c) / 3.0;
            const D3 jitter =
                (D3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5) * glm::length(t.b - t.a);
            const D3 origin = centroid + D3(rng.uniform() - 0.5, rng.uniform() - 0.5, 1.0) * 5.0;
            p.o.push_back(TVec3<T>(origin));
            p.d.push_back(TVec3<T>(centroid + jitter - origin));
            p.a.push_back(TVec3<T>(t.a));
            p.b.push_back(TVec3<T>(t.b));
            p.c.push_back(TVec3<T>(t.c));
        }
        return p;
    }();
    return pairs;
}

template <typename T>
void BM_Triangle(benchmark::State& state) {
    const auto method = static_cast<TriangleMethod>(state.range(0));
    const int reuseMask = ~(static_cast<int>(state.range(1)) - 1);
    const TrianglePairs<T>& p = trianglePairs<T>();
    std::int64_t hits = 0;
    for (auto _ : state) {
        for (int i = 0; i < kPairs; ++i) {
            const int r = i & reuseMask;
            const auto h = intersectTriangle<T>(method, p.o[r], p.d[r], p.a[i], p.b[i], p.c[i],
                                                T(0), std::numeric_limits<T>::infinity());
            hits += h.has_value();
            benchmark::DoNotOptimize(h);
        }
    }
    state.SetItemsProcessed(state.iterations() * kPairs);
    state.SetLabel(std::string(name(method)) + " hit share " +
                   std::to_string(double(hits) / double(state.iterations() * kPairs)).substr(0, 4));
}
BENCHMARK(BM_Triangle<float>)
    ->ArgsProduct({{0, 1, 2}, {1, 16}})
    ->ArgNames({"method", "rays_reused"});
BENCHMARK(BM_Triangle<double>)
    ->ArgsProduct({{0, 1, 2}, {1, 16}})
    ->ArgNames({"method", "rays_reused"});

template <typename T>
void BM_Sphere(benchmark::State& state) {
    const auto method = static_cast<SphereMethod>(state.range(0));
    std::vector<TVec3<T>> o, d, c;
    Pcg32 rng(4, 4);
    for (int i = 0; i < kPairs; ++i) {
        const D3 centre(rng.uniform() * 10, rng.uniform() * 10, 20 + rng.uniform() * 10);
        o.push_back(TVec3<T>(0));
        d.push_back(TVec3<T>(centre + (D3(rng.uniform(), rng.uniform(), 0) - 0.5) * 2.8));
        c.push_back(TVec3<T>(centre));
    }
    std::int64_t hits = 0;
    for (auto _ : state) {
        for (int i = 0; i < kPairs; ++i) {
            const auto t = intersectSphere<T>(method, o[i], d[i], c[i], T(1), T(0),
                                              std::numeric_limits<T>::infinity());
            hits += t.has_value();
            benchmark::DoNotOptimize(t);
        }
    }
    state.SetItemsProcessed(state.iterations() * kPairs);
    state.SetLabel(std::string(name(method)) + " hit share " +
                   std::to_string(double(hits) / double(state.iterations() * kPairs)).substr(0, 4));
}
BENCHMARK(BM_Sphere<float>)->DenseRange(0, 1)->ArgName("method");
BENCHMARK(BM_Sphere<double>)->DenseRange(0, 1)->ArgName("method");

}  // namespace

BENCHMARK_MAIN();
