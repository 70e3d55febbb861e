// The `shading` step (raster/methods.h; tile/coarse_tile.h): coarse fragments as Vulkan's
// VK_KHR_fragment_shading_rate defines them. One shader invocation per coarse pixel, its
// outputs written to every covered pixel of it that passes the depth test, coverage and the
// depth test per pixel, derivatives over coarse quads; the same bytes at any thread count
// and with the reference lanes.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "raster/methods.h"
#include "tests/gl_compare_helpers.h"
#include "tests/scene_test_helpers.h"

namespace {

using namespace gltest;

raster::MethodSet shadingSet(const std::string& rate) {
  raster::MethodSet set;
  raster::setMethod(set, "shading", rate);
  return set;
}

// The window position (x, y) * scale as the attribute at each corner of a triangle given in
// window coordinates, at NDC depth ndcZ, with `alpha` in the attribute's w: the attribute is
// then linear in window coordinates, and alpha tells the draw a pixel took its value from.
DrawCall windowTriangle(std::vector<glm::vec2> corners, float ndcZ, float scale, float alpha, int width, int height,
                        bool depthTest) {
  std::vector<Vertex> vertices;
  for (glm::vec2 p : corners)
    vertices.push_back({clipFromWindow(p, ndcZ, 1.0f, width, height), glm::vec4(p.x * scale, p.y * scale, 0.5f, alpha)});
  DrawCall d;
  d.mesh = makeMesh(vertices);
  d.state.depthTest = depthTest;
  return d;
}

ClearOp clearTo(float value) {
  ClearOp clear;
  clear.color = true;
  clear.colorValue = glm::vec4(value);
  clear.depth = true;
  clear.depthValue = 1.0f;
  return clear;
}

// Pixel (x, read-back row)'s four channels as floats, whatever the format.
glm::vec4 pixel(const ImageData& image, int x, int row) {
  const size_t at = (size_t(row) * size_t(image.width) + size_t(x)) * 4;
  if (!image.floats.empty()) return {image.floats[at], image.floats[at + 1], image.floats[at + 2], image.floats[at + 3]};
  return glm::vec4(image.rgba8[at], image.rgba8[at + 1], image.rgba8[at + 2], image.rgba8[at + 3]) / 255.0f;
}

// Checks a coarse rendering against the 1x1 one of the same draws: every pixel took its
// value from the same draw (alpha) or kept the clear, and the pixels of one coarse pixel
// (w x h, aligned to the stored rows) that took it from the same draw hold one value.
void checkCoarseAgainstFull(const ImageData& coarse, const ImageData& full, int w, int h, bool storedTopFirst) {
  REQUIRE(coarse.width == full.width);
  int drawChanged = 0, coarseSplit = 0;
  std::map<std::pair<int, int>, std::map<float, glm::vec4>> valueOf;   // coarse pixel -> draw (alpha) -> value
  for (int row = 0; row < full.height; ++row) {
    const int stored = storedTopFirst ? row : full.height - 1 - row;
    for (int x = 0; x < full.width; ++x) {
      const glm::vec4 a = pixel(coarse, x, row), b = pixel(full, x, row);
      drawChanged += a.w != b.w;
      auto [it, fresh] = valueOf[{x / w, stored / h}].emplace(a.w, a);
      coarseSplit += !fresh && it->second != a;
    }
  }
  CHECK(drawChanged == 0);
  CHECK(coarseSplit == 0);
}

}  // namespace

