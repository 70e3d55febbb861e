// The coarse walk's steps (coarse_tile.h), shared by the walk itself and by the two
// walks that look at its fragments: pixel history's probe tile (trace_tile.cpp) and the
// stage views' counting walk (inspect_tile.cpp). One copy of the steps is what makes those
// walks leave the bytes the coarse walk leaves.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>

#include "raster/contract.h"
#include "raster/tile/coarse_shader.h"
#include "raster/tile/interpolate.h"
#include "raster/simd/lane_layout.h"
#include "raster/tile/walk.h"

namespace raster {
namespace coarse_walk {

// The pixels of a tile (or band) where one triangle's fragments passed the depth test:
// bit x - tile.x0 of row y - tile.y0.
struct PassedPixels {
  uint64_t rows[limits::kTileSize] = {};
  bool at(int x, int y) const { return rows[y] >> x & 1u; }
};
static_assert(limits::kTileSize == 64, "a tile row of passed pixels is one uint64_t");

// Step 1: the pixels of the tile where the triangle's fragments pass, with the 1x1 walk's
// coverage and depth test (and its depth writes). Without a depth test, straight from the
// blocks' coverage (bit row * 4 + col, memory rows, as the lane masks read it).
template <class F>
[[gnu::always_inline]] inline void passedPixels(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> one,
                                                const LaneLayout<F>& layout, PassedPixels& passed, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const SetupTriangle& tri = job.triangles[one[0]];
  const DrawRecord& draw = job.draws[tri.drawIndex];
  if (draw.state.depthTest && fb.depth) {
    depthTestBin<F>(job, tile, one, layout, [&](uint32_t, const SetupTriangle&, GroupAt at, F) __attribute__((always_inline)) {
      counters.lanesCovered += unsigned(__builtin_popcount(at.laneMask));
      for (int lane = 0; lane < F::kCount; ++lane)
        if (at.laneMask >> lane & 1u)
          passed.rows[at.y + layout.dy[lane] - tile.y0] |= uint64_t(1) << (at.x + layout.dx[lane] - tile.x0);
    });
    return;
  }
  constexpr int kBlock = limits::kBlockSize;
  walkTriangleBlocks<F>(job, tri, tile, [&](int blockX, int blockY, uint32_t coverage) __attribute__((always_inline)) {
    counters.lanesCovered += unsigned(__builtin_popcount(coverage));
    for (int row = 0; row < kBlock; ++row)
      passed.rows[blockY + row - tile.y0] |= uint64_t(coverage >> (row * kBlock) & 0xFu) << (blockX - tile.x0);
  });
}

// Steps 2-3: the coarse lane groups of one triangle that hold a passed pixel, prepared at
// their coarse pixels' centres and handed to the shader.
// Shader: CoarseShader<F>, or a walk of its own that looks at the groups on the way
// (trace_tile.cpp, inspect_tile.cpp): next() gives the slot to prepare, push() takes it.
template <class F, class Shader>
void prepareCoarseGroups(const TileJob& job, const SetupTriangle& tri, const TileBounds& tile, const CoarseLayout<F>& coarse,
                         const PassedPixels& passed, Shader& shader) {
  const Framebuffer& fb = *job.framebuffer;
  const DrawRecord& draw = job.draws[tri.drawIndex];
  const int outputs = colorOutputsWritten(draw, fb);
  int rowMin = limits::kTileSize, rowMax = -1;
  uint64_t columns = 0;
  for (int row = 0; row < limits::kTileSize; ++row) {
    if (!passed.rows[row]) continue;
    rowMin = std::min(rowMin, row);
    rowMax = row;
    columns |= passed.rows[row];
  }
  if (rowMax < 0) return;
  const int columnMin = __builtin_ctzll(columns), columnMax = 63 - __builtin_clzll(columns);
  for (int row = rowMin / coarse.groupHeight * coarse.groupHeight; row <= rowMax; row += coarse.groupHeight) {
    for (int column = columnMin / coarse.groupWidth * coarse.groupWidth; column <= columnMax; column += coarse.groupWidth) {
      // The group's rectangle of passed pixels: none, all (a fullscreen pass), or some.
      const uint64_t groupColumns = (uint64_t(1) << coarse.groupWidth) - 1u;
      uint64_t some = 0, all = groupColumns;
      for (int r = 0; r < coarse.groupHeight; ++r) {
        const uint64_t bits = passed.rows[row + r] >> column & groupColumns;
        some |= bits;
        all &= bits;
      }
      if (!some) continue;
      CoarseGroup<F>& g = shader.next();
      unsigned anyPixel = 0;
      for (int s = 0; s < coarse.pixels; ++s) {   // which lanes write pixel s of their coarse pixel
        unsigned mask = (1u << F::kCount) - 1u;
        if (all != groupColumns) {
          mask = 0;
          for (int i = 0; i < F::kCount; ++i)
            mask |= unsigned(passed.at(column + coarse.laneX[i] + coarse.pixelX[s], row + coarse.laneY[i] + coarse.pixelY[s])) << i;
        }
        g.laneMask[s] = mask;
        anyPixel |= mask;
      }
      const int x = tile.x0 + column, y = tile.y0 + row;
      const size_t origin = size_t(y) * size_t(fb.width) + size_t(x);
      FragmentGroup<F>& group = g.group;
      for (int i = 0; i < F::kCount; ++i) group.texel[i] = origin + coarse.laneTexel[i];
      group.outputs = outputs;
      group.draw = &draw;
      group.laneMask = anyPixel;   // lanes with a pixel to write; the rest are helpers
      group.tri = &tri;
      group.px = F(float(x)) + coarse.centreX;
      group.py = F(float(y)) + coarse.centreY;
      group.z = fragmentDepth(tri, group.px, group.py);
      group.interpolated = false;
      shader.push();
    }
  }
}

}  // namespace coarse_walk
}  // namespace raster
