// Depth-compare sampling for 8 lanes at once, and the PCF grids whose taps share texels
// (AVX2 gathers), in both compare methods (methods.h): the same operations as
// sample_compare.cpp, lane for lane, so the results are bit-identical (tests/texture holds
// them together). With AVX-512 a Float8x2 pair's grids go through sample_compare_avx512.cpp
// first, all sixteen lanes in one register, and come here only where it declines.
#include "raster/simd/isa.h"
#if RASTER_AVX2
#include <algorithm>
#include <cmath>

#include "raster/methods.h"
#include "raster/simd/intrinsics.h"
#include "raster/texture/format.h"
#include "raster/texture/linear_taps_avx2.h"
#include "raster/texture/sampler.h"

namespace raster::sampling {
namespace {

// The row's two texels x0, x1 with one 64-bit load per lane: CLAMP_TO_EDGE gives x1 = x0 + 1
// except at the right edge (x1 = x0 = W - 1), so each lane loads the pair starting at
// min(x0, W - 2) and takes its left texel from the pair's right one at the edge. Needs W >= 2.
void fetchRowPairs(const int* codes, int width, __m256i rowStart, __m256i x0, __m256i& left, __m256i& right) {
  const __m256i start = _mm256_add_epi32(rowStart, _mm256_min_epi32(x0, _mm256_set1_epi32(width - 2)));
  __m256i lo;
  gatherTexelPairs(codes, start, lo, right);
  left = _mm256_blendv_epi8(lo, right, _mm256_cmpeq_epi32(x0, _mm256_set1_epi32(width - 1)));
}

// The reference depth clamped to [0, 1], NaN -> 0 (maxps returns its second operand on NaN).
__m256 clampRef(__m256 ref) { return _mm256_min_ps(_mm256_max_ps(ref, _mm256_setzero_ps()), _mm256_set1_ps(1.0f)); }

// lp_build_sample_comparefunc, GL_LEQUAL: all bits set where ref <= the texel.
__m256 refPasses(__m256 ref, __m256i code, float scale) {
  return _mm256_cmp_ps(ref, _mm256_mul_ps(_mm256_cvtepi32_ps(code), _mm256_set1_ps(scale)), _CMP_LE_OQ);
}

// nearestTexel of sample_compare.cpp: floor(clamp(coord * size, 0, size - 1)), NaN -> 0
// (maxps returns its second operand on NaN), truncated once clamped.
__m256i nearestTexel8(__m256 coord, int size) {
  const __m256 c = _mm256_max_ps(_mm256_mul_ps(coord, _mm256_set1_ps(float(size))), _mm256_setzero_ps());
  return _mm256_cvttps_epi32(_mm256_min_ps(c, _mm256_set1_ps(float(size - 1))));
}

bool nearestCompare() { return methods::nearestCompare(methods::active().compare); }

}  // namespace

simd::Float8 compareLinearClamp8(const Texture& depth, simd::Float8 s, simd::Float8 t, simd::Float8 ref8) {
  const __m256 ref = clampRef(ref8.v);
  const LinearTaps8 x = wrapLinearClampToEdge8(s.v, depth.width);
  const LinearTaps8 y = wrapLinearClampToEdge8(t.v, depth.height);
  const __m256i width = _mm256_set1_epi32(depth.width);
  const __m256i row0 = _mm256_mullo_epi32(y.i0, width), row1 = _mm256_mullo_epi32(y.i1, width);
  const float scale = depthCodeScale(depth);
  const int* codes = reinterpret_cast<const int*>(depth.depth.data());
  auto passes = [&](__m256i code) { return refPasses(ref, code, scale); };
  __m256 m00, m01, m10, m11;
  if (depth.width >= 2) {
    __m256i c00, c01, c10, c11;
    fetchRowPairs(codes, depth.width, row0, x.i0, c00, c01);
    fetchRowPairs(codes, depth.width, row1, x.i0, c10, c11);
    m00 = passes(c00), m01 = passes(c01), m10 = passes(c10), m11 = passes(c11);
  } else {
    auto fetch = [&](__m256i row, __m256i col) { return _mm256_i32gather_epi32(codes, _mm256_add_epi32(row, col), 4); };
    m00 = passes(fetch(row0, x.i0)), m01 = passes(fetch(row0, x.i1));
    m10 = passes(fetch(row1, x.i0)), m11 = passes(fetch(row1, x.i1));
  }
  const __m256 oneMinusW = _mm256_sub_ps(_mm256_set1_ps(1.0f), x.weight);
  const __m256 r0 = _mm256_add_ps(_mm256_and_ps(x.weight, m01), _mm256_and_ps(oneMinusW, m00));
  const __m256 r1 = _mm256_add_ps(_mm256_and_ps(x.weight, m11), _mm256_and_ps(oneMinusW, m10));
  return simd::Float8(_mm256_fmadd_ps(y.weight, _mm256_sub_ps(r1, r0), r0));
}

simd::Float8 compareNearestClamp8(const Texture& depth, simd::Float8 s, simd::Float8 t, simd::Float8 ref) {
  const __m256i texel = _mm256_add_epi32(_mm256_mullo_epi32(nearestTexel8(t.v, depth.height), _mm256_set1_epi32(depth.width)),
                                         nearestTexel8(s.v, depth.width));
  const __m256i code = _mm256_i32gather_epi32(reinterpret_cast<const int*>(depth.depth.data()), texel, 4);
  return simd::Float8(_mm256_and_ps(refPasses(clampRef(ref.v), code, depthCodeScale(depth)), _mm256_set1_ps(1.0f)));
}

simd::Float8 compareClamp8(const Texture& depth, simd::Float8 s, simd::Float8 t, simd::Float8 ref) {
  return nearestCompare() ? compareNearestClamp8(depth, s, t, ref) : compareLinearClamp8(depth, s, t, ref);
}

namespace {

// The grid's taps one lookup at a time, lookup(depth, s, t, ref) each: the lone lookups of a
// group off the shared paths, in either method. Tap (i, j) is at (origin + k * step) + base,
// the constant folded in float, then one rounding add, as the compiled shader does
// (textureCompareGrid in sampler.h).
template <int R, class Lookup>
void loneTaps8(Lookup lookup, const Texture& depth, simd::Float8 s, simd::Float8 t, float origin, float step,
               simd::Float8 ref, simd::Float8* taps) {
  constexpr int count = 2 * R + 1;
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < count; ++i)
      taps[j * count + i] = lookup(depth, simd::Float8(_mm256_add_ps(s.v, _mm256_set1_ps(origin + float(i - R) * step))),
                                   simd::Float8(_mm256_add_ps(t.v, _mm256_set1_ps(origin + float(j - R) * step))), ref);
}

// The grid of PCF taps at once, for N lane groups. Each tap's coordinate and weights are
// computed as a lone lookup computes them, and each group's taps share one (2R + 2)^2 texel
// window per lane: loaded once, compared once per texel, and each tap blends its own 2x2 of
// those compare results with its own weights, as compareLinearClamp8 would. Usually every
// tap lands on the next texel of its neighbour; near an edge, where clamping piles taps onto
// the same texels (a shadow coordinate outside the map clamps them all), each lane picks the
// compare results of the texels its taps span. Only a group whose footprints leave the
// window (rounding that moves a tap) or a map smaller than the window takes lone lookups.
// With N = 2 both groups' rows are loaded before either blends, so their cache misses
// overlap. The radius is a template argument so that the arrays below are exactly the
// grid's size and its loops unroll (a 3x3 grid's compare results stay in registers instead
// of a 6x6 array on the stack).
template <int N, int R>
void compareGridN(const Texture& depth, const simd::Float8* s, const simd::Float8* t, float origin, float step, const simd::Float8* ref8,
                  simd::Float8* const* taps) {
  constexpr int radius = R, count = 2 * R + 1, texels = count + 1;
  LinearTaps8 x[N][count], y[N][count];
  __m256i startX[N], startY[N];
  bool shared[N], picked[N];
  WindowTaps<count> wx[N], wy[N];
  for (int h = 0; h < N; ++h) {
    for (int k = 0; k < count; ++k) {
      // (origin + k * step) + base: the constant folded in float, then one rounding add, as
      // the compiled shader does (textureCompareGrid in sampler.h).
      const __m256 offset = _mm256_set1_ps(origin + float(k - radius) * step);
      x[h][k] = wrapLinearClampToEdge8(_mm256_add_ps(s[h].v, offset), depth.width);
      y[h][k] = wrapLinearClampToEdge8(_mm256_add_ps(t[h].v, offset), depth.height);
    }
    startX[h] = windowStart(x[h][0], depth.width, texels);   // tap 0's first texel where shared
    startY[h] = windowStart(y[h][0], depth.height, texels);
    shared[h] = tapsAreConsecutive(x[h], y[h], count);
    picked[h] = !shared[h] && depth.width >= texels && depth.height >= texels &&
                tapsInWindow<count>(x[h], startX[h], wx[h]) && tapsInWindow<count>(y[h], startY[h], wy[h]);
    if (!shared[h] && !picked[h]) loneTaps8<R>(compareLinearClamp8, depth, s[h], t[h], origin, step, ref8[h], taps[h]);
  }

  const float scale = depthCodeScale(depth);
  const uint32_t* codes = depth.depth.data();
  __m256 ref[N];
  alignas(32) int start[N][8];   // each lane's top-left texel of the neighbourhood
  for (int h = 0; h < N; ++h) {
    ref[h] = clampRef(ref8[h].v);
    _mm256_store_si256(reinterpret_cast<__m256i*>(start[h]),
                       _mm256_add_epi32(_mm256_mullo_epi32(startY[h], _mm256_set1_epi32(depth.width)), startX[h]));
  }
  // passes[h][r][c]: ref <= texel (r, c) of group h's neighbourhood, per lane.
  __m256 passes[N][texels][texels];
  for (int r = 0; r < texels; ++r) {
    const size_t rowOffset = size_t(r) * size_t(depth.width);
    for (int h = 0; h < N; ++h) {
      if (!shared[h] && !picked[h]) continue;
      // Columns 0-3 of the row, then (for 6 texels) columns 2-5: two 16-byte loads per lane
      // that stay inside the row, as the window does.
      for (int first = 0; first < texels; first += 2) {
        if (first + 4 > texels) break;
        __m256i v[4];   // v[k]: lane k's four codes low, lane k + 4's high
        for (int k = 0; k < 4; ++k)
          v[k] = _mm256_setr_m128i(
              _mm_loadu_si128(reinterpret_cast<const __m128i*>(codes + size_t(start[h][k]) + rowOffset + size_t(first))),
              _mm_loadu_si128(reinterpret_cast<const __m128i*>(codes + size_t(start[h][k + 4]) + rowOffset + size_t(first))));
        const __m256i t0 = _mm256_unpacklo_epi32(v[0], v[1]), t1 = _mm256_unpackhi_epi32(v[0], v[1]);
        const __m256i t2 = _mm256_unpacklo_epi32(v[2], v[3]), t3 = _mm256_unpackhi_epi32(v[2], v[3]);
        const __m256i column[4] = {_mm256_unpacklo_epi64(t0, t2), _mm256_unpackhi_epi64(t0, t2),
                                   _mm256_unpacklo_epi64(t1, t3), _mm256_unpackhi_epi64(t1, t3)};
        for (int c = 0; c < 4; ++c) passes[h][r][first + c] = refPasses(ref[h], column[c], scale);
      }
    }
  }
  for (int h = 0; h < N; ++h) {
    if (picked[h]) {
      // The same blends from each lane's picks: a window row's blend for tap column i from
      // the compare results of the two columns the tap spans, then a tap from the two rows.
      __m256 rowBlend[texels][count];
      for (int r = 0; r < texels; ++r)
        for (int i = 0; i < count; ++i) {
          const __m256 w = x[h][i].weight, oneMinusW = _mm256_sub_ps(_mm256_set1_ps(1.0f), w);
          const __m256 left = pickInWindow(wx[h].first[i], [&](int v) { return passes[h][r][v]; });
          const __m256 right = pickInWindow(wx[h].second[i], [&](int v) { return passes[h][r][v]; });
          rowBlend[r][i] = _mm256_add_ps(_mm256_and_ps(w, right), _mm256_and_ps(oneMinusW, left));
        }
      for (int j = 0; j < count; ++j)
        for (int i = 0; i < count; ++i) {
          const __m256 r0 = pickInWindow(wy[h].first[j], [&](int v) { return rowBlend[v][i]; });
          const __m256 r1 = pickInWindow(wy[h].second[j], [&](int v) { return rowBlend[v][i]; });
          taps[h][j * count + i] = simd::Float8(_mm256_fmadd_ps(y[h][j].weight, _mm256_sub_ps(r1, r0), r0));
        }
      continue;
    }
    if (!shared[h]) continue;
    for (int j = 0; j < count; ++j) {
      for (int i = 0; i < count; ++i) {
        const __m256 w = x[h][i].weight, oneMinusW = _mm256_sub_ps(_mm256_set1_ps(1.0f), w);
        const __m256 r0 = _mm256_add_ps(_mm256_and_ps(w, passes[h][j][i + 1]), _mm256_and_ps(oneMinusW, passes[h][j][i]));
        const __m256 r1 =
            _mm256_add_ps(_mm256_and_ps(w, passes[h][j + 1][i + 1]), _mm256_and_ps(oneMinusW, passes[h][j + 1][i]));
        taps[h][j * count + i] = simd::Float8(_mm256_fmadd_ps(y[h][j].weight, _mm256_sub_ps(r1, r0), r0));
      }
    }
  }
}

}  // namespace

