// The coarse-rate tile walk (coarse_tile.h). Source: the Vulkan specification, "Fragment
// Shading Rates" and "Coarse Fragments" (VK_KHR_fragment_shading_rate).
#include "raster/tile/coarse_tile.h"

#include <algorithm>
#include <cstdint>

#include "raster/tile/coarse_shader.h"
#include "raster/tile/coarse_walk.h"
#include "raster/tile/interpolate.h"
#include "raster/simd/lane_layout.h"
#include "raster/tile/walk.h"
#include "raster/util/cycles.h"

namespace raster {

using coarse_walk::passedPixels;
using coarse_walk::prepareCoarseGroups;
using coarse_walk::PassedPixels;

template <class F>
void rasterizeTileCoarse(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  const CoarseLayout<F> coarse(layout, job.coarseWidth, job.coarseHeight, fb.width);
  const uint64_t tileStart = job.timeStages ? cycleCount() : 0;
  const uint64_t shadeBefore = counters.shadeCycles, mergeBefore = counters.mergeCycles;
  CoarseShader<F> shader(job, coarse, counters);
  for (size_t i = 0; i < bin.size(); ++i) {
    const SetupTriangle& tri = job.triangles[bin[i]];
    if (colorOutputsWritten(job.draws[tri.drawIndex], fb) == 0) {   // depth only: the 1x1 walk's test and writes
      depthTestBin<F>(job, tile, bin.subspan(i, 1), layout, [](uint32_t, const SetupTriangle&, GroupAt, F) {});
      continue;
    }
    PassedPixels passed;
    passedPixels(job, tile, bin.subspan(i, 1), layout, passed, counters);
    prepareCoarseGroups(job, tri, tile, coarse, passed, shader);
  }
  shader.flush();
  if (job.timeStages)
    counters.rasterCycles += (cycleCount() - tileStart) - (counters.shadeCycles - shadeBefore) - (counters.mergeCycles - mergeBefore);
}

template void rasterizeTileCoarse<FastLanes>(const TileJob&, const TileBounds&, std::span<const uint32_t>, PipelineCounters&);
template void rasterizeTileCoarse<ScalarLanes>(const TileJob&, const TileBounds&, std::span<const uint32_t>, PipelineCounters&);

}  // namespace raster
