// A shader port bound to the pipeline: ProgramInstance<Program> is a port plus a snapshot of
// its uniforms, implementing the ShaderInstance interface the stages call. It sits above the
// stages because it instantiates the geometry stage's vertex loop and the fragment entry
// points for each lane type with the port's own code.
#pragma once

#include <algorithm>
#include <type_traits>

#include "raster/geometry/vertex_stage.h"
#include "raster/shader/program.h"
#include "raster/shader/shader_instance.h"
#include "raster/shader/texel_planes.h"
#include "raster/tile/covered_tile.h"

// ProgramInstance::shadeTileWhole's inlining (below), for speed alone.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define RASTER_FLATTEN_TILE_LOOP
#else
#define RASTER_FLATTEN_TILE_LOOP [[gnu::flatten]]
#endif

namespace raster {

template <class Program>
class ProgramInstance final : public ShaderInstance {
 public:
  // A port may compute values that depend on its uniforms alone once a draw, into members
  // of its Uniforms that no uniform() names (Program::deriveUniforms), rather than in every
  // lane group: under the frame's method set, as the draw is made inside the frame.
  explicit ProgramInstance(const typename Program::Uniforms& uniforms) : uniforms_(uniforms) {
    if constexpr (requires { Program::deriveUniforms(uniforms_); }) Program::deriveUniforms(uniforms_);
  }

  const char* name() const override { return Program::kName; }
  int varyingFloats() const override { return varyingFloatCount<Program>(); }
  int colorOutputs() const override { return Program::kColorOutputs; }
  bool samplesTextures() const override { return raster::samplesTextures<Program>(); }
  bool lanesIndependent() const override { return raster::lanesIndependent<Program>(); }
  bool samplesAroundPixel() const override { return raster::samplesAroundPixel<Program>(); }
  void appendSampledTextures(std::vector<const Texture*>& out) const override {
    std::apply([&](auto... entry) { (appendSampled(entry, out), ...); }, Program::kUniformTable);
  }

  size_t makeTexelPlanes(ThreadPool& pool, const Framebuffer& target, bool scalarLanes) override {
    if constexpr (hasTexelPlanes<Program>()) {
      TexelPlaneMaker<typename Program::Uniforms> make(uniforms_, pool, target, scalarLanes);
      Program::texelPlanes(make);
      return make.texelsMade();
    }
    return 0;
  }

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
  // Flattened: GCC inlines the port's fragment shader into this loop where it can (hdr's bright,
  // down and up passes; the composite, SSAO, lighting and blur shaders stay calls), so a block's
  // varyings and colours stay in registers: hdr's last upsample 0.394 -> 0.341 ms at 640x480,
  // 2 threads (docs/notes/2026-12-05-varying-count-and-twice-resolution.md). Not in the
  // sanitizer builds, which check the same code: flattened, they took CI 2.7 minutes longer.
  RASTER_FLATTEN_TILE_LOOP
  void shadeTileWhole(const TileJob& job, const TileBounds& tile, const SetupTriangle& tri,
                      const LaneLayout<FastLanes>& layout, bool onlyTriangle, PipelineCounters& counters) const override {
    shadeTileWholeWith<varyingFloatCount<Program>()>(
        job, tile, tri, layout, onlyTriangle, counters,
        [this](const FragmentInput<PairedLanes>& in, const PairedLanes* varyings, FragmentOutput<PairedLanes>& out)
            __attribute__((always_inline)) { shade(in, varyings, out); });
  }
#endif

 private:
  template <class F>
  void shadeVerticesWith(const VertexBatch& batch, ShadedVertices& out) const {
    int first = batch.firstVertex;
#if RASTER_ZMM_PAIRS
    // Sixteen vertices to a group where more than eight are left, in one 512-bit register
    // each: a group's per-vertex work is then half the instructions a vertex. (Per lane the
    // operations are Float8's, so every record is the same.)
    if constexpr (std::is_same_v<F, FastLanes>)
      for (; batch.endVertex - first > F::kCount; first += PairedLanes::kCount)
        vertex_stage::shadeVertexGroup<Program, PairedLanes>(uniforms_, batch, first,
                                                             std::min(batch.endVertex - first, PairedLanes::kCount), out);
#endif
    for (; first < batch.endVertex; first += F::kCount) {
      const int count = batch.endVertex - first < F::kCount ? batch.endVertex - first : F::kCount;
      vertex_stage::shadeVertexGroup<Program, F>(uniforms_, batch, first, count, out);
    }
  }
  template <class Entry>
  void appendSampled(Entry entry, std::vector<const Texture*>& out) const {
    if constexpr (IsSamplerEntry<Entry>::value)
      if (const Texture* texture = (uniforms_.*entry.member).texture) out.push_back(texture);
  }
  template <class F>
  [[gnu::always_inline]] void shade(const FragmentInput<F>& in, const F* varyings, FragmentOutput<F>& out) const {
    Program::fragment(uniforms_, in, varyingsFromArray<Program, F>(varyings), out);
  }
  typename Program::Uniforms uniforms_;
};

}  // namespace raster

#undef RASTER_FLATTEN_TILE_LOOP
