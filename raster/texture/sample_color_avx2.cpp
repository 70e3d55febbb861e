// Colour texture sampling for 8 lanes at once (AVX2 gathers, F16C conversion): the same
// operations as the scalar reference in sample_color.cpp, lane for lane, so the results
// are bit-identical (tests/texture/sampler_test.cpp holds the two together). This file holds
// the half-float and float paths and the dispatch; the RGBA8 fixed-point path is
// sample_rgba8_avx2.h, the wraps both use wrap_avx2.h.
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#include "raster/simd/prefetch.h"

#include "raster/texture/footprint_strips.h"
#include "raster/texture/linear_taps_avx2.h"
#include "raster/texture/lookup_filter.h"
#include "raster/texture/sample_half_avx512.h"
#include "raster/texture/sample_rgba8_avx2.h"
#include "raster/texture/sampler.h"

namespace raster::sampling {
namespace {

using namespace avx2;

// ---- half-float textures (SoA path) ------------------------------------------------------

[[gnu::always_inline]] inline LinearTaps8 wrapLinearFloat(__m256 coord, int size, Wrap wrap) {
  const __m256 sizeF = splat(float(size));
  const __m256i last = splat(size - 1);
  LinearTaps8 taps;
  if (wrap == Wrap::Repeat && isPowerOfTwo(size)) {
    const __m256 c = _mm256_sub_ps(_mm256_mul_ps(coord, sizeF), splat(0.5f));
    const __m256 floorC = _mm256_floor_ps(c);
    const __m256i i = _mm256_cvttps_epi32(floorC);
    taps.i0 = _mm256_and_si256(i, last);
    taps.i1 = _mm256_and_si256(_mm256_add_epi32(i, splat(1)), last);
    taps.weight = _mm256_sub_ps(c, floorC);
    return taps;
  }
  if (wrap == Wrap::Repeat) {
    const __m256 c = _mm256_sub_ps(_mm256_mul_ps(fract(coord), sizeF), splat(0.5f));
    const __m256 floorC = _mm256_floor_ps(c);
    const __m256i negative = _mm256_castps_si256(_mm256_cmp_ps(c, _mm256_setzero_ps(), _CMP_LT_OQ));
    // A NaN coordinate gives texel 0 rather than an out-of-range index.
    taps.i0 = select(negative, last, clampInt(_mm256_cvttps_epi32(floorC), 0, size - 1));
    taps.weight = _mm256_sub_ps(c, floorC);
    taps.i1 = _mm256_andnot_si256(_mm256_cmpeq_epi32(taps.i0, last), _mm256_add_epi32(taps.i0, splat(1)));
    return taps;
  }
  return wrapLinearClampToEdge8(coord, size);
}

// Four half-float channels of 8 texels, as float planes (half -> float is exact with F16C).
[[gnu::always_inline]] inline void fetchHalf(const Texture& t, __m256i x, __m256i y, __m256 rgba[4]) {
  const long long* texels = reinterpret_cast<const long long*>(t.half.data());
  const __m256i index = _mm256_add_epi32(_mm256_mullo_epi32(y, splat(t.width)), x);
  const __m256i lo = _mm256_i32gather_epi64(texels, _mm256_castsi256_si128(index), 8);
  const __m256i hi = _mm256_i32gather_epi64(texels, _mm256_extracti128_si256(index, 1), 8);
  // Each 128-bit half holds two texels: convert to floats (r g b a r g b a), then transpose
  // in registers; the unpacks leave lanes in the order 0 2 4 6 1 3 5 7, undone by a permute.
  const __m256 v0 = _mm256_cvtph_ps(_mm256_castsi256_si128(lo)), v1 = _mm256_cvtph_ps(_mm256_extracti128_si256(lo, 1));
  const __m256 v2 = _mm256_cvtph_ps(_mm256_castsi256_si128(hi)), v3 = _mm256_cvtph_ps(_mm256_extracti128_si256(hi, 1));
  const __m256 t0 = _mm256_unpacklo_ps(v0, v1), t1 = _mm256_unpackhi_ps(v0, v1);
  const __m256 t2 = _mm256_unpacklo_ps(v2, v3), t3 = _mm256_unpackhi_ps(v2, v3);
  const __m256i order = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);
  rgba[0] = _mm256_permutevar8x32_ps(_mm256_castpd_ps(_mm256_unpacklo_pd(_mm256_castps_pd(t0), _mm256_castps_pd(t2))), order);
  rgba[1] = _mm256_permutevar8x32_ps(_mm256_castpd_ps(_mm256_unpackhi_pd(_mm256_castps_pd(t0), _mm256_castps_pd(t2))), order);
  rgba[2] = _mm256_permutevar8x32_ps(_mm256_castpd_ps(_mm256_unpacklo_pd(_mm256_castps_pd(t1), _mm256_castps_pd(t3))), order);
  rgba[3] = _mm256_permutevar8x32_ps(_mm256_castpd_ps(_mm256_unpackhi_pd(_mm256_castps_pd(t1), _mm256_castps_pd(t3))), order);
}

// Eight lanes' texel pairs to planes: v[i] holds lane i's left texel (r g b a) then its
// right one; left[c] and right[c] get channel c of every lane (an 8x8 transpose).
[[gnu::always_inline]] inline void pairsToPlanes(const __m256 v[8], __m256 left[4], __m256 right[4]) {
  __m256 u[8], w[8];
  for (int i = 0; i < 8; i += 2) {
    u[i] = _mm256_unpacklo_ps(v[i], v[i + 1]);
    u[i + 1] = _mm256_unpackhi_ps(v[i], v[i + 1]);
  }
  for (int i = 0; i < 8; i += 4) {
    w[i] = _mm256_shuffle_ps(u[i], u[i + 2], 0x44);
    w[i + 1] = _mm256_shuffle_ps(u[i], u[i + 2], 0xEE);
    w[i + 2] = _mm256_shuffle_ps(u[i + 1], u[i + 3], 0x44);
    w[i + 3] = _mm256_shuffle_ps(u[i + 1], u[i + 3], 0xEE);
  }
  for (int c = 0; c < 4; ++c) {
    left[c] = _mm256_permute2f128_ps(w[c], w[c + 4], 0x20);
    right[c] = _mm256_permute2f128_ps(w[c], w[c + 4], 0x31);
  }
}

// The two adjacent texels starting at texel index start[i], for each lane i, as planes.
[[gnu::always_inline]] inline void loadHalfPairs(const Texture& t, const int* start, size_t offset, __m256 left[4],
                                                 __m256 right[4]) {
  __m256 v[8];
  for (int i = 0; i < 8; ++i)
    v[i] = _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(t.half.data() + (size_t(start[i]) + offset) * 4)));
  pairsToPlanes(v, left, right);
}

