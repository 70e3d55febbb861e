// sin, cos, asin, acos and atan as llvmpipe computes them, bit for bit: lp_build_sin_or_cos
// (lp_bld_arit.c), GLSL IR's asin_expr and NIR's atan and atan2 with llvmpipe's NIR options.
// gl_math.h has the sources and the GLSL functions over these.
#pragma once

#include "raster/simd/gl_math_bits.h"

namespace raster::glsl {
namespace detail {

// ---- constants: the double literals of the Mesa source, rounded to float ----------------
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
