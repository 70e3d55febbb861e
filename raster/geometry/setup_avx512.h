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

// The batch in registers as it passes from step to step: each vertex's window position and
// record offset, then its snapped position, and the lanes still accepted.
struct BatchLanes {
  __m512 window[3][4];   // x, y, z, w of each vertex
  __m512i vertex[3];     // each vertex's record offset, in floats
  __m512i fixedX[3], fixedY[3];
  __mmask16 accepted;
  __mmask16 frontFacing;
};

// What each accepted lane's record is made of, stored per lane for the loop that appends
// the records (appendRecords).
struct BatchRecords {
  alignas(64) int32_t minX[kSetupBatch], maxX[kSetupBatch], minY[kSetupBatch], maxY[kSetupBatch];
  alignas(64) int64_t edgeC[3][kSetupBatch], edgeDcdx[3][kSetupBatch], edgeDcdy[3][kSetupBatch];
  alignas(64) float depthOffset[kSetupBatch];
  alignas(64) float z[3][kSetupBatch], w[3][kSetupBatch];   // a0, dadx, dady
  alignas(64) float planeSetup[6][kSetupBatch];             // PlaneSetup16's fields, in order
  alignas(64) int32_t vertexAt[3][kSetupBatch];
};

// Window positions: x, y, z, w of each vertex in every live lane.
[[gnu::always_inline]] inline void gatherWindows(const float* records, const TriangleBatch& batch, BatchLanes& b) {
  using vertex_record::kWindow;
  b.accepted = batch.count >= kSetupBatch ? __mmask16(0xFFFF) : __mmask16((1u << batch.count) - 1u);
  for (int k = 0; k < 3; ++k) {
    b.vertex[k] = _mm512_load_si512(batch.vertex[k]);
    for (int c = 0; c < 4; ++c)
      b.window[k][c] = _mm512_mask_i32gather_ps(_mm512_setzero_ps(), b.accepted,
                                                _mm512_add_epi32(b.vertex[k], _mm512_set1_epi32(kWindow + c)), records, 4);
  }
}

// NaN or beyond the fixed-point range: dropped (setupTriangle's first test).
[[gnu::always_inline]] inline void dropOutOfRange(BatchLanes& b) {
  const __m512 absMask = _mm512_castsi512_ps(_mm512_set1_epi32(0x7FFFFFFF));
  const __m512 limit = _mm512_set1_ps(limits::kMaxWindowCoordinate);
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 2; ++c)
      b.accepted = _mm512_mask_cmp_ps_mask(b.accepted, _mm512_and_ps(b.window[k][c], absMask), limit, _CMP_LE_OQ);
}

// Snap (calc_fixed_position): cvtps2dq under the default rounding, as snap() rounds.
[[gnu::always_inline]] inline void snapToFixed(BatchLanes& b) {
  const __m512 half = _mm512_set1_ps(0.5f), one = _mm512_set1_ps(float(limits::kSubPixelOne));
  for (int k = 0; k < 3; ++k) {
    b.fixedX[k] = _mm512_cvtps_epi32(_mm512_mul_ps(_mm512_sub_ps(b.window[k][0], half), one));
    b.fixedY[k] = _mm512_cvtps_epi32(_mm512_mul_ps(_mm512_sub_ps(b.window[k][1], half), one));
  }
}

