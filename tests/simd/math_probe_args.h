// The arguments the math probe (shaders_cpp/test/math_probe.*) is drawn with in
// gl_math_test.cpp: how each reaches the shader unchanged, the special values, each
// function's typical ranges, and the denormal arguments of the kept-denormal cases.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "shaders_cpp/test/math_probe.h"
#include "tests/simd/gl_math_args.h"

namespace gl_math_test {

using shaders::test::MathProbe;
using testing_support::kInf;
using testing_support::kNaN;

inline bool isDenormal(float f) { return f != 0.0f && std::fabs(f) < std::numeric_limits<float>::min(); }

// An argument as the probe receives it: (value * scale) * scale2. Plain values have scales
// 1; +-Inf is (3e38 * +-2) * 1, NaN is (3e38 * 2) * 0 (the x86 default NaN, 0xffc00000),
// +-0 is (+-1e-30 * 1e-30) * 1 and a denormal d is (d * 2^64) * 2^-64: zero and denormal
// varyings do not keep their sign on the way in (this pipeline delivers -0 as +0; llvmpipe's
// interpolation, fma(0, x, a0) under DAZ, turns a negative denormal into +0). Computed in
// the shader, llvmpipe's FTZ flushes d to a zero of d's sign, as gl_math.h's daz() does.
struct Arg {
  float value = 0.0f, scale = 1.0f, scale2 = 1.0f;
  Arg() = default;
  Arg(float v) {  // NOLINT: a plain value
    if (std::isnan(v)) {
      value = 3e38f, scale = 2.0f, scale2 = 0.0f;
    } else if (v == 0.0f) {   // +-0 as an underflowing product: zero varyings lose their sign
      value = std::signbit(v) ? -1e-30f : 1e-30f, scale = 1e-30f;
    } else if (isDenormal(v)) {   // an exact product, flushed to +-0 by llvmpipe (FTZ)
      value = v * 0x1p64f, scale = 0x1p-64f;
    } else if (std::isinf(v)) {
      value = 3e38f, scale = v > 0 ? 2.0f : -2.0f;
    } else {
      value = v;
    }
  }
  float effective() const { return (value * scale) * scale2; }
};
struct Args {
  Arg x, y;
};

inline const std::vector<float>& specialValues() {
  static const std::vector<float> values = {
      0.0f, -0.0f, 1.0f, -1.0f, 2.0f, -2.0f, 0.5f, -0.5f, 4.0f, 0.25f, 1e-7f, -1e-7f, 1e-20f, -1e-20f, 1e-30f,
      std::numeric_limits<float>::min(), -std::numeric_limits<float>::min(), 1e-40f, -1e-40f, 1e-45f,
      3e38f, -3e38f, std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), kInf, -kInf, kNaN,
      1e6f, -1e6f, 1e18f, -1e18f, 4e18f, 127.9999f, 128.0f, 129.0f, -126.0f, -126.99999f, -127.0f, -127.5f, -150.0f,
      std::nextafter(1.0f, 0.0f), std::nextafter(1.0f, 2.0f), std::nextafter(-1.0f, 0.0f), std::nextafter(-1.0f, -2.0f),
      1.5707963f, 3.1415927f, 4.712389f, 6.2831855f, 0.7853982f, -1.5707963f, -3.1415927f, 48.0f, 2.2f, 0.4545f};
  return values;
}

// Multiples k * pi/2 rounded to float, and their neighbours, for k up to about 1.3e6.
inline float nearMultipleOfHalfPi(std::mt19937& rng) {
  const double k = double(rng() % 1300000u);
  float f = float(k * 1.5707963267948966);
  for (int step = int(rng() % 5u) - 2; step != 0; step += step > 0 ? -1 : 1) f = std::nextafter(f, step > 0 ? kInf : -kInf);
  return (rng() & 1u) ? f : -f;
}

// Typical arguments of each function, drawn from its usual ranges, around its edge cases,
// and from any bit pattern.
inline Args exp2Args(std::mt19937& rng) {
  switch (rng() % 4u) {
    case 0: return {uniformIn(rng, -130.0f, 130.0f), 0.0f};
    case 1: return {magnitude(rng, -30, 7), 0.0f};
    case 2: return {float(int(rng() % 260u) - 130) + ((rng() & 1u) ? 1e-6f : 0.0f), 0.0f};
    default: return {anyBits(rng), 0.0f};
  }
}

inline Args log2Args(std::mt19937& rng) {
  switch (rng() % 4u) {
    case 0: return {std::fabs(magnitude(rng, -126, 127)), 0.0f};
    case 1: return {uniformIn(rng, 0.0f, 2.0f), 0.0f};
    case 2: return {floatOf(bitsOf(1.0f) + (rng() % 64u) - 32u), 0.0f};
    default: return {anyBits(rng), 0.0f};
  }
}

inline Args powArgs(std::mt19937& rng) {
  static const float exponents[] = {2.0f, 4.0f, 48.0f, 2.2f, 0.4545f, 0.0f, 1.0f, -1.0f, 0.5f, 32.0f, 64.0f, 16.0f};
  switch (rng() % 5u) {
    case 0: return {uniformIn(rng, 0.0f, 1.0f), uniformIn(rng, 0.0f, 128.0f)};
    case 1: return {uniformIn(rng, 0.0f, 1.0f), exponents[rng() % 12u]};
    case 2: return {std::fabs(magnitude(rng, -40, 40)), magnitude(rng, -8, 8)};
    case 3: return {uniformIn(rng, -2.0f, 4.0f), float(int(rng() % 65u))};
    default: return {anyBits(rng), anyBits(rng)};
  }
}

