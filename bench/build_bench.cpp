// Build time against N (the SAH kd-tree's O(N log N), the BVH for comparison) and the price of
// recording: bytes per event and the slowdown of a traced ray. Run: build/bench/raystep_bench_build
// (scripts/measure_build.sh plots the scaling into docs/images/build-scaling.png).
#include "meshes.h"
#include "raystep/accel/accel.h"
#include "raystep/accel/outline.h"
#include "raystep/render/tracer.h"
#include "raystep/scene/scene_loader.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <vector>

namespace {

using namespace raystep;

/// The knot tessellated with `around` quads around the tube and 4 x around along it: the
/// triangles keep their shape as N = 8 around^2 grows.
const Scene& knot(int around) {
    static std::map<int, Scene> cache;
    auto it = cache.find(around);
    if (it == cache.end()) it = cache.emplace(around, bench::knotScene(4 * around, around)).first;
    return it->second;
}

/// One kd-tree build per iteration, with its rate, node count and SAH cost as counters.
void kdTreeBuild(benchmark::State& state, const KdTreeOptions& options) {
    const Scene& s = knot(static_cast<int>(state.range(0)));
    std::uint32_t nodes = 0;
    double sah = 0.0;
    for (auto _ : state) {
        const KdTree3 t(ScenePrims(s, {}), options);
        nodes = t.stats().nodes;
        sah = t.stats().sahCost;
        benchmark::DoNotOptimize(nodes);
    }
    state.counters["N"] = static_cast<double>(s.triangles.size());
    state.counters["Mtris/s"] = benchmark::Counter(static_cast<double>(s.triangles.size()) * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate);
    state.counters["nodes"] = nodes;
    state.counters["sah"] = sah;
}

// Arg: quads around the tube; N = 8 around^2 triangles, from 968 to 1,048,352 by fours.
void BM_KdTreeSahBuild(benchmark::State& state) {
    kdTreeBuild(state, KdTreeOptions{});
}
// The same with --kd-build fast: 16-32 bins at every node, perfect splits, all cores
// (timed on the wall clock: UseRealTime below).
void BM_KdTreeFastBuild(benchmark::State& state) {
    KdTreeOptions o;
    o.build = KdBuild::Fast;
    kdTreeBuild(state, o);
}
void BM_BvhSahBuild(benchmark::State& state) {
    const Scene& s = knot(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        const Bvh3 b(ScenePrims(s, {}), BvhOptions{});
        benchmark::DoNotOptimize(b.stats().nodes);
    }
    state.counters["N"] = static_cast<double>(s.triangles.size());
    state.counters["Mtris/s"] = benchmark::Counter(static_cast<double>(s.triangles.size()) * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate);
}
/// The knot sizes every build benchmark runs: 968 to 1,048,352 triangles, one build each.
void knotSizes(benchmark::internal::Benchmark* b) {
    for (const int around : {11, 23, 45, 91, 181, 362}) b->Arg(around);
    b->Unit(benchmark::kMillisecond)->Iterations(1);
}
/// The same, each size built five times, reported as the median and the extremes (for Mtris/s
/// "min" is the slowest build): one build on a shared VM is a sample of its neighbours' load as
/// much as of the code. The exact kd build (11-18 s at 1M) stays at one.
void knotSizesFiveTimes(benchmark::internal::Benchmark* b) {
    knotSizes(b);
    b->Repetitions(5)->ReportAggregatesOnly(true);
    b->ComputeStatistics(
        "min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
    b->ComputeStatistics(
        "max", [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); });
}
/// The outline a view draws a structure from (boxes only), against the one a practice prompt
/// reads (each leaf's primitive ids too): on the 181-around knot's fast kd-tree (262k triangles).
void outlineOfKnot(benchmark::State& state, OutlineDetail detail) {
    static const Accelerator tree = [] {
        AccelOptions o;
        o.kdtree.build = KdBuild::Fast;
        return buildAccelerator(knot(181), AccelKind::KdTree, {}, o);
    }();
    std::size_t ids = 0;
    for (auto _ : state) {
        const StructureOutline<3> o = outline(tree, detail);
        ids = o.leafPrimitives.size();
        benchmark::DoNotOptimize(o.nodes.data());
    }
    state.counters["leafIds"] = static_cast<double>(ids);
}
void BM_Outline_Boxes(benchmark::State& state) {
    outlineOfKnot(state, OutlineDetail::Boxes);
}
void BM_Outline_Primitives(benchmark::State& state) {
    outlineOfKnot(state, OutlineDetail::Primitives);
}

BENCHMARK(BM_KdTreeSahBuild)->Apply(knotSizes);
BENCHMARK(BM_KdTreeFastBuild)->Apply(knotSizesFiveTimes)->UseRealTime();
BENCHMARK(BM_BvhSahBuild)->Apply(knotSizesFiveTimes);
BENCHMARK(BM_Outline_Boxes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Outline_Primitives)->Unit(benchmark::kMillisecond);

// Recording: the same pixels of the default scene traced with recording off (NullRecorder: the
// hooks are discarded at compile time) and on (every event kept in an EventLog).
void tracePixels(benchmark::State& state, AccelKind kind, bool record) {
    static const Scene s = loadBuiltinScene("default");
    const Accelerator accel = buildAccelerator(s, kind);
    RenderOptions opt;
    opt.width = 160;
    opt.height = 120;
    opt.trace.bounces = 3;
    const Tracer tracer(s, accel, opt.trace);
    EventLog log;
    std::uint64_t events = 0, rays = 0;
    for (auto _ : state) {
        for (int y = 0; y < opt.height; ++y)
            for (int x = 0; x < opt.width; ++x) {
                RayCounters c;
                if (record) {
                    log.clear();
                    tracer.renderPixel(x, y, opt, c, log);
                    events += log.events().size();
                } else {
                    benchmark::DoNotOptimize(tracer.renderPixel(x, y, opt, c));
                }
                rays += c.totalRays();
            }
    }
    state.counters["Mrays/s"] = benchmark::Counter(rays * 1e-6, benchmark::Counter::kIsRate);
    if (record) {
        state.counters["events/ray"] = static_cast<double>(events) / rays;
        state.counters["bytes/event"] = sizeof(Event);
    }
}
void BM_Trace_Grid_RecordingOff(benchmark::State& s) {
    tracePixels(s, AccelKind::Grid, false);
}
void BM_Trace_Grid_RecordingOn(benchmark::State& s) {
    tracePixels(s, AccelKind::Grid, true);
}
void BM_Trace_KdTree_RecordingOff(benchmark::State& s) {
    tracePixels(s, AccelKind::KdTree, false);
}
void BM_Trace_KdTree_RecordingOn(benchmark::State& s) {
    tracePixels(s, AccelKind::KdTree, true);
}
void BM_Trace_Bvh_RecordingOff(benchmark::State& s) {
    tracePixels(s, AccelKind::Bvh, false);
}
void BM_Trace_Bvh_RecordingOn(benchmark::State& s) {
    tracePixels(s, AccelKind::Bvh, true);
}
BENCHMARK(BM_Trace_Grid_RecordingOff)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Trace_Grid_RecordingOn)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Trace_KdTree_RecordingOff)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Trace_KdTree_RecordingOn)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Trace_Bvh_RecordingOff)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Trace_Bvh_RecordingOn)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
