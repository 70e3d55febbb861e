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

// The sixteen lanes of a whole 4x4 block in one 512-bit register (simd::Float8x2): its upper
// 8-lane group (LaneLayout's group 0) in lanes 0-7, its lower one in lanes 8-15. A post
// pass's lanes read texels where their pixels are, so the samplers' 16-lane block paths
// (texture/sample_*_avx512.h) take their lane tables from here. Rows count upward in GL's y,
// as texel rows do: in an offscreen target (stored bottom row first) a lane's row is its
// memory row; in a window-system buffer (`flipY`: stored top row first, each quad's rows
// swapped in memory) it is 3 minus its memory row, so the two groups' row pairs trade places.
struct BlockLanes {
  static constexpr int kCount = 16;
  static constexpr int column(int lane) { return LaneLayout<simd::Lanes<8>>::originX(lane / 8) + laneDx(lane % 8); }
  static constexpr int row(int lane, bool flipY = false) {
    const int memoryRow = LaneLayout<simd::Lanes<8>>::originY(lane / 8) + (flipY ? 1 - laneDy(lane % 8) : laneDy(lane % 8));
    return flipY ? 3 - memoryRow : memoryRow;
  }
  // The lane at (column, row).
  static constexpr int at(int column, int row, bool flipY = false) {
    for (int lane = 0; lane < kCount; ++lane)
      if (BlockLanes::column(lane) == column && BlockLanes::row(lane, flipY) == row) return lane;
    return -1;
  }
};
// The lanes of the block's left column, by row: a lane of each row (the same four lanes in
// either kind of buffer).
inline constexpr int kBlockRowLeads[4] = {BlockLanes::at(0, 0), BlockLanes::at(0, 1), BlockLanes::at(0, 2),
                                          BlockLanes::at(0, 3)};

}  // namespace raster
