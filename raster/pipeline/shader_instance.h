// One draw's program: a shader port plus a snapshot of its uniforms, behind a small
// virtual interface so the pipeline's stages need not be templates on every port.
// The pipeline calls it once per lane group, never per pixel.
#pragma once

#include <memory>

#include "raster/pipeline/program.h"
#include "raster/pipeline/vertex_stage.h"

namespace raster {

// The lane type the reference path shades with: one 2x2 quad in plain loops.
using ScalarLanes = simd::Lanes<4>;
using simd::FastLanes;

class ShaderInstance {
 public:
  virtual ~ShaderInstance() = default;
  virtual int varyingFloats() const = 0;
  virtual int colorOutputs() const = 0;
  // Shades vertices [0, stream.vertexCount) of one instance into records
  // [recordBase, recordBase + vertexCount) of `out`.
  virtual void shadeVertices(const VertexStream& stream, int instance, int recordBase, const ViewportTransform& viewport,
                             ShadedVertices& out) const = 0;
  // Shades one lane group; `varyings` holds varyingFloats() interpolated values.
  virtual void shadeFragments(const FragmentInput<FastLanes>& in, const FastLanes* varyings,
                              FragmentOutput<FastLanes>& out) const = 0;
  virtual void shadeFragments(const FragmentInput<ScalarLanes>& in, const ScalarLanes* varyings,
                              FragmentOutput<ScalarLanes>& out) const = 0;
};

template <class Program>
class ProgramInstance final : public ShaderInstance {
 public:
  explicit ProgramInstance(const typename Program::Uniforms& uniforms) : uniforms_(uniforms) {}

  int varyingFloats() const override { return varyingFloatCount<Program>(); }
  int colorOutputs() const override { return Program::kColorOutputs; }

  void shadeVertices(const VertexStream& stream, int instance, int recordBase, const ViewportTransform& viewport,
                     ShadedVertices& out) const override {
    constexpr int kLanes = FastLanes::kCount;
    for (int first = 0; first < stream.vertexCount; first += kLanes) {
      const int count = stream.vertexCount - first < kLanes ? stream.vertexCount - first : kLanes;
      vertex_stage::shadeVertexGroup<Program, FastLanes>(uniforms_, stream, first, count, instance, recordBase + first,
                                                         viewport, out);
    }
  }
  void shadeFragments(const FragmentInput<FastLanes>& in, const FastLanes* varyings,
                      FragmentOutput<FastLanes>& out) const override {
    shade(in, varyings, out);
  }
  void shadeFragments(const FragmentInput<ScalarLanes>& in, const ScalarLanes* varyings,
                      FragmentOutput<ScalarLanes>& out) const override {
    shade(in, varyings, out);
  }

 private:
  template <class F>
  void shade(const FragmentInput<F>& in, const F* varyings, FragmentOutput<F>& out) const {
    Program::fragment(uniforms_, in, varyingsFromArray<Program, F>(varyings), out);
  }
  typename Program::Uniforms uniforms_;
};

}  // namespace raster
