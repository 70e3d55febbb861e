// The covered-tile fast path: a tile that one triangle covers whole (the fullscreen triangle
// of a post-processing pass being the common case) has no coverage to find and no fragment
// that can fail, so it can be shaded block by block straight from the planes.
//
// The reference has no such path: it walks such a tile like any other (shadeCoveredTile
// returns false), which gives the same bits. covered_tile_avx2.h has it for Float8.
#pragma once

#include <cstdint>
#include <span>

#include "raster/contract.h"
#include "raster/tile/lane_layout.h"

namespace raster {

// Shades the tile if the fast path applies to it and the lane type has one; returns whether
// it did (false: nothing was done).
template <class F>
bool shadeCoveredTile(const TileJob&, const TileBounds&, std::span<const uint32_t>, const LaneLayout<F>&,
                      PipelineCounters&) {
  return false;
}

}  // namespace raster

#include "raster/tile/covered_tile_avx2.h"
