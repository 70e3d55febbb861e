// Lookups of RGBA16F textures for Float8x2 lanes held in one 512-bit register, sixteen lanes
// at a time: NEAREST (the G-buffer reads of SSAO and lighting) and bilinear with
// CLAMP_TO_EDGE (the hdr composite and bright pass); the 3x3 grid of such lookups (the bloom
// downsample and upsample) is in sample_half_grid_avx512.h, the upsample's separable form in
// sample_half_separable_avx512.h. Inline, so that a port's lookup costs
// no call and the shader's compiler drops the channels it never reads (SSAO uses xyz); with
// the lookups of sample_color_avx2.cpp the SSAO pass took 13% longer. The wraps, blends and
// the F16C conversion are the 8-lane sampler's (sample_color_avx2.cpp) on 16 lanes at once,
// so every value is the same.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include <algorithm>
#include <bit>
#include <cstdlib>

#include "raster/limits.h"
#include "raster/simd/intrinsics.h"
#include "raster/simd/prefetch.h"
#include "raster/texture/lane_loads_avx512.h"
#include "raster/texture/lookup_filter.h"
#include "raster/texture/texture.h"
#include "raster/texture/wrap_avx512.h"
#include "raster/simd/lane_layout.h"

namespace raster::sampling {

// The texel every lane reads when all their footprints, texels x0..x1 by y0..y1 (indices
// inside the texture), lie in one tile that still holds only its last clear, with a plain
// value (cleared_tiles.h); null otherwise. Lanes of any tile but the first lane's fail.
[[gnu::always_inline]] inline const float* clearedFootprint16(const Texture& t, __m512i x0, __m512i x1, __m512i y0,
                                                              __m512i y1) {
  const ClearedTiles& tiles = t.clearedTiles;
  if (!tiles.any()) return nullptr;
  static_assert(std::has_single_bit(unsigned(limits::kTileSize)));
  constexpr int kShift = std::countr_zero(unsigned(limits::kTileSize));
  auto tileOf = [](__m512i x, __m512i y) {   // (ty << 16) | tx
    return _mm512_or_si512(_mm512_slli_epi32(_mm512_srli_epi32(y, kShift), 16), _mm512_srli_epi32(x, kShift));
  };
  const __m512i low = tileOf(x0, y0), high = tileOf(x1, y1);
  const __m512i first = _mm512_broadcastd_epi32(_mm512_castsi512_si128(low));
  if (_mm512_cmpneq_epi32_mask(low, first) | _mm512_cmpneq_epi32_mask(high, first)) return nullptr;
  const uint32_t tile = uint32_t(_mm_cvtsi128_si32(_mm512_castsi512_si128(low)));
  return tiles.cleared[size_t(tile >> 16) * size_t(tiles.tilesX) + (tile & 0xFFFFu)] ? tiles.value : nullptr;
}

// sampleHalfNearest for two groups at once: each lane's 64-bit texel read with a scalar load
// (two lanes to a 16-byte register), converted and transposed straight into Float8x2 planes,
// with about a third of the shuffles that transposing each group and joining the halves
// takes. The loads replaced two 8-element gathers: on the AMD EPYC Zen 4 host the deferred
// frame, whose SSAO pass then made 16 such lookups a pixel, read 2% faster (16 alternated
// pairs, 12 won). The texture must be RGBA16F.
[[gnu::always_inline]] inline void sampleHalfNearestPair(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc,
                                                         simd::Float8x2 out[4]) {
  const __m512i index = nearestTexelIndex16(s.v, tc.v, t.width, t.height, t.sampler.wrapS, t.sampler.wrapT);
  const long long* texels = reinterpret_cast<const long long*>(t.half.data());
  __m512 v[4];   // texels of lanes 4k..4k + 3, r g b a each
  alignas(64) int at[16];
  storeLaneIndices16(index, at);
  for (int h = 0; h < 2; ++h) {
    const __m512i texel = loadEightLanes64(texels, at, 8 * h, 8);
    v[2 * h] = _mm512_cvtph_ps(_mm512_castsi512_si256(texel));
    v[2 * h + 1] = _mm512_cvtph_ps(_mm512_extracti64x4_epi64(texel, 1));
  }
  // [r of lanes 0-7 | g of lanes 0-7] from v[0] and v[1], [b | a] likewise, and the same
  // for lanes 8-15; then each channel's two halves joined.
  const __m512i redGreen = _mm512_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28, 1, 5, 9, 13, 17, 21, 25, 29);
  const __m512i blueAlpha = _mm512_setr_epi32(2, 6, 10, 14, 18, 22, 26, 30, 3, 7, 11, 15, 19, 23, 27, 31);
  const __m512 rg0 = _mm512_permutex2var_ps(v[0], redGreen, v[1]), rg1 = _mm512_permutex2var_ps(v[2], redGreen, v[3]);
  const __m512 ba0 = _mm512_permutex2var_ps(v[0], blueAlpha, v[1]), ba1 = _mm512_permutex2var_ps(v[2], blueAlpha, v[3]);
  out[0] = simd::Float8x2(_mm512_shuffle_f32x4(rg0, rg1, _MM_SHUFFLE(1, 0, 1, 0)));
  out[1] = simd::Float8x2(_mm512_shuffle_f32x4(rg0, rg1, _MM_SHUFFLE(3, 2, 3, 2)));
  out[2] = simd::Float8x2(_mm512_shuffle_f32x4(ba0, ba1, _MM_SHUFFLE(1, 0, 1, 0)));
  out[3] = simd::Float8x2(_mm512_shuffle_f32x4(ba0, ba1, _MM_SHUFFLE(3, 2, 3, 2)));
}

