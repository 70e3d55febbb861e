// GLSL transcendental functions computed exactly as llvmpipe computes them: the same
// approximations, constants, operation order and fusion, bit for bit, on the reference
// machine kind (x86-64 with AVX2 + FMA; Debian 12's Mesa 22.3.6 llvmpipe, LLVM 15, 8-wide).
//
// Source: Mesa 22.3.6 (the Debian source package mesa_22.3.6-1+deb12u2, i.e. the code that
// is installed), files relative to src/:
//   gallium/auxiliary/gallivm/lp_bld_nir.c     maps NIR opcodes: fexp2 -> lp_build_exp2,
//       flog2 -> lp_build_log2_safe, fpow -> lp_build_pow, fsin/fcos -> lp_build_sin/cos,
//       fsqrt -> llvm.sqrt, frcp -> 1/x (fdiv), fsign -> lp_build_sgn, comparisons ordered
//       (except !=), fmin/fmax -> minps/maxps (plus a NaN fix-up when neither operand is
//       known to be a number).
//   gallium/auxiliary/gallivm/lp_bld_arit.c    lp_build_exp2, lp_build_log2_approx,
//       lp_build_polynomial, lp_build_pow, lp_build_sin_or_cos, lp_build_sgn.
//       lp_build_mad / lp_build_fmuladd emit llvm.fmuladd, which LLVM turns into one FMA on
//       FMA CPUs (written fma() below); every other multiply and add rounds on its own.
//   compiler/glsl/builtin_functions.cpp        acos = pi/2 - asin_expr(x) (a GLSL IR
//       expression); atan(y, x) -> ir_binop_atan2 -> (glsl_to_nir.cpp) nir_atan2.
//   compiler/nir/nir_builtin_builder.c         nir_atan, nir_atan2: polynomial atan.
//   gallium/drivers/llvmpipe/lp_screen.c       NIR options: lower_ffma32 (so the ffma of the
//       NIR builders become a separate multiply and add), no lower_fpow, no lower_fsign.
//   compiler/nir/nir_opt_algebraic.py, compiler/glsl/opt_algebraic.cpp: constant folding of
//       pow (see pow<Y> below).
//
// Denormals: llvmpipe's shaders start with the x86 FTZ and DAZ bits set (fragment shaders:
// lp_rast.c, vertex shaders: draw_pt.c, util_fpstate_set_denorms_to_zero), so a denormal
// operand reads as zero and a denormal result is flushed to zero. This pipeline runs with
// the default MXCSR, so while llvmpipe would flush (detail::flushBelow) every function
// here flushes denormal arguments to a zero of the same sign (daz()), and the intermediates
// where a denormal would change the result (each is marked FTZ). A fragment shader that runs
// after a draw into a half-float colour target keeps denormals in llvmpipe (its blend code
// turns FTZ/DAZ off, lp_state_fs.c generate_unswizzled_blend, and the rasterizer thread is
// left that way; measured: deferred's lighting pass writes pow(x, 0.4545) of a denormal x as
// 5e-18, not 0). raster::Renderer tells the functions which (ScopedDenormalMode); then they
// flush nothing, and log2 reads a denormal's exponent bits as llvmpipe's masks do.
//
// Measured against llvmpipe (tests/simd/gl_math_test.cpp, and a standalone GL probe reading the
// arguments with texelFetch): every result bit-identical, NaN payloads included, for all
// 2^32 arguments of sin, cos and atan(x), every 4th bit pattern (2^30 arguments) of exp2,
// log2, acos, pow(x, 48.0), pow(x, 2.2) and pow(x, 0.4545), and 31 million arguments each
// of pow(x, y), atan(y, x) and the other forms.
//
// These are the `math=llvmpipe` method (raster/methods.h), the default; the GLSL functions
// at the end of this file pick it, libm_math.h's or fast_math.h's per the method set.
//
// Lane types: float, simd::Lanes<N> (plain loops: the readable reference), simd::Float8
// (AVX2) and simd::Float8x2 (two Float8 groups). One generic text per function, over a few
// bit-level helpers (detail::), so all of them give identical bits; tests/simd/gl_math_lanes_test.cpp
// checks it, and tests/simd/gl_math_test.cpp checks them against llvmpipe through real GL.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "raster/methods.h"
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
// top of this file): 2^-126, the least normal float, while its thread flushes denormals; 0
// in the fragment stage of a pass at or after a draw into a half-float colour target, which
// keeps them. A bound rather than a flag, so daz() stays one compare and one select. Written
// only by ScopedDenormalMode, between parallel loops; process-wide for the reason the method
// set is (raster/methods.h): no two renderers draw at the same time.
inline float flushBelow = 0x1p-126f;
// x86 DAZ, as llvmpipe's shader threads run while they flush: a denormal operand reads as a
// zero of its sign.
template <class F> F daz(F x) { return sel(fabsF(x) < F(flushBelow), asFloat(asBits(x) & UOf<F>(kSignBit)), x); }
// Unordered comparisons (LLVM fcmp u*, what lp_build_cmp emits): true when either is NaN.
template <class F> auto ueq(F a, F b) { return !((a < b) | (a > b)); }
template <class F> auto ult(F a, F b) { return !(a >= b); }
template <class F> auto uge(F a, F b) { return !(a < b); }

