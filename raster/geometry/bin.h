// Stage 4, binning: set-up triangles in, per-tile lists of triangle indices out.
//
// The framebuffer is cut into kTileSize tiles (limits.h). A triangle goes into every tile
// that its pixel bounds touch, unless one of its edge functions rejects the whole overlap of
// tile and bounds at all four corners (the function is linear, so the corners decide); a
// triangle whose bounds lie in one tile goes there untested, as in llvmpipe.
// Triangles are appended in API order, so each tile sees its triangles in that order, and
// the tile stage owes the output's independence of thread count to nothing else.
//
// Large draws are binned in parts: consecutive ranges of triangles, each into its own
// TileBins in parallel, appended in range order. Each triangle is read once, and every
// tile's list is the same as one pass through the whole range would make.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "raster/contract.h"

namespace raster {

class TileBins {
 public:
  // Tiles covering a width x height framebuffer, every bin empty (capacity is kept).
  void reset(int width, int height);
  int tilesX() const { return tilesX_; }
  int tilesY() const { return tilesY_; }
  int tileCount() const { return tilesX_ * tilesY_; }
  // The triangle indices binned into tile (tileX, tileY) = tile index tileY * tilesX + tileX.
  std::span<const uint32_t> bin(int tile) const { return bins_[size_t(tile)]; }
  // The pixel rectangle of a tile, clipped to the framebuffer.
  TileBounds bounds(int tile) const;

  // Bins triangles[first, end), by their indices in `triangles`; returns the (triangle,
  // tile) pairs added.
  uint64_t binTriangles(std::span<const SetupTriangle> triangles, uint32_t first, uint32_t end);
  // Appends every tile's list of `part`, which has the same tiles, to this one's.
  void append(const TileBins& part);
  // Empties every bin, keeping the tiles.
  void clear();

 private:
  std::vector<std::vector<uint32_t>> bins_;
  int width_ = 0, height_ = 0;
  int tilesX_ = 0, tilesY_ = 0;
};

}  // namespace raster
