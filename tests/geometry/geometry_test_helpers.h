// Small builders shared by the geometry stage's tests (clip, setup, bin):
// vertex records made by hand, a framebuffer-sized coverage count evaluated with
// EdgeFunction::at, and the viewport transform of an FBO. No assets, no GL.
#pragma once

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "raster/contract.h"
#include "raster/geometry/setup.h"
#include "raster/geometry/vertex_stage.h"

namespace geometry_test {

using raster::SetupTriangle;
namespace record = raster::vertex_record;

// A vertex record holding only what setupTriangle reads: window x, y, z, 1/w and varyings.
// The clip position is (x, y, z, 1), which setup never reads.
inline std::vector<float> windowVertex(float x, float y, float z = 0.5f, float oow = 1.0f,
                                       std::initializer_list<float> varyings = {}) {
  std::vector<float> r(size_t(record::kVaryings) + varyings.size(), 0.0f);
  r[record::kClip + 0] = x;
  r[record::kClip + 1] = y;
  r[record::kClip + 2] = z;
  r[record::kClip + 3] = 1.0f;
  r[record::kWindow + 0] = x;
  r[record::kWindow + 1] = y;
  r[record::kWindow + 2] = z;
  r[record::kWindow + 3] = oow;
  size_t i = record::kVaryings;
  for (float v : varyings) r[i++] = v;
  return r;
}

// A vertex at pixel centre (px, py): window (px + 0.5, py + 0.5), snapped to fixed (256 px, 256 py).
inline std::vector<float> atPixelCentre(int px, int py) { return windowVertex(float(px) + 0.5f, float(py) + 0.5f); }

// The viewport transform of an FBO covering the whole width x height framebuffer (no flip):
// clip [-1, 1] maps to window [0, width] and [0, height], z to [0, 1].
inline raster::ViewportTransform fboViewport(int width, int height) {
  raster::ViewportTransform v;
  v.scale[0] = 0.5f * float(width);
  v.scale[1] = 0.5f * float(height);
  v.scale[2] = 0.5f;
  v.translate[0] = 0.5f * float(width);
  v.translate[1] = 0.5f * float(height);
  v.translate[2] = 0.5f;
  return v;
}

// Shaded vertices from clip positions and varyings, window positions and clip masks made
// as the vertex stage makes them (fma(x * oow, scale, translate); vertex_stage::clipMask).
struct ClipVertex {
  std::array<float, 4> clip;
  std::vector<float> varyings;
};
inline raster::ShadedVertices shadeByHand(const std::vector<ClipVertex>& vertices, int varyingFloats,
                                          const raster::ViewportTransform& vp) {
  raster::ShadedVertices s;
  s.varyingFloats = varyingFloats;
  s.stride = record::kVaryings + varyingFloats;
  s.data.assign(vertices.size() * size_t(s.stride), 0.0f);
  s.clipMask.assign(vertices.size(), 0);
  for (size_t i = 0; i < vertices.size(); ++i) {
    float* r = s.record(int(i));
    const auto& c = vertices[i].clip;
    const float oow = 1.0f / c[3];
    for (int k = 0; k < 4; ++k) r[record::kClip + k] = c[k];
    for (int k = 0; k < 3; ++k) r[record::kWindow + k] = std::fma(c[k] * oow, vp.scale[k], vp.translate[k]);
    r[record::kWindow + 3] = oow;
    for (int v = 0; v < varyingFloats; ++v) r[record::kVaryings + v] = vertices[i].varyings[size_t(v)];
    s.clipMask[i] = raster::vertex_stage::clipMask(r + record::kClip);
  }
  return s;
}

// Whether pixel centre (px, py) is inside all three edges (bounds not consulted).
inline bool insideEdges(const SetupTriangle& t, int px, int py) {
  return t.edge[0].at(px, py) > 0 && t.edge[1].at(px, py) > 0 && t.edge[2].at(px, py) > 0;
}

inline std::string pixelName(int x, int y) {
  char text[32];
  std::snprintf(text, sizeof text, "(%d, %d)", x, y);
  return text;
}

// How many set-up triangles cover each pixel of a width x height framebuffer, coverage
// evaluated with EdgeFunction::at over each triangle's bounds (as the tile stage walks it).
struct Coverage {
  int width, height;
  std::vector<int> count;
  Coverage(int w, int h) : width(w), height(h), count(size_t(w) * size_t(h), 0) {}
  int at(int x, int y) const { return count[size_t(y) * size_t(width) + size_t(x)]; }

  // Adds a triangle, and checks its bounds: inside the framebuffer, and holding every pixel
  // of the framebuffer its edges cover (a bounds off-by-one that drops covered pixels fails).
  void add(const SetupTriangle& t) {
    CHECK(t.minX >= 0);
    CHECK(t.minY >= 0);
    CHECK(t.maxX <= width - 1);
    CHECK(t.maxY <= height - 1);
    int missed = 0;
    std::string first;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const bool inBounds = x >= t.minX && x <= t.maxX && y >= t.minY && y <= t.maxY;
        if (inBounds) {
          if (insideEdges(t, x, y)) count[size_t(y) * size_t(width) + size_t(x)]++;
        } else if (insideEdges(t, x, y) && missed++ == 0) {
          first = pixelName(x, y);
        }
      }
    INFO("first pixel covered by the edges but outside the bounds: ", first);
    CHECK(missed == 0);
  }
  // The covered pixels, as (x, y) pairs in row order.
  std::vector<std::pair<int, int>> pixels() const {
    std::vector<std::pair<int, int>> out;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        if (at(x, y) > 0) out.emplace_back(x, y);
    return out;
  }
};

// Checks the count of every pixel against expected(x, y), as one assertion naming the first
// few pixels that differ.
template <class Expected>
void checkCoverage(const Coverage& c, Expected expected) {
  int mismatches = 0;
  std::string first;
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const int want = expected(x, y);
      if (c.at(x, y) != want && mismatches++ < 4) {
        char text[64];
        std::snprintf(text, sizeof text, "(%d, %d): %d not %d; ", x, y, c.at(x, y), want);
        first += text;
      }
    }
  INFO("pixels covered the wrong number of times: ", first);
  CHECK(mismatches == 0);
}

// The pixels one triangle covers inside a width x height framebuffer.
inline std::vector<std::pair<int, int>> coveredPixels(const SetupTriangle& t, int width, int height) {
  Coverage c(width, height);
  c.add(t);
  return c.pixels();
}

// A SetupState for an FBO (top-left rule) or a window-system buffer (bottom-left rule).
inline raster::SetupState setupState(int width, int height, bool bottomEdgeRule = false, int varyingFloats = 0) {
  raster::SetupState s;
  s.framebufferWidth = width;
  s.framebufferHeight = height;
  s.bottomEdgeRule = bottomEdgeRule;
  s.varyingFloats = varyingFloats;
  return s;
}

// The set-up triangles and varying planes a test collects.
struct SetupOutput {
  raster::TriangleList triangles;
  raster::PlaneList planes;
  raster::SetupLists lists() { return raster::SetupLists{triangles, planes}; }
};

inline bool setUp(const raster::SetupState& state, const std::vector<float>& a, const std::vector<float>& b,
                  const std::vector<float>& c, SetupOutput& out) {
  return raster::setupTriangle(state, a.data(), b.data(), c.data(), out.lists());
}

inline bool sameEdge(const raster::EdgeFunction& a, const raster::EdgeFunction& b) {
  return a.c == b.c && a.dcdx == b.dcdx && a.dcdy == b.dcdy;
}

}  // namespace geometry_test
