// The `div=approx` method (raster/methods.h): a reciprocal and a reciprocal square root
// without the divider or the square-root unit, for normalize / inversesqrt (simd/glsl.h)
// and the 1/w of interpolation (tile/interpolate.h).
//
// Written over gl_math_bits.h's helpers; gl_math.h includes it, beside the `math` methods.
#pragma once

#include "raster/simd/gl_math_bits.h"

namespace raster::glsl {

// A seed from the bit pattern (the exponent negated, or halved and negated, by one integer
// subtraction from a magic constant) refined by Newton steps with FMA. Plain integer and FMA
// operations, so every CPU and lane type gives the same bits, unlike the hardware estimates
// (rcpps, rsqrtps), whose tables differ between vendors. For positive normal x, measured
// over 2^20 arguments spread over the whole range (tests/simd/div_methods_test.cpp):
//   reciprocalApprox   three steps: y = 1/x (1 - e), |e| < 7e-8 (seed 5%, then 0.26%, 6.6e-6)
//   inversesqrtApprox  two steps:   y = 1/sqrt(x) (1 - e), |e| < 5e-6 (seed 3.4%, then 0.18%)
// The reciprocal takes the third step because its error reaches the image: 1/w scales every
// varying, and with two steps (6.6e-6) a full-screen pass's w = 1 gave texture coordinates
// a few ulps off, which deferred's SSAO hash (fract(sin(dot(uv, ...)) * 43758.5)) turns
// into a different noise pattern: 38.8 dB against llvmpipe instead of 81.8.
// Zero, denormal, negative, infinite and NaN arguments, and reciprocals of x >= 2^125 (a
// seed near the denormals), give garbage: the callers (normalize, the 1/w of interpolation)
// see none of them.
template <class F> requires detail::LaneType<F>
[[gnu::always_inline]] inline F reciprocalApprox(F x) {
  using U = detail::UOf<F>;
  F y = detail::asFloat(U(0x7EF311C3u) - detail::asBits(x));
  for (int step = 0; step < 3; ++step) y = detail::fmaF(y, detail::fmaF(F(0.0f) - x, y, F(1.0f)), y);   // y += y (1 - xy)
  return y;
}
template <class F> requires detail::LaneType<F>
[[gnu::always_inline]] inline F inversesqrtApprox(F x) {
  using U = detail::UOf<F>;
  F y = detail::asFloat(U(0x5F375A86u) - (detail::asBits(x) >> 1));
  const F halfX = x * F(0.5f);
  for (int step = 0; step < 2; ++step) y = y * detail::fmaF(F(0.0f) - halfX, y * y, F(1.5f));   // y (3/2 - x/2 y^2)
  return y;
}

}  // namespace raster::glsl
