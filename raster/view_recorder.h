// What the stage views (`raster render --view`, apps/views/stage_views.h) record of each
// pass of a frame. A Renderer given a ViewRecorder (Renderer::setViewRecorder) hands it
// every pass it flushes; without one (the normal case) the renderer records nothing and its
// tile loop is the one it always runs.
//
// Three kinds of record, one per recorder, so a view pays only for what it shows (each
// view's record in apps/views/stage_views.cpp names the kind it needs):
//   Fragments  each tile runs through the instrumented in-order walk (tile/inspect_tile.h):
//              per-pixel fragments, depth rejects and helper lanes, with GL's semantics;
//   TileTimes  each tile runs this pipeline's own path (fast paths included), timed;
//   Triangles  each tile runs this pipeline's own path; the pass's set-up triangles
//              (after clipping and culling) are kept as three vertices each.
// Every kind also times its tiles (the fragment walk's times measure that walk, not the
// pipeline) and sums the pass's tile-stage counters.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "raster/contract.h"
#include "raster/tile/inspect_tile.h"

namespace raster {

// A set-up triangle as a wireframe: its corners in pixel coordinates of the framebuffer's
// memory rows (pixel (x, y) spans [x, x + 1) x [y, y + 1)).
struct ViewTriangle {
  float x[3], y[3];
  uint32_t drawIndex;
};

struct ViewPass {
  int index = 0;   // in the order the frame flushed its passes, from 0
  std::string label;   // the scene's name for the pass (Backend::labelNextPass), "" if none
  int width = 0, height = 0;
  bool window = false;   // the window-system framebuffer (stored top row first: flipY)
  int colorTargets = 0;
  bool depth = false;
  std::vector<std::string> drawPrograms;   // each draw's program (ShaderInstance::name)
  uint64_t triangles = 0;                  // set up (after clipping and culling)
  int tilesX = 0, tilesY = 0;
  std::vector<uint64_t> tileCycles;        // per tile (tileY * tilesX + tileX): its clear and tile stage
  std::vector<uint32_t> tileTriangles;     // per tile: the triangles in its bin
  bool depthRanges = false;                // its heavy tiles may be walked in triangle ranges (depth_ranges.h)
  FragmentCounts counts;                   // Fragments only
  std::vector<ViewTriangle> triangleList;  // Triangles only
  PipelineCounters counters;               // the pass's tile stage (lane groups, lanes)
};

class ViewRecorder {
 public:
  enum class Record { Fragments, TileTimes, Triangles };
  explicit ViewRecorder(Record what) : what_(what) {}

  Record what() const { return what_; }
  // Called with the bytes a pass's record will hold (per-pixel counts, tile times, the
  // triangle list) before they are allocated, so that the caller can charge them to its
  // memory cap; an exception it throws aborts the pass before anything is allocated.
  using Reserve = std::function<void(uint64_t bytes, const std::string& what)>;
  void setReserve(Reserve reserve) { reserve_ = std::move(reserve); }
  // The scene's label of the pass now beginning (called by the backend after
  // Renderer::beginPass), given to the record made when that pass is flushed.
  void labelNextPass(std::string label) { pendingLabel_ = std::move(label); }

  // Renderer::flush: a pass begins (its triangles, draws and framebuffer are in `job`);
  // the tiles then fill the returned record, each only its own pixels and tile entry.
  ViewPass& beginPass(const TileJob& job, int tilesX, int tilesY);
  // Renderer::flush: every tile is done; `tileCounters` is the pass's tile-stage work.
  void endPass(const PipelineCounters& tileCounters);

  const std::vector<ViewPass>& passes() const { return passes_; }

 private:
  Record what_;
  Reserve reserve_;
  std::string pendingLabel_;
  std::vector<ViewPass> passes_;
};

}  // namespace raster
