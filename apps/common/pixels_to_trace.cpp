// The pixels to trace (pixels_to_trace.h).
#include "apps/common/pixels_to_trace.h"

#include <algorithm>
#include <utility>

#include "compare/metrics.h"

namespace cli {

std::vector<ChosenPixel> choosePixels(const scenes::ImageData& ours, const scenes::ImageData& gl, int count) {
  compare::checkComparable("final", ours, gl);
  const size_t wanted = size_t(std::max(count, 0));
  const size_t pixels = size_t(ours.width) * size_t(ours.height);
  // Differing pixels, worst first, then by index (row-major from the top: "by position").
  std::vector<std::pair<uint64_t, size_t>> differing;
  for (size_t i = 0; i < pixels; ++i)
    if (const uint64_t d = compare::pixelDifference(ours, gl, i)) differing.push_back({d, i});
  const auto worse = [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; };
  const size_t take = std::min(wanted, differing.size());
  std::partial_sort(differing.begin(), differing.begin() + std::ptrdiff_t(take), differing.end(), worse);

  std::vector<ChosenPixel> chosen;
  for (size_t k = 0; k < take; ++k)
    chosen.push_back({int(differing[k].second % size_t(ours.width)), int(differing[k].second / size_t(ours.width)),
                      differing[k].first});
  // Interior points, in eighths of the image: the centre, the quarter points, the edge midpoints'
  // inner neighbours. A point already chosen is not chosen twice.
  static constexpr int kPattern[][2] = {{4, 4}, {2, 2}, {6, 2}, {2, 6}, {6, 6}, {4, 2}, {2, 4}, {6, 4}, {4, 6},
                                        {3, 3}, {5, 3}, {3, 5}, {5, 5}, {1, 1}, {7, 1}, {1, 7}, {7, 7}};
  for (const auto& p : kPattern) {
    if (chosen.size() >= wanted) break;
    const int x = std::min(ours.width - 1, ours.width * p[0] / 8), y = std::min(ours.height - 1, ours.height * p[1] / 8);
    const bool seen = std::any_of(chosen.begin(), chosen.end(), [&](const ChosenPixel& c) { return c.x == x && c.y == y; });
    if (!seen) chosen.push_back({x, y, compare::pixelDifference(ours, gl, size_t(y) * size_t(ours.width) + size_t(x))});
  }
  return chosen;
}

}  // namespace cli
