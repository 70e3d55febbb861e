// Rendering a soup (soup.h) through any Backend, and comparing two renderings exactly.
//
// Every pass draws with the test/passthrough program (clip position at location 0, the
// colour at location 1) into a W x H framebuffer of an RGBA8 and a Depth24 texture:
//   main       the finite triangles as one draw in soup order, each vertex in its
//              triangle's ID colour, depth test LESS with writes, on a clear of colour 0 and
//              depth 1.0: the colour names the visible triangle, the depth its depth code;
//   non-finite the triangles with a NaN or infinite coordinate, alone (GL leaves them
//              undefined: only that neither side crashes is required, and what each covered
//              is reported);
//   counting   each closed mesh alone, colour (1/255, 0, 0, 0) with ONE/ONE blending and no
//              depth test: red is the number of fragments a pixel got.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "scenes/program_registry.h"
#include "scenes/soup/soup.h"

namespace scenes::soup {

// The programs soups draw with (test/passthrough), for the registry's programs outside
// every scene (scenes/registry.cpp).
std::vector<ProgramEntry> programs();

struct Rendering {
  std::string backend;
  ImageData color, depth;           // main pass
  int nonFiniteCovered = 0;         // pixels the non-finite pass left other than the clear
  std::vector<ImageData> counts;    // one per closed mesh, in soup order
};

// Draws a soup's passes on one backend. The framebuffer and program are made once for a
// size; backends cannot free meshes, so a long run makes a fresh backend now and then.
class SoupRenderer {
 public:
  SoupRenderer(Backend& backend, int width, int height);
  Rendering render(const Soup& soup);
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Backend& backend_;
  int width_, height_;
  Handle framebuffer_ = 0, program_ = 0;
  void pass(const std::vector<float>& vertices, const DrawState& state);
};

// Whether a closed mesh's count image is what a watertight rasterizer gives: every pixel
// whose centre lies inside the outline (by more than a margin for rounding) counted once,
// every pixel outside (by the margin) not at all, those within the margin at most once.
struct MeshCheck {
  int inside = 0;        // pixels whose centre is inside by the margin
  int cracks = 0;        // inside, counted 0 times
  int doubleHits = 0;    // counted 2 or more times, anywhere
  int strays = 0;        // outside by the margin, counted
  std::string first;     // the first failing pixel, described
  bool watertight() const { return cracks == 0 && doubleHits == 0 && strays == 0; }
};
MeshCheck checkWatertight(const ClosedMesh& mesh, const ImageData& counts, int width, int height);

// Ours against the reference, pixel for pixel.
struct Verdict {
  int finiteTriangles = 0, nonFiniteTriangles = 0;
  int covered = 0;                     // main-pass pixels the reference covered
  int colorDiffs = 0, depthDiffs = 0;  // main pass: pixels whose ID colour / depth code differ
  int countDiffs = 0;                  // counting passes: pixels whose count differs
  int countedPixels = 0;               // counting passes: pixels the reference counted
  int nonFiniteCoveredOurs = 0, nonFiniteCoveredReference = 0;
  std::vector<MeshCheck> ours, reference;   // per closed mesh
  std::vector<std::string> firstDiffs;      // the first few differing pixels, described

  bool identical() const { return colorDiffs == 0 && depthDiffs == 0 && countDiffs == 0; }
  bool oursWatertight() const;
  bool referenceWatertight() const;
};
Verdict compare(const Soup& soup, const Rendering& ours, const Rendering& reference);

// "triangle 17 (sliver)", "nothing" or "colour 1,2,3,4" for a main-pass pixel's bytes.
std::string describeId(const Soup& soup, const uint8_t rgba[4]);

// The soup with every finite triangle moved one pixel right: what `raster soup
// --inject-difference` draws on this pipeline's side, to show the check can fail.
Soup shiftedOnePixel(const Soup& soup);

}  // namespace scenes::soup
