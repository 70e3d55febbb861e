// The coarse-rate tile walk (coarse_tile.h). Source: the Vulkan specification, "Fragment
// Shading Rates" and "Coarse Fragments" (VK_KHR_fragment_shading_rate).
#include "raster/tile/coarse_tile.h"

#include <cstdint>

#include "raster/merge/color_write.h"
#include "raster/shader/shader_instance.h"
#include "raster/tile/interpolate.h"
#include "raster/tile/lane_layout.h"
#include "raster/tile/walk.h"
#include "raster/util/cycles.h"

namespace raster {
namespace {

constexpr int kMaxCoarseSide = 4;   // the largest rate is 4x4 (methods.h)

// The pixels of a tile (or band) where one triangle's fragments passed the depth test:
// bit x - tile.x0 of row y - tile.y0.
struct PassedPixels {
  uint64_t rows[limits::kTileSize] = {};
  int rowMin = limits::kTileSize, rowMax = -1;
  uint64_t columns = 0;   // the rows ORed: which columns hold a passed pixel
  bool at(int x, int y) const { return rows[y] >> x & 1u; }
};
static_assert(limits::kTileSize == 64, "a tile row of passed pixels is one uint64_t");

// How a lane group sits on the screen at a coarse rate: LaneLayout's quads with each lane
// a coarse pixel of width x height pixels.
template <class F>
struct CoarseLayout {
  int width, height;               // a coarse pixel, in pixels
  int groupWidth, groupHeight;     // a lane group, in pixels
  int laneX[F::kCount], laneY[F::kCount];   // each lane's coarse pixel's first pixel from the group's origin
  size_t laneTexel[F::kCount];     // the same in texels
  F centreX, centreY;              // each lane's coarse pixel centre from the group's origin
  int pixels;                      // pixels per coarse pixel
  int pixelX[kMaxCoarseSide * kMaxCoarseSide], pixelY[kMaxCoarseSide * kMaxCoarseSide];   // pixel s of a coarse pixel
  size_t pixelTexel[kMaxCoarseSide * kMaxCoarseSide];                                     // the same in texels

