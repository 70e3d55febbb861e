// The instrumented tile walk behind the stage views (`raster render --view`,
// apps/views/stage_views.h): one tile's triangles in API order, every fragment counted per pixel.
//
// It is the in-order walk of rasterize_tile.cpp with the reference lanes (ScalarLanes: one
// 2x2 quad per lane group, as GL's derivative rules describe), built from the same
// primitives (coverage.h, depthTestGroup, fillGroup, shadeGroup), so the pixels it writes
// are the bytes of `raster --scalar`, which are those of the default build. What it counts
// is GL's semantics, not this pipeline's shortcuts: every fragment in order, as if neither
// visibility first (visible_first.h) nor the covered-tile path (covered_tile.h) existed,
// and depth-only draws tested group by group rather than a 16x16 region at a time. Those
// paths change how many fragments are shaded, never the bytes.
//
// The renderer takes this walk only when a view asks for fragment counts; the normal tile
// loop is untouched. Counts are per pixel, and a tile touches only its own pixels, so
// tiles on different threads never write the same count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "raster/contract.h"

namespace raster {

// One pass's fragments per pixel, indexed as the framebuffer's texels (memory rows:
// y * width + x). Helper lanes (shaded only so dFdx / dFdy see whole quads) are counted
// apart from fragments, and never in `shaded`.
struct FragmentCounts {
  static constexpr int kCountersPerPixel = 6;   // the arrays below (4 bytes per entry each)
  int width = 0, height = 0;
  std::vector<uint32_t> shaded;            // covered, passed the depth test, fragment shader ran
  std::vector<uint32_t> depthOnly;         // covered and passed, in a draw that writes no colour (no shader runs)
  std::vector<uint32_t> depthKills;        // covered, rejected by the (early) depth test
  std::vector<uint32_t> helpersUncovered;  // helper lanes: the pixel is outside the triangle
  std::vector<uint32_t> helpersKilled;     // helper lanes: covered, but failed the depth test
  // Fragment-shader invocations whose outputs reached the pixel, each invocation shared out
  // evenly over the pixels it wrote: 1 per fragment at 1x1, 1/4 per pixel of a whole 2x2
  // coarse pixel (tile/coarse_tile.h). Its sum over a pass is the invocations that wrote.
  std::vector<float> invocations;
  void reset(int width, int height);
};

// Rasterizes one tile as rasterizeTile<ScalarLanes> would with visibility first off (same
// bytes), adding its fragments to `counts` and its work to `counters` as that walk does.
void inspectTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, FragmentCounts& counts,
                 PipelineCounters& counters);

// The same for a pass shaded at a coarse rate: the tile as rasterizeTileCoarse<ScalarLanes>
// does it (coarse_tile.h), through its own steps (coarse_walk.h). `shaded` counts the pixels
// an invocation's outputs reached; an invocation that reached none (a helper lane of its
// coarse quad) is counted in no per-pixel array, only in `counters`.
void inspectTileCoarse(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, FragmentCounts& counts,
                       PipelineCounters& counters);

}  // namespace raster
