#pragma once
// Vector types and the few helpers the whole core shares.
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace raystep {

using Vec3 = glm::dvec3;
// The 2D and 3D templates' vectors (a 2D lesson's grid and the 3D scene's share one DDA).
template <int N>
using IVecN = glm::vec<N, int, glm::defaultp>;
template <int N, typename T>
using VecN = glm::vec<N, T, glm::defaultp>;
using Color = glm::dvec3;  // linear RGB radiance

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

inline double maxComponent(const Vec3& v) {
    return std::max({v.x, v.y, v.z});
}
inline double maxAbsComponent(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}
inline bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool isBlack(const Color& c) {
    return c.x <= 0.0 && c.y <= 0.0 && c.z <= 0.0;
}

/// Mirror direction d about the normal n (both need not face each other): d - 2 (d.n) n.
inline Vec3 reflect(const Vec3& d, const Vec3& n) {
    return d - 2.0 * glm::dot(d, n) * n;
}

/// Axis-aligned box in N dimensions.
template <int N>
struct BoxN {
    using V = glm::vec<N, double, glm::defaultp>;
    V lo{kInfinity};
    V hi{-kInfinity};

    // Always inlined: the builds call these in their innermost loops, and GCC left some calls.
    [[gnu::always_inline]] void extend(const V& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    [[gnu::always_inline]] void extend(const BoxN& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const {
        for (int i = 0; i < N; ++i)
            if (lo[i] > hi[i]) return true;
        return false;
    }
    V diagonal() const { return hi - lo; }
    V centroid() const { return 0.5 * (lo + hi); }
    /// The SAH's "area": the surface area in 3D; in 2D the perimeter (a random line meets a
    /// convex region with probability proportional to its perimeter, as a random ray meets a
    /// convex body in proportion to its surface).
    double area() const {
        const V d = glm::max(diagonal(), V(0.0));
        if constexpr (N == 3)
            return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
        else
            return 2.0 * (d.x + d.y);
    }
    int longestAxis() const {
        const V d = diagonal();
        int axis = 0;
        for (int i = 1; i < N; ++i)
            if (d[i] > d[axis]) axis = i;
        return axis;
    }
    BoxN clippedTo(const BoxN& b) const { return {glm::max(lo, b.lo), glm::min(hi, b.hi)}; }
    /// The two halves either side of the plane axis = pos (a kd-tree node's children).
    std::pair<BoxN, BoxN> splitAt(int axis, double pos) const {
        BoxN l = *this, r = *this;
        l.hi[axis] = pos;
        r.lo[axis] = pos;
        return {l, r};
    }
    /// Padded to three coordinates, for the event log's node table.
    std::array<double, 3> lo3() const { return pad(lo); }
    std::array<double, 3> hi3() const { return pad(hi); }

  private:
    static std::array<double, 3> pad(const V& v) {
        std::array<double, 3> a{0.0, 0.0, 0.0};
        for (int i = 0; i < N; ++i) a[i] = v[i];
        return a;
    }
};

/// The 3D box of the scene model (primitive and scene bounds).
using Bounds3 = BoxN<3>;

}  // namespace raystep
