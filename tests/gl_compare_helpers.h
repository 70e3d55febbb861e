// Shared machinery of the tests that compare this pipeline with real GL (llvmpipe):
// building clip-space meshes from window coordinates, rendering the same draws with both
// backends into framebuffer objects (or the default framebuffer), and comparing the
// read-back images pixel by pixel (coverage, depth codes, RGBA8 steps, exact float bits).
//
// Images are read back top row first by both backends (backends/backend.h), so pixel
// (x, row) of one is pixel (x, row) of the other; "window y" below is GL's (y up),
// row = height - 1 - y.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "backends/backends.h"
#include "tests/float_bits.h"

namespace gltest {

using scenes::Backend;
using scenes::ClearOp;
using scenes::DrawState;
using scenes::Handle;
using scenes::ImageData;
using scenes::MeshData;
using scenes::TexelFormat;
using scenes::UniformValue;

// ---- meshes ---------------------------------------------------------------------------
// One vertex of the test programs: clip position at location 0, a vec4 at location 1.
struct Vertex {
  glm::vec4 position;
  glm::vec4 attribute;
};

// A mesh of Vertex records; empty `indices` means consecutive triangles (0 1 2, 3 4 5, ...).
MeshData makeMesh(const std::vector<Vertex>& vertices, std::vector<uint32_t> indices = {});

// Clip coordinates of a window position (GL window coordinates, y up, viewport = the whole
// width x height target) at NDC depth ndcZ, scaled by w: clip = (ndc * w, w).
glm::vec4 clipFromWindow(glm::vec2 window, float ndcZ, float w, int width, int height);

// Per cell of a grid of screen-aligned squares: the constant attribute and NDC depth.
struct GridCell {
  glm::vec4 attribute{0.0f};
  float ndcZ = 0.0f;
};
// Squares of cell x cell pixels tiling a width x height target (w = 1, two triangles each,
// own vertices, so attributes are constant and interpolate exactly). The callback gets the
// cell's column and its row counted from the top (read-back order).
MeshData gridMesh(int width, int height, int cell, const std::function<GridCell(int column, int rowFromTop)>& at);

// A window position clamped into the width x height viewport.
glm::vec2 clampToTarget(glm::vec2 p, int width, int height);

// The fullscreen triangle (-1,-1), (3,-1), (-1,3) in NDC, each vertex scaled by a random w
// (perspective) or 1, at random depths, with random opaque colours.
MeshData fullscreenTriangle(std::mt19937& rng, bool perspective);

// ---- rendering ----------------------------------------------------------------------------
struct TargetDesc {
  int width = 64;
  int height = 64;
  std::optional<TexelFormat> color = TexelFormat::RGBA8;   // nullopt: depth-only FBO
  std::optional<TexelFormat> depth = TexelFormat::Depth24;  // nullopt: no depth buffer
  bool defaultFramebuffer = false;  // handle 0 (RGBA8 + Depth24, window-system orientation)
};

// "160x144 Depth24", "64x64 default framebuffer": for messages.
std::string targetName(const TargetDesc& t);

struct DrawCall {
  std::string program = "test/passthrough";
  MeshData mesh;
  DrawState state;
  std::vector<std::pair<std::string, UniformValue>> uniforms;
};

struct Rendered {
  std::optional<ImageData> color;
  std::optional<ImageData> depth;
};

// Creates the target on `backend`, clears it, runs the draws in order, reads back.
Rendered render(Backend& backend, const TargetDesc& target, const std::vector<DrawCall>& draws, const ClearOp& clear);

// This pipeline and GL side by side for one test case (one GL backend at a time per process).
struct BackendPair {
  std::unique_ptr<Backend> raster;
  std::unique_ptr<Backend> gl;
  BackendPair();
};

struct BothRendered {
  Rendered raster;
  Rendered gl;
};
BothRendered renderBoth(BackendPair& backends, const TargetDesc& target, const std::vector<DrawCall>& draws,
                        const ClearOp& clear);

// Clear to colour (0, 0, 0, 0) and depth 1.0.
ClearOp clearAll();

// ---- comparison ---------------------------------------------------------------------------
// RGBA8 images of the same size. A pixel is covered when any byte differs from `clear`.
struct Rgba8Comparison {
  int coveredA = 0, coveredB = 0;   // covered pixels in each image
  int coverageDiffs = 0;            // pixels covered in exactly one image
  int colorDiffs = 0;               // pixels covered in both whose bytes differ
  int maxStep = 0;                  // largest byte difference on pixels covered in both
  std::string firstCoverageDiff;    // "pixel (x, row): raster r,g,b,a vs gl r,g,b,a"
  std::string firstColorDiff;
};
Rgba8Comparison compareRgba8(const ImageData& raster, const ImageData& gl, const uint8_t clear[4]);

// Depth codes of images of the same size and depth bits.
struct DepthComparison {
  int diffs = 0;
  uint32_t maxDiff = 0;
  std::string firstDiff;
};
DepthComparison compareDepth(const ImageData& raster, const ImageData& gl);

// Float images (RGBA16F read back as floats): exact bit patterns.
struct FloatComparison {
  int diffs = 0;                    // pixels with any channel's bits different
  std::string firstDiff;
};
FloatComparison compareFloatBits(const ImageData& raster, const ImageData& gl);

std::string describeRgba8(const ImageData& image, int x, int row);
std::string describeFloats(const ImageData& image, int x, int row);

using testing_support::bitsOf;

// Uniform float in [lo, hi) from a fixed-seed generator.
float uniform(std::mt19937& rng, float lo, float hi);

// A random colour with alpha 1.
glm::vec4 randomOpaqueColor(std::mt19937& rng);

}  // namespace gltest