template <int R>
void compareGrid8(const Texture& depth, simd::Float8 s, simd::Float8 t, float origin, float step, simd::Float8 ref,
                  simd::Float8* taps) {
  if (nearestCompare()) return loneTaps8<R>(compareNearestClamp8, depth, s, t, origin, step, ref, taps);
  compareGridN<1, R>(depth, &s, &t, origin, step, &ref, &taps);
}

template <int R>
void compareGrid8x2(const Texture& depth, const simd::Float8 s[2], const simd::Float8 t[2], float origin, float step,
                    const simd::Float8 ref[2], simd::Float8* lo, simd::Float8* hi) {
  if (nearestCompare()) {
    loneTaps8<R>(compareNearestClamp8, depth, s[0], t[0], origin, step, ref[0], lo);
    loneTaps8<R>(compareNearestClamp8, depth, s[1], t[1], origin, step, ref[1], hi);
    return;
  }
  simd::Float8* const taps[2] = {lo, hi};
  compareGridN<2, R>(depth, s, t, origin, step, ref, taps);
}

// The grids the shaders use: 3x3 (shadow) and 5x5 (deferred).
template void compareGrid8<1>(const Texture&, simd::Float8, simd::Float8, float, float, simd::Float8, simd::Float8*);
template void compareGrid8<2>(const Texture&, simd::Float8, simd::Float8, float, float, simd::Float8, simd::Float8*);
template void compareGrid8x2<1>(const Texture&, const simd::Float8*, const simd::Float8*, float, float,
                                const simd::Float8*, simd::Float8*, simd::Float8*);
template void compareGrid8x2<2>(const Texture&, const simd::Float8*, const simd::Float8*, float, float,
                                const simd::Float8*, simd::Float8*, simd::Float8*);

}  // namespace raster::sampling
#endif
