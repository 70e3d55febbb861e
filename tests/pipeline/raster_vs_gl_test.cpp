// This pipeline against real GL (llvmpipe through OSMesa) on small random draws with the
// passthrough program (shaders_cpp/test/passthrough.*): coverage must be bit-identical,
// depth codes within 1 LSB (expected: identical), and RGBA8 colours of interpolated
// random varyings within 1 step.
//
// Each case renders two passes into the same kind of target with both backends:
//   depth pass: the triangles with random opaque colours, depth test LESS, on a clear of
//               (0, 0, 0, 0) / depth 1.0; a pixel is covered iff its colour is not the clear;
//   count pass: the same triangles with colour (1/255, 0, 0, 1), depth test off, additive
//               blending: red = how many triangles cover the pixel, so a pixel a triangle
//               wrongly gains or loses shows even under other triangles. Must be identical.
// Cases: (a) random triangles (slivers, sub-pixel, vertices on pixel centres and edges,
// perspective w), (b) a jittered mesh with shared edges (every pixel exactly once),
// (c) triangles the clipper must cut (near plane, w < 0, x/y planes), (d) a fullscreen
// triangle, (e) odd target sizes. Fixed seeds; every case MESSAGEs its statistics. Cases
// (f)-(h), on the paths a target's kind selects (depth-only targets, clears a first
// triangle makes unnecessary, a NaN window z), are in raster_vs_gl_targets_test.cpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "tests/gl_compare_helpers.h"

