// The pipeline features the HDR + bloom scene adds, each against real GL (llvmpipe):
//   instancing   per-vertex and per-instance (divisor 1) attributes and gl_InstanceID, with
//                a 16-bit depth buffer and LEQUAL; RGBA32F read back, every bit compared;
//   culling      GL_BACK with counter-clockwise front faces, by winding, on random
//                triangles in an FBO and in the (flipped) default framebuffer;
//   blending     ONE/ONE on RGBA16F at half rounding boundaries, with denormal halves, and
//                at overflow (sums past 65504): GL must equal the model "float32 sum of the
//                exact destination and the source, one conversion to half toward zero",
//                and this pipeline must equal GL bit for bit;
//   viewports    draws into a viewport smaller than the target touch only that rectangle,
//                and inside it the interpolated varyings are GL's to the bit.
// Test programs: shaders_cpp/test/instanced.* and shaders_cpp/test/passthrough.*.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "raster/texture/format.h"
#include "tests/gl_compare_helpers.h"

namespace {

using namespace gltest;
using scenes::CullMode;
using scenes::DepthFunc;
using scenes::Viewport;

// ---- a small renderer of draws with instance counts and a viewport ------------------------
struct Draw {
  std::string program = "test/passthrough";
  MeshData mesh;
  DrawState state;
  int instances = 1;
};

struct Target {
  int width = 64, height = 64;
  TexelFormat color = TexelFormat::RGBA8;
  std::optional<TexelFormat> depth;
  bool defaultFramebuffer = false;   // RGBA8 + Depth24, stored flipped by both backends
};

Rendered renderDraws(Backend& backend, const Target& target, const Viewport& viewport, const ClearOp& clear,
                     const std::vector<Draw>& draws) {
  Handle framebuffer = scenes::kDefaultFramebuffer;
  if (target.defaultFramebuffer) {
    backend.resizeDefaultFramebuffer(target.width, target.height);
  } else {
    scenes::FramebufferDesc fb;
    fb.colorTextures = {backend.createTexture({target.width, target.height, target.color, {}})};
    if (target.depth) fb.depthTexture = backend.createTexture({target.width, target.height, *target.depth, {}});
    framebuffer = backend.createFramebuffer(fb);
  }
  backend.beginPass(framebuffer, viewport, clear);
  for (const Draw& d : draws) {
    const Handle program = backend.createProgram(d.program);
    const Handle mesh = backend.createMesh(d.mesh);
    backend.draw(program, mesh, d.state, d.instances);
  }
  backend.finish();
  Rendered result;
  result.color = backend.readColor(framebuffer);
  if (target.depth || target.defaultFramebuffer) result.depth = backend.readDepth(framebuffer);
  return result;
}

BothRendered renderBothDraws(BackendPair& backends, const Target& target, const Viewport& viewport,
                             const ClearOp& clear, const std::vector<Draw>& draws) {
  return {renderDraws(*backends.raster, target, viewport, clear, draws),
          renderDraws(*backends.gl, target, viewport, clear, draws)};
}

Viewport fullViewport(const Target& t) { return {0, 0, t.width, t.height}; }

DrawState noDepth() {
  DrawState s;
  s.depthTest = false;
  s.depthWrite = false;
  return s;
}

// Clip position of a window point inside a viewport (GL window coordinates, y up).
glm::vec4 clipInViewport(glm::vec2 window, const Viewport& vp, float ndcZ, float w) {
  const float ndcX = (window.x - float(vp.x)) / float(vp.width) * 2.0f - 1.0f;
  const float ndcY = (window.y - float(vp.y)) / float(vp.height) * 2.0f - 1.0f;
  return {ndcX * w, ndcY * w, ndcZ * w, w};
}

// Signed doubled area of a window-space triangle (GL, y up): > 0 is counter-clockwise.
double windowArea(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  return (double(b.x) - a.x) * (double(c.y) - a.y) - (double(c.x) - a.x) * (double(b.y) - a.y);
}

// RGBA8 colour that names triangle i (i < 65535), opaque.
glm::vec4 indexColor(int i) {
  const int n = i + 1;
  return {float(n & 255) / 255.0f, float(n >> 8) / 255.0f, 0.0f, 1.0f};
}

// A half value from its bits.
float halfValue(uint16_t bits) { return raster::format::floatFromHalf(bits); }

}  // namespace