// Bilinear blend of a 2x2 footprint, channel by channel, as llvmpipe's SoA path: rows first.
[[gnu::always_inline]] inline void blendFootprint(const __m256 p00[4], const __m256 p01[4], const __m256 p10[4],
                                                  const __m256 p11[4], __m256 wx, __m256 wy, simd::Float8 out[4]) {
  for (int c = 0; c < 4; ++c) {
    const __m256 row0 = _mm256_fmadd_ps(wx, _mm256_sub_ps(p01[c], p00[c]), p00[c]);
    const __m256 row1 = _mm256_fmadd_ps(wx, _mm256_sub_ps(p11[c], p10[c]), p10[c]);
    out[c] = simd::Float8(_mm256_fmadd_ps(wy, _mm256_sub_ps(row1, row0), row0));
  }
}

// NEAREST: one texel per lane; N lookups as sampleRgba8.
template <int N>
[[gnu::always_inline]] inline void sampleHalfNearest(const Texture& t, const __m256* s, const __m256* tc,
                                                     simd::Float8 (*out)[4]) {
  __m256 rgba[N][4];
  for (int h = 0; h < N; ++h)
    fetchHalf(t, wrapNearest(s[h], t.width, t.sampler.wrapS, false), wrapNearest(tc[h], t.height, t.sampler.wrapT, false),
              rgba[h]);
  for (int h = 0; h < N; ++h)
    for (int c = 0; c < 4; ++c) out[h][c] = simd::Float8(rgba[h][c]);
}

