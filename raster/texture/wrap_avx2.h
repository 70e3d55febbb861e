// The 8-lane helpers the colour sampler's paths share (sample_color_avx2.cpp and
// sample_rgba8_avx2.h): splats, clamps and NEAREST's wrap, as llvmpipe computes them.
#pragma once

#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#include "raster/texture/texture.h"

namespace raster::sampling::avx2 {

inline bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

inline __m256i splat(int v) { return _mm256_set1_epi32(v); }
inline __m256 splat(float v) { return _mm256_set1_ps(v); }
inline __m256i select(__m256i mask, __m256i a, __m256i b) { return _mm256_blendv_epi8(b, a, mask); }
inline __m256i clampInt(__m256i v, int lo, int hi) { return _mm256_min_epi32(_mm256_max_epi32(v, splat(lo)), splat(hi)); }
inline __m256 fract(__m256 x) { return _mm256_sub_ps(x, _mm256_floor_ps(x)); }
inline __m256 fractSafe(__m256 x) { return _mm256_min_ps(fract(x), splat(0.99999994f)); }   // NaN -> the bound
inline __m256i floorToInt(__m256 x) { return _mm256_cvttps_epi32(_mm256_floor_ps(x)); }

inline __m256i wrapNearest(__m256 coord, int size, Wrap wrap, bool floorClamp) {
  if (wrap == Wrap::Repeat) {
    if (isPowerOfTwo(size)) return _mm256_and_si256(floorToInt(_mm256_mul_ps(coord, splat(float(size)))), splat(size - 1));
    return clampInt(_mm256_cvttps_epi32(_mm256_mul_ps(fractSafe(coord), splat(float(size)))), 0, size - 1);
  }
  // CLAMP_TO_EDGE: the AoS path floors, the float path truncates (both then clamp).
  const __m256 scaled = _mm256_mul_ps(coord, splat(float(size)));
  return clampInt(floorClamp ? floorToInt(scaled) : _mm256_cvttps_epi32(scaled), 0, size - 1);
}

// The texel (y * width + x) a NEAREST lookup of the float path at (s, t) reads, for 8 lanes.
inline __m256i nearestTexelIndex8(__m256 s, __m256 t, int width, int height, Wrap wrapS, Wrap wrapT) {
  const __m256i x = wrapNearest(s, width, wrapS, false), y = wrapNearest(t, height, wrapT, false);
  return _mm256_add_epi32(_mm256_mullo_epi32(y, splat(width)), x);
}

}  // namespace raster::sampling::avx2
#endif
