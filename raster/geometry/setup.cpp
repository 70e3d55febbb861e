// Triangle setup: snapping, orientation, culling, edge functions, planes, polygon offset.
// Sources: llvmpipe lp_setup_tri.c (calc_fixed_position, triangle_both, do_triangle_ccw)
// and lp_state_setup.c (init_args, calc_coef4, lp_do_offset_tri). See setup.h.
#include "raster/geometry/setup.h"

#include <algorithm>
#include <cmath>

#include "raster/methods.h"
#include "raster/texture/format.h"

namespace raster {
namespace {

using setup_detail::PlaneSetup;
using setup_detail::planeOf;
using vertex_record::kVaryings;
using vertex_record::kWindow;
constexpr int kFixedOrder = limits::kSubPixelBits;   // FIXED_ORDER
constexpr float kFixedOne = float(limits::kSubPixelOne);

struct FixedTriangle {
  int32_t x[3], y[3];
};

// calc_fixed_position (SSE path): (v - pixel_offset) * 256, cvtps2dq.
int32_t snap(float windowCoord) { return format::roundToNearestEven((windowCoord - 0.5f) * kFixedOne); }

// lp_do_offset_tri for a unorm depth buffer: units + max(|dz/dx|, |dz/dy|) * factor.
float polygonOffset(const SetupState& state, const float* p0, const float* p1, const float* p2, float ooa) {
  const float dx01 = p0[0] - p1[0], dy01 = p0[1] - p1[1], dz01 = p0[2] - p1[2];
  const float dx20 = p2[0] - p0[0], dy20 = p2[1] - p0[1], dz20 = p2[2] - p0[2];
  const float res1 = dz20 * dy01 - dy20 * dz01;
  const float res2 = dx20 * dz01 - dz20 * dx01;
  const float dzdx = std::fabs(res1 * ooa);
  const float dzdy = std::fabs(res2 * ooa);
  const float maxSlope = (dzdx > dzdy || std::isnan(dzdx) || std::isnan(dzdy)) ? dzdx : dzdy;  // FCmp UGT
  return state.offsetUnitsScaled + maxSlope * state.offsetFactor;
}

}  // namespace

float polygonOffsetUnits(float units, int depthBits) {
  const double mrd = 1.0 / double((1u << depthBits) - 1u);
  return float(double(units) * mrd * 2.0);
}

bool setupTriangle(const SetupState& state, const float* v0, const float* v1, const float* v2, SetupLists out) {
  const float* vert[3] = {v0, v1, v2};

  // Snap, and orient by the exact area sign (triangle_both).
  // NaN or far beyond the fixed-point range: undefined in GL, dropped (limits.h).
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 2; ++c)
      if (!(std::fabs(vert[i][kWindow + c]) <= limits::kMaxWindowCoordinate)) return false;
  FixedTriangle fixed;
  for (int i = 0; i < 3; ++i) {
    fixed.x[i] = snap(vert[i][kWindow + 0]);
    fixed.y[i] = snap(vert[i][kWindow + 1]);
  }
  const int64_t dx01 = int64_t(fixed.x[0]) - fixed.x[1], dy01 = int64_t(fixed.y[0]) - fixed.y[1];
  const int64_t dx20 = int64_t(fixed.x[2]) - fixed.x[0], dy20 = int64_t(fixed.y[2]) - fixed.y[0];
  const int64_t area = dx01 * dy20 - dx20 * dy01;
  if (area == 0) return false;
  // GL's counter-clockwise (y up) is area < 0 in FBO memory rows, area > 0 when flipped.
  const bool frontFacing = state.bottomEdgeRule ? (area > 0) : (area < 0);
  if (state.cullBack && !frontFacing) return false;
  if (area < 0) {
    std::swap(vert[0], vert[1]);             // rotate_fixed_position_01
    std::swap(fixed.x[0], fixed.x[1]);
    std::swap(fixed.y[0], fixed.y[1]);
  }