// Whether sampleHalfNearestPair is this texture's lookup.
inline bool isHalfNearest(const Texture& t) {
  return t.format == TexelFormat::RGBA16F && lookupFilter(t) == Filter::Nearest;
}

// ---- LINEAR with CLAMP_TO_EDGE: the hdr post passes' lookups ---------------------------------

struct LinearTaps16 {
  __m512i i0, i1;   // texel indices along one axis
  __m512 weight;    // weight of i1
};

// wrapLinearClampToEdge8 (linear_taps_avx2.h) on 16 lanes, the same operations in each:
//   c = max(min(coord * size, size) - 0.5, 0);  i0 = floor(c);  weight = c - i0;
//   i1 = min(i0 + 1, size - 1).  A NaN coordinate gives texel size - 1.
// Each lane's size may differ (sizeF, and last = size - 1 as integers): a register that
// holds lanes along x and along y.
[[gnu::always_inline]] inline LinearTaps16 wrapLinearClampToEdge16(__m512 coord, __m512 sizeF, __m512i last) {
  __m512 c = _mm512_mul_ps(coord, sizeF);
  c = _mm512_min_ps(c, sizeF);
  c = _mm512_sub_ps(c, _mm512_set1_ps(0.5f));
  c = _mm512_max_ps(c, _mm512_setzero_ps());
  const __m512 floorC = _mm512_floor_ps(c);
  LinearTaps16 taps;
  taps.i0 = _mm512_cvttps_epi32(floorC);
  taps.weight = _mm512_sub_ps(c, floorC);
  taps.i1 = _mm512_min_epi32(_mm512_add_epi32(taps.i0, _mm512_set1_epi32(1)), last);
  return taps;
}
[[gnu::always_inline]] inline LinearTaps16 wrapLinearClampToEdge16(__m512 coord, int size) {
  return wrapLinearClampToEdge16(coord, _mm512_set1_ps(float(size)), _mm512_set1_epi32(size - 1));
}

// The prefetches ahead of a 4x4 block's lookups (simd/prefetch.h says why): its lanes'
// footprints start at texel index start[lane] and reach `rows` texel rows down. The lanes of
// the block's left column (kBlockRowLeads) hold its four rows, so their footprints' rows are
// the block's. Scalar indices, no reductions: the composite, which is not waiting on memory,
// pays little. The first bloom downsample, whose 1920x1080 source is streamed from the
// last-level cache, had spent most of its time waiting on these loads.
[[gnu::always_inline]] inline void prefetchFootprintRows(const Texture& t, const int* start, int rows) {
  const size_t last = size_t(t.width) * size_t(t.height) - 1;
  for (int lane : kBlockRowLeads) simd::prefetchRowsAhead(t.half.data(), last, size_t(start[lane]), size_t(t.width), rows);
}

