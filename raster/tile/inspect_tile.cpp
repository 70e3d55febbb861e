// The instrumented tile walk (inspect_tile.h): the in-order walk with ScalarLanes, counting.
#include "raster/tile/inspect_tile.h"

#include <algorithm>

#include "raster/tile/coverage.h"
#include "raster/tile/depth_test.h"
#include "raster/tile/group_shader.h"
#include "raster/tile/interpolate.h"
#include "raster/tile/lane_layout.h"

namespace raster {

void FragmentCounts::reset(int w, int h) {
  width = w;
  height = h;
  for (std::vector<uint32_t>* v : {&shaded, &depthOnly, &depthKills, &helpersUncovered, &helpersKilled})
    v->assign(size_t(w) * size_t(h), 0u);
}

void inspectTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, FragmentCounts& counts,
                 PipelineCounters& counters) {
  using F = ScalarLanes;
  constexpr int kBlock = limits::kBlockSize;
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  FragmentGroup<F> group;
  for (uint32_t index : bin) {
    const SetupTriangle& tri = job.triangles[index];
    const bool writesColor = colorOutputsWritten(job.draws[tri.drawIndex], fb) > 0;
    const WalkEdge edges[3] = {WalkEdge(tri.edge[0]), WalkEdge(tri.edge[1]), WalkEdge(tri.edge[2])};
    const TileBounds bounds = boundsInTile(tri, tile);
    const int x0 = bounds.x0, x1 = bounds.x1, y0 = bounds.y0, y1 = bounds.y1;
    // Every 4x4 block of the triangle's bounds in the tile, tested alone: the walk's 16x16
    // regions only skip blocks that are wholly outside or find ones wholly inside, which
    // blockCoverage finds too.
    for (int blockY = y0 & ~(kBlock - 1); blockY <= y1; blockY += kBlock) {
      for (int blockX = x0 & ~(kBlock - 1); blockX <= x1; blockX += kBlock) {
        const uint32_t coverage = blockCoverage(edges, blockX, blockY) & blockBounds(blockX, blockY, fb.width, fb.height);
        if (!coverage) continue;
        for (int g = 0; g < LaneLayout<F>::kGroupsPerBlock; ++g) {
          const unsigned covered = groupLaneMask(layout, fb.flipY, coverage, g);
          if (!covered) continue;
          const GroupAt at{blockX + LaneLayout<F>::originX(g), blockY + LaneLayout<F>::originY(g), covered};
          F z;
          const unsigned passed = depthTestGroup(job, tri, layout, at, z);
          const bool shades = passed && writesColor;
          for (int i = 0; i < F::kCount; ++i) {
            const int px = at.x + layout.dx[i], py = at.y + layout.dy[i];
            if (px >= fb.width || py >= fb.height) continue;   // a helper off the framebuffer's edge
            const size_t texel = size_t(py) * size_t(fb.width) + size_t(px);
            const bool isCovered = covered >> i & 1u, isPassed = passed >> i & 1u;
            if (isCovered && !isPassed) ++counts.depthKills[texel];
            if (!writesColor) {
              if (isPassed) ++counts.depthOnly[texel];
            } else if (isPassed) {
              ++counts.shaded[texel];
            } else if (shades) {   // shaded only for its quad's derivatives
              ++(isCovered ? counts.helpersKilled : counts.helpersUncovered)[texel];
            }
          }
          if (!shades) continue;
          counters.lanesCovered += unsigned(__builtin_popcount(passed));
          fillGroup(job, tri, layout, GroupAt{at.x, at.y, passed}, z, group);
          shadeGroup(job, group, counters);
        }
      }
    }
  }
}

}  // namespace raster
