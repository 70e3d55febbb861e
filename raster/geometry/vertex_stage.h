// Stage 1, fetch + vertex shading: vertex buffers in, shaded vertices out.
//
// Input:  a VertexStream (interleaved float vertices, an attribute layout, and optionally
//         a per-instance stream with divisor 1).
// Output: ShadedVertices, one record per (instance, vertex):
//           [0..3]  clip-space position (x, y, z, w) from gl_Position
//           [4..7]  window position (x, y, z, 1/w), llvmpipe's viewport transform
//           [8..]   the program's varyings (N floats)
//         plus a 6-bit clip mask per record.
// Every vertex of the buffer is shaded once per instance, a lane group at a time; a vertex's
// result does not depend on which lane or group computed it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "raster/shader/program.h"

namespace raster {

struct AttributeLayout {
  int location = 0;
  int components = 3;
  int offsetFloats = 0;
};

struct VertexStream {
  const float* vertices = nullptr;       // per-vertex data
  int strideFloats = 0;
  int vertexCount = 0;
  std::vector<AttributeLayout> attributes;
  const float* instances = nullptr;      // per-instance data (divisor 1), may be null
  int instanceStrideFloats = 0;
  std::vector<AttributeLayout> instanceAttributes;
};

// GL viewport mapping, with llvmpipe's orientation for window-system buffers folded in.
struct ViewportTransform {
  float scale[3];
  float translate[3];
};

struct ShadedVertices {
  int varyingFloats = 0;
  int stride = 0;                        // 8 + varyingFloats
  std::vector<float> data;
  std::vector<uint8_t> clipMask;

  int count() const { return int(clipMask.size()); }
  const float* record(int i) const { return data.data() + size_t(i) * size_t(stride); }
  float* record(int i) { return data.data() + size_t(i) * size_t(stride); }
};

namespace vertex_stage {

constexpr int kClipOffset = 0;
constexpr int kWindowOffset = 4;
constexpr int kVaryingOffset = 8;

// Clip flags as llvmpipe's draw JIT computes them (draw_llvm.c generate_clipmask):
// bit 0: x > w, 1: x + w < 0, 2: y > w, 3: y + w < 0, 4: z + w < 0, 5: z > w.
uint8_t clipMask(const float clip[4]);

// Shades `count` vertices of one instance starting at `first` into out (records already sized).
template <class Program, class F>
void shadeVertexGroup(const typename Program::Uniforms& uniforms, const VertexStream& stream, int first, int count,
                      int instance, int recordBase, const ViewportTransform& vp, ShadedVertices& out) {
  constexpr int kLanes = F::kCount;
  constexpr int kVaryings = varyingFloatCount<Program>();
  // Attribute planes, built in registers: locations and components the streams do not feed
  // read (0, 0, 0, 1); per-vertex components are gathered lane by lane (lanes past `count`
  // repeat the group's first vertex); per-instance values are the same in every lane.
  VertexInput<F> input;
  for (int a = 0; a < kMaxVertexAttributes; ++a) input.attribute[a] = glsl::vec4<F>(F(0.0f), F(0.0f), F(0.0f), F(1.0f));
  auto component = [](glsl::vec4<F>& v, int c) -> F& { return c == 0 ? v.x : c == 1 ? v.y : c == 2 ? v.z : v.w; };
  alignas(32) int vertexOffset[kLanes];
  for (int lane = 0; lane < kLanes; ++lane)
    vertexOffset[lane] = (first + (lane < count ? lane : 0)) * stream.strideFloats;   // Renderer::draw bounds it
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
  alignas(32) float pos[4][kLanes], win[4][kLanes];
  alignas(32) float vary[kVaryings > 0 ? kVaryings : 1][kLanes];
  glsl::storePlanes(position, pos);
  glsl::storePlanes(window, win);
  F flat[kVaryings > 0 ? kVaryings : 1];
  varyingsToArray<Program, F>(varyings, flat);
  for (int v = 0; v < kVaryings; ++v) flat[v].store(vary[v]);

  for (int lane = 0; lane < count; ++lane) {
    const int r = recordBase + lane;
    float* rec = out.record(r);
    for (int c = 0; c < 4; ++c) rec[kClipOffset + c] = pos[c][lane];
    for (int c = 0; c < 4; ++c) rec[kWindowOffset + c] = win[c][lane];
    for (int v = 0; v < kVaryings; ++v) rec[kVaryingOffset + v] = vary[v][lane];
    out.clipMask[size_t(r)] = clipMask(rec + kClipOffset);
  }
}

}  // namespace vertex_stage
}  // namespace raster
