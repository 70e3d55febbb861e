// The position of a cell along a Hilbert curve over a square grid: cells close on the curve
// are close on the grid, at every scale, and each cell is a side-step from the one before.
// The renderer orders the tiles of a pass whose lookups spread around each pixel this way
// (Renderer::flush), so the texels a tile reads are mostly those its recent neighbours read.
#pragma once

#include <cstdint>
#include <utility>

namespace raster {

// Cell (x, y) of a side x side grid, side a power of two: its index 0 .. side^2 - 1 along the
// curve that starts at (0, 0) and ends at (side - 1, 0) (the classic xy2d: at each level,
// the quadrant's place on the curve, then the cell taken into that quadrant's frame).
inline uint64_t hilbertIndex(uint32_t x, uint32_t y, uint32_t side) {
  uint64_t index = 0;
  for (uint32_t half = side / 2; half > 0; half /= 2) {
    const uint32_t right = (x & half) ? 1 : 0, top = (y & half) ? 1 : 0;
    index += uint64_t(half) * half * ((3 * right) ^ top);
    // A lower quadrant's frame is the grid's mirrored across a diagonal (the left quadrant's
    // across the main one, the right's across the other).
    if (top == 0) {
      if (right == 1) {
        x = half - 1 - (x & (half - 1));
        y = half - 1 - (y & (half - 1));
      }
      std::swap(x, y);
    }
  }
  return index;
}

// The smallest power of two at least n (n >= 1): the side of the grid hilbertIndex needs.
inline uint32_t hilbertSide(uint32_t n) {
  uint32_t side = 1;
  while (side < n) side *= 2;
  return side;
}

}  // namespace raster
