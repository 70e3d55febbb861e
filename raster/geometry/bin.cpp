// Binning of set-up triangles into screen tiles (see bin.h).
#include "raster/geometry/bin.h"

#include <algorithm>

namespace raster {

using limits::kTileSize;

void TileBins::reset(int width, int height) {
  width_ = width;
  height_ = height;
  tilesX_ = (width + kTileSize - 1) / kTileSize;
  tilesY_ = (height + kTileSize - 1) / kTileSize;
  // Bins keep their capacity from pass to pass (clear() empties them), and so do the bins
  // of a larger framebuffer when a smaller one comes: a frame's passes alternate sizes (the
  // shadow map and the screen, the bloom chain), and freeing and regrowing every list per
  // pass was about half of the shadow frame's serial time between its two passes.
  if (bins_.size() < size_t(tileCount())) bins_.resize(size_t(tileCount()));
  clear();
}

TileBounds TileBins::bounds(int tile) const {
  const int x0 = (tile % tilesX_) * kTileSize, y0 = (tile / tilesX_) * kTileSize;
  return {x0, y0, std::min(x0 + kTileSize, width_) - 1, std::min(y0 + kTileSize, height_) - 1};
}

uint64_t TileBins::binTriangles(std::span<const SetupTriangle> triangles, uint32_t first, uint32_t end) {
  uint64_t binned = 0;
  for (uint32_t t = first; t < end; ++t) {
    const SetupTriangle& tri = triangles[t];
    // Bounds inside one tile: binned there without the corner tests, as llvmpipe bins a
    // triangle contained in a single tile (lp_setup_bin_triangle). Most triangles of a
    // detailed mesh are; one that covers no pixel centre of its bounds then visits no
    // block of the tile (the walk tests every pixel).
    if (tri.minX / kTileSize == tri.maxX / kTileSize && tri.minY / kTileSize == tri.maxY / kTileSize) {
      bins_[size_t(tri.minY / kTileSize) * size_t(tilesX_) + size_t(tri.minX / kTileSize)].push_back(t);
      ++binned;
      continue;
    }
    for (int tileY = tri.minY / kTileSize; tileY <= tri.maxY / kTileSize; ++tileY) {
      for (int tileX = tri.minX / kTileSize; tileX <= tri.maxX / kTileSize; ++tileX) {
        // The overlap of the tile and the triangle's bounds.
        const int x0 = std::max(tileX * kTileSize, tri.minX), x1 = std::min(tileX * kTileSize + kTileSize - 1, tri.maxX);
        const int y0 = std::max(tileY * kTileSize, tri.minY), y1 = std::min(tileY * kTileSize + kTileSize - 1, tri.maxY);
        bool outside = false;
        for (const EdgeFunction& e : tri.edge)
          outside = outside || std::max({e.at(x0, y0), e.at(x1, y0), e.at(x0, y1), e.at(x1, y1)}) <= 0;
        if (outside) continue;
        bins_[size_t(tileY) * size_t(tilesX_) + size_t(tileX)].push_back(t);
        ++binned;
      }
    }
  }
  return binned;
}

void TileBins::append(const TileBins& part) {
  for (size_t tile = 0; tile < size_t(tileCount()); ++tile)
    bins_[tile].insert(bins_[tile].end(), part.bins_[tile].begin(), part.bins_[tile].end());
}

void TileBins::clear() {
  for (auto& b : bins_) b.clear();
}

}  // namespace raster
