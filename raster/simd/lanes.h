// Lane types: shading, interpolation and sampling are written once over a lane type F.
//
//   Lanes<N>  N lanes in plain C++ loops: the readable reference and test oracle
//             (Lanes<4> is one 2x2 quad). Always built.
//   Float8    8 lanes in AVX2 registers: the fast path (two quads side by side), built
//             when RASTER_AVX2 is set.
//
// Both give bit-identical results lane by lane: every operation is a single IEEE float32
// operation (the build disables contraction), and fma() is the one fused operation,
// used exactly where llvmpipe emits llvm.fmuladd (which becomes an FMA on FMA CPUs).
// (One exception: when two operands are NaN, which NaN's payload survives may differ,
// as the compiler may swap the operands of a commutative operation.)
//
// Lane order inside a quad follows llvmpipe (lp_bld_quad.h): 0 = top-left, 1 = top-right,
// 2 = bottom-left, 3 = bottom-right ("top" = lower memory row). Float8 holds quad 0 in
// lanes 0-3 and the quad to its right in lanes 4-7, as llvmpipe's 8-wide shader does.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#endif

namespace raster::simd {

// ---------------------------------------------------------------------------------------
// Lanes<N>: the portable reference.
template <int N>
struct Mask {
  bool lane[N];
  friend Mask operator&(Mask a, Mask b) { for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] && b.lane[i]; return a; }
  friend Mask operator|(Mask a, Mask b) { for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] || b.lane[i]; return a; }
  friend Mask operator!(Mask a) { for (int i = 0; i < N; ++i) a.lane[i] = !a.lane[i]; return a; }
  unsigned bits() const { unsigned b = 0; for (int i = 0; i < N; ++i) b |= unsigned(lane[i]) << i; return b; }
  static Mask fromBits(unsigned b) { Mask m; for (int i = 0; i < N; ++i) m.lane[i] = (b >> i) & 1u; return m; }
};

template <int N>
struct Lanes {
  static constexpr int kCount = N;
  using MaskType = Mask<N>;
  float lane[N];

  Lanes() = default;
  Lanes(float s) { for (int i = 0; i < N; ++i) lane[i] = s; }  // NOLINT: broadcast, as GLSL scalars
  static Lanes load(const float* p) { Lanes r; std::memcpy(r.lane, p, sizeof r.lane); return r; }
  static Lanes gather(const float* base, const int* index) {   // lane i reads base[index[i]]
    Lanes r;
    for (int i = 0; i < N; ++i) r.lane[i] = base[index[i]];
    return r;
  }
  void store(float* p) const { std::memcpy(p, lane, sizeof lane); }
  float operator[](int i) const { return lane[i]; }
  float& operator[](int i) { return lane[i]; }

#define RASTER_LANES_BINOP(op)                                                         \
  friend Lanes operator op(Lanes a, Lanes b) { for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] op b.lane[i]; return a; } \
  Lanes& operator op##=(Lanes b) { return *this = *this op b; }
  RASTER_LANES_BINOP(+)
  RASTER_LANES_BINOP(-)
  RASTER_LANES_BINOP(*)
  RASTER_LANES_BINOP(/)
#undef RASTER_LANES_BINOP
  friend Lanes operator-(Lanes a) { for (int i = 0; i < N; ++i) a.lane[i] = -a.lane[i]; return a; }

#define RASTER_LANES_CMP(op)                                                           \
  friend MaskType operator op(Lanes a, Lanes b) { MaskType m; for (int i = 0; i < N; ++i) m.lane[i] = a.lane[i] op b.lane[i]; return m; }
  RASTER_LANES_CMP(<)
  RASTER_LANES_CMP(<=)
  RASTER_LANES_CMP(>)
  RASTER_LANES_CMP(>=)
  RASTER_LANES_CMP(==)
#undef RASTER_LANES_CMP
};

template <int N>
inline Lanes<N> map(Lanes<N> a, float (*fn)(float)) { for (int i = 0; i < N; ++i) a.lane[i] = fn(a.lane[i]); return a; }

