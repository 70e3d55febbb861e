// exp2, log2 and pow as llvmpipe computes them (lp_bld_arit.c), bit for bit: the polynomials,
// their constants, and the shortcuts that give the same bits where every lane is a plain
// case (powPlain, powConstImpl). gl_math.h has the sources and the GLSL functions over these.
#pragma once

#include "raster/simd/gl_math_bits.h"

namespace raster::glsl {
namespace detail {

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

}  // namespace detail
}  // namespace raster::glsl
