// The numbers `raster compare` reports for a pair of images (compare/metrics.h), in the units
// it states: 8-bit steps for RGBA8, LSBs for depth codes, ULPs of half or float32 for float
// targets, with +0 and -0 equal and NaNs one pattern. tests/apps/cli_test.cpp checks that
// compare.json carries them; tests/compare/flip_test.cpp the perceptual metric.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <ios>
#include <string>

#include "compare/metrics.h"
#include "tests/compare/test_images.h"

namespace {

using namespace test_images;
using scenes::ImageData;
using scenes::TexelFormat;

// The value of a half bit pattern, decoded independently of compare::halfBits.
float halfValue(uint16_t bits) {
  const int exponent = (bits >> 10) & 0x1f, mantissa = bits & 0x3ff;
  const float magnitude = exponent == 0 ? std::ldexp(float(mantissa), -24)
                                        : std::ldexp(float(mantissa | 0x400), exponent - 25);
  return (bits & 0x8000) ? -magnitude : magnitude;
}

}  // namespace

TEST_SUITE("metrics") {
  TEST_CASE("identical images: no difference, infinite PSNR") {
    const compare::TargetStats s = compare::compareImages("t", rgba8Image(4, 4, 7), rgba8Image(4, 4, 7));
    CHECK(s.kind == "rgba8");
    CHECK(s.maxAbs == 0);
    CHECK(s.rmse == 0);
    CHECK(std::isinf(s.psnr));
    CHECK(s.shareDiffering == 0);
    CHECK(s.shareBitIdentical == 1);
    CHECK(compare::formatStatsLine(s).find("inf") != std::string::npos);
  }

  TEST_CASE("one step in one pixel counts as one differing pixel, none over 1") {
    const ImageData a = rgba8Image(4, 4, 100);
    ImageData b = a;
    b.rgba8[5 * 4 + 2] = 101;
    const compare::TargetStats s = compare::compareImages("t", a, b);
    CHECK(s.maxAbs == 1);
    CHECK(s.shareDiffering == doctest::Approx(1.0 / 16));
    CHECK(s.shareOver1 == 0);
    CHECK(s.rmse == doctest::Approx(std::sqrt(1.0 / 64)));
    CHECK(compare::pixelDifference(a, b, 5) == 1);
  }

  TEST_CASE("depth differences are counted in LSBs") {
    const ImageData a = depthImage(2, 1, 24, {1000, 2000});
    const compare::TargetStats s = compare::compareImages("d", a, depthImage(2, 1, 24, {1000, 2003}));
    CHECK(s.kind == "depth");
    CHECK(s.depthTexelsDiffering == 1);
    CHECK(s.maxDepthLsb == 3);
    CHECK(s.shareOver1 == doctest::Approx(0.5));
    CHECK(s.shareOver4 == 0);
  }

  TEST_CASE("half ULPs: +0 and -0 are 0 apart, 1.0 and the next half 1") {
    CHECK(compare::halfUlpDistance(compare::halfBits(0.0f), compare::halfBits(-0.0f)) == 0);
    CHECK(compare::halfUlpDistance(0x0001, 0x8001) == 2);   // across zero
    const float nextAfterOne = 1.0f + 1.0f / 1024;          // 0x3c01
    CHECK(compare::halfBits(nextAfterOne) == 0x3c01);
    const compare::TargetStats s = compare::compareImages(
        "h", halfImage({0.0f, 1.0f, 0.5f, 1.0f}), halfImage({-0.0f, nextAfterOne, 0.5f, 1.0f}));
    CHECK(s.kind == "half");
    CHECK(s.maxUlps == 1);
    CHECK(s.shareBitIdentical == 0);
    CHECK(compare::compareImages("z", halfImage({0, 0, 0, 1}), halfImage({-0.0f, 0, 0, 1})).maxUlps == 0);
  }

  // --float-final's targets: one float step must show, which half ULPs would round away.
  TEST_CASE("float ULPs: RGBA32F targets are measured in float32 steps, not half") {
    ImageData a = halfImage({0.0f, 1.0f, 0.5f, std::nanf("")}), b = halfImage({-0.0f, std::nextafter(1.0f, 2.0f), 0.5f, std::nanf("")});
    a.format = b.format = TexelFormat::RGBA32F;
    const compare::TargetStats s = compare::compareImages("f", a, b);
    CHECK(s.kind == "float");
    CHECK(s.maxUlps == 1);
    CHECK(s.shareBitIdentical == 0);
    CHECK(s.nonFinitePixels == 1);
    CHECK(compare::floatUlpDistance(compare::floatBits(0.0f), compare::floatBits(-0.0f)) == 0);
    CHECK(compare::floatBits(std::nanf("")) == compare::floatBits(std::nanf("1")));
    CHECK(compare::formatStatsLine(s).find("float") != std::string::npos);
    // The same pair as half targets: one float step is no half ULP.
    a.format = b.format = TexelFormat::RGBA16F;
    CHECK(compare::compareImages("h", a, b).maxUlps == 0);
  }

  TEST_CASE("halfBits rounds every half value back to its own bits") {
    for (uint32_t bits = 0; bits <= 0xffff; ++bits) {
      if ((bits & 0x7c00) == 0x7c00 && (bits & 0x3ff)) continue;   // NaNs have no single pattern
      const uint16_t half = uint16_t(bits);
      if (compare::halfBits(halfValue(half)) != half) FAIL("half 0x" << std::hex << bits);
    }
    CHECK(compare::halfBits(65519.0f) == 0x7bff);   // rounds down to the largest half
    CHECK(compare::halfBits(65520.0f) == 0x7c00);   // rounds up to infinity
  }
}
