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
// where a denormal would change the result (each is marked FTZ). llvmpipe's rasterizer
// thread can be left keeping denormals: the blend code of a half-float target saves the
// MXCSR, turns FTZ/DAZ off and restores it (lp_state_fs.c generate_unswizzled_blend), but a
// block whose fragments the depth test has all killed leaves it off (measured,
// gl_math_test's "llvmpipe keeps denormals after ..." case; the cause in the JIT code was
// not traced). Every scene with a half-float target has such blocks (overdraw) in its first
// half-float pass, so after a frame of hdr, deferred or pbr every later fragment shader
// keeps denormals (deferred's lighting writes pow(x, 0.4545) of a denormal x as 5e-18, not
// 0). raster::Renderer keeps them from its first pass into a half-float target with a
// depth-tested colour draw on (ScopedDenormalMode); then these functions flush nothing, and
// log2 reads a denormal's exponent bits as llvmpipe's masks do.
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
// bit-level helpers (detail::, gl_math_bits.h), so all of them give identical bits;
// tests/simd/gl_math_lanes_test.cpp checks it, and tests/simd/gl_math_test.cpp checks them
// against llvmpipe through real GL. The functions by family: gl_math_exp_log.h (exp2, log2,
// pow) and gl_math_trig.h (sin, cos, asin, acos, atan).
#pragma once

#include <limits>

#include "raster/methods.h"
#include "raster/simd/gl_math_bits.h"
#include "raster/simd/gl_math_exp_log.h"
#include "raster/simd/gl_math_trig.h"
// The other methods of the `math` step, and the div=approx reciprocals, over the same
// detail:: helpers.
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

// A value and a bound on its distance from the exact one, lane by lane.
template <class F>
struct Within {
  F value;
  F error;
};

// pow(x, Y) for a literal Y where the caller needs it only to within a known error (a colour
// that goes to an RGBA8 target, which keeps only its byte: merge/unorm8_within.h): {v, e}
// with |v - pow<Y>(x)| <= e in every lane. Under llvmpipe's math, pow(x, 48.0) is then x^32 *
// x^16 by repeated squaring, six products where pow<48.0f> takes a log2 and an exp2. On every
// float x in [0, 1] that lies within kPow48ByProductsRelError * v + 2^-120 of llvmpipe's
// (measured on all 1,065,353,217 of them, denormals flushed or kept: the most was 1.2983e-5 *
// v, and 2^-126 at the denormal end; tests/simd/pow_within_test.cpp samples them again); x
// above 1 or NaN gets an infinite error. Any other exponent or method: pow<Y>(x), error 0.
inline constexpr float kPow48ByProductsRelError = 1.31e-5f;
template <float Y, class F> requires detail::LaneType<F>
[[gnu::always_inline]] inline Within<F> powWithin(F x) {
  if constexpr (Y == 48.0f) {
    if (methods::active().math == MathMethod::Llvmpipe) {
      const F x2 = x * x, x4 = x2 * x2, x8 = x4 * x4, x16 = x8 * x8, x32 = x16 * x16;
      const F value = x32 * x16;
      const F bound = value * F(kPow48ByProductsRelError) + F(0x1p-120f);
      const auto measured = (x >= F(0.0f)) & (x <= F(1.0f));   // [0, 1]: not NaN, not above 1
      return {value, detail::sel(measured, bound, F(std::numeric_limits<float>::infinity()))};
    }
  }
  return {pow<Y>(x), F(0.0f)};
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
