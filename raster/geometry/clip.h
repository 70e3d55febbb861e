// Stage 2, clipping: one triangle of shaded vertices in, a convex polygon out.
//
// A port of Mesa's draw_pipe_clip.c (do_clip_tri), which llvmpipe uses with clipping on all
// six frustum planes (no guard band: "initial state for clipping - enabled, with no
// guardband", lp_context.c). Matching its arithmetic matters: the window positions of the
// vertices it makes decide the snapped edges, and so the coverage.
//   - planes in bit order: -x+w, x+w, -y+w, y+w, z+w, -z+w (draw_context.c);
//   - new vertex = out + t * (in - out) for the clip position and every varying, with t
//     chosen so it is computed from the vertex inside (draw_pipe_clip.c interp);
//   - its window position in plain C float math: x * (1/w) * scale + translate (no FMA);
//   - a NaN or Inf plane distance discards the triangle.
// The result is a fan emitted as (p[i-1], p[i], p[0]) for GL's last-vertex convention.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "raster/contract.h"

namespace raster::clip {

struct Polygon {
  int count = 0;
  const float* vertex[limits::kMaxClippedVertices + 1];  // records (ShadedVertices layout)
};

class Clipper {
 public:
  Clipper(int varyingFloats, const ViewportTransform& viewport);
  // Clips against the planes whose bits are set in `mask` (the OR of the vertices' masks).
  // Returns a polygon with fewer than 3 vertices when nothing is left. Pointers stay valid
  // until the next call.
  const Polygon& clipTriangle(const float* v0, const float* v1, const float* v2, unsigned mask);

 private:
  const float* interpolate(float t, const float* out, const float* in);

  int stride_;
  ViewportTransform viewport_;
  std::vector<float> scratch_;   // storage for vertices made by clipping
  int scratchUsed_ = 0;
  Polygon polygons_[2];
};

}  // namespace raster::clip
