// A depth texture (Depth24, Depth16) read through a plain sampler2D, against llvmpipe, bit for
// bit: a deferred renderer reconstructs positions from its G-buffer's depth that way
// (`texture(gDepth, uv).r`, no compare mode). GL 3.3 core makes such a texel (d, 0, 0, 1),
// d the unorm code as a float; llvmpipe computes d as float(code) * float(1 / (2^bits - 1))
// (lp_build_unsigned_norm_to_float), which texture/sample_color.cpp and its AVX2 sibling
// follow. Each case renders the depth target first, with random triangles over a cleared
// background (both backends' codes compared), then samples it in a second pass:
//   - at every texel centre of an odd-sized texture, so each lookup's texel is known and
//     the value it returns can be checked against the code read back;
//   - at random coordinates, far outside [0, 1], on texel edges, under both wrap modes
//     on each axis, compared with llvmpipe's bits;
// with SIMD lanes and the scalar lanes `--scalar` uses; and the 8- and 16-lane lookups
// against the scalar reference on random codes and special coordinates (NaN, inf, huge).
#include <doctest/doctest.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "raster/texture/sampler.h"
#include "tests/gl_compare_helpers.h"
#include "tests/texture/lookup_test_helpers.h"

namespace {

using namespace gltest;
using scenes::Filter;
using scenes::Wrap;

// 60 random triangles at random depths, some of them perspective, over a w x h target: the
// codes they leave cover the range, and the clear (0.6) stays around them.
MeshData depthTriangles(std::mt19937& rng, int w, int h) {
  std::vector<Vertex> vertices;
  for (int i = 0; i < 60; ++i) {
    const glm::vec2 c(uniform(rng, 0.0f, float(w)), uniform(rng, 0.0f, float(h)));
    const float size = uniform(rng, 1.0f, float(std::max(w, h)) * 0.6f);
    for (int v = 0; v < 3; ++v) {
      const glm::vec2 p = c + glm::vec2(uniform(rng, -size, size), uniform(rng, -size, size));
      vertices.push_back({clipFromWindow(p, uniform(rng, -0.99f, 0.99f), uniform(rng, 0.5f, 2.5f), w, h), randomOpaqueColor(rng)});
    }
  }
  return makeMesh(vertices);
}

// Draws test/color_lookup over `mesh` into a w x h RGBA32F target, sampling `texture`
// (drawLookups of lookup_test_helpers.h, for a target that is not square).
ImageData drawLookupsInto(Backend& b, Handle texture, const MeshData& mesh, int w, int h) {
  const Handle target = b.createTexture({w, h, TexelFormat::RGBA32F, {}});
  const Handle fb = b.createFramebuffer({{target}, 0});
  const Handle program = b.createProgram("test/color_lookup");
  b.beginPass(fb, {0, 0, w, h}, clearAll());
  b.bindTexture(0, texture);
  b.setUniform(program, "tex", 0);
  DrawState state;
  state.depthTest = false;
  b.draw(program, b.createMesh(mesh), state);
  return b.readColor(fb);
}

struct DepthLookups {
  ImageData codes;     // the depth target's codes, top row first
  ImageData centres;   // one lookup per texel centre, w x h, RGBA32F
  ImageData anywhere;  // lookups at random and far-out coordinates, 96 x 96, RGBA32F
};

// Renders `triangles` into a w x h depth texture of `format` with `sampler`, then samples it
// at every texel centre and over `lookups`.
DepthLookups renderAndSample(Backend& b, int w, int h, TexelFormat format, const scenes::SamplerState& sampler,
                             const MeshData& triangles, const MeshData& lookups) {
  const Handle depth = b.createTexture({w, h, format, sampler});
  const Handle fb = b.createFramebuffer({{}, depth});
  ClearOp clear;
  clear.depth = true;
  clear.depthValue = 0.6f;
  b.beginPass(fb, {0, 0, w, h}, clear);
  b.draw(b.createProgram("test/passthrough"), b.createMesh(triangles), DrawState{});
  b.finish();
  DepthLookups out;
  out.codes = b.readDepth(fb);
  // Cell (column, rowFromTop) samples texel (column, h - 1 - rowFromTop): image pixel
  // (column, rowFromTop) of the read-back codes (texture row 0 is the bottom row).
  const MeshData centres = gridMesh(w, h, 1, [&](int column, int rowFromTop) {
    GridCell cell;
    cell.attribute = glm::vec4((float(column) + 0.5f) / float(w), (float(h - 1 - rowFromTop) + 0.5f) / float(h), 0.0f, 1.0f);
    return cell;
  });
  out.centres = drawLookupsInto(b, depth, centres, w, h);
  out.anywhere = drawLookupsInto(b, depth, lookups, 96, 96);
  return out;
}

void checkDepthThroughSampler2D(int w, int h, TexelFormat format, Wrap wrapS, Wrap wrapT, unsigned seed) {
  std::mt19937 rng(seed);
  const MeshData triangles = depthTriangles(rng, w, h);
  const MeshData lookups = gridMesh(96, 96, 2, [&](int, int) {
    GridCell cell;
    cell.attribute = glm::vec4(lookupCoordinate(rng, w), lookupCoordinate(rng, h), 0.0f, 1.0f);
    return cell;
  });
  const scenes::SamplerState sampler{Filter::Nearest, wrapS, wrapT, false};
  BackendPair backends;
  const std::unique_ptr<Backend> scalar = scenes::makeRasterBackend(2, /*scalarOnly=*/true);
  const DepthLookups gl = renderAndSample(*backends.gl, w, h, format, sampler, triangles, lookups);
  const DepthLookups simd = renderAndSample(*backends.raster, w, h, format, sampler, triangles, lookups);
  const DepthLookups plain = renderAndSample(*scalar, w, h, format, sampler, triangles, lookups);

  const int bits = format == TexelFormat::Depth24 ? 24 : 16;
  const std::string name = std::to_string(w) + "x" + std::to_string(h) + (bits == 24 ? " Depth24" : " Depth16") + " wrap " +
                           (wrapS == Wrap::Repeat ? "REPEAT" : "CLAMP") + "/" + (wrapT == Wrap::Repeat ? "REPEAT" : "CLAMP");
  CAPTURE(name);
  for (const DepthLookups* side : {&simd, &plain}) {
    const DepthComparison codes = compareDepth(side->codes, gl.codes);
    CHECK_MESSAGE(codes.diffs == 0, codes.firstDiff);
    const FloatComparison centres = compareFloatBits(side->centres, gl.centres);
    CHECK_MESSAGE(centres.diffs == 0, centres.firstDiff);
    const FloatComparison anywhere = compareFloatBits(side->anywhere, gl.anywhere);
    CHECK_MESSAGE(anywhere.diffs == 0, anywhere.firstDiff);
  }

  // What GL returns at a texel centre: (float(code) * float(1 / (2^bits - 1)), 0, 0, 1), the
  // code being the one read back there. Some texels hold the clear, some a triangle.
  const float scale = float(1.0 / double((1u << bits) - 1u));
  int wrong = 0, cleared = 0;
  const uint32_t clearCode = uint32_t(std::lround(0.6 * double((1u << bits) - 1u)));
  for (size_t p = 0; p < gl.codes.depth.size(); ++p) {
    const float* rgba = &gl.centres.floats[p * 4];
    const float expected = float(gl.codes.depth[p]) * scale;
    wrong += bitsOf(rgba[0]) != bitsOf(expected) || rgba[1] != 0.0f || rgba[2] != 0.0f || rgba[3] != 1.0f;
    cleared += gl.codes.depth[p] == clearCode;
  }
  MESSAGE(name << ": " << cleared << " of " << w * h << " texels hold the clear; " << wrong << " texel-centre lookups are not (code / (2^bits - 1), 0, 0, 1)");
  CHECK(wrong == 0);
  if (w * h >= 16) {   // the triangles left both kinds of texel to look up
    CHECK(cleared > 0);
    CHECK(cleared < w * h);
  }
}

}  // namespace

