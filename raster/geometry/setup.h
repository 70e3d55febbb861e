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
#pragma once

#include <cstdint>
#include <vector>

namespace raster {

struct EdgeFunction {
  int64_t c;       // value at pixel (0, 0), fill-rule bias included
  int64_t dcdx;    // step per pixel in x (already scaled by 256), subtracted
  int64_t dcdy;    // step per pixel in y (already scaled by 256), added
  int64_t at(int px, int py) const { return c - dcdx * px + dcdy * py; }
};

struct Plane {
  float a0, dadx, dady;
};

// A triangle ready for rasterization. Varying planes live in the owning TriangleStore.
struct SetupTriangle {
  EdgeFunction edge[3];
  int minX, minY, maxX, maxY;   // inclusive pixel bounds, already inside the framebuffer
  Plane z;                      // window z
  Plane w;                      // 1/w (the position's fourth component)
  float depthOffset;            // polygon offset, added after interpolation
  uint32_t varyingBase;         // index of the first varying Plane in the store
  uint32_t drawIndex;           // which draw of the pass
  bool frontFacing;
};

struct SetupState {
  int framebufferWidth = 0;
  int framebufferHeight = 0;
  bool bottomEdgeRule = false;       // window-system (flipped) framebuffer
  bool cullBack = false;             // GL_CULL_FACE with GL_BACK, front = CCW in GL
  bool polygonOffset = false;
  float offsetFactor = 0.0f;
  float offsetUnitsScaled = 0.0f;    // units * 2 * mrd, as llvmpipe 22.3 computes it
  int varyingFloats = 0;
};

// Polygon offset units in depth-buffer terms: (float)(units * mrd * 2) computed in double,
// mrd = 1 / (2^bits - 1) (lp_state_setup.c of Mesa 22.3; measured in the reference notes).
float polygonOffsetUnits(float units, int depthBits);

// Sets up one triangle of window-space vertex records (window xyzw at offset 4, varyings
// at offset 8). Appends it and its varying planes unless culled; returns whether it did.
bool setupTriangle(const SetupState& state, const float* v0, const float* v1, const float* v2, uint32_t drawIndex,
                   std::vector<SetupTriangle>& triangles, std::vector<Plane>& varyingPlanes);

}  // namespace raster
