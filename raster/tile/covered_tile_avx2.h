// The covered-tile fast path for Float8 (covered_tile.h): each 4x4 block's two groups shaded
// as one Float8x2 pair. That skips the walk's coverage and depth bookkeeping and the
// ready-group copies. Each lane gets the walk's fragmentDepth and interpolateFragment, the
// pairs are the ones GroupShader forms there (a block's upper group, then its lower one),
// and every pixel is written once, so the bits are the same.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/merge/clear_avx2.h"
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

// One 4x4 block's colours from the fragment shader `shade(in, varyings, out)`: the draw's
// through its ShaderInstance (a single block of a walk), or a program's own, called directly
// (shadeTileWholeWith below), which also knows how many varyings it reads (kVaryingFloats).
template <int kVaryingFloats, class Shade>
[[gnu::always_inline]] inline void shadeBlockColorsWith(const TileJob& job, const SetupTriangle& tri,
                                                        const LaneLayout<simd::Float8>& layout, int blockX, int blockY,
                                                        PipelineCounters& counters, const Shade& shade,
                                                        FragmentOutput<simd::Float8x2>& out) {
  using simd::Float8;
  using simd::Float8x2;
  out.unorm8Outputs = job.unorm8Outputs;
  // Lane offsets of the pair: the block's upper group (rows 0-1), then its lower (rows 2-3).
  const Float8x2 dx(layout.dxLanes, layout.dxLanes), dy(layout.dyLanes, layout.dyLanes + Float8(2.0f));
  FragmentInput<Float8x2> in;
  Float8x2 varyings[limits::kMaxVaryingFloats];
  const Float8x2 px = Float8x2(float(blockX)) + dx, py = Float8x2(float(blockY)) + dy;
  interpolateFragment<kVaryingFloats>(job, tri, px, py, fragmentDepth(tri, px, py), in, varyings);
  const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;   // interpolation counts as rasterization
  shade(in, static_cast<const Float8x2*>(varyings), out);
  if (job.timeStages) counters.shadeCycles += cycleCount() - shadeStart;
  counters.lanesCovered += 16;
  counters.laneGroupsShaded += 2;
  counters.lanesShaded += 16;
}

// shadeBlockColorsWith, then the colours merged into every target.
template <int kVaryingFloats, class Shade>
[[gnu::always_inline]] inline void shadeBlockWholeWith(const TileJob& job, const SetupTriangle& tri,
                                                       const LaneLayout<simd::Float8>& layout, int blockX, int blockY,
                                                       PipelineCounters& counters, const Shade& shade) {
  using simd::Float8x2;
  constexpr int kBlock = limits::kBlockSize;
  const DrawRecord& draw = job.draws[tri.drawIndex];
  const Framebuffer& fb = *job.framebuffer;
  const int outputs = colorOutputsWritten(draw, fb);
  const bool additive = draw.state.blendAdditive;
  FragmentOutput<Float8x2> out;
  shadeBlockColorsWith<kVaryingFloats>(job, tri, layout, blockX, blockY, counters, shade, out);
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
  if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
}

#if RASTER_ZMM_PAIRS
// Whether a covered tile's colour goes out in whole lines (shadeRgba8LinesWith): the tile's
// only triangle (nothing after it reads or writes those lines), one RGBA8 target, not
// blended, larger than the threads' caches (TileJob::streamUntouchedClears: the window's
// image at 1920x1080), its rows whole lines apart.
inline bool storesRgba8Lines(const TileJob& job, const DrawRecord& draw, bool onlyTriangle) {
  const Framebuffer& fb = *job.framebuffer;
  if (!onlyTriangle || !job.streamUntouchedClears || draw.state.blendAdditive || colorOutputsWritten(draw, fb) != 1)
    return false;
  const Texture& target = *fb.colors[0];
  return target.format == TexelFormat::RGBA8 && fb.width % 16 == 0 &&
         (reinterpret_cast<uintptr_t>(target.rgba8.data()) & 63u) == 0;
}

