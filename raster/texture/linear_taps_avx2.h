// Float bilinear taps along one axis, 8 lanes at once: what the depth-compare sampler and the
// half-float colour sampler share (llvmpipe computes both in its float SoA path).
#pragma once

#if RASTER_AVX2
#include <immintrin.h>

#include <initializer_list>

namespace raster::sampling {

struct LinearTaps8 {
  __m256i i0, i1;   // texel indices along one axis
  __m256 weight;    // weight of i1
};

// lp_build_sample_wrap_linear, CLAMP_TO_EDGE with normalized coordinates:
//   c = max(min(coord * size, size) - 0.5, 0);  i0 = floor(c);  weight = c - i0;
//   i1 = min(i0 + 1, size - 1).
// minps/maxps return the second operand on NaN and on ties, so NaN gives texel size - 1.
inline LinearTaps8 wrapLinearClampToEdge8(__m256 coord, int size) {
  const __m256 sizeF = _mm256_set1_ps(float(size));
  __m256 c = _mm256_mul_ps(coord, sizeF);
  c = _mm256_min_ps(c, sizeF);
  c = _mm256_sub_ps(c, _mm256_set1_ps(0.5f));
  c = _mm256_max_ps(c, _mm256_setzero_ps());
  const __m256 floorC = _mm256_floor_ps(c);
  LinearTaps8 taps;
  taps.i0 = _mm256_cvttps_epi32(floorC);
  taps.weight = _mm256_sub_ps(c, floorC);
  taps.i1 = _mm256_min_epi32(_mm256_add_epi32(taps.i0, _mm256_set1_epi32(1)), _mm256_set1_epi32(size - 1));
  return taps;
}

// For a grid of lookups one step apart: true when, in every lane and along both axes, tap k
// spans texels first + k and first + k + 1 (no tap moved by rounding, none clamped at an
// edge), so the grid's footprints tile a (count + 1)^2 neighbourhood starting at tap 0's i0.
inline bool tapsAreConsecutive(const LinearTaps8* x, const LinearTaps8* y, int count) {
  __m256i consecutive = _mm256_set1_epi32(-1);
  for (int k = 0; k < count; ++k) {
    const __m256i k0 = _mm256_set1_epi32(k), k1 = _mm256_set1_epi32(k + 1);
    for (const LinearTaps8* axis : {x, y}) {
      consecutive = _mm256_and_si256(consecutive, _mm256_cmpeq_epi32(axis[k].i0, _mm256_add_epi32(axis[0].i0, k0)));
      consecutive = _mm256_and_si256(consecutive, _mm256_cmpeq_epi32(axis[k].i1, _mm256_add_epi32(axis[0].i0, k1)));
    }
  }
  return _mm256_movemask_ps(_mm256_castsi256_ps(consecutive)) == 0xFF;
}

}  // namespace raster::sampling
#endif