// Bilinear RGBA16F with CLAMP_TO_EDGE (W >= 2), blended before the transpose. With
// CLAMP_TO_EDGE x1 = x0 + 1 except at the right edge, where x1 = x0 = W - 1: each lane loads
// the pair at min(x0, W - 2) as one vector [left rgba | right rgba] (16 bytes per row), and
// at the edge takes its left texel from the pair's right one. Then lanes k and k + 4 are
// blended together in one vector [lane k | lane k + 4], each lane's weights broadcast over
// its four channels, and only the four results are transposed into planes. Every lane and
// channel gets blendFootprint's operations (rows, then columns), so the bits are the same;
// the shuffles are about half as many as transposing all four texels first.
template <int N>
[[gnu::always_inline]] inline void sampleHalfClampBlendFirst(const Texture& t, const LinearTaps8* x,
                                                              const LinearTaps8* y, simd::Float8 (*out)[4]) {
  const uint16_t* texels = t.half.data();
  __m256 rows[N][2][8];   // [group][row y0 | y1][lane]: left texel low, right texel high
  for (int h = 0; h < N; ++h) {
    const __m256i column = _mm256_min_epi32(x[h].i0, splat(t.width - 2));
    alignas(32) int start[2][8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(start[0]), _mm256_add_epi32(_mm256_mullo_epi32(y[h].i0, splat(t.width)), column));
    _mm256_store_si256(reinterpret_cast<__m256i*>(start[1]), _mm256_add_epi32(_mm256_mullo_epi32(y[h].i1, splat(t.width)), column));
    for (int r = 0; r < 2; ++r)
      for (int k = 0; k < 8; ++k)
        rows[h][r][k] = _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(texels + size_t(start[r][k]) * 4)));
    // At the right edge x1 = x0 = W - 1: the pair was loaded one texel left, so its right
    // texel is both of the lane's.
    unsigned atEdge = unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(x[h].i0, splat(t.width - 1)))));
    for (; atEdge; atEdge &= atEdge - 1) {
      const int k = __builtin_ctz(atEdge);
      for (int r = 0; r < 2; ++r) rows[h][r][k] = _mm256_permute2f128_ps(rows[h][r][k], rows[h][r][k], 0x11);
    }
  }
  for (int h = 0; h < N; ++h) {
    __m256 blended[4];   // [lane k rgba | lane k + 4 rgba]
    for (int k = 0; k < 4; ++k) {
      const __m256i lanes = _mm256_setr_epi32(k, k, k, k, k + 4, k + 4, k + 4, k + 4);
      const __m256 wx = _mm256_permutevar8x32_ps(x[h].weight, lanes), wy = _mm256_permutevar8x32_ps(y[h].weight, lanes);
      __m256 row[2];
      for (int r = 0; r < 2; ++r) {
        const __m256 left = _mm256_permute2f128_ps(rows[h][r][k], rows[h][r][k + 4], 0x20);
        const __m256 right = _mm256_permute2f128_ps(rows[h][r][k], rows[h][r][k + 4], 0x31);
        row[r] = _mm256_fmadd_ps(wx, _mm256_sub_ps(right, left), left);
      }
      blended[k] = _mm256_fmadd_ps(wy, _mm256_sub_ps(row[1], row[0]), row[0]);
    }
    const __m256 t0 = _mm256_unpacklo_ps(blended[0], blended[1]), t1 = _mm256_unpackhi_ps(blended[0], blended[1]);
    const __m256 t2 = _mm256_unpacklo_ps(blended[2], blended[3]), t3 = _mm256_unpackhi_ps(blended[2], blended[3]);
    out[h][0] = simd::Float8(_mm256_shuffle_ps(t0, t2, 0x44));
    out[h][1] = simd::Float8(_mm256_shuffle_ps(t0, t2, 0xEE));
    out[h][2] = simd::Float8(_mm256_shuffle_ps(t1, t3, 0x44));
    out[h][3] = simd::Float8(_mm256_shuffle_ps(t1, t3, 0xEE));
  }
}

