// The walk of one tile's triangles, in API order: for each triangle, its 16x16 regions (not
// for small ones, where the lane type has a faster walk), then 4x4 blocks, then lane groups,
// each with its coverage (coverage.h), and each group through the early depth test
// (depth_test.h).
//
// The walk functions are always inlined into the tile loop (rasterize_tile.cpp), as GCC
// inlines functions of internal linkage called once: outlined, each call and its visitor
// cost the shadow scene's main pass 14%.
#pragma once

#include <cstdint>
#include <span>

#include "raster/contract.h"
#include "raster/tile/coverage.h"
#include "raster/tile/depth_test.h"
#include "raster/simd/lane_layout.h"

namespace raster {

// The 4x4 blocks of one triangle inside one tile, in walk order: visitBlock(blockX, blockY,
// coverage) for every block with a covered pixel (bit row * 4 + col). Depth-only draws fill
// the 16x16 regions wholly inside the triangle themselves (depthOnlyRegion) and visit only
// the rest.
template <class F, class VisitBlock>
[[gnu::always_inline]] inline void walkTriangleBlocks(const TileJob& job, const SetupTriangle& tri, const TileBounds& tile, VisitBlock&& visitBlock) {
  constexpr int kBlock = limits::kBlockSize, kRegion = limits::kRegionSize;
  using Edge = typename EdgeWalkOf<F>::type;
  const Framebuffer& fb = *job.framebuffer;
  const RasterState& state = job.draws[tri.drawIndex].state;
  const TileBounds bounds = boundsInTile(tri, tile);
  const int x0 = bounds.x0, x1 = bounds.x1, y0 = bounds.y0, y1 = bounds.y1;
  // Binning puts a triangle only into tiles its bounds touch, but a band of a tile (a pass
  // of few tiles is walked in bands, renderer.cpp) may lie wholly beside it: the block
  // rows below would then start past y1 and walk the next band's blocks.
  if (x0 > x1 || y0 > y1) return;
  // Depth test and write, and no colour the shader writes is kept.
  const bool depthOnly =
      state.depthTest && state.depthWrite && fb.depth && colorOutputsWritten(job.draws[tri.drawIndex], fb) == 0;
  // A small triangle may walk its blocks without the regions (walkSmallTriangleBlocks,
  // coverage.h), unless it is depth-only and a whole region lies in its bounds, which the
  // regions fill whole.
  if (!(depthOnly && holdsWholeRegion(bounds)) && walkSmallTriangleBlocks<F>(tri.edge, x0, y0, x1, y1, fb.width, fb.height, visitBlock))
    return;
  const Edge edges[3] = {Edge(tri.edge[0]), Edge(tri.edge[1]), Edge(tri.edge[2])};
  const bool smallSteps = edges[0].smallSteps && edges[1].smallSteps && edges[2].smallSteps;
  // 16x16 regions first (llvmpipe's middle level): a region wholly inside needs no edge
  // tests per block, one wholly outside no blocks at all. Blocks are still walked a whole
  // row of the triangle's extent at a time, so texture reads run along long rows.
  const int firstRegionX = x0 & ~(kRegion - 1);
  for (int regionY = y0 & ~(kRegion - 1); regionY <= y1; regionY += kRegion) {
    Overlap overlap[limits::kTileSize / kRegion + 1];
    for (int regionX = firstRegionX; regionX <= x1; regionX += kRegion)
      overlap[(regionX - firstRegionX) / kRegion] = regionOverlap(edges, regionX, regionY);
    // Depth-only draws fill whole inside regions row by row, and where the lane type can,
    // regions the triangle straddles too; the blocks then skip them. A straddled region is
    // taken whole only inside the framebuffer, which its block walk would clip to; its rows
    // and columns outside the triangle's bounds hold no pixel centre inside it.
    if (depthOnly) {
      const bool rowsInside = regionY >= y0 && regionY + kRegion - 1 <= y1;
      for (int regionX = firstRegionX; regionX <= x1; regionX += kRegion) {
        Overlap& region = overlap[(regionX - firstRegionX) / kRegion];
        if (region == Overlap::Inside && rowsInside && regionX >= x0 && regionX + kRegion - 1 <= x1) {
          depthOnlyRegion<F>(tri, state, *fb.depth, fb.width, regionX, regionY);
          region = Overlap::Outside;
        } else if (region == Overlap::Partial && regionX + kRegion <= fb.width && regionY + kRegion <= fb.height &&
                   depthOnlyStraddledRegion<F>(tri, state, *fb.depth, fb.width, regionX, regionY)) {
          region = Overlap::Outside;
        }
      }
    }
    const int bandY1 = std::min(y1, regionY + kRegion - 1);
    for (int blockY = std::max(y0, regionY) & ~(kBlock - 1); blockY <= bandY1; blockY += kBlock) {
      for (int blockX = x0 & ~(kBlock - 1); blockX <= x1; blockX += kBlock) {
        const Overlap region = overlap[(blockX - firstRegionX) / kRegion];
        if (region == Overlap::Outside) {   // on to the next region's first block
          blockX = (blockX | (kRegion - 1)) - (kBlock - 1);
          continue;
        }
        const uint32_t bounds = blockBounds(blockX, blockY, fb.width, fb.height);
        const uint32_t coverage = region == Overlap::Inside ? bounds
                                  : smallSteps              ? blockCoverageSmallSteps(edges, blockX, blockY, bounds)
                                                            : blockCoverage(edges, blockX, blockY) & bounds;
        if (coverage) visitBlock(blockX, blockY, coverage);
      }
    }
  }
}

// The lane groups of one triangle inside one tile, in walk order: visit(GroupAt) for every
// group with a covered lane.
template <class F, class Visit>
[[gnu::always_inline]] inline void walkTriangle(const TileJob& job, const SetupTriangle& tri, const LaneLayout<F>& layout, const TileBounds& tile,
                  Visit&& visit) {
  const bool flipY = job.framebuffer->flipY;
  walkTriangleBlocks<F>(job, tri, tile, [&](int blockX, int blockY, uint32_t coverage) __attribute__((always_inline)) {
    for (int g = 0; g < LaneLayout<F>::kGroupsPerBlock; ++g) {
      const unsigned laneMask = groupLaneMask(layout, flipY, coverage, g);
      if (laneMask) visit(GroupAt{blockX + LaneLayout<F>::originX(g), blockY + LaneLayout<F>::originY(g), laneMask});
    }
  });
}

// Walks the bin's triangles in order through the depth test, calling
// passed(index, tri, GroupAt of the lanes that passed, z) for every lane group of a
// colour-writing draw with lanes left (depth-only draws stop at the test and its write).
template <class F, class Passed>
[[gnu::always_inline]] inline void depthTestBin(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin,
                                                const LaneLayout<F>& layout, Passed&& passed) {
  for (uint32_t index : bin) {
    const SetupTriangle& tri = job.triangles[index];
    const bool writesColor = colorOutputsWritten(job.draws[tri.drawIndex], *job.framebuffer) > 0;
    if constexpr (kDepthTestsInBlocks<F>) {
      if (!writesColor) {   // depth only: no quads needed
        const BlockDepthTest<F> depthTest(job, tri);
        walkTriangleBlocks<F>(job, tri, tile, [&](int blockX, int blockY, uint32_t coverage) __attribute__((always_inline)) {
          depthTest(blockX, blockY, coverage);
        });
        continue;
      }
    }
    walkTriangle<F>(job, tri, layout, tile, [&](GroupAt at) __attribute__((always_inline)) {
      F z;
      const unsigned lanes = depthTestGroup(job, tri, layout, at, z);
      if (lanes && writesColor) passed(index, tri, GroupAt{at.x, at.y, lanes}, z);
    });
  }
}

}  // namespace raster
