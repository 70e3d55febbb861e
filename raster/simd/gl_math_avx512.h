// gl_math.h's integer lanes for Float8x2 in one 512-bit register (AVX-512).
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

}  // namespace raster::glsl::detail
#endif
