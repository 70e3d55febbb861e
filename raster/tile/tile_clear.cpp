// Tile clears with the work the first triangle overwrites left out (tile_clear.h).
#include "raster/tile/tile_clear.h"

#include <algorithm>
#include <cmath>

#include "raster/merge/clear.h"
#include "raster/texture/format.h"
#include "raster/tile/coverage.h"
#include "raster/tile/covered_tile.h"
#include "raster/tile/depth_test.h"
#include "raster/tile/rasterize_tile.h"

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

template <class F>
size_t clearTile(const TileJob& job, std::span<const uint32_t> bin, const TileBounds& tile, const ClearValues& pending,
                 PipelineCounters& counters) {
  const bool shadesWhole = !bin.empty() && !walksVisibleFirst(job, bin.size()) &&
                           canShadeTileWhole<F>(tile, job.draws[job.triangles[bin.front()].drawIndex]);
  const TileClearPlan plan = planTileClear(job, bin, tile, pending, shadesWhole);
  const Framebuffer& fb = *job.framebuffer;
  merge::clearRect(fb, plan.rest, tile, true, bin.empty() && job.streamUntouchedClears);
  if (!plan.firstStoresDepth) return 0;
  const SetupTriangle& first = job.triangles[bin.front()];
  storeDepthCodes<F>(first, *fb.depth, fb.width, tile);
  if (plan.firstShadedWhole) shadeTileWhole<F>(job, tile, first, LaneLayout<F>(fb.flipY, fb.width), counters);
  return 1;
}

template size_t clearTile<FastLanes>(const TileJob&, std::span<const uint32_t>, const TileBounds&, const ClearValues&,
                                     PipelineCounters&);
template size_t clearTile<ScalarLanes>(const TileJob&, std::span<const uint32_t>, const TileBounds&, const ClearValues&,
                                       PipelineCounters&);

}  // namespace raster
