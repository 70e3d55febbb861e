// Interpolation: the values a fragment's lanes see, from the triangle's planes.
//
// As llvmpipe's lp_bld_interp.c: a plane is evaluated at pixel centres as
// fma(dady, y, fma(dadx, x, a0)), planes referenced to pixel (0, 0)'s centre, so lanes at
// small integer pixel coordinates are exact; varyings are perspective-correct through an
// exact 1/w, w itself interpolated from the 1/w plane; window z is the z plane plus the
// polygon offset, at most 1 (clamped to [0, 1] only for the depth test).
#pragma once

#include <cstddef>

#include "raster/contract.h"
#include "raster/methods.h"
#include "raster/simd/gl_math.h"
#include "raster/simd/lane_layout.h"

namespace raster {

template <class F>
F evaluatePlane(const Plane& p, F px, F py) {
  return simd::fma(F(p.dady), py, simd::fma(F(p.dadx), px, F(p.a0)));
}

// A fragment's window z: the z plane plus the polygon offset, then min(z, 1) as
// lp_bld_interp.c takes it with depth clamping off (GL's default): minps returns its second
// operand on NaN, so a NaN z (the planes of a triangle whose float area is 0 although its
// snapped area is not) is 1.0 for the depth test and gl_FragCoord, not 0.
template <class F>
F fragmentDepth(const SetupTriangle& tri, F px, F py) {
  return simd::min(evaluatePlane(tri.z, px, py) + F(tri.depthOffset), F(1.0f));
}

// The varying count of interpolateFragment's draw, where its caller knows it when compiled
// (a program's own fullscreen tile loop, covered_tile_avx2.h): the loop over the varyings then
// unrolls and their values can stay in registers on their way into the port. kVaryingsOfDraw:
// read from the draw.
inline constexpr int kVaryingsOfDraw = -1;

// Fragment inputs of lanes at pixels (px, py) with window z: perspective-correct varyings
// and gl_FragCoord, for a group or a pair of groups (the same operations per lane).
template <int kVaryingFloats = kVaryingsOfDraw, class F>
[[gnu::always_inline]] inline void interpolateFragment(const TileJob& job, const SetupTriangle& tri, F px, F py, F z,
                                                       FragmentInput<F>& in, F* varyings) {
  const Framebuffer& fb = *job.framebuffer;
  // Varyings: a = fma(dady, y, fma(dadx, x, a0)) * (1 / w), w from the 1/w plane. The
  // method set (methods.h) may ask for an approximate 1 / w (div=approx), or for
  // screen-linear varyings (interp=affine: setup made planes of the plain values).
  // A triangle whose vertices all have w = 1 (a post pass's fullscreen triangle, a 2D
  // draw) has the 1/w plane (1, 0, 0): w is 1 at every lane, and so are 1 / w and both
  // methods' reciprocal of it, and a product with 1 changes no bit, so they are skipped.
  const MethodSet& methodSet = methods::active();
  const bool unitW = tri.w.a0 == 1.0f && tri.w.dadx == 0.0f && tri.w.dady == 0.0f;
  const F w = unitW ? F(1.0f) : evaluatePlane(tri.w, px, py);
  const int varyingCount = kVaryingFloats != kVaryingsOfDraw ? kVaryingFloats : job.draws[tri.drawIndex].varyingFloats;
  const Plane* planes = job.varyingPlanes.data() + tri.varyingBase;
  if (!methods::perspectiveVaryings(methodSet.interp) || unitW) {
    for (int v = 0; v < varyingCount; ++v) varyings[v] = evaluatePlane(planes[v], px, py);
  } else {
    const F oow = methods::approximateDivide(methodSet.div) ? glsl::reciprocalApprox(w) : F(1.0f) / w;
    for (int v = 0; v < varyingCount; ++v) varyings[v] = evaluatePlane(planes[v], px, py) * oow;
  }

  // gl_FragCoord.y is GL's (y up): mirrored for window-system buffers (wpos_ytransform).
  const F fragY = fb.flipY ? F(float(fb.height)) - (py + F(0.5f)) : py + F(0.5f);
  in.gl_FragCoord = glsl::vec4<F>(px + F(0.5f), fragY, z, w);
  in.gl_FrontFacing = tri.frontFacing;
}

// Prepares `group` for the lane group `at` whose covered lanes passed their depth test (z as
// the test computed it): its pixel indices, triangle, pixel centres and depth.
template <class F>
[[gnu::always_inline]] inline void prepareGroup(const TileJob& job, const SetupTriangle& tri, const LaneLayout<F>& layout,
                                                GroupAt at, F z, FragmentGroup<F>& group) {
  const Framebuffer& fb = *job.framebuffer;
  const DrawRecord& draw = job.draws[tri.drawIndex];
  const size_t origin = size_t(at.y) * size_t(fb.width) + size_t(at.x);
  for (int i = 0; i < F::kCount; ++i) group.texel[i] = origin + layout.texel[i];
  group.outputs = colorOutputsWritten(draw, fb);
  group.draw = &draw;
  group.laneMask = at.laneMask;
  group.tri = &tri;
  group.px = F(float(at.x)) + layout.dxLanes;
  group.py = F(float(at.y)) + layout.dyLanes;
  group.z = z;
  group.interpolated = false;
}

// Makes a prepared group ready to shade: perspective-correct varyings (helper lanes too, so
// dFdx / dFdy see whole quads) and gl_FragCoord.
template <class F>
[[gnu::always_inline]] inline void interpolateGroup(const TileJob& job, FragmentGroup<F>& group) {
  if (group.interpolated) return;
  interpolateFragment(job, *group.tri, group.px, group.py, group.z, group.in, group.varyings);
  group.interpolated = true;
}

// prepareGroup, then interpolateGroup: for the walks that shade each group at once.
template <class F>
[[gnu::always_inline]] inline void fillGroup(const TileJob& job, const SetupTriangle& tri, const LaneLayout<F>& layout,
                                             GroupAt at, F z, FragmentGroup<F>& group) {
  prepareGroup(job, tri, layout, at, z, group);
  interpolateGroup(job, group);
}

}  // namespace raster
