// Float bits and random arguments for the tests of raster/simd/gl_math.h: the draws through
// real GL (gl_math_test.cpp) and the comparisons of its instantiations (gl_math_lanes_test.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "tests/float_bits.h"

namespace gl_math_test {

using testing_support::bitsOf;
using testing_support::floatOf;

inline float uniformIn(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
// +-m * 2^e, m in [1, 2), e in [lo, hi].
inline float magnitude(std::mt19937& rng, int lo, int hi) {
  const float m = std::ldexp(1.0f + uniformIn(rng, 0.0f, 1.0f), lo + int(rng() % unsigned(hi - lo + 1)));
  return (rng() & 1u) ? m : -m;
}
inline float anyBits(std::mt19937& rng) { return floatOf(rng()); }

}  // namespace gl_math_test
