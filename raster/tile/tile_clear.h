// A tile's share of the pass's clear, carried out at the start of the tile's task: the
// clears that the tile's first triangle overwrites before anything reads them are not
// done at all (same bytes, less memory traffic).
//
//   colour  the first triangle covers every pixel centre of the tile, writes every colour
//           target without blending, and every one of its fragments passes the depth test
//           (it has none, or the tile's depth is being cleared to a value all of them pass:
//           the floor under a camera, a post pass's fullscreen triangle);
//   depth   the same first triangle writes depth: its codes are stored in place of the
//           clear, without a test, and the walk starts at the second triangle. A
//           depth-only draw needs nothing more (shadow maps whose first triangle fills the
//           tile); a colour draw's triangle is then shaded whole by the covered-tile path
//           (covered_tile.h: the floor under a camera), where the lane type has it and the
//           tile is not walked visibility first (which would shade only what stays seen).
//
// Whether every fragment passes is proven from the z plane's extremes over the tile with a
// bound on the float rounding of its evaluation, so a triangle near the cleared depth
// keeps the clear.
//
// Where the depth clear stays, a tile whose bin holds only depth-only triangles large
// enough to hold a 16x16 region (a shadow map's floor, clipped and fanned into pieces
// none of which covers the tile alone) takes it a region at a time instead, where the lane
// type tests depth along region rows (kDepthRowsInRegions, depth_test.h): the first
// triangle to reach a region tests against the clear's code in place of the stored codes
// and writes all of the region's rows; the regions none reaches are cleared last. Each
// pixel then sees the same codes in the same order as after a whole clear, and the tile
// is stored once instead of twice.
//
// A tile whose bin is empty is cleared with streaming stores (merge/clear_avx2.h) when the
// pass's targets are larger than the threads' own caches (TileJob::streamUntouchedClears):
// nothing of the pass reads it again, and it would not stay in cache for what does.
#pragma once

#include <cstddef>
#include <span>

#include "raster/contract.h"

namespace raster {

struct TileClearPlan {
  ClearValues rest;              // the clears still to be done (merge::clearRect)
  bool firstStoresDepth = false; // the first triangle's depth codes replace the depth clear
  bool firstShadedWhole = false; // and its colour fragments are shaded by the covered-tile path
};

// What of `pending` the tile needs, given its bin (API order). `shadesWhole`: the tile's
// lane type can shade the bin's first triangle whole (canShadeTileWhole).
TileClearPlan planTileClear(const TileJob& job, std::span<const uint32_t> bin, const TileBounds& tile,
                            const ClearValues& pending, bool shadesWhole);

// True when the triangle's depth test passes at every pixel centre of `rect` against a
// buffer holding `stored` everywhere (the test as its draw's state asks for it).
bool depthTestPassesEverywhere(const SetupTriangle& tri, const RasterState& state, TexelFormat format,
                               uint32_t stored, const TileBounds& rect);

// Clears the tile as planned; returns how many of the bin's first triangles that did the
// work of (0 or 1, or the whole bin where the depth clear went region by region), which
// the walk then skips. F is the lane type the tile is walked with;
// `counters` count the fragments a triangle shaded whole.
template <class F>
size_t clearTile(const TileJob& job, std::span<const uint32_t> bin, const TileBounds& tile, const ClearValues& pending,
                 PipelineCounters& counters);

}  // namespace raster
