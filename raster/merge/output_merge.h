// Stage 6 helpers, the output merge's conversions for a whole lane group at once:
// depth quantization, and colour packing to RGBA8 or RGBA16F texels.
//
// Each function has a plain per-lane version (the reference: the scalar conversions of
// format/conversions.h lane by lane) and, for Float8, an AVX2 version that computes the
// same bits; tests/output_merge_test.cpp holds them to agree on every class of input.
#pragma once

#include <cstdint>

#include "raster/texture/format.h"
#include "raster/texture/texture.h"
#include "raster/simd/glsl.h"

namespace raster::output_merge {

// Depth codes of clamped window z per lane (z already clamped to [0, 1], NaN -> 0).
template <class F>
void depthCodes(F z, TexelFormat format, uint32_t* codes) {
  alignas(32) float lanes[F::kCount];
  z.store(lanes);
  for (int i = 0; i < F::kCount; ++i)
    codes[i] = format == TexelFormat::Depth24 ? format::depth24FromFloat(lanes[i]) : format::depth16FromFloat(lanes[i]);
}

// The depth test (LESS or LEQUAL on integer codes) of the covered lanes, and the depth
// write of the lanes that pass. Returns the lanes that pass.
template <int kLanes>
unsigned depthTest(const uint32_t* codes, uint32_t* depth, const size_t* texel, unsigned laneMask, bool lessEqual,
                   bool write) {
  for (int i = 0; i < kLanes; ++i) {
    if (!(laneMask >> i & 1u)) continue;
    uint32_t& stored = depth[texel[i]];
    const bool pass = lessEqual ? codes[i] <= stored : codes[i] < stored;
    if (!pass) laneMask &= ~(1u << i);
    else if (write) stored = codes[i];
  }
  return laneMask;
}

#if RASTER_AVX2
// An 8-lane group's lanes (two 2x2 quads side by side) against its two memory rows of 4
// pixels: permutevar8x32 indices from quad lane order to row-major order [top x..x+3 |
// bottom x..x+3], and back. `flipped`: the quads' rows are swapped (window-system buffers).
inline __m256i quadLanesToRows(bool flipped) {
  return flipped ? _mm256_setr_epi32(2, 3, 6, 7, 0, 1, 4, 5) : _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
}
inline __m256i rowsToQuadLanes(bool flipped) {
  return flipped ? _mm256_setr_epi32(4, 5, 0, 1, 6, 7, 2, 3) : _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
}

// The depth test on 8 codes against 8 stored codes: all bits set where the fragment passes.
// Codes are below 2^24, so signed compares are exact and stored + 1 cannot overflow.
// LESS: stored > code; LEQUAL: stored + 1 > code. (LEQUAL written as NOT(code > stored) is
// miscompiled by GCC 12 with AVX-512VL: the NOT, folded into the blend that consumes the
// mask, was dropped in depthOnlyRegion, and raster_vs_gl's depth-only cases failed.)
inline __m256i depthPasses(__m256i code, __m256i stored, bool lessEqual) {
  return lessEqual ? _mm256_cmpgt_epi32(_mm256_add_epi32(stored, _mm256_set1_epi32(1)), code)
                   : _mm256_cmpgt_epi32(stored, code);
}

// The same test for an 8-lane group: two 2x2 quads side by side, i.e. two memory rows of 4
// codes (rowTop at the group's first row, rowBottom the next). `flipped`: the quads' rows
// are swapped (window-system buffers).
// `wholeRows`: all 8 pixels lie inside the framebuffer. Then both rows are loaded and
// stored whole, the failing and uncovered lanes storing back what they read; the rows
// belong to the tile of the calling thread, so nothing else touches them meanwhile. At the
// framebuffer's right or top edge, masked loads and stores touch only covered lanes (AMD
// cores run masked stores as slow microcode, so they are kept for the edges).
inline unsigned depthTestRows(const uint32_t* codes, uint32_t* rowTop, uint32_t* rowBottom, unsigned laneMask,
                              bool flipped, bool lessEqual, bool write, bool wholeRows) {
  const __m256i toRows = quadLanesToRows(flipped), toQuads = rowsToQuadLanes(flipped);
  const __m256i covered =
      _mm256_permutevar8x32_epi32(_mm256_castps_si256(simd::Mask8::fromBits(laneMask).v), toRows);
  const __m256i code = _mm256_permutevar8x32_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(codes)), toRows);
  const __m128i maskTop = _mm256_castsi256_si128(covered), maskBottom = _mm256_extracti128_si256(covered, 1);
  const __m256i stored =
      wholeRows ? _mm256_setr_m128i(_mm_loadu_si128(reinterpret_cast<const __m128i*>(rowTop)),
                                    _mm_loadu_si128(reinterpret_cast<const __m128i*>(rowBottom)))
                : _mm256_setr_m128i(_mm_maskload_epi32(reinterpret_cast<const int*>(rowTop), maskTop),
                                    _mm_maskload_epi32(reinterpret_cast<const int*>(rowBottom), maskBottom));
  const __m256i pass = _mm256_and_si256(depthPasses(code, stored, lessEqual), covered);
  if (write && wholeRows) {
    const __m256i merged = _mm256_blendv_epi8(stored, code, pass);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(rowTop), _mm256_castsi256_si128(merged));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(rowBottom), _mm256_extracti128_si256(merged, 1));
  } else if (write) {
    _mm_maskstore_epi32(reinterpret_cast<int*>(rowTop), _mm256_castsi256_si128(pass), _mm256_castsi256_si128(code));
    _mm_maskstore_epi32(reinterpret_cast<int*>(rowBottom), _mm256_extracti128_si256(pass, 1), _mm256_extracti128_si256(code, 1));
  }
  return unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_permutevar8x32_epi32(pass, toQuads))));
}
#endif