  // Pixel bounds (do_triangle_ccw), trimmed to the framebuffer (draw region).
  const int adj = state.bottomEdgeRule ? 1 : 0;
  const int minX = std::max(std::min({fixed.x[0], fixed.x[1], fixed.x[2]}) >> kFixedOrder, 0);
  const int maxX = std::min((std::max({fixed.x[0], fixed.x[1], fixed.x[2]}) - 1) >> kFixedOrder, state.framebufferWidth - 1);
  const int minY = std::max((std::min({fixed.y[0], fixed.y[1], fixed.y[2]}) + adj) >> kFixedOrder, 0);
  const int maxY = std::min((std::max({fixed.y[0], fixed.y[1], fixed.y[2]}) - 1 + adj) >> kFixedOrder, state.framebufferHeight - 1);
  if (minX > maxX || minY > maxY) return false;

  // Accepted: the record is written where it stays. (Built on the stack and pushed, its
  // 128 bytes were copied through vector registers that waited on the scalar stores just
  // made: a fifth of setup's time.) The list's allocator leaves it unzeroed; every field is
  // set below.
  SetupTriangle& tri = out.appendTriangle();
  tri.minX = minX;
  tri.maxX = maxX;
  tri.minY = minY;
  tri.maxY = maxY;

  // Edge functions with the fill-rule bias.
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    EdgeFunction& e = tri.edge[i];
    const int64_t dcdx = int64_t(fixed.y[i]) - fixed.y[j];
    const int64_t dcdy = int64_t(fixed.x[i]) - fixed.x[j];
    e.c = dcdx * fixed.x[i] - dcdy * fixed.y[i];
    if (dcdx < 0) e.c++;                                   // left edges, both conventions
    else if (dcdx == 0 && (state.bottomEdgeRule ? dcdy < 0 : dcdy > 0)) e.c++;
    e.dcdx = dcdx << kFixedOrder;
    e.dcdy = dcdy << kFixedOrder;
  }

  // Planes from the unsnapped float window positions (init_args), in the rotated order.
  const float* p0 = vert[0] + kWindow;
  const float* p1 = vert[1] + kWindow;
  const float* p2 = vert[2] + kWindow;
  const float fdx01 = p0[0] - p1[0], fdy01 = p0[1] - p1[1];
  const float fdx20 = p2[0] - p0[0], fdy20 = p2[1] - p0[1];
  const float e = fdx01 * fdy20;
  const float f = fdy01 * fdx20;
  const float ooa = 1.0f / (e - f);
  tri.depthOffset = state.polygonOffset ? polygonOffset(state, p0, p1, p2, ooa) : 0.0f;

  PlaneSetup s;
  s.x0Center = p0[0] - 0.5f;
  s.y0Center = p0[1] - 0.5f;
  s.dx20Ooa = fdx20 * ooa;
  s.dy20Ooa = fdy20 * ooa;
  s.dx01Ooa = fdx01 * ooa;
  s.dy01Ooa = fdy01 * ooa;
  tri.z = planeOf(s, p0[2], p1[2], p2[2]);
  tri.w = planeOf(s, p0[3], p1[3], p2[3]);
  setup_detail::appendVaryingPlanes(state, s, vert[0], vert[1], vert[2], tri, out);
  tri.drawIndex = state.drawIndex;
  tri.frontFacing = frontFacing;
  return true;
}

void setup_detail::appendVaryingPlanes(const SetupState& state, const PlaneSetup& s, const float* v0, const float* v1,
                                       const float* v2, SetupTriangle& tri, const SetupLists& out) {
  // Perspective-correct varyings: premultiply by each vertex's 1/w (apply_perspective_corr).
  // The interp=affine method (methods.h) takes the plain values (times 1, exactly): planes
  // that are linear in screen space.
  const bool perspective = methods::perspectiveVaryings(methods::active().interp);
  const float oow0 = perspective ? v0[kWindow + 3] : 1.0f, oow1 = perspective ? v1[kWindow + 3] : 1.0f,
              oow2 = perspective ? v2[kWindow + 3] : 1.0f;
  // The list grows once per triangle (without zeroing), and the loop, free of push_back's
  // capacity checks, is one the compiler vectorizes: the same operations in every lane.
  Plane* planes = out.appendPlanes(tri, state.varyingFloats);
  const float *values0 = v0 + kVaryings, *values1 = v1 + kVaryings, *values2 = v2 + kVaryings;
  for (int v = 0; v < state.varyingFloats; ++v)
    planes[v] = planeOf(s, values0[v] * oow0, values1[v] * oow1, values2[v] * oow2);
}

}  // namespace raster