// The permutation that spreads lanes k, k + 4, k + 8 and k + 12 of a 16-lane register over
// the four elements of their 128-bit blocks, one lane a block, as blendHalfPairs16 and
// windowRowTexels16 lay the lanes out.
[[gnu::always_inline]] inline __m512i blockLanes(int k) {
  return _mm512_setr_epi32(k, k, k, k, k + 4, k + 4, k + 4, k + 4, k + 8, k + 8, k + 8, k + 8, k + 12, k + 12, k + 12,
                           k + 12);
}

// Four registers of rgba per lane, v[k] holding lanes k | k + 4 | k + 8 | k + 12 (one lane
// per 128-bit block), as Float8x2 planes r, g, b, a: a 4x4 transpose in each block, after
// which block b holds lanes 4b..4b + 3.
[[gnu::always_inline]] inline void lanesToPlanes(const __m512 (&v)[4], simd::Float8x2 out[4]) {
  const __m512 t0 = _mm512_unpacklo_ps(v[0], v[1]), t1 = _mm512_unpackhi_ps(v[0], v[1]);
  const __m512 t2 = _mm512_unpacklo_ps(v[2], v[3]), t3 = _mm512_unpackhi_ps(v[2], v[3]);
  out[0] = simd::Float8x2(_mm512_shuffle_ps(t0, t2, 0x44));
  out[1] = simd::Float8x2(_mm512_shuffle_ps(t0, t2, 0xEE));
  out[2] = simd::Float8x2(_mm512_shuffle_ps(t1, t3, 0x44));
  out[3] = simd::Float8x2(_mm512_shuffle_ps(t1, t3, 0xEE));
}

// Lane K of sixteen 32-bit lanes.
template <int K>
[[gnu::always_inline]] inline int laneOf(__m512i v) {
  return _mm_extract_epi32(_mm512_extracti32x4_epi32(v, K / 4), K % 4);
}

