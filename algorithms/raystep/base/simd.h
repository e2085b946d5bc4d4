#pragma once
// Every x86 intrinsic of the core, each beside a portable version that computes the same bits:
// the kd-tree's fast build (kdtree_fast.cpp) bins four edges at a time, the wide BVH
// (fast/wide_bvh_traverse.cpp) tests four boxes and four triangles at once, and the core must still
// build on a student's ARM64 laptop. `simd::` picks SSE2 where the compiler has it, else the
// portable code; `simd::portable::` is always there, so the tests compare the two on x86.
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace raystep::simd {

namespace portable {

/// Four floats, lane 0 first.
struct Float4 {
    float v[4];
};
/// Four 32-bit integers, lane 0 first.
struct Int4 {
    std::int32_t v[4];
};

inline Float4 load(const float* p) {
    return {{p[0], p[1], p[2], p[3]}};
}
inline Float4 splat(float x) {
    return {{x, x, x, x}};
}
inline Float4 set(float a, float b, float c, float d) {
    return {{a, b, c, d}};
}
inline void store(float* p, Float4 x) {
    for (int i = 0; i < 4; ++i) p[i] = x.v[i];
}
inline Float4 operator-(Float4 a, Float4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] -= b.v[i];
    return a;
}
inline Float4 operator*(Float4 a, Float4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] *= b.v[i];
    return a;
}

/// Four lane masks (a comparison's result), lane 0 first.
struct Mask4 {
    bool v[4];
};
inline Float4 operator+(Float4 a, Float4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] += b.v[i];
    return a;
}
inline Float4 operator/(Float4 a, Float4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] /= b.v[i];
    return a;
}
/// |a| lane by lane (the sign bit cleared, as SSE's andnot with -0.0).
inline Float4 abs(Float4 a) {
    for (int i = 0; i < 4; ++i) a.v[i] = std::fabs(a.v[i]);
    return a;
}
// Ordered comparisons, as SSE's cmpps: false in a lane where either operand is NaN.
inline Mask4 operator<(Float4 a, Float4 b) {
    Mask4 m;
    for (int i = 0; i < 4; ++i) m.v[i] = a.v[i] < b.v[i];
    return m;
}
inline Mask4 operator<=(Float4 a, Float4 b) {
    Mask4 m;
    for (int i = 0; i < 4; ++i) m.v[i] = a.v[i] <= b.v[i];
    return m;
}
inline Mask4 operator>(Float4 a, Float4 b) {
    return b < a;
}
inline Mask4 operator==(Float4 a, Float4 b) {
    Mask4 m;
    for (int i = 0; i < 4; ++i) m.v[i] = a.v[i] == b.v[i];
    return m;
}
inline Mask4 operator&(Mask4 a, Mask4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] = a.v[i] && b.v[i];
    return a;
}
inline Mask4 operator|(Mask4 a, Mask4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] = a.v[i] || b.v[i];
    return a;
}
/// !a & b lane by lane.
inline Mask4 andNot(Mask4 a, Mask4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] = !a.v[i] && b.v[i];
    return a;
}
/// Bit i set where lane i is true (SSE's movemask).
inline unsigned bits(Mask4 m) {
    unsigned r = 0;
    for (int i = 0; i < 4; ++i) r |= unsigned(m.v[i]) << i;
    return r;
}
/// m ? a : b lane by lane.
inline Float4 select(Mask4 m, Float4 a, Float4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] = m.v[i] ? a.v[i] : b.v[i];
    return a;
}
/// Lane by lane a < b ? a : b, as SSE's minps (the second operand if either is NaN).
inline Float4 min(Float4 a, Float4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i];
    return a;
}
/// Lane by lane a > b ? a : b, as SSE's maxps.
inline Float4 max(Float4 a, Float4 b) {
    for (int i = 0; i < 4; ++i) a.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i];
    return a;
}
/// Each lane converted toward zero (callers keep the lanes inside the int32 range).
inline Int4 truncate(Float4 a) {
    Int4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = static_cast<std::int32_t>(a.v[i]);
    return r;
}
/// Each lane shifted right by S bits, zeros coming in.
template <int S>
inline Int4 shiftRight(Int4 a) {
    for (int i = 0; i < 4; ++i)
        a.v[i] = static_cast<std::int32_t>(static_cast<std::uint32_t>(a.v[i]) >> S);
    return a;
}
inline void store(std::int32_t* p, Int4 x) {
    for (int i = 0; i < 4; ++i) p[i] = x.v[i];
}
template <int Lane>
inline std::int32_t lane(Int4 x) {
    return x.v[Lane];
}
/// Bit j set if starts[j] or ends[j] is not zero (j < 4).
inline unsigned occupied4(const std::uint32_t* starts, const std::uint32_t* ends) {
    unsigned mask = 0;
    for (int j = 0; j < 4; ++j) mask |= unsigned((starts[j] | ends[j]) != 0) << j;
    return mask;
}

