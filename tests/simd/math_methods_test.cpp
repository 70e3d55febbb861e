// The two alternatives to gl_math.h's llvmpipe-exact transcendentals:
//   raster/simd/fast_math.h (glsl::fast)  low-degree polynomials: each stays within its
//       documented error bound (fast::k*Max*Error) against the C library in double, and the
//       bound is tight (the samples reach at least half of it, so a worse approximation fails);
//       and the edge cases follow the header (NaN, infinities, zeros, out-of-domain arguments).
//   raster/simd/libm_math.h (glsl::libm)  the C library in double, rounded once: every finite
//       result is the double result rounded to float, and within half a float ulp of the
//       long double result (correctly rounded, up to 2^-20 ulp).
// Both: the float, Lanes<8>, Float8 and Float8x2 instantiations give the same bits (NaN
// payloads aside, as simd/lanes.h says).
//
// Samples per function: uniform in value over the claimed domain, uniform over its bit
// patterns, and log-uniform in magnitude where the domain spans many binades, a few hundred
// thousand each with fixed seeds; plus the edge values (+-0, denormals, FLT_MIN, FLT_MAX,
// huge, negative, +-inf, NaN) where they fall in the domain.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

// gl_math.h includes fast_math.h and libm_math.h after the helpers they build on.
#include "raster/simd/gl_math.h"
#include "tests/float_bits.h"

namespace {

namespace fast = raster::glsl::fast;
namespace libm = raster::glsl::libm;

using testing_support::bitsOf;
using testing_support::floatOf;
using testing_support::kInf;
using testing_support::kNaN;
constexpr int kSamples = 300000;   // per distribution

bool sameBits(float a, float b) { return bitsOf(a) == bitsOf(b); }

const std::vector<float> kEdgeValues = {
    0.0f, -0.0f, 1e-45f, -1e-45f, 1e-40f, -1e-40f, FLT_MIN, -FLT_MIN, FLT_MAX, -FLT_MAX, 1e30f, -1e30f,
    1e10f, -1e10f, 1.0f, -1.0f, 0.5f, -0.5f, 2.0f, 1e-30f, -1e-30f, kInf, -kInf, kNaN};

// ---- samples ------------------------------------------------------------------------------
std::vector<float> uniformValues(uint32_t seed, float lo, float hi) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(lo, hi);
  std::vector<float> xs(kSamples);
  for (float& x : xs) x = value(rng);
  return xs;
}
// Uniform over the bit patterns of the floats in [0, maxMagnitude], with a random sign if
// bothSigns: every binade gets samples in proportion to its count of floats.
std::vector<float> uniformBits(uint32_t seed, float maxMagnitude, bool bothSigns) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<uint32_t> pattern(0, bitsOf(maxMagnitude));
  std::vector<float> xs(kSamples);
  for (float& x : xs) x = floatOf(pattern(rng) | (bothSigns && (rng() & 1u) ? 0x80000000u : 0u));
  return xs;
}
// Magnitudes log-uniform in [2^lo, 2^hi), with a random sign if bothSigns.
std::vector<float> logScale(uint32_t seed, float lo, float hi, bool bothSigns) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> exponent(lo, hi);
  std::vector<float> xs(kSamples);
  for (float& x : xs) x = float(std::exp2(exponent(rng))) * (bothSigns && (rng() & 1u) ? -1.0f : 1.0f);
  return xs;
}

// ---- the functions ------------------------------------------------------------------------
struct Function {
  const char* name;
  float (*fast)(float, float);
  float (*precise)(float, float);      // libm
  double (*reference)(double, double);    // the C library in double
  long double (*exact)(long double, long double);   // the C library in long double
  double fastBound;
  bool relativeError;                  // relative error, else absolute
  bool (*inFastDomain)(float x, float y, double reference);   // where fastBound is claimed
};

