// The tile stage's loop (see rasterize_tile.h): which path a tile takes, and the in-order
// walk. Sources: llvmpipe lp_rast_tri_tmp.h (block coverage), lp_bld_interp.c (plane
// evaluation), lp_state_fs.c (depth clamp, early depth test), lp_bld_conv.c / lp_bld_blend.c
// (output conversion).
#include "raster/tile/rasterize_tile.h"

#include "raster/tile/coverage.h"
#include "raster/tile/covered_tile.h"
#include "raster/tile/group_shader.h"
#include "raster/tile/interpolate.h"
#include "raster/tile/visible_first.h"
#include "raster/tile/walk.h"
#include "raster/util/cycles.h"

namespace raster {
namespace {

// The in-order walk: each lane group is shaded as soon as it passes its depth test
// (prepared only: a pair of the same triangle's groups is interpolated together). Where the
// lane type tests whole blocks (depth_test_avx512.h), a block its triangle covers whole is
// tested at once; if every pixel passes, it is shaded as one pair straight from the planes
// (covered_tile.h), once any group still waiting has been shaded, so colours land in the
// order the walk makes them. A waiting group may then go alone where it would have paired
// with the block's upper group; lanes are independent (group_shader.h), so the bits are
// the same.
template <class F>
[[gnu::always_inline]] inline void walkInOrder(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin,
                                               const LaneLayout<F>& layout, PipelineCounters& counters,
                                               GroupShader<F>& shader) {
  const auto shadePassed = [&](const SetupTriangle& tri, GroupAt passed, F z) __attribute__((always_inline)) {
    counters.lanesCovered += unsigned(__builtin_popcount(passed.laneMask));
    prepareGroup(job, tri, layout, passed, z, shader.next());
    shader.push();
  };
  if constexpr (kDepthTestsInBlocks<F>) {
    const Framebuffer& fb = *job.framebuffer;
    for (size_t i = 0; i < bin.size(); ++i) {
      const SetupTriangle& tri = job.triangles[bin[i]];
      const DrawRecord& draw = job.draws[tri.drawIndex];
      if (colorOutputsWritten(draw, fb) == 0 || !canShadeBlocksWhole<F>(draw)) {
        depthTestBin<F>(job, tile, bin.subspan(i, 1), layout, [&](uint32_t, const SetupTriangle&, GroupAt passed, F z) __attribute__((always_inline)) {
          shadePassed(tri, passed, z);
        });
        continue;
      }
      const BlockDepthTest<F> depthTest(job, tri);
      walkTriangleBlocks<F>(job, tri, tile, [&](int blockX, int blockY, uint32_t coverage) __attribute__((always_inline)) {
        constexpr uint32_t kWholeBlock = 0xFFFFu;
        const bool whole = coverage == kWholeBlock;
        const uint32_t passed = whole ? depthTest(blockX, blockY, coverage) : 0u;
        if (passed == kWholeBlock) {
          shader.flush();
          shadeBlockWhole(job, tri, layout, blockX, blockY, counters);
          return;
        }
        for (int g = 0; g < LaneLayout<F>::kGroupsPerBlock; ++g) {
          const GroupAt at{blockX + LaneLayout<F>::originX(g), blockY + LaneLayout<F>::originY(g),
                           groupLaneMask(layout, fb.flipY, whole ? passed : coverage, g)};
          if (!at.laneMask) continue;
          F z;
          if (whole) {   // tested (and written) with the block above
            z = fragmentDepth(tri, F(float(at.x)) + layout.dxLanes, F(float(at.y)) + layout.dyLanes);
            shadePassed(tri, at, z);
          } else if (const unsigned lanes = depthTestGroup(job, tri, layout, at, z)) {
            shadePassed(tri, GroupAt{at.x, at.y, lanes}, z);
          }
        }
      });
    }
  } else {
    depthTestBin<F>(job, tile, bin, layout, [&](uint32_t, const SetupTriangle& tri, GroupAt passed, F z) __attribute__((always_inline)) {
      shadePassed(tri, passed, z);
    });
  }
}

}  // namespace

template <class F>
void rasterizeTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  const uint64_t tileStart = job.timeStages ? cycleCount() : 0;
  const uint64_t shadeBefore = counters.shadeCycles, mergeBefore = counters.mergeCycles;

  if (!shadeCoveredTile(job, tile, bin, layout, counters)) {
    GroupShader<F> shader(job, counters);
    if (walksVisibleFirst(job, bin.size())) {
      rasterizeVisibleFirst<F>(job, tile, bin, layout, counters, shader);
    } else {
      walkInOrder<F>(job, tile, bin, layout, counters, shader);
    }
    shader.flush();
  }
  if (job.timeStages)
    counters.rasterCycles += (cycleCount() - tileStart) - (counters.shadeCycles - shadeBefore) - (counters.mergeCycles - mergeBefore);
}

template void rasterizeTile<FastLanes>(const TileJob&, const TileBounds&, std::span<const uint32_t>, PipelineCounters&);
template void rasterizeTile<ScalarLanes>(const TileJob&, const TileBounds&, std::span<const uint32_t>, PipelineCounters&);

}  // namespace raster
