// Fetch, clip flags and the viewport transform for shaded vertices (see vertex_stage.h).
#include "raster/pipeline/vertex_stage.h"

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

void windowPosition(const float clip[4], const ViewportTransform& vp, float window[4]) {
  const float oow = 1.0f / clip[3];
  for (int c = 0; c < 3; ++c) window[c] = std::fma(clip[c] * oow, vp.scale[c], vp.translate[c]);
  window[3] = oow;
}

void fetchAttributes(const VertexStream& stream, int vertex, int instance, float values[kMaxVertexAttributes][4]) {
  for (int a = 0; a < kMaxVertexAttributes; ++a) {
    values[a][0] = values[a][1] = values[a][2] = 0.0f;
    values[a][3] = 1.0f;
  }
  auto fetch = [&](const float* base, int stride, int index, const std::vector<AttributeLayout>& layout) {
    const float* src = base + size_t(index) * size_t(stride);
    for (const AttributeLayout& attr : layout)
      for (int c = 0; c < attr.components; ++c) values[attr.location][c] = src[attr.offsetFloats + c];
  };
  fetch(stream.vertices, stream.strideFloats, vertex, stream.attributes);
  if (stream.instances) fetch(stream.instances, stream.instanceStrideFloats, instance, stream.instanceAttributes);
}

}  // namespace raster::vertex_stage
