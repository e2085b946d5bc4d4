// The wide BVH's traversal: a node's four boxes by one slab test in four lanes, the children hit
// visited nearest first, a leaf's triangles four at a time by the watertight test. Written once
// over the lane type F: simd::Float4 (SSE2 on x86-64) or simd::portable::Float4 (ARM64, and the
// tests' reference), which compute the same bits.
#include "raystep/fast/wide_bvh.h"

#include "raystep/base/simd.h"
#include "raystep/geometry/intersect.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace raystep {

namespace {

template <typename F>
F load4(const float* p) {
    if constexpr (std::is_same_v<F, simd::portable::Float4>)
        return simd::portable::load(p);
    else
        return simd::load(p);
}
template <typename F>
F splat4(float x) {
    if constexpr (std::is_same_v<F, simd::portable::Float4>)
        return simd::portable::splat(x);
    else
        return simd::splat(x);
}
template <typename F>
void store4(float* p, F x) {
    if constexpr (std::is_same_v<F, simd::portable::Float4>)
        simd::portable::store(p, x);
    else
        simd::store(p, x);
}

constexpr float kInf = std::numeric_limits<float>::infinity();

/// The next float toward +inf or -inf of a finite or infinite f (std::nextafter, inlined: it was
/// a library call per ray).
float nextToward(float f, bool up) {
    if (f == 0.0f)
        return up ? std::numeric_limits<float>::denorm_min()
                  : -std::numeric_limits<float>::denorm_min();
    if (std::isinf(f) && (f > 0) == up) return f;
    auto bits = std::bit_cast<std::uint32_t>(f);
    bits += ((f > 0) == up) ? 1 : -1;  // the magnitude grows on the side f is on
    return std::bit_cast<float>(bits);
}

/// A double bound as the float at or inside it (tMin up, tMax down): the float query never
/// reaches past the double one.
float innerLow(double x) {
    if (!(x > -double(std::numeric_limits<float>::max()))) return -kInf;
    if (x > double(std::numeric_limits<float>::max())) return kInf;
    float f = static_cast<float>(x);
    if (double(f) < x) f = nextToward(f, true);
    return f;
}
float innerHigh(double x) {
    if (!(x < double(std::numeric_limits<float>::max()))) return kInf;
    if (x < -double(std::numeric_limits<float>::max())) return -kInf;
    float f = static_cast<float>(x);
    if (double(f) > x) f = nextToward(f, false);
    return f;
}

/// One ray as the lanes want it: in float, with what the slab test and the shear precompute.
struct FloatRay {
    glm::vec3 o, d, inv;
    int nearLo[3];  // 1 if the near side of axis a is the box's low bound (d[a] >= +0)
    float tMin, tMax;
    // The watertight test's shear (Woop et al.): axes kx, ky, kz and Sx, Sy, Sz.
    int kx = 0, ky = 1, kz = 2;
    float sx = 0, sy = 0, sz = 0;
    bool triangles = true;  // false for a zero direction, which no triangle test accepts
};

FloatRay floatRay(const Ray& ray) {
    FloatRay r;
    r.o = glm::vec3(ray.origin);
    r.d = glm::vec3(ray.dir);
    for (int a = 0; a < 3; ++a) {
        r.inv[a] = 1.0f / r.d[a];  // +-inf on a +-0 component: the slab test's NaN is handled
        r.nearLo[a] = std::signbit(r.d[a]) ? 0 : 1;
    }
    r.tMin = innerLow(ray.tMin);
    r.tMax = innerHigh(ray.tMax);
    // The axis order and shear of intersectTriangleWatertight, once per ray.
    const glm::vec3 ad = glm::abs(r.d);
    r.kz = (ad.x > ad.y) ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    r.triangles = r.d[r.kz] != 0.0f;
    r.kx = (r.kz + 1) % 3;
    r.ky = (r.kx + 1) % 3;
    if (r.d[r.kz] < 0.0f) std::swap(r.kx, r.ky);
    r.sx = r.d[r.kx] / r.d[r.kz];
    r.sy = r.d[r.ky] / r.d[r.kz];
    r.sz = 1.0f / r.d[r.kz];
    return r;
}

/// The ray's slab-test values in all four lanes, set once per ray (not once per node).
template <typename F>
struct SlabLanes {
    F o[3], inv[3];
    int nearOffset[3], farOffset[3];  // floats from a node's start: lo[a] or hi[a]
    explicit SlabLanes(const FloatRay& r) {
        for (int a = 0; a < 3; ++a) {
            o[a] = splat4<F>(r.o[a]);
            inv[a] = splat4<F>(r.inv[a]);
            const int lo = 4 * a, hi = 12 + 4 * a;  // Node::lo[a], Node::hi[a]
            nearOffset[a] = r.nearLo[a] ? lo : hi;
            farOffset[a] = r.nearLo[a] ? hi : lo;
        }
    }
};
static_assert(offsetof(WideBvh::Node, hi) == 12 * sizeof(float));

/// A box's exit distance is widened by this (Ize 2013: no box lost to rounding); a child popped
/// from the stack is compared with the nearest hit widened the same, or it would be lost again.
constexpr float kWiden = 1.0f + 2.0f * gamma<float>(3);

/// The near hit of the four boxes: bit i set for child i, its entry distance in tNear.
template <typename F>
[[gnu::always_inline]] inline unsigned boxes4(const WideBvh::Node& n, const SlabLanes<F>& r, F tMin,
                                              float tHit, F& tNear) {
    const float* base = &n.lo[0][0];
    F t0[3], t1[3];
    for (int a = 0; a < 3; ++a) {
        t0[a] = (load4<F>(base + r.nearOffset[a]) - r.o[a]) * r.inv[a];
        t1[a] = (load4<F>(base + r.farOffset[a]) - r.o[a]) * r.inv[a];
    }
    // min and max return their second operand on a NaN (an origin on a slab's plane, parallel
    // to it: 0 * inf): that axis then sets no bound, as the ray runs along the box's face.
    tNear = max(t0[0], max(t0[1], max(t0[2], tMin)));
    const F tFar = min(t1[0], min(t1[1], min(t1[2], splat4<F>(tHit)))) * splat4<F>(kWiden);
    return bits(tNear <= tFar);
}

/// The watertight test of the four triangles of `b` that the ray may hit nearer than tHit. A
/// lane the float numbers cannot decide (an edge function exactly 0, a t within its own rounding)
/// is decided by intersectTriangleWatertight<float> itself, which widens to double.
template <typename F>
bool blockTest(const WideBvh::Block& b, const FloatRay& r, float& tHit, float& u, float& v,
               std::uint32_t& prim, TraversalCounters& counters) {
    // Empty lanes are the block's last ones (the build fills lanes in order).
    const unsigned used = b.prim[3] != WideBvh::kNoPrim   ? 4
                          : b.prim[2] != WideBvh::kNoPrim ? 3
                          : b.prim[1] != WideBvh::kNoPrim ? 2
                                                          : 1;
    const unsigned valid = (1u << used) - 1;
    counters.primitiveTests += used;
    const F ox = splat4<F>(r.o[r.kx]), oy = splat4<F>(r.o[r.ky]), oz = splat4<F>(r.o[r.kz]);
    const F sx = splat4<F>(r.sx), sy = splat4<F>(r.sy), sz = splat4<F>(r.sz);
    F x[3], y[3], z[3];
    for (int k = 0; k < 3; ++k) {
        const F px = load4<F>(b.v[k][r.kx]) - ox, py = load4<F>(b.v[k][r.ky]) - oy,
                pz = load4<F>(b.v[k][r.kz]) - oz;
        x[k] = px - sx * pz;
        y[k] = py - sy * pz;
        z[k] = sz * pz;
    }
    const F U = x[2] * y[1] - y[2] * x[1];
    const F V = x[0] * y[2] - y[0] * x[2];
    const F W = x[1] * y[0] - y[1] * x[0];
    const F zero = splat4<F>(0.0f);
    const unsigned onEdge = bits((U == zero) | (V == zero) | (W == zero)) & valid;
    const auto outside =
        ((U < zero) | (V < zero) | (W < zero)) & ((U > zero) | (V > zero) | (W > zero));
    const F det = U + V + W;
    // Signs agree, and the triangle is not seen edge-on (det 0) nor beyond float (det inf, NaN).
    unsigned inside = bits(andNot(outside | (det == zero), abs(det) < splat4<F>(kInf)));
    inside &= valid & ~onEdge;
    unsigned undecided = onEdge;
    bool found = false;
    if (inside) {
        // t = (U az + V bz + W cz) / det and its rounding bound, as distanceWithBound computes.
        const F invDet = splat4<F>(1.0f) / det;
        const F t = (U * z[0] + V * z[1] + W * z[2]) * invDet;
        const unsigned inRange = bits((splat4<F>(r.tMin) < t) & (t < splat4<F>(tHit))) & inside;
        if (inRange) {
            const F maxX = max(abs(x[0]), max(abs(x[1]), abs(x[2])));
            const F maxY = max(abs(y[0]), max(abs(y[1]), abs(y[2])));
            const F maxZ = max(abs(z[0]), max(abs(z[1]), abs(z[2])));
            const F shear = splat4<F>(gamma<float>(7) * (1.0f + gamma<float>(4)));
            const F g2 = splat4<F>(gamma<float>(2)), g3 = splat4<F>(gamma<float>(3)),
                    g5 = splat4<F>(gamma<float>(5));
            const F deltaX = g5 * maxX + shear * (splat4<F>(std::fabs(r.d[r.kx])) * maxZ);
            const F deltaY = g5 * maxY + shear * (splat4<F>(std::fabs(r.d[r.ky])) * maxZ);
            const F deltaZ = g3 * maxZ;
            const F deltaE = splat4<F>(2.0f) * (g2 * maxX * maxY + deltaY * maxX + deltaX * maxY);
            const F maxE = max(abs(U), max(abs(V), abs(W)));
            const F deltaT =
                splat4<F>(3.0f) * (g3 * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) * abs(invDet);
            const unsigned sure = bits(deltaT < t) & inRange;
            undecided |= inRange & ~sure;
            if (sure) {
                alignas(16) float ts[4], invs[4], vs[4], ws[4];
                store4(ts, t);
                store4(invs, invDet);
                store4(vs, V);
                store4(ws, W);
                for (unsigned m = sure; m; m &= m - 1) {
                    const int l = __builtin_ctz(m);
                    if (!(ts[l] < tHit)) continue;  // a nearer lane of this block came first
                    tHit = ts[l];
                    u = vs[l] * invs[l];
                    v = ws[l] * invs[l];
                    prim = b.prim[l];
                    found = true;
                }
            }
        }
    }
    for (unsigned m = undecided; m; m &= m - 1) {
        const int l = __builtin_ctz(m);
        const glm::vec3 a(b.v[0][0][l], b.v[0][1][l], b.v[0][2][l]);
        const glm::vec3 bb(b.v[1][0][l], b.v[1][1][l], b.v[1][2][l]);
        const glm::vec3 c(b.v[2][0][l], b.v[2][1][l], b.v[2][2][l]);
        if (const auto h = intersectTriangleWatertight<float>(r.o, r.d, a, bb, c, r.tMin, tHit)) {
            tHit = h->t;
            u = h->u;
            v = h->v;
            prim = b.prim[l];
            found = true;
        }
    }
    return found;
}

}  // namespace

