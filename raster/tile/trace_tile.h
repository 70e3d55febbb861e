// Pixel history's tile: the tile holding a pass's probe pixel, rasterized with every
// fragment at the probe recorded (raster/pixel_history.h).
//
// The walk is the reference in-order one: ScalarLanes (one 2x2 quad per lane group), each
// triangle of the bin in API order through coverage, the early depth test, interpolation,
// the shader and the output merge, built from the same functions rasterize_tile.cpp uses.
// The fast paths (visibility first, covered tiles, the vector lane types) give the same
// bytes, so the tile ends exactly as it would have; this walk only also looks at the probe.
#pragma once

#include <span>

#include "raster/contract.h"
#include "raster/pixel_history.h"

namespace raster {

// Rasterizes one tile as rasterizeTile<ScalarLanes> does (in order), appending to
// `history.fragments` every fragment at pixel (history.x, history.y), which lies in `tile`.
// `drawBase` is the pass-level index of the job's first draw (a pass flushed twice starts
// its second job's draws from 0); `origins` holds each triangle's origin (contract.h).
void traceTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, uint32_t drawBase,
               std::span<const uint32_t> origins, PassHistory& history, PipelineCounters& counters);

// The same for a pass shaded at a coarse rate (job.coarseWidth x job.coarseHeight above
// 1x1): the tile as rasterizeTileCoarse<ScalarLanes> does it (coarse_tile.h), recording at
// the probe the invocation that shaded its coarse pixel and the pixels its outputs reached.
void traceTileCoarse(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, uint32_t drawBase,
                     std::span<const uint32_t> origins, PassHistory& history, PipelineCounters& counters);

}  // namespace raster
