// The output merge for Float8 groups (AVX2; the pair writes use AVX-512 where built): a
// group's colours converted at once and written a memory row at a time. Every bit equals
// color_write.h's.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include <vector>

#include "raster/merge/color_write.h"
#include "raster/simd/intrinsics.h"
#include "raster/simd/prefetch.h"

namespace raster::merge {

// F16C's vcvtps2ph with truncation is halfFromFloatTowardZero, with round-to-nearest
// halfFromFloatNearestEven (tests/simd and format hold them equal on every class of input);
// vcvtph2ps is exact. The rounding is an immediate, so each method is its own instruction.
inline __m128i halvesOf(__m128 value) {
  return methods::halfNearestEven(methods::active().half) ? _mm_cvtps_ph(value, _MM_FROUND_TO_NEAREST_INT)
                                                          : _mm_cvtps_ph(value, _MM_FROUND_TO_ZERO);
}
inline __m128i halvesOf(__m256 value) {
  return methods::halfNearestEven(methods::active().half) ? _mm256_cvtps_ph(value, _MM_FROUND_TO_NEAREST_INT)
                                                          : _mm256_cvtps_ph(value, _MM_FROUND_TO_ZERO);
}

// Planes -> one RGBA vector per lane: v[k] holds lane k in its low half, lane k + 4 high.
inline void lanesToTexels(const glsl::vec4<simd::Float8>& color, __m256 v[4]) {
  const __m256 t0 = _mm256_unpacklo_ps(color.x.v, color.y.v), t1 = _mm256_unpackhi_ps(color.x.v, color.y.v);
  const __m256 t2 = _mm256_unpacklo_ps(color.z.v, color.w.v), t3 = _mm256_unpackhi_ps(color.z.v, color.w.v);
  v[0] = _mm256_shuffle_ps(t0, t2, 0x44);
  v[1] = _mm256_shuffle_ps(t0, t2, 0xEE);
  v[2] = _mm256_shuffle_ps(t1, t3, 0x44);
  v[3] = _mm256_shuffle_ps(t1, t3, 0xEE);
}

template <>
inline void writeHalfTexels<simd::Float8>(const glsl::vec4<simd::Float8>& color, uint16_t* texels, const size_t* texel,
                                          unsigned laneMask, bool blend) {
  __m256 v[4];
  lanesToTexels(color, v);
  for (int k = 0; k < 4; ++k) {
    for (int half = 0; half < 2; ++half) {
      const int lane = k + 4 * half;
      if (!(laneMask >> lane & 1u)) continue;
      uint16_t* dst = texels + texel[lane] * 4;
      __m128 value = half ? _mm256_extractf128_ps(v[k], 1) : _mm256_castps256_ps128(v[k]);
      if (blend) value = _mm_add_ps(_mm_cvtph_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(dst))), value);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(dst), halvesOf(value));
    }
  }
}

// packRgba8 for 8 lanes, in a register.
inline __m256i packRgba8Lanes(const glsl::vec4<simd::Float8>& color) {
  // min(1, x) keeps NaN (minps returns its second operand), * 255, cvtps2dq (NaN -> INT_MIN),
  // clamp to [0, 255]: the same as unorm8FromFloat per channel.
  auto channel = [](__m256 x) {
    const __m256 clamped = _mm256_min_ps(_mm256_set1_ps(1.0f), x);
    const __m256i scaled = _mm256_cvtps_epi32(_mm256_mul_ps(clamped, _mm256_set1_ps(255.0f)));
    return _mm256_min_epi32(_mm256_max_epi32(scaled, _mm256_setzero_si256()), _mm256_set1_epi32(255));
  };
  const __m256i r = channel(color.x.v), g = channel(color.y.v), b = channel(color.z.v), a = channel(color.w.v);
  return _mm256_or_si256(_mm256_or_si256(r, _mm256_slli_epi32(g, 8)),
                         _mm256_or_si256(_mm256_slli_epi32(b, 16), _mm256_slli_epi32(a, 24)));
}

template <>
inline void packRgba8<simd::Float8>(const glsl::vec4<simd::Float8>& color, uint32_t* texels) {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(texels), packRgba8Lanes(color));
}

// A whole 8-lane group, not blended, written row by row. The group is two quads side by
// side (simd/lane_layout.h), so lanes 0 1 4 5 are four neighbouring texels of one
// row, starting at texel[0], and lanes 2 3 6 7 of the other, starting at texel[2]: one
// store per row, or per pair of texels for RGBA16F, instead of one per lane.
inline void writeRgba8Rows(const glsl::vec4<simd::Float8>& color, uint8_t* texels, const size_t* texel) {
  // Lanes 0 1 4 5 | 2 3 6 7 (texel[0]'s row, then texel[2]'s), whichever row is on top.
  const __m256i rows = _mm256_permutevar8x32_epi32(packRgba8Lanes(color), simd::quadLanesToRows(false));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(texels + texel[0] * 4), _mm256_castsi256_si128(rows));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(texels + texel[2] * 4), _mm256_extracti128_si256(rows, 1));
}
// With `additive`, each texel gets writeHalfTexels' blend: its stored value plus the colour.
inline void writeHalfRows(const glsl::vec4<simd::Float8>& color, uint16_t* texels, const size_t* texel,
                          bool additive = false) {
  __m256 v[4];
  lanesToTexels(color, v);
  auto write = [&](size_t at, __m256 value) {
    __m128i* dst = reinterpret_cast<__m128i*>(texels + at * 4);
    if (additive) value = _mm256_add_ps(_mm256_cvtph_ps(_mm_loadu_si128(dst)), value);
    _mm_storeu_si128(dst, halvesOf(value));
  };
  // Lanes k, k + 1 (k = 0, 2) and k + 4, k + 5: neighbouring texels.
  for (int k = 0; k < 4; k += 2) {
    write(texel[k], _mm256_permute2f128_ps(v[k], v[k + 1], 0x20));
    write(texel[k + 4], _mm256_permute2f128_ps(v[k], v[k + 1], 0x31));
  }
}