template <typename F, bool AnyHit>
std::optional<Hit> WideBvh::traverse(const Ray& ray, TraversalCounters& counters) const {
    if (root_ == kEmpty) return std::nullopt;
    const FloatRay r = floatRay(ray);
    if (!(r.tMin < r.tMax)) return std::nullopt;
    float tHit = r.tMax, u = 0.0f, v = 0.0f;
    std::uint32_t prim = kNoPrim;
    struct Entry {
        std::int32_t child;
        float tNear;
    };
    // Three entries a level at most, and the build keeps the tree under 64 levels.
    Entry stack[256];
    int top = 0;
    std::int32_t cur = root_;
    const SlabLanes<F> slab(r);
    const F tMinLanes = splat4<F>(r.tMin);
    for (;;) {
        // Down the nodes, nearest child first, the others pushed.
        while (cur >= 0) {
            const Node& n = nodes_[cur];
            ++counters.nodeVisits;
            F tNear;
            unsigned hit = boxes4<F>(n, slab, tMinLanes, tHit, tNear);
            if (!hit) {
                cur = kEmpty;
                break;
            }
            alignas(16) float dist[4];
            store4(dist, tNear);
            const int a = __builtin_ctz(hit);
            hit &= hit - 1;
            if (!hit) {  // one child: no stack
                cur = n.child[a];
                continue;
            }
            const int b = __builtin_ctz(hit);
            hit &= hit - 1;
            if (!hit) {  // two: the farther waits
                const bool aFirst = dist[a] <= dist[b];
                stack[top++] = aFirst ? Entry{n.child[b], dist[b]} : Entry{n.child[a], dist[a]};
                cur = aFirst ? n.child[a] : n.child[b];
                continue;
            }
            // Three or four: pushed, sorted farthest deepest, the nearest popped.
            const int first = top;
            stack[top++] = {n.child[a], dist[a]};
            stack[top++] = {n.child[b], dist[b]};
            for (; hit; hit &= hit - 1) {
                const int i = __builtin_ctz(hit);
                stack[top++] = {n.child[i], dist[i]};
            }
            // Any hit will do for a shadow ray: no order to keep.
            if constexpr (!AnyHit)
                for (int i = first + 1; i < top; ++i)
                    for (int j = i; j > first && stack[j - 1].tNear < stack[j].tNear; --j)
                        std::swap(stack[j - 1], stack[j]);
            cur = stack[--top].child;
        }
        if (cur != kEmpty) {
            const Leaf& leaf = leaves_[~cur];
            for (std::uint32_t bi = 0; bi < leaf.blocks && r.triangles; ++bi)
                if (blockTest<F>(blocks_[leaf.firstBlock + bi], r, tHit, u, v, prim, counters))
                    if constexpr (AnyHit) return Hit{tHit, prim, u, v};
            for (std::uint32_t si = 0; si < leaf.spheres; ++si) {
                const FloatSphere& s = spheres_[leaf.firstSphere + si];
                ++counters.primitiveTests;
                const glm::vec3 c(s.center[0], s.center[1], s.center[2]);
                if (const auto t =
                        intersectSphereStable<float>(r.o, r.d, c, s.radius, r.tMin, tHit)) {
                    tHit = *t;
                    prim = spherePrims_[leaf.firstSphere + si];
                    u = v = 0.0f;
                    if constexpr (AnyHit) return Hit{tHit, prim, 0.0, 0.0};
                }
            }
        }
        // The nearest entry not beyond the nearest hit found since it was pushed.
        cur = kEmpty;
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.tNear <= tHit * kWiden) {
                cur = e.child;
                break;
            }
        }
        if (cur == kEmpty) break;
    }
    if (prim == kNoPrim) return std::nullopt;
    return Hit{tHit, prim, u, v};
}

std::optional<Hit> WideBvh::intersect(const Ray& ray, TraversalCounters& counters,
                                      Lanes lanes) const {
    if (lanes == Lanes::Portable) return traverse<simd::portable::Float4, false>(ray, counters);
    return traverse<simd::Float4, false>(ray, counters);
}

bool WideBvh::occluded(const Ray& ray, TraversalCounters& counters, Lanes lanes) const {
    if (lanes == Lanes::Portable)
        return traverse<simd::portable::Float4, true>(ray, counters).has_value();
    return traverse<simd::Float4, true>(ray, counters).has_value();
}

}  // namespace raystep
