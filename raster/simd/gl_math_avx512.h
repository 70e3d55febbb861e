// gl_math_bits.h's integer lanes for Float8x2 in one 512-bit register (AVX-512).
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include "raster/simd/intrinsics.h"

namespace raster::glsl::detail {

template <class F> struct IntLanesOf;

// Float8x2 in one 512-bit register: the same, all 16 lanes at once.
struct U8x2 {
  __m512i v;
  U8x2() = default;
  U8x2(uint32_t s) : v(_mm512_set1_epi32(int(s))) {}  // NOLINT: broadcast
  explicit U8x2(__m512i x) : v(x) {}
  friend U8x2 operator&(U8x2 a, U8x2 b) { return U8x2(_mm512_and_si512(a.v, b.v)); }
  friend U8x2 operator|(U8x2 a, U8x2 b) { return U8x2(_mm512_or_si512(a.v, b.v)); }
  friend U8x2 operator^(U8x2 a, U8x2 b) { return U8x2(_mm512_xor_si512(a.v, b.v)); }
  friend U8x2 operator+(U8x2 a, U8x2 b) { return U8x2(_mm512_add_epi32(a.v, b.v)); }
  friend U8x2 operator-(U8x2 a, U8x2 b) { return U8x2(_mm512_sub_epi32(a.v, b.v)); }
  friend U8x2 operator~(U8x2 a) { return U8x2(_mm512_xor_si512(a.v, _mm512_set1_epi32(-1))); }
  friend U8x2 operator<<(U8x2 a, int n) { return U8x2(_mm512_slli_epi32(a.v, unsigned(n))); }
  friend U8x2 operator>>(U8x2 a, int n) { return U8x2(_mm512_srli_epi32(a.v, unsigned(n))); }
};
inline U8x2 asBits(simd::Float8x2 f) { return U8x2(_mm512_castps_si512(f.v)); }
inline simd::Float8x2 asFloat(U8x2 u) { return simd::Float8x2(_mm512_castsi512_ps(u.v)); }
inline U8x2 cvtt(simd::Float8x2 f) { return U8x2(_mm512_cvttps_epi32(f.v)); }
inline simd::Float8x2 cvt(U8x2 u) { return simd::Float8x2(_mm512_cvtepi32_ps(u.v)); }
inline simd::Mask8x2 eq(U8x2 a, U8x2 b) { return {_mm512_cmpeq_epi32_mask(a.v, b.v)}; }
template <> struct IntLanesOf<simd::Float8x2> { using type = U8x2; };

// log2Core's exponent and mantissa (gl_math_exp_log.h) in one instruction each, for 8 and 16 lanes:
// vgetexpps gives floor(log2 |x|) and vgetmantps the significand in [1, 2), which for a
// positive normal x are the bit operations' float(exponent - 127) and (mantissa | 1.0).
// They differ elsewhere (getexp(0) is -inf, not -127; a denormal's true exponent, not -127),
// so only pow's plain paths use them, whose bases are normal or masked zeros; log2Impl, which
// may meet a kept denormal, takes the bit operations. Four and two operations fewer per
// log2: pow is log2, then exp2 (docs/notes/2026-11-21-what-made-it-faster.md, "log2 by
// getexp and getmant").
inline simd::Float8x2 log2Exponent(simd::Float8x2 x) { return simd::Float8x2(_mm512_getexp_ps(x.v)); }
inline simd::Float8x2 log2Mantissa(simd::Float8x2 x) {
  return simd::Float8x2(_mm512_getmant_ps(x.v, _MM_MANT_NORM_1_2, _MM_MANT_SIGN_zero));
}
inline simd::Float8 log2Exponent(simd::Float8 x) { return simd::Float8(_mm256_getexp_ps(x.v)); }
inline simd::Float8 log2Mantissa(simd::Float8 x) {
  return simd::Float8(_mm256_getmant_ps(x.v, _MM_MANT_NORM_1_2, _MM_MANT_SIGN_zero));
}

// scaleByPowerOfTwo (gl_math_exp_log.h) in one instruction: vscalefps gives p * 2^floor(ipart),
// the same product wherever gl_math_exp_log.h calls it (an integral ipart in [-126, 125], p in
// [1, 2]: no rounding, no overflow, no denormal).
inline simd::Float8x2 scaleByPowerOfTwo(simd::Float8x2 p, simd::Float8x2 ipart) {
  return simd::Float8x2(_mm512_scalef_ps(p.v, ipart.v));
}
inline simd::Float8 scaleByPowerOfTwo(simd::Float8 p, simd::Float8 ipart) {
  return simd::Float8(_mm256_scalef_ps(p.v, ipart.v));
}

}  // namespace raster::glsl::detail
#endif
