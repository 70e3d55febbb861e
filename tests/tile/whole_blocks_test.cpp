// Whole blocks: in the in-order walk (tile/rasterize_tile.cpp, walkInOrder) a 4x4 block that
// its triangle covers and passes at every pixel is shaded at once as one pair, while the
// lane groups of partly covered or partly hidden blocks wait to be paired. Colours must
// still land in the order the walk makes them: a group left waiting by one triangle is
// written before a later triangle's whole block over the same pixels. Visibility first
// (tile/visible_first.h) shades a block that shows one triangle whole the same way. Held
// against the reference lanes (--scalar: one quad at a time, no pairs, no whole blocks),
// byte for byte.
#include <doctest/doctest.h>

#include <random>
#include <vector>

#include "tests/gl_compare_helpers.h"

namespace {

constexpr int kSize = 64;   // one tile

// A triangle over window positions a, b, c at NDC depth z, in one colour.
std::vector<gltest::Vertex> triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, float z, glm::vec4 color) {
  return {{gltest::clipFromWindow(a, z, 1.0f, kSize, kSize), color},
          {gltest::clipFromWindow(b, z, 1.0f, kSize, kSize), color},
          {gltest::clipFromWindow(c, z, 1.0f, kSize, kSize), color}};
}

// Each mesh drawn in order, one draw each, into a cleared RGBA8 + Depth24 target.
gltest::Rendered render(int threads, bool scalar, const std::vector<std::vector<gltest::Vertex>>& meshes) {
  auto b = scenes::makeRasterBackend(threads, scalar);
  scenes::FramebufferDesc desc;
  desc.colorTextures = {b->createTexture({kSize, kSize, scenes::TexelFormat::RGBA8, {}})};
  desc.depthTexture = b->createTexture({kSize, kSize, scenes::TexelFormat::Depth24, {}});
  const scenes::Handle fb = b->createFramebuffer(desc);
  const scenes::Handle program = b->createProgram("test/passthrough");
  std::vector<scenes::Handle> handles;
  for (const auto& mesh : meshes) handles.push_back(b->createMesh(gltest::makeMesh(mesh)));
  b->beginPass(fb, {0, 0, kSize, kSize}, gltest::clearAll());
  for (scenes::Handle mesh : handles) b->draw(program, mesh, scenes::DrawState{});
  b->finish();
  gltest::Rendered result;
  result.color = b->readColor(fb);
  result.depth = b->readDepth(fb);
  return result;
}

void checkAgainstReference(const std::vector<std::vector<gltest::Vertex>>& meshes) {
  const gltest::Rendered reference = render(1, true, meshes);
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    const gltest::Rendered fast = render(threads, false, meshes);
    CHECK(fast.color->rgba8 == reference.color->rgba8);
    CHECK(fast.depth->depth == reference.depth->depth);
  }
}

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("a group left waiting is written before a later triangle's whole block over it") {
    // The far triangle covers four pixels of the first two rows of the block at the origin
    // (x / 4 + y / 2 < 1): one lane group, which waits for a partner. The near one (inside
    // the viewport, so not clipped into a fan) starts its walk at that block, which it
    // covers whole and passes everywhere: shaded at once, it must land after the waiting
    // group, and no pixel may keep the far colour.
    const glm::vec4 far(1.0f, 0.0f, 0.0f, 1.0f), nearColor(0.0f, 0.5f, 1.0f, 1.0f);
    const std::vector<std::vector<gltest::Vertex>> meshes = {
        triangle({0.0f, 0.0f}, {4.0f, 0.0f}, {0.0f, 2.0f}, 0.5f, far),
        triangle({0.0f, 0.0f}, {64.0f, 0.0f}, {0.0f, 64.0f}, -0.5f, nearColor)};
    checkAgainstReference(meshes);
    const gltest::Rendered fast = render(1, false, meshes);
    int farPixels = 0;
    for (size_t i = 0; i < fast.color->rgba8.size(); i += 4) farPixels += fast.color->rgba8[i] == 255;
    CHECK(farPixels == 0);
  }

  TEST_CASE("overlapping draws at random depths: whole blocks in order and visibility first match the reference") {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 48; ++trial) {
      CAPTURE(trial);
      std::vector<std::vector<gltest::Vertex>> meshes;
      // Up to 7 triangles: the tile is walked in order; 16 to 39: visibility first, where a
      // block that shows one triangle whole is shaded as one pair too.
      const int draws = trial < 40 ? 2 + trial % 6 : 16 + 3 * (trial - 40);
      for (int d = 0; d < draws; ++d) {
        const auto point = [&] { return glm::vec2(gltest::uniform(rng, -16.0f, 80.0f), gltest::uniform(rng, -16.0f, 80.0f)); };
        const glm::vec4 color(gltest::uniform(rng, 0.0f, 1.0f), gltest::uniform(rng, 0.0f, 1.0f), gltest::uniform(rng, 0.0f, 1.0f), 1.0f);
        meshes.push_back(triangle(point(), point(), point(), gltest::uniform(rng, -0.9f, 0.9f), color));
      }
      checkAgainstReference(meshes);
    }
  }
}
