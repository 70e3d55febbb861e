// Float8 (AVX2): 8 lanes, two 2x2 quads side by side, as llvmpipe's 8-wide shader; and
// Float8x2, two Float8 groups shaded as one, as two halves. Same semantics as Lanes<8> and
// Lanes<16> (lanes.h), lane for lane. Included through isa.h only.
#pragma once

#include "raster/simd/intrinsics.h"
#include "raster/simd/lanes.h"

namespace raster::simd {

// ---------------------------------------------------------------------------------------
// Float8: the AVX2 fast path. Same semantics as Lanes<8>, lane for lane.
struct Mask8 {
  __m256 v;
  friend Mask8 operator&(Mask8 a, Mask8 b) { return {_mm256_and_ps(a.v, b.v)}; }
  friend Mask8 operator|(Mask8 a, Mask8 b) { return {_mm256_or_ps(a.v, b.v)}; }
  friend Mask8 operator!(Mask8 a) { return {_mm256_xor_ps(a.v, _mm256_castsi256_ps(_mm256_set1_epi32(-1)))}; }
  unsigned bits() const { return unsigned(_mm256_movemask_ps(v)); }
  static Mask8 fromBits(unsigned b) {
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const __m256i set = _mm256_and_si256(_mm256_set1_epi32(int(b)), bit);
    return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(set, bit))};
  }
};

struct Float8 {
  static constexpr int kCount = 8;
  using MaskType = Mask8;
  __m256 v;

  Float8() = default;
  Float8(float s) : v(_mm256_set1_ps(s)) {}  // NOLINT: broadcast, as GLSL scalars
  explicit Float8(__m256 x) : v(x) {}
  static Float8 load(const float* p) { return Float8(_mm256_loadu_ps(p)); }
  static Float8 gather(const float* base, const int* index) {   // lane i reads base[index[i]]
    return Float8(_mm256_i32gather_ps(base, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(index)), 4));
  }
  void store(float* p) const { _mm256_storeu_ps(p, v); }
  float operator[](int i) const { alignas(32) float t[8]; _mm256_store_ps(t, v); return t[i]; }

  friend Float8 operator+(Float8 a, Float8 b) { return Float8(_mm256_add_ps(a.v, b.v)); }
  friend Float8 operator-(Float8 a, Float8 b) { return Float8(_mm256_sub_ps(a.v, b.v)); }
  friend Float8 operator*(Float8 a, Float8 b) { return Float8(_mm256_mul_ps(a.v, b.v)); }
  friend Float8 operator/(Float8 a, Float8 b) { return Float8(_mm256_div_ps(a.v, b.v)); }
  friend Float8 operator-(Float8 a) { return Float8(_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))); }
  Float8& operator+=(Float8 b) { return *this = *this + b; }
  Float8& operator-=(Float8 b) { return *this = *this - b; }
  Float8& operator*=(Float8 b) { return *this = *this * b; }
  Float8& operator/=(Float8 b) { return *this = *this / b; }

  friend Mask8 operator<(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
  friend Mask8 operator<=(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)}; }
  friend Mask8 operator>(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
  friend Mask8 operator>=(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)}; }
  friend Mask8 operator==(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ)}; }
};

inline Float8 select(Mask8 m, Float8 a, Float8 b) { return Float8(_mm256_blendv_ps(b.v, a.v, m.v)); }
inline Float8 fma(Float8 a, Float8 b, Float8 c) { return Float8(_mm256_fmadd_ps(a.v, b.v, c.v)); }
// _mm256_min_ps(a, b) returns b when either is NaN: the same as Lanes' a < b ? a : b.
inline Float8 min(Float8 a, Float8 b) { return Float8(_mm256_min_ps(a.v, b.v)); }
inline Float8 max(Float8 a, Float8 b) { return Float8(_mm256_max_ps(a.v, b.v)); }
inline Float8 floor(Float8 a) { return Float8(_mm256_floor_ps(a.v)); }
inline Float8 sqrt(Float8 a) { return Float8(_mm256_sqrt_ps(a.v)); }
inline Float8 abs(Float8 a) { return Float8(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v)); }
inline bool any(Mask8 m) { return m.bits() != 0; }
inline bool all(Mask8 m) { return m.bits() == 0xFFu; }