namespace {

using namespace gltest;

// A triangle in window coordinates (GL, y up) with per-vertex w, NDC z and colour.
struct WindowTriangle {
  glm::vec2 p[3];
  float w[3];
  float ndcZ[3];
  glm::vec4 color[3];
};

// Random triangles inside a width x height viewport (no clipping needed), in four kinds
// taken in turn: general (log-uniform sizes), slivers (two nearly coincident vertices, or
// three nearly collinear ones), sub-pixel, and vertices on the half-pixel grid (window
// coordinates that are multiples of 0.5: pixel centres and pixel edges).
std::vector<WindowTriangle> randomTriangles(std::mt19937& rng, int count, int width, int height) {
  const float extent = float(std::max(width, height));
  auto inside = [&] { return glm::vec2(uniform(rng, 0.0f, float(width)), uniform(rng, 0.0f, float(height))); };
  auto around = [&](glm::vec2 c, float radius) {
    return c + glm::vec2(uniform(rng, -radius, radius), uniform(rng, -radius, radius));
  };
  auto logSize = [&](float lo, float hi) { return std::exp(uniform(rng, std::log(lo), std::log(hi))); };
  std::vector<WindowTriangle> triangles;
  for (int i = 0; i < count; ++i) {
    WindowTriangle t;
    const glm::vec2 c = inside();
    switch (i % 4) {
      case 0: {  // general
        const float size = logSize(0.5f, std::max(1.0f, extent / 3.0f));
        for (auto& p : t.p) p = around(c, size);
        break;
      }
      case 1: {  // slivers
        const float tiny[] = {0.0f, 1.0f / 1024.0f, 1.0f / 256.0f, 1.0f / 128.0f, 0.01f, 0.1f};
        const float d = tiny[std::uniform_int_distribution<int>(0, 5)(rng)];
        const float angle = uniform(rng, 0.0f, 6.2831853f);
        t.p[0] = c;
        t.p[1] = c + d * glm::vec2(std::cos(angle), std::sin(angle));
        t.p[2] = around(c, logSize(1.0f, std::max(2.0f, extent / 2.0f)));
        if (i % 8 == 5) {  // nearly collinear: the third vertex just off the middle of a long edge
          t.p[1] = around(c, logSize(2.0f, std::max(3.0f, extent / 2.0f)));
          const glm::vec2 mid = 0.5f * (t.p[0] + t.p[1]);
          t.p[2] = mid + glm::vec2(uniform(rng, -0.05f, 0.05f), uniform(rng, -0.05f, 0.05f));
        }
        break;
      }
      case 2: {  // sub-pixel
        for (auto& p : t.p) p = c + glm::vec2(uniform(rng, 0.0f, 1.2f), uniform(rng, 0.0f, 1.2f));
        break;
      }
      default: {  // half-pixel grid: pixel centres (k + 0.5) and pixel edges (k)
        const float size = logSize(1.0f, std::max(2.0f, extent / 4.0f));
        for (auto& p : t.p) {
          const glm::vec2 q = around(c, size);
          p = glm::vec2(std::round(q.x * 2.0f) * 0.5f, std::round(q.y * 2.0f) * 0.5f);
        }
        break;
      }
    }
    for (int v = 0; v < 3; ++v) {
      t.p[v] = clampToTarget(t.p[v], width, height);
      t.w[v] = uniform(rng, 0.5f, 3.0f);
      t.ndcZ[v] = uniform(rng, -0.95f, 0.95f);
      t.color[v] = randomOpaqueColor(rng);
    }
    triangles.push_back(t);
  }
  return triangles;
}

std::vector<Vertex> toVertices(const std::vector<WindowTriangle>& triangles, int width, int height) {
  std::vector<Vertex> vertices;
  for (const WindowTriangle& t : triangles)
    for (int v = 0; v < 3; ++v) vertices.push_back({clipFromWindow(t.p[v], t.ndcZ[v], t.w[v], width, height), t.color[v]});
  return vertices;
}

// The two passes on any mesh of passthrough vertices (position, colour with alpha 1).
DrawCall depthPass(const MeshData& mesh) {
  DrawCall d;
  d.mesh = mesh;
  return d;
}
DrawCall countPass(MeshData mesh) {
  for (size_t v = 0; v < mesh.vertices.size(); v += size_t(mesh.strideFloats)) {
    mesh.vertices[v + 4] = 1.0f / 255.0f;
    mesh.vertices[v + 5] = 0.0f;
    mesh.vertices[v + 6] = 0.0f;
    mesh.vertices[v + 7] = 1.0f;
  }
  DrawCall d;
  d.mesh = std::move(mesh);
  d.state.depthTest = false;
  d.state.blendAdditive = true;
  return d;
}

struct CaseResult {
  int coverageDiffs = 0, colorDiffs = 0, maxStep = 0, depthDiffs = 0, countDiffs = 0;
  uint32_t maxDepthDiff = 0;
  int covered = 0, maxCount = 0;
  std::vector<int> counts;   // count pass, red of every pixel (gl), read-back order
};

// Renders both passes with both backends and checks coverage, depth and colour.
CaseResult compareCase(BackendPair& backends, const std::string& name, const TargetDesc& target, const MeshData& mesh) {
  CAPTURE(name);
  const std::string where = targetName(target);
  CAPTURE(where);
  const uint8_t clearBytes[4] = {0, 0, 0, 0};
  CaseResult r;

  const BothRendered depth = renderBoth(backends, target, {depthPass(mesh)}, clearAll());
  const Rgba8Comparison color = compareRgba8(*depth.raster.color, *depth.gl.color, clearBytes);
  const DepthComparison z = compareDepth(*depth.raster.depth, *depth.gl.depth);
  r.coverageDiffs = color.coverageDiffs;
  r.colorDiffs = color.colorDiffs;
  r.maxStep = color.maxStep;
  r.depthDiffs = z.diffs;
  r.maxDepthDiff = z.maxDiff;
  r.covered = color.coveredB;

  const BothRendered count = renderBoth(backends, target, {countPass(mesh)}, clearAll());
  const Rgba8Comparison counted = compareRgba8(*count.raster.color, *count.gl.color, clearBytes);
  r.countDiffs = counted.coverageDiffs + counted.colorDiffs;
  const std::vector<uint8_t>& bytes = count.gl.color->rgba8;
  for (size_t i = 0; i < bytes.size(); i += 4) {
    r.counts.push_back(bytes[i]);
    r.maxCount = std::max(r.maxCount, int(bytes[i]));
  }

  MESSAGE(name << " [" << where << "]: " << r.covered << " covered pixels; coverage diffs " << r.coverageDiffs
                << ", count-pass diffs " << r.countDiffs << " (max count " << r.maxCount << "), colour diffs "
                << r.colorDiffs << " (max step " << r.maxStep << "), depth diffs " << r.depthDiffs << " (max "
                << r.maxDepthDiff << " LSB)");
  const std::string firstCoverageDiff = color.firstCoverageDiff, firstCountDiff = counted.firstCoverageDiff + counted.firstColorDiff;
  const std::string firstColorDiff = color.firstColorDiff, firstDepthDiff = z.firstDiff;
  CAPTURE(firstCoverageDiff);
  CAPTURE(firstCountDiff);
  CAPTURE(firstColorDiff);
  CAPTURE(firstDepthDiff);
  CHECK(r.coverageDiffs == 0);
  CHECK(r.countDiffs == 0);
  CHECK(r.maxCount < 255);   // a saturated count would hide differences
  CHECK(r.maxStep <= 1);
  CHECK(r.maxDepthDiff <= 1);
  // Today both are exact; a difference within the tolerance is flagged, not failed.
  WARN(r.depthDiffs == 0);
  WARN(r.colorDiffs == 0);
  return r;
}

MeshData randomTriangleMesh(uint32_t seed, int count, int width, int height) {
  std::mt19937 rng(seed);
  return makeMesh(toVertices(randomTriangles(rng, count, width, height), width, height));
}

// A jittered grid of cells split into two triangles along a random diagonal, covering the
// whole target; interior vertices are shared (indexed) and moved by up to 12% of a cell,
// every other one rounded to the half-pixel grid. Border vertices stay on the border.
MeshData jitteredGridMesh(std::mt19937& rng, int width, int height, float cell) {
  const int nx = std::max(1, int(std::round(float(width) / cell)));
  const int ny = std::max(1, int(std::round(float(height) / cell)));
  const float cx = float(width) / float(nx), cy = float(height) / float(ny);
  std::vector<Vertex> vertices;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      glm::vec2 p(float(i) * cx, float(j) * cy);
      if (i > 0 && i < nx) p.x += uniform(rng, -0.12f, 0.12f) * cx;
      if (j > 0 && j < ny) p.y += uniform(rng, -0.12f, 0.12f) * cy;
      if ((i + j) % 2 == 0) {
        if (i > 0 && i < nx) p.x = std::round(p.x * 2.0f) * 0.5f;
        if (j > 0 && j < ny) p.y = std::round(p.y * 2.0f) * 0.5f;
      }
      const float w = uniform(rng, 0.5f, 3.0f);
      vertices.push_back({clipFromWindow(p, uniform(rng, -0.9f, 0.9f), w, width, height), randomOpaqueColor(rng)});
    }
  }
  std::vector<uint32_t> indices;
  auto at = [&](int i, int j) { return uint32_t(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      const bool flipWinding = (i * 7 + j * 3) % 5 == 0;   // some clockwise triangles too
      if (rng() & 1u) {
        indices.insert(indices.end(), {a, b, c});
        indices.insert(indices.end(), flipWinding ? std::initializer_list<uint32_t>{a, d, c} : std::initializer_list<uint32_t>{a, c, d});
      } else {
        indices.insert(indices.end(), {a, b, d});
        indices.insert(indices.end(), flipWinding ? std::initializer_list<uint32_t>{b, d, c} : std::initializer_list<uint32_t>{b, c, d});
      }
    }
  }
  return makeMesh(vertices, std::move(indices));
}

