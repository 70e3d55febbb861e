// The PCF grids of a Float8x2 pair in 512-bit registers (AVX-512): both lane groups' windows
// read, compared and blended sixteen lanes at once, in both compare methods (methods.h),
// with the same operations per lane as compareGridN (sample_compare_avx2.cpp), so the
// results are bit-identical (tests/texture holds them together). A pair whose every window
// passes or fails the compare whole takes taps of 1 or +0 without blending. Where a grid
// declines (a footprint that leaves its window, a map smaller than the window), the 8-lane
// grids of sample_compare_avx2.cpp take the pair.
#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include <algorithm>

#include "raster/methods.h"
#include "raster/simd/intrinsics.h"
#include "raster/texture/sample_half_grid_avx512.h"
#include "raster/texture/sampler.h"

namespace raster::sampling {
namespace {

// Four codes from each of two row pointers, a's in the low 128 bits.
[[gnu::always_inline]] inline __m256i rowsOfTwoLanes(const uint32_t* a, const uint32_t* b) {
  return _mm256_setr_m128i(_mm_loadu_si128(reinterpret_cast<const __m128i*>(a)),
                           _mm_loadu_si128(reinterpret_cast<const __m128i*>(b)));
}

// Four codes of each lane from its row pointer: lanes k, k + 4, k + 8 and k + 12 in one
// register, the 128-bit block of each.
__m512i rowsOfFourLanes(const uint32_t* const (&lane)[4]) {
  return _mm512_inserti64x4(_mm512_castsi256_si512(rowsOfTwoLanes(lane[0], lane[1])), rowsOfTwoLanes(lane[2], lane[3]), 1);
}

// Columns `first` to Cols - 1 of v, v[k] as rowsOfFourLanes reads it: codes[first + c]
// holds column c of the sixteen lanes, lane k in element k.
template <int Cols>
void columnsOfFourLanes(const __m512i (&v)[4], int first, __m512i (&codes)[Cols]) {
  const __m512i t0 = _mm512_unpacklo_epi32(v[0], v[1]), t1 = _mm512_unpackhi_epi32(v[0], v[1]);
  const __m512i t2 = _mm512_unpacklo_epi32(v[2], v[3]), t3 = _mm512_unpackhi_epi32(v[2], v[3]);
  const __m512i column[4] = {_mm512_unpacklo_epi64(t0, t2), _mm512_unpackhi_epi64(t0, t2),
                             _mm512_unpacklo_epi64(t1, t3), _mm512_unpackhi_epi64(t1, t3)};
  for (int c = 0; c < 4 && first + c < Cols; ++c) codes[first + c] = column[c];
}

// codes[r][c] = texel (r, c) of each lane's Rows x Cols window from start[lane], 16 lanes:
// each window row is read with 16-byte loads of four codes, columns 0-3, then 4-7 or the
// last four, so a window narrower than four reads codes past its right edge (the caller
// makes sure they lie in the map) and leaves them out.
//
// A window of up to four rows (the 3x3 grid's) is read four lanes at a time down all its
// rows, with four row pointers live: read a row at a time, the sixteen lanes' pointers did
// not fit the general registers, and GCC moved them in and out of vector registers on every
// row (docs/notes/2026-11-29-pcf-window-lane-by-lane.md). Taller windows (the 5x5
// grid's six rows, 24 registers of rows) measured slower that way than a row at a time.
template <int Rows, int Cols>
[[gnu::always_inline]] inline void windowCodes16(const Texture& depth, const int (&start)[16],
                                                 __m512i (&codes)[Rows][Cols]) {
  const uint32_t* texels = depth.depth.data();
  const size_t width = size_t(depth.width);
  // Lanes k, k + 4, k + 8 and k + 12 of window row r from column `first` on.
  auto lanePointers = [&](int k, int r, int first, const uint32_t* (&lane)[4]) {
    for (int q = 0; q < 4; ++q) lane[q] = texels + size_t(start[k + 4 * q]) + size_t(r) * width + size_t(first);
  };
  auto firstColumn = [](int next) { return std::min(next, std::max(Cols - 4, 0)); };
  if constexpr (Rows <= 4) {
    for (int next = 0; next < Cols; next += 4) {
      __m512i v[Rows][4];   // v[r][k]: row r of lanes k, k + 4, k + 8, k + 12
      for (int k = 0; k < 4; ++k) {
        const uint32_t* lane[4];
        lanePointers(k, 0, firstColumn(next), lane);
        for (int r = 0; r < Rows; ++r) {
          v[r][k] = rowsOfFourLanes(lane);
          for (const uint32_t*& p : lane) p += width;
        }
      }
      for (int r = 0; r < Rows; ++r) columnsOfFourLanes<Cols>(v[r], firstColumn(next), codes[r]);
    }
  } else {
    for (int r = 0; r < Rows; ++r)
      for (int next = 0; next < Cols; next += 4) {
        __m512i v[4];
        for (int k = 0; k < 4; ++k) {
          const uint32_t* lane[4];
          lanePointers(k, r, firstColumn(next), lane);
          v[k] = rowsOfFourLanes(lane);
        }
        columnsOfFourLanes<Cols>(v, firstColumn(next), codes[r]);
      }
  }
}

// A depth code read as a float in [0, 1] (refPasses' unorm conversion), 16 lanes.
[[gnu::always_inline]] inline __m512 codeDepth16(__m512i code, __m512 scale) {
  return _mm512_mul_ps(_mm512_cvtepi32_ps(code), scale);
}

// passes[r][c] = ref <= texel (r, c) of each lane's window (refPasses, 16 lanes).
template <int Rows, int Cols>
[[gnu::always_inline]] inline void windowPasses16(const Texture& depth, const __m512i (&codes)[Rows][Cols], __m512 ref,
                                                  __mmask16 (&passes)[Rows][Cols]) {
  const __m512 scale = _mm512_set1_ps(depthCodeScale(depth));
  for (int r = 0; r < Rows; ++r)
    for (int c = 0; c < Cols; ++c) passes[r][c] = _mm512_cmp_ps_mask(ref, codeDepth16(codes[r][c], scale), _CMP_LE_OQ);
}

// Where each lane's window passes the compare at every texel or fails it at every one, each
// of the lane's taps is 1 or +0 whatever its weights, in every form of the grid (a row's
// blend is w + (1 - w) = 1 for any weight in [0, 1], or +0 + +0; a tap blends two equal
// rows to that value). A code reads as a float through a rounded product, which keeps
// their order, so comparing with the window's least and greatest codes is comparing with
// every code. In the shadow scene about 99% of the pairs' windows are uniform: the compare
// changes only along a shadow's edge (docs/notes/2026-11-21-what-made-it-faster.md,
// "PCF windows that pass or fail whole").
// True, with the `tapCount` taps written (1 where the lane's window passes, +0 where it
// fails), when every lane's window is uniform; false, with nothing written, otherwise.
[[gnu::always_inline]] inline bool uniformTaps16(const Texture& depth, __m512i least, __m512i greatest, __m512 ref,
                                                 int tapCount, simd::Float8x2* taps) {
  const __m512 scale = _mm512_set1_ps(depthCodeScale(depth));
  const __mmask16 pass = _mm512_cmp_ps_mask(ref, codeDepth16(least, scale), _CMP_LE_OQ);
  const __mmask16 fail = _mm512_cmp_ps_mask(ref, codeDepth16(greatest, scale), _CMP_GT_OQ);
  if (__mmask16(pass | fail) != 0xFFFF) return false;
  const simd::Float8x2 value(_mm512_maskz_mov_ps(pass, _mm512_set1_ps(1.0f)));
  for (int k = 0; k < tapCount; ++k) taps[k] = value;
  return true;
}

// uniformTaps16 from a window's codes as windowCodes16 reads them.
template <int Rows, int Cols>
[[gnu::always_inline]] inline bool uniformTaps16(const Texture& depth, const __m512i (&codes)[Rows][Cols], __m512 ref,
                                                 int tapCount, simd::Float8x2* taps) {
  __m512i least = codes[0][0], greatest = codes[0][0];
  for (int r = 0; r < Rows; ++r)
    for (int c = 0; c < Cols; ++c) {
      least = _mm512_min_epu32(least, codes[r][c]);
      greatest = _mm512_max_epu32(greatest, codes[r][c]);
    }
  return uniformTaps16(depth, least, greatest, ref, tapCount, taps);
}

// The least and greatest code of each lane's 4x4 window from start[lane], 16 lanes, lane k
// in element k: the same bounds uniformTaps16 takes from windowCodes16's 4x4 codes, found
// before any transpose. Each 16-byte window row is loaded into one half of a 256-bit
// register (lanes k and k + 4, or k + 8 and k + 12), and the rows are reduced there, so
// only the reduced rows are joined into 512-bit registers and transposed. Joining every row
// first, as windowCodes16 must, took three times the shuffles; those all run on one port
// (docs/notes/2026-11-29-pcf-uniform-test-before-transpose.md).
[[gnu::always_inline]] inline void windowBounds4x4(const Texture& depth, const int (&start)[16], __m512i& least,
                                                   __m512i& greatest) {
  const uint32_t* texels = depth.depth.data();
  const size_t width = size_t(depth.width);
  __m512i rowLeast[4], rowGreatest[4];   // as rowsOfFourLanes: lanes k, k + 4, k + 8, k + 12
  for (int k = 0; k < 4; ++k) {
    const uint32_t* lane[4];
    for (int q = 0; q < 4; ++q) lane[q] = texels + size_t(start[k + 4 * q]);
    auto rowPair = [&](int first, size_t r) { return rowsOfTwoLanes(lane[first] + r * width, lane[first + 1] + r * width); };
    __m256i lowLeast = rowPair(0, 0), highLeast = rowPair(2, 0);
    __m256i lowGreatest = lowLeast, highGreatest = highLeast;
    for (size_t r = 1; r < 4; ++r) {
      const __m256i low = rowPair(0, r), high = rowPair(2, r);
      lowLeast = _mm256_min_epu32(lowLeast, low);
      lowGreatest = _mm256_max_epu32(lowGreatest, low);
      highLeast = _mm256_min_epu32(highLeast, high);
      highGreatest = _mm256_max_epu32(highGreatest, high);
    }
    rowLeast[k] = _mm512_inserti64x4(_mm512_castsi256_si512(lowLeast), highLeast, 1);
    rowGreatest[k] = _mm512_inserti64x4(_mm512_castsi256_si512(lowGreatest), highGreatest, 1);
  }
  __m512i columnLeast[4], columnGreatest[4];
  columnsOfFourLanes<4>(rowLeast, 0, columnLeast);
  columnsOfFourLanes<4>(rowGreatest, 0, columnGreatest);
  least = _mm512_min_epu32(_mm512_min_epu32(columnLeast[0], columnLeast[1]), _mm512_min_epu32(columnLeast[2], columnLeast[3]));
  greatest = _mm512_max_epu32(_mm512_max_epu32(columnGreatest[0], columnGreatest[1]),
                              _mm512_max_epu32(columnGreatest[2], columnGreatest[3]));
}

// Each lane's window origin, start[lane] = y * width + x, in memory to be read as scalars.
void storeWindowStarts(const Texture& depth, __m512i x, __m512i y, int (&start)[16]) {
  storeLaneIndices16(_mm512_add_epi32(_mm512_mullo_epi32(y, _mm512_set1_epi32(depth.width)), x), start);
}

__m512 clampRef16(__m512 ref) { return _mm512_min_ps(_mm512_max_ps(ref, _mm512_setzero_ps()), _mm512_set1_ps(1.0f)); }

// nearestTexel8 on 16 lanes.
__m512i nearestTexel16(__m512 coord, int size) {
  const __m512 c = _mm512_max_ps(_mm512_mul_ps(coord, _mm512_set1_ps(float(size))), _mm512_setzero_ps());
  return _mm512_cvttps_epi32(_mm512_min_ps(c, _mm512_set1_ps(float(size - 1))));
}

// compare=nearest's grid for a Float8x2 pair: tap (i, j) is the compare of one texel, and
// where every lane's taps land on consecutive texels (no edge between them) those are one
// count x count window per lane, loaded a row at a time and compared once per texel. False,
// with nothing written, otherwise.
template <int R>
bool compareNearestGrid16(const Texture& depth, simd::Float8x2 s, simd::Float8x2 t, float origin, float step,
                          simd::Float8x2 ref, simd::Float8x2* taps) {
  constexpr int count = 2 * R + 1;
  __m512i x[count], y[count];
  for (int k = 0; k < count; ++k) {
    const __m512 offset = _mm512_set1_ps(origin + float(k - R) * step);   // as compareGridN
    x[k] = nearestTexel16(_mm512_add_ps(s.v, offset), depth.width);
    y[k] = nearestTexel16(_mm512_add_ps(t.v, offset), depth.height);
  }
  __mmask16 consecutive = 0xFFFF;
  for (int k = 1; k < count; ++k)
    consecutive &= _mm512_cmpeq_epi32_mask(x[k], _mm512_add_epi32(x[0], _mm512_set1_epi32(k))) &
                   _mm512_cmpeq_epi32_mask(y[k], _mm512_add_epi32(y[0], _mm512_set1_epi32(k)));
  // A 3-wide window's rows are read four codes wide: the fourth must lie in the row.
  if (count < 4) consecutive &= _mm512_cmplt_epi32_mask(x[0], _mm512_set1_epi32(depth.width - 3));
  if (consecutive != 0xFFFF) return false;

  alignas(64) int start[16];
  storeWindowStarts(depth, x[0], y[0], start);
  __m512i codes[count][count];
  windowCodes16(depth, start, codes);
  const __m512 clampedRef = clampRef16(ref.v);
  if (uniformTaps16(depth, codes, clampedRef, count * count, taps)) return true;
  __mmask16 passes[count][count];
  windowPasses16(depth, codes, clampedRef, passes);
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < count; ++i) taps[j * count + i] = simd::Float8x2(_mm512_maskz_mov_ps(passes[j][i], _mm512_set1_ps(1.0f)));
  return true;
}

}  // namespace

