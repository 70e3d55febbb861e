// Coarse group shading (coarse_tile.h): a lane group whose lanes stand for coarse pixels,
// through its draw's fragment shader, then each lane's outputs to the pixels of its coarse
// pixel that passed (merge::writeCoarseColorOutput).
//
// The reference shades each group at once. coarse_shader_avx2.h shades Float8 groups two
// per call (Float8x2) where group_shader_avx2.h pairs 1x1 groups; lanes are independent and
// colours are written in the order the groups became ready, so pairing changes no bit.
#pragma once

#include <cstddef>

#include "raster/contract.h"
#include "raster/merge/color_write.h"
#include "raster/shader/shader_instance.h"
#include "raster/tile/interpolate.h"
#include "raster/simd/lane_layout.h"
#include "raster/util/cycles.h"

namespace raster {

constexpr int kMaxCoarseSide = 4;   // the largest rate is 4x4 (methods.h)
constexpr int kMaxCoarsePixels = kMaxCoarseSide * kMaxCoarseSide;

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
  int pixelX[kMaxCoarsePixels], pixelY[kMaxCoarsePixels];   // pixel s of a coarse pixel
  size_t pixelTexel[kMaxCoarsePixels];                      // the same in texels

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

// A prepared coarse group (prepareGroup's fields, at coarse pixel centres) and which lanes
// write pixel s of their coarse pixel: laneMask[s].
template <class F>
struct CoarseGroup {
  FragmentGroup<F> group;
  unsigned laneMask[kMaxCoarsePixels];
};

// Writes a shaded coarse group's colour outputs.
template <class F>
void writeCoarseGroup(const TileJob& job, const CoarseLayout<F>& coarse, const CoarseGroup<F>& g, const FragmentOutput<F>& out) {
  const Framebuffer& fb = *job.framebuffer;
  for (int k = 0; k < g.group.outputs; ++k)
    merge::writeCoarseColorOutput(*fb.colors[k], out.color[k], g.group.texel, coarse.pixelTexel, g.laneMask, coarse.pixels,
                                  g.group.draw->state.blendAdditive);
}

// Shades one prepared coarse group and writes its outputs.
template <class F>
void shadeCoarseGroup(const TileJob& job, const CoarseLayout<F>& coarse, CoarseGroup<F>& g, PipelineCounters& counters) {
  interpolateGroup(job, g.group);   // counted as rasterization, as in the 1x1 walk
  const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;
  FragmentOutput<F> out;
  out.unorm8Outputs = job.unorm8Outputs;
  g.group.draw->shader->shadeFragments(g.group.in, g.group.varyings, out);
  const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;
  counters.shadeCycles += mergeStart - shadeStart;
  counters.laneGroupsShaded += 1;
  counters.lanesShaded += F::kCount;
  writeCoarseGroup(job, coarse, g, out);
  if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
}

// Shades a tile's coarse groups in order: next() is where the walk prepares one, push()
// hands it over, flush() finishes any group still waiting.
template <class F>
class CoarseShader {
 public:
  CoarseShader(const TileJob& job, const CoarseLayout<F>& coarse, PipelineCounters& counters)
      : job_(job), coarse_(coarse), counters_(counters) {}
  CoarseGroup<F>& next() { return slot_; }
  void push() { shadeCoarseGroup(job_, coarse_, slot_, counters_); }
  void flush() {}

 private:
  const TileJob& job_;
  const CoarseLayout<F>& coarse_;
  PipelineCounters& counters_;
  CoarseGroup<F> slot_;
};

}  // namespace raster

#include "raster/tile/coarse_shader_avx2.h"
