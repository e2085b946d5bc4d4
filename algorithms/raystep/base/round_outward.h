#pragma once
// Double bounds to float bounds, rounded outward, so the float box still holds the double one.

#include <immintrin.h>  // SSE2, which every x86-64 has

#include <cstdint>

namespace raystep {

/// `in` holds N lows then N highs; `out` gets them as floats, each low rounded to the nearest
/// float at or below it and each high to the nearest at or above (a value that is a float stays
/// itself). Four at a time in SSE2: the kd-tree's fast build converts every clipped reference,
/// and one edge at a time was 5% of its instructions (two at a time, 5% still). The scalar
/// reference is the test's std::nextafter.
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

}  // namespace raystep