// RGBA8 under the `filter=float` method (methods.h): the float path above, on texels read
// as unorm8 * float(1/255); bit-identical to sample_color.cpp's sampleFloat.
template <int N>
void sampleRgba8Float(const Texture& t, const __m256* s, const __m256* tc, simd::Float8 (*out)[4]) {
  const bool inStrips = texelsInStripsOnly(t);
  const int* texels = reinterpret_cast<const int*>(inStrips ? t.strips8.data() : t.rgba8.data());
  const __m256 kUnorm8 = splat(float(1.0 / 255.0));
  auto fetch = [&](__m256i x, __m256i y, __m256 planes[4]) {
    const __m256i p = _mm256_i32gather_epi32(texels, texelUnits(t, inStrips, x, y), 4);
    for (int c = 0; c < 4; ++c) planes[c] = _mm256_mul_ps(_mm256_cvtepi32_ps(channel(p, c)), kUnorm8);
  };
  if (lookupFilter(t) == Filter::Nearest) {
    for (int h = 0; h < N; ++h) {
      __m256 planes[4];
      fetch(wrapNearest(s[h], t.width, t.sampler.wrapS, false), wrapNearest(tc[h], t.height, t.sampler.wrapT, false), planes);
      for (int c = 0; c < 4; ++c) out[h][c] = simd::Float8(planes[c]);
    }
    return;
  }
  for (int h = 0; h < N; ++h) {
    const LinearTaps8 x = wrapLinearFloat(s[h], t.width, t.sampler.wrapS);
    const LinearTaps8 y = wrapLinearFloat(tc[h], t.height, t.sampler.wrapT);
    __m256 p00[4], p01[4], p10[4], p11[4];
    fetch(x.i0, y.i0, p00);
    fetch(x.i1, y.i0, p01);
    fetch(x.i0, y.i1, p10);
    fetch(x.i1, y.i1, p11);
    blendFootprint(p00, p01, p10, p11, x.weight, y.weight, out[h]);
  }
}

template <int N>
[[gnu::always_inline]] inline void sampleHalf(const Texture& t, const __m256* s, const __m256* tc, simd::Float8 (*out)[4]) {
  if (lookupFilter(t) == Filter::Nearest) return sampleHalfNearest<N>(t, s, tc, out);
  LinearTaps8 x[N], y[N];
  for (int h = 0; h < N; ++h) {
    x[h] = wrapLinearFloat(s[h], t.width, t.sampler.wrapS);
    y[h] = wrapLinearFloat(tc[h], t.height, t.sampler.wrapT);
  }
  if (t.sampler.wrapS == Wrap::ClampToEdge && t.width >= 2) return sampleHalfClampBlendFirst<N>(t, x, y, out);
  __m256 p00[N][4], p01[N][4], p10[N][4], p11[N][4];
  for (int h = 0; h < N; ++h) {
    fetchHalf(t, x[h].i0, y[h].i0, p00[h]);
    fetchHalf(t, x[h].i1, y[h].i0, p01[h]);
    fetchHalf(t, x[h].i0, y[h].i1, p10[h]);
    fetchHalf(t, x[h].i1, y[h].i1, p11[h]);
  }
  for (int h = 0; h < N; ++h) blendFootprint(p00[h], p01[h], p10[h], p11[h], x[h].weight, y[h].weight, out[h]);
}

