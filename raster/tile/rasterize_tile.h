// Stage 5, the tile stage: one 64x64 screen tile's triangles, in API order, into pixels.
//
// Input:  the pass's TileJob (contract.h) and the tile's bin (triangle indices in API order).
// Output: the tile's texels of the framebuffer's attachments, through merge/.
//
// Per triangle the tile is walked in 16x16 regions and 4x4 blocks (coverage.h, walk.h), a
// 4x4 block being what llvmpipe hands its shader; covered blocks are split into lane groups
// (two 2x2 quads for 8 lanes, as llvmpipe's 8-wide shader; lane_layout.h) with helper lanes
// evaluated from the planes so dFdx / dFdy see whole quads; a group with no covered lane is
// skipped. Each group is depth-tested early (depth_test.h), interpolated (interpolate.h),
// shaded and merged (group_shader.h). Two fast paths give the same bits with less work:
//   visible_first.h  passes whose colour draws do not blend, on tiles crossed by many
//                    triangles: depth-test every triangle first, then shade only each
//                    pixel's visible fragment;
//   covered_tile.h   a tile one triangle covers whole (a fullscreen pass) is shaded block
//                    by block straight from the planes; so is a tile's first triangle that
//                    covers it and passes its depth test everywhere (tile_clear.h), and, in
//                    the in-order walk, any 4x4 block a triangle covers whole and passes.
// A tile is rasterized by one task and touches no other tile's pixels, so the output does
// not depend on the thread count.
#pragma once

#include <span>

#include "raster/contract.h"

namespace raster {

// Whether a tile of the job with `triangles` in its bin is walked visibility first. A tile
// crossed by fewer triangles has little overdraw to save (a floor, a cube's faces), and the
// visibility pass would cost more than it saves. (Speed only: the bytes are the same.)
inline bool walksVisibleFirst(const TileJob& job, size_t triangles) {
  constexpr size_t kVisibilityFirstMinTriangles = 16;
  return job.visibilityFirst && triangles >= kVisibilityFirstMinTriangles;
}

// Rasterizes one tile with lane type F (FastLanes, or ScalarLanes for the reference path).
template <class F>
void rasterizeTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, PipelineCounters& counters);

}  // namespace raster