/// `in` holds N lows then N highs; `out` gets them as floats, each low rounded to the nearest
/// float at or below it and each high to the nearest at or above (a value that is a float stays
/// itself), so the float box still holds the double one.
template <int N>
void roundOutward(const double* in, float* out) {
    static_assert(N == 2 || N == 3);
    for (int j = 0; j < 2 * N; ++j) {
        const float f = static_cast<float>(in[j]);  // to nearest
        const bool low = j < N;
        if (low && static_cast<double>(f) > in[j])
            out[j] = std::nextafter(f, -std::numeric_limits<float>::infinity());
        else if (!low && static_cast<double>(f) < in[j])
            out[j] = std::nextafter(f, std::numeric_limits<float>::infinity());
        else
            out[j] = f;
    }
}

}  // namespace portable

#if defined(__SSE2__)
namespace sse2 {

struct Float4 {
    __m128 v;
};
struct Int4 {
    __m128i v;
};
struct Mask4 {
    __m128 v;
};
inline Float4 operator+(Float4 a, Float4 b) {
    return {_mm_add_ps(a.v, b.v)};
}
inline Float4 operator/(Float4 a, Float4 b) {
    return {_mm_div_ps(a.v, b.v)};
}
inline Float4 abs(Float4 a) {
    return {_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v)};
}
inline Mask4 operator<(Float4 a, Float4 b) {
    return {_mm_cmplt_ps(a.v, b.v)};
}
inline Mask4 operator<=(Float4 a, Float4 b) {
    return {_mm_cmple_ps(a.v, b.v)};
}
inline Mask4 operator>(Float4 a, Float4 b) {
    return {_mm_cmpgt_ps(a.v, b.v)};
}
inline Mask4 operator==(Float4 a, Float4 b) {
    return {_mm_cmpeq_ps(a.v, b.v)};
}
inline Mask4 operator&(Mask4 a, Mask4 b) {
    return {_mm_and_ps(a.v, b.v)};
}
inline Mask4 operator|(Mask4 a, Mask4 b) {
    return {_mm_or_ps(a.v, b.v)};
}
inline Mask4 andNot(Mask4 a, Mask4 b) {
    return {_mm_andnot_ps(a.v, b.v)};
}
inline unsigned bits(Mask4 m) {
    return unsigned(_mm_movemask_ps(m.v));
}
inline Float4 select(Mask4 m, Float4 a, Float4 b) {
    return {_mm_or_ps(_mm_and_ps(m.v, a.v), _mm_andnot_ps(m.v, b.v))};
}

inline Float4 load(const float* p) {
    return {_mm_loadu_ps(p)};
}
inline Float4 splat(float x) {
    return {_mm_set1_ps(x)};
}
inline Float4 set(float a, float b, float c, float d) {
    return {_mm_setr_ps(a, b, c, d)};
}
inline void store(float* p, Float4 x) {
    _mm_storeu_ps(p, x.v);
}
inline Float4 operator-(Float4 a, Float4 b) {
    return {_mm_sub_ps(a.v, b.v)};
}
inline Float4 operator*(Float4 a, Float4 b) {
    return {_mm_mul_ps(a.v, b.v)};
}
inline Float4 min(Float4 a, Float4 b) {
    return {_mm_min_ps(a.v, b.v)};
}
inline Float4 max(Float4 a, Float4 b) {
    return {_mm_max_ps(a.v, b.v)};
}
inline Int4 truncate(Float4 a) {
    return {_mm_cvttps_epi32(a.v)};
}
template <int S>
inline Int4 shiftRight(Int4 a) {
    return {_mm_srli_epi32(a.v, S)};
}
inline void store(std::int32_t* p, Int4 x) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(p), x.v);
}
template <int Lane>
inline std::int32_t lane(Int4 x) {
    return _mm_cvtsi128_si32(_mm_srli_si128(x.v, 4 * Lane));
}
inline unsigned occupied4(const std::uint32_t* starts, const std::uint32_t* ends) {
    const auto load = [](const std::uint32_t* p) {
        return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    };
    const __m128i any = _mm_or_si128(load(starts), load(ends));
    const int empty = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(any, _mm_setzero_si128())));
    return unsigned(~empty & 0xF);
}

