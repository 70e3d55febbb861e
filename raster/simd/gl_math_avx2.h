// The 32-bit integer lanes gl_math_bits.h's bit manipulation needs, for Float8 (U8) and for
// Float8x2 as two halves (U8x2; gl_math_avx512.h when Float8x2 is one 512-bit register).
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"

namespace raster::glsl::detail {

template <class F> struct IntLanesOf;

struct U8 {
  __m256i v;
  U8() = default;
  U8(uint32_t s) : v(_mm256_set1_epi32(int(s))) {}  // NOLINT: broadcast
  explicit U8(__m256i x) : v(x) {}
  friend U8 operator&(U8 a, U8 b) { return U8(_mm256_and_si256(a.v, b.v)); }
  friend U8 operator|(U8 a, U8 b) { return U8(_mm256_or_si256(a.v, b.v)); }
  friend U8 operator^(U8 a, U8 b) { return U8(_mm256_xor_si256(a.v, b.v)); }
  friend U8 operator+(U8 a, U8 b) { return U8(_mm256_add_epi32(a.v, b.v)); }
  friend U8 operator-(U8 a, U8 b) { return U8(_mm256_sub_epi32(a.v, b.v)); }
  friend U8 operator~(U8 a) { return U8(_mm256_xor_si256(a.v, _mm256_set1_epi32(-1))); }
  friend U8 operator<<(U8 a, int n) { return U8(_mm256_slli_epi32(a.v, n)); }
  friend U8 operator>>(U8 a, int n) { return U8(_mm256_srli_epi32(a.v, n)); }
};
inline U8 asBits(simd::Float8 f) { return U8(_mm256_castps_si256(f.v)); }
inline simd::Float8 asFloat(U8 u) { return simd::Float8(_mm256_castsi256_ps(u.v)); }
inline U8 cvtt(simd::Float8 f) { return U8(_mm256_cvttps_epi32(f.v)); }
inline simd::Float8 cvt(U8 u) { return simd::Float8(_mm256_cvtepi32_ps(u.v)); }
inline simd::Mask8 eq(U8 a, U8 b) { return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(a.v, b.v))}; }
template <> struct IntLanesOf<simd::Float8> { using type = U8; };

#if !RASTER_ZMM_PAIRS
// Float8x2: the same, half by half.
struct U8x2 {
  U8 lo, hi;
  U8x2() = default;
  U8x2(uint32_t s) : lo(s), hi(s) {}  // NOLINT: broadcast
  U8x2(U8 low, U8 high) : lo(low), hi(high) {}
  friend U8x2 operator&(U8x2 a, U8x2 b) { return {a.lo & b.lo, a.hi & b.hi}; }
  friend U8x2 operator|(U8x2 a, U8x2 b) { return {a.lo | b.lo, a.hi | b.hi}; }
  friend U8x2 operator^(U8x2 a, U8x2 b) { return {a.lo ^ b.lo, a.hi ^ b.hi}; }
  friend U8x2 operator+(U8x2 a, U8x2 b) { return {a.lo + b.lo, a.hi + b.hi}; }
  friend U8x2 operator-(U8x2 a, U8x2 b) { return {a.lo - b.lo, a.hi - b.hi}; }
  friend U8x2 operator~(U8x2 a) { return {~a.lo, ~a.hi}; }
  friend U8x2 operator<<(U8x2 a, int n) { return {a.lo << n, a.hi << n}; }
  friend U8x2 operator>>(U8x2 a, int n) { return {a.lo >> n, a.hi >> n}; }
};
inline U8x2 asBits(simd::Float8x2 f) { return {asBits(f.lo), asBits(f.hi)}; }
inline simd::Float8x2 asFloat(U8x2 u) { return {asFloat(u.lo), asFloat(u.hi)}; }
inline U8x2 cvtt(simd::Float8x2 f) { return {cvtt(f.lo), cvtt(f.hi)}; }
inline simd::Float8x2 cvt(U8x2 u) { return {cvt(u.lo), cvt(u.hi)}; }
inline simd::Mask8x2 eq(U8x2 a, U8x2 b) { return {eq(a.lo, b.lo), eq(a.hi, b.hi)}; }
template <> struct IntLanesOf<simd::Float8x2> { using type = U8x2; };
#endif

}  // namespace raster::glsl::detail

#include "raster/simd/gl_math_avx512.h"
#endif
