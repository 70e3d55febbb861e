// The div=approx method (raster/methods.h): reciprocalApprox and inversesqrtApprox of
// simd/div_approx.h against the exact values, over the whole range of positive normal floats,
// and the same bits in every lane type.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "raster/simd/glsl.h"
#include "tests/float_bits.h"

namespace {

using raster::glsl::inversesqrtApprox;
using raster::glsl::reciprocalApprox;
using Plain = raster::simd::Lanes<8>;

// Positive normal floats: log-uniform over the whole range, plus powers of two and the ends.
std::vector<float> positiveNormals() {
  std::vector<float> v = {1.0f, 2.0f, 0.5f, 3.0f, std::numeric_limits<float>::min(), std::numeric_limits<float>::max(),
                          1e-30f, 1e30f, 0.1f, 7.0f};
  for (int e = -125; e <= 127; ++e) v.push_back(std::ldexp(1.0f, e));
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> exponent(-125.9, 127.9);
  while (v.size() < (1u << 20)) v.push_back(float(std::exp2(exponent(rng))));
  while (v.size() % 8) v.push_back(1.0f);
  return v;
}

using testing_support::bitsOf;

}  // namespace

TEST_SUITE("simd") {
  TEST_CASE("div=approx: the reciprocal and inverse square root within their stated relative error") {
    const std::vector<float> values = positiveNormals();
    double worstRcp = 0, worstRsqrt = 0;
    for (const float x : values) {
      const float rcp = reciprocalApprox(x), rsqrt = inversesqrtApprox(x);
      // Where 1/x is near the bottom of the normal range (x >= 2^125) the seed is denormal and
      // the seed's subtraction leaves the float range: not a case the callers see (1/w of a
      // clipped vertex, squared lengths of unit-scale vectors); measure the rest.
      if (x < 0x1p125f) worstRcp = std::max(worstRcp, std::fabs(double(rcp) * double(x) - 1.0));
      worstRsqrt = std::max(worstRsqrt, std::fabs(double(rsqrt) * std::sqrt(double(x)) - 1.0));
    }
    MESSAGE("reciprocalApprox: max relative error " << worstRcp << "; inversesqrtApprox: " << worstRsqrt);
    CHECK(worstRcp < 7e-8);     // the bounds stated in div_approx.h
    CHECK(worstRsqrt < 5e-6);
    CHECK(worstRcp > 3e-8);     // an approximation: more than half a float ulp (2^-24 = 6e-8 relative at most)
    CHECK(worstRsqrt > 1e-7);
  }

  TEST_CASE("div=approx: every lane type gives the same bits") {
    const std::vector<float> values = positiveNormals();
    for (size_t i = 0; i < values.size(); i += 8) {
      const Plain plainRcp = reciprocalApprox(Plain::load(&values[i]));
      const Plain plainRsqrt = inversesqrtApprox(Plain::load(&values[i]));
#if RASTER_AVX2
      float fastRcp[8], fastRsqrt[8];
      reciprocalApprox(raster::simd::Float8::load(&values[i])).store(fastRcp);
      inversesqrtApprox(raster::simd::Float8::load(&values[i])).store(fastRsqrt);
#endif
      for (int l = 0; l < 8; ++l) {
        const float x = values[i + size_t(l)];
        REQUIRE(bitsOf(plainRcp.lane[l]) == bitsOf(reciprocalApprox(x)));
        REQUIRE(bitsOf(plainRsqrt.lane[l]) == bitsOf(inversesqrtApprox(x)));
#if RASTER_AVX2
        REQUIRE(bitsOf(fastRcp[l]) == bitsOf(reciprocalApprox(x)));
        REQUIRE(bitsOf(fastRsqrt[l]) == bitsOf(inversesqrtApprox(x)));
#endif
      }
    }
  }

  TEST_CASE("div=approx: the reciprocal of 1 is exactly 1") {
    // Interpolation leaves out the 1/w of a triangle whose w is 1 at every vertex (a
    // fullscreen pass's, tile/interpolate.h), a product with 1 either way: that keeps
    // --preset fast's bytes only while this reciprocal lands on 1.0 exactly.
    CHECK(bitsOf(reciprocalApprox(1.0f)) == bitsOf(1.0f));
    CHECK(bitsOf(reciprocalApprox(Plain(1.0f)).lane[7]) == bitsOf(1.0f));
  }

  TEST_CASE("div: normalize follows the method set; exact is llvmpipe's v * (1 / sqrt(dot(v, v)))") {
    using raster::glsl::vec3;
    const vec3<float> v(3.0f, 4.0f, 12.0f);
    const float exact = 1.0f / std::sqrt(169.0f);
    CHECK(bitsOf(raster::glsl::normalize(v).x) == bitsOf(3.0f * exact));
    raster::MethodSet approx;
    approx.div = raster::DivMethod::Approx;
    const raster::ScopedMethods scoped(approx);
    const float n = raster::glsl::normalize(v).x;
    CHECK(bitsOf(n) == bitsOf(3.0f * inversesqrtApprox(169.0f)));
    CHECK(std::fabs(n / (3.0f / 13.0f) - 1.0f) < 5e-6f);
  }

  TEST_CASE("normalizeUniform gives every lane the bits of the lanes' own normalize, in both div methods") {
    using raster::glsl::vec3;
#if RASTER_AVX2
    using Lanes = raster::simd::Float8x2;   // the shader ports' widest lane type
#else
    using Lanes = raster::simd::Lanes<8>;
#endif
    constexpr int kLanes = Lanes::kCount;
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> component(-100.0f, 100.0f);
    std::vector<glm::vec3> inputs = {{0.5f, 1.0f, 0.3f}, {0.0f, 0.0f, 0.0f}, {1e-30f, 0.0f, 0.0f}, {1e-40f, 2e-39f, 0.0f},
                                     {3e38f, 3e38f, 1.0f}, {-0.0f, 1.0f, -2.0f}, {std::numeric_limits<float>::infinity(), 1.0f, 0.0f},
                                     {std::numeric_limits<float>::quiet_NaN(), 1.0f, 1.0f}};
    for (int i = 0; i < 20000; ++i) inputs.push_back({component(rng), component(rng), component(rng) * std::ldexp(1.0f, i % 60 - 30)});
    for (const raster::DivMethod method : {raster::DivMethod::Exact, raster::DivMethod::Approx}) {
      raster::MethodSet set;
      set.div = method;
      const raster::ScopedMethods scoped(set);
      size_t differing = 0;
      for (const glm::vec3& v : inputs) {
        const vec3<Lanes> once = raster::glsl::normalizeUniform<Lanes>(v);
        const vec3<Lanes> lanes = raster::glsl::normalize(vec3<Lanes>(v));
        alignas(64) float a[3][kLanes], b[3][kLanes];
        once.x.store(a[0]), once.y.store(a[1]), once.z.store(a[2]);
        lanes.x.store(b[0]), lanes.y.store(b[1]), lanes.z.store(b[2]);
        for (int c = 0; c < 3; ++c)
          for (int l = 0; l < kLanes; ++l) differing += bitsOf(a[c][l]) != bitsOf(b[c][l]);
      }
      CAPTURE(int(method));
      CHECK(differing == 0);
    }
  }
}
