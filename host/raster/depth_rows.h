// The Z-buffer's inner loop: one row's run of covered centres depth-tested against a band
// of the depth and face buffers, in three interchangeable kernels of identical results.
//
// The test is Catmull's (1974) per pixel: the face's plane at the centre against the
// stored depth, the nearer one kept. Ours differs in what it computes with: the plane is
// evaluated at each centre x + 0.5 with exactly the operations of depth_at() (depth.h),
// a * (x + 0.5) + b * (y + 0.5) + c in double precision, never by adding increments, so
// every kernel and every raster method agree to the bit; an empty pixel (face 0) always
// takes the face, so the depth buffer is never cleared; a tie keeps the stored face, which
// the Z-buffer relies on by drawing faces in id order. Branch-free: which face wins a pixel
// is unpredictable, and branches on it cost more than the arithmetic.
//
// The kernels: DepthRowScalar (any machine), DepthRowSse2 (two pixels per instruction,
// every x86-64) and DepthRowAvx2 (four, only where the CPU has AVX2; the caller checks
// with has_avx2()). The vector kernels handle a run's last partial group with a lane mask,
// so they read and write back (unchanged) up to 3 entries past the run: the buffers need
// kDepthRowPad entries of padding after their last row.
#pragma once

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define FB89_HAS_AVX2_KERNEL 1
#endif

#include "host/raster/screen_scene.h"

namespace fb89::host {

inline constexpr int kDepthRowPad = 4;

// Depth-tests centres [xb, xe) of row y (xb < xe); depth and face point at the row's x = 0,
// and `mark` (the face's index + 1) goes into face[] where the face wins.
// Returns how many the face won. With kLowerIdOnTies a face also wins a centre of equal depth
// held by a higher index (the shared rule's tie, nearer() in depth.h, kept whatever order the
// faces come in: the hierarchical Z-buffer's, hzb.h); without it the stored face keeps it.
struct DepthRowScalar {
    template <bool kLowerIdOnTies = false>
    static uint64_t test(const DepthPlane& plane, int y, int xb, int xe, uint32_t mark,
                         double* __restrict depth, uint32_t* __restrict face) {
        const double a = plane.a, by = plane.b * (y + 0.5), c = plane.c;
        uint64_t written = 0;
        double xc = xb + 0.5;
        for (int x = xb; x < xe; ++x, xc += 1.0) {
            const double z = a * xc + by + c;
            bool wins = (face[x] == 0) | (z < depth[x]);
            if constexpr (kLowerIdOnTies) wins = wins | ((z == depth[x]) & (mark < face[x]));
            depth[x] = wins ? z : depth[x];
            face[x] = wins ? mark : face[x];
            written += wins;
        }
        return written;
    }
};

#if defined(__SSE2__)
struct DepthRowSse2 {
    template <bool kLowerIdOnTies = false>
    static uint64_t test(const DepthPlane& plane, int y, int xb, int xe, uint32_t mark,
                         double* __restrict depth, uint32_t* __restrict face) {
        const __m128d a = _mm_set1_pd(plane.a), by = _mm_set1_pd(plane.b * (y + 0.5));
        const __m128d c = _mm_set1_pd(plane.c), two = _mm_set1_pd(2.0);
        const __m128i vmark = _mm_set1_epi32(static_cast<int>(mark));
        __m128d xc = _mm_set_pd(xb + 1.5, xb + 0.5);
        __m128i won = _mm_setzero_si128();  // minus the pixels won, per lane
        for (int x = xb; x < xe; x += 2) {
            // plane and depth test
            const __m128d z = _mm_add_pd(_mm_add_pd(_mm_mul_pd(a, xc), by), c);
            const __m128d d = _mm_loadu_pd(depth + x);
            const __m128i f = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(face + x));
            const __m128i empty = _mm_cmpeq_epi32(f, _mm_setzero_si128());
            __m128d wins =
                _mm_or_pd(_mm_cmplt_pd(z, d), _mm_castsi128_pd(_mm_unpacklo_epi32(empty, empty)));
            if constexpr (kLowerIdOnTies) {
                // indices are below 2^31: the signed compare is the unsigned one
                const __m128i lower = _mm_cmplt_epi32(vmark, f);
                wins =
                    _mm_or_pd(wins, _mm_and_pd(_mm_cmpeq_pd(z, d),
                                               _mm_castsi128_pd(_mm_unpacklo_epi32(lower, lower))));
            }
            if (x + 1 == xe) wins = _mm_and_pd(wins, _mm_castsi128_pd(_mm_set_epi64x(0, -1)));
            // keep the winners
            _mm_storeu_pd(depth + x, _mm_or_pd(_mm_and_pd(wins, z), _mm_andnot_pd(wins, d)));
            const __m128i w32 = _mm_shuffle_epi32(_mm_castpd_si128(wins), _MM_SHUFFLE(2, 0, 2, 0));
            const __m128i merged =
                _mm_or_si128(_mm_and_si128(w32, vmark), _mm_andnot_si128(w32, f));
            _mm_storel_epi64(reinterpret_cast<__m128i*>(face + x), merged);
            won = _mm_add_epi64(won, _mm_castpd_si128(wins));
            xc = _mm_add_pd(xc, two);
        }
        int64_t lanes[2];
        _mm_storeu_si128(reinterpret_cast<__m128i*>(lanes), won);
        return static_cast<uint64_t>(-(lanes[0] + lanes[1]));
    }
};
#endif