template <int N> inline Lanes<N> select(Mask<N> m, Lanes<N> a, Lanes<N> b) { for (int i = 0; i < N; ++i) a.lane[i] = m.lane[i] ? a.lane[i] : b.lane[i]; return a; }
template <int N> inline Lanes<N> fma(Lanes<N> a, Lanes<N> b, Lanes<N> c) { for (int i = 0; i < N; ++i) a.lane[i] = std::fma(a.lane[i], b.lane[i], c.lane[i]); return a; }
// min/max follow x86 minps/maxps (what llvmpipe emits): the second operand wins on NaN.
template <int N> inline Lanes<N> min(Lanes<N> a, Lanes<N> b) { for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] < b.lane[i] ? a.lane[i] : b.lane[i]; return a; }
template <int N> inline Lanes<N> max(Lanes<N> a, Lanes<N> b) { for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] > b.lane[i] ? a.lane[i] : b.lane[i]; return a; }
template <int N> inline Lanes<N> floor(Lanes<N> a) { return map(a, [](float x) { return std::floor(x); }); }
template <int N> inline Lanes<N> sqrt(Lanes<N> a) { return map(a, [](float x) { return std::sqrt(x); }); }
template <int N> inline Lanes<N> abs(Lanes<N> a) { return map(a, [](float x) { return std::fabs(x); }); }
template <int N> inline bool any(Mask<N> m) { return m.bits() != 0; }
template <int N> inline bool all(Mask<N> m) { return m.bits() == (1u << N) - 1u; }

// Quad differences (llvmpipe lp_bld_quad.c, fine derivatives; coarse is the same there):
// dFdx: lanes {0,1} get a1 - a0, lanes {2,3} get a3 - a2; dFdy: {0,2} get a2 - a0, {1,3} a3 - a1.
template <int N>
inline Lanes<N> quadDdx(Lanes<N> a) {
  static_assert(N % 4 == 0, "derivatives need whole quads");
  Lanes<N> r;
  for (int q = 0; q < N; q += 4) {
    r.lane[q + 0] = r.lane[q + 1] = a.lane[q + 1] - a.lane[q + 0];
    r.lane[q + 2] = r.lane[q + 3] = a.lane[q + 3] - a.lane[q + 2];
  }
  return r;
}
template <int N>
inline Lanes<N> quadDdy(Lanes<N> a) {
  static_assert(N % 4 == 0, "derivatives need whole quads");
  Lanes<N> r;
  for (int q = 0; q < N; q += 4) {
    r.lane[q + 0] = r.lane[q + 2] = a.lane[q + 2] - a.lane[q + 0];
    r.lane[q + 1] = r.lane[q + 3] = a.lane[q + 3] - a.lane[q + 1];
  }
  return r;
}

using Quad = Lanes<4>;

#if RASTER_AVX2
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

// ---------------------------------------------------------------------------------------
// Float8x2: two lane groups shaded as one, op for op (low() is one 4x2 group, high()
// another). Same semantics as Lanes<16>, lane for lane. The halves share no data, so the
// core overlaps one half's texture reads and long dependency chains (sin, pow) with the
// other's: one group alone leaves it waiting on every gather.
#if defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512VL__)
// With AVX-512 both halves live in one 512-bit register: each operation is one instruction
// instead of two (the same IEEE operation on each lane, so the same bits), which halves
// what the core must decode and track for the shader arithmetic (pow and ACES 1.3x faster
// measured on Zen 4, which executes it as two 256-bit halves).
#define RASTER_ZMM_PAIRS 1
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
inline bool any(Mask8x2 m) { return m.k != 0; }
inline bool all(Mask8x2 m) { return m.k == 0xFFFFu; }
// Float8's in-lane shuffles, on all four 128-bit lanes (one quad each).
inline Float8x2 quadDdx(Float8x2 a) {
  return Float8x2(_mm512_sub_ps(_mm512_permute_ps(a.v, _MM_SHUFFLE(3, 3, 1, 1)), _mm512_permute_ps(a.v, _MM_SHUFFLE(2, 2, 0, 0))));
}
inline Float8x2 quadDdy(Float8x2 a) {
  return Float8x2(_mm512_sub_ps(_mm512_permute_ps(a.v, _MM_SHUFFLE(3, 2, 3, 2)), _mm512_permute_ps(a.v, _MM_SHUFFLE(1, 0, 1, 0))));
}
#else
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

using FastLanes = Float8;
#else
using FastLanes = Lanes<8>;
#endif

}  // namespace raster::simd
