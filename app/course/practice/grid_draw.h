#pragma once
// What the grid topics share (dda.cpp, mailbox.cpp): a uniform grid and a 2D or 3D ray with
// numbers a student works by hand, the grid's corner markers, the data in words, and whether a
// recorded walk is one to do by hand (no near tie a rounding could decide either way).
#include "course/practice/generator.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace raystep::practice {

template <int N>
struct DdaData {
    std::array<int, N> res{};
    std::array<double, N> lo{}, hi{}, o{}, d{};
    double cell = 1.0;
};

/// Coordinates are drawn in whole hundredths and divided once, so 0.9 is the double nearest
/// 0.9 (the one a student types), not 0.1 + 0.8 rounded twice.
inline double hundredths(long v) {
    return static_cast<double>(v) / 100.0;
}

template <int N>
DdaData<N> drawDda(Random& r, PracticeLevel level) {
    const bool easy = level == PracticeLevel::Easy, hard = level == PracticeLevel::Hard;
    DdaData<N> g;
    // The cell in hundredths: 1, 0.5 or 2.
    long cell = easy ? 100 : r.pick(std::vector<long>{100, 100, 50, 200});
    if (hard) cell = r.pick(std::vector<long>{100, 50});
    g.cell = hundredths(cell);
    // Reciprocals that are short decimals; at hard, exact in binary so a drawn tie is exact.
    const std::vector<double> dirs = hard
                                         ? std::vector<double>{0.25, 0.5, 1.0, 2.0}
                                         : std::vector<double>{0.25, 0.4, 0.5, 0.8, 1.0, 1.25, 2.0};
    // Where in its cell the origin lies, in hundredths of the cell: never on a boundary.
    const std::vector<long> fracs = hard ? std::vector<long>{25, 50, 75}
                                         : std::vector<long>{10, 20, 30, 40, 50, 60, 70, 80, 90};
    std::array<long, N> lo{}, o{};
    for (int a = 0; a < N; ++a) {
        g.res[a] = N == 2 ? r.between(easy ? 3 : 4, easy ? 5 : 6) : r.between(easy ? 2 : 3, 4);
        lo[a] = easy ? 0 : cell * r.between(-2, 2);
        g.d[a] = r.pick(dirs) * (easy ? 1 : r.sign());
        o[a] = lo[a] + cell * r.between(0, g.res[a] - 1) + cell * r.pick(fracs) / 100;
    }
    if (hard) {
        // Through a vertex inside the grid: o = V - s d, with s a multiple of a quarter cell so
        // o stays in whole hundredths.
        const long s = cell * r.pick(std::vector<long>{2, 4, 6, 8, 12}) / 4;
        for (int a = 0; a < N; ++a) {
            const long v = lo[a] + cell * r.between(1, g.res[a] - 1);
            o[a] = v - static_cast<long>(std::lround(static_cast<double>(s) * g.d[a]));
        }
    }
    if (!easy && r.chance(50)) {
        // From outside, through one face: the ray then enters the grid there first.
        const int a = r.between(0, N - 1);
        const long out = cell * r.between(0, 1) + cell * r.pick(fracs) / 100;
        o[a] = g.d[a] > 0 ? lo[a] - out : lo[a] + cell * g.res[a] + out;
    }
    for (int a = 0; a < N; ++a) {
        g.lo[a] = hundredths(lo[a]);
        g.hi[a] = hundredths(lo[a] + cell * g.res[a]);
        g.o[a] = hundredths(o[a]);
    }
    return g;
}

inline std::vector<double> asVec(const auto& a) {
    return std::vector<double>(a.begin(), a.end());
}

template <int N>
std::string gridWords(const DdaData<N>& g, bool it) {
    std::string cells, size;
    for (int a = 0; a < N; ++a) {
        cells += (a ? " x " : "") + std::to_string(g.res[a]);
        size += (a ? " x " : "") + num(g.cell, it);
    }
    const std::string box = "`min = " + vec(asVec(g.lo)) + "`" + (it ? " a " : " to ") +
                            "`max = " + vec(asVec(g.hi)) + "`";
    const std::string ray = "`o = " + vec(asVec(g.o)) + "`, `d = " + vec(asVec(g.d)) + "`";
    if (it)
        return "Il raggio " + ray + " e una griglia uniforme di " + cells + " celle da " + box +
               ", celle di " + size + ".";
    return "The ray " + ray + " and a uniform grid of " + cells + " cells from " + box +
           ", cells of " + size + ".";
}

