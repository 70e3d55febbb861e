// One draw's program: a shader port plus a snapshot of its uniforms, behind a small
// virtual interface so the pipeline's stages need not be templates on every port.
// The pipeline calls it once per lane group, never per pixel.
#pragma once

#include <memory>

#include "raster/shader/program.h"
#include "raster/geometry/vertex_stage.h"

namespace raster {

// The lane type the reference path shades with: one 2x2 quad in plain loops.
using ScalarLanes = simd::Lanes<4>;
using simd::FastLanes;
#if RASTER_AVX2
// Two FastLanes groups shaded in one call (raster_tile.cpp pairs them).
using PairedLanes = simd::Float8x2;
#endif

class ShaderInstance {
 public:
  virtual ~ShaderInstance() = default;
  virtual int varyingFloats() const = 0;
  virtual int colorOutputs() const = 0;
  // Whether its fragment shader reads textures: the pipeline then shades lane groups two
  // at a time (raster_tile.cpp), so one group's texel loads overlap the other's.
  virtual bool samplesTextures() const = 0;
  // Shades vertices [0, stream.vertexCount) of one instance into records
  // [recordBase, recordBase + vertexCount) of `out`.
  virtual void shadeVertices(const VertexStream& stream, int instance, int recordBase, const ViewportTransform& viewport,
                             ShadedVertices& out) const = 0;
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
#if RASTER_AVX2
  void shadeFragments(const FragmentInput<PairedLanes>& in, const PairedLanes* varyings,
                      FragmentOutput<PairedLanes>& out) const override {
    shade(in, varyings, out);
  }
#endif

 private:
  template <class F>
  void shade(const FragmentInput<F>& in, const F* varyings, FragmentOutput<F>& out) const {
    Program::fragment(uniforms_, in, varyingsFromArray<Program, F>(varyings), out);
  }
  typename Program::Uniforms uniforms_;
};

}  // namespace raster
