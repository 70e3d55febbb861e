// Shared machinery of the GL-comparison tests (see gl_compare_helpers.h).
#include "tests/gl_compare_helpers.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace gltest {

MeshData makeMesh(const std::vector<Vertex>& vertices, std::vector<uint32_t> indices) {
  MeshData mesh;
  mesh.strideFloats = 8;
  mesh.attributes = {{0, 4, 0}, {1, 4, 4}};
  mesh.vertices.reserve(vertices.size() * 8);
  for (const Vertex& v : vertices) {
    for (int c = 0; c < 4; ++c) mesh.vertices.push_back(v.position[c]);
    for (int c = 0; c < 4; ++c) mesh.vertices.push_back(v.attribute[c]);
  }
  if (indices.empty()) {
    for (uint32_t i = 0; i + 2 < vertices.size(); i += 3) indices.insert(indices.end(), {i, i + 1, i + 2});
  }
  mesh.indices = std::move(indices);
  return mesh;
}

glm::vec4 clipFromWindow(glm::vec2 window, float ndcZ, float w, int width, int height) {
  const float ndcX = window.x / float(width) * 2.0f - 1.0f;
  const float ndcY = window.y / float(height) * 2.0f - 1.0f;
  return {ndcX * w, ndcY * w, ndcZ * w, w};
}

MeshData gridMesh(int width, int height, int cell, const std::function<GridCell(int, int)>& at) {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  for (int row = 0; row * cell < height; ++row) {
    for (int column = 0; column * cell < width; ++column) {
      const GridCell c = at(column, row);
      const float x0 = float(column * cell), x1 = float(column * cell + cell);
      const float y1 = float(height - row * cell), y0 = y1 - float(cell);   // window y, up
      const auto base = uint32_t(vertices.size());
      for (glm::vec2 p : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y1)})
        vertices.push_back({clipFromWindow(p, c.ndcZ, 1.0f, width, height), c.attribute});
      indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  }
  return makeMesh(vertices, std::move(indices));
}

Rendered render(Backend& backend, const TargetDesc& target, const std::vector<DrawCall>& draws, const ClearOp& clear) {
  Handle framebuffer = scenes::kDefaultFramebuffer;
  if (target.defaultFramebuffer) {
    backend.resizeDefaultFramebuffer(target.width, target.height);
  } else {
    scenes::FramebufferDesc fb;
    if (target.color) fb.colorTextures = {backend.createTexture({target.width, target.height, *target.color, {}})};
    if (target.depth) fb.depthTexture = backend.createTexture({target.width, target.height, *target.depth, {}});
    framebuffer = backend.createFramebuffer(fb);
  }
  backend.beginPass(framebuffer, {0, 0, target.width, target.height}, clear);
  for (const DrawCall& d : draws) {
    const Handle program = backend.createProgram(d.program);
    const Handle mesh = backend.createMesh(d.mesh);
    for (const auto& [name, value] : d.uniforms) backend.setUniform(program, name, value);
    backend.draw(program, mesh, d.state);
  }
  backend.finish();
  Rendered result;
  if (target.color || target.defaultFramebuffer) result.color = backend.readColor(framebuffer);
  if (target.depth || target.defaultFramebuffer) result.depth = backend.readDepth(framebuffer);
  return result;
}

BackendPair::BackendPair() : raster(scenes::makeRasterBackend(0)), gl(scenes::makeGlBackend()) {}

BothRendered renderBoth(BackendPair& backends, const TargetDesc& target, const std::vector<DrawCall>& draws,
                        const ClearOp& clear) {
  return {render(*backends.raster, target, draws, clear), render(*backends.gl, target, draws, clear)};
}

ClearOp clearAll() {
  ClearOp clear;
  clear.color = true;
  clear.colorValue = glm::vec4(0.0f);
  clear.depth = true;
  clear.depthValue = 1.0f;
  return clear;
}

std::string describeRgba8(const ImageData& image, int x, int row) {
  const size_t at = (size_t(row) * size_t(image.width) + size_t(x)) * 4;
  std::ostringstream s;
  s << int(image.rgba8[at]) << "," << int(image.rgba8[at + 1]) << "," << int(image.rgba8[at + 2]) << ","
    << int(image.rgba8[at + 3]);
  return s.str();
}

std::string describeFloats(const ImageData& image, int x, int row) {
  const size_t at = (size_t(row) * size_t(image.width) + size_t(x)) * 4;
  std::ostringstream s;
  s.precision(9);
  for (int c = 0; c < 4; ++c) s << (c ? "," : "") << image.floats[at + size_t(c)];
  return s.str();
}

float uniform(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

glm::vec4 randomOpaqueColor(std::mt19937& rng) {
  return {uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), 1.0f};
}