// ---- constants: the double literals of the Mesa source, rounded to float ----------------
// lp_build_exp2_polynomial (EXP_POLY_DEGREE 5): minimax 2^x on [0, 1).
constexpr float kExp2P0 = float(1.000000000000000000000);
constexpr float kExp2P1 = float(0.693153073200168932794);
constexpr float kExp2P2 = float(0.240153617044375388211);
constexpr float kExp2P3 = float(0.0558263180532956664775);
constexpr float kExp2P4 = float(0.00898934009049466391101);
constexpr float kExp2P5 = float(0.00187757667519147912699);
// lp_build_log2_polynomial (LOG_POLY_DEGREE 4): log2((1+sqrt z)/(1-sqrt z))/sqrt z.
constexpr float kLog2P0 = float(2.88539009343309178325);
constexpr float kLog2P1 = float(0.961791550404184197881);
constexpr float kLog2P2 = float(0.577440339438736392009);
constexpr float kLog2P3 = float(0.403343858251329912514);
constexpr float kLog2P4 = float(0.406718052498846252698);
// lp_build_sin_or_cos (Cephes sinf/cosf, as in sse_mathfun).
constexpr float kFourOverPi = float(1.27323954473516);
constexpr float kDP1 = float(-0.78515625);
constexpr float kDP2 = float(-2.4187564849853515625e-4);
constexpr float kDP3 = float(-3.77489497744594108e-8);
constexpr float kCos0 = float(2.443315711809948E-005);
constexpr float kCos1 = float(-1.388731625493765E-003);
constexpr float kCos2 = float(4.166664568298827E-002);
constexpr float kSin0 = float(-1.9515295891E-4);
constexpr float kSin1 = float(8.3321608736E-3);
constexpr float kSin2 = float(-1.6666654611E-1);
// GLSL IR asin_expr (builtin_functions.cpp), the acos coefficients; M_PI_2f, M_PI_4f.
constexpr float kPi2 = 1.57079632679489661923f;
constexpr float kPi4Minus1 = 0.785398163397448309616f - 1.0f;
constexpr float kAcosP0 = 0.08132463f;
constexpr float kAcosP1 = -0.02363318f;
constexpr float kAsinP0 = 0.086566724f;
constexpr float kAsinP1 = -0.03102955f;
// nir_atan (nir_builtin_builder.c): odd minimax polynomial on [0, 1].
constexpr float kAtan1 = 0.9999793128310355f;
constexpr float kAtan3 = -0.3326756418091246f;
constexpr float kAtan5 = 0.1938924977115610f;
constexpr float kAtan7 = -0.1173503194786851f;
constexpr float kAtan9 = 0.0536813784310406f;
constexpr float kAtan11 = -0.0121323213173444f;

