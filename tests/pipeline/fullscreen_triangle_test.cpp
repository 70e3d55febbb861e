// The fullscreen triangle of post passes, (-1, -1), (3, -1), (-1, 3) at z = 0, w = 1, as a
// post.vert draws it with glDrawArrays(GL_TRIANGLES, 0, 3): two of its vertices lie outside
// the view volume, so it is clipped (or not: llvmpipe's guard band), and a post pass depends
// on two things the clipping must keep, at any size:
//   - every pixel is shaded exactly once (a clipped polygon drawn as a fan must not shade
//     its inner edges twice, nor miss a pixel): ONE/ONE blending of 1/255 counts it;
//   - the texture coordinate it interpolates, aPos * 0.5 + 0.5, is llvmpipe's to the bit, and
//     a NEAREST lookup of a target of the same size at it reads the pixel's own texel,
//     floor(uv * size) = pixel, which is how a deferred pass reads its G-buffer.
// Checked at odd sizes from 1x1 to long thin targets, against llvmpipe, SIMD and scalar lanes.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "tests/gl_compare_helpers.h"

namespace {

using namespace gltest;

// The post passes' triangle; the attribute is the fragUV post.vert computes at each vertex
// (aPos * 0.5 + 0.5: exact in float), as a colour the passthrough program interpolates.
MeshData postTriangle() {
  return makeMesh({{glm::vec4(-1.0f, -1.0f, 0.0f, 1.0f), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)},
                   {glm::vec4(3.0f, -1.0f, 0.0f, 1.0f), glm::vec4(2.0f, 0.0f, 0.0f, 1.0f)},
                   {glm::vec4(-1.0f, 3.0f, 0.0f, 1.0f), glm::vec4(0.0f, 2.0f, 0.0f, 1.0f)}});
}

struct Drawn {
  ImageData uv;      // RGBA32F, the interpolated fragUV
  ImageData counts;  // RGBA8, red = how many times each pixel was shaded
};

Drawn drawPostTriangle(Backend& b, int w, int h) {
  const Handle program = b.createProgram("test/passthrough");
  const Handle mesh = b.createMesh(postTriangle());
  DrawState state;
  state.depthTest = false;
  const Handle uvTarget = b.createTexture({w, h, TexelFormat::RGBA32F, {}});
  const Handle uvFb = b.createFramebuffer({{uvTarget}, 0});
  b.beginPass(uvFb, {0, 0, w, h}, clearAll());
  b.draw(program, mesh, state);
  // The count pass: the same triangle with colour 1/255, added to a clear of 0.
  std::vector<Vertex> counting;
  for (const glm::vec4 p : {glm::vec4(-1, -1, 0, 1), glm::vec4(3, -1, 0, 1), glm::vec4(-1, 3, 0, 1)})
    counting.push_back({p, glm::vec4(1.0f / 255.0f, 0.0f, 0.0f, 0.0f)});
  const Handle countTarget = b.createTexture({w, h, TexelFormat::RGBA8, {}});
  const Handle countFb = b.createFramebuffer({{countTarget}, 0});
  b.beginPass(countFb, {0, 0, w, h}, clearAll());
  DrawState additive = state;
  additive.blendAdditive = true;
  b.draw(program, b.createMesh(makeMesh(counting)), additive);
  b.finish();
  return {b.readColor(uvFb), b.readColor(countFb)};
}

}  // namespace

TEST_SUITE("raster_vs_gl") {
  TEST_CASE("the post passes' fullscreen triangle: every pixel once, llvmpipe's texture coordinates, each pixel's own texel") {
    BackendPair backends;
    const std::unique_ptr<Backend> scalar = scenes::makeRasterBackend(2, /*scalarOnly=*/true);
    const int sizes[][2] = {{1, 1}, {2, 1}, {1, 3}, {7, 3}, {37, 23}, {333, 197}, {641, 2}, {1, 479}, {1023, 769}};
    for (const auto& size : sizes) {
      const int w = size[0], h = size[1];
      const std::string where = std::to_string(w) + "x" + std::to_string(h);
      CAPTURE(where);
      const Drawn gl = drawPostTriangle(*backends.gl, w, h);
      for (Backend* side : {backends.raster.get(), scalar.get()}) {
        CAPTURE(side->name());
        const Drawn ours = drawPostTriangle(*side, w, h);
        const FloatComparison uv = compareFloatBits(ours.uv, gl.uv);
        CHECK_MESSAGE(uv.diffs == 0, uv.firstDiff);
        CHECK(ours.counts.rgba8 == gl.counts.rgba8);
      }
      // What both must hold (GL's image checked, the others equal it): each pixel shaded once,
      // and its uv inside its own texel (read-back rows are top first; GL's t = 0 is the bottom).
      int notOnce = 0, otherTexel = 0;
      for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
          const size_t p = size_t(row) * size_t(w) + size_t(x);
          notOnce += gl.counts.rgba8[p * 4] != 1;
          const float u = gl.uv.floats[p * 4], v = gl.uv.floats[p * 4 + 1];
          otherTexel += int(std::floor(u * float(w))) != x || int(std::floor(v * float(h))) != h - 1 - row;
        }
      CHECK(notOnce == 0);
      CHECK(otherTexel == 0);
    }
  }
}
