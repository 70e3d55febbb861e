// Float8 coarse groups shaded two per call (Float8x2), for the draws whose 1x1 groups are
// paired (shadedInPairs, group_shader_avx2.h): one group's lookups overlap the other's
// memory waits, and with AVX-512 a pair's arithmetic is one 512-bit operation.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/tile/coarse_shader.h"
#include "raster/tile/group_shader.h"
#include "raster/tile/pairing_queue.h"

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
  out.unorm8Outputs = job.unorm8Outputs;
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

// CoarseShader for Float8 groups: GroupShader<Float8>'s pairing (the same queue,
// pairing_queue.h), for the draws it pairs; colours land in the order the groups became ready.
template <>
class CoarseShader<simd::Float8> {
  struct Policy {
    const TileJob& job;
    const CoarseLayout<simd::Float8>& coarse;
    PipelineCounters& counters;
    bool paired(const CoarseGroup<simd::Float8>& g) const { return shadedInPairs(*g.group.draw); }
    bool canPair(const CoarseGroup<simd::Float8>& a, const CoarseGroup<simd::Float8>& b) const {
      return raster::canPair(a.group, b.group);
    }
    void shadeOne(CoarseGroup<simd::Float8>& g) const { shadeCoarseGroup(job, coarse, g, counters); }
    void shadePair(CoarseGroup<simd::Float8>& a, CoarseGroup<simd::Float8>& b) const {
      shadeCoarsePair(job, coarse, a, b, counters);
    }
  };

 public:
  CoarseShader(const TileJob& job, const CoarseLayout<simd::Float8>& coarse, PipelineCounters& counters)
      : queue_(Policy{job, coarse, counters}) {}
  CoarseGroup<simd::Float8>& next() { return queue_.next(); }
  void push() { queue_.push(); }
  void flush() { queue_.flush(); }

 private:
  PairingQueue<CoarseGroup<simd::Float8>, Policy> queue_;
};

}  // namespace raster
#endif
