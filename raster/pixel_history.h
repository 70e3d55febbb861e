// Pixel history: the records the pipeline keeps, when asked, of everything that happened at
// one pixel of a pass (RenderDoc's "pixel history", from inside the pipeline).
//
// Renderer::setPixelHistory(&history) turns it on. From then, every pass (each beginPass)
// gets a PassHistory: what it draws into and which programs it runs. A pass with a probe
// (history.probes) also gets, in API order, every fragment that reached the probe pixel:
// its triangle, coverage, depth test, shader inputs and outputs, texture lookups and the
// pixel's value before and after it. The tile holding the probe pixel is walked by
// tile/trace_tile.cpp, in order and with ScalarLanes (the reference lane type, which gives
// the same bytes as every fast path), or, in a pass shaded at a coarse rate, by the coarse
// walk's own steps (tile/coarse_walk.h) with ScalarLanes; every other tile runs as always.
// So tracing changes no output, and the value a pass stores at the probe is the rendered pixel.
//
// Coordinates here are the pipeline's: column x and memory row y of the pass's attachments.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "raster/contract.h"
#include "raster/texture/sample_trace.h"

namespace raster {

// A pixel's value in every attachment of a framebuffer, decoded as the pipeline stores it
// (RGBA8 as unorm8 / 255, RGBA16F as the half's value), and its depth code.
struct PixelValue {
  std::vector<std::array<float, 4>> colors;   // one per colour attachment, in draw-buffer order
  bool hasDepth = false;
  uint32_t depthCode = 0;
};

// The pixel's values in `framebuffer` at column x, memory row y.
PixelValue readPixel(const Framebuffer& framebuffer, int x, int y);

// One fragment of the probe pixel: a lane at that pixel in a lane group of some triangle.
struct FragmentRecord {
  uint32_t draw = 0;              // the draw's index in its pass (PassHistory::programs)
  uint32_t instance = 0;          // gl_InstanceID
  uint32_t primitive = 0;         // the triangle's index in the draw's indices / 3
  bool clipped = false;           // the clipper cut the primitive: this is one piece of it
  bool frontFacing = true;
  // Screen-space weights of the set-up triangle's vertices at the pixel centre, from its edge
  // functions (fill-rule bias included), in the primitive's vertex order; of the clipped
  // piece's vertices where `clipped`.
  double barycentric[3] = {};
  bool covered = false;           // the pixel centre is inside (else a helper lane of its quad)
  bool depthTested = false;       // depth test on and a depth buffer bound
  bool depthPassed = true;        // the test's result (true when not tested)
  bool earlyDepth = true;         // tested before shading: every test of this pipeline is
  float z = 0.0f;                 // window z: the z plane plus polygon offset, at most 1
  uint32_t depthCode = 0;         // z clamped to [0, 1] and quantized, as compared and stored
  bool regionFill = false;        // depth-only draw, tested along rows (tile/depth_test.h
                                  // depthOnlyRegion), not in a quad: no lane was shaded
  bool shaded = false;            // the fragment shader ran on its lane
  bool helper = false;            // shaded, but not covered or failed its depth test: never written
  bool discarded = false;         // no port discards; kept so the record says so
  bool written = false;           // its colour outputs reached the attachments
  float fragCoord[4] = {};        // gl_FragCoord as the shader saw it
  std::vector<float> varyings;    // the interpolated inputs, flattened in declaration order
  std::vector<std::array<float, 4>> outputs;         // the colour outputs, per location
  std::vector<sampling::SampleRecord> samples;       // its texture lookups, in order
  // A pass shaded at a coarse rate (methods.h, `shading`; tile/coarse_tile.h): one
  // invocation per coarse pixel, interpolated at its centre (fragCoord above), its outputs
  // written to every pixel of the coarse pixel that is covered and passed the depth test.
  // coverage, z and the depth test above stay the probe pixel's own.
  int coarseWidth = 1, coarseHeight = 1;   // the pass's coarse pixel, in pixels; 1x1: not coarse
  int coarseX = 0, coarseY = 0;            // the probe's coarse pixel's first pixel (column, memory row)
  int lane = -1;                           // the invocation's lane in its coarse group (ScalarLanes)
  std::vector<std::array<int, 2>> broadcast;   // the pixels (column, memory row) its outputs were written to
  PixelValue before, after;       // the pixel just before and after this fragment
};

// One pass (a beginPass): what it draws into, and at its probe pixel what happened.
struct PassHistory {
  int pass = 0;                            // passes counted from setPixelHistory, from 0
  std::string label;                       // the scene's name for it (Backend::labelNextPass)
  std::vector<const Texture*> colors;      // the colour attachments
  const Texture* depth = nullptr;
  int width = 0, height = 0;
  bool flipY = false;                      // a window-system buffer: memory row 0 is the top
  ClearValues clear;
  bool keepsDenormals = false;             // its fragment stage kept denormals (simd/gl_math.h)
  std::vector<std::string> programs;       // each draw's program, in order
  bool probed = false;                     // the pass has a probe pixel inside its framebuffer
  int x = -1, y = -1;                      // the probe: column and memory row
  PixelValue afterClear;                   // the pixel after the pass's clear (the pass's start)
  std::vector<FragmentRecord> fragments;   // every fragment at the probe, in order
  PixelValue stored;                       // the pixel when the pass ends
};

struct PixelHistory {
  std::map<int, std::pair<int, int>> probes;   // pass -> (column, memory row) to trace
  std::vector<PassHistory> passes;             // every pass since the history was set
};

}  // namespace raster
