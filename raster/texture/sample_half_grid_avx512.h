// The 3x3 grid of RGBA16F bilinear lookups with CLAMP_TO_EDGE for Float8x2 lanes in one
// 512-bit register (the bloom downsample and upsample, textureGrid3x3 in sampler.h), and the
// grid taps that the 16-lane shadow compare (sample_compare_avx512.cpp) shares: the same
// wraps and blends as the single lookups of sample_half_avx512.h, which this builds on.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include "raster/texture/sample_half_avx512.h"

namespace raster::sampling {

// The taps along both axes of a grid of lookups, tap k at s + offsetS(k) and t + offsetT(k),
// each offset a float made as the grid's scalar reference makes it: bloomGridTaps16 and
// compareGridTaps16 below, which the 16-lane grids and their tests share.
template <int N, class OffsetS, class OffsetT>
[[gnu::always_inline]] inline void gridTaps16(__m512 s, __m512 t, int width, int height, OffsetS offsetS, OffsetT offsetT,
                                              LinearTaps16 (&x)[N], LinearTaps16 (&y)[N]) {
  for (int k = 0; k < N; ++k) {
    x[k] = wrapLinearClampToEdge16(_mm512_add_ps(s, _mm512_set1_ps(offsetS(k))), width);
    y[k] = wrapLinearClampToEdge16(_mm512_add_ps(t, _mm512_set1_ps(offsetT(k))), height);
  }
}

// textureGrid3x3's taps (sampler.h): tap k at coord + float(k - 1) * step.
[[gnu::always_inline]] inline void bloomGridTaps16(const Texture& texture, __m512 s, __m512 t, float stepS, float stepT,
                                                   LinearTaps16 (&x)[3], LinearTaps16 (&y)[3]) {
  gridTaps16(s, t, texture.width, texture.height, [&](int k) { return float(k - 1) * stepS; },
             [&](int k) { return float(k - 1) * stepT; }, x, y);
}

// compareGrid8's taps (sampler_avx2.h): tap k at coord + (origin + float(k - R) * step).
template <int R>
[[gnu::always_inline]] inline void compareGridTaps16(const Texture& depth, __m512 s, __m512 t, float origin, float step,
                                                     LinearTaps16 (&x)[2 * R + 1], LinearTaps16 (&y)[2 * R + 1]) {
  const auto offset = [&](int k) { return origin + float(k - R) * step; };
  gridTaps16(s, t, depth.width, depth.height, offset, offset, x, y);
}

// tapsAreConsecutive (linear_taps_avx2.h) on 16 lanes, along one axis: true when, in every
// lane, tap k spans texels first + k and first + k + 1. A tap's second texel is
// min(i0 + 1, size - 1) (wrapLinearClampToEdge16), so where each tap's first texel is
// first + k, every tap's second one is the next texel when the last tap's is: one compare
// per tap, or-ed as vectors (masked compares had each waited on the last one's mask).
[[gnu::always_inline]] inline bool axisTapsAreConsecutive16(const LinearTaps16* axis, int count) {
  const __m512i first = axis[0].i0;
  __m512i differs = _mm512_xor_si512(axis[count - 1].i1, _mm512_add_epi32(first, _mm512_set1_epi32(count)));
  for (int k = 1; k < count; ++k)
    differs = _mm512_or_si512(differs, _mm512_xor_si512(axis[k].i0, _mm512_add_epi32(first, _mm512_set1_epi32(k))));
  return _mm512_test_epi32_mask(differs, differs) == 0;
}

// The same along both axes.
[[gnu::always_inline]] inline bool tapsAreConsecutive16(const LinearTaps16* x, const LinearTaps16* y, int count) {
  return axisTapsAreConsecutive16(x, count) && axisTapsAreConsecutive16(y, count);
}

// Window row `rowOffset` (texels below each lane's start) of lanes k, k + 4, k + 8 and
// k + 12, each read with one 32-byte load from its texel start[lane]: texel[v] holds window
// texel v of the four lanes, one lane per 128-bit block, rgba each (the layout
// blendHalfPairs16 lines a pair up in).
[[gnu::always_inline]] inline void windowRowTexels16(const uint16_t* texels, const int* start, size_t rowOffset, int k,
                                                     __m512 (&texel)[4]) {
  auto row = [&](int lane) {   // [texel 0 | 1 | 2 | 3] of the lane's window row
    return _mm512_cvtph_ps(
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(texels + (size_t(start[lane]) + rowOffset) * 4)));
  };
  const __m512 a = row(k), b = row(k + 4), c = row(k + 8), d = row(k + 12);
  // Lane blocks [a | b | c | d] of texel v, from each lane's [0 | 1 | 2 | 3]: a 4x4
  // transpose of 128-bit blocks.
  const __m512 abLow = _mm512_shuffle_f32x4(a, b, _MM_SHUFFLE(1, 0, 1, 0));    // a0 a1 b0 b1
  const __m512 abHigh = _mm512_shuffle_f32x4(a, b, _MM_SHUFFLE(3, 2, 3, 2));   // a2 a3 b2 b3
  const __m512 cdLow = _mm512_shuffle_f32x4(c, d, _MM_SHUFFLE(1, 0, 1, 0));
  const __m512 cdHigh = _mm512_shuffle_f32x4(c, d, _MM_SHUFFLE(3, 2, 3, 2));
  texel[0] = _mm512_shuffle_f32x4(abLow, cdLow, _MM_SHUFFLE(2, 0, 2, 0));
  texel[1] = _mm512_shuffle_f32x4(abLow, cdLow, _MM_SHUFFLE(3, 1, 3, 1));
  texel[2] = _mm512_shuffle_f32x4(abHigh, cdHigh, _MM_SHUFFLE(2, 0, 2, 0));
  texel[3] = _mm512_shuffle_f32x4(abHigh, cdHigh, _MM_SHUFFLE(3, 1, 3, 1));
}