// RGBA8 texels per lane, r in the low byte: r g b a in memory on little-endian x86.
template <class F>
void packRgba8(const glsl::vec4<F>& color, uint32_t* texels) {
  alignas(32) float c[4][F::kCount];
  glsl::storePlanes(color, c);
  for (int i = 0; i < F::kCount; ++i) {
    texels[i] = 0;
    for (int ch = 0; ch < 4; ++ch) texels[i] |= uint32_t(format::unorm8FromFloat(c[ch][i])) << (8 * ch);
  }
}

// Writes the covered lanes' colours to RGBA16F texels (4 halves each, at texel[i] * 4):
// the source converted toward zero, or with ONE/ONE blending the exact destination plus the
// source in float32, converted once toward zero.
template <class F>
void writeHalfTexels(const glsl::vec4<F>& color, uint16_t* texels, const size_t* texel, unsigned laneMask, bool blend) {
  alignas(32) float c[4][F::kCount];
  glsl::storePlanes(color, c);
  for (int i = 0; i < F::kCount; ++i) {
    if (!(laneMask >> i & 1u)) continue;
    uint16_t* dst = texels + texel[i] * 4;
    for (int ch = 0; ch < 4; ++ch) {
      const float value = blend ? format::floatFromHalf(dst[ch]) + c[ch][i] : c[ch][i];
      dst[ch] = format::halfFromFloatTowardZero(value);
    }
  }
}

#if RASTER_AVX2
// F16C's vcvtps2ph with truncation is halfFromFloatTowardZero (tests/simd and format hold
// them equal on every class of input); vcvtph2ps is exact.
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
      _mm_storel_epi64(reinterpret_cast<__m128i*>(dst), _mm_cvtps_ph(value, _MM_FROUND_TO_ZERO));
    }
  }
}

