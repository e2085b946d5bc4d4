#pragma once
// Double bounds to float bounds, rounded outward, so the float box still holds the double one.

#include <immintrin.h>  // SSE2, which every x86-64 has

#include <cstdint>

namespace raystep {

/// `in` holds N lows then N highs; `out` gets them as floats, each low rounded to the nearest
/// float at or below it and each high to the nearest at or above (a value that is a float stays
/// itself). Two at a time in SSE2: the kd-tree's fast build converts every clipped reference,
/// and one edge at a time was 5% of its instructions. The scalar reference is the test's
/// std::nextafter.
template <int N>
void roundOutward(const double* in, float* out) {
    static_assert(N == 2 || N == 3);
    for (int i = 0; i < 2 * N; i += 2) {
        // Lane k of this pair holds edge i + k: a low (rounded down) if i + k < N.
        const bool down0 = i < N, down1 = i + 1 < N;
        const __m128d x = _mm_loadu_pd(&in[i]);
        const __m128 f = _mm_cvtpd_ps(x);  // to nearest, in lanes 0 and 1
        const __m128d back = _mm_cvtps_pd(f);
        // The lanes where rounding to nearest went the wrong way (64-bit masks)...
        const __m128d downLanes = _mm_castsi128_pd(_mm_set_epi64x(down1 ? -1 : 0, down0 ? -1 : 0));
        const __m128d wrong64 = _mm_or_pd(_mm_and_pd(downLanes, _mm_cmpgt_pd(back, x)),
                                          _mm_andnot_pd(downLanes, _mm_cmplt_pd(back, x)));
        // ... as 32-bit masks in lanes 0 and 1.
        const __m128i wrong = _mm_castps_si128(_mm_shuffle_ps(
            _mm_castpd_ps(wrong64), _mm_castpd_ps(wrong64), _MM_SHUFFLE(2, 0, 2, 0)));
        // One step of the bit pattern: down is -1 on a positive float and +1 on a negative one,
        // up the opposite; from a zero of either sign, down gives -denorm_min, up +denorm_min.
        const __m128i bits = _mm_castps_si128(f);
        const __m128i dir = _mm_set_epi32(1, 1, down1 ? -1 : 1, down0 ? -1 : 1);
        const __m128i sign = _mm_srai_epi32(bits, 31);
        const __m128i stepped = _mm_add_epi32(bits, _mm_sub_epi32(_mm_xor_si128(dir, sign), sign));
        const __m128i zero =
            _mm_cmpeq_epi32(_mm_and_si128(bits, _mm_set1_epi32(0x7fffffff)), _mm_setzero_si128());
        const __m128i fromZero =
            _mm_set_epi32(1, 1, down1 ? int(0x80000001u) : 1, down0 ? int(0x80000001u) : 1);
        const __m128i step =
            _mm_or_si128(_mm_and_si128(zero, fromZero), _mm_andnot_si128(zero, stepped));
        const __m128i result =
            _mm_or_si128(_mm_and_si128(wrong, step), _mm_andnot_si128(wrong, bits));
        _mm_storel_pi(reinterpret_cast<__m64*>(&out[i]), _mm_castsi128_ps(result));
    }
}

}  // namespace raystep
