// The pass's work items (a tile, a band of one, or a range of a tile's triangles), and heavy
// tiles of depth-only passes walked in triangle ranges by several threads at once.
//
// Shadow maps spread their work unevenly over their tiles: pbr's last cascade puts 57% of
// it in one (BENCHMARKS.md, the scaling model), and the thread walking that tile sets the
// pass's time. In a pass whose every draw tests and writes depth and writes no colour (LESS
// or LEQUAL, the only tests there are: contract.h), each pixel's code ends as the least of
// its starting code and the codes of its covered fragments, in whatever order they come: a
// write only ever lowers the stored code (LEQUAL's equal code writes the same code again),
// and a code above it changes nothing. So such a tile's bin may be cut into consecutive
// ranges walked at once: the first into the target, with the tile's share of the clear
// (tile_clear.h, as for any bin), each later one into a copy of the depth target whose tile
// starts above every code, so that it keeps its range's least codes. After the loop the
// copies are folded into the target by a per-pixel minimum: every pixel ends with the code
// one thread walking the whole bin in order gives it, at any thread count.
//
// A copy is the depth target's size (the walk addresses the buffer by pixel), kept between
// passes; at most kMaxDepthRanges - 1 of them, one per range after the first, each shared by
// every split tile (tiles do not overlap): 4 MiB a copy for a 1024x1024 map, and no target
// larger than kMaxDepthRangeTexels is split.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "raster/contract.h"

namespace raster {

// One item of the pass's parallel loop: tile `tile`'s pixels `bounds` (the whole tile, or a
// 16-row band of it), walking its bin's triangles [first, first + count) (count 0: all of
// them). `range` 0 walks into the pass's targets; range k > 0 is a later range of a heavy
// depth-only tile, walked into depth copy k - 1.
struct TileWorkItem {
  int tile = 0;
  TileBounds bounds{};
  uint32_t first = 0, count = 0;
  int range = 0;
  std::span<const uint32_t> triangles(std::span<const uint32_t> bin) const {
    return count ? bin.subspan(first, count) : bin;
  }
};

// At most this many ranges a tile (so copies a pass), and at least this many triangles a
// range: a range of a few triangles would cost more in its copy's tile than it saves.
constexpr int kMaxDepthRanges = 4;
constexpr size_t kMinDepthRangeTriangles = 64;

// Whether the pass's tiles may be walked in ranges: a depth target of at most
// kMaxDepthRangeTexels, and every draw tests and writes depth and writes no colour target.
// The cap bounds the copies' memory, which no --max-memory charge covers: at most 16 MiB a
// copy, three copies (the scenes' shadow maps are 1024x1024, 4 MiB).
constexpr size_t kMaxDepthRangeTexels = size_t(2048) * 2048;
bool mayWalkDepthRanges(std::span<const DrawRecord> draws, const Framebuffer& framebuffer);

// The ranges a tile of `binSize` triangles is walked in, in a pass of `passEntries` bin
// entries on `threads` threads: one, unless the tile holds more than 1 / (2 x threads) of
// the entries; then as many as the threads, up to kMaxDepthRanges and one per
// kMinDepthRangeTriangles.
int depthRangeCount(size_t binSize, size_t passEntries, int threads);

// Cuts each heavy tile's item into its ranges (depthRangeCount); binSizes[t] is tile t's
// count of triangles (the pass's bins, geometry/bin.h, as the renderer holds them). Range k
// of a tile is placed k / ranges of the way down the list, so that a parallel loop's first
// split hands a tile's ranges to different threads. Returns the most ranges any tile took
// (1: none was cut).
int cutHeavyTiles(std::vector<TileWorkItem>& items, std::span<const size_t> binSizes, int threads);

// The depth copies a pass's later ranges walk into: copy k serves range k + 1 of every split
// tile. Grown, never shrunk, so the next frame's passes allocate nothing.
class DepthRangeCopies {
 public:
  // `count` copies of `framebuffer`'s depth target (its size and format), and a framebuffer
  // for each: `framebuffer` with its depth target replaced. Before the pass's loop.
  void prepare(const Framebuffer& framebuffer, int count);
  // Copy k's framebuffer, with `tile` set above every code: for range k + 1's task.
  const Framebuffer& beginRange(int k, const TileBounds& tile);
  // Lowers `framebuffer`'s depth codes over `tile` to copy k's where those are less. After
  // the pass's loop.
  void fold(int k, const Framebuffer& framebuffer, const TileBounds& tile) const;

 private:
  std::vector<std::unique_ptr<Texture>> textures_;
  std::vector<Framebuffer> framebuffers_;
};

}  // namespace raster