// Bilinear RGBA16F for two groups whose sixteen footprints all lie in one 4x4 texel window,
// as where a 4x4 pixel block samples a texture of half its resolution (the hdr composite's
// bloom lookup: texels x/2 - 1 .. x/2 + 2): four 32-byte loads, one a window row, turned
// into one plane a channel, and each lane's four texels picked from a plane with one permute
// each, in place of blendHalfPairs16's 32 loads and their shuffles (the 1920x1080 composite
// 6% shorter on the AMD EPYC Zen 4 host; picking from the rows with two-source permutes, 4%).
// The blend is blendHalfPairs16's, lane by lane: rows, then columns. False (nothing written)
// when the footprints do not fit, or the texture is under four texels along an axis; the
// lanes of two corners of the block are compared first, so that lookups that spread wider
// pay a few instructions only, and give the window's corner with a third.
[[gnu::always_inline]] inline bool blendHalfWindow16(const Texture& t, const LinearTaps16& x, const LinearTaps16& y,
                                                     simd::Float8x2 out[4]) {
  // Opposite corners of an offscreen target's block (BlockLanes), three columns and a row
  // apart in a window-system buffer's; and that buffer's first row's left pixel.
  constexpr int kFirst = BlockLanes::at(0, 0), kLast = BlockLanes::at(3, 3), kFirstFlipped = BlockLanes::at(0, 0, true);
  const int x0 = laneOf<kFirst>(x.i0), xLast = laneOf<kLast>(x.i0), y0 = laneOf<kFirst>(y.i0), yLast = laneOf<kLast>(y.i0);
  if (t.width < 4 || t.height < 4 || std::abs(x0 - xLast) > 2 || std::abs(y0 - yLast) > 2) return false;
  // The window's corner: the lowest first texel, moved in to keep the window in the texture.
  // Every tap's offset in it must be 0..3 (unsigned: a REPEAT wrap's i1 of 0 fails): the
  // first row's left pixel in either kind of block. Where the lowest texels lie elsewhere
  // (a mirrored lookup), the lanes' least ones.
  __m512i dx0, dx1, dy0, dy1;
  int originX = 0, originY = 0;
  auto fits = [&](int lowX, int lowY) __attribute__((always_inline)) {
    originX = std::min(lowX, t.width - 4);
    originY = std::min(lowY, t.height - 4);
    const __m512i cornerX = _mm512_set1_epi32(originX), cornerY = _mm512_set1_epi32(originY);
    dx0 = _mm512_sub_epi32(x.i0, cornerX);
    dx1 = _mm512_sub_epi32(x.i1, cornerX);
    dy0 = _mm512_sub_epi32(y.i0, cornerY);
    dy1 = _mm512_sub_epi32(y.i1, cornerY);
    const __m512i three = _mm512_set1_epi32(3);
    return !(_mm512_cmpgt_epu32_mask(dx0, three) | _mm512_cmpgt_epu32_mask(dx1, three) |
             _mm512_cmpgt_epu32_mask(dy0, three) | _mm512_cmpgt_epu32_mask(dy1, three));
  };
  if (!fits(std::min(x0, xLast), std::min(y0, laneOf<kFirstFlipped>(y.i0))) &&
      !fits(_mm512_reduce_min_epi32(x.i0), _mm512_reduce_min_epi32(y.i0)))
    return false;
  // The window's rows, texels 0..3 rgba each, turned into one plane a channel: element
  // 4 * column + row (lanesToPlanes' 4x4 transpose in each 128-bit block, block = column).
  const uint16_t* corner = t.half.data() + (size_t(originY) * size_t(t.width) + size_t(originX)) * 4;
  __m512 rows[4];
  for (int r = 0; r < 4; ++r)
    rows[r] = _mm512_cvtph_ps(
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(corner + size_t(r) * size_t(t.width) * 4)));
  simd::Float8x2 planes[4];
  lanesToPlanes(rows, planes);
  auto element = [](__m512i column, __m512i row) __attribute__((always_inline)) {
    return _mm512_add_epi32(_mm512_slli_epi32(column, 2), row);
  };
  const __m512i elements[2][2] = {{element(dx0, dy0), element(dx1, dy0)}, {element(dx0, dy1), element(dx1, dy1)}};
  for (int c = 0; c < 4; ++c) {
    __m512 row[2];
    for (int r = 0; r < 2; ++r) {
      const __m512 left = _mm512_permutexvar_ps(elements[r][0], planes[c].v);
      const __m512 right = _mm512_permutexvar_ps(elements[r][1], planes[c].v);
      row[r] = _mm512_fmadd_ps(x.weight, _mm512_sub_ps(right, left), left);
    }
    out[c] = simd::Float8x2(_mm512_fmadd_ps(y.weight, _mm512_sub_ps(row[1], row[0]), row[0]));
  }
  return true;
}

// Where a 4x4 pixel block reads a texture at its own resolution, each lane's footprint
// starts at texel (X + column, Y + row) of the lane's pixel in the block (BlockLanes,
// lane_layout.h), in a block of an offscreen target or of a window-system buffer ([swapped]).
struct OwnResolutionLanes {
  alignas(64) int column[16];
  alignas(64) int row[2][16];            // [swapped][lane]
  alignas(64) int element[2][16];        // 4 * column + row: the lane's element in a plane
  alignas(64) int rowLanes[2][4][16];    // [swapped][row]: the row's lanes, column c in block c
};
inline constexpr OwnResolutionLanes kOwnResolutionLanes = [] {
  OwnResolutionLanes lanes{};
  for (int lane = 0; lane < BlockLanes::kCount; ++lane) {
    const int column = BlockLanes::column(lane);
    lanes.column[lane] = column;
    for (int swapped = 0; swapped < 2; ++swapped) {
      const int row = lanes.row[swapped][lane] = BlockLanes::row(lane, swapped == 1);
      lanes.element[swapped][lane] = 4 * column + row;
      for (int channel = 0; channel < 4; ++channel) lanes.rowLanes[swapped][row][4 * column + channel] = lane;
    }
  }
  return lanes;
}();

