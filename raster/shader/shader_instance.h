// How the pipeline's stages call a draw's program: a small virtual interface, so the stages
// need not be templates on every shader port. The pipeline calls it once per lane group,
// never per pixel. ProgramInstance (raster/program_instance.h) implements it for a port.
#pragma once

#include <memory>
#include <vector>

#include "raster/contract.h"
#include "raster/shader/program.h"
#include "raster/util/parallel.h"

namespace raster {

template <class F>
struct LaneLayout;   // simd/lane_layout.h

class ShaderInstance {
 public:
  virtual ~ShaderInstance() = default;
  // The program's name, as the scene created it: "shadow/main" (pixel history shows it).
  virtual const char* name() const = 0;
  virtual int varyingFloats() const = 0;
  virtual int colorOutputs() const = 0;
  // Whether its fragment shader reads textures: the pipeline then shades lane groups two
  // at a time (tile/group_shader_avx2.h), so one group's texel loads overlap the other's.
  virtual bool samplesTextures() const = 0;
  // Whether its lanes are independent (raster::lanesIndependent, shader/program.h).
  virtual bool lanesIndependent() const = 0;
  // Whether it samples around its pixel (raster::samplesAroundPixel, shader/program.h).
  virtual bool samplesAroundPixel() const = 0;
  // Appends the textures its sampler uniforms are bound to for this draw (none unbound).
  virtual void appendSampledTextures(std::vector<const Texture*>& out) const = 0;
  // Makes the program's texel planes for this draw (shader/texel_planes.h), if it declares
  // any, on `pool`'s threads: before any of its fragments is shaded, while `target` is the
  // pass's framebuffer. With `scalarLanes` in the plain-C++ lanes (the same bits either way).
  // Returns the texels made.
  virtual size_t makeTexelPlanes(ThreadPool& pool, const Framebuffer& target, bool scalarLanes) = 0;
  // Shades a batch of one instance's vertices into their records of `out`, with the
  // plain-C++ lanes when `scalarLanes` (the same bits either way).
  virtual void shadeVertices(const VertexBatch& batch, ShadedVertices& out, bool scalarLanes) const = 0;
  // Shades one lane group; `varyings` holds varyingFloats() interpolated values.
  virtual void shadeFragments(const FragmentInput<FastLanes>& in, const FastLanes* varyings,
                              FragmentOutput<FastLanes>& out) const = 0;
  virtual void shadeFragments(const FragmentInput<ScalarLanes>& in, const ScalarLanes* varyings,
                              FragmentOutput<ScalarLanes>& out) const = 0;
#if RASTER_AVX2
  virtual void shadeFragments(const FragmentInput<PairedLanes>& in, const PairedLanes* varyings,
                              FragmentOutput<PairedLanes>& out) const = 0;
  // Shades and merges a tile that `tri` covers whole, every fragment passing its depth test
  // (tile/covered_tile.h, shadeTileWhole): the covered-tile loop instantiated for this
  // program, calling its fragment shader directly: one virtual call a tile, not one a block.
  virtual void shadeTileWhole(const TileJob& job, const TileBounds& tile, const SetupTriangle& tri,
                              const LaneLayout<FastLanes>& layout, bool onlyTriangle,
                              PipelineCounters& counters) const = 0;
#endif
};

}  // namespace raster
