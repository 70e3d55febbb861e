// GLSL transcendental functions, precise: each lane computed by the C library in double
// precision and rounded once to float. The reference the fast approximations (fast_math.h)
// are measured against, and a choice for when accuracy matters more than speed or llvmpipe's
// exact bits (gl_math.h).
//
// glibc's double functions are accurate to well under one double ulp, so rounding their
// result to float gives the correctly rounded float result except in rare cases where the
// exact value lies within ~2^-29 float ulp of a rounding boundary; tests/simd/
// math_methods_test.cpp checks every result against long double within half a float ulp.
//
// Semantics are the C library's, which fills in what GLSL leaves undefined: pow(x < 0, y)
// is NaN unless y is an integer (pow(-2, 3) = -8), pow(0, 0) = 1, pow(1, NaN) = 1,
// atan(+-0, -0) = +-pi, atan(+-inf, +-inf) = +-pi/4 or +-3pi/4, asin/acos of |x| > 1 = NaN.
// Denormal arguments are used as they are.
//
// The vector lane types go lane by lane through memory: slow, so these are kept out of line
// ([[gnu::noinline]]) to keep the shader code that calls them small.
//
// Written over gl_math_bits.h's lane types; gl_math.h includes it and picks it per the method
// set.
#pragma once

#include <cmath>

#include "raster/simd/gl_math_bits.h"

namespace raster::glsl::libm {

// ---- one float: double precision, rounded once ------------------------------------------
inline float exp2(float x) { return float(std::exp2(double(x))); }
inline float log2(float x) { return float(std::log2(double(x))); }
inline float pow(float x, float y) { return float(std::pow(double(x), double(y))); }
inline float sin(float x) { return float(std::sin(double(x))); }
inline float cos(float x) { return float(std::cos(double(x))); }
inline float asin(float x) { return float(std::asin(double(x))); }
inline float acos(float x) { return float(std::acos(double(x))); }
inline float atan(float yOverX) { return float(std::atan(double(yOverX))); }
inline float atan(float y, float x) { return float(std::atan2(double(y), double(x))); }

namespace impl {

// fn applied to every lane of x (and y), through an aligned array.
template <class F, class Fn>
[[gnu::always_inline]] inline F eachLane(F x, Fn fn) {
  alignas(64) float v[F::kCount];
  x.store(v);
  for (int i = 0; i < F::kCount; ++i) v[i] = fn(v[i]);
  return F::load(v);
}
template <class F, class Fn>
[[gnu::always_inline]] inline F eachLane(F x, F y, Fn fn) {
  alignas(64) float vx[F::kCount];
  alignas(64) float vy[F::kCount];
  x.store(vx);
  y.store(vy);
  for (int i = 0; i < F::kCount; ++i) vx[i] = fn(vx[i], vy[i]);
  return F::load(vx);
}

}  // namespace impl

// ---- vector lane types (Lanes<N>, Float8, Float8x2): lane by lane ------------------------
// The lambdas call the float overloads above (libm::exp2(float), ...), so every lane type
// gives the float overload's bits.
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F exp2(F x) { return impl::eachLane(x, [](float v) { return libm::exp2(v); }); }
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F log2(F x) { return impl::eachLane(x, [](float v) { return libm::log2(v); }); }
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F pow(F x, F y) { return impl::eachLane(x, y, [](float a, float b) { return libm::pow(a, b); }); }
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F sin(F x) { return impl::eachLane(x, [](float v) { return libm::sin(v); }); }
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F cos(F x) { return impl::eachLane(x, [](float v) { return libm::cos(v); }); }
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F asin(F x) { return impl::eachLane(x, [](float v) { return libm::asin(v); }); }
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F acos(F x) { return impl::eachLane(x, [](float v) { return libm::acos(v); }); }
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F atan(F yOverX) { return impl::eachLane(yOverX, [](float v) { return libm::atan(v); }); }
template <detail::VectorLanes F> requires detail::LaneType<F>
[[gnu::noinline]] F atan(F y, F x) { return impl::eachLane(y, x, [](float a, float b) { return libm::atan(a, b); }); }

}  // namespace raster::glsl::libm
