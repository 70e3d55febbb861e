// The output merge's SIMD colour conversions and writes equal the scalar reference on every
// class of input (merge/color_write.h and its AVX2 sibling).
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/merge/color_write.h"
#include "raster/merge/unorm8_within.h"

namespace {

using raster::simd::FastLanes;
using Plain = raster::simd::Lanes<8>;

// Interesting floats: rounding boundaries of both formats, specials, and random values.
std::vector<float> interestingValues() {
  std::vector<float> v = {0.0f, -0.0f, 1.0f, -1.0f, 2.0f, 1e10f, -1e10f, std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::denorm_min(), 1.0f + 1e-7f, 1.0f - 1e-8f};
  for (int k = 0; k < 256; ++k) {
    const float b = (float(k) + 0.5f) / 255.0f;
    v.insert(v.end(), {b, std::nextafter(b, 0.0f), std::nextafter(b, 1.0f)});
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(-0.1f, 1.1f);
  for (int i = 0; i < 4000; ++i) v.push_back(unit(rng));
  while (v.size() % 8) v.push_back(0.5f);
  return v;
}

}  // namespace

TEST_SUITE("format") {
  // merge/unorm8_within.h: a lane it passes must give its byte for every value within the
  // error; the values sit on, beside and between the RGBA8 write's rounding boundaries.
  TEST_CASE("unorm8Within: every value within the error of a lane it passes converts to that lane's byte") {
    std::vector<float> values = interestingValues();
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-0.01f, 1.01f);
    for (int i = 0; i < 20000; ++i) values.push_back(unit(rng));
    for (const float v : {3.9f, 7.9f, 8.0f, 100.0f, -3.0f, -100.0f}) values.push_back(v);
    while (values.size() % 8) values.push_back(0.5f);
    const auto byteOf = [](float x) { return raster::format::unorm8FromFloat(x); };
    size_t passed = 0, refused = 0, wrong = 0;
    for (const float error : {0.0f, 1e-7f, 1e-6f, 1e-5f, 1e-4f, 1e-3f}) {
      for (size_t i = 0; i < values.size(); i += 8) {
        const unsigned lanes = raster::merge::unorm8Within(Plain::load(&values[i]), Plain(error)).bits();
        CHECK(raster::merge::unorm8Within(FastLanes::load(&values[i]), FastLanes(error)).bits() == lanes);
        for (int l = 0; l < 8; ++l) {
          const float v = values[i + l];
          if (!(lanes >> l & 1u)) {
            ++refused;
            continue;
          }
          ++passed;
          // The farthest values within the error either way, and some between.
          const double reach = double(error);
          for (const double t : {-1.0, -0.5, -0.01, 0.01, 0.5, 1.0}) {
            float y = float(double(v) + t * reach);
            while (std::fabs(double(y) - double(v)) > reach) y = std::nextafter(y, v);
            if (byteOf(y) != byteOf(v) && wrong++ == 0) MESSAGE("v = " << v << ", error " << error << ", y = " << y);
          }
        }
      }
    }
    CHECK(wrong == 0);
    CHECK(passed > 100000);   // it passes what it should, and refuses what it must:
    CHECK(refused > 1000);
    for (int k = 0; k < 255; ++k) {   // a value whose product is a tie is refused, even at no error
      const float tie = (float(k) + 0.5f) / 255.0f;
      if (float(tie * 255.0f) == float(k) + 0.5f) CHECK(!raster::merge::unorm8Within(Plain(tie), Plain(0.0f)).bits());
    }
    CHECK(!raster::merge::unorm8Within(Plain(std::numeric_limits<float>::quiet_NaN()), Plain(0.0f)).bits());
    CHECK(!raster::merge::unorm8Within(Plain(0.5f), Plain(std::numeric_limits<float>::infinity())).bits());
    CHECK(!raster::merge::unorm8Within(Plain(0.5f), Plain(std::numeric_limits<float>::quiet_NaN())).bits());
  }

