#pragma once
// The slides' DDA as the lecture writes it (Amanatides & Woo's loop, `tMaxX += tDeltaX`), in
// floating point and drifting as that loop does: for lessons and tests to set beside the exact
// walk of dda.h, which the grid uses.
#include "raystep/accel/dda.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace raystep {

/// One cell of the textbook walk: a row of the lecture's table.
template <int N, typename T = double>
struct TextbookCell {
    IVecN<N> cell;    // X, Y (, Z)
    VecN<N, T> tMax;  // tMaxX, tMaxY (, tMaxZ) in this cell, as accumulated so far
};

namespace detail {

/// The slides' set-up of one axis, at the point where the ray enters the grid.
template <typename T>
struct TextbookAxis {
    int X = 0;  // the first cell along this axis
    int step = 0;
    T tMax = std::numeric_limits<T>::infinity();
    T tDelta = std::numeric_limits<T>::infinity();
    int justOut = 0;  // the cell index just outside the grid, where the walk stops
};

/// Where the ray enters the grid's box (t >= 0), by the slab test in T; false if it misses,
/// touches only, or has a coordinate that is not finite.
template <int N, typename T>
bool textbookEntry(const GridSpec<N, T>& grid, const VecN<N, T>& o, const VecN<N, T>& d,
                   T& tEnter) {
    T tExit = std::numeric_limits<T>::infinity();
    tEnter = T(0);
    for (int i = 0; i < N; ++i) {
        if (!(std::isfinite(o[i]) && std::isfinite(d[i]) && grid.res[i] > 0)) return false;
        if (d[i] == T(0)) {
            if (o[i] < grid.lo[i] || o[i] > grid.hi[i]) return false;
            continue;
        }
        T t0 = (grid.lo[i] - o[i]) / d[i], t1 = (grid.hi[i] - o[i]) / d[i];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tExit = std::min(tExit, t1);
    }
    return tEnter < tExit;
}

/// X = the cell holding o + tEnter d; stepX = sign of dx; tMaxX = the crossing of the next
/// boundary; tDeltaX = VSizeX / |dx|.
template <int N, typename T>
TextbookAxis<T> textbookAxis(const GridSpec<N, T>& grid, int axis, const VecN<N, T>& o,
                             const VecN<N, T>& d, T tEnter) {
    TextbookAxis<T> a;
    const T size = grid.cellSize(axis);
    const T p = o[axis] + tEnter * d[axis];
    a.X = int(std::clamp(std::floor((p - grid.lo[axis]) / size), T(0), T(grid.res[axis] - 1)));
    a.step = d[axis] > T(0) ? 1 : (d[axis] < T(0) ? -1 : 0);
    a.justOut = a.step > 0 ? grid.res[axis] : -1;
    if (a.step == 0) return a;  // parallel: never crosses a boundary of this axis
    a.tMax = (grid.lo[axis] + T(a.X + (a.step > 0 ? 1 : 0)) * size - o[axis]) / d[axis];
    a.tDelta = size / std::abs(d[axis]);
    return a;
}

}  // namespace detail

/// The slides' 2D DDA: the cells the ray o + t d (t >= 0) visits on `grid`, each with its tMaxX,
/// tMaxY. Steps X when tMaxX < tMaxY, else Y (an exact tie steps Y only), and accumulates
/// tMax += tDelta: long walks drift (see Dda in dda.h for the exact walk).
template <typename T = double>
std::vector<TextbookCell<2, T>> ddaTextbook(const GridSpec<2, T>& grid, const VecN<2, T>& o,
                                            const VecN<2, T>& d) {
    std::vector<TextbookCell<2, T>> cells;
    T tEnter;
    if (!detail::textbookEntry<2, T>(grid, o, d, tEnter)) return cells;
    auto [X, stepX, tMaxX, tDeltaX, justOutX] = detail::textbookAxis<2, T>(grid, 0, o, d, tEnter);
    auto [Y, stepY, tMaxY, tDeltaY, justOutY] = detail::textbookAxis<2, T>(grid, 1, o, d, tEnter);
    for (;;) {
        cells.push_back({{X, Y}, {tMaxX, tMaxY}});
        if (std::isinf(std::min(tMaxX, tMaxY))) break;  // no boundary ahead (a zero direction)
        if (tMaxX < tMaxY) {
            X += stepX;
            if (X == justOutX) break;
            tMaxX += tDeltaX;
        } else {
            Y += stepY;
            if (Y == justOutY) break;
            tMaxY += tDeltaY;
        }
    }
    return cells;
}

/// The slides' 3D DDA (Amanatides & Woo's loop, the smallest tMax stepping): the cells the ray
/// o + t d (t >= 0) visits on `grid`, each with its tMaxX, tMaxY, tMaxZ, in floating point.
template <typename T = double>
std::vector<TextbookCell<3, T>> ddaTextbook(const GridSpec<3, T>& grid, const VecN<3, T>& o,
                                            const VecN<3, T>& d) {
    std::vector<TextbookCell<3, T>> cells;
    T tEnter;
    if (!detail::textbookEntry<3, T>(grid, o, d, tEnter)) return cells;
    auto [X, stepX, tMaxX, tDeltaX, justOutX] = detail::textbookAxis<3, T>(grid, 0, o, d, tEnter);
    auto [Y, stepY, tMaxY, tDeltaY, justOutY] = detail::textbookAxis<3, T>(grid, 1, o, d, tEnter);
    auto [Z, stepZ, tMaxZ, tDeltaZ, justOutZ] = detail::textbookAxis<3, T>(grid, 2, o, d, tEnter);
    for (;;) {
        cells.push_back({{X, Y, Z}, {tMaxX, tMaxY, tMaxZ}});
        if (std::isinf(std::min({tMaxX, tMaxY, tMaxZ}))) break;  // no boundary ahead
        if (tMaxX < tMaxY) {
            if (tMaxX < tMaxZ) {
                X += stepX;
                if (X == justOutX) break;
                tMaxX += tDeltaX;
            } else {
                Z += stepZ;
                if (Z == justOutZ) break;
                tMaxZ += tDeltaZ;
            }
        } else {
            if (tMaxY < tMaxZ) {
                Y += stepY;
                if (Y == justOutY) break;
                tMaxY += tDeltaY;
            } else {
                Z += stepZ;
                if (Z == justOutZ) break;
                tMaxZ += tDeltaZ;
            }
        }
    }
    return cells;
}

}  // namespace raystep
