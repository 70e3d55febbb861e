// The separable bloom grids (AVX-512): textureGrid3x3 of an RGBA16F texture on 16 lanes where
// a 4x4 block's coordinates are the same down its columns and along its rows, as a full-screen
// pass's are (the bloom upsample, reading a mip of half its size; the downsample, reading one
// of twice its size). Each tap is then wrapped once a column or row, and each texel row
// blended once per block column instead of once per lane.
// The lane-by-lane grid and the taps this shares with it are in sample_half_grid_avx512.h,
// the windows and transposes in sample_half_avx512.h; lookupColorGrid3x3 (sampler_avx2.h)
// tries this one first. Same operations on the same texels per lane, so the same bits.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include <algorithm>
#include <cmath>

#include "raster/simd/intrinsics.h"
#include "raster/texture/sample_half_grid_avx512.h"
#include "raster/texture/texture.h"
#include "raster/simd/lane_layout.h"

namespace raster::sampling {

// The lanes of a 4x4 block (BlockLanes, lane_layout.h) that the grids below read its
// coordinates from: each lane's column lead (the lane of its column in the first row) and row
// lead (the lane of its row in the first column), and the leads gathered into one register:
// the first row's, left to right (elements 0-3), then the first column's, top to bottom
// (4-7, as kBlockRowLeads orders the rows), then the same again (8-15).
struct BlockLeadLanes {
  alignas(64) int columnLead[16];
  alignas(64) int rowLead[16];
  alignas(64) int leads[16];
};
inline constexpr BlockLeadLanes kBlockLeadLanes = [] {
  BlockLeadLanes lanes{};
  for (int lane = 0; lane < BlockLanes::kCount; ++lane) {
    lanes.columnLead[lane] = BlockLanes::at(BlockLanes::column(lane), 0);
    lanes.rowLead[lane] = BlockLanes::at(0, BlockLanes::row(lane));
    lanes.leads[lane] = lane % 8 < 4 ? BlockLanes::at(lane % 4, 0) : kBlockRowLeads[lane % 4];
  }
  return lanes;
}();
inline constexpr __mmask16 kLeadRows = 0xF0F0;            // the elements of a lead register that hold rows
inline constexpr int kLeadRowElements[4] = {4, 5, 6, 7};   // block row r's element

// textureGrid3x3's taps (bloomGridTaps16) of a block whose coordinates are the same down each
// column and along each row, bit for bit, as a full-screen pass's are (its planes have no
// cross term): tap k of the four columns along x in elements 0-3 and of the four rows along y
// in elements 4-7, each made with the same operations as that lane's own (one wrap a tap for
// the eight, where bloomGridTaps16 wraps sixteen lanes along each axis). Any lane's taps are
// then its column's and its row's. False, with nothing written, where the coordinates differ.
[[gnu::always_inline]] inline bool blockGridTaps16(const Texture& t, __m512 s, __m512 tc, float stepS, float stepT,
                                                   LinearTaps16 (&tap)[3]) {
  const BlockLeadLanes& lanes = kBlockLeadLanes;
  const __m512i sBits = _mm512_castps_si512(s), tBits = _mm512_castps_si512(tc);
  if (_mm512_cmpneq_epi32_mask(_mm512_permutexvar_epi32(_mm512_load_si512(lanes.columnLead), sBits), sBits) |
      _mm512_cmpneq_epi32_mask(_mm512_permutexvar_epi32(_mm512_load_si512(lanes.rowLead), tBits), tBits))
    return false;
  const __m512i leads = _mm512_load_si512(lanes.leads);
  const __m512 coord = _mm512_mask_permutexvar_ps(_mm512_permutexvar_ps(leads, s), kLeadRows, leads, tc);
  const __m512 sizeF = _mm512_mask_blend_ps(kLeadRows, _mm512_set1_ps(float(t.width)), _mm512_set1_ps(float(t.height)));
  const __m512i last = _mm512_mask_blend_epi32(kLeadRows, _mm512_set1_epi32(t.width - 1), _mm512_set1_epi32(t.height - 1));
  for (int k = 0; k < 3; ++k) {   // tap k at coord + float(k - 1) * step, as bloomGridTaps16
    const __m512 offset =
        _mm512_mask_blend_ps(kLeadRows, _mm512_set1_ps(float(k - 1) * stepS), _mm512_set1_ps(float(k - 1) * stepT));
    tap[k] = wrapLinearClampToEdge16(_mm512_add_ps(coord, offset), sizeF, last);
  }
  return true;
}

// The least or the greatest (Least) of three lead registers' elements 0-3 (Block 0: the
// columns') or 4-7 (Block 1: the rows').
template <int Block, bool Least>
[[gnu::always_inline]] inline int acrossLeads(__m512i a, __m512i b, __m512i c) {
  auto op = [](__m128i x, __m128i y) { return Least ? _mm_min_epi32(x, y) : _mm_max_epi32(x, y); };
  auto four = [](__m512i v) { return _mm512_extracti32x4_epi32(v, Block); };
  __m128i v = op(op(four(a), four(b)), four(c));
  v = op(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(1, 0, 3, 2)));
  return _mm_cvtsi128_si32(op(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(2, 3, 0, 1))));
}

