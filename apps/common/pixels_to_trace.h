// Which pixels to trace (`raster trace`): `raster report --pixels N` traces these, and `raster
// compare` names the first as the one to trace. The worst differing pixels of the final image
// first (largest difference over the channels against GL, in the kind's unit,
// compare::pixelDifference; ties by position, row by row from the top), then, when fewer than
// N differ, interior points of a fixed pattern (the centre, then the quarter points).
#pragma once

#include <cstdint>
#include <vector>

#include "backends/backend.h"

namespace cli {

struct ChosenPixel {
  int x = 0, y = 0;            // image coordinates, row 0 at the top
  uint64_t difference = 0;     // 0 for an interior point that does not differ
};

// At most `count` distinct pixels; ours and gl must be comparable (compare::checkComparable).
std::vector<ChosenPixel> choosePixels(const scenes::ImageData& ours, const scenes::ImageData& gl, int count);

}  // namespace cli
