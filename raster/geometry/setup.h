// Stage 3, triangle setup: three window-space vertices in, a rasterizable triangle out.
//
// Follows llvmpipe: lp_setup_tri.c for snapping, orientation, culling and the edge
// functions; lp_state_setup.c for the attribute planes and polygon offset.
//
// Fixed point: window x/y are snapped to 8 sub-pixel bits relative to pixel centres,
//   fixed = roundToNearestEven((v - 0.5f) * 256.0f)                 (calc_fixed_position)
// so integer pixel coordinates (px, py) in fixed units are pixel centres. The area sign is
// an exact 64-bit cross product; zero area is dropped; "clockwise" triangles (area < 0 in
// memory coordinates) are made counter-clockwise by swapping v0 and v1.
//
// Edge i runs from v[i] to v[i+1]; in memory coordinates (row 0 first):
//   dcdx = y[i] - y[i+1],  dcdy = x[i] - x[i+1],  c = dcdx * x[i] - dcdy * y[i]   (int64)
//   c += 1 for left edges (dcdx < 0), and for horizontal edges by the fill rule:
//   dcdy > 0 under top-left (FBOs), dcdy < 0 under bottom-left (window-system buffers).
// A pixel centre (px, py) is covered when, for all three edges,
//   c - dcdx * 256 * px + dcdy * 256 * py > 0.
// In GL's y-up window coordinates both cases are the same rule: left and bottom edges
// are inclusive.
//
// Planes: every interpolated quantity a gets a0, dadx, dady in float32 with the setup
// JIT's exact operation order, referenced to pixel (0, 0)'s centre; perspective varyings
// are premultiplied by 1/w. Fragments evaluate fma(dady, py, fma(dadx, px, a0)).
//
// setupTriangle is the reference, one triangle at a time; setup_avx512.h sets up 16 at once
// (assemble.cpp batches unclipped triangles for it) and appends the same records.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/contract.h"

namespace raster {

struct SetupState {
  int framebufferWidth = 0;
  int framebufferHeight = 0;
  bool bottomEdgeRule = false;       // window-system (flipped) framebuffer
  bool cullBack = false;             // GL_CULL_FACE with GL_BACK, front = CCW in GL
  bool polygonOffset = false;
  float offsetFactor = 0.0f;
  float offsetUnitsScaled = 0.0f;    // units * 2 * mrd, as llvmpipe 22.3 computes it
  int varyingFloats = 0;
  uint32_t drawIndex = 0;            // which draw of the pass the triangles belong to
};

// The part of the pass's lists reserved for a chunk of a large draw set up in parallel
// (Renderer::setUpChunked): a slot for each of its primitives, written in place, so that
// nothing is copied after. What does not fit (clipping that makes more triangles than the
// chunk has primitives) goes on in `spill`, which the renderer appends after the draw.
struct SetupWindow {
  size_t first = 0, next = 0, end = 0;   // the window's slots in the pass's triangles
  size_t nextPlane = 0;                  // the next of its slots in the pass's varying planes
  bool spilling = false;                 // the window is full: the last triangle went to spill
  TriangleList spill;
  PlaneList spillPlanes;                 // the spilled triangles' planes (varyingBase counts from 0 here)
  size_t written() const { return next - first + spill.size(); }
};

// Where set-up triangles are appended: the triangle and, for each, its varying planes,
// at the lists' ends, or into a window of them (already sized).
struct SetupLists {
  TriangleList& triangles;
  PlaneList& varyingPlanes;
  std::vector<uint32_t>* origins = nullptr;   // pixel history only: each triangle's origin (contract.h)
  SetupWindow* window = nullptr;

  // A new triangle's record, left for the caller to fill (the list's allocator zeroes nothing).
  SetupTriangle& appendTriangle() const {
    if (!window) return triangles.emplace_back();
    window->spilling = window->next == window->end;
    return window->spilling ? window->spill.emplace_back() : triangles[window->next++];
  }
  // `count` planes for the triangle appendTriangle just gave: tri.varyingBase set.
  Plane* appendPlanes(SetupTriangle& tri, int count) const {
    if (window && !window->spilling) {
      tri.varyingBase = uint32_t(window->nextPlane);
      window->nextPlane += size_t(count);
      return varyingPlanes.data() + tri.varyingBase;
    }
    PlaneList& list = window ? window->spillPlanes : varyingPlanes;
    tri.varyingBase = uint32_t(list.size());
    list.resize(list.size() + size_t(count));
    return list.data() + tri.varyingBase;
  }
};

// Polygon offset units in depth-buffer terms: (float)(units * mrd * 2) computed in double,
// mrd = 1 / (2^bits - 1) (lp_state_setup.c of Mesa 22.3; measured in the reference notes).
float polygonOffsetUnits(float units, int depthBits);

// Sets up one triangle of shaded vertex records (contract.h, vertex_record). Appends it and
// its varying planes to `out` unless it is culled, has no area after snapping, has a window
// coordinate that is NaN or beyond limits::kMaxWindowCoordinate, or has pixel bounds that are
// empty within the framebuffer; returns whether it did. (A small triangle between pixel
// centres keeps non-empty bounds and is set up, covering nothing: llvmpipe's bounds are as
// conservative.)
bool setupTriangle(const SetupState& state, const float* v0, const float* v1, const float* v2, SetupLists out);

namespace setup_detail {

// The setup JIT's per-triangle derived values (init_args), from the window positions of
// the vertices in their rotated order.
struct PlaneSetup {
  float x0Center, y0Center;
  float dx01Ooa, dy01Ooa, dx20Ooa, dy20Ooa;
};

// calc_coef4: the plane of one quantity with values a0, a1, a2 at the three vertices.
inline Plane planeOf(const PlaneSetup& s, float a0, float a1, float a2) {
  const float da01 = a0 - a1;
  const float da20 = a2 - a0;
  Plane p;
  p.dadx = da01 * s.dy20Ooa - da20 * s.dy01Ooa;
  p.dady = da20 * s.dx01Ooa - da01 * s.dx20Ooa;
  p.a0 = a0 - (p.dadx * s.x0Center + p.dady * s.y0Center);
  return p;
}

// The varying planes of the triangle `tri` just appended, from its vertex records in
// rotated order: appended to out.varyingPlanes, tri.varyingBase set.
void appendVaryingPlanes(const SetupState& state, const PlaneSetup& s, const float* v0, const float* v1,
                         const float* v2, SetupTriangle& tri, const SetupLists& out);

}  // namespace setup_detail

}  // namespace raster

#include "raster/geometry/setup_avx512.h"
