// Tile clears that leave out what the first triangle overwrites (tile/tile_clear.h): the
// proof that a triangle passes the depth test everywhere is sound, and a target cleared
// that way holds the bytes of a clear done first, whatever the target held before (with
// colour, the covering triangle is then shaded by the covered-tile path on the tiles of
// whole blocks, and walked on the partial ones).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "raster/texture/format.h"
#include "raster/tile/depth_test.h"
#include "raster/tile/tile_clear.h"
#include "tests/gl_compare_helpers.h"

namespace {

using raster::FastLanes;

// Whether the pipeline's own z arithmetic passes the test at every pixel of rect.
bool everyPixelPasses(const raster::SetupTriangle& tri, const raster::RasterState& state, raster::TexelFormat format,
                      uint32_t stored, const raster::TileBounds& rect) {
  for (int y = rect.y0; y <= rect.y1; ++y) {
    for (int x = rect.x0; x <= rect.x1; x += FastLanes::kCount) {
      alignas(64) float columns[FastLanes::kCount];
      for (int i = 0; i < FastLanes::kCount; ++i) columns[i] = float(x + i);
      uint32_t codes[FastLanes::kCount];
      raster::depthCodes(raster::clampDepth(raster::fragmentDepth(tri, FastLanes::load(columns), FastLanes(float(y)))), format, codes);
      for (int i = 0; i < FastLanes::kCount && x + i <= rect.x1; ++i) {
        const bool pass = state.depthFunc == raster::DepthFunc::Lequal ? codes[i] <= stored : codes[i] < stored;
        if (!pass) return false;
      }
    }
  }
  return true;
}

// A triangle with only a z plane and an offset (the proof reads nothing else).
raster::SetupTriangle zOnly(float a0, float dadx, float dady, float offset) {
  raster::SetupTriangle tri{};
  tri.z = {a0, dadx, dady};
  tri.depthOffset = offset;
  return tri;
}

// A triangle covering the whole viewport at NDC depth z, with a colour.
gltest::Vertex corner(glm::vec2 window, float z, int w, int h) {
  return {gltest::clipFromWindow(window, z, 1.0f, w, h), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f)};
}
// `slope`: how much z rises from the first corner to the second and falls to the third, so
// that each pixel of a row gets its own code (0: one depth everywhere).
std::vector<gltest::Vertex> fullscreen(float z, int w, int h, float slope = 0.0f) {
  return {corner({-8.0f, -8.0f}, z, w, h), corner({3.0f * float(w), -8.0f}, z + slope, w, h),
          corner({-8.0f, 3.0f * float(h)}, z - 0.5f * slope, w, h)};
}

// Random triangles over the target, at random depths and colours.
std::vector<gltest::Vertex> scattered(std::mt19937& rng, int count, int w, int h) {
  std::vector<gltest::Vertex> vertices;
  for (int i = 0; i < 3 * count; ++i)
    vertices.push_back({gltest::clipFromWindow({gltest::uniform(rng, -4.0f, float(w) + 4.0f), gltest::uniform(rng, -4.0f, float(h) + 4.0f)},
                                               gltest::uniform(rng, -0.95f, 0.95f), gltest::uniform(rng, 0.5f, 2.0f), w, h),
                        glm::vec4(gltest::uniform(rng, 0.0f, 1.0f), gltest::uniform(rng, 0.0f, 1.0f), gltest::uniform(rng, 0.0f, 1.0f), 1.0f)});
  return vertices;
}

struct Frame {
  std::vector<gltest::Vertex> vertices;   // drawn in this order
  scenes::DrawState state;
};

// Two frames into one target: the first leaves texels behind, the second clears and draws.
// eager: the second frame's clear in a pass of its own, before a pass that only draws.
gltest::Rendered twoFrames(scenes::Backend& b, bool withColor, bool eager, const Frame& first, const Frame& second, int w, int h) {
  scenes::FramebufferDesc desc;
  if (withColor) desc.colorTextures = {b.createTexture({w, h, scenes::TexelFormat::RGBA8, {}})};
  desc.depthTexture = b.createTexture({w, h, scenes::TexelFormat::Depth24, {}});
  const scenes::Handle fb = b.createFramebuffer(desc);
  const scenes::Handle program = b.createProgram("test/passthrough");
  scenes::ClearOp clear = gltest::clearAll();
  clear.color = withColor;
  clear.colorValue = glm::vec4(0.1f, 0.2f, 0.3f, 0.4f);
  b.beginPass(fb, {0, 0, w, h}, clear);
  b.draw(program, b.createMesh(gltest::makeMesh(first.vertices)), first.state);
  const scenes::Handle mesh = b.createMesh(gltest::makeMesh(second.vertices));
  b.beginPass(fb, {0, 0, w, h}, clear);
  if (eager) b.beginPass(fb, {0, 0, w, h}, scenes::ClearOp{});
  b.draw(program, mesh, second.state);
  b.finish();
  gltest::Rendered result;
  if (withColor) result.color = b.readColor(fb);
  result.depth = b.readDepth(fb);
  return result;
}

}  // namespace

