// The grid sweep: one grid per resolution over the same rays, timing the build and the walk and
// counting what the rays paid (the lesson on voxel size).
#include "course/grid_sweep.h"

#include "raystep/accel/accel.h"
#include "raystep/base/math.h"

#include <chrono>
#include <cmath>

namespace raystep {

std::vector<GridSweepRow> runGridSweep(const std::variant<Scene, Scene2D>& scene,
                                       const GridSweepSpec& spec, const ProgressFn& progress) {
    std::vector<GridSweepRow> rows;
    const auto* s3 = std::get_if<Scene>(&scene);
    const auto* s2 = std::get_if<Scene2D>(&scene);
    for (std::size_t k = 0; k < spec.resolutions.size(); ++k) {
        if (progress && !progress(static_cast<double>(k) / spec.resolutions.size()))
            throw BuildCancelled();
        const int res = spec.resolutions[k];
        AccelOptions o;
        o.grid.res = std::array<int, 3>{res, res, s3 ? res : 1};
        GridSweepRow row;
        row.resolution = res;
        TraversalCounters c;
        std::uint64_t rays = 0;
        const auto t0 = std::chrono::steady_clock::now();
        std::chrono::steady_clock::time_point t1;
        if (s3) {
            const Accelerator accel = buildAccelerator(*s3, AccelKind::Grid, {}, o);
            t1 = std::chrono::steady_clock::now();
            const BuildSummary sum = summarize(accel);
            row.cells = sum.stats.nodes;
            row.references = sum.stats.references;
            for (int y = 0; y < spec.height; ++y)
                for (int x = 0; x < spec.width; ++x, ++rays)
                    intersect(accel,
                              s3->camera.generateRay(x + 0.5, y + 0.5, spec.width, spec.height), c);
        } else {
            // 2D: a fan of rays from the example ray's origin (or the scene's corner).
            const Accelerator2D accel = buildAccelerator2D(*s2, AccelKind::Grid, o);
            t1 = std::chrono::steady_clock::now();
            const BuildSummary sum = summarize(accel);
            row.cells = sum.stats.nodes;
            row.references = sum.stats.references;
            const Vec2 origin = s2->exampleRay ? s2->exampleRay->origin : s2->bounds().lo;
            const int n = spec.width * spec.height;
            for (int i = 0; i < n; ++i, ++rays) {
                const double a = 2.0 * kPi * (i + 0.5) / n;
                const Ray2 ray{origin, Vec2(std::cos(a), std::sin(a))};
                std::visit([&](const auto& g) { g.intersect(ray, c); }, accel);
            }
        }
        const auto t2 = std::chrono::steady_clock::now();
        row.buildMs = std::chrono::duration<double, std::milli>(t1 - t0).count();
        row.traceMs = std::chrono::duration<double, std::milli>(t2 - t1).count();
        row.testsPerRay = static_cast<double>(c.primitiveTests) / rays;
        row.cellsPerRay = static_cast<double>(c.nodeVisits) / rays;
        row.skipsPerRay = static_cast<double>(c.mailboxSkips) / rays;
        rows.push_back(row);
    }
    if (progress) progress(1.0);
    return rows;
}

}  // namespace raystep
