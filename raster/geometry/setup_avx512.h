// Setup of 16 triangles at once (AVX-512): setupTriangle's snapping, orientation, culling,
// bounds, edge functions, polygon offset and z / w planes with one triangle per lane, the
// same operations in the same order (the int64 products in 64-bit lanes, the float ones
// without contraction, 1 / area by a true division), so every record is the one
// setupTriangle appends. Each accepted triangle's record is then written in lane order and
// its varying planes appended as setupTriangle appends them (setup_detail).
//
// Why: a detailed mesh's triangles are each a few pixels, and setting them up one by one
// in scalar code was a fifth of a depth-only pass of 12,000 of them (deferred's shadow
// map), mostly the latency of one triangle's chain of snaps, products and a division.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include <cstdint>

#include "raster/geometry/setup.h"
#include "raster/limits.h"
#include "raster/simd/intrinsics.h"

namespace raster {

// Triangles per batch.
inline constexpr int kSetupBatch = 16;

// Up to 16 triangles whose vertex records all lie in one array, each vertex given as its
// record's offset in floats from `records` (so below 2^31).
struct TriangleBatch {
  alignas(64) int32_t vertex[3][kSetupBatch];
  int count = 0;
};

namespace setup_batch_detail {

// An int64 vector pair (lanes 0-7, 8-15) from 16 int32 lanes.
struct Int64x16 {
  __m512i lo, hi;
};
inline Int64x16 widen(__m512i v) {
  return {_mm512_cvtepi32_epi64(_mm512_castsi512_si256(v)), _mm512_cvtepi32_epi64(_mm512_extracti64x4_epi64(v, 1))};
}
inline Int64x16 sub(Int64x16 a, Int64x16 b) { return {_mm512_sub_epi64(a.lo, b.lo), _mm512_sub_epi64(a.hi, b.hi)}; }
inline Int64x16 mul(Int64x16 a, Int64x16 b) { return {_mm512_mullo_epi64(a.lo, b.lo), _mm512_mullo_epi64(a.hi, b.hi)}; }
inline __mmask16 join(__mmask8 lo, __mmask8 hi) { return __mmask16(unsigned(lo) | unsigned(hi) << 8); }
inline __mmask16 lessThanZero(Int64x16 a) {
  return join(_mm512_cmplt_epi64_mask(a.lo, _mm512_setzero_si512()), _mm512_cmplt_epi64_mask(a.hi, _mm512_setzero_si512()));
}
inline __mmask16 greaterThanZero(Int64x16 a) {
  return join(_mm512_cmpgt_epi64_mask(a.lo, _mm512_setzero_si512()), _mm512_cmpgt_epi64_mask(a.hi, _mm512_setzero_si512()));
}
inline __mmask16 equalsZero(Int64x16 a) {
  return join(_mm512_cmpeq_epi64_mask(a.lo, _mm512_setzero_si512()), _mm512_cmpeq_epi64_mask(a.hi, _mm512_setzero_si512()));
}
inline void store(int64_t* to, Int64x16 a) {
  _mm512_storeu_si512(to, a.lo);
  _mm512_storeu_si512(to + 8, a.hi);
}

// planeOf (setup.h) in every lane: the same products and differences, none fused.
struct PlaneSetup16 {
  __m512 x0Center, y0Center, dx01Ooa, dy01Ooa, dx20Ooa, dy20Ooa;
};
inline void planeOf16(const PlaneSetup16& s, __m512 a0, __m512 a1, __m512 a2, float* outA0, float* outDadx, float* outDady) {
  const __m512 da01 = _mm512_sub_ps(a0, a1);
  const __m512 da20 = _mm512_sub_ps(a2, a0);
  const __m512 dadx = _mm512_sub_ps(_mm512_mul_ps(da01, s.dy20Ooa), _mm512_mul_ps(da20, s.dy01Ooa));
  const __m512 dady = _mm512_sub_ps(_mm512_mul_ps(da20, s.dx01Ooa), _mm512_mul_ps(da01, s.dx20Ooa));
  _mm512_store_ps(outA0, _mm512_sub_ps(a0, _mm512_add_ps(_mm512_mul_ps(dadx, s.x0Center), _mm512_mul_ps(dady, s.y0Center))));
  _mm512_store_ps(outDadx, dadx);
  _mm512_store_ps(outDady, dady);
}

}  // namespace setup_batch_detail

// Sets up the batch's triangles, appending each that setupTriangle would append, in batch
// order, with the same record and planes. Returns the bits (lane = triangle) of those
// appended.
inline uint32_t setupTriangleBatch(const SetupState& state, const float* records, const TriangleBatch& batch, SetupLists out) {
  using namespace setup_batch_detail;
  using vertex_record::kWindow;
  constexpr int kOrder = limits::kSubPixelBits;
  const __mmask16 live = batch.count >= kSetupBatch ? __mmask16(0xFFFF) : __mmask16((1u << batch.count) - 1u);

  // Window positions: x, y, z, w of each vertex in every lane.
  __m512 window[3][4];
  __m512i vertex[3];
  for (int k = 0; k < 3; ++k) {
    vertex[k] = _mm512_load_si512(batch.vertex[k]);
    for (int c = 0; c < 4; ++c)
      window[k][c] = _mm512_mask_i32gather_ps(_mm512_setzero_ps(), live, _mm512_add_epi32(vertex[k], _mm512_set1_epi32(kWindow + c)),
                                              records, 4);
  }
  // NaN or beyond the fixed-point range: dropped (setupTriangle's first test).
  __mmask16 accepted = live;
  const __m512 absMask = _mm512_castsi512_ps(_mm512_set1_epi32(0x7FFFFFFF));
  const __m512 limit = _mm512_set1_ps(limits::kMaxWindowCoordinate);
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 2; ++c)
      accepted = _mm512_mask_cmp_ps_mask(accepted, _mm512_and_ps(window[k][c], absMask), limit, _CMP_LE_OQ);
  if (!accepted) return 0;