// lp_build_exp2 (lp_bld_arit.c):
//   x = minps(128, x); x = maxps(-126.99999, x)        (NaN passes through)
//   ipart = floor(x); fpart = x - ipart                 (lp_build_ifloor_fract, roundps)
//   expipart = bits((cvtt(ipart) + 127) << 23)          (2^ipart; 0 for ipart = -127)
//   P(f) = lp_build_polynomial(f, degree 5): f2 = f*f, even/odd Horner in f2 with
//          fmuladd, then fmuladd(odd, f, even)
//   result = expipart * P(fpart)                        (plain multiply)
// Always inlined (here and log2Impl): pow is exp2(log2), and for Float8x2 an outlined call
// would pass both 64-byte halves through the stack.
template <class F>
[[gnu::always_inline]] inline F exp2Polynomial(F fpart) {
  const F f2 = fpart * fpart;
  F odd = F(kExp2P5);
  F even = F(kExp2P4);
  odd = fmaF(f2, odd, F(kExp2P3));
  even = fmaF(f2, even, F(kExp2P2));
  odd = fmaF(f2, odd, F(kExp2P1));
  even = fmaF(f2, even, F(kExp2P0));
  return fmaF(odd, fpart, even);
}
template <class F>
[[gnu::always_inline]] inline F exp2Core(F x) {
  using U = UOf<F>;
  x = minps(F(128.0f), x);
  x = maxps(F(-126.99999f), x);
  const F ipart = floorF(x);
  const F fpart = x - ipart;
  const F expipart = asFloat((cvtt(ipart) + U(127u)) << 23);
  return expipart * exp2Polynomial(fpart);
}
template <class F>
[[gnu::always_inline]] inline F exp2Impl(F x) { return exp2Core(daz(x)); }

// exp2Core's expipart * p for an integral ipart in [-126, 125] and a p in [1, 2]: 2^ipart
// is a normal float and the product is p with its exponent moved, rounding nothing. Where
// AVX-512 has that as one instruction (vscalefps, gl_math_avx512.h) it replaces four.
template <class F>
F scaleByPowerOfTwo(F p, F ipart) {
  using U = UOf<F>;
  return asFloat((cvtt(ipart) + U(127u)) << 23) * p;
}

// exp2Core for an x in [-126, 126): its clamps change nothing, floor(x) is in [-126, 125]
// and the polynomial of a fraction in [0, 1) is in [1, 2] (P(0) = 1, every coefficient
// positive, P(1) = 2 to float precision), so the scale is scaleByPowerOfTwo's case. Same
// bits, two clamps and three operations fewer.
template <class F>
[[gnu::always_inline]] inline F exp2InNormalRange(F x) {
  const F ipart = floorF(x);
  return scaleByPowerOfTwo(exp2Polynomial(x - ipart), ipart);
}
// lp_build_log2_safe = lp_build_log2_approx(handle_edge_cases = TRUE):
//   logexp = float(((bits(x) & 0x7f800000) >> 23) - 127)
//   mant = bits((bits(x) & 0x007fffff) | bits(1.0))            (in [1, 2))
//   y = (mant - 1) / (mant + 1);  z = y * y
//   P(z) = lp_build_polynomial(z, degree 4): z2 = z*z, even/odd Horner with fmuladd
//   result = fmuladd(y, P(z), logexp)
//   then, unordered compares: x >= +inf -> +inf; x == 0 -> -inf; x < 0 -> NaN
//   (so NaN -> NaN; with DAZ a denormal compares equal to 0 -> -inf).
// log2Core is the approximation alone: for a positive normal finite x, daz and the edge
// cases change nothing.
//
// Its exponent and mantissa steps are log2Exponent and log2Mantissa; where AVX-512 has them
// as one instruction each (gl_math_avx512.h), those give the same values for such an x.
template <class F>
F log2Exponent(F x) {
  using U = UOf<F>;
  return cvt(((asBits(x) & U(0x7f800000u)) >> 23) - U(127u));
}
template <class F>
F log2Mantissa(F x) {
  using U = UOf<F>;
  return asFloat((asBits(x) & U(0x007fffffu)) | U(0x3f800000u));
}
// Bitwise: the bit operations above even where AVX-512 has its instructions, which read a
// kept denormal's true exponent where llvmpipe's masks read exponent 0.
template <bool Bitwise = false, class F>
[[gnu::always_inline]] inline F log2Core(F x) {
  F logexp, mant;
  if constexpr (Bitwise) {
    logexp = log2Exponent<F>(x);
    mant = log2Mantissa<F>(x);
  } else {
    logexp = log2Exponent(x);
    mant = log2Mantissa(x);
  }
  const F y = (mant - F(1.0f)) / (mant + F(1.0f));
  const F z = y * y;
  const F z2 = z * z;
  F even = F(kLog2P4);
  F odd = F(kLog2P3);
  even = fmaF(z2, even, F(kLog2P2));
  odd = fmaF(z2, odd, F(kLog2P1));
  even = fmaF(z2, even, F(kLog2P0));
  const F p = fmaF(odd, z, even);
  return fmaF(y, p, logexp);
}
template <class F>
[[gnu::always_inline]] inline F log2Impl(F x) {
  x = daz(x);
  // Bitwise: a denormal x that is kept (flushBelow 0) reads as llvmpipe's masks read it.
  F res = log2Core<true>(x);
  const float inf = __builtin_inff();
  res = sel(uge(x, F(inf)), F(inf), res);
  res = sel(ueq(x, F(0.0f)), F(-inf), res);
  res = sel(ult(x, F(0.0f)), F(__builtin_nanf("")), res);
  return res;
}