// Clip-space triangles the clipper must cut, in three kinds taken in turn; each has one
// vertex well inside the view volume so most of them leave something on screen:
//   near: a vertex behind the near plane (z < -w, w > 0);
//   w < 0: a vertex behind the eye;
//   side: vertices beyond the x / y planes (|x| or |y| up to 3w).
std::vector<Vertex> clippedTriangles(std::mt19937& rng, int count) {
  auto insideVertex = [&] {
    const float w = uniform(rng, 0.5f, 3.0f);
    return glm::vec4(uniform(rng, -0.9f, 0.9f) * w, uniform(rng, -0.9f, 0.9f) * w, uniform(rng, -0.9f, 0.9f) * w, w);
  };
  std::vector<Vertex> vertices;
  for (int i = 0; i < count; ++i) {
    glm::vec4 p[3] = {insideVertex(), insideVertex(), insideVertex()};
    switch (i % 3) {
      case 0: {  // near plane
        const float w = uniform(rng, 0.3f, 3.0f);
        p[1] = glm::vec4(uniform(rng, -1.5f, 1.5f) * w, uniform(rng, -1.5f, 1.5f) * w, uniform(rng, -4.0f, -1.02f) * w, w);
        if (i % 6 == 3) p[2].z = uniform(rng, -3.0f, -1.01f) * p[2].w;
        break;
      }
      case 1: {  // behind the eye
        p[1] = glm::vec4(uniform(rng, -3.0f, 3.0f), uniform(rng, -3.0f, 3.0f), uniform(rng, -3.0f, 3.0f), uniform(rng, -2.0f, -0.05f));
        if (i % 6 == 4) p[2].w = -p[2].w;
        break;
      }
      default: {  // x / y planes
        for (int v = 1; v < 3; ++v) {
          const float w = p[v].w;
          p[v].x = uniform(rng, -3.0f, 3.0f) * w;
          p[v].y = uniform(rng, -3.0f, 3.0f) * w;
        }
        break;
      }
    }
    for (const glm::vec4& q : p) vertices.push_back({q, randomOpaqueColor(rng)});
  }
  return vertices;
}