// tapsInWindow (linear_taps_avx2.h) on 16 lanes: whether both texels of every tap lie in
// the window of kTaps + 1 texels from `start` in every lane.
template <int kTaps>
[[gnu::always_inline]] inline bool tapsInWindow16(const LinearTaps16 (&taps)[kTaps], __m512i start) {
  __mmask16 inside = 0xFFFF;
  for (const LinearTaps16& tap : taps)
    for (__m512i texel : {tap.i0, tap.i1})
      inside &= _mm512_cmple_epu32_mask(_mm512_sub_epi32(texel, start), _mm512_set1_epi32(kTaps));
  return inside == 0xFFFF;
}

// Per lane block (blockLanes), value[v] for the window texel v = at of that lane, as
// pickInWindow does per 8 lanes.
[[gnu::always_inline]] inline __m512 pickInWindow16(const __m512 (&value)[4], __m512i at) {
  __m512 picked = value[0];
  for (int v = 1; v < 4; ++v) picked = _mm512_mask_mov_ps(picked, _mm512_cmpeq_epi32_mask(at, _mm512_set1_epi32(v)), value[v]);
  return picked;
}

// blendHalfGrid16 near an edge, where clamping piles taps onto the same texels: each lane's
// window starts at tap 0's first texel moved in from the far edge (startX, startY), and each
// tap blends the window texels its lane picks, with the same operations as where the taps
// lie in place (blendGridPicked does this per 8 lanes). All four window rows' blends are
// kept, since a tap row may take any two of them. An axis whose taps are consecutive in
// every lane (InPlaceX, InPlaceY: a block at the left or right edge is in place down the
// rows, one at the top or bottom along them) has its window start at tap 0's first texel
// (its last tap's second texel is at most size - 1, so no move in) and tap k spans window
// texels k and k + 1: those are taken as they are, which is what picking them gives.
template <bool InPlaceX, bool InPlaceY>
[[gnu::always_inline]] inline void blendHalfGridPicked16(const Texture& t, const int* start, const LinearTaps16 (&x)[3],
                                                         const LinearTaps16 (&y)[3], __m512i startX, __m512i startY,
                                                         __m512 (&blended)[9][4]) {
  const uint16_t* texels = t.half.data();
  for (int k = 0; k < 4; ++k) {
    const __m512i lanes = blockLanes(k);
    // Each tap column's window texels and weight, the same in every row.
    __m512i leftColumn[3], rightColumn[3];
    __m512 weightX[3];
    for (int i = 0; i < 3; ++i) {
      if constexpr (!InPlaceX) {
        leftColumn[i] = _mm512_permutexvar_epi32(lanes, _mm512_sub_epi32(x[i].i0, startX));
        rightColumn[i] = _mm512_permutexvar_epi32(lanes, _mm512_sub_epi32(x[i].i1, startX));
      }
      weightX[i] = _mm512_permutexvar_ps(lanes, x[i].weight);
    }
    __m512 rowBlend[3][4];   // [tap column][window row]
    for (int r = 0; r < 4; ++r) {
      __m512 texel[4];
      windowRowTexels16(texels, start, size_t(r) * size_t(t.width), k, texel);
      for (int i = 0; i < 3; ++i) {
        const __m512 left = InPlaceX ? texel[i] : pickInWindow16(texel, leftColumn[i]);
        const __m512 right = InPlaceX ? texel[i + 1] : pickInWindow16(texel, rightColumn[i]);
        rowBlend[i][r] = _mm512_fmadd_ps(weightX[i], _mm512_sub_ps(right, left), left);
      }
    }
    for (int j = 0; j < 3; ++j) {
      __m512i topRow = _mm512_setzero_si512(), bottomRow = _mm512_setzero_si512();
      if constexpr (!InPlaceY) {
        topRow = _mm512_permutexvar_epi32(lanes, _mm512_sub_epi32(y[j].i0, startY));
        bottomRow = _mm512_permutexvar_epi32(lanes, _mm512_sub_epi32(y[j].i1, startY));
      }
      const __m512 weightY = _mm512_permutexvar_ps(lanes, y[j].weight);
      for (int i = 0; i < 3; ++i) {
        const __m512 top = InPlaceY ? rowBlend[i][j] : pickInWindow16(rowBlend[i], topRow);
        const __m512 bottom = InPlaceY ? rowBlend[i][j + 1] : pickInWindow16(rowBlend[i], bottomRow);
        blended[j * 3 + i][k] = _mm512_fmadd_ps(weightY, _mm512_sub_ps(bottom, top), top);
      }
    }
  }
}

