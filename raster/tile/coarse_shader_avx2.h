// Float8 coarse groups shaded two per call (Float8x2), for the draws whose 1x1 groups are
// paired (shadedInPairs, group_shader_avx2.h): one group's lookups overlap the other's
// memory waits, and with AVX-512 a pair's arithmetic is one 512-bit operation.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/tile/coarse_shader.h"
#include "raster/tile/group_shader.h"

namespace raster {

// Shades two prepared coarse groups in one Float8x2 call, then writes a's outputs and b's.
[[gnu::noinline]] inline void shadeCoarsePair(const TileJob& job, const CoarseLayout<simd::Float8>& coarse,
                                              CoarseGroup<simd::Float8>& a, CoarseGroup<simd::Float8>& b,
                                              PipelineCounters& counters) {
  using simd::Float8x2;
  FragmentInput<Float8x2> in;
  Float8x2 varyings[limits::kMaxVaryingFloats];
  interpolatePair(job, a.group, b.group, in, varyings);   // counted as rasterization
  const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;
  FragmentOutput<Float8x2> out;
  a.group.draw->shader->shadeFragments(in, varyings, out);
  const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;
  counters.shadeCycles += mergeStart - shadeStart;
  counters.laneGroupsShaded += 2;
  counters.lanesShaded += Float8x2::kCount;
  FragmentOutput<simd::Float8> low, high;
  for (int k = 0; k < a.group.outputs; ++k) {
    low.color[k] = merge::lowGroup(out.color[k]);
    high.color[k] = merge::highGroup(out.color[k]);
  }
  writeCoarseGroup(job, coarse, a, low);
  writeCoarseGroup(job, coarse, b, high);
  if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
}

// CoarseShader for Float8 groups: a group of a paired draw waits until the next ready
// group joins it, or until one that cannot join or the end of the tile sends it alone, as
// GroupShader<Float8> does; colours land in the order the groups became ready.
template <>
class CoarseShader<simd::Float8> {
 public:
  CoarseShader(const TileJob& job, const CoarseLayout<simd::Float8>& coarse, PipelineCounters& counters)
      : job_(job), coarse_(coarse), counters_(counters) {}
  CoarseGroup<simd::Float8>& next() { return slots_[nextIndex()]; }
  void push() {
    const int index = nextIndex();
    CoarseGroup<simd::Float8>& ready = slots_[index];
    if (shadedInPairs(*ready.group.draw)) {
      if (waiting_ >= 0 && canPair(slots_[waiting_].group, ready.group)) {
        shadeCoarsePair(job_, coarse_, slots_[waiting_], ready, counters_);
        waiting_ = -1;
        return;
      }
      flush();
      waiting_ = index;
      return;
    }
    flush();
    shadeCoarseGroup(job_, coarse_, ready, counters_);
  }
  void flush() {
    if (waiting_ >= 0) shadeCoarseGroup(job_, coarse_, slots_[waiting_], counters_);
    waiting_ = -1;
  }

 private:
  int nextIndex() const { return waiting_ == 0 ? 1 : 0; }
  const TileJob& job_;
  const CoarseLayout<simd::Float8>& coarse_;
  PipelineCounters& counters_;
  CoarseGroup<simd::Float8> slots_[2];
  int waiting_ = -1;   // the slot of the group waiting for a partner, or -1
};

}  // namespace raster
#endif