// The exact area sign; zero area dropped; culling; clockwise triangles get v0 and v1
// swapped (rotate_fixed_position_01).
[[gnu::always_inline]] inline void orientAndCull(const SetupState& state, BatchLanes& b) {
  const Int64x16 x0 = widen(b.fixedX[0]), x1 = widen(b.fixedX[1]), x2 = widen(b.fixedX[2]);
  const Int64x16 y0 = widen(b.fixedY[0]), y1 = widen(b.fixedY[1]), y2 = widen(b.fixedY[2]);
  const Int64x16 area = sub(mul(sub(x0, x1), sub(y2, y0)), mul(sub(x2, x0), sub(y0, y1)));
  const __mmask16 negative = lessThanZero(area);
  b.frontFacing = state.bottomEdgeRule ? greaterThanZero(area) : negative;
  b.accepted &= __mmask16(~equalsZero(area));
  if (state.cullBack) b.accepted &= b.frontFacing;
  if (!b.accepted) return;
  for (int c = 0; c < 4; ++c) {
    const __m512 w0 = b.window[0][c];
    b.window[0][c] = _mm512_mask_blend_ps(negative, w0, b.window[1][c]);
    b.window[1][c] = _mm512_mask_blend_ps(negative, b.window[1][c], w0);
  }
  const __m512i fx0 = b.fixedX[0], fy0 = b.fixedY[0], v0 = b.vertex[0];
  b.fixedX[0] = _mm512_mask_blend_epi32(negative, fx0, b.fixedX[1]);
  b.fixedX[1] = _mm512_mask_blend_epi32(negative, b.fixedX[1], fx0);
  b.fixedY[0] = _mm512_mask_blend_epi32(negative, fy0, b.fixedY[1]);
  b.fixedY[1] = _mm512_mask_blend_epi32(negative, b.fixedY[1], fy0);
  b.vertex[0] = _mm512_mask_blend_epi32(negative, v0, b.vertex[1]);
  b.vertex[1] = _mm512_mask_blend_epi32(negative, b.vertex[1], v0);
}

// Pixel bounds (do_triangle_ccw), trimmed to the framebuffer; empty bounds dropped.
[[gnu::always_inline]] inline void pixelBounds(const SetupState& state, BatchLanes& b, BatchRecords& r) {
  constexpr int kOrder = limits::kSubPixelBits;
  const __m512i adj = _mm512_set1_epi32(state.bottomEdgeRule ? 1 : 0), oneFixed = _mm512_set1_epi32(1);
  const __m512i lowX = _mm512_min_epi32(_mm512_min_epi32(b.fixedX[0], b.fixedX[1]), b.fixedX[2]);
  const __m512i highX = _mm512_max_epi32(_mm512_max_epi32(b.fixedX[0], b.fixedX[1]), b.fixedX[2]);
  const __m512i lowY = _mm512_min_epi32(_mm512_min_epi32(b.fixedY[0], b.fixedY[1]), b.fixedY[2]);
  const __m512i highY = _mm512_max_epi32(_mm512_max_epi32(b.fixedY[0], b.fixedY[1]), b.fixedY[2]);
  const __m512i x0 = _mm512_max_epi32(_mm512_srai_epi32(lowX, kOrder), _mm512_setzero_si512());
  const __m512i x1 = _mm512_min_epi32(_mm512_srai_epi32(_mm512_sub_epi32(highX, oneFixed), kOrder),
                                      _mm512_set1_epi32(state.framebufferWidth - 1));
  const __m512i y0 = _mm512_max_epi32(_mm512_srai_epi32(_mm512_add_epi32(lowY, adj), kOrder), _mm512_setzero_si512());
  const __m512i y1 = _mm512_min_epi32(_mm512_srai_epi32(_mm512_add_epi32(_mm512_sub_epi32(highY, oneFixed), adj), kOrder),
                                      _mm512_set1_epi32(state.framebufferHeight - 1));
  b.accepted = _mm512_mask_cmple_epi32_mask(b.accepted, x0, x1);
  b.accepted = _mm512_mask_cmple_epi32_mask(b.accepted, y0, y1);
  if (!b.accepted) return;
  _mm512_store_si512(r.minX, x0);
  _mm512_store_si512(r.maxX, x1);
  _mm512_store_si512(r.minY, y0);
  _mm512_store_si512(r.maxY, y1);
}

