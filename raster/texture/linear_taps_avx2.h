// What the 8-lane samplers share: float bilinear taps along one axis (the depth-compare
// sampler and the half-float colour sampler; llvmpipe computes both in its float SoA path),
// and the gather of two neighbouring 32-bit texels per lane (depth codes, RGBA8).
#pragma once

#if RASTER_AVX2
#include "raster/simd/intrinsics.h"

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

// Near an edge, clamping piles a grid's taps onto the same texels, so they are no longer one
// texel apart; each lane's footprints still lie in a window of count + 1 texels along each
// axis, started at tap 0's first texel and moved in from the far edge so it stays inside
// (windowStart). WindowTaps says, per tap and lane, which window texels the tap spans: lane
// masks of the taps whose first (second) texel is window texel v >= 1 (a lane in none of
// them takes window texel 0).
template <int kTaps>
struct WindowTaps {
  static constexpr int kWindow = kTaps + 1;
  __m256 first[kTaps][kWindow], second[kTaps][kWindow];   // [tap][window texel], [.][0] unused
};

inline __m256i windowStart(const LinearTaps8& tap0, int size, int window) {
  return _mm256_min_epi32(tap0.i0, _mm256_set1_epi32(size - window));
}

// Fills `out`; false when some tap of some lane has a texel outside its window.
template <int kTaps>
bool tapsInWindow(const LinearTaps8* taps, __m256i start, WindowTaps<kTaps>& out) {
  constexpr int kWindow = WindowTaps<kTaps>::kWindow;
  __m256i outside = _mm256_setzero_si256();
  for (int k = 0; k < kTaps; ++k) {
    const __m256i at[2] = {_mm256_sub_epi32(taps[k].i0, start), _mm256_sub_epi32(taps[k].i1, start)};
    for (int side = 0; side < 2; ++side) {
      outside = _mm256_or_si256(outside, _mm256_cmpgt_epi32(_mm256_setzero_si256(), at[side]));
      outside = _mm256_or_si256(outside, _mm256_cmpgt_epi32(at[side], _mm256_set1_epi32(kWindow - 1)));
      for (int v = 1; v < kWindow; ++v)
        (side ? out.second : out.first)[k][v] = _mm256_castsi256_ps(_mm256_cmpeq_epi32(at[side], _mm256_set1_epi32(v)));
    }
  }
  return _mm256_testz_si256(outside, outside);
}

// Per lane, value(v) of the window texel v that `is` names (a row of WindowTaps::first or
// ::second).
template <int kWindow, class Value>
[[gnu::always_inline]] inline __m256 pickInWindow(const __m256 (&is)[kWindow], Value&& value) {
  __m256 picked = value(0);
  for (int v = 1; v < kWindow; ++v) picked = _mm256_blendv_ps(picked, value(v), is[v]);
  return picked;
}

// Texels index and index + 1 of each lane, 32 bits each (index + 1 in the same array): one
// 64-bit gather element per lane (32-bit indices into a 64-bit-element view are byte
// offsets / 8: scale 4), lanes 0-3 then 4-7, split into the left texels and the right ones
// in lane order.
inline void gatherTexelPairs(const void* texels, __m256i index, __m256i& left, __m256i& right) {
  const long long* base = static_cast<const long long*>(texels);
  const __m256 lo = _mm256_castsi256_ps(_mm256_i32gather_epi64(base, _mm256_castsi256_si128(index), 4));
  const __m256 hi = _mm256_castsi256_ps(_mm256_i32gather_epi64(base, _mm256_extracti128_si256(index, 1), 4));
  // lo = [l0 r0 l1 r1 | l2 r2 l3 r3], hi likewise for lanes 4-7.
  left = _mm256_permute4x64_epi64(_mm256_castps_si256(_mm256_shuffle_ps(lo, hi, 0x88)), 0xD8);
  right = _mm256_permute4x64_epi64(_mm256_castps_si256(_mm256_shuffle_ps(lo, hi, 0xDD)), 0xD8);
}

}  // namespace raster::sampling
#endif