glm::vec2 clampToTarget(glm::vec2 p, int width, int height) {
  return {std::clamp(p.x, 0.0f, float(width)), std::clamp(p.y, 0.0f, float(height))};
}

MeshData fullscreenTriangle(std::mt19937& rng, bool perspective) {
  const glm::vec2 ndc[3] = {{-1.0f, -1.0f}, {3.0f, -1.0f}, {-1.0f, 3.0f}};
  std::vector<Vertex> vertices;
  for (const glm::vec2& p : ndc) {
    const float w = perspective ? uniform(rng, 0.5f, 3.0f) : 1.0f;
    const float z = uniform(rng, -0.9f, 0.9f);
    vertices.push_back({glm::vec4(p.x * w, p.y * w, z * w, w), randomOpaqueColor(rng)});
  }
  return makeMesh(vertices);
}

std::string targetName(const TargetDesc& t) {
  std::ostringstream s;
  s << t.width << "x" << t.height;
  if (t.defaultFramebuffer) s << " default framebuffer";
  else s << (t.depth == TexelFormat::Depth16 ? " Depth16" : " Depth24");
  return s.str();
}

namespace {

std::string where(int x, int row) {
  return "pixel (x " + std::to_string(x) + ", row " + std::to_string(row) + " from the top)";
}

void requireSameShape(const ImageData& a, const ImageData& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  REQUIRE(a.format == b.format);
}

}  // namespace

Rgba8Comparison compareRgba8(const ImageData& raster, const ImageData& gl, const uint8_t clear[4]) {
  requireSameShape(raster, gl);
  REQUIRE(raster.rgba8.size() == size_t(raster.width) * size_t(raster.height) * 4);
  REQUIRE(gl.rgba8.size() == raster.rgba8.size());
  Rgba8Comparison r;
  for (int row = 0; row < raster.height; ++row) {
    for (int x = 0; x < raster.width; ++x) {
      const size_t at = (size_t(row) * size_t(raster.width) + size_t(x)) * 4;
      const bool coveredA = std::memcmp(&raster.rgba8[at], clear, 4) != 0;
      const bool coveredB = std::memcmp(&gl.rgba8[at], clear, 4) != 0;
      r.coveredA += coveredA;
      r.coveredB += coveredB;
      const std::string text = where(x, row) + ": raster " + describeRgba8(raster, x, row) + " vs gl " + describeRgba8(gl, x, row);
      if (coveredA != coveredB) {
        if (r.coverageDiffs++ == 0) r.firstCoverageDiff = text;
        continue;
      }
      if (!coveredA) continue;
      int step = 0;
      for (int c = 0; c < 4; ++c) step = std::max(step, std::abs(int(raster.rgba8[at + size_t(c)]) - int(gl.rgba8[at + size_t(c)])));
      if (step > 0 && r.colorDiffs++ == 0) r.firstColorDiff = text;
      r.maxStep = std::max(r.maxStep, step);
    }
  }
  return r;
}

DepthComparison compareDepth(const ImageData& raster, const ImageData& gl) {
  requireSameShape(raster, gl);
  REQUIRE(raster.depthBits == gl.depthBits);
  REQUIRE(raster.depth.size() == size_t(raster.width) * size_t(raster.height));
  REQUIRE(gl.depth.size() == raster.depth.size());
  DepthComparison r;
  for (int row = 0; row < raster.height; ++row) {
    for (int x = 0; x < raster.width; ++x) {
      const size_t at = size_t(row) * size_t(raster.width) + size_t(x);
      const uint32_t a = raster.depth[at], b = gl.depth[at];
      if (a == b) continue;
      const uint32_t diff = a > b ? a - b : b - a;
      if (r.diffs++ == 0) r.firstDiff = where(x, row) + ": raster " + std::to_string(a) + " vs gl " + std::to_string(b);
      r.maxDiff = std::max(r.maxDiff, diff);
    }
  }
  return r;
}

FloatComparison compareFloatBits(const ImageData& raster, const ImageData& gl) {
  requireSameShape(raster, gl);
  REQUIRE(raster.floats.size() == size_t(raster.width) * size_t(raster.height) * 4);
  REQUIRE(gl.floats.size() == raster.floats.size());
  FloatComparison r;
  for (int row = 0; row < raster.height; ++row) {
    for (int x = 0; x < raster.width; ++x) {
      const size_t at = (size_t(row) * size_t(raster.width) + size_t(x)) * 4;
      bool same = true;
      for (int c = 0; c < 4; ++c) same = same && bitsOf(raster.floats[at + size_t(c)]) == bitsOf(gl.floats[at + size_t(c)]);
      if (!same && r.diffs++ == 0)
        r.firstDiff = where(x, row) + ": raster " + describeFloats(raster, x, row) + " vs gl " + describeFloats(gl, x, row);
    }
  }
  return r;
}

}  // namespace gltest