#if defined(FB89_HAS_AVX2_KERNEL)
// Does this CPU (and its OS) run AVX2? Asked once.
inline bool has_avx2() {
    static const bool yes = __builtin_cpu_supports("avx2");
    return yes;
}

struct DepthRowAvx2 {
    template <bool kLowerIdOnTies = false>
    [[gnu::target("avx2")]] static uint64_t test(const DepthPlane& plane, int y, int xb, int xe,
                                                 uint32_t mark, double* __restrict depth,
                                                 uint32_t* __restrict face) {
        const __m256d a = _mm256_set1_pd(plane.a), by = _mm256_set1_pd(plane.b * (y + 0.5));
        const __m256d c = _mm256_set1_pd(plane.c), four = _mm256_set1_pd(4.0);
        const __m128i vmark = _mm_set1_epi32(static_cast<int>(mark));
        const __m256i lane = _mm256_set_epi64x(3, 2, 1, 0);
        __m256d xc = _mm256_add_pd(_mm256_set1_pd(xb + 0.5), _mm256_set_pd(3, 2, 1, 0));
        __m256i won = _mm256_setzero_si256();  // minus the pixels won, per lane
        for (int x = xb; x < xe; x += 4) {
            // plane and depth test
            const __m256d z = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a, xc), by), c);
            const __m256d d = _mm256_loadu_pd(depth + x);
            const __m128i f = _mm_loadu_si128(reinterpret_cast<const __m128i*>(face + x));
            const __m256i empty = _mm256_cvtepi32_epi64(_mm_cmpeq_epi32(f, _mm_setzero_si128()));
            __m256d wins =
                _mm256_or_pd(_mm256_cmp_pd(z, d, _CMP_LT_OQ), _mm256_castsi256_pd(empty));
            if constexpr (kLowerIdOnTies) {
                // indices are below 2^31: the signed compare is the unsigned one
                const __m256i lower = _mm256_cvtepi32_epi64(_mm_cmplt_epi32(vmark, f));
                wins = _mm256_or_pd(wins, _mm256_and_pd(_mm256_cmp_pd(z, d, _CMP_EQ_OQ),
                                                        _mm256_castsi256_pd(lower)));
            }
            if (x + 4 > xe) {
                const __m256i inside = _mm256_cmpgt_epi64(_mm256_set1_epi64x(xe - x), lane);
                wins = _mm256_and_pd(wins, _mm256_castsi256_pd(inside));
            }
            // keep the winners
            _mm256_storeu_pd(depth + x, _mm256_blendv_pd(d, z, wins));
            const __m256 w = _mm256_castpd_ps(wins);
            const __m128 w32 = _mm_shuffle_ps(_mm256_castps256_ps128(w),
                                              _mm256_extractf128_ps(w, 1), _MM_SHUFFLE(2, 0, 2, 0));
            _mm_storeu_si128(reinterpret_cast<__m128i*>(face + x),
                             _mm_blendv_epi8(f, vmark, _mm_castps_si128(w32)));
            won = _mm256_add_epi64(won, _mm256_castpd_si256(wins));
            xc = _mm256_add_pd(xc, four);
        }
        int64_t lanes[4];
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(lanes), won);
        return static_cast<uint64_t>(-(lanes[0] + lanes[1] + lanes[2] + lanes[3]));
    }
};
#endif

}  // namespace fb89::host