// Whether every lane holds a true value (for the float lane type, bool | bool is an int).
inline bool allLanes(int m) { return m != 0; }
template <class M> bool allLanes(M m) { return simd::all(m); }

// pow's common case, checked once per group: every x is +-0 or a positive normal float and
// every y is 0 or finite with |y| >= 2^-55. Then pow is exp2Core(log2Core(x) * y), with 0
// where x is 0, bit for bit:
//   - daz(x), daz(y) and the NaN choice of the product change nothing;
//   - log2's edge cases (inf, 0, negative, NaN) do not occur, and a zero x is masked;
//   - exp2's flush of a denormal product does nothing: log2Core(x) is an fmuladd of the
//     floats y (0, or >= 2^-25 and a multiple of 2^-48) and p (a multiple of 2^-22) onto an
//     integer, so it is 0 or at least 2^-70 in magnitude, and times |y| >= 2^-55 it is
//     0 or at least 2^-125, no denormal.
template <class F>
[[gnu::always_inline]] inline bool powBaseIsPlain(F x) {
  return allLanes(((x >= F(0x1p-126f)) | (x == F(0.0f))) & (x < F(__builtin_inff())));
}
constexpr float kPlainExponentMin = 0x1p-55f;
template <class F>
[[gnu::always_inline]] inline F powPlain(F x, F y) {
  return sel(x == F(0.0f), F(0.0f), exp2Core(log2Core(x) * y));
}

// lp_build_pow: x == 0 (unordered: NaN too) ? 0 : exp2(log2_safe(x) * y).
// So pow(0, y) = 0 for every y, pow(NaN, y) = 0, pow(x < 0, y) = NaN.
template <class F>
[[gnu::always_inline]] inline F powImpl(F x, F y) {
  const F ay = fabsF(y);
  if (powBaseIsPlain(x) && allLanes(((ay >= F(kPlainExponentMin)) | (ay == F(0.0f))) & (ay < F(__builtin_inff()))))
    return powPlain(x, y);
  x = daz(x);
  y = daz(y);
  const auto zero = ueq(x, F(0.0f));
  // The product as the JIT code computes it: where both factors are NaN, y's NaN wins
  // (measured); exp2Impl flushes a denormal product (FTZ).
  const F res = exp2Impl(sel(y == y, log2Impl(x) * y, y));
  return sel(zero, F(0.0f), res);
}

// powImpl with an exponent fixed at compile time, a normal float: daz(y) is y and y is no
// NaN, so only x's part is left.
// When also |y| <= 0.98 (the composite's gamma 1 / 2.2), powPlain's product lies in
// exp2InNormalRange's range for every positive normal x: log2Core(x) is fma(y', p, e) with
// the exponent e in [-126, 127] and y' * p < 1 (log2 of the mantissa), so it is in
// [-126, 128] and times |y| <= 0.98 in [-125.5, 125.5]. A zero x is masked as in powPlain.
constexpr float kNormalRangeExponentMax = 0.98f;
template <float Y, class F>
[[gnu::always_inline]] inline F powConstImpl(F x) {
  static_assert(Y == Y && __builtin_isnormal(Y), "a literal exponent is a normal float");
  if constexpr (Y >= kPlainExponentMin || Y <= -kPlainExponentMin)
    if (powBaseIsPlain(x)) {
      if constexpr (Y <= kNormalRangeExponentMax && Y >= -kNormalRangeExponentMax)
        return sel(x == F(0.0f), F(0.0f), exp2InNormalRange(log2Core(x) * F(Y)));
      return powPlain(x, F(Y));
    }
  x = daz(x);
  const auto zero = ueq(x, F(0.0f));
  const F res = exp2Impl(log2Impl(x) * F(Y));
  return sel(zero, F(0.0f), res);
}