  // Snap (calc_fixed_position): cvtps2dq under the default rounding, as snap() rounds.
  __m512i fixedX[3], fixedY[3];
  const __m512 half = _mm512_set1_ps(0.5f), one = _mm512_set1_ps(float(limits::kSubPixelOne));
  for (int k = 0; k < 3; ++k) {
    fixedX[k] = _mm512_cvtps_epi32(_mm512_mul_ps(_mm512_sub_ps(window[k][0], half), one));
    fixedY[k] = _mm512_cvtps_epi32(_mm512_mul_ps(_mm512_sub_ps(window[k][1], half), one));
  }
  // The exact area sign; zero area dropped; culling; clockwise triangles get v0 and v1
  // swapped (rotate_fixed_position_01).
  __mmask16 frontFacing;
  {
    const Int64x16 x0 = widen(fixedX[0]), x1 = widen(fixedX[1]), x2 = widen(fixedX[2]);
    const Int64x16 y0 = widen(fixedY[0]), y1 = widen(fixedY[1]), y2 = widen(fixedY[2]);
    const Int64x16 area = sub(mul(sub(x0, x1), sub(y2, y0)), mul(sub(x2, x0), sub(y0, y1)));
    const __mmask16 negative = lessThanZero(area);
    frontFacing = state.bottomEdgeRule ? greaterThanZero(area) : negative;
    accepted &= __mmask16(~equalsZero(area));
    if (state.cullBack) accepted &= frontFacing;
    if (!accepted) return 0;
    for (int c = 0; c < 4; ++c) {
      const __m512 w0 = window[0][c];
      window[0][c] = _mm512_mask_blend_ps(negative, w0, window[1][c]);
      window[1][c] = _mm512_mask_blend_ps(negative, window[1][c], w0);
    }
    const __m512i fx0 = fixedX[0], fy0 = fixedY[0], v0 = vertex[0];
    fixedX[0] = _mm512_mask_blend_epi32(negative, fx0, fixedX[1]);
    fixedX[1] = _mm512_mask_blend_epi32(negative, fixedX[1], fx0);
    fixedY[0] = _mm512_mask_blend_epi32(negative, fy0, fixedY[1]);
    fixedY[1] = _mm512_mask_blend_epi32(negative, fixedY[1], fy0);
    vertex[0] = _mm512_mask_blend_epi32(negative, v0, vertex[1]);
    vertex[1] = _mm512_mask_blend_epi32(negative, vertex[1], v0);
  }