const Function kFunctions[] = {
    {"exp2", [](float x, float) { return fast::exp2(x); }, [](float x, float) { return libm::exp2(x); },
     [](double x, double) { return std::exp2(x); }, [](long double x, long double) { return std::exp2(x); },
     fast::kExp2MaxRelError, true,
     [](float, float, double r) { return r >= FLT_MIN && r <= FLT_MAX; }},
    {"log2", [](float x, float) { return fast::log2(x); }, [](float x, float) { return libm::log2(x); },
     [](double x, double) { return std::log2(x); }, [](long double x, long double) { return std::log2(x); },
     fast::kLog2MaxAbsError, false,
     [](float x, float, double) { return x >= FLT_MIN && x <= FLT_MAX; }},
    {"pow", [](float x, float y) { return fast::pow(x, y); }, [](float x, float y) { return libm::pow(x, y); },
     [](double x, double y) { return std::pow(x, y); }, [](long double x, long double y) { return std::pow(x, y); },
     fast::kPowMaxRelError, true,
     [](float x, float y, double r) {   // positive normal x, finite y, a result in [2^-125, 2^127]
       return x >= FLT_MIN && x <= FLT_MAX && std::isfinite(y) && r >= 0x1p-125 && r <= 0x1p127;
     }},
    {"sin", [](float x, float) { return fast::sin(x); }, [](float x, float) { return libm::sin(x); },
     [](double x, double) { return std::sin(x); }, [](long double x, long double) { return std::sin(x); },
     fast::kSinMaxAbsError, false,
     [](float x, float, double) { return std::fabs(x) <= 8192.0f; }},
    {"cos", [](float x, float) { return fast::cos(x); }, [](float x, float) { return libm::cos(x); },
     [](double x, double) { return std::cos(x); }, [](long double x, long double) { return std::cos(x); },
     fast::kCosMaxAbsError, false,
     [](float x, float, double) { return std::fabs(x) <= 8192.0f; }},
    {"atan", [](float x, float) { return fast::atan(x); }, [](float x, float) { return libm::atan(x); },
     [](double x, double) { return std::atan(x); }, [](long double x, long double) { return std::atan(x); },
     fast::kAtanMaxAbsError, false,
     [](float x, float, double) { return !std::isnan(x); }},
    {"atan2", [](float y, float x) { return fast::atan(y, x); }, [](float y, float x) { return libm::atan(y, x); },
     [](double y, double x) { return std::atan2(y, x); }, [](long double y, long double x) { return std::atan2(y, x); },
     fast::kAtan2MaxAbsError, false,
     [](float y, float x, double) {   // finite, and not both below 2^-126 (see fast_math.h)
       return std::isfinite(x) && std::isfinite(y) && (std::fabs(x) >= FLT_MIN || std::fabs(y) >= FLT_MIN);
     }},
    {"asin", [](float x, float) { return fast::asin(x); }, [](float x, float) { return libm::asin(x); },
     [](double x, double) { return std::asin(x); }, [](long double x, long double) { return std::asin(x); },
     fast::kAsinMaxAbsError, false,
     [](float x, float, double) { return std::fabs(x) <= 1.0f; }},
    {"acos", [](float x, float) { return fast::acos(x); }, [](float x, float) { return libm::acos(x); },
     [](double x, double) { return std::acos(x); }, [](long double x, long double) { return std::acos(x); },
     fast::kAcosMaxAbsError, false,
     [](float x, float, double) { return std::fabs(x) <= 1.0f; }},
};

// Arguments (x, y); y is unused by the one-argument functions.
struct Arguments {
  std::vector<float> x, y;
  void add(const std::vector<float>& xs, const std::vector<float>& ys) {
    x.insert(x.end(), xs.begin(), xs.end());
    y.insert(y.end(), ys.begin(), ys.end());
  }
  void add(const std::vector<float>& xs) { add(xs, std::vector<float>(xs.size(), 0.0f)); }
};

// pow's exponents: for each base x, y = t / log2(x) with t uniform in [-125, 127], so the
// results x^y = 2^t spread over the whole float range (a uniform y would mostly overflow).
std::vector<float> exponentsSpreadingResults(const std::vector<float>& bases, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> log2Result(-125.0, 127.0);
  std::vector<float> ys;
  for (float x : bases) {
    const float y = float(log2Result(rng) / std::log2(double(x)));
    ys.push_back(std::isfinite(y) ? y : 1.0f);   // x = 1
  }
  return ys;
}