template <>
inline void depthCodes<simd::Float8>(simd::Float8 z, TexelFormat format, uint32_t* codes) {
  __m256i result;
  if (format == TexelFormat::Depth24) {
    // z * 16777215.0f, cvtps2dq (round to nearest even); z in [0, 1] cannot overflow.
    result = _mm256_cvtps_epi32(_mm256_mul_ps(z.v, _mm256_set1_ps(16777215.0f)));
  } else {
    // z * (65535/65536)f + 128.0f, low 16 bits of the float.
    const __m256 t = _mm256_add_ps(_mm256_mul_ps(z.v, _mm256_set1_ps(65535.0f / 65536.0f)), _mm256_set1_ps(128.0f));
    result = _mm256_and_si256(_mm256_castps_si256(t), _mm256_set1_epi32(0xFFFF));
  }
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(codes), result);
}

#if RASTER_ZMM_PAIRS
// depthCodes<Float8> and depthPasses for 16 lanes in one 512-bit register (a 4x4 block's
// depth test): the same operations per lane; the passing lanes among `covered` as a mask.
inline __m512i depthCodes16(simd::Float8x2 z, TexelFormat format) {
  if (format == TexelFormat::Depth24) return _mm512_cvtps_epi32(_mm512_mul_ps(z.v, _mm512_set1_ps(16777215.0f)));
  const __m512 t = _mm512_add_ps(_mm512_mul_ps(z.v, _mm512_set1_ps(65535.0f / 65536.0f)), _mm512_set1_ps(128.0f));
  return _mm512_and_si512(_mm512_castps_si512(t), _mm512_set1_epi32(0xFFFF));
}
inline __mmask16 depthPasses16(__mmask16 covered, __m512i code, __m512i stored, bool lessEqual) {
  return lessEqual ? _mm512_mask_cmpgt_epi32_mask(covered, _mm512_add_epi32(stored, _mm512_set1_epi32(1)), code)
                   : _mm512_mask_cmpgt_epi32_mask(covered, stored, code);
}
#endif

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
// side (raster_tile.cpp, LaneLayout), so lanes 0 1 4 5 are four neighbouring texels of one
// row, starting at texel[0], and lanes 2 3 6 7 of the other, starting at texel[2]: one
// store per row, or per pair of texels for RGBA16F, instead of one per lane.
inline void writeRgba8Rows(const glsl::vec4<simd::Float8>& color, uint8_t* texels, const size_t* texel) {
  // Lanes 0 1 4 5 | 2 3 6 7 (texel[0]'s row, then texel[2]'s), whichever row is on top.
  const __m256i rows = _mm256_permutevar8x32_epi32(packRgba8Lanes(color), quadLanesToRows(false));
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
    _mm_storeu_si128(dst, _mm256_cvtps_ph(value, _MM_FROUND_TO_ZERO));
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

// The same for a pair of whole groups (simd::Float8x2), `first` the low group's texels and
// `second` the high one's. With 512-bit pairs, one conversion and one lane-to-row permute
// serve both groups.
inline void writeRgba8RowsPair(const glsl::vec4<simd::Float8x2>& color, uint8_t* texels, const size_t* first,
                               const size_t* second) {
#if RASTER_ZMM_PAIRS
  auto channel = [](__m512 x) {   // packRgba8Lanes' conversion, 16 lanes
    const __m512 clamped = _mm512_min_ps(_mm512_set1_ps(1.0f), x);
    const __m512i scaled = _mm512_cvtps_epi32(_mm512_mul_ps(clamped, _mm512_set1_ps(255.0f)));
    return _mm512_min_epi32(_mm512_max_epi32(scaled, _mm512_setzero_si512()), _mm512_set1_epi32(255));
  };
  const __m512i r = channel(color.x.v), g = channel(color.y.v), b = channel(color.z.v), a = channel(color.w.v);
  const __m512i packed = _mm512_or_si512(_mm512_or_si512(r, _mm512_slli_epi32(g, 8)),
                                         _mm512_or_si512(_mm512_slli_epi32(b, 16), _mm512_slli_epi32(a, 24)));
  // quadLanesToRows(false) in each half: [first's two rows | second's two rows].
  const __m512i rows = _mm512_permutexvar_epi32(
      _mm512_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7, 8, 9, 12, 13, 10, 11, 14, 15), packed);
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
#endif

}  // namespace raster::output_merge