// Element c of a lead register over the four channels of [column 0 rgba | 1 | 2 | 3].
[[gnu::always_inline]] inline __m512i columnsOverChannels() {
  return _mm512_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3);
}

// The second half of the separable grids below: with every window row blended along x
// (rowBlend[window row][tap column], [column 0 rgba | 1 | 2 | 3], the window's first row
// texel row originY), each tap row blends two of those per block row, the window rows and
// weight of the row's element of `tap` (blockGridTaps16), and a transpose and one permute a
// channel put the lanes in place. Inline, so that a port's compiler drops the taps and
// channels it never reads.
[[gnu::always_inline]] inline void blendSeparableColumns(const float (*rowBlend)[3][16], const LinearTaps16 (&tap)[3],
                                                         int originY, simd::Float8x2 (&taps)[9][4]) {
  // Each block row's taps along y.
  const __m512i cornerY = _mm512_set1_epi32(originY);
  alignas(64) int top[3][16], bottom[3][16];
  alignas(64) float weightY[3][16];
  for (int j = 0; j < 3; ++j) {
    _mm512_store_si512(top[j], _mm512_sub_epi32(tap[j].i0, cornerY));
    _mm512_store_si512(bottom[j], _mm512_sub_epi32(tap[j].i1, cornerY));
    _mm512_store_ps(weightY[j], tap[j].weight);
  }
  // Lane L's value in a tap's planes sits at element 4 * column + row after lanesToPlanes
  // (the own-resolution lookup's table, an offscreen target's rows).
  const __m512i toLanes = _mm512_load_si512(kOwnResolutionLanes.element[0]);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      __m512 blockRow[4];   // [column 0 rgba | 1 | 2 | 3] of block row r
      for (int r = 0; r < 4; ++r) {
        const int row = kLeadRowElements[r];   // block row r's element of the taps
        const __m512 above = _mm512_load_ps(rowBlend[top[j][row]][i]);
        const __m512 below = _mm512_load_ps(rowBlend[bottom[j][row]][i]);
        blockRow[r] = _mm512_fmadd_ps(_mm512_set1_ps(weightY[j][row]), _mm512_sub_ps(below, above), above);
      }
      simd::Float8x2 planes[4];
      lanesToPlanes(blockRow, planes);
      for (int c = 0; c < 4; ++c) taps[j * 3 + i][c] = simd::Float8x2(_mm512_permutexvar_ps(toLanes, planes[c].v));
    }
}

