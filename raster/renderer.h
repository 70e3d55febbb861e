// The pipeline's front door: passes and draws in API order, executed as GL would. It
// sequences the stages and owns the threads; the stages themselves never see a thread.
//
//   beginPass(framebuffer, viewport, clear)   binds a framebuffer; its clear waits for flush
//   draw(shader, vertices, indices, state)    geometry now: vertex shading, primitive
//                                             assembly, clipping, setup and binning
//   flush()                                   every tile in parallel: its clear, then tile/
//                                             (coverage, early depth, shading) and merge/
//
// One draw's walk through the folders (ARCHITECTURE.md tells it at length):
//   geometry/vertex_stage -> geometry/assemble (clip, setup) -> geometry/bin
//   -> tile/rasterize_tile (coverage, early depth, interpolation, shading) -> merge/color_write
// Each tile is rasterized by one task, walking its triangles in API order, so the output
// does not depend on the thread count; a depth-only pass's heavy tile is walked in ranges of
// its triangles by several, whose least codes are the same (tile/depth_ranges.h).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "raster/contract.h"
#include "raster/geometry/bin.h"
#include "raster/geometry/setup.h"
#include "raster/pixel_history.h"
#include "raster/shader/shader_instance.h"
#include "raster/tile/depth_ranges.h"
#include "raster/util/parallel.h"
#include "raster/view_recorder.h"

namespace raster {

class Renderer {
 public:
  // threads = 0: every core. scalarOnly: shade with the plain-C++ lane type (every SIMD
  // fast path off); the output bytes are the same.
  explicit Renderer(int threads = 0, bool scalarOnly = false);
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
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
  // Records every pass flushed from now on for the stage views (view_recorder.h); null
  // (the default) records nothing. The output bytes are the same either way.
  void setViewRecorder(ViewRecorder* recorder) { viewRecorder_ = recorder; }
  // Pixel history (pixel_history.h): from the next beginPass on, every pass is recorded in
  // `history`, and a pass with a probe has every fragment at its probe pixel recorded too.
  // Null turns it off. The output bytes are the same either way.
  void setPixelHistory(PixelHistory* history) { history_ = history; }

 private:
  // One chunk of a draw set up in parallel: its window of the pass's lists (setup.h), whose
  // spill lists are kept so that no draw allocates them anew, and where its spilled
  // triangles went.
  struct SetupChunk {
    SetupWindow window;
    PipelineCounters counters;
    size_t spillAt = 0;
  };
  // Draws of fewer primitives than twice this are set up in one piece, and binned so.
  static constexpr size_t kSetupChunkPrimitives = 1024;
  // Vertex buffers of fewer vertices than twice this are shaded in one piece per instance.
  static constexpr int kVertexRange = 1024;

  bool visibilityFirst() const;
  void orderAlongHilbertCurve();
  void beginPassHistory();
  void shadeVertices(const ShaderInstance& shader, const VertexStream& vertices, int instanceCount);
  int setUpChunked(const SetupState& setup, std::span<const uint32_t> indices, int vertexCount, size_t primitives);
  void appendSpills(int chunks);
  void bin(uint32_t firstTriangle, int setupChunks);

  ThreadPool pool_;
  bool scalarOnly_;
  Framebuffer framebuffer_;
  ClearValues pendingClear_;   // the pass's glClear, carried out by the tiles at flush
  ViewportTransform viewport_{};
  std::vector<DrawRecord> draws_;
  TriangleList triangles_;
  PlaneList varyingPlanes_;
  std::vector<uint32_t> triangleOrigins_;   // beside triangles_, only while pixel history is on
  TileBins bins_;
  // flush()'s items: the pass's tiles, bands of them where the tiles are few, or ranges of
  // a heavy depth-only tile's triangles (tile/depth_ranges.h), and those ranges' copies.
  std::vector<TileWorkItem> workItems_;
  std::vector<size_t> binSizes_;   // each tile's bin size, the pass's, for cutHeavyTiles
  DepthRangeCopies depthCopies_;
  std::vector<TileBins> binParts_;   // a large draw's parts, binned in parallel, then appended to bins_
  ShadedVertices shaded_;   // the current draw's vertex records: kept, so no draw allocates them anew
  std::vector<SetupChunk> setupChunks_;
  PipelineCounters counters_;
  bool timeStages_ = false;
  bool visibilityFirstAllowed_ = true;
  // Whether a pass of this renderer has drawn into a half-float colour target with a
  // depth-tested colour draw: from then on its fragment stage keeps denormals, as llvmpipe's
  // threads do after such a pass's first block that fails its depth test (simd/gl_math.h).
  bool fragmentsKeepDenormals_ = false;
  ViewRecorder* viewRecorder_ = nullptr;
  PixelHistory* history_ = nullptr;
};

}  // namespace raster
