// Group shading: a ready FragmentGroup through its draw's fragment shader, then its colour
// outputs through the output merge (merge/color_write.h).
//
// The tile stage hands groups to a GroupShader in the order they pass their depth test. The
// reference shades each at once. group_shader_avx2.h shades Float8 groups two per call
// (Float8x2) where that pays: a group waits until the next one joins it. Lanes are
// independent and colours are written in the order the groups became ready, so pairing
// never changes a bit.
#pragma once

#include "raster/contract.h"
#include "raster/merge/color_write.h"
#include "raster/shader/shader_instance.h"
#include "raster/tile/interpolate.h"
#include "raster/util/cycles.h"

namespace raster {

// Shades one ready group and writes its colour outputs; a group the walk only prepared is
// interpolated first (counted as rasterization, as in the walk).
template <class F>
void shadeGroup(const TileJob& job, FragmentGroup<F>& group, PipelineCounters& counters) {
  interpolateGroup(job, group);
  const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;
  FragmentOutput<F> out;
  out.unorm8Outputs = job.unorm8Outputs;
  group.draw->shader->shadeFragments(group.in, group.varyings, out);
  const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;
  counters.shadeCycles += mergeStart - shadeStart;
  counters.laneGroupsShaded += 1;
  counters.lanesShaded += F::kCount;
  merge::writeGroup(*job.framebuffer, group, out);
  if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
}

// Shades a tile's ready groups in order: next() is where the caller prepares a group
// (prepareGroup, tile/interpolate.h), push() hands it over to be interpolated and shaded,
// flush() finishes any group still waiting.
template <class F>
class GroupShader {
 public:
  GroupShader(const TileJob& job, PipelineCounters& counters) : job_(job), counters_(counters) {}
  FragmentGroup<F>& next() { return slot_; }
  void push() { shadeGroup(job_, slot_, counters_); }
  void flush() {}

 private:
  const TileJob& job_;
  PipelineCounters& counters_;
  FragmentGroup<F> slot_;
};

}  // namespace raster

#include "raster/tile/group_shader_avx2.h"