// textureGrid3x3 of a block whose taps are its columns' along x and its rows' along y
// (blockGridTaps16's `tap`), and span at most 8 texels along each axis: a full-screen pass
// reading a mip of half its size (the bloom upsample: 6x6 texels a block). Then each row
// blend serves a whole block column: per texel row, the 4 columns x 3 taps are blended once
// (three registers of [column 0 rgba | 1 | 2 | 3], their texels picked from the row's 8 with
// two-source permutes), where the lane-by-lane path blends each of the 16 lanes' rows after
// loading and transposing them per lane. Each tap row then blends two of those per block
// row, and a transpose and one permute a channel put the lanes in place. Every lane's values
// come from the same operations on the same texels as before: rows, then columns, the row's
// weight broadcast over its channels. False (nothing written) where the taps spread wider.
[[gnu::always_inline]] inline bool blendHalfSeparable16(const Texture& t, const LinearTaps16 (&tap)[3],
                                                        simd::Float8x2 (&taps)[9][4]) {
  constexpr int kSpan = 8;   // texels along each axis
  if (t.width < kSpan) return false;
  // The window: the lowest first texel along each axis (left moved in so that 8 texels fit).
  const int originX = std::min(acrossLeads<0, true>(tap[0].i0, tap[1].i0, tap[2].i0), t.width - kSpan);
  const int lastX = acrossLeads<0, false>(tap[0].i1, tap[1].i1, tap[2].i1);
  const int originY = acrossLeads<1, true>(tap[0].i0, tap[1].i0, tap[2].i0);
  const int lastY = acrossLeads<1, false>(tap[0].i1, tap[1].i1, tap[2].i1);
  if (lastX - originX >= kSpan || lastY - originY >= kSpan) return false;
  const int rows = lastY - originY + 1;

  // Per tap column: the permute indices of its left and right texels and its weight, for
  // [column 0 rgba | 1 | 2 | 3] (each column's over four channels).
  const __m512i spread = columnsOverChannels();
  const __m512i channel = _mm512_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3);
  const __m512i cornerX = _mm512_set1_epi32(originX);
  auto pickIndex = [&](__m512i texel) __attribute__((always_inline)) {
    return _mm512_add_epi32(_mm512_slli_epi32(_mm512_permutexvar_epi32(spread, _mm512_sub_epi32(texel, cornerX)), 2),
                            channel);
  };
  __m512i leftIndex[3], rightIndex[3];
  __m512 weightX[3];
  for (int i = 0; i < 3; ++i) {
    leftIndex[i] = pickIndex(tap[i].i0);
    rightIndex[i] = pickIndex(tap[i].i1);
    weightX[i] = _mm512_permutexvar_ps(spread, tap[i].weight);
  }
  // Row blends of every window row: rowBlend[row][tap column], [column 0 rgba | 1 | 2 | 3].
  alignas(64) float rowBlend[kSpan][3][16];
  const uint16_t* texels = t.half.data() + (size_t(originY) * size_t(t.width) + size_t(originX)) * 4;
  for (int r = 0; r < rows; ++r) {
    const uint16_t* row = texels + size_t(r) * size_t(t.width) * 4;
    const __m512 low = _mm512_cvtph_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row)));        // texels 0-3
    const __m512 high = _mm512_cvtph_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row + 16)));  // 4-7
    for (int i = 0; i < 3; ++i) {
      const __m512 left = _mm512_permutex2var_ps(low, leftIndex[i], high);
      const __m512 right = _mm512_permutex2var_ps(low, rightIndex[i], high);
      _mm512_store_ps(rowBlend[r][i], _mm512_fmadd_ps(weightX[i], _mm512_sub_ps(right, left), left));
    }
  }
  blendSeparableColumns(rowBlend, tap, originY, taps);
  return true;
}

// blendHalfSeparable16 for a grid whose block columns lie two texels apart, as where a
// full-screen pass reads a mip of twice its size (the bloom downsample: 10x10 texels a block,
// wider than that path's 8), from blockGridTaps16's taps. It takes a block only where tap i
// of column c spans window texels 2c + i and 2c + i + 1: then a window row's ten texels are
// three loads, and each tap column's texels for the four block columns one 128-bit shuffle
// of them (texels 0 2 4 6, 1 3 5 7, 2 4 6 8 and 3 5 7 9, each shared by two taps), where the
// lane-by-lane grid loads, converts and transposes each lane's 4x4 window. The same
// operations on the same texels per lane (rows, then columns), so the same bits. False
// (nothing written) elsewhere: near an edge, where clamping piles taps up; in a mip of odd
// size, where the step drifts off two texels.
[[gnu::always_inline]] inline bool blendHalfStrided16(const Texture& t, const LinearTaps16 (&tap)[3],
                                                      simd::Float8x2 (&taps)[9][4]) {
  // Along x, tap k of column c spans texels originX + 2c + k and the next.
  constexpr __mmask16 kColumns = 0x000F;
  const int originX = _mm_cvtsi128_si32(_mm512_castsi512_si128(tap[0].i0));
  const __m512i first =
      _mm512_add_epi32(_mm512_set1_epi32(originX), _mm512_setr_epi32(0, 2, 4, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
  for (int k = 0; k < 3; ++k) {
    const __m512i left = _mm512_add_epi32(first, _mm512_set1_epi32(k));
    if (_mm512_mask_cmpeq_epi32_mask(kColumns, tap[k].i0, left) != kColumns ||
        _mm512_mask_cmpeq_epi32_mask(kColumns, tap[k].i1, _mm512_add_epi32(left, _mm512_set1_epi32(1))) != kColumns)
      return false;
  }
  // Along y, the window's rows: the least first texel and the greatest second one of the rows'.
  const int originY = acrossLeads<1, true>(tap[0].i0, tap[1].i0, tap[2].i0);
  const int lastY = acrossLeads<1, false>(tap[0].i1, tap[1].i1, tap[2].i1);
  constexpr int kMaxRows = 12;   // window rows: 10 for the downsample's blocks
  if (lastY - originY >= kMaxRows) return false;
  const int rows = lastY - originY + 1;

  // Each tap column's weight for [column 0 rgba | 1 | 2 | 3].
  const __m512i spread = columnsOverChannels();
  __m512 weightX[3];
  for (int i = 0; i < 3; ++i) weightX[i] = _mm512_permutexvar_ps(spread, tap[i].weight);
  const size_t firstTexel = size_t(originY) * size_t(t.width) + size_t(originX);
  simd::prefetchRowsAhead(t.half.data(), size_t(t.width) * size_t(t.height) - 1, firstTexel, size_t(t.width), rows);
  // Row blends of every window row: rowBlend[row][tap column], [column 0 rgba | 1 | 2 | 3].
  // Window texels 0-9 lie in the texture: texel 9 is tap 2's second texel in column 3.
  alignas(64) float rowBlend[kMaxRows][3][16];
  const uint16_t* texels = t.half.data() + firstTexel * 4;
  for (int r = 0; r < rows; ++r) {
    const uint16_t* row = texels + size_t(r) * size_t(t.width) * 4;
    // Texels 0-3 (a), 4-7 (b), 8-9 (c), and the window two texels on: 2-5 (a2), 6-9 (b2).
    const __m512 a = _mm512_cvtph_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row)));
    const __m512 b = _mm512_cvtph_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row + 16)));
    const __m512 c =
        _mm512_castps256_ps512(_mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(row + 32))));
    const __m512 a2 = _mm512_castsi512_ps(_mm512_alignr_epi64(_mm512_castps_si512(b), _mm512_castps_si512(a), 4));
    const __m512 b2 = _mm512_castsi512_ps(_mm512_alignr_epi64(_mm512_castps_si512(c), _mm512_castps_si512(b), 4));
    const __m512 even[2] = {_mm512_shuffle_f32x4(a, b, _MM_SHUFFLE(2, 0, 2, 0)),      // texels 0 2 4 6
                            _mm512_shuffle_f32x4(a2, b2, _MM_SHUFFLE(2, 0, 2, 0))};   // 2 4 6 8
    const __m512 odd[2] = {_mm512_shuffle_f32x4(a, b, _MM_SHUFFLE(3, 1, 3, 1)),       // 1 3 5 7
                           _mm512_shuffle_f32x4(a2, b2, _MM_SHUFFLE(3, 1, 3, 1))};    // 3 5 7 9
    // Tap i of column c spans texels 2c + i and 2c + i + 1.
    const __m512 left[3] = {even[0], odd[0], even[1]}, right[3] = {odd[0], even[1], odd[1]};
    for (int i = 0; i < 3; ++i)
      _mm512_store_ps(rowBlend[r][i], _mm512_fmadd_ps(weightX[i], _mm512_sub_ps(right[i], left[i]), left[i]));
  }
  blendSeparableColumns(rowBlend, tap, originY, taps);
  return true;
}

