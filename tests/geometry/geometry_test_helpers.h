// Shaded vertex records built by hand for the geometry stage's tests.
#pragma once

#include <array>
#include <vector>

#include "raster/contract.h"

namespace geometry_test {

// A record (contract.h, vertex_record) with a clip position, a window position and
// varyings; the window position is given directly (setup reads only it).
struct Vertex {
  std::vector<float> data;
  const float* get() const { return data.data(); }
};

inline Vertex windowVertex(float x, float y, float z = 0.5f, float oneOverW = 1.0f, std::vector<float> varyings = {}) {
  Vertex v;
  v.data = {0, 0, 0, 1, x, y, z, oneOverW};
  v.data.insert(v.data.end(), varyings.begin(), varyings.end());
  return v;
}

inline Vertex clipVertex(float x, float y, float z, float w, std::vector<float> varyings = {}) {
  Vertex v;
  v.data = {x, y, z, w, 0, 0, 0, 0};
  v.data.insert(v.data.end(), varyings.begin(), varyings.end());
  return v;
}

// Whether a set-up triangle covers pixel (px, py): every edge function positive there, and
// the pixel inside the triangle's bounds (the walk visits only those).
inline bool covers(const raster::SetupTriangle& tri, int px, int py) {
  if (px < tri.minX || px > tri.maxX || py < tri.minY || py > tri.maxY) return false;
  for (const raster::EdgeFunction& e : tri.edge)
    if (e.at(px, py) <= 0) return false;
  return true;
}

}  // namespace geometry_test