// Edge functions with the fill-rule bias, in 64-bit lanes.
[[gnu::always_inline]] inline void edgeFunctions(const SetupState& state, const BatchLanes& b, BatchRecords& r) {
  constexpr int kOrder = limits::kSubPixelBits;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const Int64x16 xi = widen(b.fixedX[i]), yi = widen(b.fixedY[i]);
    const Int64x16 dcdx = sub(yi, widen(b.fixedY[j])), dcdy = sub(xi, widen(b.fixedX[j]));
    Int64x16 c = sub(mul(dcdx, xi), mul(dcdy, yi));
    const __mmask16 left = lessThanZero(dcdx);
    const __mmask16 horizontal = equalsZero(dcdx) & (state.bottomEdgeRule ? lessThanZero(dcdy) : greaterThanZero(dcdy));
    const __mmask16 bias = left | horizontal;
    const __m512i oneBias = _mm512_set1_epi64(1);
    c.lo = _mm512_mask_add_epi64(c.lo, __mmask8(bias), c.lo, oneBias);
    c.hi = _mm512_mask_add_epi64(c.hi, __mmask8(bias >> 8), c.hi, oneBias);
    store(r.edgeC[i], c);
    store(r.edgeDcdx[i], {_mm512_slli_epi64(dcdx.lo, kOrder), _mm512_slli_epi64(dcdx.hi, kOrder)});
    store(r.edgeDcdy[i], {_mm512_slli_epi64(dcdy.lo, kOrder), _mm512_slli_epi64(dcdy.hi, kOrder)});
  }
}

// Planes from the unsnapped window positions (init_args), and the polygon offset.
[[gnu::always_inline]] inline void planesAndOffset(const SetupState& state, const BatchLanes& b, BatchRecords& r) {
  const __m512 *p0 = b.window[0], *p1 = b.window[1], *p2 = b.window[2];
  const __m512 fdx01 = _mm512_sub_ps(p0[0], p1[0]), fdy01 = _mm512_sub_ps(p0[1], p1[1]);
  const __m512 fdx20 = _mm512_sub_ps(p2[0], p0[0]), fdy20 = _mm512_sub_ps(p2[1], p0[1]);
  const __m512 e = _mm512_mul_ps(fdx01, fdy20);
  const __m512 f = _mm512_mul_ps(fdy01, fdx20);
  const __m512 ooa = _mm512_div_ps(_mm512_set1_ps(1.0f), _mm512_sub_ps(e, f));
  if (state.polygonOffset) {   // lp_do_offset_tri, as polygonOffset() computes it
    const __m512 absMask = _mm512_castsi512_ps(_mm512_set1_epi32(0x7FFFFFFF));
    const __m512 dz01 = _mm512_sub_ps(p0[2], p1[2]), dz20 = _mm512_sub_ps(p2[2], p0[2]);
    const __m512 res1 = _mm512_sub_ps(_mm512_mul_ps(dz20, fdy01), _mm512_mul_ps(fdy20, dz01));
    const __m512 res2 = _mm512_sub_ps(_mm512_mul_ps(fdx20, dz01), _mm512_mul_ps(dz20, fdx01));
    const __m512 dzdx = _mm512_and_ps(_mm512_mul_ps(res1, ooa), absMask);
    const __m512 dzdy = _mm512_and_ps(_mm512_mul_ps(res2, ooa), absMask);
    // dzdx > dzdy or either NaN: dzdx (FCmp UGT), else dzdy.
    const __m512 maxSlope = _mm512_mask_blend_ps(_mm512_cmp_ps_mask(dzdx, dzdy, _CMP_NLE_UQ), dzdy, dzdx);
    _mm512_store_ps(r.depthOffset,
                    _mm512_add_ps(_mm512_set1_ps(state.offsetUnitsScaled), _mm512_mul_ps(maxSlope, _mm512_set1_ps(state.offsetFactor))));
  } else {
    _mm512_store_ps(r.depthOffset, _mm512_setzero_ps());
  }
  const __m512 half = _mm512_set1_ps(0.5f);
  PlaneSetup16 s;
  s.x0Center = _mm512_sub_ps(p0[0], half);
  s.y0Center = _mm512_sub_ps(p0[1], half);
  s.dx20Ooa = _mm512_mul_ps(fdx20, ooa);
  s.dy20Ooa = _mm512_mul_ps(fdy20, ooa);
  s.dx01Ooa = _mm512_mul_ps(fdx01, ooa);
  s.dy01Ooa = _mm512_mul_ps(fdy01, ooa);
  planeOf16(s, p0[2], p1[2], p2[2], r.z[0], r.z[1], r.z[2]);
  planeOf16(s, p0[3], p1[3], p2[3], r.w[0], r.w[1], r.w[2]);
  _mm512_store_ps(r.planeSetup[0], s.x0Center);
  _mm512_store_ps(r.planeSetup[1], s.y0Center);
  _mm512_store_ps(r.planeSetup[2], s.dx01Ooa);
  _mm512_store_ps(r.planeSetup[3], s.dy01Ooa);
  _mm512_store_ps(r.planeSetup[4], s.dx20Ooa);
  _mm512_store_ps(r.planeSetup[5], s.dy20Ooa);
  for (int k = 0; k < 3; ++k) _mm512_store_si512(r.vertexAt[k], b.vertex[k]);
}