// blendHalfSeparable16 for textureGrid3x3's taps, out of line: the upsample pays one call a
// block, and the downsample, which never takes this path, carries none of its code.
[[gnu::noinline]] inline bool blendHalfGridSeparable16(const Texture& t, __m512 s, __m512 tc, float stepS, float stepT,
                                                       simd::Float8x2 (&taps)[9][4]) {
  LinearTaps16 tap[3];
  return blockGridTaps16(t, s, tc, stepS, stepT, tap) && blendHalfSeparable16(t, tap, taps);
}

// blendHalfStrided16 for textureGrid3x3's taps, inline: the downsample's compiler drops the
// taps and channels it never reads.
[[gnu::always_inline]] inline bool blendHalfGridStrided16(const Texture& t, __m512 s, __m512 tc, float stepS,
                                                          float stepT, simd::Float8x2 (&taps)[9][4]) {
  LinearTaps16 tap[3];
  return blockGridTaps16(t, s, tc, stepS, stepT, tap) && blendHalfStrided16(t, tap, taps);
}

// Whether blendHalfGridSeparable16 may take a grid, from two lanes' centre coordinates: the
// block's first and last columns (lanes 0 and 5) at most 3 texels apart, and its first and
// last rows (lanes 0 and 10). A block that spreads wider (the downsample's grid, 10 texels a
// block) does not fit 8 texels; this spares it the call. Only a shortcut: the call checks.
[[gnu::always_inline]] inline bool mayBeSeparable16(const Texture& t, __m512 s, __m512 tc) {
  const float s0 = _mm512_cvtss_f32(s), s5 = _mm_cvtss_f32(_mm_movehdup_ps(_mm512_extractf32x4_ps(s, 1)));
  const float t0 = _mm512_cvtss_f32(tc), t10 = _mm_cvtss_f32(_mm_movehl_ps(_mm512_extractf32x4_ps(tc, 2), _mm512_extractf32x4_ps(tc, 2)));
  return std::fabs(s5 - s0) * float(t.width) <= 3.0f && std::fabs(t10 - t0) * float(t.height) <= 3.0f;
}

}  // namespace raster::sampling
#endif
