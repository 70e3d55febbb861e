// The early depth test's SIMD forms equal the scalar reference on every class of input
// (tile/depth_test.h and its AVX2 sibling).
#include <doctest/doctest.h>

#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/tile/depth_test.h"

namespace {

using raster::simd::FastLanes;
using Plain = raster::simd::Lanes<8>;

}  // namespace

TEST_SUITE("format") {
  TEST_CASE("depth quantization: SIMD lanes equal the scalar conversion") {
    std::vector<float> values;
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 80000; ++i) values.push_back(unit(rng));
    for (uint32_t k = 0; k < 70000; k += 7) values.push_back((float(k) + 0.5f) / 65535.0f);
    values.insert(values.end(), {0.0f, 1.0f, 0.5f, 1.0f / 16777215.0f});
    while (values.size() % 8) values.push_back(0.25f);
    for (raster::TexelFormat format : {raster::TexelFormat::Depth24, raster::TexelFormat::Depth16}) {
      for (size_t i = 0; i < values.size(); i += 8) {
        uint32_t fast[8], plain[8];
        raster::depthCodes(FastLanes::load(&values[i]), format, fast);
        raster::depthCodes(Plain::load(&values[i]), format, plain);
        CHECK(std::memcmp(fast, plain, sizeof fast) == 0);
      }
    }
  }

#if RASTER_AVX2
  TEST_CASE("depth test of a lane group: whole-row and masked-edge forms equal the per-lane test") {
    std::mt19937 rng(6);
    for (int round = 0; round < 4000; ++round) {
      const bool flipped = round & 1, lessEqual = round & 2, write = round & 4, wholeRows = round & 8;
      // Row position of each lane (the inverse of depthTestRows' quad -> row permutation).
      const int rowOfLane[2][8] = {{0, 1, 4, 5, 2, 3, 6, 7}, {4, 5, 0, 1, 6, 7, 2, 3}};
      uint32_t codes[8], rows[8];
      for (int i = 0; i < 8; ++i) {
        codes[i] = rng() % 6;   // few values: ties between code and stored are common
        rows[i] = rng() % 6;
      }
      uint32_t expected[8];
      std::memcpy(expected, rows, sizeof rows);
      size_t texel[8];
      for (int i = 0; i < 8; ++i) texel[i] = size_t(rowOfLane[flipped][i]);
      const unsigned laneMask = unsigned(rng()) & 0xFFu;
      raster::RasterState state;
      state.depthFunc = lessEqual ? raster::DepthFunc::Lequal : raster::DepthFunc::Less;
      state.depthWrite = write;
      const unsigned expectedPass = raster::depthTest<8>(codes, expected, texel, laneMask, lessEqual, write);
      const unsigned pass = raster::depthTestRows(codes, raster::GroupRows{rows, rows + 4, wholeRows, flipped}, laneMask, state);
      CHECK(pass == expectedPass);
      CHECK(std::memcmp(rows, expected, sizeof rows) == 0);
    }
  }
#endif
}
