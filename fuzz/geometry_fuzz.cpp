// Fuzz target: clipping, triangle setup and binning fed arbitrary vertices (any float bits:
// NaN, infinities, w near 0 and negative, coordinates up to 1e38) and framebuffer sizes. No
// input may crash or trip a sanitizer, and every set-up triangle must keep the promises the
// tile stage relies on: bounds inside the framebuffer, no more than the clipper's vertex
// budget, bins in API order.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "raster/geometry/assemble.h"
#include "raster/geometry/bin.h"
#include "raster/geometry/vertex_stage.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr size_t kVertexBytes = 4 * sizeof(float);
  if (size < 4 + 3 * kVertexBytes) return 0;
  // Framebuffer: 1..1024 on a side (kept small so binning stays fast); the rest: vertices.
  const int width = 1 + (data[0] | (data[1] & 3) << 8), height = 1 + (data[2] | (data[3] & 3) << 8);
  const size_t vertexCount = (size - 4) / kVertexBytes;
  const raster::ViewportTransform viewport{{0.5f * float(width), 0.5f * float(height), 0.5f},
                                           {0.5f * float(width), 0.5f * float(height), 0.5f}};
  raster::ShadedVertices shaded;
  shaded.varyingFloats = 1;
  shaded.stride = raster::vertex_record::kVaryings + 1;
  shaded.data.resize(vertexCount * size_t(shaded.stride));
  shaded.clipMask.resize(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v) {
    float* record = shaded.record(int(v));
    std::memcpy(record, data + 4 + v * kVertexBytes, kVertexBytes);   // clip x y z w
    // The window position as the vertex stage makes it (its FMA form is not needed here).
    const float oow = 1.0f / record[3];
    for (int c = 0; c < 3; ++c) record[raster::vertex_record::kWindow + c] = record[c] * oow * viewport.scale[c] + viewport.translate[c];
    record[raster::vertex_record::kWindow + 3] = oow;
    record[raster::vertex_record::kVaryings] = float(v);
    shaded.clipMask[v] = raster::vertex_stage::clipMask(record);
  }
  std::vector<uint32_t> indices;
  for (uint32_t i = 0; i + 2 < vertexCount; i += 3) indices.insert(indices.end(), {i, i + 1, i + 2});

  raster::SetupState setup;
  setup.framebufferWidth = width;
  setup.framebufferHeight = height;
  setup.varyingFloats = 1;
  setup.bottomEdgeRule = data[0] & 1;
  setup.cullBack = data[2] & 1;
  raster::TriangleList triangles;
  raster::PlaneList planes;
  raster::PipelineCounters counters;
  const raster::AssemblyInput input{setup, shaded, indices, int(vertexCount), viewport};
  raster::assemblePrimitives(input, 0, indices.size() / 3, {triangles, planes}, counters);
  for (const raster::SetupTriangle& tri : triangles) {
    if (tri.minX < 0 || tri.minY < 0 || tri.maxX >= width || tri.maxY >= height || tri.minX > tri.maxX || tri.minY > tri.maxY)
      __builtin_trap();
    if (tri.varyingBase + 1 > planes.size()) __builtin_trap();
  }
  raster::TileBins bins;
  bins.reset(width, height);
  bins.binTriangles(triangles, 0, uint32_t(triangles.size()));
  for (int t = 0; t < bins.tileCount(); ++t) {
    const auto bin = bins.bin(t);
    for (size_t i = 1; i < bin.size(); ++i)
      if (bin[i - 1] >= bin[i]) __builtin_trap();
  }
  return 0;
}