// N lookups of any format.
template <int N>
void sampleColorN(const Texture& texture, const simd::Float8* s, const simd::Float8* t, simd::Float8 (*out)[4]) {
  __m256 sv[N], tv[N];
  for (int h = 0; h < N; ++h) sv[h] = s[h].v, tv[h] = t[h].v;
  if (texture.format == TexelFormat::RGBA8 && !methods::fixedPointFilter(methods::active().filter)) {
    sampleRgba8Float<N>(texture, sv, tv, out);
  } else if (texture.format == TexelFormat::RGBA8) {
    sampleRgba8<N>(texture, sv, tv, out);
  } else if (texture.format == TexelFormat::RGBA16F) {
    sampleHalf<N>(texture, sv, tv, out);
  } else if (texture.isDepth() && lookupFilter(texture) == Filter::Nearest) {
    // A depth texture through sampler2D (the pbr scene's position reconstruction and SSAO):
    // code * depthCodeScale in r, (0, 0, 1) in gba, as sample_color.cpp's depthTexelChannel.
    const int* codes = reinterpret_cast<const int*>(texture.depth.data());
    const __m256 scale = splat(depthCodeScale(texture));
    for (int h = 0; h < N; ++h) {
      const __m256i index =
          nearestTexelIndex8(sv[h], tv[h], texture.width, texture.height, texture.sampler.wrapS, texture.sampler.wrapT);
      out[h][0] = simd::Float8(_mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_i32gather_epi32(codes, index, 4)), scale));
      out[h][1] = out[h][2] = simd::Float8(0.0f);
      out[h][3] = simd::Float8(1.0f);
    }
  } else if (texture.format == TexelFormat::RGBA32F && lookupFilter(texture) == Filter::Nearest) {
    // A small float table read texel by texel (pbr's 4x4 SSAO rotation noise, once a pixel):
    // each channel one gather at the float path's NEAREST index.
    const float* texels = texture.f32.data();
    for (int h = 0; h < N; ++h) {
      const __m256i first = _mm256_slli_epi32(
          nearestTexelIndex8(sv[h], tv[h], texture.width, texture.height, texture.sampler.wrapS, texture.sampler.wrapT), 2);
      for (int c = 0; c < 4; ++c) out[h][c] = simd::Float8(_mm256_i32gather_ps(texels + c, first, 4));
    }
  } else {   // RGBA32F LINEAR (sampled only by tests) and depth LINEAR: the scalar reference per lane
    for (int h = 0; h < N; ++h) {
      alignas(32) float ss[8], ts[8], planes[4][8];
      s[h].store(ss);
      t[h].store(ts);
      for (int i = 0; i < 8; ++i) {
        float rgba[4];
        sampleColor(texture, ss[i], ts[i], rgba);
        for (int c = 0; c < 4; ++c) planes[c][i] = rgba[c];
      }
      for (int c = 0; c < 4; ++c) out[h][c] = simd::Float8::load(planes[c]);
    }
  }
}

// Row r of each lane's 4x4 texel window (from texel start[lane]), as planes: [column][channel].
[[gnu::always_inline]] inline void loadWindowRow(const Texture& t, const int* start, int r, __m256 (&row)[4][4]) {
  loadHalfPairs(t, start, size_t(r) * size_t(t.width), row[0], row[1]);
  loadHalfPairs(t, start, size_t(r) * size_t(t.width) + 2, row[2], row[3]);
}

// The grid's taps when tap k spans window texels k and k + 1 along both axes in every lane:
// blendFootprint for each, row by row. A window row's texels give its three row blends (one
// per tap column, with x[i]'s weight), which with the previous row's make the tap row
// between them; each row is blended once, and only two rows' blends are live at a time
// (holding the whole window spilled it to memory: 10% slower).
[[gnu::always_inline]] inline void blendGridInPlace(const Texture& t, const int* start, const LinearTaps8* x,
                                                    const LinearTaps8* y, simd::Float8 (*taps)[4]) {
  __m256 above[3][4];   // the previous window row's blends: [tap column][channel]
  for (int r = 0; r < 4; ++r) {
    __m256 texel[4][4];   // window row r: [column][channel]
    loadWindowRow(t, start, r, texel);
    __m256 row[3][4];
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 4; ++c)
        row[i][c] = _mm256_fmadd_ps(x[i].weight, _mm256_sub_ps(texel[i + 1][c], texel[i][c]), texel[i][c]);
    if (r > 0)
      for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 4; ++c)
          taps[(r - 1) * 3 + i][c] =
              simd::Float8(_mm256_fmadd_ps(y[r - 1].weight, _mm256_sub_ps(row[i][c], above[i][c]), above[i][c]));
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 4; ++c) above[i][c] = row[i][c];
  }
}