void checkEveryPixelOnce(const CaseResult& r, const TargetDesc& target) {
  const std::string where = targetName(target);
  CAPTURE(where);
  int notOnce = 0;
  for (int c : r.counts) notOnce += c != 1;
  CHECK(notOnce == 0);
  CHECK(int(r.counts.size()) == target.width * target.height);
}

}  // namespace

TEST_SUITE("raster_vs_gl") {
  TEST_CASE("(a) random triangles: slivers, sub-pixel, half-pixel-grid vertices, perspective w") {
    BackendPair backends;
    const TargetDesc targets[] = {
        {64, 64, TexelFormat::RGBA8, TexelFormat::Depth24},
        {100, 75, TexelFormat::RGBA8, TexelFormat::Depth24},
        {64, 64, TexelFormat::RGBA8, TexelFormat::Depth16},
        {80, 60, std::nullopt, std::nullopt, true},
    };
    uint32_t seed = 1001;
    for (const TargetDesc& target : targets)
      for (int run = 0; run < 3; ++run, ++seed)
        compareCase(backends, "(a) 300 random triangles, seed " + std::to_string(seed), target,
                    randomTriangleMesh(seed, 300, target.width, target.height));
  }

  TEST_CASE("(b) a jittered mesh with shared edges covers every pixel exactly once") {
    BackendPair backends;
    std::mt19937 rng(2002);
    const TargetDesc targets[] = {
        {64, 64, TexelFormat::RGBA8, TexelFormat::Depth24},
        {67, 131, TexelFormat::RGBA8, TexelFormat::Depth24},
        {96, 40, TexelFormat::RGBA8, TexelFormat::Depth16},
        {72, 56, std::nullopt, std::nullopt, true},
    };
    for (const TargetDesc& target : targets) {
      for (float cell : {3.0f, 8.5f}) {
        const CaseResult r = compareCase(backends, "(b) jittered shared-edge mesh, cell " + std::to_string(cell), target,
                                         jitteredGridMesh(rng, target.width, target.height, cell));
        checkEveryPixelOnce(r, target);
      }
    }
  }

  TEST_CASE("(c) triangles crossing the near plane, w < 0 and the x/y planes are clipped alike") {
    BackendPair backends;
    std::mt19937 rng(3003);
    const TargetDesc targets[] = {
        {64, 64, TexelFormat::RGBA8, TexelFormat::Depth24},
        {50, 70, TexelFormat::RGBA8, TexelFormat::Depth16},
    };
    for (const TargetDesc& target : targets) {
      for (int run = 0; run < 3; ++run) {
        const CaseResult r = compareCase(backends, "(c) 150 clipped triangles", target, makeMesh(clippedTriangles(rng, 150)));
        CHECK(r.covered > target.width * target.height / 4);   // the clipped triangles do reach the screen
      }
    }
  }

  TEST_CASE("(d) a fullscreen triangle covers every pixel once") {
    BackendPair backends;
    std::mt19937 rng(4004);
    const TargetDesc targets[] = {
        {64, 64, TexelFormat::RGBA8, TexelFormat::Depth24},
        {130, 70, TexelFormat::RGBA8, TexelFormat::Depth16},
        {40, 24, std::nullopt, std::nullopt, true},
    };
    for (const TargetDesc& target : targets) {
      for (bool perspective : {false, true}) {
        const CaseResult r = compareCase(backends, perspective ? "(d) fullscreen triangle, perspective w" : "(d) fullscreen triangle",
                                         target, fullscreenTriangle(rng, perspective));
        checkEveryPixelOnce(r, target);
      }
    }
  }

  TEST_CASE("(e) odd target sizes: 1x1, 7x5, 33x17, 67x131, 257x3") {
    BackendPair backends;
    std::mt19937 rng(5005);
    const int sizes[][2] = {{1, 1}, {7, 5}, {33, 17}, {67, 131}, {257, 3}};
    for (const auto& size : sizes) {
      for (TexelFormat depth : {TexelFormat::Depth24, TexelFormat::Depth16}) {
        const TargetDesc target{size[0], size[1], TexelFormat::RGBA8, depth};
        compareCase(backends, "(e) 120 random triangles", target, randomTriangleMesh(rng(), 120, size[0], size[1]));
        const CaseResult r = compareCase(backends, "(e) fullscreen triangle", target, fullscreenTriangle(rng, true));
        checkEveryPixelOnce(r, target);
        const CaseResult mesh = compareCase(backends, "(e) jittered shared-edge mesh", target,
                                            jitteredGridMesh(rng, size[0], size[1], 4.0f));
        checkEveryPixelOnce(mesh, target);
      }
    }
  }
}
