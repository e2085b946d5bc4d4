// The replay app's speed (issue 5): redrawing the 2D view while scrubbing a log of a million
// events, and the time to a first painted window. Needs an X server: run under xvfb-run -a.
// Run: xvfb-run -a build/bench/raystep_bench_gui
#include "image_view.h"
#include "main_window.h"
#include "view2d.h"

#include "raystep/scene/scene_loader.h"

#include <benchmark/benchmark.h>
#include <QApplication>
#include <QElapsedTimer>

#include <random>

namespace {

using namespace raystep;
using namespace raystep::gui;

/// 20,000 random segments: a 2D scene whose SAH kd-tree build records over a million events.
Scene2D manySegments() {
    Scene2D s;
    s.name = "20k-segments";
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const Vec2 p(100 * u(rng), 60 * u(rng));
        s.segments.push_back({p, p + Vec2(2 * u(rng) - 1, 2 * u(rng) - 1)});
    }
    return s;
}

// Scrubbing: a jump to a random cursor of a one-million-event log (the build's replay: node,
// candidates, choice), then the 2D view and the inspector repainted, as on every cursor move.
void BM_ScrubMillionEvents(benchmark::State& state) {
    MainWindow w;
    w.resize(1500, 900);
    w.show();
    AccelOptions o;
    w.session().load(manySegments(), AccelKind::KdTree, o);
    w.session().recordBuild();
    Session& s = w.session();
    std::mt19937 rng(3);
    std::uniform_int_distribution<std::size_t> pick(0, s.size());
    QApplication::processEvents();
    for (auto _ : state) {
        s.setCursor(pick(rng));
        w.view2D()->repaint();
        QApplication::processEvents();
    }
    state.counters["events"] = static_cast<double>(s.size());
    state.counters["frames/s"] =
        benchmark::Counter(state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ScrubMillionEvents)->Unit(benchmark::kMillisecond)->UseRealTime();

// From constructing the window to its first frame painted with what it opens on: lesson 1 (its
// scene loaded, its pixel traced; the image keeps rendering in the background).
void BM_FirstFrame(benchmark::State& state) {
    for (auto _ : state) {
        QElapsedTimer t;
        t.start();
        MainWindow w;
        w.resize(1500, 900);
        w.openLesson("1", true);
        w.show();
        // The lesson opens in the background: the frame that counts shows it.
        while (!w.lastOpenOk().has_value())
            QApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents, 5);
        w.repaint();
        QApplication::processEvents();
        benchmark::DoNotOptimize(w.grab());
        state.SetIterationTime(t.nsecsElapsed() * 1e-9);
        w.tasks().shutdown();  // the image keeps rendering otherwise
    }
}
BENCHMARK(BM_FirstFrame)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(5);

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("raystep-bench");
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    return 0;
}
