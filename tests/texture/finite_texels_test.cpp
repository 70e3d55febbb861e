// holdsNonFiniteTexels (raster/texture/finite_texels.h): what shading=2x2-smooth asks of a
// pass's sources before it shades the pass coarse.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <limits>

#include "raster/texture/finite_texels.h"

TEST_SUITE("format") {
  TEST_CASE("finite texels: a NaN or an infinity in any channel of a half or float texture, anywhere") {
    raster::Texture half(7, 5, raster::TexelFormat::RGBA16F);
    CHECK(!raster::holdsNonFiniteTexels(half));
    half.half.back() = 0x7BFF;   // 65504, the largest finite half
    CHECK(!raster::holdsNonFiniteTexels(half));
    for (const uint16_t bits : {uint16_t(0x7C00), uint16_t(0xFC00), uint16_t(0x7E00), uint16_t(0xFE01)}) {
      for (const size_t at : {size_t(0), size_t(13), half.half.size() - 1}) {
        raster::Texture t = half;
        t.half[at] = bits;
        CAPTURE(bits);
        CAPTURE(at);
        CHECK(raster::holdsNonFiniteTexels(t));
      }
    }
    raster::Texture wide(3, 3, raster::TexelFormat::RGBA32F);
    wide.f32[5] = std::numeric_limits<float>::max();
    CHECK(!raster::holdsNonFiniteTexels(wide));
    wide.f32[35] = -std::numeric_limits<float>::infinity();
    CHECK(raster::holdsNonFiniteTexels(wide));
    wide.f32[35] = std::numeric_limits<float>::quiet_NaN();
    CHECK(raster::holdsNonFiniteTexels(wide));
    // Formats that cannot hold one.
    raster::Texture bytes(4, 4, raster::TexelFormat::RGBA8);
    std::memset(bytes.rgba8.data(), 0xFF, bytes.rgba8.size());
    CHECK(!raster::holdsNonFiniteTexels(bytes));
    raster::Texture depth(4, 4, raster::TexelFormat::Depth24);
    CHECK(!raster::holdsNonFiniteTexels(depth));
  }
}
