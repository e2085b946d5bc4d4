#pragma once
// Internal to assess/: a student's ray grouped unit by unit as the reference's, and the first
// place where it departs from the reference, explained (divergence.cpp).
#include "raystep/assess/assess.h"

#include <optional>
#include <vector>

namespace raystep::assess_detail {

/// A student's double arithmetic in another order: times agree to this relative tolerance.
constexpr double kTimeTolerance = 1e-9;
bool sameTime(double a, double b);

/// The student's records of one ray, unit by unit as the reference's.
struct StudentUnit {
    const StudentRecord* walk = nullptr;  // the cell or node (nullptr: tests before any)
    std::vector<const StudentRecord*> tests;
};
struct StudentRun {
    std::vector<StudentUnit> units;
    const StudentRecord* end = nullptr;  // the hit or miss
    bool logsWalk = false, logsTests = false;
};
StudentRun group(const StudentRay& ray);

/// What a student's file logs: its cells or nodes, its tests (what it does not log is not
/// checked).
struct Logged {
    bool walk = false, tests = false;
};

/// The student's ray and the grid in N dimensions (a Reference keeps its grid in 3).
template <int N>
struct RayOnGrid {
    GridSpec<N, double> grid;
    VecN<N, double> o, d;
};
template <int N>
RayOnGrid<N> onGrid(const GridSpec<3, double>& grid3, const StudentRay& ray) {
    RayOnGrid<N> r;
    for (int a = 0; a < N; ++a) {
        r.grid.lo[a] = grid3.lo[a];
        r.grid.hi[a] = grid3.hi[a];
        r.grid.res[a] = grid3.res[a];
        r.o[a] = ray.origin[a];
        r.d[a] = ray.dir[a];
    }
    return r;
}

/// Where `ray` first departs from `ref`, raystep's run of it, explained in `lang`; nullopt when
/// it does not. `logged`: what the file logs (on any of its rays), so a ray that logs no cell is
/// checked for none when the others log theirs.
std::optional<Divergence> firstDivergence(const Reference& reference, const StudentRay& ray,
                                          const ReferenceRay& ref, Language lang,
                                          const Logged& logged);

}  // namespace raystep::assess_detail
