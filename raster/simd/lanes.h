// Lane types: shading, interpolation and sampling are written once over a lane type F.
// This file holds the reference, Lanes<N>: N lanes in plain C++ loops (Lanes<4> is one 2x2
// quad), always built, the readable definition of every operation and the test oracle. Its
// siblings hold the same operations for wider registers, chosen in isa.h:
//   lanes_avx2.h    Float8 (8 lanes in AVX2 registers, two quads side by side) and Float8x2
//                   (two Float8 groups shaded as one) as two Float8 halves
//   lanes_avx512.h  Float8x2 in one 512-bit register, when the build has AVX-512
//
// Every lane type gives bit-identical results lane by lane: every operation is a single IEEE float32
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

// Eight registers stored lane by lane: for each lane i < count, rows[0..7] at lane i as the
// eight floats at out + i * stride (one slice of a per-lane record: the vertex stage writes
// its records so). The reference; lanes_avx2.h has Float8's as one 8x8 transpose.
template <class F>
void storeLanesTransposed(const F* rows, float* out, size_t stride, int count) {
  float planes[8][F::kCount];
  for (int r = 0; r < 8; ++r) rows[r].store(planes[r]);
  for (int i = 0; i < count; ++i)
    for (int r = 0; r < 8; ++r) out[size_t(i) * stride + size_t(r)] = planes[r][i];
}

}  // namespace raster::simd
