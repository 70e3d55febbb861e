// Unit tests of raster/texture/format.h at every rounding boundary, against independent
// models (double-precision arithmetic that is exact where it is used, and the CPU's F16C
// conversions), plus confirmations against GL (llvmpipe) for the render-target writes.
//
// Models: a float product is computed exactly in double and rounded once to float (the same
// as the float multiply llvmpipe does); "round half to even" of a double that holds the
// value exactly is done with floor and an exact comparison with 0.5.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#endif

#include "raster/texture/format.h"
#include "tests/gl_compare_helpers.h"

namespace {

using namespace raster::format;

float bitsToFloat(uint32_t b) {
  float f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

// Round half to even of a value held exactly by the double.
int64_t roundHalfEvenExact(double p) {
  const double f = std::floor(p);
  const double frac = p - f;   // exact: p and f are close doubles
  if (frac > 0.5) return int64_t(f) + 1;
  if (frac < 0.5) return int64_t(f);
  return (int64_t(f) % 2 == 0) ? int64_t(f) : int64_t(f) + 1;
}

// float(a * b) for floats a and b: the double product is exact (24 + 24 bits), one rounding.
float floatProduct(float a, float b) { return float(double(a) * double(b)); }

// unorm8: min(x, 1), * 255 in float, round half to even, saturate; NaN and negatives give 0.
uint8_t unorm8Model(float x) {
  if (std::isnan(x)) return 0;
  if (x >= 1.0f) return 255;
  const float p = floatProduct(x, 255.0f);
  if (!(p > 0.0f)) return 0;
  const int64_t r = roundHalfEvenExact(double(p));
  return uint8_t(r > 255 ? 255 : r);
}

// depth24 for z in [0, 1]: z * 16777215 in float, round half to even.
uint32_t depth24Model(float z) { return uint32_t(roundHalfEvenExact(double(floatProduct(z, 16777215.0f)))); }

// depth16 for z in [0, 1]: t = float(z * float(65535/65536)) + 128.0f, low 16 bits. In [128, 256)
// floats are spaced 2^-16, so the float add rounds p to that grid (half to even) and the
// mantissa's low 16 bits are that count of 2^-16 steps.
uint32_t depth16Model(float z) {
  const float p = floatProduct(z, float(65535.0 / 65536.0));
  return uint32_t(roundHalfEvenExact(double(p) * 65536.0)) & 0xFFFFu;
}

// Floats around x: x and `n` float steps each way.
std::vector<float> around(float x, int n) {
  std::vector<float> out{x};
  float lo = x, hi = x;
  for (int i = 0; i < n; ++i) {
    lo = std::nextafter(lo, -INFINITY);
    hi = std::nextafter(hi, INFINITY);
    out.push_back(lo);
    out.push_back(hi);
  }
  return out;
}

bool isHalfNan(uint16_t h) { return (h & 0x7C00u) == 0x7C00u && (h & 0x03FFu) != 0; }

#if RASTER_AVX2
uint16_t f16cTowardZero(float f) { return uint16_t(_cvtss_sh(f, _MM_FROUND_TO_ZERO)); }
uint16_t f16cNearestEven(float f) { return uint16_t(_cvtss_sh(f, _MM_FROUND_TO_NEAREST_INT)); }
#endif

}  // namespace

TEST_SUITE("format") {
  TEST_CASE("unorm8FromFloat: every rounding boundary (k + 0.5) / 255 and its float neighbours") {
    int checked = 0, productRounded = 0;
    for (int k = 0; k < 255; ++k) {
      for (float b : {float((k + 0.5) / 255.0), (float(k) + 0.5f) / 255.0f}) {
        for (float x : around(b, 32)) {
          CAPTURE(k);
          CAPTURE(x);
          REQUIRE(unorm8FromFloat(x) == unorm8Model(x));
          // Within half a step of the exact value, except where the float product rounded.
          const double exact = double(x) * 255.0;
          const int code = unorm8FromFloat(x);
          CHECK(std::fabs(double(code) - exact) <= 0.5 + 1e-4);
          productRounded += code != int(roundHalfEvenExact(exact));
          ++checked;
        }
      }
    }
    MESSAGE("unorm8: " << checked << " values at boundaries; " << productRounded
                       << " round differently from the exact x * 255 (the float product's rounding)");
    // Monotone over [0, 1] (every 97th float).
    uint32_t previous = 0;
    int decreases = 0;
    for (uint32_t bits = 0; bits <= floatBits(1.0f); bits += 97) {
      const uint32_t code = unorm8FromFloat(bitsToFloat(bits));
      decreases += code < previous;
      previous = code;
    }
    CHECK(decreases == 0);
    CHECK(unorm8FromFloat(1.0f) == 255);
    // The reference notes' measurements (AVX path).
    CHECK(unorm8FromFloat(0.5f / 255.0f) == 0);
    CHECK(unorm8FromFloat(1.5f / 255.0f) == 2);
    CHECK(unorm8FromFloat(2.5f / 255.0f) == 2);
    CHECK(unorm8FromFloat(127.5f / 255.0f) == 128);
    CHECK(unorm8FromFloat(254.5f / 255.0f) == 254);
    CHECK(unorm8FromFloat(-0.1f) == 0);
    CHECK(unorm8FromFloat(1e10f) == 255);
    CHECK(unorm8FromFloat(300.0f) == 255);
    CHECK(unorm8FromFloat(3e9f) == 255);
    CHECK(unorm8FromFloat(INFINITY) == 255);
    CHECK(unorm8FromFloat(-INFINITY) == 0);
    CHECK(unorm8FromFloat(std::numeric_limits<float>::quiet_NaN()) == 0);
    CHECK(unorm8FromFloat(-std::numeric_limits<float>::quiet_NaN()) == 0);
    CHECK(unorm8FromFloat(-0.0f) == 0);
    CHECK(unorm8FromFloat(std::numeric_limits<float>::denorm_min()) == 0);
  }

  TEST_CASE("depth24FromFloat: boundaries (k + 0.5) / (2^24 - 1) against multiply-in-float, round half to even") {
    std::vector<uint32_t> ks;
    for (uint32_t i = 0; i <= 4096; ++i) ks.push_back(uint32_t(uint64_t(i) * (kDepth24Max - 1) / 4096));
    for (uint32_t k = 0; k < 64; ++k) ks.push_back(k);
    for (uint32_t k = kDepth24Max - 64; k < kDepth24Max; ++k) ks.push_back(k);
    for (int e = 1; e < 24; ++e)   // where the float spacing of z changes
      for (int d = -2; d <= 2; ++d) ks.push_back(uint32_t(int64_t(1) << e) + uint32_t(d));
    int checked = 0, productRounded = 0;
    for (uint32_t k : ks) {
      for (float z : around(float((k + 0.5) / double(kDepth24Max)), 3)) {
        if (z < 0.0f || z > 1.0f) continue;
        CAPTURE(k);
        CAPTURE(z);
        REQUIRE(depth24FromFloat(z) == depth24Model(z));
        const double exact = double(z) * double(kDepth24Max);
        CHECK(std::fabs(double(depth24FromFloat(z)) - exact) <= 1.0);
        productRounded += int64_t(depth24FromFloat(z)) != roundHalfEvenExact(exact);
        ++checked;
      }
    }
    MESSAGE("depth24: " << checked << " values at " << ks.size() << " boundaries; " << productRounded
                        << " round differently from the exact z * (2^24 - 1)");
    CHECK(depth24FromFloat(0.0f) == 0u);
    CHECK(depth24FromFloat(-0.0f) == 0u);
    CHECK(depth24FromFloat(1.0f) == kDepth24Max);
    CHECK(depth24FromFloat(std::nextafter(1.0f, 0.0f)) == depth24Model(std::nextafter(1.0f, 0.0f)));
    CHECK(depth24FromFloat(std::numeric_limits<float>::denorm_min()) == 0u);
    CHECK(depth24FromFloat(-1e-7f) == 0u);
    // The reference notes' measurements: 0.5 -> 8388608 (8388607.5 to even), 0.3f -> 5033164.
    CHECK(depth24FromFloat(0.5f) == 8388608u);
    CHECK(depth24FromFloat(0.3f) == 5033164u);
    for (int k = 0; k < 4; ++k) {   // 0.5, 1.5, 2.5, 3.5 after the product: 0, 2, 2, 4
      const float z = float((k + 0.5) / double(kDepth24Max));
      if (floatProduct(z, 16777215.0f) == float(k) + 0.5f) CHECK(depth24FromFloat(z) == uint32_t(k % 2 ? k + 1 : k));
    }
  }

  TEST_CASE("depth16FromFloat: every code boundary (k + 0.5) / 65535 against the magic-number model") {
    int checked = 0, differsFromExact = 0;
    for (uint32_t k = 0; k < kDepth16Max; ++k) {
      for (float z : around(float((k + 0.5) / double(kDepth16Max)), 2)) {
        if (z < 0.0f || z > 1.0f) continue;
        const uint32_t code = depth16FromFloat(z);
        if (code != depth16Model(z)) {
          CAPTURE(k);
          CAPTURE(z);
          REQUIRE(code == depth16Model(z));
        }
        const int64_t exact = roundHalfEvenExact(double(z) * double(kDepth16Max));   // exact: 24 + 16 bits
        differsFromExact += int64_t(code) != exact;
        if (std::llabs(int64_t(code) - exact) > 1) {
          CAPTURE(z);
          REQUIRE(std::llabs(int64_t(code) - exact) <= 1);
        }
        ++checked;
      }
    }
    MESSAGE("depth16: " << checked << " values at all 65535 boundaries; " << differsFromExact
                        << " differ from round-half-even(z * 65535) (the float product's rounding)");
    CHECK(differsFromExact > 0);   // the trick is not the exact rounding: the model matters
    CHECK(depth16FromFloat(0.0f) == 0u);
    CHECK(depth16FromFloat(1.0f) == kDepth16Max);
    CHECK(depth16FromFloat(std::nextafter(1.0f, 0.0f)) == kDepth16Max);
    // The reference notes' measurements, where exact rounding would give 1 and 3.
    CHECK(depth16FromFloat(1.5f / 65535.0f) == 2u);
    CHECK(depth16FromFloat(3.5f / 65535.0f) == 4u);
    CHECK(roundHalfEvenExact(double(1.5f / 65535.0f) * 65535.0) == 1);
  }

  TEST_CASE("half conversions: all 65536 halves round-trip; the reference notes' values") {
    int nans = 0;
    for (uint32_t h = 0; h < 65536; ++h) {
      const float f = floatFromHalf(uint16_t(h));
      CAPTURE(h);
      if (isHalfNan(uint16_t(h))) {
        ++nans;
        REQUIRE(std::isnan(f));
        REQUIRE(isHalfNan(halfFromFloatTowardZero(f)));
        REQUIRE(isHalfNan(halfFromFloatNearestEven(f)));
        REQUIRE((halfFromFloatTowardZero(f) & 0x8000u) == (h & 0x8000u));   // sign kept
        continue;
      }
      REQUIRE(halfFromFloatTowardZero(f) == h);
      REQUIRE(halfFromFloatNearestEven(f) == h);
#if RASTER_AVX2
      REQUIRE(floatBits(f) == floatBits(_cvtsh_ss(uint16_t(h))));
#endif
    }
    CHECK(nans == 2 * 1023);
    // Measured on llvmpipe (render-target writes truncate; uploads round to nearest even).
    CHECK(halfFromFloatTowardZero(1.0007f) == 0x3C00);
    CHECK(halfFromFloatNearestEven(1.0007f) == 0x3C01);
    CHECK(halfFromFloatTowardZero(70000.0f) == 0x7BFF);
    CHECK(halfFromFloatTowardZero(65520.0f) == 0x7BFF);
    CHECK(halfFromFloatNearestEven(65520.0f) == 0x7C00);
    CHECK(halfFromFloatNearestEven(70000.0f) == 0x7C00);
    CHECK(halfFromFloatTowardZero(1e-6f) == 0x0010);
    CHECK(halfFromFloatNearestEven(1e-6f) == 0x0011);
    CHECK(halfFromFloatTowardZero(INFINITY) == 0x7C00);
    CHECK(halfFromFloatTowardZero(-INFINITY) == 0xFC00);
    CHECK(halfFromFloatTowardZero(-70000.0f) == 0xFBFF);
    CHECK(isHalfNan(halfFromFloatTowardZero(std::numeric_limits<float>::quiet_NaN())));
  }

#if RASTER_AVX2
  TEST_CASE("half conversions against F16C (vcvtps2ph, truncate and nearest-even) on every boundary class") {
    auto check = [](float f, int& mismatches) {
      const uint16_t tz = halfFromFloatTowardZero(f), ne = halfFromFloatNearestEven(f);
      const uint16_t tzRef = f16cTowardZero(f), neRef = f16cNearestEven(f);
      if (tz != tzRef || ne != neRef) {
        if (mismatches++ < 5) {
          CAPTURE(floatBits(f));
          CAPTURE(f);
          CHECK(tz == tzRef);
          CHECK(ne == neRef);
        }
      }
    };
    int mismatches = 0;
    long checked = 0;
    // 10 million random bit patterns (every class: NaN, Inf, denormals, overflow, ties rarely).
    std::mt19937 rng(8008);
    for (int i = 0; i < 10'000'000; ++i, ++checked) check(bitsToFloat(uint32_t(rng())), mismatches);
    // Every float whose 13 dropped mantissa bits are a tie (0x1000) or next to one.
    for (uint32_t high = 0; high < (1u << 19); ++high)
      for (uint32_t low : {0x1000u, 0x0FFFu, 0x1001u, 0x0000u, 0x1FFFu}) check(bitsToFloat((high << 13) | low), mismatches), ++checked;
    // Half denormals: ties (m + 0.5) * 2^-24 and their neighbours, both signs; and the
    // normal/denormal border 2^-14.
    for (int m = 0; m < 1025; ++m)
      for (float f : around(float((m + 0.5) * std::ldexp(1.0, -24)), 3)) check(f, mismatches), check(-f, mismatches), checked += 2;
    for (float f : around(std::ldexp(1.0f, -14), 64)) check(f, mismatches), check(-f, mismatches), checked += 2;
    // Overflow: every float from 65504 up to 2^16 * 1.0625, both signs.
    for (uint32_t b = floatBits(65504.0f); b <= floatBits(69632.0f); ++b)
      check(bitsToFloat(b), mismatches), check(-bitsToFloat(b), mismatches), checked += 2;
    // Float denormals, zeros, infinities, NaN payloads.
    for (uint32_t b = 0; b < (1u << 23); b += 4099) check(bitsToFloat(b), mismatches), check(-bitsToFloat(b), mismatches), checked += 2;
    for (uint32_t b = 0x7F800000u; b <= 0x7FFFFFFFu; b += 65521) check(bitsToFloat(b), mismatches), check(-bitsToFloat(b), mismatches), checked += 2;
    MESSAGE("half vs F16C: " << checked << " floats, " << mismatches << " mismatches");
    CHECK(mismatches == 0);
  }
#endif

  TEST_CASE("GL confirms the render-target conversions (RGBA8, Depth24, Depth16, RGBA16F), and so do we") {
    using namespace gltest;
    constexpr int kSize = 64;
    constexpr int kCells = kSize * kSize;
    std::mt19937 rng(9009);

    // Values for a grid of 1x1-pixel squares, 4 channels each (colour) or one (depth).
    std::vector<float> unorm;
    for (int k = 0; k < 255; ++k)
      for (float x : around(float((k + 0.5) / 255.0), 1)) unorm.push_back(x);
    for (float x : {0.5f / 255.0f, 1.5f / 255.0f, 2.5f / 255.0f, 127.5f / 255.0f, 254.5f / 255.0f, -0.1f, 1e10f, 300.0f,
                    3e9f, 1.0f, 0.0f, std::nextafter(1.0f, 2.0f), -1e10f})
      unorm.push_back(x);
    while (unorm.size() < size_t(kCells) * 4) unorm.push_back(uniform(rng, -0.05f, 1.05f));

    std::vector<float> halfValues = {1.0007f, 70000.0f, 1e-6f, 65520.0f, -70000.0f, -1.0007f, -1e-6f, 65504.0f,
                                     std::nextafter(65520.0f, 0.0f), 1e5f, 3e38f, 5.96e-8f, 2.9e-8f, 6.1e-5f, 6.2e-5f};
    for (uint32_t h = 0; h < 0x7C00u; h += 37) {   // ties between consecutive halves, both signs
      const float tie = float(0.5 * (double(floatFromHalf(uint16_t(h))) + double(floatFromHalf(uint16_t(h + 1)))));
      halfValues.push_back(tie);
      halfValues.push_back(-tie);
    }
    while (halfValues.size() < size_t(kCells) * 4)
      halfValues.push_back((rng() & 1u ? 1.0f : -1.0f) * std::exp2(uniform(rng, -26.0f, 17.0f)));

    // Window depths z = fma(ndc, 0.5, 0.5): NDC values aimed at the codes' boundaries.
    auto depthNdc = [&](double codes) {
      std::vector<float> ndc;
      for (int i = 0; ndc.size() < size_t(kCells); ++i) {
        const double k = std::floor(double(i) * (codes - 1.0) / double(kCells / 3));
        for (float n : around(float(2.0 * ((k + 0.5) / codes) - 1.0), 1)) ndc.push_back(std::clamp(n, -1.0f, 1.0f));
      }
      ndc.resize(size_t(kCells));
      ndc[0] = 0.0f;   // window z 0.5
      ndc[1] = -1.0f;
      ndc[2] = 1.0f;
      return ndc;
    };
    const std::vector<float> ndc24 = depthNdc(16777215.0), ndc16 = depthNdc(65535.0);

    auto colorGrid = [&](const std::vector<float>& values) {
      DrawCall d;
      d.mesh = gridMesh(kSize, kSize, 1, [&](int x, int row) {
        const size_t i = (size_t(row) * kSize + size_t(x)) * 4;
        return GridCell{glm::vec4(values[i], values[i + 1], values[i + 2], values[i + 3]), 0.0f};
      });
      d.state.depthTest = false;
      return d;
    };
    auto depthGrid = [&](const std::vector<float>& ndc) {
      DrawCall d;
      d.mesh = gridMesh(kSize, kSize, 1, [&](int x, int row) { return GridCell{glm::vec4(1.0f), ndc[size_t(row) * kSize + size_t(x)]}; });
      d.state.depthFunc = scenes::DepthFunc::Lequal;   // codes up to 2^n - 1 pass against the clear
      return d;
    };

    for (bool gl : {true, false}) {
      auto backend = gl ? scenes::makeGlBackend() : scenes::makeRasterBackend(0);
      const std::string who = backend->name();
      CAPTURE(who);

      const Rendered rgba8 = render(*backend, {kSize, kSize, TexelFormat::RGBA8, std::nullopt}, {colorGrid(unorm)}, clearAll());
      int rgba8Diffs = 0;
      for (size_t i = 0; i < unorm.size(); ++i) {
        if (rgba8.color->rgba8[i] != unorm8FromFloat(unorm[i]) && rgba8Diffs++ < 3) {
          CAPTURE(unorm[i]);
          CHECK(int(rgba8.color->rgba8[i]) == int(unorm8FromFloat(unorm[i])));
        }
      }

      const Rendered half = render(*backend, {kSize, kSize, TexelFormat::RGBA16F, std::nullopt}, {colorGrid(halfValues)}, clearAll());
      int halfDiffs = 0;
      for (size_t i = 0; i < halfValues.size(); ++i) {
        const float expected = floatFromHalf(halfFromFloatTowardZero(halfValues[i]));
        if (floatBits(half.color->floats[i]) != floatBits(expected) && halfDiffs++ < 3) {
          CAPTURE(halfValues[i]);
          CHECK(half.color->floats[i] == expected);
        }
      }

      int depthDiffs = 0;
      for (TexelFormat format : {TexelFormat::Depth24, TexelFormat::Depth16}) {
        const std::vector<float>& ndc = format == TexelFormat::Depth24 ? ndc24 : ndc16;
        const Rendered depth = render(*backend, {kSize, kSize, std::nullopt, format}, {depthGrid(ndc)}, clearAll());
        for (size_t i = 0; i < ndc.size(); ++i) {
          const float windowZ = std::fma(ndc[i], 0.5f, 0.5f);
          const uint32_t expected = format == TexelFormat::Depth24 ? depth24FromFloat(windowZ) : depth16FromFloat(windowZ);
          if (depth.depth->depth[i] != expected && depthDiffs++ < 3) {
            CAPTURE(ndc[i]);
            CAPTURE(windowZ);
            CHECK(depth.depth->depth[i] == expected);
          }
        }
      }
      MESSAGE(who << ": " << unorm.size() << " RGBA8 writes (" << rgba8Diffs << " off unorm8FromFloat), " << halfValues.size()
                  << " RGBA16F writes (" << halfDiffs << " off halfFromFloatTowardZero), " << 2 * kCells
                  << " depth writes (" << depthDiffs << " off depth24/16FromFloat)");
      CHECK(rgba8Diffs == 0);
      CHECK(halfDiffs == 0);
      CHECK(depthDiffs == 0);
    }
  }
}