// textureGrid3x3 (sampler.h) for such a texture on 16 lanes, when every lane's nine 2x2
// footprints lie in one 4x4 window of texels inside the texture. Usually tap k spans window
// texels k and k + 1 along both axes in every lane: each window row is then read with one
// 32-byte load per lane, its texels lined up lane by lane as blendHalfPairs16 lines up a pair
// (lanes k, k + 4, k + 8 and k + 12 in one register), and blended in the same order, rows
// then columns, as sampleHalfGridShared does per 8 lanes. Near an edge of the texture each
// lane picks the texels its taps span (blendHalfGridPicked16): the downsample's blocks at a
// mip's edge (blendHalfStrided16 takes the others). Inline, so the shader's compiler drops
// the taps a port never reads (the downsample reads five of nine). False, with
// nothing written, when some footprint leaves its window (a step other than one texel, a
// texture smaller than 4x4 near its edge); sampleColorGrid8 takes those.
[[gnu::always_inline]] inline bool blendHalfGrid16(const Texture& t, const LinearTaps16 (&x)[3],
                                                   const LinearTaps16 (&y)[3], simd::Float8x2 (&taps)[9][4]) {
  // Where an axis's taps are consecutive, the window starts at tap 0's first texel along it.
  const bool inPlaceX = axisTapsAreConsecutive16(x, 3), inPlaceY = axisTapsAreConsecutive16(y, 3);
  const bool inPlace = inPlaceX && inPlaceY;
  __m512i startX = x[0].i0, startY = y[0].i0;
  if (!inPlace) {
    if (t.width < 4 || t.height < 4) return false;
    startX = _mm512_min_epi32(startX, _mm512_set1_epi32(t.width - 4));
    startY = _mm512_min_epi32(startY, _mm512_set1_epi32(t.height - 4));
    if (!tapsInWindow16(x, startX) || !tapsInWindow16(y, startY)) return false;
  }
  const uint16_t* texels = t.half.data();
  alignas(64) int start[16];   // each lane's top-left window texel
  storeLaneIndices16(_mm512_add_epi32(_mm512_mullo_epi32(startY, _mm512_set1_epi32(t.width)), startX), start);
  prefetchFootprintRows(t, start, 4);
  __m512 blended[9][4];   // [tap][k]: lanes k | k + 4 | k + 8 | k + 12, rgba each
  if (inPlaceX && !inPlaceY) {   // a block at the top or bottom edge
    blendHalfGridPicked16<true, false>(t, start, x, y, startX, startY, blended);
  } else if (inPlaceY && !inPlaceX) {   // at the left or right edge
    blendHalfGridPicked16<false, true>(t, start, x, y, startX, startY, blended);
  } else if (!inPlace) {   // at a corner: picked along both
    blendHalfGridPicked16<false, false>(t, start, x, y, startX, startY, blended);
  } else {
    for (int k = 0; k < 4; ++k) {
      const __m512i lanes = blockLanes(k);
      __m512 above[3];   // the previous window row's blends, one per tap column
      for (int r = 0; r < 4; ++r) {
        __m512 texel[4];
        windowRowTexels16(texels, start, size_t(r) * size_t(t.width), k, texel);
        for (int i = 0; i < 3; ++i) {
          const __m512 weightX = _mm512_permutexvar_ps(lanes, x[i].weight);
          const __m512 blend = _mm512_fmadd_ps(weightX, _mm512_sub_ps(texel[i + 1], texel[i]), texel[i]);
          if (r > 0) {
            const __m512 weightY = _mm512_permutexvar_ps(lanes, y[r - 1].weight);
            blended[(r - 1) * 3 + i][k] = _mm512_fmadd_ps(weightY, _mm512_sub_ps(blend, above[i]), above[i]);
          }
          above[i] = blend;
        }
      }
    }
  }
  for (int tap = 0; tap < 9; ++tap) lanesToPlanes(blended[tap], taps[tap]);
  return true;
}

}  // namespace raster::sampling
#endif
