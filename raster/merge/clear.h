// glClear, carried out one tile rectangle at a time inside the tiles' tasks (so it runs in
// parallel, and the tile's pixels are then in cache for its triangles).
//
// Colour clear values are converted once, as llvmpipe converts them: unorm8 rounded from
// the clamped value, half-floats truncated toward zero (format.h); depth to its code.
#pragma once

#include <cstdint>
#include <span>

#include "raster/contract.h"

namespace raster::merge {

// Clears the rectangle `rect` (inclusive) of the framebuffer's depth buffer, when `values`
// asks for it, and of its colour attachments when `values` asks and `colorToo` is set.
// `untouched`: nothing of the pass writes or reads the rectangle afterwards (a tile no
// triangle reaches), so its rows are stored around the cache (clear_avx2.h).
void clearRect(const Framebuffer& framebuffer, const ClearValues& values, const TileBounds& rect, bool colorToo,
               bool untouched = false);

// After a pass: what each colour target's cleared tiles are now (texture/cleared_tiles.h).
// `clearedColor`: the pass cleared colour; touched[tile]: some triangle was binned to the
// framebuffer's tile (index ty * tilesX + tx). Tracked are RGBA16F targets the size of the
// framebuffer, stored bottom row first, whose clear is plain; every other is forgotten.
void recordClearedTiles(const Framebuffer& framebuffer, bool clearedColor, int tilesX, std::span<const uint8_t> touched);

}  // namespace raster::merge
