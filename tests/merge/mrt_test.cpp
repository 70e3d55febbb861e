// MRT: one draw writes three colour attachments of different formats (RGBA8, RGBA16F,
// RGBA16F, as the deferred G-buffer) and a 16-bit depth buffer; every attachment equals
// what GL writes, bit for bit, for random perspective triangles.
#include <doctest/doctest.h>

#include <random>
#include <vector>

#include "tests/gl_compare_helpers.h"

TEST_SUITE("raster_vs_gl") {
  TEST_CASE("MRT: one draw writes RGBA8 + RGBA16F + RGBA16F, each equal to GL's") {
    using namespace gltest;
    constexpr int kW = 67, kH = 45;
    std::mt19937 rng(31);
    std::vector<Vertex> vertices;
    for (int t = 0; t < 60 * 3; ++t) {
      const float w = uniform(rng, 0.5f, 3.0f);
      const glm::vec2 window(uniform(rng, -5.0f, kW + 5.0f), uniform(rng, -5.0f, kH + 5.0f));
      vertices.push_back({clipFromWindow(window, uniform(rng, -0.9f, 0.9f), w, kW, kH),
                          glm::vec4(uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f),
                                    uniform(rng, 0.0f, 1.0f))});
    }
    const MeshData mesh = makeMesh(vertices);
    BackendPair backends;
    scenes::ImageData images[2][4];
    Backend* sides[2] = {backends.raster.get(), backends.gl.get()};
    for (int k = 0; k < 2; ++k) {
      Backend& b = *sides[k];
      const scenes::SamplerState nearest{scenes::Filter::Nearest, scenes::Wrap::ClampToEdge, scenes::Wrap::ClampToEdge, false};
      const Handle c0 = b.createTexture({kW, kH, TexelFormat::RGBA8, nearest});
      const Handle c1 = b.createTexture({kW, kH, TexelFormat::RGBA16F, nearest});
      const Handle c2 = b.createTexture({kW, kH, TexelFormat::RGBA16F, nearest});
      const Handle depth = b.createTexture({kW, kH, TexelFormat::Depth16, nearest});
      const Handle fb = b.createFramebuffer({{c0, c1, c2}, depth});
      const Handle program = b.createProgram("test/mrt");
      const Handle m = b.createMesh(mesh);
      b.beginPass(fb, {0, 0, kW, kH}, clearAll());
      b.draw(program, m, DrawState{});
      for (int a = 0; a < 3; ++a) images[k][a] = b.readColor(fb, a);
      images[k][3] = b.readDepth(fb);
    }
    const uint8_t clear[4] = {0, 0, 0, 0};
    const Rgba8Comparison unorm = compareRgba8(images[0][0], images[1][0], clear);
    MESSAGE("RGBA8: " << unorm.coverageDiffs << " coverage and " << unorm.colorDiffs << " colour differences");
    CHECK(unorm.coverageDiffs == 0);
    CHECK(unorm.colorDiffs == 0);
    for (int a = 1; a < 3; ++a) {
      const FloatComparison half = compareFloatBits(images[0][a], images[1][a]);
      MESSAGE("RGBA16F attachment " << a << ": " << half.diffs << " pixels differ " << half.firstDiff);
      CHECK(half.diffs == 0);
    }
    const DepthComparison z = compareDepth(images[0][3], images[1][3]);
    MESSAGE("Z16: " << z.diffs << " texels differ");
    CHECK(z.diffs == 0);
  }
}