TEST_SUITE("texture") {
  TEST_CASE("a depth texture through sampler2D, NEAREST: Depth24 and Depth16 at odd sizes, every wrap, SIMD and scalar lanes equal llvmpipe") {
    checkDepthThroughSampler2D(37, 23, TexelFormat::Depth24, Wrap::ClampToEdge, Wrap::ClampToEdge, 501);
    checkDepthThroughSampler2D(37, 23, TexelFormat::Depth16, Wrap::ClampToEdge, Wrap::ClampToEdge, 502);
    checkDepthThroughSampler2D(37, 23, TexelFormat::Depth24, Wrap::Repeat, Wrap::ClampToEdge, 503);
    checkDepthThroughSampler2D(13, 41, TexelFormat::Depth16, Wrap::ClampToEdge, Wrap::Repeat, 504);
    checkDepthThroughSampler2D(1, 1, TexelFormat::Depth24, Wrap::Repeat, Wrap::Repeat, 505);
    checkDepthThroughSampler2D(97, 3, TexelFormat::Depth24, Wrap::Repeat, Wrap::Repeat, 506);
  }

#if RASTER_AVX2
  TEST_CASE("depth through sampler2D: the 8- and 16-lane lookups equal the scalar reference") {
    std::mt19937 rng(507);
    long mismatches = 0, lookups = 0;
    for (const raster::TexelFormat format : {raster::TexelFormat::Depth24, raster::TexelFormat::Depth16}) {
      for (const auto& [w, h] : {std::pair{37, 23}, std::pair{1, 1}, std::pair{13, 7}, std::pair{3, 1001}}) {
        raster::Texture tex(w, h, format);
        for (uint32_t& code : tex.depth) code = uint32_t(rng()) >> (32 - tex.depthBits());
        for (raster::Wrap ws : {raster::Wrap::Repeat, raster::Wrap::ClampToEdge})
          for (raster::Wrap wt : {raster::Wrap::Repeat, raster::Wrap::ClampToEdge}) {
            tex.sampler = {raster::Filter::Nearest, ws, wt, false};
            for (int round = 0; round < 200; ++round) {
              alignas(64) float s16[16], t16[16];
              for (int i = 0; i < 16; ++i) {
                s16[i] = laneCoordinate(rng);
                t16[i] = laneCoordinate(rng);
              }
              using raster::simd::Float8;
              Float8 out[4];
              raster::sampling::sampleColor8(tex, Float8::load(s16), Float8::load(t16), out);
              // And through the ports' entry point for paired groups (sampler_avx2.h).
              const raster::simd::Float8x2 s = raster::simd::Float8x2::load(s16), t = raster::simd::Float8x2::load(t16);
              const auto viaPort = raster::sampling::lookupColor(tex, raster::glsl::vec2<raster::simd::Float8x2>{s, t});
              const raster::simd::Float8x2 port[4] = {viaPort.x, viaPort.y, viaPort.z, viaPort.w};
              for (int i = 0; i < 16; ++i) {
                float ref[4];
                raster::sampling::sampleColor(tex, s16[i], t16[i], ref);
                for (int c = 0; c < 4; ++c) {
                  const float single = i < 8 ? out[c][i] : ref[c];
                  for (const float got : {single, float(port[c][i])}) {
                    if (bitsOf(got) == bitsOf(ref[c])) continue;
                    if (++mismatches <= 3)
                      MESSAGE("mismatch: " << w << "x" << h << " bits " << tex.depthBits() << " at (" << s16[i] << ", " << t16[i]
                                           << ") channel " << c << ": SIMD " << got << " scalar " << ref[c]);
                  }
                }
                ++lookups;
              }
            }
          }
      }
    }
    MESSAGE(lookups << " lookups, " << mismatches << " channel mismatches");
    CHECK(lookups > 0);
    CHECK(mismatches == 0);
  }
#endif
}
