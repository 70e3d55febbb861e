// Coverage: which pixel centres of a tile a set-up triangle covers, found hierarchically as
// llvmpipe's lp_rast_tri_tmp.h does: 16x16 regions are tested whole against each edge, then
// the 4x4 blocks of regions the triangle crosses, then the pixels of blocks an edge crosses.
//
// An edge function is linear, so over a rectangle of pixel centres it is largest and
// smallest at fixed corners: a square is tested by its first pixel's value plus two offsets
// worked out once per triangle and tile (WalkEdge), with no corner evaluated.
//
// This file is the reference. coverage_avx2.h adds WalkEdge8, which tests a straddled
// block's 16 pixels in two (or, with AVX-512, one) vector compares; both give the same bits.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "raster/contract.h"

namespace raster {

// The largest and smallest amounts an edge function rises over a rectangle of pixel
// centres whose far corner is (farX, farY) pixels from its first one.
inline void edgeExtremes(const EdgeFunction& e, int farX, int farY, int64_t& high, int64_t& low) {
  const int64_t alongX = -e.dcdx * farX, alongY = e.dcdy * farY;
  high = std::max<int64_t>(alongX, 0) + std::max<int64_t>(alongY, 0);
  low = std::min<int64_t>(alongX, 0) + std::min<int64_t>(alongY, 0);
}

// Whether an edge's steps are small, |dcdx| + |dcdy| < 2^28: a 4x4 block's pixel offsets,
// dcdy * row - dcdx * col, then fit 30 bits, so the vector walks keep them in 32-bit lanes.
inline bool hasSmallSteps(const EdgeFunction& e) { return std::abs(e.dcdx) + std::abs(e.dcdy) < (int64_t(1) << 28); }

// One edge function as the walk uses it, set up once per triangle and tile.
struct WalkEdge {
  EdgeFunction f;
  int64_t blockMax, blockMin;     // over a 4x4 block's pixel centres
  int64_t regionMax, regionMin;   // over a 16x16 region's
  bool smallSteps;                // hasSmallSteps(f)

  explicit WalkEdge(const EdgeFunction& e) : f(e) {
    constexpr int kBlock = limits::kBlockSize, kRegion = limits::kRegionSize;
    edgeExtremes(e, kBlock - 1, kBlock - 1, blockMax, blockMin);
    edgeExtremes(e, kRegion - 1, kRegion - 1, regionMax, regionMin);
    smallSteps = hasSmallSteps(e);
  }

  // Bits (row * 4 + col) of a block whose first pixel has value c00, set where
  // c00 - dcdx * col + dcdy * row > 0.
  uint32_t straddledCoverage(int64_t c00) const {
    uint32_t mask = 0;
    for (int row = 0; row < limits::kBlockSize; ++row)
      for (int col = 0; col < limits::kBlockSize; ++col)
        if (c00 - f.dcdx * col + f.dcdy * row > 0) mask |= 1u << (row * limits::kBlockSize + col);
    return mask;
  }
};

// The edge type a lane type's walk uses (coverage_avx2.h: WalkEdge8 for Float8).
template <class F>
struct EdgeWalkOf {
  using type = WalkEdge;
};

// The part of a triangle's pixel bounds inside `tile` (a tile or a band of one): empty when
// x0 > x1 or y0 > y1, as when binning put the triangle in a tile whose band it misses.
inline TileBounds boundsInTile(const SetupTriangle& tri, const TileBounds& tile) {
  return {std::max(tile.x0, tri.minX), std::max(tile.y0, tri.minY), std::min(tile.x1, tri.maxX), std::min(tile.y1, tri.maxY)};
}

// Whether a rectangle (inclusive) holds a whole 16x16 region of the region grid.
inline bool holdsWholeRegion(const TileBounds& r) {
  constexpr int kRegion = limits::kRegionSize;
  return ((r.x0 + kRegion - 1) & ~(kRegion - 1)) + kRegion - 1 <= r.x1 &&
         ((r.y0 + kRegion - 1) & ~(kRegion - 1)) + kRegion - 1 <= r.y1;
}

// How a square of pixels lies against a triangle: wholly outside one edge, wholly inside
// all three, or across an edge.
enum class Overlap { Outside, Inside, Partial };

template <class Edge>
Overlap regionOverlap(const Edge (&edges)[3], int x, int y) {
  Overlap result = Overlap::Inside;
  for (const Edge& e : edges) {
    const int64_t c00 = e.f.at(x, y);
    if (c00 + e.regionMax <= 0) return Overlap::Outside;
    if (c00 + e.regionMin <= 0) result = Overlap::Partial;
  }
  return result;
}

// Coverage of one 4x4 block: bit (row * 4 + col) set when that pixel centre is inside.
template <class Edge>
uint32_t blockCoverage(const Edge (&edges)[3], int blockX, int blockY) {
  uint32_t mask = 0xFFFFu;
  for (const Edge& e : edges) {
    const int64_t c00 = e.f.at(blockX, blockY);
    if (c00 + e.blockMax <= 0) return 0;   // all outside this edge
    if (c00 + e.blockMin > 0) continue;    // all inside this edge
    mask &= e.straddledCoverage(c00);
  }
  return mask;
}

// The same, for edges that all have small steps, kept to the pixels of `within`. The
// reference has no faster form; coverage_avx2.h gives WalkEdge8 one without branches.
inline uint32_t blockCoverageSmallSteps(const WalkEdge (&edges)[3], int blockX, int blockY, uint32_t within) {
  return blockCoverage(edges, blockX, blockY) & within;
}

// The blocks of a small triangle's part of a tile, [x0, x1] x [y0, y1], walked without the
// region level: visitBlock(blockX, blockY, coverage) for each covered block inside the
// framebuffer, row by row, left to right, as the region walk (walk.h) visits them. Returns
// false, visiting nothing, where it does not apply. It takes the triangle's edge functions,
// not its walk edges, so that a triangle it takes (most of a scene's) never builds the
// extremes only the region walk reads. The reference has no such walk, so its regions
// always run; coverage_avx2.h gives Float8 one (AVX-512).
template <class F, class VisitBlock>
bool walkSmallTriangleBlocks(const EdgeFunction (&)[3], int, int, int, int, int, int, VisitBlock&&) {
  return false;
}

// Pixels of the block inside the framebuffer.
inline uint32_t blockBounds(int blockX, int blockY, int width, int height) {
  constexpr int kBlock = limits::kBlockSize;
  if (blockX + kBlock <= width && blockY + kBlock <= height) return 0xFFFFu;
  uint32_t mask = 0;
  for (int row = 0; row < kBlock; ++row)
    for (int col = 0; col < kBlock; ++col)
      if (blockX + col < width && blockY + row < height) mask |= 1u << (row * kBlock + col);
  return mask;
}

// True when the triangle covers every pixel centre of the rectangle (inclusive).
inline bool triangleCoversRect(const SetupTriangle& tri, const TileBounds& rect) {
  if (rect.x1 < rect.x0 || rect.y1 < rect.y0) return false;
  // The walk visits only the bounds (which hold every covered pixel centre anyway).
  if (tri.minX > rect.x0 || tri.maxX < rect.x1 || tri.minY > rect.y0 || tri.maxY < rect.y1) return false;
  for (const EdgeFunction& e : tri.edge) {
    int64_t high, low;
    edgeExtremes(e, rect.x1 - rect.x0, rect.y1 - rect.y0, high, low);
    if (e.at(rect.x0, rect.y0) + low <= 0) return false;   // some pixel centre outside this edge
  }
  return true;
}

}  // namespace raster

#include "raster/tile/coverage_avx2.h"
