// This pipeline against real GL (llvmpipe through OSMesa) on the paths a target's kind
// selects rather than the triangles' shapes (raster_vs_gl_test.cpp has those): depth-only
// targets (shadow maps), colour clears a first triangle may make unnecessary, and a NaN
// window z. The passthrough program (shaders_cpp/test/passthrough.*); every byte must
// match. Cases: (f) depth-only targets: depth codes alone, inside and straddled regions,
// with and without polygon offset; (g) colour clears under a first triangle that covers a
// tile, or nearly; (h) a NaN window z; (i) a depth-only tile crowded with triangles, walked
// in ranges on several threads (tile/depth_ranges.h). Fixed seeds.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "tests/gl_compare_helpers.h"

namespace {

using namespace gltest;

// (f) Depth-only targets, as shadow maps are drawn: no colour attachment, so the rasterizer
// runs no shader and fills the regions wholly inside a triangle row by row. Large random
// triangles, then the fullscreen triangle, under LESS or LEQUAL, with or without polygon
// offset; the depth codes must be identical.
void compareDepthOnly(BackendPair& backends, const TargetDesc& target, const MeshData& mesh, scenes::DepthFunc func,
                      bool offset) {
  DrawCall draw;
  draw.mesh = mesh;
  draw.state.depthFunc = func;
  draw.state.polygonOffset = offset;
  draw.state.offsetFactor = offset ? 1.5f : 0.0f;
  draw.state.offsetUnits = offset ? 4.0f : 0.0f;
  const BothRendered both = renderBoth(backends, target, {draw}, clearAll());
  const DepthComparison z = compareDepth(*both.raster.depth, *both.gl.depth);
  const std::string where = targetName(target) + (func == scenes::DepthFunc::Lequal ? " LEQUAL" : " LESS") +
                            (offset ? " with polygon offset" : "");
  CAPTURE(where);
  const std::string firstDepthDiff = z.firstDiff;
  CAPTURE(firstDepthDiff);
  MESSAGE("(f) depth only [" << where << "]: depth diffs " << z.diffs << " (max " << z.maxDiff << " LSB)");
  CHECK(z.diffs == 0);
}

}  // namespace

