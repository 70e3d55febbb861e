// The covered-tile fast path: a tile that one triangle covers whole (the fullscreen triangle
// of a post-processing pass being the common case) has no coverage to find and no fragment
// that can fail, so it can be shaded block by block straight from the planes. The same path
// shades a tile's first triangle when it covers the tile and passes its depth test at every
// pixel against the pending clear (tile_clear.h: the floor under a camera).
//
// The reference has no such path: it walks such a tile like any other (shadeCoveredTile
// returns false), which gives the same bits. covered_tile_avx2.h has it for Float8.
#pragma once

#include <cstdint>
#include <span>

#include "raster/contract.h"
#include "raster/limits.h"
#include "raster/simd/lane_layout.h"

namespace raster {

// Shades the tile if the fast path applies to it and the lane type has one; returns whether
// it did (false: nothing was done).
template <class F>
bool shadeCoveredTile(const TileJob&, const TileBounds&, std::span<const uint32_t>, const LaneLayout<F>&,
                      PipelineCounters&) {
  return false;
}

// Whether lane type F has the path for a draw: one whose lane groups GroupShader pairs (the
// path shades a block's two groups as one pair).
template <class F>
bool canShadeBlocksWhole(const DrawRecord&) {
  return false;
}

// And for a tile of whole 4x4 blocks.
template <class F>
bool canShadeTileWhole(const TileBounds& tile, const DrawRecord& draw) {
  constexpr int kBlock = limits::kBlockSize;
  return canShadeBlocksWhole<F>(draw) && (tile.x1 + 1 - tile.x0) % kBlock == 0 && (tile.y1 + 1 - tile.y0) % kBlock == 0;
}

// One 4x4 block of the path: every pixel covered by `tri` and passing its depth test (done
// by the caller), shaded as one pair, the block's upper group then its lower one, as
// GroupShader pairs them, and merged. Only where canShadeBlocksWhole holds for the draw.
template <class F>
void shadeBlockWhole(const TileJob&, const SetupTriangle&, const LaneLayout<F>&, int, int, PipelineCounters&) {}

// The path itself, for a triangle the caller has shown to cover the tile, each of whose
// fragments passes its depth test (its codes, where it writes depth, are stored by the
// caller): every pixel of the tile shaded and merged as the in-order walk would. Only where
// canShadeTileWhole. `onlyTriangle`: nothing after it reaches the tile (its colour may then
// be stored around the cache).
template <class F>
void shadeTileWhole(const TileJob&, const TileBounds&, const SetupTriangle&, const LaneLayout<F>&, bool onlyTriangle,
                    PipelineCounters&) {}

}  // namespace raster

#include "raster/tile/covered_tile_avx2.h"