inline Float8 quadDdx(Float8 a) {
  // Per quad: (a1 - a0) for lanes 0,1 and (a3 - a2) for lanes 2,3.
  const __m256 right = _mm256_permute_ps(a.v, _MM_SHUFFLE(3, 3, 1, 1));
  const __m256 left = _mm256_permute_ps(a.v, _MM_SHUFFLE(2, 2, 0, 0));
  return Float8(_mm256_sub_ps(right, left));
}
inline Float8 quadDdy(Float8 a) {
  // Per quad: (a2 - a0) for lanes 0,2 and (a3 - a1) for lanes 1,3.
  const __m256 bottom = _mm256_permute_ps(a.v, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 top = _mm256_permute_ps(a.v, _MM_SHUFFLE(1, 0, 1, 0));
  return Float8(_mm256_sub_ps(bottom, top));
}

// An 8-lane group (two 2x2 quads side by side) against its two memory rows of 4 pixels:
// permutevar8x32 indices from quad lane order to row-major order [top x..x+3 | bottom
// x..x+3], and back. `flipped`: the quads' rows are swapped (window-system buffers).
inline __m256i quadLanesToRows(bool flipped) {
  return flipped ? _mm256_setr_epi32(2, 3, 6, 7, 0, 1, 4, 5) : _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
}
inline __m256i rowsToQuadLanes(bool flipped) {
  return flipped ? _mm256_setr_epi32(4, 5, 0, 1, 6, 7, 2, 3) : _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
}

// storeLanesTransposed (lanes.h) for eight whole lanes: one 8x8 transpose (unpacks, then
// shuffles within 128-bit halves, then the halves exchanged) and a 32-byte store a lane,
// in place of 64 single floats.
inline void storeLanesTransposed(const Float8* rows, float* out, size_t stride, int count) {
  if (count < 8) {
    storeLanesTransposed<Float8>(rows, out, stride, count);
    return;
  }
  const __m256 t0 = _mm256_unpacklo_ps(rows[0].v, rows[1].v), t1 = _mm256_unpackhi_ps(rows[0].v, rows[1].v);
  const __m256 t2 = _mm256_unpacklo_ps(rows[2].v, rows[3].v), t3 = _mm256_unpackhi_ps(rows[2].v, rows[3].v);
  const __m256 t4 = _mm256_unpacklo_ps(rows[4].v, rows[5].v), t5 = _mm256_unpackhi_ps(rows[4].v, rows[5].v);
  const __m256 t6 = _mm256_unpacklo_ps(rows[6].v, rows[7].v), t7 = _mm256_unpackhi_ps(rows[6].v, rows[7].v);
  // u0: lanes 0 and 4 of rows 0-3 (low and high half), u1: lanes 1 and 5, u2: 2 and 6, u3: 3 and 7.
  const __m256 u0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)), u1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 u2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)), u3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 u4 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(1, 0, 1, 0)), u5 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 u6 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(1, 0, 1, 0)), u7 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(3, 2, 3, 2));
  _mm256_storeu_ps(out + 0 * stride, _mm256_permute2f128_ps(u0, u4, 0x20));
  _mm256_storeu_ps(out + 1 * stride, _mm256_permute2f128_ps(u1, u5, 0x20));
  _mm256_storeu_ps(out + 2 * stride, _mm256_permute2f128_ps(u2, u6, 0x20));
  _mm256_storeu_ps(out + 3 * stride, _mm256_permute2f128_ps(u3, u7, 0x20));
  _mm256_storeu_ps(out + 4 * stride, _mm256_permute2f128_ps(u0, u4, 0x31));
  _mm256_storeu_ps(out + 5 * stride, _mm256_permute2f128_ps(u1, u5, 0x31));
  _mm256_storeu_ps(out + 6 * stride, _mm256_permute2f128_ps(u2, u6, 0x31));
  _mm256_storeu_ps(out + 7 * stride, _mm256_permute2f128_ps(u3, u7, 0x31));
}

// ---------------------------------------------------------------------------------------
// Float8x2: two lane groups shaded as one, op for op (low() is one 4x2 group, high()
// another). Same semantics as Lanes<16>, lane for lane. The halves share no data, so the
// core overlaps one half's texture reads and long dependency chains (sin, pow) with the
// other's: one group alone leaves it waiting on every gather.