  TEST_CASE("RGBA8 packing: SIMD lanes equal the scalar conversion") {
    const std::vector<float> values = interestingValues();
    for (size_t i = 0; i + 8 <= values.size(); i += 8) {
      float lanes[4][8];
      for (int c = 0; c < 4; ++c)
        for (int l = 0; l < 8; ++l) lanes[c][l] = values[(i + size_t(l) + size_t(c) * 3) % values.size()];
      uint32_t fast[8], plain[8];
      raster::merge::packRgba8(raster::glsl::vec4<FastLanes>(FastLanes::load(lanes[0]), FastLanes::load(lanes[1]),
                                                                    FastLanes::load(lanes[2]), FastLanes::load(lanes[3])),
                                      fast);
      raster::merge::packRgba8(
          raster::glsl::vec4<Plain>(Plain::load(lanes[0]), Plain::load(lanes[1]), Plain::load(lanes[2]), Plain::load(lanes[3])),
          plain);
      CHECK(std::memcmp(fast, plain, sizeof fast) == 0);
    }
  }

  TEST_CASE("RGBA16F writes and ONE/ONE blends: SIMD lanes equal the scalar conversion, in both half methods") {
   for (const raster::HalfMethod method : {raster::HalfMethod::TowardZero, raster::HalfMethod::NearestEven}) {
    raster::MethodSet methods;
    methods.half = method;
    const raster::ScopedMethods scoped(methods);
    const std::vector<float> values = interestingValues();
    std::vector<float> extremes = {65504.0f, 65519.0f, 65520.0f, 70000.0f, -70000.0f, 1e-6f, -1e-7f, 6.1e-5f, 1.0007f};
    std::mt19937 rng(5);
    long compared = 0;
    for (int round = 0; round < 2000; ++round) {
      float lanes[4][8];
      for (auto& channel : lanes)
        for (float& x : channel) x = rng() % 4 == 0 ? extremes[rng() % extremes.size()] * float(rng() % 3) : values[rng() % values.size()] * 9.0f;
      const bool blend = round % 2 == 1;
      std::vector<uint16_t> fast(8 * 4), plain(8 * 4);
      for (size_t i = 0; i < fast.size(); ++i) fast[i] = plain[i] = raster::format::halfFromFloatTowardZero(values[rng() % values.size()] * 70000.0f);
      const size_t texel[8] = {3, 0, 7, 1, 6, 2, 5, 4};
      const unsigned laneMask = unsigned(rng()) & 0xFFu;
      raster::merge::writeHalfTexels(raster::glsl::vec4<FastLanes>(FastLanes::load(lanes[0]), FastLanes::load(lanes[1]),
                                                                          FastLanes::load(lanes[2]), FastLanes::load(lanes[3])),
                                            fast.data(), texel, laneMask, blend);
      raster::merge::writeHalfTexels(raster::glsl::vec4<Plain>(Plain::load(lanes[0]), Plain::load(lanes[1]),
                                                                      Plain::load(lanes[2]), Plain::load(lanes[3])),
                                            plain.data(), texel, laneMask, blend);
      CHECK(fast == plain);
      ++compared;
    }
    CHECK(compared == 2000);
   }
  }