template <int N>
ojson markers(const DdaData<N>& g) {
    // Two markers whose bounds are the grid's corners, exactly (cell / 8 is exact in binary).
    const double rad = g.cell / 8;
    std::array<double, N> a{}, b{};
    for (int k = 0; k < N; ++k) {
        a[k] = g.lo[k] + rad;
        b[k] = g.hi[k] - rad;
    }
    ojson scene;
    if constexpr (N == 2) {
        scene["dimensions"] = 2;
        scene["description"] = "practice: a uniform grid marked by two corner circles";
        scene["grid"] = {g.res[0], g.res[1]};
        scene["circles"] = {{{"center", jsonVec(asVec(a))}, {"radius", rad}},
                            {{"center", jsonVec(asVec(b))}, {"radius", rad}}};
    } else {
        std::array<double, 3> c{}, e{};
        double extent = 0;
        for (int k = 0; k < 3; ++k) {
            c[k] = (g.lo[k] + g.hi[k]) / 2;
            extent = std::max(extent, g.hi[k] - g.lo[k]);
        }
        e = {c[0] + 1.3 * extent, c[1] + 1.0 * extent, c[2] + 2.0 * extent};
        scene["description"] = "practice: a uniform grid marked by two corner spheres";
        scene["camera"] = {{"eye", jsonVec(asVec(e))}, {"look_at", jsonVec(asVec(c))}};
        scene["lights"] = {{{"position", jsonVec(asVec(e))}}};
        scene["objects"] = {{{"type", "sphere"}, {"center", jsonVec(asVec(a))}, {"radius", rad}},
                            {{"type", "sphere"}, {"center", jsonVec(asVec(b))}, {"radius", rad}}};
    }
    return scene;
}

/// Every axis at one speed makes every tDelta one number and every step a tie.
template <int N>
bool oneSpeed(const DdaData<N>& g) {
    for (int a = 1; a < N; ++a)
        if (std::abs(g.d[a]) != std::abs(g.d[0])) return false;
    return true;
}

/// The walk starts off every grid line: the origin (inside) or the entry point (from outside),
/// but at hard, where a ray may come in through a vertex.
template <int N>
bool startFits(const DdaData<N>& g, PracticeLevel level) {
    double tEnter = 0.0;
    for (int a = 0; a < N; ++a) {
        const double t = ((g.d[a] > 0 ? g.lo[a] : g.hi[a]) - g.o[a]) / g.d[a];
        tEnter = std::max(tEnter, t);
    }
    for (int a = 0; a < N; ++a) {
        const double p = g.o[a] + tEnter * g.d[a];
        const double along = (p - g.lo[a]) / g.cell;
        const bool entryAxis = tEnter > 0 && std::abs(along - std::round(along)) < 1e-9 &&
                               (std::round(along) == 0 || std::round(along) == g.res[a]);
        if (entryAxis) continue;
        if (std::abs(along - std::round(along)) < 0.05 &&
            (tEnter == 0 || level != PracticeLevel::Hard))
            return false;
    }
    return true;
}

/// What a recorded walk looks like to a student doing it by hand.
struct WalkShape {
    int cells = 0;         // dda_cell events
    int ties = 0;          // cells after the first entered by stepping two axes at once
    bool hit = false;      // a ray_hit ends the trace
    bool readable = true;  // no two crossings within 0.05 (nor equal, unless ties are allowed)
};

/// The walk of the log's ray: its cells, its ties, and whether it can be done by hand: every
/// tMax comparison decided by more than 0.05 (or an exact tie, where `ties` allows them), the
/// first cell entered neither through a vertex nor within 0.05 of a boundary.
template <int N>
WalkShape walkShape(const EventLog& log, bool ties) {
    WalkShape w;
    double tEnter = 0;
    for (const Event& e : log.events()) {
        if (std::holds_alternative<RayHit>(e)) w.hit = true;
        if (const auto* s = std::get_if<DdaSetup>(&e)) tEnter = s->tEnter;
        const auto* c = std::get_if<DdaCell>(&e);
        if (!c) continue;
        ++w.cells;
        const bool twoAxes = std::popcount(static_cast<unsigned>(c->axes)) > 1;
        if (twoAxes && w.cells > 1) ++w.ties;
        if (w.cells == 1 && twoAxes) w.readable = false;
        std::array<double, N> t{};
        for (int a = 0; a < N; ++a) t[a] = c->tMax[a];
        std::sort(t.begin(), t.end());
        const double gap = t[1] - t[0];
        if (gap != 0.0 && gap < 0.05) w.readable = false;
        if (gap == 0.0 && !ties) w.readable = false;
        if (w.cells == 1 && t[0] - tEnter < 0.05) w.readable = false;  // next to a boundary
    }
    return w;
}

}  // namespace raystep::practice