// Bilinear RGBA16F where the lanes read a texture at its own resolution, as a post pass's
// 4x4 block does its own pixels (the hdr composite's scene): the footprints span texels
// X..X + 4 by Y..Y + 4, none at the right or bottom edge. Each of those five texel rows is
// read with two 32-byte loads, texels X..X + 3 (the footprints' left texels) and X + 1..X + 4
// (their right ones), and each pixel row is blended with its four pixels' rgba in one
// register, each lane's weights broadcast over its channels; one 4x4 transpose and a
// permute a channel put the results in lane order: the same operations per lane and channel
// as blendHalfPairs16 (rows, then columns), with ten loads and twenty shuffles where its
// form for this case, a 32-byte load per two lanes' pairs, took sixteen and thirty-two (the
// 640x480 composite 2.234 -> 2.162 ms, 1 thread; 1.198 -> 1.188 ms, 2 threads; 8 alternated
// rounds each). The five rows are prefetched ahead, as blendHalfPairs16's are. False, with
// nothing written, where the lanes do not lie so.
[[gnu::always_inline]] inline bool blendHalfOwnResolution16(const Texture& t, const LinearTaps16& x, const LinearTaps16& y,
                                                            simd::Float8x2 out[4]) {
  const OwnResolutionLanes& lanes = kOwnResolutionLanes;
  // The first row's left pixel, in an offscreen target's block or a window-system buffer's.
  const int originX = laneOf<BlockLanes::at(0, 0)>(x.i0);
  const int originY = std::min(laneOf<BlockLanes::at(0, 0)>(y.i0), laneOf<BlockLanes::at(0, 0, true)>(y.i0));
  if (originX > t.width - 5 || originY > t.height - 5) return false;   // so every i1 is i0 + 1, and the loads fit
  if (_mm512_cmpneq_epi32_mask(_mm512_sub_epi32(x.i0, _mm512_set1_epi32(originX)), _mm512_load_si512(lanes.column)))
    return false;
  const __m512i rows = _mm512_sub_epi32(y.i0, _mm512_set1_epi32(originY));
  int swapped = 0;
  if (_mm512_cmpneq_epi32_mask(rows, _mm512_load_si512(lanes.row[0]))) {
    if (_mm512_cmpneq_epi32_mask(rows, _mm512_load_si512(lanes.row[1]))) return false;
    swapped = 1;
  }
  const size_t first = size_t(originY) * size_t(t.width) + size_t(originX);
  simd::prefetchRowsAhead(t.half.data(), size_t(t.width) * size_t(t.height) - 1, first, size_t(t.width), 5);
  const uint16_t* corner = t.half.data() + first * 4;
  __m512 left[5], right[5];   // texel row r: [texel 0 | 1 | 2 | 3] rgba each, from X and from X + 1
  for (int r = 0; r < 5; ++r) {
    const uint16_t* row = corner + size_t(r) * size_t(t.width) * 4;
    left[r] = _mm512_cvtph_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row)));
    right[r] = _mm512_cvtph_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row + 4)));
  }
  __m512 blended[4];   // pixel row r: its four pixels' rgba
  for (int r = 0; r < 4; ++r) {
    const __m512i rowLanes = _mm512_load_si512(lanes.rowLanes[swapped][r]);
    const __m512 weightX = _mm512_permutexvar_ps(rowLanes, x.weight), weightY = _mm512_permutexvar_ps(rowLanes, y.weight);
    const __m512 top = _mm512_fmadd_ps(weightX, _mm512_sub_ps(right[r], left[r]), left[r]);
    const __m512 bottom = _mm512_fmadd_ps(weightX, _mm512_sub_ps(right[r + 1], left[r + 1]), left[r + 1]);
    blended[r] = _mm512_fmadd_ps(weightY, _mm512_sub_ps(bottom, top), top);
  }
  simd::Float8x2 planes[4];   // element 4 * column + row
  lanesToPlanes(blended, planes);
  const __m512i element = _mm512_load_si512(lanes.element[swapped]);
  for (int c = 0; c < 4; ++c) out[c] = simd::Float8x2(_mm512_permutexvar_ps(element, planes[c].v));
  return true;
}

