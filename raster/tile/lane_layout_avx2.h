// An 8-lane group (two 2x2 quads side by side) against its two memory rows of 4 pixels:
// the permutes between the two orders, for the tile and merge stages' AVX2 paths.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"

namespace raster {

// permutevar8x32 indices from quad lane order to row-major order [top x..x+3 | bottom
// x..x+3], and back. `flipped`: the quads' rows are swapped (window-system buffers).
inline __m256i quadLanesToRows(bool flipped) {
  return flipped ? _mm256_setr_epi32(2, 3, 6, 7, 0, 1, 4, 5) : _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
}
inline __m256i rowsToQuadLanes(bool flipped) {
  return flipped ? _mm256_setr_epi32(4, 5, 0, 1, 6, 7, 2, 3) : _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
}

}  // namespace raster
#endif
