// The tile stage's loop (see rasterize_tile.h): which path a tile takes, and the in-order
// walk. Sources: llvmpipe lp_rast_tri_tmp.h (block coverage), lp_bld_interp.c (plane
// evaluation), lp_state_fs.c (depth clamp, early depth test), lp_bld_conv.c / lp_bld_blend.c
// (output conversion).
#include "raster/tile/rasterize_tile.h"

#include "raster/tile/coverage.h"
#include "raster/tile/covered_tile.h"
#include "raster/tile/group_shader.h"
#include "raster/tile/interpolate.h"
#include "raster/tile/visible_first.h"
#include "raster/tile/walk.h"
#include "raster/util/cycles.h"

namespace raster {

template <class F>
void rasterizeTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  const uint64_t tileStart = job.timeStages ? cycleCount() : 0;
  const uint64_t shadeBefore = counters.shadeCycles, mergeBefore = counters.mergeCycles;

  if (!shadeCoveredTile(job, tile, bin, layout, counters)) {
    GroupShader<F> shader(job, counters);
    if (walksVisibleFirst(job, bin.size())) {
      rasterizeVisibleFirst<F>(job, tile, bin, layout, counters, shader);
    } else {   // in order: each group is shaded as soon as it passes its depth test
      // Prepared only: a pair of the same triangle's groups is interpolated together.
      depthTestBin<F>(job, tile, bin, layout, [&](uint32_t, const SetupTriangle& tri, GroupAt passed, F z) __attribute__((always_inline)) {
        counters.lanesCovered += unsigned(__builtin_popcount(passed.laneMask));
        prepareGroup(job, tri, layout, passed, z, shader.next());
        shader.push();
      });
    }
    shader.flush();
  }
  if (job.timeStages)
    counters.rasterCycles += (cycleCount() - tileStart) - (counters.shadeCycles - shadeBefore) - (counters.mergeCycles - mergeBefore);
}

template void rasterizeTile<FastLanes>(const TileJob&, const TileBounds&, std::span<const uint32_t>, PipelineCounters&);
template void rasterizeTile<ScalarLanes>(const TileJob&, const TileBounds&, std::span<const uint32_t>, PipelineCounters&);

}  // namespace raster
