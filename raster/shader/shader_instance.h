// One draw's program: a shader port plus a snapshot of its uniforms, behind a small
// virtual interface so the pipeline's stages need not be templates on every port.
// The pipeline calls it once per lane group, never per pixel.
#pragma once

#include <memory>

#include "raster/shader/program.h"
#include "raster/geometry/vertex_stage.h"

namespace raster {

class ShaderInstance {
 public:
  virtual ~ShaderInstance() = default;
  virtual int varyingFloats() const = 0;
  virtual int colorOutputs() const = 0;
  // Whether its fragment shader reads textures: the pipeline then shades lane groups two
  // at a time (raster_tile.cpp), so one group's texel loads overlap the other's.
  virtual bool samplesTextures() const = 0;
  // Shades one instance's vertices into their records of `out`, with the plain-C++ lanes
  // when `scalarLanes` (the same bits either way).
  virtual void shadeVertices(const VertexBatch& batch, ShadedVertices& out, bool scalarLanes) const = 0;
  // Shades one lane group; `varyings` holds varyingFloats() interpolated values.
  virtual void shadeFragments(const FragmentInput<FastLanes>& in, const FastLanes* varyings,
                              FragmentOutput<FastLanes>& out) const = 0;
  virtual void shadeFragments(const FragmentInput<ScalarLanes>& in, const ScalarLanes* varyings,
                              FragmentOutput<ScalarLanes>& out) const = 0;
#if RASTER_AVX2
  virtual void shadeFragments(const FragmentInput<PairedLanes>& in, const PairedLanes* varyings,
                              FragmentOutput<PairedLanes>& out) const = 0;
#endif
};

template <class Program>
class ProgramInstance final : public ShaderInstance {
 public:
  explicit ProgramInstance(const typename Program::Uniforms& uniforms) : uniforms_(uniforms) {}

  int varyingFloats() const override { return varyingFloatCount<Program>(); }
  int colorOutputs() const override { return Program::kColorOutputs; }
  bool samplesTextures() const override { return raster::samplesTextures<Program>(); }

  void shadeVertices(const VertexBatch& batch, ShadedVertices& out, bool scalarLanes) const override {
    if (scalarLanes) shadeVerticesWith<ScalarLanes>(batch, out);
    else shadeVerticesWith<FastLanes>(batch, out);
  }
  void shadeFragments(const FragmentInput<FastLanes>& in, const FastLanes* varyings,
                      FragmentOutput<FastLanes>& out) const override {
    shade(in, varyings, out);
  }
  void shadeFragments(const FragmentInput<ScalarLanes>& in, const ScalarLanes* varyings,
                      FragmentOutput<ScalarLanes>& out) const override {
    shade(in, varyings, out);
  }
#if RASTER_AVX2
  void shadeFragments(const FragmentInput<PairedLanes>& in, const PairedLanes* varyings,
                      FragmentOutput<PairedLanes>& out) const override {
    shade(in, varyings, out);
  }
#endif

 private:
  template <class F>
  void shadeVerticesWith(const VertexBatch& batch, ShadedVertices& out) const {
    const int vertexCount = batch.stream.vertexCount;
    for (int first = 0; first < vertexCount; first += F::kCount) {
      const int count = vertexCount - first < F::kCount ? vertexCount - first : F::kCount;
      vertex_stage::shadeVertexGroup<Program, F>(uniforms_, batch, first, count, out);
    }
  }
  template <class F>
  void shade(const FragmentInput<F>& in, const F* varyings, FragmentOutput<F>& out) const {
    Program::fragment(uniforms_, in, varyingsFromArray<Program, F>(varyings), out);
  }
  typename Program::Uniforms uniforms_;
};

}  // namespace raster
