// Visibility first, for passes whose colour draws do not blend (TileJob::visibilityFirst).
//
// Pass 1 walks every triangle of the bin in order with the depth test alone, and records per
// pixel the last colour-writing triangle whose fragment passed: the fragment whose colour
// the pixel would end with. Pass 2 shades, group by group, only those fragments: for each
// triangle a group's pixels name, the group exactly as the in-order walk prepares it (same
// origin, planes and helper lanes, so the same bits), with only that triangle's pixels
// written; where the port's lanes are independent, the triangles of one group are
// interpolated that way and then shaded in one call. Each pixel is written once, so no
// order is needed between the groups.
//
// This file is the reference, lane by lane; visible_first_avx2.h marks and reads a Float8
// group's two rows at once, and (AVX-512) a whole 4x4 block.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <span>

#include "raster/contract.h"
#include "raster/tile/covered_tile.h"
#include "raster/tile/group_shader.h"
#include "raster/tile/interpolate.h"
#include "raster/simd/lane_layout.h"
#include "raster/tile/walk.h"

namespace raster {

// Per-pixel triangle indices of one tile (kNone: no triangle shows there). Stored a 4x4
// block at a time, each block's 16 entries (row * 4 + col) in one 64-byte line: a block is
// marked, and read whole, with one load and one store, and a group of two rows is half of
// one. mark() also keeps which groups it marked (bit: group column, per pair of rows), for
// forEachVisible(shade); markBlock() keeps no such bits, and forEachVisible(shade, whole)
// finds the groups that show a triangle from the entries themselves.
template <class F>
class TileTriangles {
 public:
  static constexpr int kLanes = F::kCount;
  static constexpr int kTile = limits::kTileSize;
  static constexpr int kGroupWidth = 2 * LaneLayout<F>::kQuads;   // 4 (8 lanes) or 2 (4 lanes)
  static constexpr uint32_t kNone = ~0u;

  explicit TileTriangles(bool flipY) : local_(flipY, kTile), flipY_(flipY) {}
  // Forgets every mark (a new tile): every entry shows no triangle. (Filling the 16 KiB
  // once a tile lets a mark write its rows without asking whether they were marked before,
  // and forEachVisible(shade, whole) tell a marked pixel from its entry alone.)
  void reset() {
    std::fill(std::begin(marked_), std::end(marked_), 0u);
    std::fill(std::begin(entries_), std::end(entries_), kNone);
  }

  // Lanes `passed` of the group at tile offset (lx, ly) now show triangle `index`.
  void mark(int lx, int ly, unsigned passed, uint32_t index) {
    markGroup(lx, ly, passed != 0);
    for (; passed; passed &= passed - 1) {
      const int lane = __builtin_ctz(passed);
      entries_[entryIndex(lx + local_.dx[lane], ly + local_.dy[lane])] = index;
    }
  }

  // Pixels `passed` (bit row * 4 + col) of the 4x4 block at tile offset (lx, ly) now show
  // triangle `index` (no bits: nothing changes), for lane types with kDepthTestsInBlocks
  // (visible_first_avx2.h), whose forEachVisible(shade, whole) reads the entries back.
  void markBlock(int lx, int ly, uint32_t passed, uint32_t index);

  // forEachVisible over what markBlock marked, a 4x4 block at a time (upper group, then
  // lower), where a block whose 16 pixels all show one triangle goes to whole(lx, ly,
  // index) first: when that returns false, its groups go to shade as usual. Float8 has it
  // (visible_first_avx2.h).
  template <class Shade, class Whole>
  void forEachVisible(Shade&& shade, Whole&& whole) const;

  // Calls shade(lx, ly, index, laneMask) once per triangle that marked group (lx, ly).
  template <class Shade>
  void forEachVisible(Shade&& shade) const {
    for (int row = 0; row < kTile / 2; ++row) {
      for (uint32_t bits = marked_[row]; bits; bits &= bits - 1) {
        const int lx = __builtin_ctz(bits) * kGroupWidth, ly = row * 2;
        uint32_t lanes[kLanes];
        unsigned remaining = 0;
        for (int i = 0; i < kLanes; ++i) {
          lanes[i] = entries_[entryIndex(lx + local_.dx[i], ly + local_.dy[i])];
          if (lanes[i] != kNone) remaining |= 1u << i;
        }
        while (remaining) {
          const uint32_t index = lanes[__builtin_ctz(remaining)];
          unsigned laneMask = 0;
          for (int i = 0; i < kLanes; ++i)
            if (lanes[i] == index) laneMask |= 1u << i;
          remaining &= ~laneMask;
          shade(lx, ly, index, laneMask);
        }
      }
    }
  }

 private:
  static constexpr int kBlock = limits::kBlockSize;
  // Where pixel (x, y) of the tile keeps its entry: its block's line, then row * 4 + col.
  // Unsigned, as the offsets are never negative: shifts and masks, without the fix-ups a
  // signed division by 4 takes (about ten instructions a marked block).
  static int entryIndex(int x, int y) {
    const unsigned ux = unsigned(x), uy = unsigned(y);
    return int(((uy / kBlock) * (kTile / kBlock) + ux / kBlock) * (kBlock * kBlock) + (uy % kBlock) * kBlock + ux % kBlock);
  }

  // Marks the group at (lx, ly) as holding entries when `any` (mark() alone: markBlock keeps
  // no bits): an or, not a branch, since the visibility pass's depth tests fail whole about
  // half the time (37-53% of its blocks), in no pattern a branch predictor can learn.
  void markGroup(int lx, int ly, bool any) { marked_[ly / 2] |= uint32_t(any) << (lx / kGroupWidth); }