// A pair's colour (simd::Float8x2) as its two groups' colours: the low group, the high one.
inline glsl::vec4<simd::Float8> lowGroup(const glsl::vec4<simd::Float8x2>& c) {
  return {c.x.low(), c.y.low(), c.z.low(), c.w.low()};
}
inline glsl::vec4<simd::Float8> highGroup(const glsl::vec4<simd::Float8x2>& c) {
  return {c.x.high(), c.y.high(), c.z.high(), c.w.high()};
}

#if RASTER_ZMM_PAIRS
// A pair's RGBA8 texels as the rows they go to, 16 bytes each: [the low group's lane 0 row |
// its lane 2 row | the high group's lane 0 row | its lane 2 row]. One conversion and one
// lane-to-row permute serve both groups.
inline __m512i rgba8RowsPair(const glsl::vec4<simd::Float8x2>& color) {
  auto channel = [](__m512 x) {   // packRgba8Lanes' conversion, 16 lanes
    const __m512 clamped = _mm512_min_ps(_mm512_set1_ps(1.0f), x);
    const __m512i scaled = _mm512_cvtps_epi32(_mm512_mul_ps(clamped, _mm512_set1_ps(255.0f)));
    return _mm512_min_epi32(_mm512_max_epi32(scaled, _mm512_setzero_si512()), _mm512_set1_epi32(255));
  };
  const __m512i r = channel(color.x.v), g = channel(color.y.v), b = channel(color.z.v), a = channel(color.w.v);
  const __m512i packed = _mm512_or_si512(_mm512_or_si512(r, _mm512_slli_epi32(g, 8)),
                                         _mm512_or_si512(_mm512_slli_epi32(b, 16), _mm512_slli_epi32(a, 24)));
  // simd::quadLanesToRows(false) in each half.
  return _mm512_permutexvar_epi32(_mm512_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7, 8, 9, 12, 13, 10, 11, 14, 15), packed);
}
#endif

// writeRgba8Rows for a pair of whole groups (simd::Float8x2), `first` the low group's texels
// and `second` the high one's; with 512-bit pairs, from rgba8RowsPair.
inline void writeRgba8RowsPair(const glsl::vec4<simd::Float8x2>& color, uint8_t* texels, const size_t* first,
                               const size_t* second) {
#if RASTER_ZMM_PAIRS
  const __m512i rows = rgba8RowsPair(color);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(texels + first[0] * 4), _mm512_castsi512_si128(rows));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(texels + first[2] * 4), _mm512_extracti32x4_epi32(rows, 1));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(texels + second[0] * 4), _mm512_extracti32x4_epi32(rows, 2));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(texels + second[2] * 4), _mm512_extracti32x4_epi32(rows, 3));
#else
  writeRgba8Rows(lowGroup(color), texels, first);
  writeRgba8Rows(highGroup(color), texels, second);
#endif
}
inline void writeHalfRowsPair(const glsl::vec4<simd::Float8x2>& color, uint16_t* texels, const size_t* first,
                              const size_t* second, bool additive = false) {
  writeHalfRows(lowGroup(color), texels, first, additive);
  writeHalfRows(highGroup(color), texels, second, additive);
}
// A covered tile (covered_tile_avx2.h) stores each target row in tile-wide runs, 64 texels,
// too short for the hardware prefetchers to fetch lines ahead of the stores, so each store
// waited on its line's read for ownership: the hdr bright pass and composite write 16.6 and
// 8.3 MB at 1920x1080. These prefetch, for the `rows` rows of a block whose top-left texel is
// `origin`, rows `stride` texels apart, the line simd::kPrefetchTexelsAhead to the right, in an
// RGBA8 or RGBA16F target (others are left alone).
template <class Channel, class Allocator>
inline void prefetchRowsForWrite(const std::vector<Channel, Allocator>& texels, size_t origin, size_t stride, int rows) {
  if (texels.size() >= 4) simd::prefetchRowsAhead(texels.data(), texels.size() / 4 - 1, origin, stride, rows);
}
inline void prefetchBlockRowsForWrite(const Texture& target, size_t origin, size_t stride, int rows) {
  if (target.format == TexelFormat::RGBA16F) prefetchRowsForWrite(target.half, origin, stride, rows);
  else if (target.format == TexelFormat::RGBA8) prefetchRowsForWrite(target.rgba8, origin, stride, rows);
}

// writeColorOutput for a Float8 group: whole groups a row at a time where the format allows.
[[gnu::noinline]] inline void writeColorOutput(Texture& target, const glsl::vec4<simd::Float8>& color, const size_t* texel,
                             unsigned laneMask, bool blendAdditive) {
  if (laneMask == 0xFFu) {
    if (target.format == TexelFormat::RGBA8 && !blendAdditive) return writeRgba8Rows(color, target.rgba8.data(), texel);
    if (target.format == TexelFormat::RGBA16F) return writeHalfRows(color, target.half.data(), texel, blendAdditive);
  }
  writeColorOutput<simd::Float8>(target, color, texel, laneMask, blendAdditive);
}

}  // namespace raster::merge
#endif
