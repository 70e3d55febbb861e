// The depth test, early: before the fragment shader runs. Every depth test of the scenes is
// early, as llvmpipe's is (lp_state_fs.c): no shader writes gl_FragDepth or discards, so a
// fragment's depth is known before shading and a failed lane is never shaded.
//
// Per lane: window z (plane + polygon offset, at most 1: NaN -> 1) clamped to [0, 1], quantized to
// the depth buffer's code (format.h, as llvmpipe rounds), compared with the stored code
// (LESS or LEQUAL on integers) and written where it passes and depth writes are on.
//
// This file is the reference, lane by lane. depth_test_avx2.h tests a whole 8-lane group
// against its two memory rows at once, and fills the depth-only regions a row at a time;
// depth_test_avx512.h tests a whole 4x4 block in one register. Same bits every way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "raster/contract.h"
#include "raster/simd/prefetch.h"
#include "raster/texture/format.h"
#include "raster/tile/interpolate.h"
#include "raster/simd/lane_layout.h"

namespace raster {

// z clamped for the test: max first, as lp_build_clamp does (a NaN would become 0: maxps
// returns its second operand; fragmentDepth has already made it 1).
template <class F>
F clampDepth(F z) {
  return simd::min(simd::max(z, F(0.0f)), F(1.0f));
}

// Depth codes of clamped window z per lane.
template <class F>
void depthCodes(F z, TexelFormat format, uint32_t* codes) {
  alignas(64) float lanes[F::kCount];
  z.store(lanes);
  for (int i = 0; i < F::kCount; ++i)
    codes[i] = format == TexelFormat::Depth24 ? format::depth24FromFloat(lanes[i]) : format::depth16FromFloat(lanes[i]);
}

// The test (LESS or LEQUAL) of the covered lanes, and the write of the lanes that pass, for
// lanes whose texels are depth[texel[i]]. Returns the lanes that pass.
template <int kLanes>
unsigned depthTest(const uint32_t* codes, uint32_t* depth, const size_t* texel, unsigned laneMask, bool lessEqual,
                   bool write) {
  for (int i = 0; i < kLanes; ++i) {
    if (!(laneMask >> i & 1u)) continue;
    uint32_t& stored = depth[texel[i]];
    const bool pass = lessEqual ? codes[i] <= stored : codes[i] < stored;
    if (!pass) laneMask &= ~(1u << i);
    else if (write) stored = codes[i];
  }
  return laneMask;
}

// Depth test of the lane group `at`: z from the plane plus the polygon offset (returned in
// z, unclamped, for gl_FragCoord), then the test and write. Returns the lanes that pass.
template <class F>
unsigned depthTestGroup(const TileJob& job, const SetupTriangle& tri, const LaneLayout<F>& layout, GroupAt at, F& z) {
  const Framebuffer& fb = *job.framebuffer;
  // Pixel coordinates per lane (small integers: the float sums are exact).
  const F px = F(float(at.x)) + layout.dxLanes;
  const F py = F(float(at.y)) + layout.dyLanes;
  z = fragmentDepth(tri, px, py);
  const RasterState& state = job.draws[tri.drawIndex].state;
  if (!state.depthTest || !fb.depth) return at.laneMask;
  uint32_t codes[F::kCount];
  depthCodes(clampDepth(z), fb.depth->format, codes);
  size_t texel[F::kCount];
  const size_t origin = size_t(at.y) * size_t(fb.width) + size_t(at.x);
  for (int i = 0; i < F::kCount; ++i) texel[i] = origin + layout.texel[i];
  return depthTest<F::kCount>(codes, fb.depth->depth.data(), texel, at.laneMask, state.depthFunc == DepthFunc::Lequal,
                              state.depthWrite);
}

// A depth-only draw over a 16x16 region wholly inside its triangle: no lane is shaded, so
// the test runs along memory rows instead of in 2x2 quads. Each pixel gets the arithmetic
// depthTestGroup gives it, and a triangle touches each pixel once, so the same bits land.
template <class F>
void depthOnlyRegion(const SetupTriangle& tri, const RasterState& state, Texture& depth, int width, int x, int y) {
  constexpr int kRegion = limits::kRegionSize;
  alignas(64) float columnOffsets[F::kCount];
  for (int i = 0; i < F::kCount; ++i) columnOffsets[i] = float(i);
  const F columns = F::load(columnOffsets);
  size_t texel[F::kCount];
  for (int i = 0; i < F::kCount; ++i) texel[i] = size_t(i);
  for (int row = 0; row < kRegion; ++row) {
    const F py(float(y + row));
    uint32_t* dst = depth.depth.data() + size_t(y + row) * size_t(width) + size_t(x);
    for (int column = 0; column < kRegion; column += F::kCount) {
      uint32_t codes[F::kCount];
      depthCodes(clampDepth(fragmentDepth(tri, F(float(x + column)) + columns, py)), depth.format, codes);
      depthTest<F::kCount>(codes, dst + column, texel, (1u << F::kCount) - 1u, state.depthFunc == DepthFunc::Lequal, true);
    }
  }
}

// The depth codes of a triangle of a depth-only draw stored over the rectangle `rect`
// (inclusive) without reading the buffer: what the walk writes when the triangle covers
// every pixel centre there and every one of them passes the test (tile/tile_clear.cpp
// proves it against a pending clear, which this store then replaces). Each pixel's code is
// computed as depthTestGroup computes it; pixels are exact small integers in any lane.
template <class F>
void storeDepthCodes(const SetupTriangle& tri, Texture& depth, int width, const TileBounds& rect) {
  alignas(64) float columnOffsets[F::kCount];
  for (int i = 0; i < F::kCount; ++i) columnOffsets[i] = float(i);
  const F columns = F::load(columnOffsets);
  const size_t rowBytes = size_t(rect.x1 + 1 - rect.x0) * sizeof(uint32_t);
  for (int y = rect.y0; y <= rect.y1; ++y) {
    if (y + simd::kPrefetchRowsAhead <= rect.y1)
      simd::prefetchLines(depth.depth.data() + size_t(y + simd::kPrefetchRowsAhead) * size_t(width) + size_t(rect.x0),
                          rowBytes);
    const F py = F(float(y));
    uint32_t* row = depth.depth.data() + size_t(y) * size_t(width);
    for (int x = rect.x0; x <= rect.x1; x += F::kCount) {
      alignas(64) uint32_t codes[F::kCount];
      depthCodes(clampDepth(fragmentDepth(tri, F(float(x)) + columns, py)), depth.format, codes);
      if (x + F::kCount - 1 <= rect.x1) std::memcpy(row + x, codes, sizeof codes);
      else std::memcpy(row + x, codes, size_t(rect.x1 + 1 - x) * sizeof(uint32_t));
    }
  }
}

// A depth-only draw over a 16x16 region inside the framebuffer that its triangle straddles
// (some pixel centres inside, some not) or covers: each covered pixel tested and written as
// BlockDepthTest would, in memory rows instead of blocks. `pendingClear`, when given, is
// the code of a depth clear the region has not taken yet: the test reads it in place of the
// stored codes, and every row of the region is written, covered or not. Returns false
// where the lane type has no such form (kDepthRowsInRegions) or an edge's steps are not
// small; the walk then visits the region's blocks.
template <class F>
constexpr bool kDepthRowsInRegions = false;
template <class F>
bool depthOnlyStraddledRegion(const SetupTriangle&, const RasterState&, Texture&, int, int, int,
                              const uint32_t* pendingClear = nullptr) {
  (void)pendingClear;
  return false;
}

// Whether a lane type tests depth a whole 4x4 block at a time, in memory rows, where no
// quads are needed (depth-only draws, the visibility pass): only where that is faster than
// two group tests (depth_test_avx512.h).
template <class F>
constexpr bool kDepthTestsInBlocks = false;

// That test, for the blocks of one triangle: made once per triangle, then called per block,
// blockTest(blockX, blockY, coverage) tests and writes the pixels `coverage` (bit row * 4 +
// col) of the 4x4 block at (blockX, blockY), each as depthTestGroup would, and returns those
// that pass. Defined for the lane types with kDepthTestsInBlocks (depth_test_avx512.h, which
// keeps the triangle's z plane, the buffer and the test in registers across its blocks).
template <class F>
class BlockDepthTest;

// What every BlockDepthTest holds across a triangle's blocks: the z plane broadcast into the
// register type L it computes depths in, and the depth buffer and test of the triangle's draw.
template <class L>
class BlockDepthState {
 public:
  BlockDepthState(const TileJob& job, const SetupTriangle& tri)
      : dadx_(tri.z.dadx), dady_(tri.z.dady), a0_(tri.z.a0), depthOffset_(tri.depthOffset) {
    const Framebuffer& fb = *job.framebuffer;
    const RasterState& state = job.draws[tri.drawIndex].state;
    tests_ = state.depthTest && fb.depth;
    if (!tests_) return;
    buffer_ = fb.depth->depth.data();
    format_ = fb.depth->format;
    width_ = fb.width, height_ = fb.height;
    lessEqual_ = state.depthFunc == DepthFunc::Lequal;
    writes_ = state.depthWrite;
  }

 protected:
  const L dadx_, dady_, a0_, depthOffset_;   // the z plane, broadcast
  bool tests_ = false, lessEqual_ = false, writes_ = false;
  uint32_t* buffer_ = nullptr;
  TexelFormat format_ = TexelFormat::Depth16;
  int width_ = 0, height_ = 0;
};

}  // namespace raster

#include "raster/tile/depth_test_avx2.h"
#include "raster/tile/depth_test_avx512.h"
