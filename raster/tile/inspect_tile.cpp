// The instrumented tile walks (inspect_tile.h): the in-order walk with ScalarLanes, counting,
// and the coarse walk's.
#include "raster/tile/inspect_tile.h"

#include <algorithm>

#include "raster/tile/coarse_shader.h"
#include "raster/tile/coarse_walk.h"
#include "raster/tile/coverage.h"
#include "raster/tile/depth_test.h"
#include "raster/tile/group_shader.h"
#include "raster/tile/interpolate.h"
#include "raster/simd/lane_layout.h"

namespace raster {

void FragmentCounts::reset(int w, int h) {
  width = w;
  height = h;
  for (std::vector<uint32_t>* v : {&shaded, &depthOnly, &depthKills, &helpersUncovered, &helpersKilled})
    v->assign(size_t(w) * size_t(h), 0u);
  invocations.assign(size_t(w) * size_t(h), 0.0f);
}

void inspectTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, FragmentCounts& counts,
                 PipelineCounters& counters) {
  using F = ScalarLanes;
  constexpr int kBlock = limits::kBlockSize;
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  FragmentGroup<F> group;
  for (uint32_t index : bin) {
    const SetupTriangle& tri = job.triangles[index];
    const bool writesColor = colorOutputsWritten(job.draws[tri.drawIndex], fb) > 0;
    const WalkEdge edges[3] = {WalkEdge(tri.edge[0]), WalkEdge(tri.edge[1]), WalkEdge(tri.edge[2])};
    const TileBounds bounds = boundsInTile(tri, tile);
    const int x0 = bounds.x0, x1 = bounds.x1, y0 = bounds.y0, y1 = bounds.y1;
    // Every 4x4 block of the triangle's bounds in the tile, tested alone: the walk's 16x16
    // regions only skip blocks that are wholly outside or find ones wholly inside, which
    // blockCoverage finds too.
    for (int blockY = y0 & ~(kBlock - 1); blockY <= y1; blockY += kBlock) {
      for (int blockX = x0 & ~(kBlock - 1); blockX <= x1; blockX += kBlock) {
        const uint32_t coverage = blockCoverage(edges, blockX, blockY) & blockBounds(blockX, blockY, fb.width, fb.height);
        if (!coverage) continue;
        for (int g = 0; g < LaneLayout<F>::kGroupsPerBlock; ++g) {
          const unsigned covered = groupLaneMask(layout, fb.flipY, coverage, g);
          if (!covered) continue;
          const GroupAt at{blockX + LaneLayout<F>::originX(g), blockY + LaneLayout<F>::originY(g), covered};
          F z;
          const unsigned passed = depthTestGroup(job, tri, layout, at, z);
          const bool shades = passed && writesColor;
          for (int i = 0; i < F::kCount; ++i) {
            const int px = at.x + layout.dx[i], py = at.y + layout.dy[i];
            if (px >= fb.width || py >= fb.height) continue;   // a helper off the framebuffer's edge
            const size_t texel = size_t(py) * size_t(fb.width) + size_t(px);
            const bool isCovered = covered >> i & 1u, isPassed = passed >> i & 1u;
            if (isCovered && !isPassed) ++counts.depthKills[texel];
            if (!writesColor) {
              if (isPassed) ++counts.depthOnly[texel];
            } else if (isPassed) {
              ++counts.shaded[texel];
              counts.invocations[texel] += 1.0f;
            } else if (shades) {   // shaded only for its quad's derivatives
              ++(isCovered ? counts.helpersKilled : counts.helpersUncovered)[texel];
            }
          }
          if (!shades) continue;
          counters.lanesCovered += unsigned(__builtin_popcount(passed));
          fillGroup(job, tri, layout, GroupAt{at.x, at.y, passed}, z, group);
          shadeGroup(job, group, counters);
        }
      }
    }
  }
}

