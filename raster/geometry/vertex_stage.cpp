// Clip flags of shaded vertices (see vertex_stage.h).
#include "raster/geometry/vertex_stage.h"

#include <cmath>

namespace raster::vertex_stage {

uint8_t clipMask(const float clip[4]) {
  const float x = clip[0], y = clip[1], z = clip[2], w = clip[3];
  uint8_t mask = 0;
  if (x > w) mask |= 1u << 0;
  if (0.0f > x + w) mask |= 1u << 1;
  if (y > w) mask |= 1u << 2;
  if (0.0f > y + w) mask |= 1u << 3;
  if (0.0f > z + w) mask |= 1u << 4;
  if (z > w) mask |= 1u << 5;
  // NaN positions: llvmpipe's compares are ordered, so NaN sets no flag; the clipper's
  // NaN check then discards such triangles if any other vertex is clipped.
  return mask;
}

}  // namespace raster::vertex_stage