  CoarseLayout(const LaneLayout<F>& fine, int w, int h, int framebufferWidth) : width(w), height(h) {
    groupWidth = LaneLayout<F>::kQuads * 2 * w;
    groupHeight = 2 * h;
    alignas(64) float cx[F::kCount], cy[F::kCount];
    for (int i = 0; i < F::kCount; ++i) {
      laneX[i] = fine.dx[i] * w;   // fine.dy is flipped on window-system buffers: GL's top row first
      laneY[i] = fine.dy[i] * h;
      laneTexel[i] = size_t(laneY[i]) * size_t(framebufferWidth) + size_t(laneX[i]);
      cx[i] = float(laneX[i]) + 0.5f * float(w - 1);   // pixel centres are at integers (interpolate.h)
      cy[i] = float(laneY[i]) + 0.5f * float(h - 1);
    }
    centreX = F::load(cx);
    centreY = F::load(cy);
    pixels = w * h;
    for (int s = 0; s < pixels; ++s) {
      pixelX[s] = s % w;
      pixelY[s] = s / w;
      pixelTexel[s] = size_t(pixelY[s]) * size_t(framebufferWidth) + size_t(pixelX[s]);
    }
  }
};

// Shades the coarse lane groups of one triangle that hold a passed pixel, and writes each
// lane's outputs to its passed pixels.
template <class F>
void shadeCoarse(const TileJob& job, const SetupTriangle& tri, const TileBounds& tile, const CoarseLayout<F>& coarse,
                 const PassedPixels& passed, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const DrawRecord& draw = job.draws[tri.drawIndex];
  const int outputs = colorOutputsWritten(draw, fb);
  const int columnMin = __builtin_ctzll(passed.columns), columnMax = 63 - __builtin_clzll(passed.columns);
  FragmentGroup<F> group;
  group.draw = &draw;
  group.tri = &tri;
  group.outputs = outputs;
  for (int row = passed.rowMin / coarse.groupHeight * coarse.groupHeight; row <= passed.rowMax; row += coarse.groupHeight) {
    for (int column = columnMin / coarse.groupWidth * coarse.groupWidth; column <= columnMax; column += coarse.groupWidth) {
      // Which lanes write pixel s of their coarse pixel.
      unsigned laneMask[kMaxCoarseSide * kMaxCoarseSide];
      unsigned anyPixel = 0;
      for (int s = 0; s < coarse.pixels; ++s) {
        unsigned mask = 0;
        for (int i = 0; i < F::kCount; ++i)
          mask |= unsigned(passed.at(column + coarse.laneX[i] + coarse.pixelX[s], row + coarse.laneY[i] + coarse.pixelY[s])) << i;
        laneMask[s] = mask;
        anyPixel |= mask;
      }
      if (!anyPixel) continue;
      const int x = tile.x0 + column, y = tile.y0 + row;
      const size_t origin = size_t(y) * size_t(fb.width) + size_t(x);
      for (int i = 0; i < F::kCount; ++i) group.texel[i] = origin + coarse.laneTexel[i];
      group.laneMask = anyPixel;
      group.px = F(float(x)) + coarse.centreX;
      group.py = F(float(y)) + coarse.centreY;
      group.z = fragmentDepth(tri, group.px, group.py);
      group.interpolated = false;
      interpolateGroup(job, group);
      const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;
      FragmentOutput<F> out;
      draw.shader->shadeFragments(group.in, group.varyings, out);
      const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;
      counters.shadeCycles += mergeStart - shadeStart;
      counters.laneGroupsShaded += 1;
      counters.lanesShaded += F::kCount;
      for (int k = 0; k < outputs; ++k)
        merge::writeCoarseColorOutput(*fb.colors[k], out.color[k], group.texel, coarse.pixelTexel, laneMask, coarse.pixels,
                                      draw.state.blendAdditive);
      if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
    }
  }
}

}  // namespace

template <class F>
void rasterizeTileCoarse(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  const CoarseLayout<F> coarse(layout, job.coarseWidth, job.coarseHeight, fb.width);
  const uint64_t tileStart = job.timeStages ? cycleCount() : 0;
  const uint64_t shadeBefore = counters.shadeCycles, mergeBefore = counters.mergeCycles;
  for (size_t i = 0; i < bin.size(); ++i) {
    // 1. Coverage and the depth test, per pixel (a depth-only draw ends here).
    PassedPixels passed;
    depthTestBin<F>(job, tile, bin.subspan(i, 1), layout, [&](uint32_t, const SetupTriangle&, GroupAt at, F) {
      counters.lanesCovered += unsigned(__builtin_popcount(at.laneMask));
      for (int lane = 0; lane < F::kCount; ++lane) {
        if (!(at.laneMask >> lane & 1u)) continue;
        const int row = at.y + layout.dy[lane] - tile.y0, column = at.x + layout.dx[lane] - tile.x0;
        passed.rows[row] |= uint64_t(1) << column;
        passed.rowMin = std::min(passed.rowMin, row);
        passed.rowMax = std::max(passed.rowMax, row);
        passed.columns |= uint64_t(1) << column;
      }
    });
    // 2-3. Coarse groups shaded and written.
    if (passed.rowMax >= 0) shadeCoarse(job, job.triangles[bin[i]], tile, coarse, passed, counters);
  }
  if (job.timeStages)
    counters.rasterCycles += (cycleCount() - tileStart) - (counters.shadeCycles - shadeBefore) - (counters.mergeCycles - mergeBefore);
}

template void rasterizeTileCoarse<FastLanes>(const TileJob&, const TileBounds&, std::span<const uint32_t>, PipelineCounters&);
template void rasterizeTileCoarse<ScalarLanes>(const TileJob&, const TileBounds&, std::span<const uint32_t>, PipelineCounters&);

}  // namespace raster