  TEST_CASE("half=rne writes round to nearest even, half=rtz (llvmpipe) truncates") {
    const float values[] = {1.0007f, 65520.0f, 70000.0f, -1.0007f, 1e-6f, 0.333333f};
    for (const raster::HalfMethod method : {raster::HalfMethod::TowardZero, raster::HalfMethod::NearestEven}) {
      raster::MethodSet methods;
      methods.half = method;
      const raster::ScopedMethods scoped(methods);
      for (const float v : values) {
        float lanes[4][8];
        for (auto& channel : lanes)
          for (float& x : channel) x = v;
        std::vector<uint16_t> texels(8 * 4, 0);
        const size_t texel[8] = {0, 1, 2, 3, 4, 5, 6, 7};
        raster::merge::writeHalfTexels(raster::glsl::vec4<FastLanes>(FastLanes::load(lanes[0]), FastLanes::load(lanes[1]),
                                                                     FastLanes::load(lanes[2]), FastLanes::load(lanes[3])),
                                       texels.data(), texel, 0xFFu, false);
        const uint16_t expected = method == raster::HalfMethod::NearestEven ? raster::format::halfFromFloatNearestEven(v)
                                                                            : raster::format::halfFromFloatTowardZero(v);
        CAPTURE(v);
        for (uint16_t h : texels) CHECK(h == expected);
      }
    }
    CHECK(raster::format::halfFromFloatNearestEven(1.0007f) != raster::format::halfFromFloatTowardZero(1.0007f));
  }
#if RASTER_AVX2
  TEST_CASE("whole groups stored or blended a row at a time, alone or as a pair, equal the per-lane writes") {
    using raster::simd::Float8;
    using raster::simd::Float8x2;
    const std::vector<float> values = interestingValues();
    std::mt19937 rng(7);
    for (int round = 0; round < 400; ++round) {
      // A 4x4 block of a 4-texel-wide target: group a on rows 0-1, group b on rows 2-3, lanes
      // in quad order (simd/lane_layout.h), rows swapped on flipped targets.
      const bool flipped = round & 1;
      size_t first[8], second[8];
      for (int i = 0; i < 8; ++i) {
        const int dx = (i / 4) * 2 + (i & 1), dy = flipped ? 1 - ((i >> 1) & 1) : (i >> 1) & 1;
        first[i] = size_t(dy * 4 + dx);
        second[i] = first[i] + 8;
      }
      float lanes[4][16];
      for (auto& channel : lanes)
        for (float& x : channel) x = values[rng() % values.size()] * (round % 3 == 0 ? 70000.0f : 1.0f);
      auto group = [&](int g) {
        return raster::glsl::vec4<Float8>(Float8::load(lanes[0] + 8 * g), Float8::load(lanes[1] + 8 * g),
                                          Float8::load(lanes[2] + 8 * g), Float8::load(lanes[3] + 8 * g));
      };
      auto plainGroup = [&](int g) {
        return raster::glsl::vec4<Plain>(Plain::load(lanes[0] + 8 * g), Plain::load(lanes[1] + 8 * g),
                                         Plain::load(lanes[2] + 8 * g), Plain::load(lanes[3] + 8 * g));
      };
      const raster::glsl::vec4<Float8x2> pair(Float8x2(group(0).x, group(1).x), Float8x2(group(0).y, group(1).y),
                                              Float8x2(group(0).z, group(1).z), Float8x2(group(0).w, group(1).w));

      uint8_t expected8[16 * 4], rows8[16 * 4], pair8[16 * 4];
      for (int g = 0; g < 2; ++g) {
        uint32_t packed[8];
        raster::merge::packRgba8(plainGroup(g), packed);
        for (int i = 0; i < 8; ++i) std::memcpy(expected8 + (g ? second : first)[i] * 4, &packed[i], 4);
      }
      raster::merge::writeRgba8Rows(group(0), rows8, first);
      raster::merge::writeRgba8Rows(group(1), rows8, second);
      raster::merge::writeRgba8RowsPair(pair, pair8, first, second);
      CHECK(std::memcmp(rows8, expected8, sizeof expected8) == 0);
      CHECK(std::memcmp(pair8, expected8, sizeof expected8) == 0);

      std::vector<uint16_t> expected16(16 * 4), rows16(16 * 4), pair16(16 * 4);
      raster::merge::writeHalfTexels(plainGroup(0), expected16.data(), first, 0xFFu, false);
      raster::merge::writeHalfTexels(plainGroup(1), expected16.data(), second, 0xFFu, false);
      raster::merge::writeHalfRows(group(0), rows16.data(), first);
      raster::merge::writeHalfRows(group(1), rows16.data(), second);
      raster::merge::writeHalfRowsPair(pair, pair16.data(), first, second);
      CHECK(rows16 == expected16);
      CHECK(pair16 == expected16);

      // Additive blending onto those texels: each its stored value plus the colour again.
      raster::merge::writeHalfTexels(plainGroup(0), expected16.data(), first, 0xFFu, true);
      raster::merge::writeHalfTexels(plainGroup(1), expected16.data(), second, 0xFFu, true);
      raster::merge::writeHalfRows(group(0), rows16.data(), first, true);
      raster::merge::writeHalfRows(group(1), rows16.data(), second, true);
      raster::merge::writeHalfRowsPair(pair, pair16.data(), first, second, true);
      CHECK(rows16 == expected16);
      CHECK(pair16 == expected16);
    }
  }

#endif
}