// The accepted lanes' records, in lane order, each with its varying planes appended as
// setupTriangle appends them.
[[gnu::always_inline]] inline void appendRecords(const SetupState& state, const float* records, const BatchLanes& b,
                                                 const BatchRecords& r, SetupLists out) {
  for (uint32_t lanes = b.accepted; lanes; lanes &= lanes - 1) {
    const int lane = __builtin_ctz(lanes);
    SetupTriangle& tri = out.appendTriangle();
    for (int i = 0; i < 3; ++i) tri.edge[i] = EdgeFunction{r.edgeC[i][lane], r.edgeDcdx[i][lane], r.edgeDcdy[i][lane]};
    tri.minX = r.minX[lane];
    tri.minY = r.minY[lane];
    tri.maxX = r.maxX[lane];
    tri.maxY = r.maxY[lane];
    tri.z = Plane{r.z[0][lane], r.z[1][lane], r.z[2][lane]};
    tri.w = Plane{r.w[0][lane], r.w[1][lane], r.w[2][lane]};
    tri.depthOffset = r.depthOffset[lane];
    const setup_detail::PlaneSetup laneSetup{r.planeSetup[0][lane], r.planeSetup[1][lane], r.planeSetup[2][lane],
                                             r.planeSetup[3][lane], r.planeSetup[4][lane], r.planeSetup[5][lane]};
    setup_detail::appendVaryingPlanes(state, laneSetup, records + r.vertexAt[0][lane], records + r.vertexAt[1][lane],
                                      records + r.vertexAt[2][lane], tri, out);
    tri.drawIndex = state.drawIndex;
    tri.frontFacing = (b.frontFacing >> lane) & 1u;
  }
}

}  // namespace setup_batch_detail

// Sets up the batch's triangles, appending each that setupTriangle would append, in batch
// order, with the same record and planes. Returns the bits (lane = triangle) of those
// appended. The steps are setupTriangle's, in its order, each on 16 lanes.
inline uint32_t setupTriangleBatch(const SetupState& state, const float* records, const TriangleBatch& batch, SetupLists out) {
  using namespace setup_batch_detail;
  BatchLanes b;
  gatherWindows(records, batch, b);
  dropOutOfRange(b);
  if (!b.accepted) return 0;
  snapToFixed(b);
  orientAndCull(state, b);
  if (!b.accepted) return 0;
  BatchRecords r;
  pixelBounds(state, b, r);
  if (!b.accepted) return 0;
  edgeFunctions(state, b, r);
  planesAndOffset(state, b, r);
  appendRecords(state, records, b, r, out);
  return b.accepted;
}

}  // namespace raster
#endif
