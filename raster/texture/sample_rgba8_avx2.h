// Bilinear and NEAREST lookups of RGBA8 textures for 8 lanes (llvmpipe's 8-bit fixed-point
// AoS path), N lookups at once; sample_color_avx2.cpp's sampleColorN calls sampleRgba8.
// Inline, so that its phases interleave with the caller's. sample_rgba8_avx512.h is the same
// path on 16 lanes; tests/texture/sampler_simd_test.cpp holds both to the scalar reference.
#pragma once

#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#include "raster/simd/lanes_avx2.h"
#include "raster/texture/footprint_strips.h"
#include "raster/texture/linear_taps_avx2.h"
#include "raster/texture/lookup_filter.h"
#include "raster/texture/texture.h"
#include "raster/texture/wrap_avx2.h"

namespace raster::sampling::avx2 {

struct FixedTaps8 {
  __m256i x0, x1, weight;
};

inline FixedTaps8 wrapLinearFixed(__m256 coord, int size, Wrap wrap) {
  FixedTaps8 taps;
  const __m256i last = splat(size - 1);
  if (wrap == Wrap::Repeat && !isPowerOfTwo(size)) {
    const __m256 scaled = _mm256_mul_ps(_mm256_mul_ps(fract(coord), splat(float(size))), splat(256.0f));
    const __m256i fixed = _mm256_sub_epi32(_mm256_cvtps_epi32(scaled), splat(128));
    taps.weight = _mm256_and_si256(fixed, splat(255));
    __m256i x0 = _mm256_srai_epi32(fixed, 8);
    x0 = select(_mm256_cmpgt_epi32(_mm256_setzero_si256(), x0), last, x0);
    taps.x0 = _mm256_min_epi32(x0, last);
    taps.x1 = _mm256_andnot_si256(_mm256_cmpeq_epi32(taps.x0, last), _mm256_add_epi32(taps.x0, splat(1)));
    return taps;
  }
  const __m256i fixed = _mm256_sub_epi32(_mm256_cvtps_epi32(_mm256_mul_ps(coord, splat(float(size << 8)))), splat(128));
  taps.weight = _mm256_and_si256(fixed, splat(255));
  const __m256i x0 = _mm256_srai_epi32(fixed, 8);
  if (wrap == Wrap::Repeat) {
    taps.x0 = _mm256_and_si256(x0, last);
    taps.x1 = _mm256_andnot_si256(_mm256_cmpeq_epi32(taps.x0, last), _mm256_add_epi32(taps.x0, splat(1)));
  } else {
    const __m256i low = _mm256_cmpgt_epi32(x0, splat(-1));    // x0 >= 0
    const __m256i high = _mm256_cmpgt_epi32(last, x0);        // x0 < size - 1
    taps.x0 = select(high, _mm256_and_si256(x0, low), last);
    taps.x1 = _mm256_add_epi32(taps.x0, _mm256_and_si256(_mm256_and_si256(low, high), splat(1)));
  }
  return taps;
}

// lerp8 with pmulhrsw: a + floor((w * (b - a) * 128 + 16384) / 32768), per 32-bit lane,
// given weight128 = w * 128. pmulhrsw computes exactly that rounding on 16-bit values, and
// b - a (-255..255) and w * 128 (0..32640) fit 16 bits: the low half of each lane gets the
// step. A negative step leaves its high half zero instead of all ones, an error of 65536,
// which the final & 0xFF removes.
inline __m256i lerp8(__m256i weight128, __m256i a, __m256i b) {
  const __m256i step = _mm256_mulhrs_epi16(_mm256_sub_epi32(b, a), weight128);
  return _mm256_and_si256(_mm256_add_epi32(a, step), splat(0xFF));
}

inline __m256i channel(__m256i texels, int c) { return _mm256_and_si256(_mm256_srli_epi32(texels, 8 * c), splat(0xFF)); }

// Where texels (x, y) are: in rows, texel y * width + x; in a strip copy that holds the
// texels (texelsInStripsOnly), their 4-byte units there (footprint_strips.h's
// stripUnitOfTexel per lane; y / 3 as a multiply and a shift, exact for 0 <= y < 98304).
inline __m256i texelUnits(const Texture& t, bool inStrips, __m256i x, __m256i y) {
  if (!inStrips) return _mm256_add_epi32(_mm256_mullo_epi32(y, splat(t.width)), x);
  static_assert(kStripStep == 3, "the multiplier is for a step of 3");
  const __m256i strip = _mm256_min_epi32(_mm256_srli_epi32(_mm256_mullo_epi32(y, splat(43691)), 17),
                                         splat(int(stripCount(t.height)) - 1));
  const __m256i row = _mm256_sub_epi32(y, _mm256_mullo_epi32(strip, splat(kStripStep)));
  return _mm256_add_epi32(_mm256_slli_epi32(_mm256_add_epi32(_mm256_mullo_epi32(strip, splat(t.width)), x), 2), row);
}

// N independent 8-lane lookups (N = 2 for Float8x2 shading). Each phase runs over all of
// them before the next, so the texel loads of every lookup are in flight together: one
// lookup's cache misses overlap the other's instead of following them.
//
// A grey texture is read from its one-byte copy (texture.h): the same taps, weights and
// lerps on the one channel that r, g and b share, so each of the three gets the bits it
// would get from rgba8; alpha is 255 at every texel. Four bytes gathered from a texel's
// byte hold it and, one byte up, its right neighbour: a bilinear row is one element.
template <int N>
[[gnu::always_inline]] inline void sampleRgba8(const Texture& t, const __m256* s, const __m256* tc, simd::Float8 (*out)[4]) {
  const bool grey = t.hasGreyCopy();
  const bool inStrips = texelsInStripsOnly(t);   // (a grey texture keeps its rows)
  const int* texels = reinterpret_cast<const int*>(inStrips ? t.strips8.data() : t.rgba8.data());
  const int* greyBytes = reinterpret_cast<const int*>(t.grey8.data());
  const __m256i low8 = splat(0xFF);
  auto index = [&](__m256i x, __m256i y) { return texelUnits(t, inStrips, x, y); };
  // One texel a lane: RGBA in four bytes, or the grey byte in the low eight bits.
  auto fetch = [&](__m256i x, __m256i y) {
    return grey ? _mm256_and_si256(_mm256_i32gather_epi32(greyBytes, index(x, y), 1), low8)
                : _mm256_i32gather_epi32(texels, index(x, y), 4);
  };
  const __m256 kUnorm8 = splat(float(1.0 / 255.0));
  // Lookup h's channels, from channelValue(c) for c = 0..3 (grey: c = 0, copied to g and b).
  auto put = [&](int h, auto&& channelValue) {
    for (int c = 0; c < (grey ? 1 : 4); ++c)
      out[h][c] = simd::Float8(_mm256_mul_ps(_mm256_cvtepi32_ps(channelValue(c)), kUnorm8));
    if (grey) {
      out[h][1] = out[h][2] = out[h][0];
      out[h][3] = simd::Float8(_mm256_mul_ps(_mm256_cvtepi32_ps(low8), kUnorm8));
    }
  };
  if (lookupFilter(t) == Filter::Nearest) {
    __m256i p[N];
    for (int h = 0; h < N; ++h)
      p[h] = fetch(wrapNearest(s[h], t.width, t.sampler.wrapS, true), wrapNearest(tc[h], t.height, t.sampler.wrapT, true));
    for (int h = 0; h < N; ++h) put(h, [&](int c) { return channel(p[h], c); });
    return;
  }
  FixedTaps8 x[N], y[N];
  __m256i p00[N], p01[N], p10[N], p11[N];
  for (int h = 0; h < N; ++h) {
    x[h] = wrapLinearFixed(s[h], t.width, t.sampler.wrapS);
    y[h] = wrapLinearFixed(tc[h], t.height, t.sampler.wrapT);
    const __m256i adjacent = _mm256_cmpeq_epi32(x[h].x1, _mm256_add_epi32(x[h].x0, splat(1)));
    if (!inStrips && _mm256_movemask_epi8(adjacent) == -1) {
      // Every lane's two texels of a row are neighbours (no wrap, no clamp between them):
      // one element fetches both, 64 bits of RGBA8 or 32 of the grey copy. (In the strips
      // they are a column apart: that case takes the four fetches below.)
      const __m256i row0 = index(x[h].x0, y[h].x0), row1 = index(x[h].x0, y[h].x1);
      if (grey) {
        const __m256i top = _mm256_i32gather_epi32(greyBytes, row0, 1), bottom = _mm256_i32gather_epi32(greyBytes, row1, 1);
        p00[h] = _mm256_and_si256(top, low8), p01[h] = _mm256_and_si256(_mm256_srli_epi32(top, 8), low8);
        p10[h] = _mm256_and_si256(bottom, low8), p11[h] = _mm256_and_si256(_mm256_srli_epi32(bottom, 8), low8);
      } else {
        gatherTexelPairs(texels, row0, p00[h], p01[h]);
        gatherTexelPairs(texels, row1, p10[h], p11[h]);
      }
      continue;
    }
    p00[h] = fetch(x[h].x0, y[h].x0);
    p01[h] = fetch(x[h].x1, y[h].x0);
    p10[h] = fetch(x[h].x0, y[h].x1);
    p11[h] = fetch(x[h].x1, y[h].x1);
  }
  for (int h = 0; h < N; ++h) {
    const __m256i weightX = _mm256_slli_epi32(x[h].weight, 7), weightY = _mm256_slli_epi32(y[h].weight, 7);
    put(h, [&](int c) {
      const __m256i row0 = lerp8(weightX, channel(p00[h], c), channel(p01[h], c));
      const __m256i row1 = lerp8(weightX, channel(p10[h], c), channel(p11[h], c));
      return lerp8(weightY, row0, row1);
    });
  }
}


}  // namespace raster::sampling::avx2
#endif