// compareGridN for both groups in 512-bit registers, lane k of Float8x2 in element k: the
// same tap coordinates (wrapLinearClampToEdge16 is wrapLinearClampToEdge8 on 16 lanes), the
// same window loads, compares and blends per lane, half the instructions. Near a map edge
// (a shadow coordinate outside the map clamps every tap) each lane picks the compare results
// of the texels its taps span, as compareGridN does per 8 lanes. False, with nothing
// written, when some footprint leaves its window (rounding that moves a tap, a step that is
// not one texel) or the map is smaller than the window. compare=nearest takes
// compareNearestGrid16.
template <int R>
bool compareGrid16(const Texture& depth, simd::Float8x2 s, simd::Float8x2 t, float origin, float step, simd::Float8x2 ref16,
                   simd::Float8x2* taps) {
  if (methods::nearestCompare(methods::active().compare)) return compareNearestGrid16<R>(depth, s, t, origin, step, ref16, taps);
  constexpr int count = 2 * R + 1, texels = count + 1;
  LinearTaps16 x[count], y[count];
  compareGridTaps16<R>(depth, s.v, t.v, origin, step, x, y);
  const bool inPlace = tapsAreConsecutive16(x, y, count);   // then the window starts at tap 0's first texel
  __m512i startX = x[0].i0, startY = y[0].i0;
  if (!inPlace) {
    if (depth.width < texels || depth.height < texels) return false;
    startX = _mm512_min_epi32(startX, _mm512_set1_epi32(depth.width - texels));   // windowStart
    startY = _mm512_min_epi32(startY, _mm512_set1_epi32(depth.height - texels));
    if (!tapsInWindow16(x, startX) || !tapsInWindow16(y, startY)) return false;
  }

  alignas(64) int start[16];   // each lane's top-left texel of the neighbourhood
  storeWindowStarts(depth, startX, startY, start);
  const __m512 ref = clampRef16(ref16.v);
  if constexpr (texels == 4) {   // the 3x3 grid: its bounds first, the codes only where they are needed
    __m512i least, greatest;
    windowBounds4x4(depth, start, least, greatest);
    if (uniformTaps16(depth, least, greatest, ref, count * count, taps)) return true;
  }
  __m512i codes[texels][texels];   // codes[r][c]: texel (r, c) of the lane's neighbourhood
  windowCodes16(depth, start, codes);
  // The 5x5 grid takes its bounds from the codes: read first, a 6x6 window's bounds cost more
  // than they saved (docs/notes/2026-11-25-tried-and-not-kept.md, "The bounds-first uniform
  // test for the 5x5 grid too").
  if constexpr (texels != 4)
    if (uniformTaps16(depth, codes, ref, count * count, taps)) return true;
  __mmask16 passes[texels][texels];   // passes[r][c]: ref <= texel (r, c) of the lane's neighbourhood
  windowPasses16(depth, codes, ref, passes);
  if (inPlace) {
    // The blends of compareGridN. A row's blend for tap column i, (w and right) + ((1 - w)
    // and left), is the left term with w added where the right texel passes: the same sum
    // where it does, and where it does not the left term alone, which +0 + it is (the left
    // term is +0 or 1 - w >= +0). Each window row's blends serve the taps above and below
    // it; two rows of them are live at a time.
    __m512 oneMinusW[count];
    for (int i = 0; i < count; ++i) oneMinusW[i] = _mm512_sub_ps(_mm512_set1_ps(1.0f), x[i].weight);
    auto blendRow = [&](int r, __m512 (&out)[count]) {
      for (int i = 0; i < count; ++i) {
        const __m512 left = _mm512_maskz_mov_ps(passes[r][i], oneMinusW[i]);
        out[i] = _mm512_mask_add_ps(left, passes[r][i + 1], left, x[i].weight);
      }
    };
    __m512 above[count], below[count];
    blendRow(0, above);
    for (int j = 0; j < count; ++j) {
      blendRow(j + 1, below);
      for (int i = 0; i < count; ++i) {
        taps[j * count + i] = simd::Float8x2(_mm512_fmadd_ps(y[j].weight, _mm512_sub_ps(below[i], above[i]), above[i]));
        above[i] = below[i];
      }
    }
    return true;
  }
  // Near an edge, compareGridN's picked blends: the lanes whose tap starts (ends) at window
  // texel v, per tap and axis; a window row's blend for tap column i from the compare results
  // of the two columns the tap spans, then a tap from the two rows it spans.
  auto windowTexels = [](const LinearTaps16& tap, __m512i from, __mmask16 (&first)[texels], __mmask16 (&second)[texels]) {
    const __m512i at[2] = {_mm512_sub_epi32(tap.i0, from), _mm512_sub_epi32(tap.i1, from)};
    for (int v = 0; v < texels; ++v) {
      first[v] = _mm512_cmpeq_epi32_mask(at[0], _mm512_set1_epi32(v));
      second[v] = _mm512_cmpeq_epi32_mask(at[1], _mm512_set1_epi32(v));
    }
  };
  auto pickPasses = [](const __mmask16 (&row)[texels], const __mmask16 (&is)[texels]) {
    __mmask16 picked = 0;
    for (int v = 0; v < texels; ++v) picked |= row[v] & is[v];
    return picked;
  };
  __m512 rowBlend[count][texels];   // [tap column][window row]
  for (int i = 0; i < count; ++i) {
    __mmask16 left[texels], right[texels];
    windowTexels(x[i], startX, left, right);
    const __m512 w = x[i].weight, oneMinusW = _mm512_sub_ps(_mm512_set1_ps(1.0f), w);
    for (int r = 0; r < texels; ++r)
      rowBlend[i][r] = _mm512_add_ps(_mm512_maskz_mov_ps(pickPasses(passes[r], right), w),
                                     _mm512_maskz_mov_ps(pickPasses(passes[r], left), oneMinusW));
  }
  for (int j = 0; j < count; ++j) {
    __mmask16 top[texels], bottom[texels];
    windowTexels(y[j], startY, top, bottom);
    for (int i = 0; i < count; ++i) {
      __m512 r0 = rowBlend[i][0], r1 = rowBlend[i][0];
      for (int v = 1; v < texels; ++v) {
        r0 = _mm512_mask_mov_ps(r0, top[v], rowBlend[i][v]);
        r1 = _mm512_mask_mov_ps(r1, bottom[v], rowBlend[i][v]);
      }
      taps[j * count + i] = simd::Float8x2(_mm512_fmadd_ps(y[j].weight, _mm512_sub_ps(r1, r0), r0));
    }
  }
  return true;
}

template bool compareGrid16<1>(const Texture&, simd::Float8x2, simd::Float8x2, float, float, simd::Float8x2, simd::Float8x2*);
template bool compareGrid16<2>(const Texture&, simd::Float8x2, simd::Float8x2, float, float, simd::Float8x2, simd::Float8x2*);

}  // namespace raster::sampling
#endif