// The pow forms of a literal exponent (pow48, pow2_2, ...) and powVec3Const.
inline Args constantPowArgs(std::mt19937& rng) {
  switch (rng() % 4u) {
    case 0: return {uniformIn(rng, 0.0f, 1.0f), uniformIn(rng, 0.0f, 1.0f)};
    case 1: return {uniformIn(rng, 0.0f, 4.0f), uniformIn(rng, 0.0f, 4.0f)};
    case 2: return {magnitude(rng, -30, 30), magnitude(rng, -30, 30)};
    default: return {anyBits(rng), anyBits(rng)};
  }
}

inline Args sinCosArgs(std::mt19937& rng) {
  switch (rng() % 6u) {
    case 0: return {uniformIn(rng, -1e6f, 1e6f), 0.0f};
    case 1: return {uniformIn(rng, -10.0f, 10.0f), 0.0f};
    case 2: return {nearMultipleOfHalfPi(rng), 0.0f};
    case 3: return {magnitude(rng, -30, 30), 0.0f};
    case 4: {  // the SSAO hash: dot(p * 1024, vec2(127.1, 311.7)), p in [0, 1]^2
      const float px = uniformIn(rng, 0.0f, 1.0f) * 1024.0f, py = uniformIn(rng, 0.0f, 1.0f) * 1024.0f;
      return {px * 127.1f + py * 311.7f, 0.0f};
    }
    default: return {anyBits(rng), 0.0f};
  }
}

inline Args atan2Args(std::mt19937& rng) {
  switch (rng() % 5u) {
    case 0: return {uniformIn(rng, -1.0f, 1.0f), uniformIn(rng, -1.0f, 1.0f)};
    case 1: return {magnitude(rng, -40, 40), magnitude(rng, -40, 40)};
    case 2: {  // |y| == |x|, and near it
      const float a = magnitude(rng, -20, 20);
      return {a, (rng() & 1u) ? -a : std::nextafter(a, kInf)};
    }
    case 3: return {magnitude(rng, -10, 10), magnitude(rng, 58, 70)};   // |t| >= 1e18
    default: return {anyBits(rng), anyBits(rng)};
  }
}

inline Args acosAsinArgs(std::mt19937& rng) {
  switch (rng() % 4u) {
    case 0: return {uniformIn(rng, -1.1f, 1.1f), 0.0f};
    case 1: return {floatOf(bitsOf(1.0f) - (rng() % 4096u)) * ((rng() & 1u) ? 1.0f : -1.0f), 0.0f};
    case 2: return {magnitude(rng, -30, 0), 0.0f};
    default: return {anyBits(rng), 0.0f};
  }
}

inline Args atanArgs(std::mt19937& rng) {   // atan(y_over_x)
  switch (rng() % 3u) {
    case 0: return {uniformIn(rng, -2.0f, 2.0f), 0.0f};
    case 1: return {magnitude(rng, -40, 40), 0.0f};
    default: return {anyBits(rng), 0.0f};
  }
}

inline Args typicalArgs(int func, std::mt19937& rng) {
  switch (func) {
    case MathProbe::kExp2: return exp2Args(rng);
    case MathProbe::kLog2: return log2Args(rng);
    case MathProbe::kPow:
    case MathProbe::kPowVec3: return powArgs(rng);
    case MathProbe::kPow48:
    case MathProbe::kPow2_2:
    case MathProbe::kPow0_4545:
    case MathProbe::kPow2:
    case MathProbe::kPow4:
    case MathProbe::kPowVec3Const: return constantPowArgs(rng);
    case MathProbe::kSin:
    case MathProbe::kCos: return sinCosArgs(rng);
    case MathProbe::kAtan2: return atan2Args(rng);
    case MathProbe::kAcos:
    case MathProbe::kAsin: return acosAsinArgs(rng);
    default: return atanArgs(rng);
  }
}

// Arguments for one function: the special values (and, for two-argument functions, every
// pair of them), then `count` in all from the function's typical ranges.
inline std::vector<Args> argumentsFor(int func, size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<Args> args;
  const auto& special = specialValues();
  const bool twoArgs = func == MathProbe::kPow || func == MathProbe::kAtan2 || func == MathProbe::kPowVec3 ||
                       func == MathProbe::kPowVec3Const;
  if (twoArgs) {
    for (float a : special)
      for (float b : special) args.push_back({a, b});
  } else {
    for (float a : special) args.push_back({a, 0.0f});
  }
  while (args.size() < count) args.push_back(typicalArgs(func, rng));
  args.resize(count);
  return args;
}

// A denormal, or a float near the least normal one (whose products in the functions are
// denormals), of either sign.
inline float nearDenormal(std::mt19937& rng) {
  if (rng() % 2u) return floatOf((rng() & 0x807fffffu) | 1u);   // exponent 0, never zero
  return magnitude(rng, -149, -120);                             // ldexp: denormal below -126
}

// argumentsFor's arguments with each x (and y) replaced by nearDenormal a third of the time.
inline std::vector<Args> keptDenormalArguments(int func, size_t count, uint32_t seed) {
  std::vector<Args> args = argumentsFor(func, count, seed);
  std::mt19937 rng(seed ^ 0x9e3779b9u);
  for (Args& a : args) {
    if (rng() % 3u == 0) a.x = nearDenormal(rng);
    if (rng() % 3u == 0) a.y = nearDenormal(rng);
  }
  return args;
}

}  // namespace gl_math_test