TEST_SUITE("raster_vs_gl") {
  TEST_CASE("(f) depth-only targets: identical depth codes, inside and straddled regions included") {
    BackendPair backends;
    std::mt19937 rng(6006);
    const TargetDesc targets[] = {
        {160, 144, std::nullopt, TexelFormat::Depth24},
        {99, 67, std::nullopt, TexelFormat::Depth16},
    };
    for (const TargetDesc& target : targets) {
      for (scenes::DepthFunc func : {scenes::DepthFunc::Less, scenes::DepthFunc::Lequal}) {
        for (bool offset : {false, true}) {
          // Mostly large triangles, so many 16x16 regions lie wholly inside one.
          std::vector<Vertex> vertices, onHalfPixels;
          for (int i = 0; i < 40; ++i) {
            const glm::vec2 c(uniform(rng, 0.0f, float(target.width)), uniform(rng, 0.0f, float(target.height)));
            const float size = uniform(rng, 20.0f, 150.0f);
            for (int v = 0; v < 3; ++v) {
              const glm::vec2 p = clampToTarget(c + glm::vec2(uniform(rng, -size, size), uniform(rng, -size, size)),
                                                target.width, target.height);
              const float ndcZ = uniform(rng, -0.95f, 0.95f), w = uniform(rng, 0.5f, 3.0f);
              const glm::vec4 color = randomOpaqueColor(rng);
              vertices.push_back({clipFromWindow(p, ndcZ, w, target.width, target.height), color});
              // The same corner on the half-pixel grid: edges then run through pixel
              // centres, whose coverage only the fill rule decides.
              const glm::vec2 snapped = glm::round(p * 2.0f) * 0.5f;
              onHalfPixels.push_back({clipFromWindow(snapped, ndcZ, w, target.width, target.height), color});
            }
          }
          compareDepthOnly(backends, target, makeMesh(vertices), func, offset);
          compareDepthOnly(backends, target, makeMesh(onHalfPixels), func, offset);
          compareDepthOnly(backends, target, fullscreenTriangle(rng, true), func, offset);
        }
      }
    }
  }

  // A tile whose first triangle covers it whole, with no depth test or blending, skips its
  // colour clear (Renderer::flush): every texel is written anyway. Here the first triangle
  // leaves one corner pixel of a tile uncovered, or covers tiles whole but under a depth
  // test that rejects it (cleared depth 0.5) or with blending, and a second draw follows.
  // Every byte must match GL, so texels only the clear writes keep its colour (new targets
  // start zeroed: a wrongly skipped clear shows).
  TEST_CASE("(g) colour clears under a first triangle that covers a tile, or nearly") {
    BackendPair backends;
    ClearOp clear;
    clear.color = true;
    clear.colorValue = glm::vec4(0.2f, 0.4f, 0.6f, 0.8f);
    clear.depth = true;
    clear.depthValue = 0.5f;   // the first triangle (window z 0.625) fails LESS wherever there is depth
    const TargetDesc targets[] = {
        {150, 100, TexelFormat::RGBA8, std::nullopt},
        {150, 100, TexelFormat::RGBA8, TexelFormat::Depth24},
        {130, 70, std::nullopt, std::nullopt, true},
    };
    // Window-space corners of a triangle whose long edge is x + y = c: pixels whose centres
    // sum to more than c stay uncovered (c = 126.9 leaves pixel (63, 63) of tile 0 only).
    auto cornerCut = [](float c) {
      return std::vector<glm::vec2>{{-300.0f, -300.0f}, {c + 300.0f, -300.0f}, {-300.0f, c + 300.0f}};
    };
    const std::vector<glm::vec2> cuts[] = {cornerCut(126.9f), cornerCut(127.1f), cornerCut(60.0f), cornerCut(400.0f)};
    for (const TargetDesc& target : targets) {
      for (const auto& corners : cuts) {
        for (bool blend : {false, true}) {
          std::vector<Vertex> vertices;
          for (const glm::vec2& p : corners)
            vertices.push_back({clipFromWindow(p, 0.25f, 1.0f, target.width, target.height), glm::vec4(0.9f, 0.1f, 0.3f, 1.0f)});
          DrawCall first;
          first.mesh = makeMesh(vertices);
          first.state.depthTest = !blend;
          first.state.blendAdditive = blend;
          // A second, depth-tested draw inside tile 0.
          const glm::vec4 green(0.1f, 0.8f, 0.2f, 1.0f);
          auto at = [&](glm::vec2 p) { return Vertex{clipFromWindow(p, -0.5f, 1.0f, target.width, target.height), green}; };
          DrawCall second;
          second.mesh = makeMesh({at({10.0f, 10.0f}), at({90.0f, 20.0f}), at({30.0f, 95.0f})});
          const BothRendered both = renderBoth(backends, target, {first, second}, clear);
          INFO(targetName(target), ", edge x + y = ", corners[1].x - 300.0f, blend ? ", blending" : "");
          REQUIRE(both.raster.color);
          REQUIRE(both.gl.color);
          CHECK(both.raster.color->rgba8 == both.gl.color->rgba8);
        }
      }
    }
  }

  TEST_CASE("(h) a NaN window z is 1 for the depth test, as llvmpipe's min(z, 1) makes it") {
    // Found by `raster soup` (seed 71 at 64x64): a collinear triangle with its third vertex
    // outside the viewport and beyond the far plane. Clipping bends it by an ulp, so its
    // snapped area is not 0 but its float area is: the planes are NaN. llvmpipe takes
    // min(z, 1) in interpolation (lp_bld_interp.c), so the NaN is 1.0: LESS fails against a
    // clear of 1.0, LEQUAL passes and writes 1.0. A NaN made 0 would pass both and write 0.
    auto fromBits = [](uint32_t bits) {
      float f;
      std::memcpy(&f, &bits, sizeof f);
      return f;
    };
    const uint32_t clip[3][4] = {{0xbe880000, 0xbef00000, 0x3eee7823, 0x3f800000},
                                 {0x3f5c0000, 0x3ea00000, 0xbea01d63, 0x3f800000},
                                 {0xbfb20000, 0xbfa00000, 0x3f9f436a, 0x3f800000}};
    std::vector<Vertex> vertices;
    for (const auto& v : clip)
      vertices.push_back({{fromBits(v[0]), fromBits(v[1]), fromBits(v[2]), fromBits(v[3])}, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f)});
    BackendPair backends;
    const TargetDesc target{64, 64, TexelFormat::RGBA8, TexelFormat::Depth24};
    ClearOp clear = clearAll();
    clear.colorValue = glm::vec4(1.0f);   // the fragment's NaN colour writes 0, so it shows
    for (const scenes::DepthFunc func : {scenes::DepthFunc::Less, scenes::DepthFunc::Lequal}) {
      DrawCall draw;
      draw.mesh = makeMesh(vertices);
      draw.state.depthFunc = func;
      const BothRendered both = renderBoth(backends, target, {draw}, clear);
      const char* funcName = func == scenes::DepthFunc::Less ? "LESS" : "LEQUAL";
      INFO(funcName);
      const uint8_t white[4] = {255, 255, 255, 255};
      const Rgba8Comparison color = compareRgba8(*both.raster.color, *both.gl.color, white);
      const DepthComparison depth = compareDepth(*both.raster.depth, *both.gl.depth);
      CAPTURE(color.firstCoverageDiff);
      CAPTURE(depth.firstDiff);
      CHECK(color.coverageDiffs == 0);
      CHECK(depth.diffs == 0);
      CHECK(color.coveredB == (func == scenes::DepthFunc::Less ? 0 : 1));   // the pixel the sliver covers
      CHECK(std::count(both.raster.depth->depth.begin(), both.raster.depth->depth.end(), 0xFFFFFFu) == 64 * 64);
    }
  }

  // A shadow map's tile that holds most of the pass's triangles is walked in triangle ranges
  // on several threads, and the ranges' least codes folded together: every code must be the
  // one GL (and one thread) gives, under LESS and LEQUAL mixed in the pass, with polygon
  // offset, repeated triangles (LEQUAL's equal codes) and triangles over the tile's edges.
  // A pass with a draw that does not write depth keeps its tiles whole.
  TEST_CASE("(i) a depth-only tile crowded with triangles, walked in ranges: identical depth codes") {
    std::mt19937 rng(9090);
    const TargetDesc target{200, 150, std::nullopt, TexelFormat::Depth24};
    auto smallTriangles = [&](int count, glm::vec2 lo, glm::vec2 hi) {
      std::vector<Vertex> vertices;
      for (int i = 0; i < count; ++i) {
        const glm::vec2 c(uniform(rng, lo.x, hi.x), uniform(rng, lo.y, hi.y));
        const float ndcZ = uniform(rng, -0.9f, 0.9f);
        for (int v = 0; v < 3; ++v) {
          const glm::vec2 p = clampToTarget(c + glm::vec2(uniform(rng, -6.0f, 6.0f), uniform(rng, -6.0f, 6.0f)), target.width, target.height);
          vertices.push_back({clipFromWindow(p, ndcZ + uniform(rng, -0.05f, 0.05f), 1.0f, target.width, target.height), glm::vec4(1.0f)});
        }
        if (i % 7 == 0) vertices.insert(vertices.end(), vertices.end() - 3, vertices.end());   // the same triangle again
      }
      return makeMesh(vertices);
    };
    DrawCall crowd, more, spread;
    crowd.mesh = smallTriangles(1200, {60.0f, 60.0f}, {132.0f, 132.0f});   // tile (1, 1) and over its edges
    more.mesh = smallTriangles(500, {64.0f, 64.0f}, {128.0f, 128.0f});
    more.state.depthFunc = scenes::DepthFunc::Lequal;
    more.state.polygonOffset = true;
    more.state.offsetFactor = 1.0f;
    more.state.offsetUnits = 2.0f;
    spread.mesh = smallTriangles(60, {0.0f, 0.0f}, {200.0f, 150.0f});
    const auto walks = [](const Backend& backend) {
      for (const auto& [name, value] : backend.statistics())
        if (name == "depth_range_walks") return value;
      return -1.0;
    };
    for (const bool writesEverywhere : {true, false}) {
      DrawCall readOnly = spread;
      readOnly.state.depthWrite = writesEverywhere;
      const std::vector<DrawCall> draws = {spread, crowd, readOnly, more};
      const std::unique_ptr<Backend> gl = scenes::makeGlBackend();
      const Rendered reference = render(*gl, target, draws, clearAll());
      for (const int threads : {1, 2, 3, 8}) {
        CAPTURE(threads);
        CAPTURE(writesEverywhere);
        const std::unique_ptr<Backend> raster = scenes::makeRasterBackend(threads);
        const Rendered ours = render(*raster, target, draws, clearAll());
        const DepthComparison z = compareDepth(*ours.depth, *reference.depth);
        CAPTURE(z.firstDiff);
        CHECK(z.diffs == 0);
        // Walked in ranges where it may be, whole where it may not.
        CHECK((walks(*raster) > 0) == (threads > 1 && writesEverywhere));
      }
    }
    // A depth target over kMaxDepthRangeTexels keeps its tiles whole: the copies' memory
    // stays bounded. The same crowd, in the corner tile of a 2049x2048 map.
    const TargetDesc large{2049, 2048, std::nullopt, TexelFormat::Depth24};
    DrawCall corner;
    corner.mesh = makeMesh([&] {
      std::vector<Vertex> vertices;
      for (int i = 0; i < 800; ++i) {
        const glm::vec2 c(uniform(rng, 4.0f, 60.0f), uniform(rng, 4.0f, 60.0f));
        const float ndcZ = uniform(rng, -0.9f, 0.9f);
        for (int v = 0; v < 3; ++v)
          vertices.push_back({clipFromWindow(c + glm::vec2(uniform(rng, -4.0f, 4.0f), uniform(rng, -4.0f, 4.0f)), ndcZ, 1.0f,
                                             large.width, large.height), glm::vec4(1.0f)});
      }
      return vertices;
    }());
    const std::unique_ptr<Backend> gl = scenes::makeGlBackend();
    const std::unique_ptr<Backend> raster = scenes::makeRasterBackend(4);
    const Rendered reference = render(*gl, large, {corner}, clearAll());
    const Rendered ours = render(*raster, large, {corner}, clearAll());
    CHECK(compareDepth(*ours.depth, *reference.depth).diffs == 0);
    CHECK(walks(*raster) == 0);
  }
}