  // Pixel bounds (do_triangle_ccw), trimmed to the framebuffer.
  alignas(64) int32_t minX[kSetupBatch], maxX[kSetupBatch], minY[kSetupBatch], maxY[kSetupBatch];
  {
    const __m512i adj = _mm512_set1_epi32(state.bottomEdgeRule ? 1 : 0), oneFixed = _mm512_set1_epi32(1);
    const __m512i lowX = _mm512_min_epi32(_mm512_min_epi32(fixedX[0], fixedX[1]), fixedX[2]);
    const __m512i highX = _mm512_max_epi32(_mm512_max_epi32(fixedX[0], fixedX[1]), fixedX[2]);
    const __m512i lowY = _mm512_min_epi32(_mm512_min_epi32(fixedY[0], fixedY[1]), fixedY[2]);
    const __m512i highY = _mm512_max_epi32(_mm512_max_epi32(fixedY[0], fixedY[1]), fixedY[2]);
    const __m512i x0 = _mm512_max_epi32(_mm512_srai_epi32(lowX, kOrder), _mm512_setzero_si512());
    const __m512i x1 = _mm512_min_epi32(_mm512_srai_epi32(_mm512_sub_epi32(highX, oneFixed), kOrder),
                                        _mm512_set1_epi32(state.framebufferWidth - 1));
    const __m512i y0 = _mm512_max_epi32(_mm512_srai_epi32(_mm512_add_epi32(lowY, adj), kOrder), _mm512_setzero_si512());
    const __m512i y1 = _mm512_min_epi32(_mm512_srai_epi32(_mm512_add_epi32(_mm512_sub_epi32(highY, oneFixed), adj), kOrder),
                                        _mm512_set1_epi32(state.framebufferHeight - 1));
    accepted = _mm512_mask_cmple_epi32_mask(accepted, x0, x1);
    accepted = _mm512_mask_cmple_epi32_mask(accepted, y0, y1);
    if (!accepted) return 0;
    _mm512_store_si512(minX, x0);
    _mm512_store_si512(maxX, x1);
    _mm512_store_si512(minY, y0);
    _mm512_store_si512(maxY, y1);
  }

