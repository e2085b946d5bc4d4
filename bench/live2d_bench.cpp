// Live 2D editing (issue 19): one frame of a ray drag as the app makes it, on the lecture's
// scenes. A frame copies the scene with the ray's origin moved, builds its structure again,
// shows it with MainWindow::showLive (the walk, or the build when a build is replayed, recorded
// again at the same step) and repaints the 2D view. Target: 30 frames/s, 33 ms a frame.
// Needs an X server. Run: xvfb-run -a build/bench/raystep_bench_live2d
#include "live2d.h"
#include "main_window.h"
#include "view2d.h"

#include <benchmark/benchmark.h>
#include <QApplication>

namespace {

using namespace raystep;
using namespace raystep::gui;

void dragFrames(benchmark::State& state, const char* scene, AccelKind kind, bool build) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    w.openScene(scene, kind, /*quiet=*/true, {}, /*renderImage=*/false);
    if (!w.waitUntilIdle() || !w.lastOpenOk().value_or(false)) {
        state.SkipWithError("the scene did not open");
        return;
    }
    if (build) w.session().recordBuild();
    // The cursor in the middle of the walk (or build): relive keeps it at that step.
    w.session().setCursor(w.session().size() / 2);
    QApplication::processEvents();
    Live2D* live = w.live2D();
    const Scene2D start = *w.session().scene2D();
    live->begin("bench");
    long frame = 0;
    for (auto _ : state) {
        // A small circle of positions: every frame is a new ray.
        Scene2D s = start;
        const double a = 0.05 * static_cast<double>(frame++);
        s.exampleRay->origin += Vec2(0.3 * std::cos(a), 0.3 * std::sin(a));
        live->preview(s);
        w.view2D()->repaint();
        QApplication::processEvents();
    }
    live->end();
    state.counters["events"] = static_cast<double>(w.session().size());
    state.counters["frames/s"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_DragRay_LectureGrid(benchmark::State& state) {
    dragFrames(state, "lecture-grid", AccelKind::Grid, false);
}
void BM_DragRay_LectureKdTree(benchmark::State& state) {
    dragFrames(state, "lecture-kdtree", AccelKind::KdTree, false);
}
// Lesson 10's BVH: overlapping boxes by depth, drawn from the outline made with each build.
void BM_DragRay_LectureBvh(benchmark::State& state) {
    dragFrames(state, "lecture-kdtree", AccelKind::Bvh, false);
}
// Lesson 11: the kd-tree's build replayed while the scene changes (the build recorded again).
void BM_DragRay_LectureKdTreeBuildShown(benchmark::State& state) {
    dragFrames(state, "lecture-kdtree", AccelKind::KdTree, true);
}
BENCHMARK(BM_DragRay_LectureGrid)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DragRay_LectureKdTree)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DragRay_LectureBvh)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DragRay_LectureKdTreeBuildShown)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("raystep-bench");
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    return 0;
}
