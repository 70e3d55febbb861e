// What the sampler tests share: random textures, where a lookup lands, and a pass that
// draws one lookup per grid cell into a float target.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <random>

#include "raster/texture/format.h"
#include "raster/texture/texture.h"
#include "tests/gl_compare_helpers.h"

namespace gltest {

// A SIMD lookup's channel against the scalar one's: the same bits, or NaN against NaN (which
// NaN's sign survives an fma of NaNs may differ).
inline bool sameLookup(float got, float ref) { return bitsOf(got) == bitsOf(ref) || (std::isnan(got) && std::isnan(ref)); }

// A w x h texture of random texels: any RGBA8 bytes, or halves or floats of values in [-8, 8]. A grey
// one has r = g = b and alpha 255 at every texel, and so also the samplers' one-byte copy.
inline raster::Texture randomTexture(std::mt19937& rng, int w, int h, raster::TexelFormat format, bool grey = false) {
  raster::Texture tex(w, h, format);
  for (uint8_t& b : tex.rgba8) b = uint8_t(rng());
  for (uint16_t& v : tex.half) v = raster::format::halfFromFloatTowardZero(uniform(rng, -8.0f, 8.0f));
  for (float& v : tex.f32) v = uniform(rng, -8.0f, 8.0f);
  for (uint32_t& code : tex.depth) code = uint32_t(rng()) & (format == raster::TexelFormat::Depth24 ? 0xFFFFFFu : 0xFFFFu);
  if (grey) {
    for (size_t i = 0; i < tex.rgba8.size(); i += 4) {
      tex.rgba8[i + 1] = tex.rgba8[i + 2] = tex.rgba8[i];
      tex.rgba8[i + 3] = 255;
    }
    REQUIRE(raster::makeGreyCopy(tex));
  }
  return tex;
}

// A lookup coordinate: random, far outside, or on a texel centre / edge of the texture.
inline float lookupCoordinate(std::mt19937& rng, int size) {
  switch (rng() % 5) {
    case 0: return uniform(rng, -0.2f, 1.2f);
    case 1: return uniform(rng, -40.0f, 40.0f);
    case 2: return (float(int(rng() % unsigned(size))) + 0.5f) / float(size);        // texel centre
    case 3: return float(int(rng() % unsigned(size + 1))) / float(size);             // texel edge
    default: return (float(int(rng() % unsigned(8 * size))) + 0.5f) / float(8 * size);  // 1/8 texel steps
  }
}

// A coordinate for the vector-against-scalar lookup cases: one lane in eight a special value
// (zeros of both signs, texel edges, past any int, NaN, infinities), the rest in [-3, 3].
inline float laneCoordinate(std::mt19937& rng) {
  static const float specials[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 1e30f, -1e30f, 3e9f, std::nanf(""),
                                   std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
  return rng() % 8 == 0 ? specials[rng() % std::size(specials)] : uniform(rng, -3.0f, 3.0f);
}

// Draws test/color_lookup over `mesh` (a grid whose cells carry lookup coordinates) into a
// size x size RGBA32F target, sampling `texture`, and reads the target back.
inline ImageData drawLookups(Backend& b, Handle texture, const MeshData& mesh, int size) {
  scenes::TextureDesc targetDesc;
  targetDesc.width = targetDesc.height = size;
  targetDesc.format = TexelFormat::RGBA32F;
  const Handle target = b.createTexture(targetDesc);
  const Handle fb = b.createFramebuffer({{target}, 0});
  const Handle program = b.createProgram("test/color_lookup");
  const Handle meshHandle = b.createMesh(mesh);
  b.beginPass(fb, {0, 0, size, size}, clearAll());
  b.bindTexture(0, texture);
  b.setUniform(program, "tex", 0);
  DrawState state;
  state.depthTest = false;
  b.draw(program, meshHandle, state);
  return b.readColor(fb);
}

}  // namespace gltest
