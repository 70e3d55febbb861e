// The 16-lane NEAREST wrap that the lookups of Float8x2 lanes in one 512-bit register share
// (sample_half_avx512.h, sample_nearest_avx512.h): wrap_avx2.h's wrapNearest on sixteen lanes,
// the same operations in each, so every index is the same.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include "raster/simd/intrinsics.h"
#include "raster/texture/texture.h"

namespace raster::sampling {

// The texel index along one axis for NEAREST, as the 8-lane wrapNearest of the float path
// (no floor before the CLAMP_TO_EDGE clamp): REPEAT of a power-of-two size masks the
// floored coordinate, of another size scales the fraction (at most 0.99999994, NaN too);
// both clamp a truncated index to [0, size - 1].
[[gnu::always_inline]] inline __m512i wrapNearest16(__m512 coord, int size, Wrap wrap) {
  const __m512 sizeF = _mm512_set1_ps(float(size));
  const __m512i last = _mm512_set1_epi32(size - 1);
  if (wrap == Wrap::Repeat && size > 0 && (size & (size - 1)) == 0)
    return _mm512_and_si512(_mm512_cvttps_epi32(_mm512_floor_ps(_mm512_mul_ps(coord, sizeF))), last);
  if (wrap == Wrap::Repeat) {
    const __m512 fraction = _mm512_min_ps(_mm512_sub_ps(coord, _mm512_floor_ps(coord)), _mm512_set1_ps(0.99999994f));
    coord = fraction;
  }
  const __m512i index = _mm512_cvttps_epi32(_mm512_mul_ps(coord, sizeF));
  return _mm512_min_epi32(_mm512_max_epi32(index, _mm512_setzero_si512()), last);
}

// The texel (y * width + x) a NEAREST lookup at (s, t) reads, for sixteen lanes.
[[gnu::always_inline]] inline __m512i nearestTexelIndex16(__m512 s, __m512 t, int width, int height, Wrap wrapS, Wrap wrapT) {
  const __m512i x = wrapNearest16(s, width, wrapS), y = wrapNearest16(t, height, wrapT);
  return _mm512_add_epi32(_mm512_mullo_epi32(y, _mm512_set1_epi32(width)), x);
}

}  // namespace raster::sampling
#endif
