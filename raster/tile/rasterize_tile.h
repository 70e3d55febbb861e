// Stages 5 and 6, rasterization and output merge, for one 64x64 screen tile.
//
// Input:  the tile's bin (triangle indices in API order), the set-up triangles, their
//         draws, and the framebuffer.
// Output: the tile's pixels in the framebuffer's attachments.
//
// Per triangle, the tile is walked in 4x4 blocks (llvmpipe's LP_RASTER_BLOCK_SIZE): a block
// is trivially rejected or accepted by its corners, else its 16 pixel centres are tested.
// Covered blocks are shaded a lane group at a time (two 2x2 quads side by side for 8
// lanes, as llvmpipe's 8-wide shader), with helper lanes evaluated from the planes so
// dFdx / dFdy see whole quads; a group with no covered lane is skipped.
// Per group: z from its plane plus polygon offset, clamped to [0, 1] and quantized; depth
// test and write; then varyings (perspective-correct), the fragment shader, and the
// conversion and write of every colour output for the lanes that passed.
// Passes whose colour draws do not blend, on tiles crossed by many triangles, shade only
// the visible fragments: all the tile's triangles are depth-tested first, recording each
// pixel's last colour fragment to pass, and then only those are shaded (same groups, same
// bits; TileJob::visibilityFirst).
// Programs that read textures are shaded two groups per call (simd::Float8x2, with AVX2):
// their lookups wait on memory, and a second group's lookups overlap that wait. Pairing
// never changes a bit: lanes are independent, and writes keep their order.
// A tile that a single triangle covers whole (a post-processing pass's fullscreen
// triangle) skips the walk: its blocks are shaded pair by pair straight from the planes.
#pragma once

#include <span>

#include "raster/renderer.h"

namespace raster {

struct TileJob {
  const Framebuffer* framebuffer = nullptr;
  std::span<const SetupTriangle> triangles;
  std::span<const Plane> varyingPlanes;
  std::span<const RecordedDraw> draws;
  bool timeStages = false;   // read the cycle counter around each stage (raster bench)
  // No colour draw of the pass blends: tiles find each pixel's visible fragment first and
  // shade only those (rasterizeVisibleFirst in raster_tile.cpp).
  bool visibilityFirst = false;
};

constexpr int kTileSize = 64;   // llvmpipe TILE_ORDER 6

// True when the triangle covers every pixel centre of the rectangle [x0, x1) x [y0, y1).
bool triangleCoversRect(const SetupTriangle& tri, int x0, int y0, int x1, int y1);

// True when the bin's first triangle writes every colour texel of the rectangle
// [x0, x1) x [y0, y1) of the tile: it covers every pixel centre there, its draw writes
// every colour target of the framebuffer without blending, and no depth test can reject
// one of its fragments. A colour clear of that rectangle would be overwritten before
// anything reads it (the fullscreen triangles of the post-processing passes).
bool firstTriangleOverwritesColor(const TileJob& job, std::span<const uint32_t> bin, int x0, int y0, int x1, int y1);

template <class F>
void rasterizeTile(const TileJob& job, int tileX, int tileY, std::span<const uint32_t> bin, PipelineCounters& counters);

}  // namespace raster
