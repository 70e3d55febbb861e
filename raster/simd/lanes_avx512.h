// Float8x2 in one 512-bit register (AVX-512F/DQ/VL): two Float8 groups shaded as one.
// Same semantics as Lanes<16> (lanes.h), lane for lane. Included through isa.h only, after
// lanes_avx2.h, when the build has AVX-512.
// With AVX-512 both halves live in one 512-bit register: each operation is one instruction
// instead of two (the same IEEE operation on each lane, so the same bits), which halves
// what the core must decode and track for the shader arithmetic (pow and ACES 1.3x faster
// measured on Zen 4, which executes it as two 256-bit halves).
#pragma once

#include "raster/simd/lanes_avx2.h"

namespace raster::simd {

struct Mask8x2 {
  __mmask16 k;   // bit i: lane i (0-7 the low group, 8-15 the high one)
  friend Mask8x2 operator&(Mask8x2 a, Mask8x2 b) { return {__mmask16(a.k & b.k)}; }
  friend Mask8x2 operator|(Mask8x2 a, Mask8x2 b) { return {__mmask16(a.k | b.k)}; }
  friend Mask8x2 operator!(Mask8x2 a) { return {__mmask16(~a.k)}; }
  unsigned bits() const { return k; }
  static Mask8x2 fromBits(unsigned b) { return {__mmask16(b)}; }
  Mask8 low() const { return {_mm256_castsi256_ps(_mm256_movm_epi32(__mmask8(k)))}; }
  Mask8 high() const { return {_mm256_castsi256_ps(_mm256_movm_epi32(__mmask8(k >> 8)))}; }
};

struct Float8x2 {
  static constexpr int kCount = 16;
  using MaskType = Mask8x2;
  __m512 v;

  Float8x2() = default;
  Float8x2(float s) : v(_mm512_set1_ps(s)) {}  // NOLINT: broadcast, as GLSL scalars
  Float8x2(Float8 low, Float8 high) : v(_mm512_insertf32x8(_mm512_castps256_ps512(low.v), high.v, 1)) {}
  explicit Float8x2(__m512 x) : v(x) {}
  static Float8x2 load(const float* p) { return Float8x2(_mm512_loadu_ps(p)); }
  static Float8x2 gather(const float* base, const int* index) {   // lane i reads base[index[i]]
    return Float8x2(_mm512_i32gather_ps(_mm512_loadu_si512(index), base, 4));
  }
  void store(float* p) const { _mm512_storeu_ps(p, v); }
  float operator[](int i) const { alignas(64) float t[16]; _mm512_store_ps(t, v); return t[i]; }
  Float8 low() const { return Float8(_mm512_extractf32x8_ps(v, 0)); }
  Float8 high() const { return Float8(_mm512_extractf32x8_ps(v, 1)); }

  friend Float8x2 operator+(Float8x2 a, Float8x2 b) { return Float8x2(_mm512_add_ps(a.v, b.v)); }
  friend Float8x2 operator-(Float8x2 a, Float8x2 b) { return Float8x2(_mm512_sub_ps(a.v, b.v)); }
  friend Float8x2 operator*(Float8x2 a, Float8x2 b) { return Float8x2(_mm512_mul_ps(a.v, b.v)); }
  friend Float8x2 operator/(Float8x2 a, Float8x2 b) { return Float8x2(_mm512_div_ps(a.v, b.v)); }
  friend Float8x2 operator-(Float8x2 a) { return Float8x2(_mm512_xor_ps(a.v, _mm512_set1_ps(-0.0f))); }
  Float8x2& operator+=(Float8x2 b) { return *this = *this + b; }
  Float8x2& operator-=(Float8x2 b) { return *this = *this - b; }
  Float8x2& operator*=(Float8x2 b) { return *this = *this * b; }
  Float8x2& operator/=(Float8x2 b) { return *this = *this / b; }

  friend Mask8x2 operator<(Float8x2 a, Float8x2 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ)}; }
  friend Mask8x2 operator<=(Float8x2 a, Float8x2 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ)}; }
  friend Mask8x2 operator>(Float8x2 a, Float8x2 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GT_OQ)}; }
  friend Mask8x2 operator>=(Float8x2 a, Float8x2 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OQ)}; }
  friend Mask8x2 operator==(Float8x2 a, Float8x2 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_EQ_OQ)}; }
};

inline Float8x2 select(Mask8x2 m, Float8x2 a, Float8x2 b) { return Float8x2(_mm512_mask_blend_ps(m.k, b.v, a.v)); }
inline Float8x2 fma(Float8x2 a, Float8x2 b, Float8x2 c) { return Float8x2(_mm512_fmadd_ps(a.v, b.v, c.v)); }
// As Float8: min/max return the second operand when either is NaN.
inline Float8x2 min(Float8x2 a, Float8x2 b) { return Float8x2(_mm512_min_ps(a.v, b.v)); }
inline Float8x2 max(Float8x2 a, Float8x2 b) { return Float8x2(_mm512_max_ps(a.v, b.v)); }
inline Float8x2 floor(Float8x2 a) { return Float8x2(_mm512_roundscale_ps(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)); }
inline Float8x2 sqrt(Float8x2 a) { return Float8x2(_mm512_sqrt_ps(a.v)); }
inline Float8x2 abs(Float8x2 a) { return Float8x2(_mm512_andnot_ps(_mm512_set1_ps(-0.0f), a.v)); }
// storeLanesTransposed (lanes.h) for sixteen lanes: each half by Float8's 8x8 transpose.
inline void storeLanesTransposed(const Float8x2* rows, float* out, size_t stride, int count) {
  Float8 low[8], high[8];
  for (int r = 0; r < 8; ++r) low[r] = rows[r].low(), high[r] = rows[r].high();
  storeLanesTransposed(low, out, stride, count < 8 ? count : 8);
  if (count > 8) storeLanesTransposed(high, out + 8 * stride, stride, count - 8);
}
inline bool any(Mask8x2 m) { return m.k != 0; }
inline bool all(Mask8x2 m) { return m.k == 0xFFFFu; }
// Float8's in-lane shuffles, on all four 128-bit lanes (one quad each).
inline Float8x2 quadDdx(Float8x2 a) {
  return Float8x2(_mm512_sub_ps(_mm512_permute_ps(a.v, _MM_SHUFFLE(3, 3, 1, 1)), _mm512_permute_ps(a.v, _MM_SHUFFLE(2, 2, 0, 0))));
}
inline Float8x2 quadDdy(Float8x2 a) {
  return Float8x2(_mm512_sub_ps(_mm512_permute_ps(a.v, _MM_SHUFFLE(3, 2, 3, 2)), _mm512_permute_ps(a.v, _MM_SHUFFLE(1, 0, 1, 0))));
}

}  // namespace raster::simd