  // Edge functions with the fill-rule bias, in 64-bit lanes.
  alignas(64) int64_t edgeC[3][kSetupBatch], edgeDcdx[3][kSetupBatch], edgeDcdy[3][kSetupBatch];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const Int64x16 xi = widen(fixedX[i]), yi = widen(fixedY[i]);
    const Int64x16 dcdx = sub(yi, widen(fixedY[j])), dcdy = sub(xi, widen(fixedX[j]));
    Int64x16 c = sub(mul(dcdx, xi), mul(dcdy, yi));
    const __mmask16 left = lessThanZero(dcdx);
    const __mmask16 horizontal = equalsZero(dcdx) & (state.bottomEdgeRule ? lessThanZero(dcdy) : greaterThanZero(dcdy));
    const __mmask16 bias = left | horizontal;
    const __m512i oneBias = _mm512_set1_epi64(1);
    c.lo = _mm512_mask_add_epi64(c.lo, __mmask8(bias), c.lo, oneBias);
    c.hi = _mm512_mask_add_epi64(c.hi, __mmask8(bias >> 8), c.hi, oneBias);
    store(edgeC[i], c);
    store(edgeDcdx[i], {_mm512_slli_epi64(dcdx.lo, kOrder), _mm512_slli_epi64(dcdx.hi, kOrder)});
    store(edgeDcdy[i], {_mm512_slli_epi64(dcdy.lo, kOrder), _mm512_slli_epi64(dcdy.hi, kOrder)});
  }

  // Planes from the unsnapped window positions (init_args), and the polygon offset.
  const __m512 *p0 = window[0], *p1 = window[1], *p2 = window[2];
  const __m512 fdx01 = _mm512_sub_ps(p0[0], p1[0]), fdy01 = _mm512_sub_ps(p0[1], p1[1]);
  const __m512 fdx20 = _mm512_sub_ps(p2[0], p0[0]), fdy20 = _mm512_sub_ps(p2[1], p0[1]);
  const __m512 e = _mm512_mul_ps(fdx01, fdy20);
  const __m512 f = _mm512_mul_ps(fdy01, fdx20);
  const __m512 ooa = _mm512_div_ps(_mm512_set1_ps(1.0f), _mm512_sub_ps(e, f));
  alignas(64) float depthOffset[kSetupBatch];
  if (state.polygonOffset) {   // lp_do_offset_tri, as polygonOffset() computes it
    const __m512 dz01 = _mm512_sub_ps(p0[2], p1[2]), dz20 = _mm512_sub_ps(p2[2], p0[2]);
    const __m512 res1 = _mm512_sub_ps(_mm512_mul_ps(dz20, fdy01), _mm512_mul_ps(fdy20, dz01));
    const __m512 res2 = _mm512_sub_ps(_mm512_mul_ps(fdx20, dz01), _mm512_mul_ps(dz20, fdx01));
    const __m512 dzdx = _mm512_and_ps(_mm512_mul_ps(res1, ooa), absMask);
    const __m512 dzdy = _mm512_and_ps(_mm512_mul_ps(res2, ooa), absMask);
    // dzdx > dzdy or either NaN: dzdx (FCmp UGT), else dzdy.
    const __m512 maxSlope = _mm512_mask_blend_ps(_mm512_cmp_ps_mask(dzdx, dzdy, _CMP_NLE_UQ), dzdy, dzdx);
    _mm512_store_ps(depthOffset,
                    _mm512_add_ps(_mm512_set1_ps(state.offsetUnitsScaled), _mm512_mul_ps(maxSlope, _mm512_set1_ps(state.offsetFactor))));
  } else {
    _mm512_store_ps(depthOffset, _mm512_setzero_ps());
  }
  PlaneSetup16 s;
  s.x0Center = _mm512_sub_ps(p0[0], half);
  s.y0Center = _mm512_sub_ps(p0[1], half);
  s.dx20Ooa = _mm512_mul_ps(fdx20, ooa);
  s.dy20Ooa = _mm512_mul_ps(fdy20, ooa);
  s.dx01Ooa = _mm512_mul_ps(fdx01, ooa);
  s.dy01Ooa = _mm512_mul_ps(fdy01, ooa);
  alignas(64) float z[3][kSetupBatch], w[3][kSetupBatch];
  planeOf16(s, p0[2], p1[2], p2[2], z[0], z[1], z[2]);
  planeOf16(s, p0[3], p1[3], p2[3], w[0], w[1], w[2]);
  alignas(64) float planeSetup[6][kSetupBatch];
  _mm512_store_ps(planeSetup[0], s.x0Center);
  _mm512_store_ps(planeSetup[1], s.y0Center);
  _mm512_store_ps(planeSetup[2], s.dx01Ooa);
  _mm512_store_ps(planeSetup[3], s.dy01Ooa);
  _mm512_store_ps(planeSetup[4], s.dx20Ooa);
  _mm512_store_ps(planeSetup[5], s.dy20Ooa);
  alignas(64) int32_t vertexAt[3][kSetupBatch];
  for (int k = 0; k < 3; ++k) _mm512_store_si512(vertexAt[k], vertex[k]);

  // The records, in lane order.
  for (uint32_t lanes = accepted; lanes; lanes &= lanes - 1) {
    const int lane = __builtin_ctz(lanes);
    SetupTriangle& tri = out.triangles.emplace_back();
    for (int i = 0; i < 3; ++i) tri.edge[i] = EdgeFunction{edgeC[i][lane], edgeDcdx[i][lane], edgeDcdy[i][lane]};
    tri.minX = minX[lane];
    tri.minY = minY[lane];
    tri.maxX = maxX[lane];
    tri.maxY = maxY[lane];
    tri.z = Plane{z[0][lane], z[1][lane], z[2][lane]};
    tri.w = Plane{w[0][lane], w[1][lane], w[2][lane]};
    tri.depthOffset = depthOffset[lane];
    const setup_detail::PlaneSetup laneSetup{planeSetup[0][lane], planeSetup[1][lane], planeSetup[2][lane],
                                             planeSetup[3][lane], planeSetup[4][lane], planeSetup[5][lane]};
    setup_detail::appendVaryingPlanes(state, laneSetup, records + vertexAt[0][lane], records + vertexAt[1][lane],
                                      records + vertexAt[2][lane], tri, out);
    tri.drawIndex = state.drawIndex;
    tri.frontFacing = (frontFacing >> lane) & 1u;
  }
  return accepted;
}

}  // namespace raster
#endif