// lp_build_sin_or_cos (Cephes, via sse_mathfun), for |x| reduced by multiples of pi/4:
//   ax = |x|;  j = cvtt(ax * 4/pi);  j = (j + 1) & ~1;  yj = float(j)
//   r = fmuladd(yj, DP3, fmuladd(yj, DP2, fmuladd(yj, DP1, ax)))     (DPi = -pi/4 split)
//   z = r * r
//   cos poly: ((fmuladd(fmuladd(z, c0, c1), z, c2) * z) * z - z * 0.5) + 1
//   sin poly: fmuladd(fmuladd(fmuladd(z, s0, s1), z, s2) * z, r, r)
//   sin: sign = (bits(x) ^ ((cvtt + 1) << 29)) & sign bit;  poly = ((j & 2) == 0) ? sin : cos
//   cos: j2 = j - 2; sign = ((~j2 & 4) << 29);               poly = ((j2 & 2) == 0) ? sin : cos
//   result = clamp(poly ^ sign, -1, 1) (minps then maxps); NaN for infinite or NaN x.
// Arguments with |x| * 4/pi >= 2^31 make cvtt return 0x80000000 (as on x86).
template <class F>
[[gnu::always_inline]] inline F sinOrCosImpl(F a, bool cosine) {
  using U = UOf<F>;
  a = daz(a);
  const U ai = asBits(a);
  const F xAbs = asFloat(ai & U(~kSignBit));
  const F scaled = xAbs * F(kFourOverPi);
  const U emm2Add = cvtt(scaled) + U(1u);
  const U emm2And = emm2Add & U(~1u);
  const F yj = cvt(emm2And);
  U emm2, signBit;
  if (cosine) {
    emm2 = emm2And - U(2u);
    signBit = (~emm2 & U(4u)) << 29;
  } else {
    emm2 = emm2And;
    signBit = (ai ^ (emm2Add << 29)) & U(kSignBit);
  }
  const auto useSinPoly = eq(emm2 & U(2u), U(0u));
  const F x1 = fmaF(yj, F(kDP1), xAbs);
  const F x2 = fmaF(yj, F(kDP2), x1);
  const F x3 = fmaF(yj, F(kDP3), x2);
  const F z = x3 * x3;
  const F c4 = fmaF(z, F(kCos0), F(kCos1));
  const F c6 = fmaF(c4, z, F(kCos2));
  const F c8 = (c6 * z) * z;
  const F cosPoly = (c8 - z * F(0.5f)) + F(1.0f);
  const F s4 = fmaF(z, F(kSin0), F(kSin1));
  const F s6 = fmaF(s4, z, F(kSin2));
  const F sinPoly = fmaF(s6 * z, x3, x3);
  F res = asFloat(asBits(sel(useSinPoly, sinPoly, cosPoly)) ^ signBit);
  res = minps(res, F(1.0f));
  res = maxps(res, F(-1.0f));
  return sel(isFiniteMask(a), res, F(__builtin_nanf("")));
}

// lp_build_sgn: (sign bit of x) | 1.0, then 0 where x == 0 (an unordered compare, so NaN
// gives 0 too).
template <class F>
F signImpl(F x) {
  using U = UOf<F>;
  const F s = asFloat((asBits(x) & U(kSignBit)) | U(0x3f800000u));
  return sel(ueq(x, F(0.0f)), F(0.0f), s);
}

// NIR fmin of two operands not known to be numbers (lp_bld_nir.c: GALLIVM_NAN_RETURN_OTHER):
// minps(a, b), but a where b is NaN; so NaN only when both are.
template <class F>
F fminOther(F a, F b) {
  return sel(b == b, minps(a, b), a);
}

// GLSL IR asin_expr(x, p0, p1) (builtin_functions.cpp), compiled without fusion:
//   sign(x) * (pi/2 - sqrt(1 - |x|) * (pi/2 + |x| * ((pi/4 - 1) + |x| * (p0 + |x| * p1))))
template <class F>
F asinExpr(F x, float p0, float p1) {
  const F ax = fabsF(x);
  const F poly = F(kPi2) + ax * (F(kPi4Minus1) + ax * (F(p0) + ax * F(p1)));
  return signImpl(x) * (F(kPi2) - sqrtF(F(1.0f) - ax) * poly);
}

