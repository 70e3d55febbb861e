// The pipeline's front door: passes and draws in API order, executed as GL would.
//
//   beginPass(framebuffer, viewport, clear)   binds a framebuffer and clears it
//   draw(shader, vertices, indices, state)    vertex shading, clipping, setup and binning
//                                             now; rasterization when the pass is flushed
//   flush()                                   rasterizes every binned tile in parallel
//
// Flow of one draw (folders under raster/pipeline):
//   fetch + vertex shading (vertex_stage) -> clip (clip) -> setup (setup) -> bin (here)
//   -> per tile: coverage, early depth, quad shading, output merge (raster_tile)
// Tiles are 64x64 pixels and each is rasterized by one task, walking its triangles in API
// order, so the output does not depend on the thread count.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "raster/texture/texture.h"
#include "raster/geometry/setup.h"
#include "raster/shader/shader_instance.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/util/parallel.h"

namespace raster {

// A framebuffer: colour attachments (draw buffers in order) and an optional depth buffer.
// flipY marks a window-system buffer, stored top row first as llvmpipe stores them: its
// viewport transform is mirrored and its fill rule is bottom-left in memory rows.
struct Framebuffer {
  std::vector<Texture*> colors;
  Texture* depth = nullptr;
  int width = 0;
  int height = 0;
  bool flipY = false;
};

struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;   // GL window coordinates (y up)
};

struct ClearValues {
  bool color = false;
  float colorValue[4] = {0, 0, 0, 0};
  bool depth = false;
  float depthValue = 1.0f;
};

enum class DepthFunc { Less, Lequal };

struct RasterState {
  bool depthTest = true;
  DepthFunc depthFunc = DepthFunc::Less;
  bool depthWrite = true;
  bool cullBack = false;
  bool polygonOffset = false;
  float offsetFactor = 0.0f;
  float offsetUnits = 0.0f;
  bool blendAdditive = false;
};

// A draw as the rasterizer needs it after binning.
struct RecordedDraw {
  std::unique_ptr<ShaderInstance> shader;
  RasterState state;
  // The shader's answers, asked once per draw rather than once per lane group.
  bool samplesTextures = false;   // shader->samplesTextures()
  int varyingFloats = 0;          // shader->varyingFloats()
  int colorOutputs = 0;           // shader->colorOutputs()
};

// The colour outputs a draw writes to a framebuffer: those both its shader and the
// framebuffer have (0: a depth-only draw).
inline int colorOutputsWritten(const RecordedDraw& draw, const Framebuffer& framebuffer) {
  return std::min(draw.colorOutputs, int(framebuffer.colors.size()));
}

// What happened in the pipeline since the counters were last reset.
struct PipelineCounters {
  uint64_t trianglesIn = 0;        // primitives assembled from indices
  uint64_t trianglesClipped = 0;   // that needed the clipper
  uint64_t trianglesRejected = 0;  // trivially outside one plane
  uint64_t trianglesSetUp = 0;     // that reached the rasterizer (after culling)
  uint64_t tileBinEntries = 0;     // (triangle, tile) pairs binned
  uint64_t laneGroupsShaded = 0;   // fragment-shader invocations (lane groups)
  uint64_t lanesShaded = 0;        // lanes in those groups (pixels + helpers)
  uint64_t lanesCovered = 0;       // shaded lanes that passed coverage and depth (the rest are helpers)
  // Time-stamp-counter cycles per stage. Vertex shading, clip + setup and binning are
  // timed on the calling thread, as wall time (each runs in parallel where the draw is
  // large enough); the tile stages are summed over every thread: raster = coverage, depth
  // and interpolation; shade = the fragment shader; merge = colour conversion and writes.
  uint64_t vertexCycles = 0, setupCycles = 0, binCycles = 0;
  uint64_t rasterCycles = 0, shadeCycles = 0, mergeCycles = 0;
  PipelineCounters& operator+=(const PipelineCounters& o);
};

class Renderer {
 public:
  // threads = 0: every core. scalarOnly: shade with the plain-C++ lane type (every SIMD
  // fast path off); the output bytes are the same.
  explicit Renderer(int threads = 0, bool scalarOnly = false);
  ~Renderer();

  void beginPass(const Framebuffer& framebuffer, const Viewport& viewport, const ClearValues& clear);
  void draw(std::unique_ptr<ShaderInstance> shader, const VertexStream& vertices, std::span<const uint32_t> indices,
            const RasterState& state, int instanceCount = 1);
  void flush();

  const PipelineCounters& counters() const { return counters_; }
  // Per-stage cycle counts cost a few percent (the counter is read around every lane
  // group), so they are taken only when asked for.
  void setStageTiming(bool on) { timeStages_ = on; }
  void resetCounters() { counters_ = {}; }
  // Passes whose colour draws do not blend find each pixel's visible fragment before
  // shading (TileJob::visibilityFirst); off, every fragment that passes its depth test is
  // shaded in order. The output bytes are the same either way.
  void setVisibilityFirst(bool allowed) { visibilityFirstAllowed_ = allowed; }
  int threads() const { return pool_.threads(); }

 private:
  // A draw's primitives, as assemble() reads them.
  struct AssemblyInput {
    const SetupState& setup;
    const ShadedVertices& shaded;
    std::span<const uint32_t> indices;
    int vertexCount;
    uint32_t drawIndex;
  };
  // Where assemble() appends its triangles and planes, and counts what it saw.
  struct SetupOutput {
    std::vector<SetupTriangle>& triangles;
    std::vector<Plane>& varyingPlanes;
    PipelineCounters& counters;
  };
  // One chunk of a draw set up in parallel: its own lists, kept so no draw allocates them anew.
  struct SetupChunk {
    std::vector<SetupTriangle> triangles;
    std::vector<Plane> varyingPlanes;
    PipelineCounters counters;
    size_t triangleAt = 0, planeAt = 0;   // where its lists land in the pass's
  };
  // Draws of fewer primitives than twice this are set up in one piece, and binned so.
  static constexpr size_t kSetupChunkPrimitives = 1024;

  void clearRect(int x0, int y0, int x1, int y1, bool colorToo) const;   // colorToo: its colour clear too, if any
  bool visibilityFirst() const;
  void assemble(const AssemblyInput& in, size_t first, size_t end, SetupOutput out) const;
  void appendChunks(int chunks);
  void bin(uint32_t firstTriangle);

  ThreadPool pool_;
  bool scalarOnly_;
  Framebuffer framebuffer_;
  ClearValues pendingClear_;   // the pass's glClear, carried out by the tiles at flush
  ViewportTransform viewport_{};
  std::vector<RecordedDraw> draws_;
  std::vector<SetupTriangle> triangles_;
  std::vector<Plane> varyingPlanes_;
  std::vector<std::vector<uint32_t>> bins_;   // per tile: triangle indices in API order
  ShadedVertices shaded_;   // the current draw's vertex records: kept, so no draw allocates them anew
  std::vector<SetupChunk> setupChunks_;
  int tilesX_ = 0, tilesY_ = 0;
  PipelineCounters counters_;
  bool timeStages_ = false;
  bool visibilityFirstAllowed_ = true;
};

}  // namespace raster