// Four blocks side by side, from texel column `x` (a multiple of 16) of block row `blockY`:
// each memory row of the four is one 64-byte line, stored around the cache. A block's
// 16-byte rows had each waited on their line's read for ownership (the hdr composite's
// 8.3 MB at 1920x1080); a streaming store of a whole line needs none.
template <int kVaryingFloats, class Shade>
[[gnu::always_inline]] inline void shadeRgba8LinesWith(const TileJob& job, const SetupTriangle& tri,
                                                       const LaneLayout<simd::Float8>& layout, int x, int blockY,
                                                       PipelineCounters& counters, const Shade& shade) {
  const Framebuffer& fb = *job.framebuffer;
  __m512i rows[4];   // block b: [its lane 0 row | lane 2 row | lane 8 row | lane 10 row]
  for (int b = 0; b < 4; ++b) {
    FragmentOutput<simd::Float8x2> out;
    shadeBlockColorsWith<kVaryingFloats>(job, tri, layout, x + 4 * b, blockY, counters, shade, out);
    rows[b] = merge::rgba8RowsPair(out.color[0]);
  }
  const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;
  // A 4x4 transpose of 16-byte rows: line j holds row j of each block, left to right.
  const __m512i low01 = _mm512_shuffle_i32x4(rows[0], rows[1], _MM_SHUFFLE(1, 0, 1, 0));
  const __m512i low23 = _mm512_shuffle_i32x4(rows[2], rows[3], _MM_SHUFFLE(1, 0, 1, 0));
  const __m512i high01 = _mm512_shuffle_i32x4(rows[0], rows[1], _MM_SHUFFLE(3, 2, 3, 2));
  const __m512i high23 = _mm512_shuffle_i32x4(rows[2], rows[3], _MM_SHUFFLE(3, 2, 3, 2));
  const __m512i line[4] = {_mm512_shuffle_i32x4(low01, low23, _MM_SHUFFLE(2, 0, 2, 0)),
                           _mm512_shuffle_i32x4(low01, low23, _MM_SHUFFLE(3, 1, 3, 1)),
                           _mm512_shuffle_i32x4(high01, high23, _MM_SHUFFLE(2, 0, 2, 0)),
                           _mm512_shuffle_i32x4(high01, high23, _MM_SHUFFLE(3, 1, 3, 1))};
  // Line j goes to memory row layout.dy of lane 0 or 2 (j = 0, 1), plus 2 for the lower group.
  uint8_t* const origin = fb.colors[0]->rgba8.data() + (size_t(blockY) * size_t(fb.width) + size_t(x)) * 4;
  for (int j = 0; j < 4; ++j) {
    const int row = layout.dy[(j & 1) * 2] + (j & 2);
    _mm512_stream_si512(reinterpret_cast<__m512i*>(origin + size_t(row) * size_t(fb.width) * 4), line[j]);
  }
  if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
}
#endif

template <>
[[gnu::always_inline]] inline void shadeBlockWhole<simd::Float8>(const TileJob& job, const SetupTriangle& tri,
                                                                 const LaneLayout<simd::Float8>& layout, int blockX,
                                                                 int blockY, PipelineCounters& counters) {
  const ShaderInstance& shader = *job.draws[tri.drawIndex].shader;
  shadeBlockWholeWith<kVaryingsOfDraw>(
      job, tri, layout, blockX, blockY, counters,
      [&](const FragmentInput<simd::Float8x2>& in, const simd::Float8x2* varyings, FragmentOutput<simd::Float8x2>& out) {
        shader.shadeFragments(in, varyings, out);
      });
}

// Every block of the tile, with the fragment shader `shade`. Each program's instance runs
// this loop with a direct call of its own fragment shader (ShaderInstance::shadeTileWhole):
// one virtual call a tile instead of one a block, which made hdr's frame at 1920x1080 (ten
// fullscreen passes, the composite and the bright pass the largest) 1-2% shorter.
template <int kVaryingFloats, class Shade>
[[gnu::always_inline]] inline void shadeTileWholeWith(const TileJob& job, const TileBounds& tile,
                                                      const SetupTriangle& tri, const LaneLayout<simd::Float8>& layout,
                                                      bool onlyTriangle, PipelineCounters& counters, const Shade& shade) {
  constexpr int kBlock = limits::kBlockSize;
#if RASTER_ZMM_PAIRS
  if (storesRgba8Lines(job, job.draws[tri.drawIndex], onlyTriangle)) {
    for (int blockY = tile.y0; blockY <= tile.y1; blockY += kBlock) {
      int blockX = tile.x0;   // a multiple of the tile size, so of 16
      for (; blockX + 16 <= tile.x1 + 1; blockX += 16)
        shadeRgba8LinesWith<kVaryingFloats>(job, tri, layout, blockX, blockY, counters, shade);
      for (; blockX <= tile.x1; blockX += kBlock)
        shadeBlockWholeWith<kVaryingFloats>(job, tri, layout, blockX, blockY, counters, shade);
    }
    merge::endStreaming();
    return;
  }
#endif
  for (int blockY = tile.y0; blockY <= tile.y1; blockY += kBlock)
    for (int blockX = tile.x0; blockX <= tile.x1; blockX += kBlock)
      shadeBlockWholeWith<kVaryingFloats>(job, tri, layout, blockX, blockY, counters, shade);
}

template <>
inline void shadeTileWhole<simd::Float8>(const TileJob& job, const TileBounds& tile, const SetupTriangle& tri,
                                         const LaneLayout<simd::Float8>& layout, bool onlyTriangle,
                                         PipelineCounters& counters) {
  job.draws[tri.drawIndex].shader->shadeTileWhole(job, tile, tri, layout, onlyTriangle, counters);
}

inline bool shadeCoveredTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin,
                             const LaneLayout<simd::Float8>& layout, PipelineCounters& counters) {
  if (bin.size() != 1) return false;
  const SetupTriangle& tri = job.triangles[bin.front()];
  // A depth test could fail lanes.
  if (job.draws[tri.drawIndex].state.depthTest && job.framebuffer->depth) return false;
  if (!canShadeTileWhole<simd::Float8>(tile, job.draws[tri.drawIndex]) || !triangleCoversRect(tri, tile)) return false;
  shadeTileWhole(job, tile, tri, layout, /*onlyTriangle=*/true, counters);
  return true;
}

}  // namespace raster
#endif