/// portable::roundOutward four edges at a time: the fast build converts every clipped reference,
/// and one edge at a time was 5% of its instructions.
template <int N>
void roundOutward(const double* in, float* out) {
    static_assert(N == 2 || N == 3);
    for (int g = 0; g < 2 * N; g += 4) {
        // Edges g..g+3 (the last group of 3D holds two): lane k is a low if g + k < N.
        const bool two = 2 * N - g == 2;
        const auto down = [&](int k) { return g + k < N; };
        const __m128d x0 = _mm_loadu_pd(&in[g]);
        const __m128d x1 = two ? x0 : _mm_loadu_pd(&in[g + 2]);
        const __m128 f = _mm_movelh_ps(_mm_cvtpd_ps(x0), _mm_cvtpd_ps(x1));  // to nearest
        // The lanes where rounding to nearest went the wrong way, as 64-bit masks...
        const auto wrongWay = [&](__m128d x, __m128d back, int k) {
            const __m128d downLanes =
                _mm_castsi128_pd(_mm_set_epi64x(down(k + 1) ? -1 : 0, down(k) ? -1 : 0));
            return _mm_or_pd(_mm_and_pd(downLanes, _mm_cmpgt_pd(back, x)),
                             _mm_andnot_pd(downLanes, _mm_cmplt_pd(back, x)));
        };
        const __m128d wrong0 = wrongWay(x0, _mm_cvtps_pd(f), 0);
        const __m128d wrong1 = wrongWay(x1, _mm_cvtps_pd(_mm_movehl_ps(f, f)), 2);
        // ... as 32-bit masks in lanes 0-3.
        const __m128i wrong = _mm_castps_si128(
            _mm_shuffle_ps(_mm_castpd_ps(wrong0), _mm_castpd_ps(wrong1), _MM_SHUFFLE(2, 0, 2, 0)));
        // One step of the bit pattern: down is -1 on a positive float and +1 on a negative one,
        // up the opposite; from a zero of either sign, down gives -denorm_min, up +denorm_min.
        const auto lanes = [&](int ifDown, int ifUp) {
            return _mm_set_epi32(down(3) ? ifDown : ifUp, down(2) ? ifDown : ifUp,
                                 down(1) ? ifDown : ifUp, down(0) ? ifDown : ifUp);
        };
        const __m128i bits = _mm_castps_si128(f);
        const __m128i sign = _mm_srai_epi32(bits, 31);
        const __m128i stepped =
            _mm_add_epi32(bits, _mm_sub_epi32(_mm_xor_si128(lanes(-1, 1), sign), sign));
        const __m128i zero =
            _mm_cmpeq_epi32(_mm_and_si128(bits, _mm_set1_epi32(0x7fffffff)), _mm_setzero_si128());
        const __m128i step = _mm_or_si128(_mm_and_si128(zero, lanes(int(0x80000001u), 1)),
                                          _mm_andnot_si128(zero, stepped));
        const __m128 result = _mm_castsi128_ps(
            _mm_or_si128(_mm_and_si128(wrong, step), _mm_andnot_si128(wrong, bits)));
        if (two)
            _mm_storel_pi(reinterpret_cast<__m64*>(&out[g]), result);
        else
            _mm_storeu_ps(&out[g], result);
    }
}

}  // namespace sse2
using namespace sse2;
#else
using namespace portable;
#endif

}  // namespace raystep::simd