#if !RASTER_ZMM_PAIRS   // isa.h: otherwise lanes_avx512.h holds Float8x2
struct Mask8x2 {
  Mask8 lo, hi;
  friend Mask8x2 operator&(Mask8x2 a, Mask8x2 b) { return {a.lo & b.lo, a.hi & b.hi}; }
  friend Mask8x2 operator|(Mask8x2 a, Mask8x2 b) { return {a.lo | b.lo, a.hi | b.hi}; }
  friend Mask8x2 operator!(Mask8x2 a) { return {!a.lo, !a.hi}; }
  unsigned bits() const { return lo.bits() | hi.bits() << 8; }
  static Mask8x2 fromBits(unsigned b) { return {Mask8::fromBits(b & 0xFFu), Mask8::fromBits(b >> 8)}; }
  Mask8 low() const { return lo; }
  Mask8 high() const { return hi; }
};

struct Float8x2 {
  static constexpr int kCount = 16;
  using MaskType = Mask8x2;
  Float8 lo, hi;

  Float8x2() = default;
  Float8x2(float s) : lo(s), hi(s) {}  // NOLINT: broadcast, as GLSL scalars
  Float8x2(Float8 low, Float8 high) : lo(low), hi(high) {}
  static Float8x2 load(const float* p) { return {Float8::load(p), Float8::load(p + 8)}; }
  void store(float* p) const { lo.store(p); hi.store(p + 8); }
  float operator[](int i) const { return i < 8 ? lo[i] : hi[i - 8]; }
  Float8 low() const { return lo; }
  Float8 high() const { return hi; }

  friend Float8x2 operator+(Float8x2 a, Float8x2 b) { return {a.lo + b.lo, a.hi + b.hi}; }
  friend Float8x2 operator-(Float8x2 a, Float8x2 b) { return {a.lo - b.lo, a.hi - b.hi}; }
  friend Float8x2 operator*(Float8x2 a, Float8x2 b) { return {a.lo * b.lo, a.hi * b.hi}; }
  friend Float8x2 operator/(Float8x2 a, Float8x2 b) { return {a.lo / b.lo, a.hi / b.hi}; }
  friend Float8x2 operator-(Float8x2 a) { return {-a.lo, -a.hi}; }
  Float8x2& operator+=(Float8x2 b) { return *this = *this + b; }
  Float8x2& operator-=(Float8x2 b) { return *this = *this - b; }
  Float8x2& operator*=(Float8x2 b) { return *this = *this * b; }
  Float8x2& operator/=(Float8x2 b) { return *this = *this / b; }

  friend Mask8x2 operator<(Float8x2 a, Float8x2 b) { return {a.lo < b.lo, a.hi < b.hi}; }
  friend Mask8x2 operator<=(Float8x2 a, Float8x2 b) { return {a.lo <= b.lo, a.hi <= b.hi}; }
  friend Mask8x2 operator>(Float8x2 a, Float8x2 b) { return {a.lo > b.lo, a.hi > b.hi}; }
  friend Mask8x2 operator>=(Float8x2 a, Float8x2 b) { return {a.lo >= b.lo, a.hi >= b.hi}; }
  friend Mask8x2 operator==(Float8x2 a, Float8x2 b) { return {a.lo == b.lo, a.hi == b.hi}; }
};

inline Float8x2 select(Mask8x2 m, Float8x2 a, Float8x2 b) { return {select(m.lo, a.lo, b.lo), select(m.hi, a.hi, b.hi)}; }
inline Float8x2 fma(Float8x2 a, Float8x2 b, Float8x2 c) { return {fma(a.lo, b.lo, c.lo), fma(a.hi, b.hi, c.hi)}; }
inline Float8x2 min(Float8x2 a, Float8x2 b) { return {min(a.lo, b.lo), min(a.hi, b.hi)}; }
inline Float8x2 max(Float8x2 a, Float8x2 b) { return {max(a.lo, b.lo), max(a.hi, b.hi)}; }
inline Float8x2 floor(Float8x2 a) { return {floor(a.lo), floor(a.hi)}; }
inline Float8x2 sqrt(Float8x2 a) { return {sqrt(a.lo), sqrt(a.hi)}; }
inline Float8x2 abs(Float8x2 a) { return {abs(a.lo), abs(a.hi)}; }
inline bool any(Mask8x2 m) { return any(m.lo | m.hi); }
inline bool all(Mask8x2 m) { return all(m.lo) && all(m.hi); }
inline Float8x2 quadDdx(Float8x2 a) { return {quadDdx(a.lo), quadDdx(a.hi)}; }
inline Float8x2 quadDdy(Float8x2 a) { return {quadDdy(a.lo), quadDdy(a.hi)}; }
#endif

}  // namespace raster::simd
