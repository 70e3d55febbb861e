// Which tiles of a render target still hold nothing but its last clear: the fast-clear
// metadata GPUs keep beside a target, here for RGBA16F colour targets (the hdr scene's
// float target, whose background the bright pass and the composite read).
//
// A pass writes a target only through the triangles binned to each tile (renderer.cpp), so
// after a pass that clears colour, a tile no triangle reached holds the clear's texel at
// every texel; after a pass that does not clear, such a tile holds what it held before.
// The 16-lane bilinear lookup (sample_half_avx512.h) then skips the fetch of a lane group
// whose footprints all lie in one such tile: the texels are known. It does so only for a
// `plain` value, every channel finite and not -0, where the blend returns the value itself:
// each step is fma(w, right - left, left) with right = left and w in [0, 1), so
// right - left = +0, w * +0 = +0, and left + +0 = left unless left is -0.
// (NEAREST lookups could do the same; SSAO's scattered reads rarely qualify, and the first
// measurement of the deferred passes with it read 2-4% slower.) The clear itself still happens (tile/tile_clear.h): the
// texels are in memory for every other reader, read-back included.
//
// merge::recordClearedTiles keeps it after each pass. Anything else that writes a texture's
// texels (an upload) calls forget().
#pragma once

#include <cstdint>
#include <vector>

namespace raster {

struct ClearedTiles {
  int tilesX = 0;                  // the target's tiles of limits::kTileSize texels, per row
  std::vector<uint8_t> cleared;    // tile ty * tilesX + tx: 1 while it holds only `value`
  float value[4] = {};             // the clear's texel, converted to float
  bool any() const { return !cleared.empty(); }
  void forget() { cleared.clear(); }
};

}  // namespace raster