// The grid's taps near an edge, where `wx` and `wy` say which window texels each tap spans
// in each lane: the same blends, from the texels each lane picks.
void blendGridPicked(const Texture& t, const int* start, const LinearTaps8* x, const LinearTaps8* y,
                     const WindowTaps<3>& wx, const WindowTaps<3>& wy, simd::Float8 (*taps)[4]) {
  __m256 row[4][3][4];   // [window row][tap column][channel]
  for (int r = 0; r < 4; ++r) {
    __m256 w[4][4];   // window row r: [column][channel]
    loadWindowRow(t, start, r, w);
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 4; ++c) {
        const __m256 left = pickInWindow(wx.first[i], [&](int v) { return w[v][c]; });
        const __m256 right = pickInWindow(wx.second[i], [&](int v) { return w[v][c]; });
        row[r][i][c] = _mm256_fmadd_ps(x[i].weight, _mm256_sub_ps(right, left), left);
      }
  }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 4; ++c) {
        const __m256 top = pickInWindow(wy.first[j], [&](int v) { return row[v][i][c]; });
        const __m256 bottom = pickInWindow(wy.second[j], [&](int v) { return row[v][i][c]; });
        taps[j * 3 + i][c] = simd::Float8(_mm256_fmadd_ps(y[j].weight, _mm256_sub_ps(bottom, top), top));
      }
}

// The 3x3 grid for RGBA16F with LINEAR and CLAMP_TO_EDGE, when every lane's nine 2x2
// footprints lie in one 4x4 window of texels, loaded once: the window starts at tap 0's
// first texel, moved in from the right and bottom edges so it stays inside. Usually tap k
// then spans window texels k and k + 1; near an edge, where clamping piles taps onto the
// same texels, each lane picks the texels its taps span. Returns false (nothing written)
// when some footprint leaves the window (a step that is not one texel) or the texture is
// smaller than 4x4.
bool sampleHalfGridShared(const Texture& t, __m256 s, __m256 tc, float stepS, float stepT, simd::Float8 (*taps)[4]) {
  if (t.width < 4 || t.height < 4) return false;
  LinearTaps8 x[3], y[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = wrapLinearClampToEdge8(_mm256_add_ps(s, splat(float(k - 1) * stepS)), t.width);
    y[k] = wrapLinearClampToEdge8(_mm256_add_ps(tc, splat(float(k - 1) * stepT)), t.height);
  }
  const __m256i startX = windowStart(x[0], t.width, 4), startY = windowStart(y[0], t.height, 4);
  const bool inPlace = tapsAreConsecutive(x, y, 3);   // then start = tap 0's first texel
  WindowTaps<3> wx, wy;
  if (!inPlace && !(tapsInWindow(x, startX, wx) && tapsInWindow(y, startY, wy))) return false;
  alignas(32) int start[8];   // each lane's top-left texel of its window
  _mm256_store_si256(reinterpret_cast<__m256i*>(start), _mm256_add_epi32(_mm256_mullo_epi32(startY, splat(t.width)), startX));
  if (inPlace) blendGridInPlace(t, start, x, y, taps);
  else blendGridPicked(t, start, x, y, wx, wy, taps);
  return true;
}

}  // namespace

void sampleColor8(const Texture& texture, simd::Float8 s, simd::Float8 t, simd::Float8 out[4]) {
  sampleColorN<1>(texture, &s, &t, reinterpret_cast<simd::Float8(*)[4]>(out));
}

void sampleColor8x2(const Texture& texture, const simd::Float8 s[2], const simd::Float8 t[2], simd::Float8 out[2][4]) {
  sampleColorN<2>(texture, s, t, out);
}

simd::Float8 samplePlane8(const TexelPlane& plane, simd::Float8 s, simd::Float8 t) {
  const __m256i index = nearestTexelIndex8(s.v, t.v, plane.width, plane.height, plane.wrapS, plane.wrapT);
  return simd::Float8(_mm256_i32gather_ps(plane.values.data(), index, 4));
}