// nir_atan(y_over_x) (nir_builtin_builder.c), with llvmpipe's NIR options: ffma lowered to
// a multiply and an add, fdiv a true division, fmin/fmax minps/maxps, no NaN fix-up (the
// shader is not `precise`).
//   a = |v|;  t = min(a, 1) / max(a, 1)
//   t2 = t*t, t3 = t2*t, t5 = t3*t2, t7 = t5*t2, t9 = t7*t2
//   s = ((((t*c1 + t3*c3) + t5*c5) + t7*c7) + t9*c9) + (t9*c11)*t2
//   The last term is nir_atan's (t9*t2)*c11 after nir_opt_algebraic's "propagate constants
//   up multiplication chains" (fmul(fmul(a, b) used once, #c) -> fmul(fmul(a, c), b)):
//   t11 is the only power used once. Measured: the literal (t9*t2)*c11 is 1 ulp off on
//   0.05% of arguments near |v| = 1, this form matches all.
//   s = b2f(1 < a) * (s * -2 + pi/2) + s       (range reduction fix-up, unfused)
//   result = s * sign(v)
template <class F>
F atanCore(F v) {
  const F a = fabsF(v);
  const F t = minps(a, F(1.0f)) / maxps(a, F(1.0f));
  const F t2 = t * t;
  const F t3 = t2 * t;
  const F t5 = t3 * t2;
  const F t7 = t5 * t2;
  const F t9 = t7 * t2;
  F s = daz(t * F(kAtan1)) + t3 * F(kAtan3);   // FTZ: t * c1 is denormal for t just above 2^-126
  s = s + t5 * F(kAtan5);
  s = s + t7 * F(kAtan7);
  s = s + t9 * F(kAtan9);
  s = s + (t9 * F(kAtan11)) * t2;   // t11 * c11, reassociated by NIR (see above)
  const F b2f = sel(F(1.0f) < a, F(1.0f), F(0.0f));
  s = b2f * (s * F(-2.0f) + F(kPi2)) + s;
  return s * signImpl(v);
}

// nir_atan2(y, x) (nir_builtin_builder.c), ffma lowered as above:
//   flip = 0 >= x;  s = flip ? |x| : y;  t = flip ? y : |x|
//   scale = |t| >= 1e18 ? 0.25 : 1;  rcp = 1 / (t * scale);  q = (s * scale) * rcp
//   tan = |x| == |y| ? 1 : |q|
//   arc = b2f(flip) * pi/2 + atan(tan)
//   result = min(y, rcp) < 0 ? -arc : arc          (fmin: a NaN operand gives the other)
template <class F>
F atan2Impl(F y, F x) {
  y = daz(y);
  x = daz(x);
  const F ax = fabsF(x);
  const auto flip = F(0.0f) >= x;
  const F s = sel(flip, ax, y);
  const F t = sel(flip, y, ax);
  const F scale = sel(fabsF(t) >= F(1e18f), F(0.25f), F(1.0f));
  const F rcp = F(1.0f) / (t * scale);
  const F q = daz((s * scale) * rcp);   // FTZ
  const F tan = sel(ax == fabsF(y), F(1.0f), fabsF(q));
  const F arc = sel(flip, F(1.0f), F(0.0f)) * F(kPi2) + atanCore(tan);
  return sel(fminOther(y, rcp) < F(0.0f), -arc, arc);
}

}  // namespace detail

}  // namespace raster::glsl

// The other methods of the `math` step, and the div=approx reciprocals, over the detail::
// helpers above.
#include "raster/simd/div_approx.h"
#include "raster/simd/fast_math.h"
#include "raster/simd/libm_math.h"

