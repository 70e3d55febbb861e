// The covered-tile fast path for Float8 (covered_tile.h): each 4x4 block's two groups shaded
// as one Float8x2 pair. That skips the walk's coverage and depth bookkeeping and the
// ready-group copies. Each lane gets the walk's fragmentDepth and interpolateFragment, the
// pairs are the ones GroupShader forms there (a block's upper group, then its lower one),
// and every pixel is written once, so the bits are the same.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/merge/color_write.h"
#include "raster/tile/coverage.h"
#include "raster/tile/covered_tile.h"
#include "raster/tile/group_shader.h"
#include "raster/tile/interpolate.h"

namespace raster {

template <>
inline bool canShadeBlocksWhole<simd::Float8>(const DrawRecord& draw) {
  return shadedInPairs(draw);   // pairs only where GroupShader forms them
}

// shadeBlockWhole with the fragment shader `shade(in, varyings, out)`: the draw's, through
// its ShaderInstance, or a program's own, inline (shadeTileWholeWith below).
template <class Shade>
[[gnu::always_inline]] inline void shadeBlockWholeWith(const TileJob& job, const SetupTriangle& tri,
                                                       const LaneLayout<simd::Float8>& layout, int blockX, int blockY,
                                                       PipelineCounters& counters, const Shade& shade) {
  using simd::Float8;
  using simd::Float8x2;
  constexpr int kBlock = limits::kBlockSize;
  const DrawRecord& draw = job.draws[tri.drawIndex];
  const Framebuffer& fb = *job.framebuffer;
  // Lane offsets of the pair: the block's upper group (rows 0-1), then its lower (rows 2-3).
  const Float8x2 dx(layout.dxLanes, layout.dxLanes), dy(layout.dyLanes, layout.dyLanes + Float8(2.0f));
  const int outputs = colorOutputsWritten(draw, fb);
  const bool additive = draw.state.blendAdditive;
  FragmentInput<Float8x2> in;
  Float8x2 varyings[limits::kMaxVaryingFloats];
  FragmentOutput<Float8x2> out;
  const Float8x2 px = Float8x2(float(blockX)) + dx, py = Float8x2(float(blockY)) + dy;
  interpolateFragment(job, tri, px, py, fragmentDepth(tri, px, py), in, varyings);
  const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;   // interpolation counts as rasterization
  shade(in, static_cast<const Float8x2*>(varyings), out);
  const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;

  size_t upper[8], lower[8];
  const size_t origin = size_t(blockY) * size_t(fb.width) + size_t(blockX);
  for (int i = 0; i < 8; ++i) {
    upper[i] = origin + layout.texel[i];
    lower[i] = upper[i] + 2 * size_t(fb.width);
  }
  for (int k = 0; k < outputs; ++k) {
    Texture& target = *fb.colors[k];
    merge::prefetchBlockRowsForWrite(target, origin, size_t(fb.width), kBlock);
    const glsl::vec4<Float8x2>& c = out.color[k];
    if (!additive && target.format == TexelFormat::RGBA8) {
      merge::writeRgba8RowsPair(c, target.rgba8.data(), upper, lower);
    } else if (target.format == TexelFormat::RGBA16F) {
      merge::writeHalfRowsPair(c, target.half.data(), upper, lower, additive);
    } else {
      merge::writeColorOutput(target, merge::lowGroup(c), upper, 0xFFu, additive);
      merge::writeColorOutput(target, merge::highGroup(c), lower, 0xFFu, additive);
    }
  }
  if (job.timeStages) {
    counters.shadeCycles += mergeStart - shadeStart;
    counters.mergeCycles += cycleCount() - mergeStart;
  }
  counters.lanesCovered += 16;
  counters.laneGroupsShaded += 2;
  counters.lanesShaded += 16;
}

template <>
[[gnu::always_inline]] inline void shadeBlockWhole<simd::Float8>(const TileJob& job, const SetupTriangle& tri,
                                                                 const LaneLayout<simd::Float8>& layout, int blockX,
                                                                 int blockY, PipelineCounters& counters) {
  const ShaderInstance& shader = *job.draws[tri.drawIndex].shader;
  shadeBlockWholeWith(job, tri, layout, blockX, blockY, counters,
                      [&](const FragmentInput<simd::Float8x2>& in, const simd::Float8x2* varyings,
                          FragmentOutput<simd::Float8x2>& out) { shader.shadeFragments(in, varyings, out); });
}

// Every block of the tile, with the fragment shader `shade`. Each program's instance runs
// this loop with a direct call of its own fragment shader (ShaderInstance::shadeTileWhole):
// one virtual call a tile instead of one a block, which made hdr's frame (four fullscreen
// passes of 1920x1080 or a quarter of it) 1-2% shorter.
template <class Shade>
[[gnu::always_inline]] inline void shadeTileWholeWith(const TileJob& job, const TileBounds& tile,
                                                      const SetupTriangle& tri, const LaneLayout<simd::Float8>& layout,
                                                      PipelineCounters& counters, const Shade& shade) {
  constexpr int kBlock = limits::kBlockSize;
  for (int blockY = tile.y0; blockY <= tile.y1; blockY += kBlock)
    for (int blockX = tile.x0; blockX <= tile.x1; blockX += kBlock)
      shadeBlockWholeWith(job, tri, layout, blockX, blockY, counters, shade);
}

template <>
inline void shadeTileWhole<simd::Float8>(const TileJob& job, const TileBounds& tile, const SetupTriangle& tri,
                                         const LaneLayout<simd::Float8>& layout, PipelineCounters& counters) {
  job.draws[tri.drawIndex].shader->shadeTileWhole(job, tile, tri, layout, counters);
}

inline bool shadeCoveredTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin,
                             const LaneLayout<simd::Float8>& layout, PipelineCounters& counters) {
  if (bin.size() != 1) return false;
  const SetupTriangle& tri = job.triangles[bin.front()];
  // A depth test could fail lanes.
  if (job.draws[tri.drawIndex].state.depthTest && job.framebuffer->depth) return false;
  if (!canShadeTileWhole<simd::Float8>(tile, job.draws[tri.drawIndex]) || !triangleCoversRect(tri, tile)) return false;
  shadeTileWhole(job, tile, tri, layout, counters);
  return true;
}

}  // namespace raster
#endif
