// Heavy tiles of depth-only passes in triangle ranges (see depth_ranges.h).
#include "raster/tile/depth_ranges.h"

#include <algorithm>
#include <numeric>

namespace raster {

namespace {

// Above every depth code (Depth16 and Depth24 codes are at most 2^24 - 1), and small enough
// that LEQUAL's stored + 1 cannot overflow in the tests' signed compares: every fragment
// passes against it, so a copy's tile ends with its range's least codes, or this where the
// range covers nothing, which the fold's minimum then leaves out.
constexpr uint32_t kAboveEveryCode = 1u << 24;

}  // namespace

bool mayWalkDepthRanges(std::span<const DrawRecord> draws, const Framebuffer& framebuffer) {
  const Texture* depth = framebuffer.depth;
  if (!depth || draws.empty() || size_t(depth->width) * size_t(depth->height) > kMaxDepthRangeTexels) return false;
  return std::all_of(draws.begin(), draws.end(), [&](const DrawRecord& draw) {
    return draw.state.depthTest && draw.state.depthWrite && colorOutputsWritten(draw, framebuffer) == 0;
  });
}

int depthRangeCount(size_t binSize, size_t passEntries, int threads) {
  if (threads < 2 || binSize * 2 * size_t(threads) <= passEntries) return 1;
  return int(std::min({size_t(threads), size_t(kMaxDepthRanges), std::max<size_t>(binSize / kMinDepthRangeTriangles, 1)}));
}

int cutHeavyTiles(std::vector<TileWorkItem>& items, std::span<const size_t> binSizes, int threads) {
  const size_t entries = std::accumulate(binSizes.begin(), binSizes.end(), size_t(0));
  // Each item with its place in the list: the items as they were at the even places, a
  // later range just after the item k / ranges of the way down.
  std::vector<std::pair<size_t, TileWorkItem>> placed;
  int most = 1;
  const size_t count = items.size();
  for (size_t i = 0; i < count; ++i) {
    TileWorkItem item = items[i];
    const size_t size = binSizes[size_t(item.tile)];
    const int ranges = item.count == 0 ? depthRangeCount(size, entries, threads) : 1;
    most = std::max(most, ranges);
    for (int k = 0; k < ranges; ++k) {
      const size_t first = size * size_t(k) / size_t(ranges), end = size * size_t(k + 1) / size_t(ranges);
      if (ranges > 1) item.first = uint32_t(first), item.count = uint32_t(end - first), item.range = k;
      placed.emplace_back(k == 0 ? 2 * i : 2 * (count * size_t(k) / size_t(ranges)) + 1, item);
    }
  }
  std::stable_sort(placed.begin(), placed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  items.clear();
  for (const auto& [place, item] : placed) items.push_back(item);
  return most;
}

void DepthRangeCopies::prepare(const Framebuffer& framebuffer, int count) {
  const Texture& depth = *framebuffer.depth;
  if (textures_.size() < size_t(count)) textures_.resize(size_t(count));
  framebuffers_.resize(textures_.size());
  for (int k = 0; k < count; ++k) {
    std::unique_ptr<Texture>& copy = textures_[size_t(k)];
    if (!copy || copy->width != depth.width || copy->height != depth.height || copy->format != depth.format)
      copy = std::make_unique<Texture>(depth.width, depth.height, depth.format);
    framebuffers_[size_t(k)] = framebuffer;
    framebuffers_[size_t(k)].depth = copy.get();
  }
}

const Framebuffer& DepthRangeCopies::beginRange(int k, const TileBounds& tile) {
  Texture& copy = *textures_[size_t(k)];
  for (int y = tile.y0; y <= tile.y1; ++y) {
    uint32_t* row = copy.depth.data() + size_t(y) * size_t(copy.width);
    std::fill(row + tile.x0, row + tile.x1 + 1, kAboveEveryCode);
  }
  return framebuffers_[size_t(k)];
}

void DepthRangeCopies::fold(int k, const Framebuffer& framebuffer, const TileBounds& tile) const {
  const Texture& copy = *textures_[size_t(k)];
  Texture& target = *framebuffer.depth;
  for (int y = tile.y0; y <= tile.y1; ++y) {
    const uint32_t* from = copy.depth.data() + size_t(y) * size_t(copy.width);
    uint32_t* into = target.depth.data() + size_t(y) * size_t(target.width);
    for (int x = tile.x0; x <= tile.x1; ++x) into[x] = std::min(into[x], from[x]);
  }
}

}  // namespace raster