TEST_SUITE("shading_rate") {
  TEST_CASE("a coarse pixel's one value reaches its covered pixels; uncovered and depth-failing pixels keep theirs") {
    constexpr int kWidth = 37, kHeight = 29;   // odd: coarse pixels cut by the framebuffer's edges
    auto backend = scenes::makeRasterBackend(2);
    for (bool window : {false, true}) {
      INFO((window ? "window-system framebuffer (RGBA8)" : "FBO (RGBA32F)"));
      TargetDesc target{kWidth, kHeight, TexelFormat::RGBA32F, TexelFormat::Depth24, window};
      // Near: a constant-alpha triangle with an edge at a slant across coarse pixels; far:
      // a larger one behind it, failing the depth test where the near one is, and not
      // reaching the top right corner.
      const DrawCall near = windowTriangle({{3.3f, 2.1f}, {30.7f, 6.2f}, {8.9f, 25.4f}}, -0.5f, 1.0f / 64.0f, 0.25f, kWidth,
                                           kHeight, true);
      const DrawCall far = windowTriangle({{0.0f, 0.0f}, {36.2f, 0.0f}, {0.0f, 28.6f}}, 0.5f, 1.0f / 64.0f, 1.0f, kWidth, kHeight,
                                          true);
      DrawCall post = far;   // the same triangle without a depth test: a post pass
      post.state.depthTest = false;
      const ClearOp clear = clearTo(0.0f);
      const Rendered full = render(*backend, target, {near, far}, clear);
      const Rendered fullPost = render(*backend, target, {post}, clear);
      for (const std::string rate : {"2x1", "1x2", "2x2", "4x4"}) {
        INFO("shading=" << rate);
        const raster::ScopedMethods scoped(shadingSet(rate));
        const int w = raster::methods::coarsePixelWidth(shadingSet(rate).shading);
        const int h = raster::methods::coarsePixelHeight(shadingSet(rate).shading);
        // A depth-tested pass is a geometry pass: 1x1, the same bytes.
        const Rendered geometry = render(*backend, target, {near, far}, clear);
        CHECK(geometry.color->floats == full.color->floats);
        CHECK(geometry.color->rgba8 == full.color->rgba8);
        // A post pass takes the rate: every covered pixel written, the rest the clear.
        const Rendered coarse = render(*backend, target, {post}, clear);
        checkCoarseAgainstFull(*coarse.color, *fullPost.color, w, h, window);
        const bool changed = coarse.color->floats != fullPost.color->floats || coarse.color->rgba8 != fullPost.color->rgba8;
        CHECK(changed);   // the post pass did take the rate
      }
      // 2x2-all takes the geometry pass too: the far triangle fails per pixel where the near
      // one is, and the near one keeps its pixels.
      const raster::ScopedMethods scoped(shadingSet("2x2-all"));
      const Rendered all = render(*backend, target, {near, far}, clear);
      checkCoarseAgainstFull(*all.color, *full.color, 2, 2, window);
      CHECK(all.depth->depth == full.depth->depth);   // depth is per pixel, at each pixel's own z
    }
  }

  TEST_CASE("interpolation at the coarse pixel's centre, derivatives across coarse pixels") {
    constexpr int kSize = 32;
    constexpr float kScale = 1.0f / 8.0f;   // v = window position / 8
    auto backend = scenes::makeRasterBackend(1);
    const TargetDesc target{kSize, kSize, TexelFormat::RGBA32F, std::nullopt};
    // A post pass: the fullscreen triangle with v = window position * scale (derivatives.frag:
    // out.z = dFdx(v.x * v.y), exactly 2 * scale * scale * y over a 2-pixel-wide coarse pixel
    // whose centre is at window y).
    DrawCall d;
    d.program = "test/derivatives";
    std::vector<Vertex> vertices;
    for (const glm::vec2 ndc : {glm::vec2(-1.0f, -1.0f), glm::vec2(3.0f, -1.0f), glm::vec2(-1.0f, 3.0f)}) {
      const glm::vec2 window = (ndc + 1.0f) * 0.5f * float(kSize);
      vertices.push_back({glm::vec4(ndc, 0.0f, 1.0f), glm::vec4(window * kScale, 1.0f, 0.0f)});
    }
    d.mesh = makeMesh(vertices);
    d.state.depthTest = false;
    const raster::ScopedMethods scoped(shadingSet("2x2"));
    const Rendered r = render(*backend, target, {d}, clearTo(0.0f));
    int off = 0;
    for (int row = 0; row < kSize; ++row) {
      const int glY = kSize - 1 - row;
      const double centreY = double(glY / 2 * 2) + 1.0;   // the coarse pixel's centre, window y
      for (int x = 0; x < kSize; ++x) {
        const double expect = 2.0 * kScale * kScale * centreY;
        off += std::fabs(double(pixel(*r.color, x, row).z) - expect) > 1e-4;
      }
    }
    CHECK(off == 0);
  }

  // Every registry scene under shading=2x2 (post passes) and 2x2-all (every pass), at an odd
  // size: threads 1, 2 and 5 and the reference lanes give the bytes of one thread.
  TEST_CASE("every scene at 2x2 and 2x2-all: threads 1, 2 and 5 and scalar lanes give identical bytes") {
    scenes::SceneOptions options;
    options.width = 97;
    options.height = 61;
    bool someSceneCoarse = false;
    for (const std::string& sceneName : testing_support::scenesUnderTest()) {
      // The first, SIMD lanes on one thread, is the reference.
      auto runs = testing_support::prepareScene(sceneName, options, {{1, false}, {2, false}, {5, false}, {1, true}});
      std::vector<scenes::Target> gl;
      for (const std::string rate : {"1x1", "2x2", "2x2-all"}) {
        const raster::ScopedMethods scoped(shadingSet(rate));
        std::vector<std::vector<scenes::Target>> targets;
        for (size_t i = 0; i < (rate == "1x1" ? 1 : runs.size()); ++i) targets.push_back(runs[i].render(options.time));
        if (rate == "1x1") {
          gl = targets[0];
          continue;
        }
        someSceneCoarse |= targets[0].back().image.rgba8 != gl.back().image.rgba8;
        for (size_t i = 1; i < runs.size(); ++i) {
          INFO("shading=" << rate << ": " << sceneName << " at " << options.width << "x" << options.height << ", " << runs[i].name);
          testing_support::checkSameBytes(targets[0], targets[i]);
        }
      }
    }
    CHECK(someSceneCoarse);   // the rate reached some scene's final image
  }
}