TEST_SUITE("hdr_features") {
  TEST_CASE("instancing: per-instance offsets and colours, gl_InstanceID, Depth16 LEQUAL, equal GL bit for bit") {
    BackendPair backends;
    std::mt19937 rng(1101);
    const Target target{96, 80, TexelFormat::RGBA32F, TexelFormat::Depth16};
    // One small shape of three triangles (a fan and a sliver), perspective w, coloured per vertex.
    std::vector<Vertex> shape;
    for (int v = 0; v < 9; ++v) {
      const float w = uniform(rng, 0.7f, 1.6f);
      const glm::vec2 ndc(uniform(rng, -0.3f, 0.3f), uniform(rng, -0.3f, 0.3f));
      shape.push_back({glm::vec4(ndc.x * w, ndc.y * w, uniform(rng, -0.2f, 0.2f) * w, w),
                       glm::vec4(uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), 1.0f)});
    }
    MeshData mesh = makeMesh(shape, {0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 2, 4});
    // Instance { offset : vec3 (clip space); colour : vec4 } at locations 2 and 3. Pairs of
    // instances share an offset, so LEQUAL lets the later one win on equal depth.
    constexpr int kInstances = 61;
    for (int i = 0; i < kInstances; ++i) {
      const bool twin = i % 5 == 4;
      const size_t prev = mesh.instances.size() - 7;
      const float ox = twin ? mesh.instances[prev] : uniform(rng, -0.9f, 0.9f);
      const float oy = twin ? mesh.instances[prev + 1] : uniform(rng, -0.9f, 0.9f);
      const float oz = twin ? mesh.instances[prev + 2] : uniform(rng, -0.6f, 0.6f);
      mesh.instances.insert(mesh.instances.end(), {ox, oy, oz, uniform(rng, 0.1f, 2.0f), uniform(rng, 0.1f, 2.0f),
                                                   uniform(rng, 0.1f, 2.0f), 1.0f});
    }
    mesh.instanceStrideFloats = 7;
    mesh.instanceAttributes = {{2, 3, 0}, {3, 4, 3}};

    DrawState state;
    state.depthFunc = DepthFunc::Lequal;
    const std::vector<Draw> draws = {{"test/instanced", mesh, state, kInstances}};
    const BothRendered r = renderBothDraws(backends, target, fullViewport(target), clearAll(), draws);

    const FloatComparison color = compareFloatBits(*r.raster.color, *r.gl.color);
    const DepthComparison depth = compareDepth(*r.raster.depth, *r.gl.depth);
    // How many instances are visible (alpha = gl_InstanceID, clear alpha 0 shared with
    // instance 0, so count distinct alphas among pixels whose colour is not the clear).
    std::vector<bool> seen(kInstances, false);
    int covered = 0;
    for (size_t p = 0; p < r.gl.color->floats.size(); p += 4) {
      if (r.gl.color->floats[p] == 0.0f && r.gl.color->floats[p + 1] == 0.0f && r.gl.color->floats[p + 2] == 0.0f) continue;
      ++covered;
      seen[size_t(r.gl.color->floats[p + 3])] = true;
    }
    const int visible = int(std::count(seen.begin(), seen.end(), true));
    MESSAGE("instancing: " << covered << " pixels covered, " << visible << " of " << kInstances
                           << " instances visible; colour bit differences " << color.diffs
                           << ", depth differences " << depth.diffs);
    CHECK(visible > kInstances / 2);   // the draw really drew many instances
    CHECK_MESSAGE(color.diffs == 0, color.firstDiff);
    CHECK_MESSAGE(depth.diffs == 0, depth.firstDiff);
  }

  TEST_CASE("instancing: the scene's 1000 instances of a 36-index cube in one draw equal GL") {
    BackendPair backends;
    std::mt19937 rng(1102);
    const Target target{128, 96, TexelFormat::RGBA32F, TexelFormat::Depth16};
    // The seed's cube (36 indices of 24 vertices), as clip-space positions at w = 1 scaled
    // small: 1000 instances on a jittered grid, each with its own colour.
    const float corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    std::vector<Vertex> cube;
    for (const auto& c : corners)
      cube.push_back({glm::vec4(c[0] * 0.02f, c[1] * 0.02f + c[0] * 0.007f, c[2] * 0.02f, 1.0f),
                      glm::vec4(0.5f + 0.5f * c[0], 0.5f + 0.5f * c[1], 0.5f + 0.5f * c[2], 1.0f)});
    MeshData mesh = makeMesh(cube, {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                    3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5});
    for (int i = 0; i < 1000; ++i)
      mesh.instances.insert(mesh.instances.end(),
                            {float(i % 40) / 20.0f - 0.975f + uniform(rng, -0.01f, 0.01f),
                             float(i / 40) / 12.5f - 0.96f + uniform(rng, -0.01f, 0.01f), uniform(rng, -0.5f, 0.5f),
                             uniform(rng, 0.2f, 1.0f), uniform(rng, 0.2f, 1.0f), uniform(rng, 0.2f, 1.0f), 1.0f});
    mesh.instanceStrideFloats = 7;
    mesh.instanceAttributes = {{2, 3, 0}, {3, 4, 3}};
    DrawState state;
    state.depthFunc = DepthFunc::Lequal;
    state.cull = CullMode::Back;
    const BothRendered r = renderBothDraws(backends, target, fullViewport(target), clearAll(), {{"test/instanced", mesh, state, 1000}});
    const FloatComparison color = compareFloatBits(*r.raster.color, *r.gl.color);
    const DepthComparison depth = compareDepth(*r.raster.depth, *r.gl.depth);
    CHECK_MESSAGE(color.diffs == 0, color.firstDiff);
    CHECK_MESSAGE(depth.diffs == 0, depth.firstDiff);
  }

  TEST_CASE("culling: GL_BACK keeps exactly GL's counter-clockwise triangles, FBO and default framebuffer") {
    BackendPair backends;
    const Target targets[] = {
        {96, 96, TexelFormat::RGBA8, std::nullopt, false},
        {71, 53, TexelFormat::RGBA8, std::nullopt, false},
        {96, 96, TexelFormat::RGBA8, std::nullopt, true},
    };
    uint32_t seed = 1201;
    for (const Target& target : targets) {
      CAPTURE(target.width);
      CAPTURE(target.defaultFramebuffer);
      std::mt19937 rng(seed++);
      const uint8_t clearBytes[4] = {0, 0, 0, 0};

      // (1) One triangle per 8x8 cell, random winding: whether each survives is visible on
      // its own, and must follow its winding in GL window coordinates (checked where the
      // area is not tiny, so snapping cannot flip it).
      std::vector<Vertex> vertices;
      std::vector<double> areas;
      const int columns = target.width / 8, rows = target.height / 8;
      for (int cy = 0; cy < rows; ++cy) {
        for (int cx = 0; cx < columns; ++cx) {
          glm::vec2 p[3];
          for (auto& q : p) q = glm::vec2(float(cx * 8) + uniform(rng, 0.5f, 7.5f), float(cy * 8) + uniform(rng, 0.5f, 7.5f));
          areas.push_back(windowArea(p[0], p[1], p[2]));
          const int index = int(areas.size()) - 1;
          const float w = uniform(rng, 0.5f, 2.0f);
          for (const auto& q : p) vertices.push_back({clipFromWindow(q, 0.0f, w, target.width, target.height), indexColor(index)});
        }
      }
      DrawState cull = noDepth();
      cull.cull = CullMode::Back;
      const Viewport full = fullViewport(target);
      const BothRendered cells = renderBothDraws(backends, target, full, clearAll(), {{"test/passthrough", makeMesh(vertices), cull}});
      const Rgba8Comparison c = compareRgba8(*cells.raster.color, *cells.gl.color, clearBytes);
      CHECK_MESSAGE(c.coverageDiffs == 0, c.firstCoverageDiff);
      CHECK_MESSAGE(c.colorDiffs == 0, c.firstColorDiff);
      // Which triangles GL kept, from the colours it wrote.
      std::vector<bool> kept(areas.size(), false);
      const std::vector<uint8_t>& px = cells.gl.color->rgba8;
      for (size_t p = 0; p < px.size(); p += 4) {
        const int n = px[p] | (px[p + 1] << 8);
        if (n > 0) kept[size_t(n - 1)] = true;
      }
      int checked = 0, wrong = 0, keptCount = 0;
      for (size_t i = 0; i < areas.size(); ++i) {
        keptCount += kept[i];
        if (std::abs(areas[i]) < 4.0) continue;   // tiny: may cover no pixel at all
        ++checked;
        wrong += kept[i] != (areas[i] > 0.0);
      }
      MESSAGE(target.width << "x" << target.height << std::string(target.defaultFramebuffer ? " default" : " FBO") << ": GL kept "
                            << keptCount << " of " << areas.size() << " cell triangles; " << wrong << " of " << checked
                            << " disagree with the window-space winding");
      CHECK(wrong == 0);
      CHECK(keptCount > int(areas.size()) / 4);
      CHECK(keptCount < int(areas.size()) * 3 / 4);

      // (2) Overlapping random triangles, some crossing the near plane (w < 0 at a vertex):
      // culled and unculled images both equal GL's.
      std::vector<Vertex> random;
      for (int i = 0; i < 120; ++i) {
        for (int v = 0; v < 3; ++v) {
          const float w = i % 4 == 3 ? uniform(rng, -0.6f, 2.0f) : uniform(rng, 0.4f, 2.0f);
          random.push_back({glm::vec4(uniform(rng, -1.3f, 1.3f) * std::abs(w), uniform(rng, -1.3f, 1.3f) * std::abs(w),
                                      uniform(rng, -0.9f, 0.9f) * std::abs(w), w),
                            indexColor(i)});
        }
      }
      for (bool culled : {false, true}) {
        DrawState s = noDepth();
        s.cull = culled ? CullMode::Back : CullMode::None;
        const BothRendered r = renderBothDraws(backends, target, full, clearAll(), {{"test/passthrough", makeMesh(random), s}});
        const Rgba8Comparison cmp = compareRgba8(*r.raster.color, *r.gl.color, clearBytes);
        CAPTURE(culled);
        CHECK_MESSAGE(cmp.coverageDiffs == 0, cmp.firstCoverageDiff);
        CHECK_MESSAGE(cmp.colorDiffs == 0, cmp.firstColorDiff);
      }
    }
  }

  TEST_CASE("blending: ONE/ONE on RGBA16F is a float32 sum converted once toward zero, as GL, up to and past 65504") {
    BackendPair backends;
    std::mt19937 rng(1301);
    // (destination half, source float) pairs, four to a cell (one per channel).
    std::vector<std::pair<float, float>> pairs;
    const float ulp1 = 1.0f / 1024.0f;   // half ULP at 1.0
    for (float k : {0.0f, 0.25f, 0.4999f, 0.5f, 0.5001f, 0.75f, 0.9999f, 1.0f, 1.0001f, 1.5f, 1.9999f, 2.0f, 2.5f})
      for (float dst : {1.0f, -1.0f, 1.5f}) {
        pairs.push_back({dst, k * ulp1});
        pairs.push_back({dst, -k * ulp1});
      }
    for (float src : {0.999f, 1.0f, 1.001f, 1.999f, 2.0f, 2.001f, 3.0f, -0.5f, -1.0f})   // half ULP 2 at 2048
      pairs.push_back({2048.0f, src});
    // sums just below, at and past the largest half: 65504 + 15.99 is 65519.99 (RNE would
    // still give 65504), + 16 = 65520 (RNE gives Inf), past that only RTZ keeps 65504.
    for (float src : {1.0f, 8.0f, 15.99f, 16.0f, 31.99f, 32.0f, 1000.0f, 65504.0f, 1e10f, 3.0e38f})
      for (float sign : {1.0f, -1.0f}) pairs.push_back({sign * 65504.0f, sign * src});
    for (float src : {5504.0f, 5519.99f, 5520.0f, 6000.0f}) pairs.push_back({60000.0f, src});
    for (float src : {65504.0f, 65519.0f, 65520.0f, 70000.0f, 1e30f}) pairs.push_back({0.0f, src});
    // denormal halves (2^-24 is the smallest) and sums across the normal boundary 2^-14
    const float d = std::ldexp(1.0f, -24);
    for (float src : {0.5f * d, d, 1.5f * d, 2.999f * d, 1e-9f}) {
      pairs.push_back({d, src});
      pairs.push_back({0.0f, src});
      pairs.push_back({std::ldexp(1.0f, -14) - d, src});
    }
    // random halves of every magnitude with random sources of similar size
    while (pairs.size() % 4 != 0 || pairs.size() < 1024) {
      const float dst = halfValue(uint16_t(std::uniform_int_distribution<int>(0, 0xFBFF)(rng)));   // finite, any sign
      if (std::isnan(dst) || std::isinf(dst)) continue;
      const float src = dst * uniform(rng, -1.5f, 1.5f) + (std::abs(dst) + 1e-7f) * uniform(rng, -0.01f, 0.01f);
      pairs.push_back({dst, src});
    }

    const Target target{64, 64, TexelFormat::RGBA16F, std::nullopt};
    const int cell = 2, columns = target.width / cell;
    REQUIRE(pairs.size() / 4 <= size_t(columns * (target.height / cell)));
    auto cellValues = [&](bool source) {
      return gridMesh(target.width, target.height, cell, [&](int column, int row) {
        GridCell c;
        const size_t first = size_t(row * columns + column) * 4;
        for (int ch = 0; ch < 4; ++ch) {
          const size_t i = std::min(first + size_t(ch), pairs.size() - 1);
          c.attribute[ch] = source ? pairs[i].second : pairs[i].first;
        }
        return c;
      });
    };
    DrawState blend = noDepth();
    blend.blendAdditive = true;
    // The destination is written by a plain draw (its values are halves: stored exactly).
    const BothRendered r = renderBothDraws(backends, target, fullViewport(target), clearAll(),
                                           {{"test/passthrough", cellValues(false), noDepth()},
                                            {"test/passthrough", cellValues(true), blend}});
    const FloatComparison bits = compareFloatBits(*r.raster.color, *r.gl.color);
    CHECK_MESSAGE(bits.diffs == 0, bits.firstDiff);

    // GL against the model, pair by pair; and how many pairs a round-to-nearest-even (or
    // convert-then-add) model would have got wrong, so the cases really probe the boundaries.
    int modelWrong = 0, rneWrong = 0, twoStepWrong = 0, overflowCases = 0;
    std::string firstWrong;
    for (size_t i = 0; i < pairs.size(); ++i) {
      const size_t pixel = size_t(int(i / 4) / columns * cell) * size_t(target.width) + size_t(int(i / 4) % columns * cell);
      const float gl = r.gl.color->floats[pixel * 4 + i % 4];
      const float sum = pairs[i].first + pairs[i].second;
      const float model = halfValue(raster::format::halfFromFloatTowardZero(sum));
      const float rne = halfValue(raster::format::halfFromFloatNearestEven(sum));
      const float twoStep = halfValue(raster::format::halfFromFloatTowardZero(
          pairs[i].first + halfValue(raster::format::halfFromFloatTowardZero(pairs[i].second))));
      overflowCases += std::abs(sum) > 65504.0f;
      if (bitsOf(gl) != bitsOf(model) && modelWrong++ == 0)
        firstWrong = std::to_string(pairs[i].first) + " + " + std::to_string(pairs[i].second) + ": gl " +
                     std::to_string(gl) + ", model " + std::to_string(model);
      rneWrong += bitsOf(gl) != bitsOf(rne);
      twoStepWrong += bitsOf(gl) != bitsOf(twoStep);
    }
    MESSAGE(pairs.size() << " pairs (" << overflowCases << " past 65504): GL differs from the RTZ float-sum model in "
                         << modelWrong << ", from round-to-nearest-even in " << rneWrong
                         << ", from convert-source-then-add in " << twoStepWrong);
    CHECK_MESSAGE(modelWrong == 0, firstWrong);
    CHECK(rneWrong > 0);
    CHECK(twoStepWrong > 0);
    CHECK(overflowCases >= 20);
  }

  TEST_CASE("viewports: draws into a smaller viewport touch only that rectangle, and match GL inside it") {
    BackendPair backends;
    std::mt19937 rng(1401);
    struct Case {
      Target target;
      Viewport viewport;
    };
    const Case cases[] = {
        {{64, 48, TexelFormat::RGBA32F, std::nullopt}, {0, 0, 20, 15}},     // a bloom-mip-like corner
        {{64, 48, TexelFormat::RGBA32F, std::nullopt}, {5, 7, 33, 21}},     // offset, odd size
        {{53, 61, TexelFormat::RGBA16F, std::nullopt}, {11, 3, 17, 40}},
        {{64, 48, TexelFormat::RGBA8, std::nullopt, true}, {9, 4, 31, 27}}, // flipped default framebuffer
    };
    for (const Case& k : cases) {
      const Viewport& vp = k.viewport;
      CAPTURE(vp.x);
      CAPTURE(vp.y);
      CAPTURE(vp.width);
      CAPTURE(vp.height);
      CAPTURE(k.target.defaultFramebuffer);
      // The fullscreen triangle of the post passes, with a varying that changes across it,
      // and random triangles reaching well outside the viewport, some with perspective w.
      std::vector<Vertex> vertices = {{glm::vec4(-1, -1, 0, 1), glm::vec4(0.0f, 0.0f, 0.25f, 1.0f)},
                                      {glm::vec4(3, -1, 0, 1), glm::vec4(2.0f, 0.0f, 0.5f, 1.0f)},
                                      {glm::vec4(-1, 3, 0, 1), glm::vec4(0.0f, 2.0f, 0.75f, 1.0f)}};
      for (int i = 0; i < 40; ++i) {
        for (int v = 0; v < 3; ++v) {
          const float w = uniform(rng, 0.5f, 2.0f);
          const glm::vec2 window(uniform(rng, -20.0f, float(k.target.width) + 20.0f),
                                 uniform(rng, -20.0f, float(k.target.height) + 20.0f));
          vertices.push_back({clipInViewport(window, vp, uniform(rng, -0.5f, 0.5f), w),
                              glm::vec4(uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), 1.0f)});
        }
      }
      ClearOp clear = clearAll();
      clear.colorValue = glm::vec4(0.0f, 0.0f, 0.0f, 0.0f);
      const BothRendered r = renderBothDraws(backends, k.target, vp, clear, {{"test/passthrough", makeMesh(vertices), noDepth()}});
      const ImageData& ours = *r.raster.color;
      const ImageData& gl = *r.gl.color;
      int outsideOurs = 0, outsideGl = 0, insideCovered = 0;
      for (int row = 0; row < ours.height; ++row) {
        for (int x = 0; x < ours.width; ++x) {
          const int windowY = ours.height - 1 - row;   // read-back rows are top first
          const bool inside = x >= vp.x && x < vp.x + vp.width && windowY >= vp.y && windowY < vp.y + vp.height;
          const size_t at = (size_t(row) * size_t(ours.width) + size_t(x)) * 4;
          bool oursTouched = false, glTouched = false;
          for (int c = 0; c < 4; ++c) {
            if (ours.format == TexelFormat::RGBA8) {
              oursTouched |= ours.rgba8[at + size_t(c)] != 0;
              glTouched |= gl.rgba8[at + size_t(c)] != 0;
            } else {
              oursTouched |= ours.floats[at + size_t(c)] != 0.0f;
              glTouched |= gl.floats[at + size_t(c)] != 0.0f;
            }
          }
          if (!inside) {
            outsideOurs += oursTouched;
            outsideGl += glTouched;
          } else {
            insideCovered += oursTouched;
          }
        }
      }
      MESSAGE("viewport (" << vp.x << ", " << vp.y << ", " << vp.width << ", " << vp.height << ") of " << ours.width << "x"
                           << ours.height << std::string(k.target.defaultFramebuffer ? " default framebuffer" : " FBO")
                           << ": pixels touched outside it: ours " << outsideOurs << ", GL " << outsideGl
                           << "; inside: " << insideCovered << " of " << vp.width * vp.height);
      CHECK(outsideOurs == 0);
      CHECK(outsideGl == 0);
      CHECK(insideCovered == vp.width * vp.height);   // the fullscreen triangle fills the viewport
      if (ours.format == TexelFormat::RGBA8) {
        const uint8_t clearBytes[4] = {0, 0, 0, 0};
        const Rgba8Comparison cmp = compareRgba8(ours, gl, clearBytes);
        CHECK_MESSAGE(cmp.coverageDiffs == 0, cmp.firstCoverageDiff);
        CHECK_MESSAGE(cmp.colorDiffs == 0, cmp.firstColorDiff);
      } else {
        const FloatComparison cmp = compareFloatBits(ours, gl);
        CHECK_MESSAGE(cmp.diffs == 0, cmp.firstDiff);
      }
    }
  }
}
