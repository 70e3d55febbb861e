// How a lane group sits on the screen: quads of 2x2 pixels (lanes TL, TR, BL, BR, as
// llvmpipe's lp_bld_quad.h orders them), quads side by side.
//
// An 8-lane group (FastLanes) is two quads side by side: a 4x2 rectangle, half of a 4x4
// block. A 4-lane group (ScalarLanes) is one quad, a quarter of a block. "Top" is GL's top:
// on window-system buffers, stored top row first, the quad's rows are swapped, so
// dFdy = bottom - top lanes gives GL's sign. (llvmpipe computes the memory-row difference
// and negates it, nir_lower_wpos_ytransform; both are the same exact value.)
#pragma once

#include <cstddef>
#include <cstdint>

#include "raster/limits.h"
#include "raster/simd/isa.h"

namespace raster {

// A lane group's place in the framebuffer: the pixel of its lane 0's quad corner (x, y),
// and the lanes whose pixels are covered (bit i: lane i).
struct GroupAt {
  int x, y;
  unsigned laneMask;
};

// Lane i's pixel offset from its group's origin, rows in GL's order (a window-system buffer
// swaps a quad's rows in memory: LaneLayout's flipY): quads side by side, each TL, TR, BL, BR.
constexpr int laneDx(int i) { return (i / 4) * 2 + (i & 1); }
constexpr int laneDy(int i) { return (i >> 1) & 1; }

template <class F>
struct LaneLayout {
  static constexpr int kLanes = F::kCount;
  static constexpr int kQuads = kLanes / 4;
  static constexpr int kGroupsPerBlock = 16 / kLanes;
  int dx[kLanes], dy[kLanes];   // each lane's pixel offset from the group's origin
  F dxLanes, dyLanes;           // the same offsets as lane values
  size_t texel[kLanes];         // the same offsets in texels of a `width`-wide attachment
  LaneLayout(bool flipY, int width) {
    alignas(32) float fx[kLanes], fy[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      dx[i] = laneDx(i);
      dy[i] = flipY ? 1 - laneDy(i) : laneDy(i);
      fx[i] = float(dx[i]);
      fy[i] = float(dy[i]);
      texel[i] = size_t(dy[i]) * size_t(width) + size_t(dx[i]);
    }
    dxLanes = F::load(fx);
    dyLanes = F::load(fy);
  }
  // Group g's origin inside a 4x4 block: 8 lanes cover rows 0-1 then 2-3; 4 lanes one quad.
  static constexpr int originX(int g) { return kQuads == 2 ? 0 : (g & 1) * 2; }
  static constexpr int originY(int g) { return kQuads == 2 ? g * 2 : (g >> 1) * 2; }
  // Lane mask of group g from the block's coverage (bit row * 4 + col).
  unsigned laneMask(uint32_t coverage, int g) const {
    unsigned mask = 0;
    for (int i = 0; i < kLanes; ++i) {
      const int row = originY(g) + dy[i], col = originX(g) + dx[i];
      mask |= (coverage >> (row * limits::kBlockSize + col) & 1u) << i;
    }
    return mask;
  }
};

// laneMask() of 8-lane groups for every pair of block rows at once: a table from the rows'
// 8 coverage bits (upper row in bits 0-3) to the 8 lanes of a group, one per orientation.
struct RowPairLanes {
  uint8_t lanes[2][256];
  RowPairLanes() {
    for (int flip = 0; flip < 2; ++flip) {
      const LaneLayout<simd::Lanes<8>> layout(flip == 1, 0);
      for (unsigned bits = 0; bits < 256; ++bits) lanes[flip][bits] = uint8_t(layout.laneMask(bits, 0));
    }
  }
};
inline const RowPairLanes kRowPairLanes;

// The lane mask of group g of a block with `coverage`.
template <class F>
unsigned groupLaneMask(const LaneLayout<F>& layout, bool flipY, uint32_t coverage, int g) {
  if constexpr (F::kCount == 8) return kRowPairLanes.lanes[flipY][(coverage >> (8 * g)) & 0xFFu];
  else return layout.laneMask(coverage, g);
}

}  // namespace raster