#if RASTER_ZMM_PAIRS
void sampleColor8x2(const Texture& texture, simd::Float8x2 s, simd::Float8x2 t, simd::Float8x2 out[4]) {
  if (isHalfNearest(texture)) return sampleHalfNearestPair(texture, s, t, out);
  const simd::Float8 sHalves[2] = {s.low(), s.high()}, tHalves[2] = {t.low(), t.high()};
  if (texture.format == TexelFormat::RGBA16F && lookupFilter(texture) == Filter::Linear && texture.width >= 2) {
    // Both groups' taps joined, for the 16-lane blend (sample_half_avx512.h), any wraps: it
    // declines a group with a footprint at the last column, which CLAMP_TO_EDGE repeats and
    // REPEAT splits across its seam (the environment maps repeat along s). Here, not in
    // the ports' inline lookup: there it made the hdr frame, which never takes it, about 3%
    // slower (its code beside the composite's lookups; 9 alternated rounds, 7 lost).
    LinearTaps8 x[2], y[2];
    for (int h = 0; h < 2; ++h) {
      x[h] = wrapLinearFloat(sHalves[h].v, texture.width, texture.sampler.wrapS);
      y[h] = wrapLinearFloat(tHalves[h].v, texture.height, texture.sampler.wrapT);
    }
    auto join = [](const LinearTaps8 (&taps)[2]) {
      return LinearTaps16{_mm512_inserti64x4(_mm512_castsi256_si512(taps[0].i0), taps[1].i0, 1),
                          _mm512_inserti64x4(_mm512_castsi256_si512(taps[0].i1), taps[1].i1, 1),
                          _mm512_insertf32x8(_mm512_castps256_ps512(taps[0].weight), taps[1].weight, 1)};
    };
    if (blendHalfPairs16(texture, join(x), join(y), out)) return;
  }
  simd::Float8 planes[2][4];
  sampleColorN<2>(texture, sHalves, tHalves, planes);
  for (int c = 0; c < 4; ++c) out[c] = simd::Float8x2(planes[0][c], planes[1][c]);
}

#endif

void prefetchColor8(const Texture& texture, simd::Float8 s, simd::Float8 t) {
  if (lookupFilter(texture) != Filter::Linear) return;
  // The texel rows the lookup will read: each lane's footprint starts at (x0, y0) and
  // (x0, y1), in the layout it reads, with the same wrapping.
  const char* base = nullptr;
  int texelShift = 0;   // log2 of the bytes a texel
  __m256i first, second;   // the texel index of each lane's footprint rows' first texels
  if (texture.format == TexelFormat::RGBA8) {
    const bool grey = texture.hasGreyCopy(), inStrips = texelsInStripsOnly(texture);
    base = grey       ? reinterpret_cast<const char*>(texture.grey8.data())
           : inStrips ? reinterpret_cast<const char*>(texture.strips8.data())
                      : reinterpret_cast<const char*>(texture.rgba8.data());
    texelShift = grey ? 0 : 2;
    const FixedTaps8 x = wrapLinearFixed(s.v, texture.width, texture.sampler.wrapS);
    const FixedTaps8 y = wrapLinearFixed(t.v, texture.height, texture.sampler.wrapT);
    first = texelUnits(texture, inStrips, x.x0, y.x0), second = texelUnits(texture, inStrips, x.x0, y.x1);
  } else if (texture.format == TexelFormat::RGBA16F) {
    base = reinterpret_cast<const char*>(texture.half.data());
    texelShift = 3;
    const LinearTaps8 x = wrapLinearFloat(s.v, texture.width, texture.sampler.wrapS);
    const LinearTaps8 y = wrapLinearFloat(t.v, texture.height, texture.sampler.wrapT);
    first = texelUnits(texture, false, x.i0, y.i0), second = texelUnits(texture, false, x.i0, y.i1);
  } else {
    return;
  }
  alignas(32) int rows[2][8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(rows[0]), first);
  _mm256_store_si256(reinterpret_cast<__m256i*>(rows[1]), second);
  for (int i = 0; i < 8; ++i) {
    simd::prefetchLineToL2(base + (size_t(unsigned(rows[0][i])) << texelShift));
    simd::prefetchLineToL2(base + (size_t(unsigned(rows[1][i])) << texelShift));
  }
}

void sampleColorGrid8(const Texture& texture, simd::Float8 s, simd::Float8 t, float stepS, float stepT,
                      simd::Float8 (*taps)[4]) {
  const SamplerState& state = texture.sampler;
  if (texture.format == TexelFormat::RGBA16F && lookupFilter(texture) == Filter::Linear && state.wrapS == Wrap::ClampToEdge &&
      state.wrapT == Wrap::ClampToEdge && sampleHalfGridShared(texture, s.v, t.v, stepS, stepT, taps))
    return;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      sampleColor8(texture, simd::Float8(_mm256_add_ps(s.v, splat(float(i - 1) * stepS))),
                   simd::Float8(_mm256_add_ps(t.v, splat(float(j - 1) * stepT))), taps[j * 3 + i]);
}

}  // namespace raster::sampling
#endif
