// Tile clears with the work the first triangle overwrites left out (tile_clear.h).
#include "raster/tile/tile_clear.h"

#include <algorithm>
#include <cmath>

#include "raster/limits.h"
#include "raster/merge/clear.h"
#include "raster/texture/format.h"
#include "raster/tile/coverage.h"
#include "raster/tile/covered_tile.h"
#include "raster/tile/depth_test.h"
#include "raster/tile/rasterize_tile.h"
#include "raster/util/cycles.h"

namespace raster {

bool depthTestPassesEverywhere(const SetupTriangle& tri, const RasterState& state, TexelFormat format,
                               uint32_t stored, const TileBounds& rect) {
  // The z plane plus the offset is linear, so its largest value over the rectangle's pixel
  // centres is at a corner. The pipeline evaluates it in float (fma(dady, y, fma(dadx, x,
  // a0)) + offset: at most five roundings, each under 2^-24 of a sum no larger than M
  // below); 2^-20 * M bounds them all, and double holds the exact corners to far better.
  const Plane& z = tri.z;
  double largest = -INFINITY;
  for (int y : {rect.y0, rect.y1})
    for (int x : {rect.x0, rect.x1})
      largest = std::max(largest, double(z.a0) + double(z.dadx) * x + double(z.dady) * y + double(tri.depthOffset));
  const double magnitude = std::fabs(double(z.a0)) + std::fabs(double(z.dadx)) * std::max(std::abs(rect.x0), std::abs(rect.x1)) +
                           std::fabs(double(z.dady)) * std::max(std::abs(rect.y0), std::abs(rect.y1)) +
                           std::fabs(double(tri.depthOffset));
  if (!std::isfinite(largest) || !std::isfinite(magnitude)) return false;   // NaN planes: keep the clear
  const double bound = std::clamp(largest + magnitude * 0x1p-20, 0.0, 1.0);
  const float boundUp = std::min(std::nextafter(float(bound), 2.0f), 1.0f);
  // Codes rise with z (format.h); one code of slack for a vector form that rounds the
  // quantization's product differently from the scalar one.
  const uint32_t code = (format == TexelFormat::Depth24 ? format::depth24FromFloat(boundUp) : format::depth16FromFloat(boundUp)) + 1;
  return state.depthFunc == DepthFunc::Lequal ? code <= stored : code < stored;
}

TileClearPlan planTileClear(const TileJob& job, std::span<const uint32_t> bin, const TileBounds& tile,
                            const ClearValues& pending, bool shadesWhole) {
  TileClearPlan plan{pending, false};
  if (bin.empty() || (!pending.color && !pending.depth)) return plan;
  const SetupTriangle& tri = job.triangles[bin.front()];
  const DrawRecord& draw = job.draws[tri.drawIndex];
  const Framebuffer& fb = *job.framebuffer;
  if (!triangleCoversRect(tri, tile)) return plan;
  const bool depthTested = draw.state.depthTest && fb.depth;
  // Tested fragments see the depth clear's value (the only depth there may be unknown).
  if (depthTested && !(pending.depth && depthTestPassesEverywhere(tri, draw.state, fb.depth->format,
                                                                  format::depthClearCode(pending.depthValue, fb.depth->depthBits()), tile)))
    return plan;
  const int outputs = colorOutputsWritten(draw, fb);
  if (!draw.state.blendAdditive && outputs == int(fb.colors.size())) plan.rest.color = false;
  if (depthTested && draw.state.depthWrite && (outputs == 0 || shadesWhole)) {
    plan.rest.depth = false;
    plan.firstStoresDepth = true;
    plan.firstShadedWhole = outputs > 0;
  }
  return plan;
}

namespace {

// The depth clear taken a region at a time, on first touch (tile_clear.h): the whole bin
// walked here, each triangle's regions in the order walk.h visits them. Returns false,
// having written nothing, where the tile or a triangle of its bin does not qualify.
template <class F>
bool walkTakingDepthClearByRegion(const TileJob& job, std::span<const uint32_t> bin, const TileBounds& tile,
                                  float clearValue, PipelineCounters& counters) {
  constexpr int kRegion = limits::kRegionSize, kRegionsAcross = limits::kTileSize / kRegion;
  static_assert(kRegionsAcross * kRegionsAcross <= 32, "a tile's regions are bits of one word");
  if constexpr (!kDepthRowsInRegions<F>) return false;
  const Framebuffer& fb = *job.framebuffer;
  if (bin.empty() || !fb.depth || tile.x0 % kRegion || (tile.x1 + 1) % kRegion || tile.y0 % kRegion || (tile.y1 + 1) % kRegion)
    return false;
  for (uint32_t index : bin) {
    const SetupTriangle& tri = job.triangles[index];
    const DrawRecord& draw = job.draws[tri.drawIndex];
    if (!draw.state.depthTest || !draw.state.depthWrite || colorOutputsWritten(draw, fb) != 0) return false;
    for (const EdgeFunction& e : tri.edge)
      if (!hasSmallSteps(e)) return false;
    // A triangle too small to hold a region keeps its block walk (walk.h): sixteen rows
    // would cost it more than the clear saves.
    const TileBounds bounds = boundsInTile(tri, tile);
    if (bounds.x0 <= bounds.x1 && bounds.y0 <= bounds.y1 && !holdsWholeRegion(bounds)) return false;
  }
  // Bit (row * kRegionsAcross + column) of the region at (regionX, regionY) in the tile.
  const auto regionBit = [&](int regionX, int regionY) {
    return 1u << ((regionY - tile.y0) / kRegion * kRegionsAcross + (regionX - tile.x0) / kRegion);
  };
  const uint64_t start = job.timeStages ? cycleCount() : 0;
  const uint32_t clearCode = format::depthClearCode(clearValue, fb.depth->depthBits());
  uint32_t taken = 0;   // the regions (regionBit) that took the clear
  for (uint32_t index : bin) {
    const SetupTriangle& tri = job.triangles[index];
    const RasterState& state = job.draws[tri.drawIndex].state;
    const TileBounds bounds = boundsInTile(tri, tile);
    if (bounds.x0 > bounds.x1 || bounds.y0 > bounds.y1) continue;
    const WalkEdge edges[3] = {WalkEdge(tri.edge[0]), WalkEdge(tri.edge[1]), WalkEdge(tri.edge[2])};
    for (int regionY = bounds.y0 & ~(kRegion - 1); regionY <= bounds.y1; regionY += kRegion) {
      for (int regionX = bounds.x0 & ~(kRegion - 1); regionX <= bounds.x1; regionX += kRegion) {
        if (regionOverlap(edges, regionX, regionY) == Overlap::Outside) continue;
        const uint32_t bit = regionBit(regionX, regionY);
        depthOnlyStraddledRegion<F>(tri, state, *fb.depth, fb.width, regionX, regionY, taken & bit ? nullptr : &clearCode);
        taken |= bit;
      }
    }
  }
  // The regions no triangle reached take the clear now.
  ClearValues depthClear;
  depthClear.depth = true;
  depthClear.depthValue = clearValue;
  for (int regionY = tile.y0; regionY <= tile.y1; regionY += kRegion)
    for (int regionX = tile.x0; regionX <= tile.x1; regionX += kRegion)
      if (!(taken & regionBit(regionX, regionY)))
        merge::clearRect(fb, depthClear, TileBounds{regionX, regionY, regionX + kRegion - 1, regionY + kRegion - 1}, false);
  if (job.timeStages) counters.rasterCycles += cycleCount() - start;
  return true;
}

}  // namespace

template <class F>
size_t clearTile(const TileJob& job, std::span<const uint32_t> bin, const TileBounds& tile, const ClearValues& pending,
                 PipelineCounters& counters) {
  const bool shadesWhole = !bin.empty() && !walksVisibleFirst(job, bin.size()) &&
                           canShadeTileWhole<F>(tile, job.draws[job.triangles[bin.front()].drawIndex]);
  const TileClearPlan plan = planTileClear(job, bin, tile, pending, shadesWhole);
  const Framebuffer& fb = *job.framebuffer;
  // A depth-only bin of large triangles takes its depth clear region by region instead.
  if (plan.rest.depth && walkTakingDepthClearByRegion<F>(job, bin, tile, plan.rest.depthValue, counters)) {
    ClearValues colorOnly = plan.rest;   // what else the pass clears (its draws write no colour)
    colorOnly.depth = false;
    merge::clearRect(fb, colorOnly, tile, true);
    return bin.size();
  }
  merge::clearRect(fb, plan.rest, tile, true, bin.empty() && job.streamUntouchedClears);
  if (!plan.firstStoresDepth) return 0;
  const SetupTriangle& first = job.triangles[bin.front()];
  storeDepthCodes<F>(first, *fb.depth, fb.width, tile);
  if (plan.firstShadedWhole)
    shadeTileWhole<F>(job, tile, first, LaneLayout<F>(fb.flipY, fb.width), bin.size() == 1, counters);
  return 1;
}

template size_t clearTile<FastLanes>(const TileJob&, std::span<const uint32_t>, const TileBounds&, const ClearValues&,
                                     PipelineCounters&);
template size_t clearTile<ScalarLanes>(const TileJob&, std::span<const uint32_t>, const TileBounds&, const ClearValues&,
                                       PipelineCounters&);

}  // namespace raster
