// Float8 groups shaded two per call (Float8x2), for programs that read textures (one
// group's lookups overlap the other's memory waits) and, with AVX-512, for every program
// (a pair's arithmetic is one 512-bit operation instead of two 256-bit ones).
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/tile/group_shader.h"
#include "raster/tile/pairing_queue.h"

namespace raster {

// Whether a draw's Float8 groups are shaded in pairs.
inline bool shadedInPairs(const DrawRecord& draw) {
#if RASTER_ZMM_PAIRS
  return true;
#else
  return draw.samplesTextures;
#endif
}

// Two groups of the same draw and facing can share one shader call. They may cover the same
// pixels (overlapping triangles), but the later group was depth-tested after the earlier
// one's depth write, and a's colours are written before b's, so the framebuffer ends the
// same as shading each alone.
inline bool canPair(const FragmentGroup<simd::Float8>& a, const FragmentGroup<simd::Float8>& b) {
  return a.draw == b.draw && a.tri->frontFacing == b.tri->frontFacing;
}

// Interpolates two groups for one Float8x2 call. Two prepared groups of one triangle are
// interpolated together, one operation for both (the same per lane as two); otherwise each
// alone (if not done yet), joined.
inline void interpolatePair(const TileJob& job, FragmentGroup<simd::Float8>& a, FragmentGroup<simd::Float8>& b,
                            FragmentInput<simd::Float8x2>& in, simd::Float8x2* varyings) {
  using simd::Float8x2;
  if (a.tri == b.tri && !a.interpolated && !b.interpolated) {
    interpolateFragment(job, *a.tri, Float8x2(a.px, b.px), Float8x2(a.py, b.py), Float8x2(a.z, b.z), in, varyings);
    return;
  }
  interpolateGroup(job, a);
  interpolateGroup(job, b);
  const glsl::vec4<simd::Float8>& ca = a.in.gl_FragCoord;
  const glsl::vec4<simd::Float8>& cb = b.in.gl_FragCoord;
  in.gl_FragCoord = {{ca.x, cb.x}, {ca.y, cb.y}, {ca.z, cb.z}, {ca.w, cb.w}};
  in.gl_FrontFacing = a.in.gl_FrontFacing;
  const int varyingCount = a.draw->varyingFloats;
  for (int v = 0; v < varyingCount; ++v) varyings[v] = {a.varyings[v], b.varyings[v]};
}

// Shades two ready groups in one Float8x2 call, then writes a's outputs and b's. Kept out
// of line, as the tile loop's callees were before the stage split: inlined into the walk it
// cost the shadow scene's main pass a few percent.
[[gnu::noinline]] inline void shadeGroupPair(const TileJob& job, FragmentGroup<simd::Float8>& a, FragmentGroup<simd::Float8>& b,
                           PipelineCounters& counters) {
  using simd::Float8x2;
  FragmentInput<Float8x2> in;
  Float8x2 varyings[limits::kMaxVaryingFloats];
  interpolatePair(job, a, b, in, varyings);   // counted as rasterization, as in the walk
  const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;
  FragmentOutput<Float8x2> out;
  out.unorm8Outputs = job.unorm8Outputs;
  a.draw->shader->shadeFragments(in, varyings, out);
  const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;
  counters.shadeCycles += mergeStart - shadeStart;
  counters.laneGroupsShaded += 2;
  counters.lanesShaded += Float8x2::kCount;

  const Framebuffer& fb = *job.framebuffer;
  const bool additive = a.draw->state.blendAdditive;
  for (int k = 0; k < a.outputs; ++k) {
    const glsl::vec4<Float8x2>& c = out.color[k];
    merge::writeColorOutput(*fb.colors[k], merge::lowGroup(c), a.texel, a.laneMask, additive);
    merge::writeColorOutput(*fb.colors[k], merge::highGroup(c), b.texel, b.laneMask, additive);
  }
  if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
}

// GroupShader for Float8 groups: a group of a paired draw waits in its slot (perhaps not yet
// interpolated) until the next ready group joins it, or until one that cannot join (another
// draw or facing) or the end of the tile sends it alone. Each group passed its depth test
// before it became ready, and colours are written in the order the groups became ready, so
// the framebuffer ends as if each were shaded alone.
template <>
class GroupShader<simd::Float8> {
  // How the shared pairing queue (pairing_queue.h) shades 1x1 groups.
  struct Policy {
    const TileJob& job;
    PipelineCounters& counters;
    bool paired(const FragmentGroup<simd::Float8>& g) const { return shadedInPairs(*g.draw); }
    bool canPair(const FragmentGroup<simd::Float8>& a, const FragmentGroup<simd::Float8>& b) const { return raster::canPair(a, b); }
    void shadeOne(FragmentGroup<simd::Float8>& g) const { shadeGroup(job, g, counters); }
    void shadePair(FragmentGroup<simd::Float8>& a, FragmentGroup<simd::Float8>& b) const { shadeGroupPair(job, a, b, counters); }
  };

 public:
  GroupShader(const TileJob& job, PipelineCounters& counters) : queue_(Policy{job, counters}) {}
  // Where the next group is prepared: never the waiting group's slot.
  FragmentGroup<simd::Float8>& next() { return queue_.next(); }
  void push() { queue_.push(); }
  // Shades the waiting group alone.
  void flush() { queue_.flush(); }

 private:
  PairingQueue<FragmentGroup<simd::Float8>, Policy> queue_;
};

}  // namespace raster
#endif