// The claimed domain of each function, sampled three ways, plus the edge values.
Arguments argumentsFor(const std::string& name) {
  Arguments args;
  if (name == "exp2") {
    args.add(uniformValues(1, -126.0f, 128.0f));
    args.add(uniformBits(2, 128.0f, true));
    args.add(logScale(3, -30.0f, 7.0f, true));
  } else if (name == "log2") {
    args.add(uniformValues(4, 0.0f, 64.0f));
    args.add(uniformBits(5, FLT_MAX, false));
    args.add(logScale(6, -10.0f, 10.0f, false));
  } else if (name == "pow") {
    const std::vector<float> bases = uniformBits(7, FLT_MAX, false);
    args.add(bases, exponentsSpreadingResults(bases, 8));
    const std::vector<float> nearOne = uniformValues(9, 0.0f, 4.0f);
    args.add(nearOne, exponentsSpreadingResults(nearOne, 10));
    args.add(uniformValues(11, 0.0f, 16.0f), uniformValues(12, -16.0f, 16.0f));
  } else if (name == "sin" || name == "cos") {
    args.add(uniformValues(13, -8192.0f, 8192.0f));
    args.add(uniformBits(14, 8192.0f, true));
    args.add(uniformValues(15, -12.57f, 12.57f));   // the first few periods, densely
  } else if (name == "atan") {
    args.add(uniformValues(16, -16.0f, 16.0f));
    args.add(uniformBits(17, FLT_MAX, true));
    args.add(logScale(18, -20.0f, 20.0f, true));
  } else if (name == "atan2") {
    args.add(uniformValues(19, -10.0f, 10.0f), uniformValues(20, -10.0f, 10.0f));
    args.add(uniformBits(21, FLT_MAX, true), uniformBits(22, FLT_MAX, true));
    args.add(logScale(23, -20.0f, 20.0f, true), logScale(24, -20.0f, 20.0f, true));
  } else {   // asin, acos
    args.add(uniformValues(25, -1.0f, 1.0f));
    args.add(uniformBits(26, 1.0f, true));
  }
  // The edge values: alone, and for the two-argument functions every pair of them.
  args.add(kEdgeValues);
  if (name == "pow" || name == "atan2")
    for (float x : kEdgeValues) args.add(std::vector<float>(kEdgeValues.size(), x), kEdgeValues);
  return args;
}

// ---- checks -------------------------------------------------------------------------------
// Whether r is the float nearest to exact (within 2^-20 ulp of a tie: the C library's double
// result is not exact either).
bool correctlyRounded(float r, long double exact) {
  const long double below = std::nextafter(r, -kInf), above = std::nextafter(r, kInf);
  const long double slack = (above - below) * 0x1p-21L;
  return exact >= (below + r) / 2 - slack && exact <= (above + r) / 2 + slack;
}

}  // namespace