TEST_SUITE("clears") {
  TEST_CASE("a triangle proven to pass everywhere passes at every pixel, by the pipeline's own arithmetic") {
    std::mt19937 rng(26);
    const raster::TileBounds rect{64, 128, 127, 191};
    int proven = 0, cases = 0;
    for (raster::TexelFormat format : {raster::TexelFormat::Depth24, raster::TexelFormat::Depth16}) {
      const int bits = format == raster::TexelFormat::Depth24 ? 24 : 16;
      for (raster::DepthFunc func : {raster::DepthFunc::Less, raster::DepthFunc::Lequal}) {
        raster::RasterState state;
        state.depthFunc = func;
        for (int i = 0; i < 3000; ++i, ++cases) {
          // Planes whose largest value lands within a few codes of the stored value.
          const float clearZ = i % 3 == 0 ? 1.0f : gltest::uniform(rng, 0.0f, 1.0f);
          const uint32_t stored = raster::format::depthClearCode(clearZ, bits);
          const float slope = gltest::uniform(rng, -1e-4f, 1e-4f), slopeY = gltest::uniform(rng, -1e-4f, 1e-4f);
          const float top = clearZ - float(int(rng() % 8)) / float((1u << bits) - 1) + gltest::uniform(rng, -3e-6f, 3e-6f);
          const float a0 = top - std::max(slope * 64.0f, slope * 127.0f) - std::max(slopeY * 128.0f, slopeY * 191.0f);
          const raster::SetupTriangle tri = zOnly(a0, slope, slopeY, i % 5 == 0 ? 1e-6f : 0.0f);
          if (!raster::depthTestPassesEverywhere(tri, state, format, stored, rect)) continue;
          ++proven;
          INFO("case " << i << " z0 " << tri.z.a0 << " dzdx " << slope << " dzdy " << slopeY);
          REQUIRE(everyPixelPasses(tri, state, format, stored, rect));
        }
      }
    }
    MESSAGE(proven << " of " << cases << " triangles proven to pass");
    CHECK(proven > cases / 10);   // the proof is not vacuous
    CHECK(proven < cases);
  }

  TEST_CASE("far from the cleared depth the proof holds; at it, or with NaN planes, it does not") {
    raster::RasterState less;
    const raster::TileBounds rect{0, 0, 63, 63};
    const uint32_t cleared = raster::format::depthClearCode(1.0f, 24);
    CHECK(raster::depthTestPassesEverywhere(zOnly(0.5f, 1e-3f, -1e-3f, 0.0f), less, raster::TexelFormat::Depth24, cleared, rect));
    CHECK_FALSE(raster::depthTestPassesEverywhere(zOnly(1.0f, 0.0f, 0.0f, 0.0f), less, raster::TexelFormat::Depth24, cleared, rect));
    CHECK_FALSE(raster::depthTestPassesEverywhere(zOnly(0.5f, 1e-2f, 0.0f, 0.0f), less, raster::TexelFormat::Depth24, cleared, rect));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(raster::depthTestPassesEverywhere(zOnly(nan, 0.0f, 0.0f, 0.0f), less, raster::TexelFormat::Depth24, cleared, rect));
    CHECK_FALSE(raster::depthTestPassesEverywhere(zOnly(0.5f, 0.0f, 0.0f, nan), less, raster::TexelFormat::Depth24, cleared, rect));
  }

  TEST_CASE("a clear left to the first triangle gives the bytes of a clear done first, over stale texels") {
    constexpr int kW = 150, kH = 130;   // partial tiles at the right and top
    std::mt19937 rng(7);
    const Frame stale{scattered(rng, 80, kW, kH), {}};
    scenes::DrawState lequal, offset;
    lequal.depthFunc = scenes::DepthFunc::Lequal;
    offset.polygonOffset = true;
    offset.offsetFactor = 2.0f;
    offset.offsetUnits = 4.0f;
    struct Case {
      const char* name;
      float z;
      scenes::DrawState state;
      float slope = 0.0f;
    };
    const Case cases[] = {{"mid depth, LESS", 0.0f, {}}, {"mid depth, LEQUAL", 0.0f, lequal}, {"at the far plane, LESS", 1.0f, {}},
                          {"at the far plane, LEQUAL", 1.0f, lequal}, {"just short of it", 0.99999f, {}},
                          {"polygon offset", 0.3f, offset}, {"sloped", 0.0f, {}, 0.6f},
                          {"sloped, polygon offset", -0.2f, offset, 0.5f}};
    // The covering triangle first, then more triangles over what it left: a few (its tiles
    // walked in order, so the covered-tile path shades it) or many (visibility first).
    for (const Case& c : cases) {
      for (int moreCount : {6, 40}) {
        Frame second{fullscreen(c.z, kW, kH, c.slope), c.state};
        const std::vector<gltest::Vertex> more = scattered(rng, moreCount, kW, kH);
        second.vertices.insert(second.vertices.end(), more.begin(), more.end());
        for (bool withColor : {false, true}) {
          for (int threads : {1, 2, 5}) {
            for (bool scalar : {false, true}) {
              if (scalar && threads != 2) continue;
              CAPTURE(c.name);
              CAPTURE(moreCount);
              CAPTURE(withColor);
              CAPTURE(threads);
              CAPTURE(scalar);
              auto lazyBackend = scenes::makeRasterBackend(threads, scalar);
              auto eagerBackend = scenes::makeRasterBackend(threads, scalar);
              const gltest::Rendered lazy = twoFrames(*lazyBackend, withColor, false, stale, second, kW, kH);
              const gltest::Rendered eager = twoFrames(*eagerBackend, withColor, true, stale, second, kW, kH);
              CHECK(lazy.depth->depth == eager.depth->depth);
              if (withColor) CHECK(lazy.color->rgba8 == eager.color->rgba8);
            }
          }
        }
      }
    }
  }
}