// Bilinear RGBA16F for two groups at once, blended before the transpose, as the 8-lane
// sampleHalfClampBlendFirst (sample_color_avx2.cpp) does per group: each lane loads its row's
// texel pair [left rgba | right rgba] with one 16-byte load, lanes k, k + 4, k + 8 and k + 12
// blend together in one register, each lane's weights broadcast over its channels (rows,
// then columns: the same operations per lane and channel), and only the four results are
// transposed into Float8x2 planes. Footprints that fit one 4x4 texel window take
// blendHalfWindow16 instead, and a block reading at its own resolution
// blendHalfOwnResolution16. `x` must come from CLAMP_TO_EDGE, where x1 = x0 + 1 except at
// the right edge; there, unless the window took the lookup, this returns false and writes
// nothing (sampleColor8x2 takes those).
[[gnu::always_inline]] inline bool blendHalfPairs16(const Texture& t, const LinearTaps16& x, const LinearTaps16& y,
                                                    simd::Float8x2 out[4]) {
  if (blendHalfWindow16(t, x, y, out) || blendHalfOwnResolution16(t, x, y, out)) return true;
  if (_mm512_cmpeq_epi32_mask(x.i0, _mm512_set1_epi32(t.width - 1))) return false;
  const uint16_t* texels = t.half.data();
  const __m512i width = _mm512_set1_epi32(t.width);
  const __m512i rowStart[2] = {_mm512_add_epi32(_mm512_mullo_epi32(y.i0, width), x.i0),
                               _mm512_add_epi32(_mm512_mullo_epi32(y.i1, width), x.i0)};
  alignas(64) int start[2][16];   // [row y0 | y1][lane]: the lane's left texel
  storeLaneIndices16(rowStart[0], start[0]);
  storeLaneIndices16(rowStart[1], start[1]);
  prefetchFootprintRows(t, start[0], 2);
  // Lane k's row-r pair [left rgba | right rgba] and lane k + 4's, in one register.
  auto pairs = [&](int r, int k) __attribute__((always_inline)) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(texels + size_t(start[r][k]) * 4));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(texels + size_t(start[r][k + 4]) * 4));
    return _mm512_cvtph_ps(_mm256_inserti128_si256(_mm256_castsi128_si256(a), b, 1));
  };
  __m512 blended[4];   // [lane k | k + 4 | k + 8 | k + 12], rgba each
  for (int k = 0; k < 4; ++k) {
    const __m512i lanes = blockLanes(k);
    const __m512 weightX = _mm512_permutexvar_ps(lanes, x.weight), weightY = _mm512_permutexvar_ps(lanes, y.weight);
    __m512 row[2];
    for (int r = 0; r < 2; ++r) {
      const __m512 g0 = pairs(r, k), g1 = pairs(r, k + 8);
      const __m512 left = _mm512_shuffle_f32x4(g0, g1, _MM_SHUFFLE(2, 0, 2, 0));
      const __m512 right = _mm512_shuffle_f32x4(g0, g1, _MM_SHUFFLE(3, 1, 3, 1));
      row[r] = _mm512_fmadd_ps(weightX, _mm512_sub_ps(right, left), left);
    }
    blended[k] = _mm512_fmadd_ps(weightY, _mm512_sub_ps(row[1], row[0]), row[0]);
  }
  lanesToPlanes(blended, out);
  return true;
}

// Whether sampleHalfBilinearPair is this texture's lookup: RGBA16F, LINEAR, CLAMP_TO_EDGE
// along both axes (the hdr scene's post targets), at least two texels wide.
inline bool isHalfBilinearClamp(const Texture& t) {
  return t.format == TexelFormat::RGBA16F && lookupFilter(t) == Filter::Linear &&
         t.sampler.wrapS == Wrap::ClampToEdge && t.sampler.wrapT == Wrap::ClampToEdge && t.width >= 2;
}

// The lookup for such a texture, inline; false (nothing written) when some lane is at the
// right edge and the footprints do not fit one 4x4 window. Footprints in a tile that holds
// only a clear read no texels.
[[gnu::always_inline]] inline bool sampleHalfBilinearPair(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc,
                                                          simd::Float8x2 out[4]) {
  const LinearTaps16 x = wrapLinearClampToEdge16(s.v, t.width), y = wrapLinearClampToEdge16(tc.v, t.height);
  if (const float* value = clearedFootprint16(t, x.i0, x.i1, y.i0, y.i1)) {   // four equal texels blend to theirs
    for (int c = 0; c < 4; ++c) out[c] = simd::Float8x2(_mm512_set1_ps(value[c]));
    return true;
  }
  return blendHalfPairs16(t, x, y, out);
}

}  // namespace raster::sampling
#endif