  const LaneLayout<F> local_;   // lane offsets within the tile
  const bool flipY_;
  alignas(64) uint32_t entries_[kTile * kTile];
  uint32_t marked_[kTile / 2] = {};
};

}  // namespace raster

#include "raster/tile/visible_first_avx2.h"

namespace raster {

// Lanes `lanes` of the interpolated group `into` take another triangle's fragment inputs
// and varyings (`in`, `varyings`): one more triangle the group shows (rasterizeVisibleFirst).
// The rest of `into` (its pixel centres and depth, its triangle) stays its first triangle's;
// being interpolated, the group no longer reads them.
template <class F>
[[gnu::always_inline]] inline void takeLanes(FragmentGroup<F>& into, const FragmentInput<F>& in, const F* varyings,
                                             unsigned lanes) {
  const auto take = F::MaskType::fromBits(lanes);
  glsl::vec4<F>& coord = into.in.gl_FragCoord;
  const glsl::vec4<F>& fromCoord = in.gl_FragCoord;
  coord = glsl::vec4<F>(simd::select(take, fromCoord.x, coord.x), simd::select(take, fromCoord.y, coord.y),
                        simd::select(take, fromCoord.z, coord.z), simd::select(take, fromCoord.w, coord.w));
  for (int v = 0; v < into.draw->varyingFloats; ++v) into.varyings[v] = simd::select(take, varyings[v], into.varyings[v]);
  into.laneMask |= lanes;
}

// Rasterizes one tile visibility first (see the top of this file).
template <class F>
void rasterizeVisibleFirst(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin,
                           const LaneLayout<F>& layout, PipelineCounters& counters, GroupShader<F>& shader) {
  thread_local TileTriangles<F> visibleFlip(true), visible(false);
  TileTriangles<F>& shown = job.framebuffer->flipY ? visibleFlip : visible;
  shown.reset();
  // Pass 2 for one group: its lanes `laneMask`, which show triangle `index`, prepared as the
  // in-order walk prepares them and shaded. Interpolated at once: here a pair's groups are
  // mostly of different triangles, and leaving it to the pair had made the hdr scene pass 8%
  // slower.
  //
  // The triangles one group shows come one after another (forEachVisible), and where they
  // are of one draw whose lanes are independent (raster::lanesIndependent) and face the same
  // way, they share one shader call: each triangle's lanes are interpolated as above, and the
  // open group takes those that show it. Lanes are independent, so each gets the bits its own
  // call gave it. (In the hdr swarm at 640x480 a group shows 2.3 triangles on average.)
  FragmentGroup<F>* open = nullptr;   // the group gathering lanes, not yet pushed
  int openX = 0, openY = 0;
  FragmentInput<F> anotherIn;         // a further triangle of the open group, interpolated
  F anotherVaryings[limits::kMaxVaryingFloats];
  const auto shadeGroup = [&](int lx, int ly, uint32_t index, unsigned laneMask) __attribute__((always_inline)) {
    const SetupTriangle& tri = job.triangles[index];
    const GroupAt at{tile.x0 + lx, tile.y0 + ly, laneMask};
    const F px = F(float(at.x)) + layout.dxLanes, py = F(float(at.y)) + layout.dyLanes;
    counters.lanesCovered += unsigned(__builtin_popcount(laneMask));
    if (open && openX == lx && openY == ly && open->draw == &job.draws[tri.drawIndex] &&
        open->draw->lanesIndependent && open->tri->frontFacing == tri.frontFacing) {
      interpolateFragment(job, tri, px, py, fragmentDepth(tri, px, py), anotherIn, anotherVaryings);
      takeLanes(*open, anotherIn, anotherVaryings, laneMask);
      return;
    }
    if (open) shader.push();
    open = &shader.next();
    openX = lx, openY = ly;
    fillGroup(job, tri, layout, at, fragmentDepth(tri, px, py), *open);
  };
  if constexpr (kDepthTestsInBlocks<F>) {
    // The visibility pass needs no quads: its depth tests run a whole block at a time.
    for (uint32_t index : bin) {
      const SetupTriangle& tri = job.triangles[index];
      const bool writesColor = colorOutputsWritten(job.draws[tri.drawIndex], *job.framebuffer) > 0;
      const BlockDepthTest<F> depthTest(job, tri);
      walkTriangleBlocks<F>(job, tri, tile, [&](int blockX, int blockY, uint32_t coverage) __attribute__((always_inline)) {
        const uint32_t passed = depthTest(blockX, blockY, coverage);
        if (writesColor) shown.markBlock(blockX - tile.x0, blockY - tile.y0, passed, index);
      });
    }
    // A block that shows one triangle whole is shaded as one pair straight from the planes
    // (covered_tile.h); each pixel is written once, so the order of blocks is free.
    shown.forEachVisible(shadeGroup, [&](int lx, int ly, uint32_t index) __attribute__((always_inline)) {
      const SetupTriangle& tri = job.triangles[index];
      if (!canShadeBlocksWhole<F>(job.draws[tri.drawIndex])) return false;
      shadeBlockWhole(job, tri, layout, tile.x0 + lx, tile.y0 + ly, counters);
      return true;
    });
  } else {
    depthTestBin<F>(job, tile, bin, layout, [&](uint32_t index, const SetupTriangle&, GroupAt passed, F) __attribute__((always_inline)) {
      shown.mark(passed.x - tile.x0, passed.y - tile.y0, passed.laneMask, index);
    });
    shown.forEachVisible(shadeGroup);
  }
  if (open) shader.push();   // the last group gathered
}

}  // namespace raster
