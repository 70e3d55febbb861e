// Bilinear lookups of RGBA8 textures (llvmpipe's 8-bit fixed-point path) for Float8x2 lanes
// held in one 512-bit register: the G-buffer's material maps, sixteen lanes at a time.
// Inline, so that a port's lookup costs no call and no trip of its four channels through
// memory, and the shader's compiler drops the channels it never reads. The taps, weights
// and lerps are the 8-lane sampler's (sample_rgba8_avx2.h, sampleRgba8, grey copies too)
// on 16 lanes at once, so every value is the same. An uploaded texture's footprints are
// read from its strip copy (footprint_strips.h) where all 16 have neighbouring rows.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS && defined(__AVX512BW__)
#define RASTER_RGBA8_ZMM 1
#include "raster/methods.h"
#include "raster/simd/intrinsics.h"
#include "raster/simd/prefetch.h"
#include "raster/texture/footprint_strips.h"
#include "raster/texture/lane_loads_avx512.h"
#include "raster/texture/lookup_filter.h"
#include "raster/texture/texture.h"

namespace raster::sampling {

struct FixedTaps16 {
  __m512i x0, x1, weight;   // the two texels along one axis and x1's weight in 1/256
};

// wrapLinearFixed of sample_rgba8_avx2.h on 16 lanes: the coordinate in 24.8 fixed point,
// half a texel back, then wrapped or clamped.
[[gnu::always_inline]] inline FixedTaps16 wrapLinearFixed16(__m512 coord, int size, Wrap wrap) {
  const __m512i last = _mm512_set1_epi32(size - 1), one = _mm512_set1_epi32(1), low8 = _mm512_set1_epi32(255);
  FixedTaps16 taps;
  if (wrap == Wrap::Repeat && !(size > 0 && (size & (size - 1)) == 0)) {
    const __m512 fraction = _mm512_sub_ps(coord, _mm512_floor_ps(coord));
    const __m512 scaled = _mm512_mul_ps(_mm512_mul_ps(fraction, _mm512_set1_ps(float(size))), _mm512_set1_ps(256.0f));
    const __m512i fixed = _mm512_sub_epi32(_mm512_cvtps_epi32(scaled), _mm512_set1_epi32(128));
    taps.weight = _mm512_and_si512(fixed, low8);
    __m512i x0 = _mm512_srai_epi32(fixed, 8);
    x0 = _mm512_mask_mov_epi32(x0, _mm512_cmpgt_epi32_mask(_mm512_setzero_si512(), x0), last);   // below 0: the last
    taps.x0 = _mm512_min_epi32(x0, last);
    taps.x1 = _mm512_maskz_add_epi32(_mm512_cmpneq_epi32_mask(taps.x0, last), taps.x0, one);  // past the last: 0
    return taps;
  }
  const __m512i fixed =
      _mm512_sub_epi32(_mm512_cvtps_epi32(_mm512_mul_ps(coord, _mm512_set1_ps(float(size << 8)))), _mm512_set1_epi32(128));
  taps.weight = _mm512_and_si512(fixed, low8);
  const __m512i x0 = _mm512_srai_epi32(fixed, 8);
  if (wrap == Wrap::Repeat) {
    taps.x0 = _mm512_and_si512(x0, last);
    taps.x1 = _mm512_maskz_add_epi32(_mm512_cmpneq_epi32_mask(taps.x0, last), taps.x0, one);
  } else {
    const __mmask16 low = _mm512_cmpgt_epi32_mask(x0, _mm512_set1_epi32(-1));   // x0 >= 0
    const __mmask16 high = _mm512_cmpgt_epi32_mask(last, x0);                    // x0 < size - 1
    taps.x0 = _mm512_mask_mov_epi32(last, high, _mm512_maskz_mov_epi32(low, x0));
    taps.x1 = _mm512_mask_add_epi32(taps.x0, __mmask16(low & high), taps.x0, one);
  }
  return taps;
}

// a + floor((w * (b - a) * 128 + 16384) / 32768) per 32-bit lane (sample_rgba8_avx2.h's
// lerp8: pmulhrsw on the low 16 bits, the final & 0xFF removing a negative step's carry).
[[gnu::always_inline]] inline __m512i lerp8x16(__m512i weight128, __m512i a, __m512i b) {
  return _mm512_and_si512(_mm512_add_epi32(a, _mm512_mulhrs_epi16(_mm512_sub_epi32(b, a), weight128)),
                          _mm512_set1_epi32(0xFF));
}

// y / kStripStep per lane, the strip of a footprint whose first row is y: a multiply and
// a shift, exact for 0 <= y < 98304 (textures are at most 16384 texels a side).
[[gnu::always_inline]] inline __m512i stripIndex16(__m512i y) {
  static_assert(kStripStep == 3, "the multiplier is for a step of 3");
  return _mm512_srli_epi32(_mm512_mullo_epi32(y, _mm512_set1_epi32(43691)), 17);
}

// The 4-byte unit of texel (x, y) in strip `strip` of the copy, per lane:
// (strip * width + x) * 4 + (y - 3 * strip).
[[gnu::always_inline]] inline __m512i unitInStrip16(int width, __m512i x, __m512i y, __m512i strip) {
  const __m512i row = _mm512_sub_epi32(y, _mm512_mullo_epi32(strip, _mm512_set1_epi32(kStripStep)));
  const __m512i column = _mm512_add_epi32(_mm512_mullo_epi32(strip, _mm512_set1_epi32(width)), x);
  return _mm512_add_epi32(_mm512_slli_epi32(column, 2), row);
}

struct StripColumns16 {
  __m512i left, right;   // per lane, the 4-byte units of the footprint's columns x0 and x1 at row y0
};

// Where a footprint with columns x0, x1 and first row y0 starts in the strip copy, as
// stripUnit of footprint_strips.h: in strip y0 / 3.
[[gnu::always_inline]] inline StripColumns16 stripColumns16(int width, const FixedTaps16& x, __m512i y0) {
  const __m512i left = unitInStrip16(width, x.x0, y0, stripIndex16(y0));
  return {left, _mm512_add_epi32(left, _mm512_slli_epi32(_mm512_sub_epi32(x.x1, x.x0), 2))};
}

// The 4-byte units of any texels (x, y) in a strip copy that holds the texels
// (footprint_strips.h's stripUnitOfTexel per lane: a last row no strip starts at is in the
// last strip).
[[gnu::always_inline]] inline __m512i stripTexelUnits16(const Texture& t, __m512i x, __m512i y) {
  const __m512i strip = _mm512_min_epi32(stripIndex16(y), _mm512_set1_epi32(int(stripCount(t.height)) - 1));
  return unitInStrip16(t.width, x, y, strip);
}

// Whether sampleRgba8Pair is this texture's lookup under the active method set.
inline bool isRgba8Bilinear(const Texture& t) {
  return t.format == TexelFormat::RGBA8 && lookupFilter(t) == Filter::Linear &&
         methods::fixedPointFilter(methods::active().filter);
}

// The bilinear RGBA8 lookup of 16 lanes (isRgba8Bilinear). A grey texture is read from
// its one-byte copy (texture.h): the same taps, weights and lerps on the one channel that
// r, g and b share, alpha 1.
[[gnu::always_inline]] inline void sampleRgba8Pair(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc,
                                                   simd::Float8x2 out[4]) {
  const FixedTaps16 x = wrapLinearFixed16(s.v, t.width, t.sampler.wrapS);
  const FixedTaps16 y = wrapLinearFixed16(tc.v, t.height, t.sampler.wrapT);
  const bool grey = t.hasGreyCopy();
  const void* texels = grey ? static_cast<const void*>(t.grey8.data()) : static_cast<const void*>(t.rgba8.data());
  const __m512i low8 = _mm512_set1_epi32(0xFF);
  // The fetches below are always inlined: the profile-guided build had outlined the strip
  // path's (a call per fetch, its lanes passed through memory).
  // One texel a lane: RGBA in four bytes, or the grey byte in the low eight bits.
  auto fetch = [&](__m512i index) __attribute__((always_inline)) {
    return grey ? _mm512_and_si512(_mm512_i32gather_epi32(index, texels, 1), low8) : _mm512_i32gather_epi32(index, texels, 4);
  };
  // Two RGBA texels a lane that lie side by side in memory, as one 64-bit element at
  // base + 4 * index (lanes 0-7, then 8-15), split into the first texels and the second ones
  // in lane order.
  auto fetchTwo = [&](const void* base, __m512i index, __m512i& first, __m512i& second) __attribute__((always_inline)) {
    const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    const __m512i odd = _mm512_add_epi32(even, _mm512_set1_epi32(1));
    alignas(64) int at[16];   // scalar loads, not two 64-bit gathers (lane_loads_avx512.h)
    storeLaneIndices16(index, at);
    const __m512i lo = loadEightLanes64(base, at, 0, 4), hi = loadEightLanes64(base, at, 8, 4);
    first = _mm512_permutex2var_epi32(lo, even, hi);
    second = _mm512_permutex2var_epi32(lo, odd, hi);
  };
  // Where every lane's two texels of a row are neighbours, both with one element: four grey
  // bytes from the left texel on, or the two RGBA texels.
  auto fetchPair = [&](__m512i index, __m512i& left, __m512i& right) __attribute__((always_inline)) {
    if (grey) {
      const __m512i bytes = _mm512_i32gather_epi32(index, texels, 1);
      left = _mm512_and_si512(bytes, low8), right = _mm512_and_si512(_mm512_srli_epi32(bytes, 8), low8);
      return;
    }
    fetchTwo(texels, index, left, right);
  };
  const __m512i one = _mm512_set1_epi32(1);
  __m512i p00, p01, p10, p11;
  if (t.hasStripCopy() && _mm512_cmpeq_epi32_mask(y.x1, _mm512_add_epi32(y.x0, one)) == 0xFFFF) {
    // Every footprint's rows are neighbours: its two columns from the strip copy, each one
    // element holding the column's texel in row y0, then in row y1 (footprint_strips.h).
    const StripColumns16 at = stripColumns16(t.width, x, y.x0);
    fetchTwo(t.strips8.data(), at.left, p00, p10);
    fetchTwo(t.strips8.data(), at.right, p01, p11);
  } else if (texelsInStripsOnly(t)) {
    // Some footprint's rows are not neighbours (clamped at the first or last row, or a
    // REPEAT wrap from the last to the first), and the strips alone hold the texels: each
    // texel from its own unit.
    const int* strips = reinterpret_cast<const int*>(t.strips8.data());
    auto texel = [&](__m512i column, __m512i row) __attribute__((always_inline)) {
      return _mm512_i32gather_epi32(stripTexelUnits16(t, column, row), strips, 4);
    };
    p00 = texel(x.x0, y.x0), p01 = texel(x.x1, y.x0), p10 = texel(x.x0, y.x1), p11 = texel(x.x1, y.x1);
  } else {
    // Rows y0 and y1 of rgba8 or of the grey copy. (Their starts are computed here, not
    // before the strip path: there the compiler left them in, two multiplies a lookup.)
    const __m512i width = _mm512_set1_epi32(t.width);
    const __m512i row0 = _mm512_mullo_epi32(y.x0, width), row1 = _mm512_mullo_epi32(y.x1, width);
    if (_mm512_cmpeq_epi32_mask(x.x1, _mm512_add_epi32(x.x0, one)) == 0xFFFF) {
      fetchPair(_mm512_add_epi32(row0, x.x0), p00, p01);
      fetchPair(_mm512_add_epi32(row1, x.x0), p10, p11);
    } else {
      p00 = fetch(_mm512_add_epi32(row0, x.x0)), p01 = fetch(_mm512_add_epi32(row0, x.x1));
      p10 = fetch(_mm512_add_epi32(row1, x.x0)), p11 = fetch(_mm512_add_epi32(row1, x.x1));
    }
  }
  const __m512i weightX = _mm512_slli_epi32(x.weight, 7), weightY = _mm512_slli_epi32(y.weight, 7);
  const __m512 kUnorm8 = _mm512_set1_ps(float(1.0 / 255.0));
  auto filtered = [&](int c) {   // channel c of every lane, blended, as a float
    auto channel = [&](__m512i v) { return _mm512_and_si512(_mm512_srli_epi32(v, 8 * c), low8); };
    const __m512i top = lerp8x16(weightX, channel(p00), channel(p01));
    const __m512i bottom = lerp8x16(weightX, channel(p10), channel(p11));
    return simd::Float8x2(_mm512_mul_ps(_mm512_cvtepi32_ps(lerp8x16(weightY, top, bottom)), kUnorm8));
  };
  if (grey) {
    out[0] = out[1] = out[2] = filtered(0);
    out[3] = simd::Float8x2(_mm512_mul_ps(_mm512_cvtepi32_ps(low8), kUnorm8));
  } else {
    for (int c = 0; c < 4; ++c) out[c] = filtered(c);
  }
}

// The cache lines sampleRgba8Pair will read from a texture's strip copy (texturePrefetch):
// each lane's two footprint columns, one line or two.
[[gnu::always_inline]] inline void prefetchRgba8Strips(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc) {
  const FixedTaps16 x = wrapLinearFixed16(s.v, t.width, t.sampler.wrapS);
  const FixedTaps16 y = wrapLinearFixed16(tc.v, t.height, t.sampler.wrapT);
  // A footprint whose rows are not neighbours is read texel by texel (or from rgba8); its
  // strip here is a nearby one, in the copy, and the prefetch is only a wasted one.
  const StripColumns16 at = stripColumns16(t.width, x, _mm512_min_epi32(y.x0, _mm512_set1_epi32(t.height - 2)));
  alignas(64) int units[2][16];
  _mm512_store_si512(units[0], at.left);
  _mm512_store_si512(units[1], at.right);
  const char* base = reinterpret_cast<const char*>(t.strips8.data());
  for (int i = 0; i < 16; ++i) {
    simd::prefetchLineToL2(base + size_t(unsigned(units[0][i])) * 4);
    simd::prefetchLineToL2(base + size_t(unsigned(units[1][i])) * 4);
  }
}

}  // namespace raster::sampling
#endif
