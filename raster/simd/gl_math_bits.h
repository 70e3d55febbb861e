// The bit-level helpers every gl_math function is written over: a lane type's integer
// lanes and conversions (cvttps2dq, cvtdq2ps; minps and maxps as x86 computes them), x86 DAZ
// as llvmpipe's threads run it (daz, flushBelow), and the unordered comparisons LLVM emits.
// One text for float, simd::Lanes<N>, Float8 and Float8x2, so each function written over
// them gives the same bits in every lane type. The integer lanes of the vector types are in
// gl_math_avx2.h (and gl_math_avx512.h).
#pragma once

#include <cstdint>
#include <cstring>

#include "raster/simd/isa.h"

namespace raster::glsl {
namespace detail {

// ---- 32-bit integer lanes of a lane type, for bit manipulation --------------------------
template <int N>
struct ULanes {
  uint32_t lane[N];
  ULanes() = default;
  ULanes(uint32_t s) { for (int i = 0; i < N; ++i) lane[i] = s; }  // NOLINT: broadcast
#define RASTER_ULANES_OP(op)                                                                  \
  friend ULanes operator op(ULanes a, ULanes b) { for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] op b.lane[i]; return a; }
  RASTER_ULANES_OP(&)
  RASTER_ULANES_OP(|)
  RASTER_ULANES_OP(^)
  RASTER_ULANES_OP(+)
  RASTER_ULANES_OP(-)
#undef RASTER_ULANES_OP
  friend ULanes operator~(ULanes a) { for (int i = 0; i < N; ++i) a.lane[i] = ~a.lane[i]; return a; }
  friend ULanes operator<<(ULanes a, int n) { for (int i = 0; i < N; ++i) a.lane[i] <<= n; return a; }
  friend ULanes operator>>(ULanes a, int n) { for (int i = 0; i < N; ++i) a.lane[i] >>= n; return a; }
};

// Scalar: the bit pattern and float conversions of one lane.
inline uint32_t asBits(float f) { uint32_t u; std::memcpy(&u, &f, sizeof u); return u; }
inline float asFloat(uint32_t u) { float f; std::memcpy(&f, &u, sizeof f); return f; }
// cvttps2dq: truncate toward zero; NaN and out-of-range give 0x80000000 (what LLVM's
// fptosi becomes on x86, and what llvmpipe's code relies on for huge arguments).
inline uint32_t cvtt(float f) {
  if (!(f >= -2147483648.0f && f < 2147483648.0f)) return 0x80000000u;
  return uint32_t(int32_t(f));
}
// cvtdq2ps: signed integer to float, rounding to nearest even.
inline float cvt(uint32_t u) { return float(int32_t(u)); }
inline bool eq(uint32_t a, uint32_t b) { return a == b; }
inline float sel(bool m, float a, float b) { return m ? a : b; }
inline float fmaF(float a, float b, float c) { return std::fma(a, b, c); }
inline float floorF(float a) { return std::floor(a); }
inline float sqrtF(float a) { return std::sqrt(a); }
// minps(a, b) / maxps(a, b): a < b ? a : b, so b is returned when either is NaN.
inline float minps(float a, float b) { return a < b ? a : b; }
inline float maxps(float a, float b) { return a > b ? a : b; }

template <int N>
ULanes<N> asBits(simd::Lanes<N> f) { ULanes<N> u; std::memcpy(u.lane, f.lane, sizeof u.lane); return u; }
template <int N>
simd::Lanes<N> asFloat(ULanes<N> u) { simd::Lanes<N> f; std::memcpy(f.lane, u.lane, sizeof f.lane); return f; }
template <int N>
ULanes<N> cvtt(simd::Lanes<N> f) { ULanes<N> u; for (int i = 0; i < N; ++i) u.lane[i] = cvtt(f.lane[i]); return u; }
template <int N>
simd::Lanes<N> cvt(ULanes<N> u) { simd::Lanes<N> f; for (int i = 0; i < N; ++i) f.lane[i] = cvt(u.lane[i]); return f; }
template <int N>
simd::Mask<N> eq(ULanes<N> a, ULanes<N> b) { simd::Mask<N> m; for (int i = 0; i < N; ++i) m.lane[i] = a.lane[i] == b.lane[i]; return m; }

template <class F> struct IntLanesOf;
template <> struct IntLanesOf<float> { using type = uint32_t; };
template <int N> struct IntLanesOf<simd::Lanes<N>> { using type = ULanes<N>; };

}  // namespace detail
}  // namespace raster::glsl

// The integer lanes of the vector lane types (simd/isa.h chooses which exist).
#include "raster/simd/gl_math_avx2.h"

namespace raster::glsl {
namespace detail {

// Every vector lane type (Lanes<N>, Float8, Float8x2): its own operations from simd/lanes.h.
template <class F>
concept VectorLanes = requires { typename F::MaskType; };
template <VectorLanes F> F sel(typename F::MaskType m, F a, F b) { return simd::select(m, a, b); }
template <VectorLanes F> F fmaF(F a, F b, F c) { return simd::fma(a, b, c); }
template <VectorLanes F> F floorF(F a) { return simd::floor(a); }
template <VectorLanes F> F sqrtF(F a) { return simd::sqrt(a); }
template <VectorLanes F> F minps(F a, F b) { return simd::min(a, b); }
template <VectorLanes F> F maxps(F a, F b) { return simd::max(a, b); }

template <class F> using UOf = typename IntLanesOf<F>::type;

// The lane types these functions accept.
template <class F>
concept LaneType = requires { typename IntLanesOf<F>::type; };

constexpr uint32_t kSignBit = 0x80000000u;

template <class F> F fabsF(F x) { return asFloat(asBits(x) & UOf<F>(~kSignBit)); }
template <class F> auto isFiniteMask(F x) { const UOf<F> e = asBits(x) & UOf<F>(0x7f800000u); return !eq(e, UOf<F>(0x7f800000u)); }
// Below what magnitude the shader code now running reads a float as zero in llvmpipe (see the
// top of gl_math.h): 2^-126, the least normal float, while its thread flushes denormals; 0
// where it keeps them (raster::Renderer's fragment stage from its first depth-tested pass
// into a half-float target on). A bound rather than a flag, so daz() stays one compare and
// one select. Written only by ScopedDenormalMode, between parallel loops; process-wide for
// the reason the method set is (raster/methods.h): no two renderers draw at the same time.
inline float flushBelow = 0x1p-126f;
// x86 DAZ, as llvmpipe's shader threads run while they flush: a denormal operand reads as a
// zero of its sign.
template <class F> F daz(F x) { return sel(fabsF(x) < F(flushBelow), asFloat(asBits(x) & UOf<F>(kSignBit)), x); }
// Unordered comparisons (LLVM fcmp u*, what lp_build_cmp emits): true when either is NaN.
template <class F> auto ueq(F a, F b) { return !((a < b) | (a > b)); }
template <class F> auto ult(F a, F b) { return !(a >= b); }
template <class F> auto uge(F a, F b) { return !(a < b); }

// Whether every lane holds a true value (for the float lane type, bool | bool is an int).
inline bool allLanes(int m) { return m != 0; }
template <class M> bool allLanes(M m) { return simd::all(m); }

}  // namespace detail
}  // namespace raster::glsl