TEST_SUITE("math_methods") {
  TEST_CASE("fast: each function within its documented error bound, and the bound is tight") {
    for (const Function& fn : kFunctions) {
      const std::string name = fn.name;
      CAPTURE(name);
      const Arguments args = argumentsFor(fn.name);
      double maxError = 0.0;
      float worstX = 0.0f, worstY = 0.0f;
      size_t checked = 0;
      for (size_t i = 0; i < args.x.size(); ++i) {
        const float x = args.x[i], y = args.y[i];
        const double reference = fn.reference(x, y);
        if (!fn.inFastDomain(x, y, reference)) continue;
        const double difference = std::fabs(double(fn.fast(x, y)) - reference);
        const double error = fn.relativeError ? difference / std::fabs(reference) : difference;
        ++checked;
        if (!(error <= maxError)) maxError = error, worstX = x, worstY = y;   // NaN counts as worst
      }
      CAPTURE(worstX);
      CAPTURE(worstY);
      CAPTURE(maxError);
      CHECK(checked > size_t(kSamples));
      REQUIRE(maxError <= fn.fastBound);
      CHECK(maxError >= fn.fastBound / 2);
    }
  }

  TEST_CASE("fast: edge cases") {
    const float halfPi = float(M_PI / 2), pi = float(M_PI);
    SUBCASE("exp2: overflow to +inf, underflow to 0, exact powers of two") {
      CHECK(fast::exp2(0.0f) == 1.0f);
      CHECK(fast::exp2(-0.0f) == 1.0f);
      for (float x : {128.0f, 200.0f, 1e30f, FLT_MAX, kInf}) CHECK(fast::exp2(x) == kInf);
      for (float x : {-127.0f, -127.5f, -200.0f, -1e30f, -FLT_MAX, -kInf}) CHECK(sameBits(fast::exp2(x), 0.0f));
      for (int k = -126; k <= 127; ++k) CHECK(fast::exp2(float(k)) == std::ldexp(1.0f, k));
      CHECK(std::isnan(fast::exp2(kNaN)));
    }
    SUBCASE("log2: 0 and denormals give -inf, negatives NaN, +inf stays") {
      for (float x : {0.0f, -0.0f, 1e-45f, 1e-40f, 0x1p-127f}) CHECK(fast::log2(x) == -kInf);
      for (float x : {-1e-45f, -FLT_MIN, -1.0f, -FLT_MAX, -kInf, kNaN}) CHECK(std::isnan(fast::log2(x)));
      CHECK(fast::log2(kInf) == kInf);
      for (int k = -126; k <= 127; ++k) CHECK(fast::log2(std::ldexp(1.0f, k)) == float(k));
      CHECK(fast::log2(FLT_MAX) == 128.0f);   // 127.99999991, rounded
    }
    SUBCASE("pow: NaN for x < 0, 0 for x = 0 and y > 0, 1 for y = 0 and x = 1") {
      for (float x : {-1.0f, -2.0f, -8.0f, -FLT_MIN, -kInf})
        for (float y : {1.0f, 2.0f, 3.0f, 0.5f, -1.0f}) CHECK(std::isnan(fast::pow(x, y)));
      for (float y : {1e-30f, 0.5f, 1.0f, 2.2f, 48.0f, FLT_MAX, kInf}) {
        CHECK(sameBits(fast::pow(0.0f, y), 0.0f));
        CHECK(sameBits(fast::pow(1e-40f, y), 0.0f));   // a denormal base reads as 0
      }
      for (float y : {-0.5f, -1.0f, -FLT_MAX}) CHECK(fast::pow(0.0f, y) == kInf);
      for (float x : {FLT_MIN, 0.3f, 1.0f, 7.0f, FLT_MAX}) CHECK(fast::pow(x, 0.0f) == 1.0f);
      for (float y : {-1e30f, -3.0f, 0.0f, 0.5f, 1e30f}) CHECK(fast::pow(1.0f, y) == 1.0f);
      CHECK(fast::pow(kInf, 1.0f) == kInf);
      CHECK(sameBits(fast::pow(kInf, -1.0f), 0.0f));
      CHECK(fast::pow(2.0f, 200.0f) == kInf);
      CHECK(sameBits(fast::pow(2.0f, -200.0f), 0.0f));
      CHECK(std::isnan(fast::pow(kNaN, 2.0f)));
      CHECK(std::isnan(fast::pow(2.0f, kNaN)));
    }
    SUBCASE("sin, cos: NaN for +-inf and NaN, [-1, 1] for every finite argument") {
      for (float x : {kInf, -kInf, kNaN}) {
        CHECK(std::isnan(fast::sin(x)));
        CHECK(std::isnan(fast::cos(x)));
      }
      CHECK(sameBits(fast::sin(0.0f), 0.0f));
      CHECK(fast::cos(0.0f) == 1.0f);
      CHECK(fast::cos(-0.0f) == 1.0f);
      CHECK(fast::sin(1e-40f) == 1e-40f);
      std::mt19937 rng(30);
      for (int i = 0; i < 100000; ++i) {
        float x = floatOf(rng());
        if (!std::isfinite(x)) continue;
        const float s = fast::sin(x), c = fast::cos(x);
        if (!(s >= -1.0f && s <= 1.0f && c >= -1.0f && c <= 1.0f)) FAIL_CHECK("x = " << x << ": sin " << s << ", cos " << c);
      }
      for (float x : {1e10f, -1e10f, 1e30f, FLT_MAX, -FLT_MAX}) {
        CHECK(std::fabs(fast::sin(x)) <= 1.0f);
        CHECK(std::fabs(fast::cos(x)) <= 1.0f);
      }
    }
    SUBCASE("atan") {
      CHECK(fast::atan(kInf) == halfPi);
      CHECK(fast::atan(-kInf) == -halfPi);
      CHECK(sameBits(fast::atan(0.0f), 0.0f));
      CHECK(sameBits(fast::atan(-0.0f), -0.0f));
      CHECK(std::isnan(fast::atan(kNaN)));
    }
    SUBCASE("atan(y, x): NaN in, NaN out; the axes; atan(0, 0) = 0") {
      for (float v : {0.0f, 1.0f, -1.0f, kInf, kNaN}) {
        CHECK(std::isnan(fast::atan(kNaN, v)));
        CHECK(std::isnan(fast::atan(v, kNaN)));
      }
      CHECK(sameBits(fast::atan(0.0f, 0.0f), 0.0f));
      CHECK(sameBits(fast::atan(0.0f, 1.0f), 0.0f));
      CHECK(sameBits(fast::atan(-0.0f, 1.0f), -0.0f));
      CHECK(fast::atan(0.0f, -1.0f) == pi);
      CHECK(fast::atan(-0.0f, -1.0f) == -pi);
      CHECK(fast::atan(1.0f, 0.0f) == halfPi);
      CHECK(fast::atan(-1.0f, 0.0f) == -halfPi);
      CHECK(fast::atan(kInf, 1.0f) == halfPi);
      CHECK(sameBits(fast::atan(1.0f, kInf), 0.0f));
      CHECK(fast::atan(1.0f, -kInf) == pi);
      CHECK(std::isnan(fast::atan(kInf, kInf)));   // undefined in GLSL; documented
    }
    SUBCASE("asin, acos: NaN outside [-1, 1]; exact at 0 and +-1") {
      for (float x : {std::nextafter(1.0f, 2.0f), -std::nextafter(1.0f, 2.0f), 2.0f, -FLT_MAX, kInf, -kInf, kNaN}) {
        CHECK(std::isnan(fast::asin(x)));
        CHECK(std::isnan(fast::acos(x)));
      }
      CHECK(sameBits(fast::asin(0.0f), 0.0f));
      CHECK(sameBits(fast::asin(-0.0f), -0.0f));
      CHECK(fast::asin(1.0f) == halfPi);
      CHECK(fast::asin(-1.0f) == -halfPi);
      CHECK(fast::acos(0.0f) == halfPi);
      CHECK(fast::acos(1.0f) == 0.0f);
      CHECK(fast::acos(-1.0f) == pi);
    }
  }

  TEST_CASE("libm: the C library's double result rounded once, i.e. correctly rounded floats") {
    for (const Function& fn : kFunctions) {
      const std::string name = fn.name;
      CAPTURE(name);
      const Arguments args = argumentsFor(fn.name);
      size_t notRoundedOnce = 0, notCorrectlyRounded = 0, nanMismatch = 0;
      std::string first;
      for (size_t i = 0; i < args.x.size(); ++i) {
        const float x = args.x[i], y = args.y[i];
        const float r = fn.precise(x, y);
        const double reference = fn.reference(x, y);
        if (std::isnan(reference) || std::isnan(r)) {
          nanMismatch += std::isnan(reference) != std::isnan(r);
          continue;
        }
        if (!sameBits(r, float(reference)) && notRoundedOnce++ == 0) first = "x = " + std::to_string(x) + ", y = " + std::to_string(y);
        if (std::isfinite(r) && !correctlyRounded(r, fn.exact(x, y)) && notCorrectlyRounded++ == 0)
          first = "x = " + std::to_string(x) + ", y = " + std::to_string(y) + ": not correctly rounded";
      }
      CAPTURE(first);
      CHECK(notRoundedOnce == 0);
      CHECK(notCorrectlyRounded == 0);
      CHECK(nanMismatch == 0);
    }
    // The C library's choices where GLSL leaves results undefined (see libm_math.h).
    CHECK(libm::pow(-2.0f, 3.0f) == -8.0f);
    CHECK(std::isnan(libm::pow(-8.0f, 1.0f / 3.0f)));
    CHECK(libm::pow(0.0f, 0.0f) == 1.0f);
    CHECK(libm::atan(0.0f, -0.0f) == float(M_PI));
    CHECK(libm::log2(0.0f) == -kInf);
    CHECK(std::isnan(libm::log2(-1.0f)));
    CHECK(libm::exp2(-140.0f) == 0x1p-140f);   // denormal results are kept
  }

  // fast::powConst<Y> (glsl::pow<Y> with `math=fast`) against fast::pow(x, Y), on groups of 16
  // arguments whose every lane is +-0 or a positive normal float (its shortcut, where 0 < |Y|
  // <= 0.98), and on groups with one other lane (denormal, negative, infinite, NaN: the full
  // function). Returns how many lanes of every lane type differ in their bits.
  template <float Y>
  size_t powConstMismatches() {
    using raster::simd::Lanes;
    using L8 = Lanes<8>;
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> exponent(-126.0f, 127.99f);
    const float others[] = {1e-40f, -1e-45f, -0.0f, -2.0f, -FLT_MAX, kInf, -kInf, kNaN};
    const float plain[] = {0.0f, -0.0f, FLT_MIN, FLT_MAX, 1.0f, 0.5f};
    size_t mismatches = 0;
    const auto check = [&](float got, float expected) {
      if (!sameBits(got, expected) && !(std::isnan(got) && std::isnan(expected))) ++mismatches;
    };
    for (int group = 0; group < 20000; ++group) {
      alignas(64) float xs[16];
      for (float& x : xs) x = rng() % 8u == 0 ? plain[rng() % 6u] : std::exp2(exponent(rng));
      if (group % 4 == 3) xs[rng() % 16u] = others[rng() % 8u];
      float expected[16];
      for (int l = 0; l < 16; ++l) {
        expected[l] = fast::pow(xs[l], Y);
        check(fast::powConst<Y>(xs[l]), expected[l]);
      }
      alignas(64) float out[16];
      fast::powConst<Y>(L8::load(xs)).store(out);
      fast::powConst<Y>(L8::load(xs + 8)).store(out + 8);
      for (int l = 0; l < 16; ++l) check(out[l], expected[l]);
#if RASTER_AVX2
      using raster::simd::Float8;
      using raster::simd::Float8x2;
      fast::powConst<Y>(Float8::load(xs)).store(out);
      fast::powConst<Y>(Float8::load(xs + 8)).store(out + 8);
      for (int l = 0; l < 16; ++l) check(out[l], expected[l]);
      fast::powConst<Y>(Float8x2::load(xs)).store(out);
      for (int l = 0; l < 16; ++l) check(out[l], expected[l]);
#endif
    }
    return mismatches;
  }

  TEST_CASE("fast: pow with a literal exponent gives pow(x, Y)'s bits, with or without its shortcut") {
    CHECK(powConstMismatches<1.0f / 2.2f>() == 0);   // the hdr composite's gamma
    CHECK(powConstMismatches<0.98f>() == 0);
    CHECK(powConstMismatches<0.01f>() == 0);
    CHECK(powConstMismatches<-0.5f>() == 0);
    CHECK(powConstMismatches<-0.98f>() == 0);
    CHECK(powConstMismatches<0.99f>() == 0);   // beyond the shortcut: fast::pow itself
    CHECK(powConstMismatches<2.5f>() == 0);
  }

  TEST_CASE("fast and libm: float, Lanes<8>, Float8 and Float8x2 give the same bits") {
    using raster::simd::Lanes;
    using L8 = Lanes<8>;
#if RASTER_AVX2
    using raster::simd::Float8;
    using raster::simd::Float8x2;
#endif
    struct LaneFunction {
      const char* name;
      float (*scalar)(float, float);
      L8 (*lanes)(L8, L8);
#if RASTER_AVX2
      Float8 (*float8)(Float8, Float8);
      Float8x2 (*paired)(Float8x2, Float8x2);
#endif
    };
#if RASTER_AVX2
#define RASTER_LANE_FN(name, expr)                                                                    \
  LaneFunction {                                                                                      \
    name, [](float x, float y) -> float { (void)y; return expr; }, [](L8 x, L8 y) -> L8 { (void)y; return expr; }, \
        [](Float8 x, Float8 y) -> Float8 { (void)y; return expr; },                                   \
        [](Float8x2 x, Float8x2 y) -> Float8x2 { (void)y; return expr; }                              \
  }
#else
#define RASTER_LANE_FN(name, expr) \
  LaneFunction { name, [](float x, float y) -> float { (void)y; return expr; }, [](L8 x, L8 y) -> L8 { (void)y; return expr; } }
#endif
    const LaneFunction functions[] = {
        RASTER_LANE_FN("fast::exp2", fast::exp2(x)),       RASTER_LANE_FN("fast::log2", fast::log2(x)),
        RASTER_LANE_FN("fast::pow", fast::pow(x, y)),      RASTER_LANE_FN("fast::sin", fast::sin(x)),
        RASTER_LANE_FN("fast::cos", fast::cos(x)),         RASTER_LANE_FN("fast::atan", fast::atan(x)),
        RASTER_LANE_FN("fast::atan2", fast::atan(x, y)),   RASTER_LANE_FN("fast::asin", fast::asin(x)),
        RASTER_LANE_FN("fast::acos", fast::acos(x)),       RASTER_LANE_FN("libm::exp2", libm::exp2(x)),
        RASTER_LANE_FN("libm::log2", libm::log2(x)),       RASTER_LANE_FN("libm::pow", libm::pow(x, y)),
        RASTER_LANE_FN("libm::sin", libm::sin(x)),         RASTER_LANE_FN("libm::cos", libm::cos(x)),
        RASTER_LANE_FN("libm::atan", libm::atan(x)),       RASTER_LANE_FN("libm::atan2", libm::atan(x, y)),
        RASTER_LANE_FN("libm::asin", libm::asin(x)),       RASTER_LANE_FN("libm::acos", libm::acos(x)),
    };
#undef RASTER_LANE_FN
    constexpr size_t kArguments = size_t(1) << 18;   // per function
    for (const LaneFunction& fn : functions) {
      const std::string name = fn.name;
      CAPTURE(name);
      std::mt19937 rng(77);
      std::uniform_real_distribution<float> shaderRange(-64.0f, 64.0f);
      size_t differing = 0;
      std::string first;
      for (size_t i = 0; i < kArguments; i += 16) {
        alignas(64) float xs[16], ys[16], lanesOut[16];
        for (int l = 0; l < 16; ++l) {
          // A third arbitrary bit patterns (every class), a third the usual shader ranges,
          // a third the edge values.
          switch (rng() % 3u) {
            case 0: xs[l] = floatOf(rng()), ys[l] = floatOf(rng()); break;
            case 1: xs[l] = shaderRange(rng), ys[l] = shaderRange(rng); break;
            default: xs[l] = kEdgeValues[rng() % kEdgeValues.size()], ys[l] = kEdgeValues[rng() % kEdgeValues.size()]; break;
          }
        }
        fn.lanes(L8::load(xs), L8::load(ys)).store(lanesOut);
        fn.lanes(L8::load(xs + 8), L8::load(ys + 8)).store(lanesOut + 8);
        float scalarOut[16];
        for (int l = 0; l < 16; ++l) scalarOut[l] = fn.scalar(xs[l], ys[l]);
        // NaN results need only both be NaN: where two NaNs meet (a NaN argument and a NaN
        // made inside), which payload survives depends on the compiler's operand order
        // (see simd/lanes.h).
        auto compare = [&](const float* out, const char* laneType) {
          for (int l = 0; l < 16; ++l)
            if (!sameBits(out[l], lanesOut[l]) && !(std::isnan(out[l]) && std::isnan(lanesOut[l])) && differing++ == 0)
              first = std::string(laneType) + " differs from Lanes<8> at x = " + std::to_string(xs[l]) + ", y = " + std::to_string(ys[l]) +
                      ": " + std::to_string(bitsOf(out[l])) + " vs " + std::to_string(bitsOf(lanesOut[l]));
        };
        compare(scalarOut, "float");
#if RASTER_AVX2
        alignas(64) float float8Out[16], pairedOut[16];
        fn.float8(Float8::load(xs), Float8::load(ys)).store(float8Out);
        fn.float8(Float8::load(xs + 8), Float8::load(ys + 8)).store(float8Out + 8);
        fn.paired(Float8x2::load(xs), Float8x2::load(ys)).store(pairedOut);
        compare(float8Out, "Float8");
        compare(pairedOut, "Float8x2");
#endif
      }
      CAPTURE(first);
      CHECK(differing == 0);
    }
  }
}