namespace raster::glsl {

// ---- the GLSL functions ------------------------------------------------------------------
// One template each, for float, Lanes<N> and Float8 (detail::LaneType). A call with a float
// argument picks these over the C library's double overloads (an exact match), so a port
// instantiated with F = float computes what llvmpipe computes too.
//
// Each follows the `math` step of the method set (raster/methods.h): llvmpipe's
// approximation above (the default), the C library in double (libm_math.h) or the fast
// polynomials (fast_math.h). The step is one branch per call on a value fixed for the frame.
#define RASTER_MATH_METHOD(llvmpipeForm, call)           \
  switch (methods::active().math) {                      \
    case MathMethod::Fast:                               \
    case MathMethod::FastFragment: return fast::call;    \
    case MathMethod::Libm: return libm::call;            \
    case MathMethod::Llvmpipe: break;                    \
  }                                                      \
  return llvmpipeForm
template <class F> requires detail::LaneType<F> F exp2(F x) { RASTER_MATH_METHOD(detail::exp2Impl(x), exp2(x)); }
template <class F> requires detail::LaneType<F> F log2(F x) { RASTER_MATH_METHOD(detail::log2Impl(x), log2(x)); }
template <class F> requires detail::LaneType<F> [[gnu::always_inline]] inline F sin(F x) {
  RASTER_MATH_METHOD(detail::sinOrCosImpl(x, false), sin(x));
}
template <class F> requires detail::LaneType<F> [[gnu::always_inline]] inline F cos(F x) {
  RASTER_MATH_METHOD(detail::sinOrCosImpl(x, true), cos(x));
}
template <class F> requires detail::LaneType<F> F acos(F x) {
  RASTER_MATH_METHOD(F(detail::kPi2) - detail::asinExpr(detail::daz(x), detail::kAcosP0, detail::kAcosP1), acos(x));
}
template <class F> requires detail::LaneType<F> F asin(F x) {
  RASTER_MATH_METHOD(detail::asinExpr(detail::daz(x), detail::kAsinP0, detail::kAsinP1), asin(x));
}
// GLSL atan(y_over_x) and atan(y, x).
template <class F> requires detail::LaneType<F> F atan(F yOverX) { RASTER_MATH_METHOD(detail::atanCore(detail::daz(yOverX)), atan(yOverX)); }
template <class F> requires detail::LaneType<F> F atan(F y, F x) { RASTER_MATH_METHOD(detail::atan2Impl(y, x), atan(y, x)); }

// pow(x, y) with a run-time exponent (a varying, a uniform, a computed value): llvmpipe's
// lp_build_pow, exp2(log2(x) * y), with pow(0, y) = 0.
template <class F> requires detail::LaneType<F> [[gnu::always_inline]] inline F pow(F x, F y) {
  RASTER_MATH_METHOD(detail::powImpl(x, y), pow(x, y));
}

// pow(x, Y) with a literal exponent in the GLSL source: Mesa's compilers fold some of
// these before llvmpipe sees them (GLSL IR opt_algebraic.cpp, NIR nir_opt_algebraic.py):
//   pow(x, 1.0) = x;  pow(x, 2.0) = x * x;  pow(x, 4.0) = (x * x) * (x * x)
// every other exponent is the run-time pow. Write pow<2.0f>(x) for GLSL pow(x, 2.0):
// pow(x, F(2.0f)) is the run-time pow, which differs from x * x in the last bits (and is
// NaN for x < 0). Measured against llvmpipe for 1, 2, 4, 2.2, 0.4545 and 48.
// Not modelled (write them out in the port): a literal base, pow(2.0, y) = exp2(y) and
// pow(1.0, y) = 1; and all-constant calls, which the compiler evaluates with the C library.
// The folds are the compiler's, not the math library's, so every `math` method keeps them;
// the other exponents take the method's pow.
template <float Y, class F> requires detail::LaneType<F>
[[gnu::always_inline]] inline F pow(F x) {
  if constexpr (Y == 1.0f) {
    return x;
  } else if constexpr (Y == 2.0f) {
    return detail::daz(x * x);   // FTZ, as every multiply in llvmpipe's shaders
  } else if constexpr (Y == 4.0f) {
    const F squared = detail::daz(x * x);
    return detail::daz(squared * squared);
  } else {
    switch (methods::active().math) {
      case MathMethod::Fast:
      case MathMethod::FastFragment: return fast::powConst<Y>(x);   // fast::pow(x, F(Y)), shortened
      case MathMethod::Libm: return libm::pow(x, F(Y));
      case MathMethod::Llvmpipe: break;
    }
    return detail::powConstImpl<Y>(x);
  }
}
#undef RASTER_MATH_METHOD

// Sets whether the shader code run until it is destroyed flushes denormals as llvmpipe's
// thread would (detail::flushBelow). Made and destroyed outside parallel loops.
class ScopedDenormalMode {
 public:
  explicit ScopedDenormalMode(bool flush) : previous_(detail::flushBelow) { detail::flushBelow = flush ? 0x1p-126f : 0.0f; }
  ~ScopedDenormalMode() { detail::flushBelow = previous_; }
  ScopedDenormalMode(const ScopedDenormalMode&) = delete;
  ScopedDenormalMode& operator=(const ScopedDenormalMode&) = delete;

 private:
  float previous_;
};

}  // namespace raster::glsl