namespace {

// The coarse walk's shader (coarse_walk.h's Shader) for the stage views: each group is
// shaded as CoarseShader<ScalarLanes> does it, after its pixels are counted.
class CountingCoarseShader {
 public:
  CountingCoarseShader(const TileJob& job, const CoarseLayout<ScalarLanes>& coarse, FragmentCounts& counts,
                       PipelineCounters& counters)
      : job_(job), coarse_(coarse), counts_(counts), counters_(counters) {}
  CoarseGroup<ScalarLanes>& next() { return slot_; }
  void push() {
    for (int i = 0; i < ScalarLanes::kCount; ++i) {
      int written = 0;
      for (int s = 0; s < coarse_.pixels; ++s) written += int(slot_.laneMask[s] >> i & 1u);
      for (int s = 0; s < coarse_.pixels; ++s) {
        if (!(slot_.laneMask[s] >> i & 1u)) continue;
        const size_t texel = slot_.group.texel[i] + coarse_.pixelTexel[s];
        ++counts_.shaded[texel];
        counts_.invocations[texel] += 1.0f / float(written);
      }
    }
    shadeCoarseGroup(job_, coarse_, slot_, counters_);
  }
  void flush() {}

 private:
  const TileJob& job_;
  const CoarseLayout<ScalarLanes>& coarse_;
  FragmentCounts& counts_;
  PipelineCounters& counters_;
  CoarseGroup<ScalarLanes> slot_;
};

}  // namespace

void inspectTileCoarse(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, FragmentCounts& counts,
                       PipelineCounters& counters) {
  using F = ScalarLanes;
  constexpr int kBlock = limits::kBlockSize;
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  const CoarseLayout<F> coarse(layout, job.coarseWidth, job.coarseHeight, fb.width);
  CountingCoarseShader shader(job, coarse, counts, counters);
  for (size_t i = 0; i < bin.size(); ++i) {
    const SetupTriangle& tri = job.triangles[bin[i]];
    const DrawRecord& draw = job.draws[tri.drawIndex];
    const std::span<const uint32_t> one = bin.subspan(i, 1);
    // Covered pixels, for the depth test's rejects: every block alone, as inspectTile finds
    // them (walkTriangleBlocks would fill a depth-only draw's regions, a second depth write).
    coarse_walk::PassedPixels covered;
    const WalkEdge edges[3] = {WalkEdge(tri.edge[0]), WalkEdge(tri.edge[1]), WalkEdge(tri.edge[2])};
    const TileBounds bounds = boundsInTile(tri, tile);
    for (int blockY = bounds.y0 & ~(kBlock - 1); blockY <= bounds.y1; blockY += kBlock)
      for (int blockX = bounds.x0 & ~(kBlock - 1); blockX <= bounds.x1; blockX += kBlock) {
        const uint32_t coverage = blockCoverage(edges, blockX, blockY) & blockBounds(blockX, blockY, fb.width, fb.height);
        for (int row = 0; row < kBlock; ++row)
          covered.rows[blockY + row - tile.y0] |= uint64_t(coverage >> (row * kBlock) & 0xFu) << (blockX - tile.x0);
      }
    coarse_walk::PassedPixels passed;
    const bool writesColor = colorOutputsWritten(draw, fb) > 0;
    if (writesColor) {
      coarse_walk::passedPixels(job, tile, one, layout, passed, counters);
    } else {   // depth only: the 1x1 walk's test and writes
      depthTestBin<F>(job, tile, one, layout, [&](uint32_t, const SetupTriangle&, GroupAt at, F) {
        for (int lane = 0; lane < F::kCount; ++lane)
          if (at.laneMask >> lane & 1u)
            passed.rows[at.y + layout.dy[lane] - tile.y0] |= uint64_t(1) << (at.x + layout.dx[lane] - tile.x0);
      });
    }
    for (int row = 0; row < limits::kTileSize; ++row) {
      const uint64_t kills = covered.rows[row] & ~passed.rows[row], depthOnly = writesColor ? 0 : passed.rows[row];
      for (uint64_t bits = kills | depthOnly; bits; bits &= bits - 1) {
        const int column = __builtin_ctzll(bits);
        const size_t texel = size_t(tile.y0 + row) * size_t(fb.width) + size_t(tile.x0 + column);
        if (kills >> column & 1u) ++counts.depthKills[texel];
        if (depthOnly >> column & 1u) ++counts.depthOnly[texel];
      }
    }
    if (writesColor) coarse_walk::prepareCoarseGroups(job, tri, tile, coarse, passed, shader);
  }
}

}  // namespace raster
