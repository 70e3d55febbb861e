// Stage 1, fetch + vertex shading: vertex buffers in, shaded vertices out.
//
// Input:  a VertexStream (interleaved float vertices, an attribute layout, and optionally
//         a per-instance stream with divisor 1).
// Output: ShadedVertices (contract.h), one record per (instance, vertex): clip position,
//         window position and varyings (vertex_record), plus a 6-bit clip mask.
// Every vertex of the buffer is shaded once per instance, a lane group at a time; a vertex's
// result does not depend on which lane or group computed it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "raster/contract.h"
#include "raster/shader/program.h"

namespace raster {

namespace vertex_stage {

// Clip flags as llvmpipe's draw JIT computes them (draw_llvm.c generate_clipmask):
// bit 0: x > w, 1: x + w < 0, 2: y > w, 3: y + w < 0, 4: z + w < 0, 5: z > w.
uint8_t clipMask(const float clip[4]);

// clipMask for every lane at once: the same ordered compares of the same floats, each
// plane's flag added as a power of two (exact in float).
template <class F>
F clipMaskLanes(const glsl::vec4<F>& clip) {
  const F zero(0.0f);
  auto flag = [&](auto outside, float bit) { return simd::select(outside, F(bit), zero); };
  return flag(clip.x > clip.w, 1.0f) + flag(zero > clip.x + clip.w, 2.0f) + flag(clip.y > clip.w, 4.0f) +
         flag(zero > clip.y + clip.w, 8.0f) + flag(zero > clip.z + clip.w, 16.0f) + flag(clip.z > clip.w, 32.0f);
}

// Shades `count` vertices of one instance, from vertex `first` of the batch on, into its
// records (already sized): one lane group.
template <class Program, class F>
void shadeVertexGroup(const typename Program::Uniforms& uniforms, const VertexBatch& batch, int first, int count,
                      ShadedVertices& out) {
  constexpr int kLanes = F::kCount;
  constexpr int kVaryings = varyingFloatCount<Program>();
  const VertexStream& stream = batch.stream;
  const ViewportTransform& vp = batch.viewport;
  const int instance = batch.instance;
  // Attribute planes, built in registers: locations and components the streams do not feed
  // read (0, 0, 0, 1); per-vertex components are gathered lane by lane (lanes past `count`
  // repeat the group's first vertex); per-instance values are the same in every lane.
  VertexInput<F> input;
  for (int a = 0; a < limits::kMaxVertexAttributes; ++a) input.attribute[a] = glsl::vec4<F>(F(0.0f), F(0.0f), F(0.0f), F(1.0f));
  auto component = [](glsl::vec4<F>& v, int c) -> F& { return c == 0 ? v.x : c == 1 ? v.y : c == 2 ? v.z : v.w; };
  alignas(32) int vertexOffset[kLanes];
  for (int lane = 0; lane < kLanes; ++lane)
    vertexOffset[lane] = (first + (lane < count ? lane : 0)) * stream.strideFloats;   // limits::kMaxVertexBufferFloats
  for (const AttributeLayout& attr : stream.attributes)
    for (int c = 0; c < attr.components; ++c)
      component(input.attribute[attr.location], c) = F::gather(stream.vertices + attr.offsetFloats + c, vertexOffset);
  if (stream.instances) {
    const float* src = stream.instances + size_t(instance) * size_t(stream.instanceStrideFloats);
    for (const AttributeLayout& attr : stream.instanceAttributes)
      for (int c = 0; c < attr.components; ++c)
        component(input.attribute[attr.location], c) = F(src[attr.offsetFloats + c]);
  }
  input.gl_InstanceID = F(float(instance));

  glsl::vec4<F> position;
  typename Program::template Varyings<F> varyings;
  Program::vertex(uniforms, input, position, varyings);

  // Window position as the draw JIT computes it for every vertex (generate_viewport):
  // oow = 1/w; x_win = fma(x * oow, scale, translate); w_win = oow.
  const F oow = F(1.0f) / position.w;
  const glsl::vec4<F> window(simd::fma(position.x * oow, F(vp.scale[0]), F(vp.translate[0])),
                             simd::fma(position.y * oow, F(vp.scale[1]), F(vp.translate[1])),
                             simd::fma(position.z * oow, F(vp.scale[2]), F(vp.translate[2])), oow);
  // The records, the lanes' values in record order: clip position, window position, the
  // varyings. Eight of them at a time go out lane by lane (a transpose where the lane type
  // has one); the varyings past the last whole eight, one float at a time.
  static_assert(vertex_record::kClip == 0 && vertex_record::kWindow == 4 && vertex_record::kVaryings == 8,
                "a record starts with the clip and window positions");
  constexpr int kFields = vertex_record::kVaryings + kVaryings;
  F fields[kFields] = {position.x, position.y, position.z, position.w, window.x, window.y, window.z, window.w};
  varyingsToArray<Program, F>(varyings, fields + vertex_record::kVaryings);
  const int firstRecord = batch.recordBase + first;
  float* const records = out.record(firstRecord);
  const size_t stride = size_t(out.stride);
  int field = 0;
  for (; field + 8 <= kFields; field += 8) simd::storeLanesTransposed(fields + field, records + field, stride, count);
  for (; field < kFields; ++field) {
    alignas(32) float lanes[kLanes];
    fields[field].store(lanes);
    for (int lane = 0; lane < count; ++lane) records[size_t(lane) * stride + size_t(field)] = lanes[lane];
  }
  alignas(32) float clipFlags[kLanes];
  clipMaskLanes(position).store(clipFlags);
  for (int lane = 0; lane < count; ++lane) out.clipMask[size_t(firstRecord + lane)] = uint8_t(clipFlags[lane]);
}

}  // namespace vertex_stage
}  // namespace raster
