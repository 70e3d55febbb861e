// powWithin<48> (gl_math.h) stands in for pow<48> where only a colour's RGBA8 bytes are kept
// (shaders_cpp/shadow/main.h; docs/porting.md, section 5). Its bound was measured on every
// float of [0, 1]; this checks it again on a sample (every 4099th float, the 2^14 floats
// below 1, and around the places where the difference was largest), in every lane type, and
// its edges.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raster/simd/gl_math.h"
#include "raster/simd/isa.h"
#include "tests/float_bits.h"

TEST_SUITE("math_methods") {
  TEST_CASE("powWithin<48>: within its stated error of pow<48> on [0, 1], an infinite error elsewhere") {
    using testing_support::bitsOf;
    using testing_support::floatOf;
    using testing_support::kInf;
    using testing_support::kNaN;
    std::vector<float> xs;
    for (uint32_t bits = 0; bits <= bitsOf(1.0f); bits += 4099) xs.push_back(floatOf(bits));
    for (uint32_t bits = bitsOf(1.0f) - (1u << 14); bits <= bitsOf(1.0f); ++bits) xs.push_back(floatOf(bits));
    for (const float worst : {0.24191992f, 0.999282062f, 0.162104934f})
      for (int d = -64; d <= 64; ++d) xs.push_back(floatOf(bitsOf(worst) + uint32_t(d)));
    while (xs.size() % 16) xs.push_back(0.5f);
    size_t outside = 0;
    double largest = 0.0;   // the largest |value - pow<48>| / value seen
    auto check = [&](float x, float value, float error) {
      const float exact = raster::glsl::pow<48.0f>(x);
      const double gap = std::fabs(double(value) - double(exact));
      if (!(gap <= double(error)) && outside++ == 0)
        MESSAGE("x = " << x << ": " << value << " vs " << exact << ", error " << error);
      if (value > 1e-30f) largest = std::max(largest, gap / double(value));
    };
    // Sixteen lanes from xs[i] on, as lane type L computes them (L::kCount divides 16).
    auto checkLanes = [&]<class L>(size_t i) {
      for (int first = 0; first < 16; first += L::kCount) {
        const auto within = raster::glsl::powWithin<48.0f>(L::load(&xs[i + size_t(first)]));
        alignas(64) float value[16], error[16];
        within.value.store(value);
        within.error.store(error);
        for (int l = 0; l < L::kCount; ++l) check(xs[i + size_t(first + l)], value[l], error[l]);
      }
    };
    for (size_t i = 0; i < xs.size(); i += 16) {
      for (int l = 0; l < 16; ++l) {
        const auto scalar = raster::glsl::powWithin<48.0f>(xs[i + size_t(l)]);
        check(xs[i + size_t(l)], scalar.value, scalar.error);
      }
      checkLanes.template operator()<raster::simd::Lanes<8>>(i);
#if RASTER_AVX2
      checkLanes.template operator()<raster::simd::Float8>(i);
      checkLanes.template operator()<raster::simd::Float8x2>(i);
#endif
    }
    CHECK(outside == 0);
    // The bound is the measured one, not a loose one: the sample comes within 2% of it.
    CHECK(largest >= 0.98 * double(raster::glsl::kPow48ByProductsRelError));
    for (const float x : {1.0000001f, 2.0f, kInf, kNaN, -0.5f, -kInf})
      CHECK(raster::glsl::powWithin<48.0f>(x).error == kInf);
    // Under any other math method the method's own pow, with no error.
    using raster::MathMethod;
    for (const MathMethod method : {MathMethod::Fast, MathMethod::FastFragment, MathMethod::Libm}) {
      raster::MethodSet set;
      set.math = method;
      const raster::ScopedMethods scoped(set);
      for (const float x : {0.0f, 0.3f, 0.97f, 1.0f}) {
        const auto within = raster::glsl::powWithin<48.0f>(x);
        CHECK(bitsOf(within.value) == bitsOf(raster::glsl::pow<48.0f>(x)));
        CHECK(within.error == 0.0f);
      }
    }
  }
}
