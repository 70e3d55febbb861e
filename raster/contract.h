// The records that flow between the pipeline's stages, in the order data flows:
//
//   VertexStream ──geometry/vertex_stage──> ShadedVertices ──geometry/clip, setup──> SetupTriangle
//   SetupTriangle ──geometry/bin──> per-tile bins ──renderer──> TileJob (one pass's work)
//   TileJob ──tile/──> FragmentGroup (lanes that passed their depth test, ready to shade)
//   FragmentGroup ──shader──> FragmentOutput ──merge/──> texels of the Framebuffer
//
// Each record is a plain value type with named fields; stages own none of them and keep no
// pointers into another stage's storage beyond one pass. The limits they are sized by are in
// limits.h, with their reasons. See ARCHITECTURE.md for who produces and consumes each.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "raster/limits.h"
#include "raster/simd/glsl.h"
#include "raster/texture/texture.h"
#include "raster/util/default_init.h"

namespace raster {

class ShaderInstance;   // shader/shader_instance.h: a program and its uniforms

// ---- pass state (the renderer's inputs) ----------------------------------------------------

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

// The fixed-function state of a draw.
struct RasterState {
  bool depthTest = true;
  DepthFunc depthFunc = DepthFunc::Less;
  bool depthWrite = true;
  bool cullBack = false;      // GL_CULL_FACE with GL_BACK, front = counter-clockwise
  bool polygonOffset = false;
  float offsetFactor = 0.0f;
  float offsetUnits = 0.0f;
  bool blendAdditive = false;  // glBlendFunc(GL_ONE, GL_ONE)
};

// ---- vertices (scene -> geometry) ------------------------------------------------------------

struct AttributeLayout {
  int location = 0;
  int components = 3;
  int offsetFloats = 0;
};

// Interleaved float vertices, and optionally a per-instance stream (divisor 1).
struct VertexStream {
  const float* vertices = nullptr;
  int strideFloats = 0;
  int vertexCount = 0;
  std::vector<AttributeLayout> attributes;
  const float* instances = nullptr;   // may be null
  int instanceStrideFloats = 0;
  std::vector<AttributeLayout> instanceAttributes;
};

// GL's viewport mapping, with llvmpipe's orientation for window-system buffers folded in.
struct ViewportTransform {
  float scale[3];
  float translate[3];
};

// Vertices [firstVertex, endVertex) of one instance to shade, vertex v into record
// recordBase + v.
struct VertexBatch {
  const VertexStream& stream;
  const ViewportTransform& viewport;
  int instance;
  int recordBase;
  int firstVertex, endVertex;
};

// ---- shaded vertices (vertex stage -> clip and setup) ----------------------------------------

// Where each quantity sits in a shaded vertex record:
//   [0..3]  clip-space position (x, y, z, w) from gl_Position
//   [4..7]  window position (x, y, z, 1/w), llvmpipe's viewport transform
//   [8..]   the program's varyings (varyingFloats of them)
namespace vertex_record {
constexpr int kClip = 0;
constexpr int kWindow = 4;
constexpr int kVaryings = 8;
}  // namespace vertex_record

// One record per (instance, vertex), instance-major, and a 6-bit clip mask per record.
struct ShadedVertices {
  int varyingFloats = 0;
  int stride = 0;   // vertex_record::kVaryings + varyingFloats
  std::vector<float> data;
  std::vector<uint8_t> clipMask;

  int count() const { return int(clipMask.size()); }
  const float* record(int i) const { return data.data() + size_t(i) * size_t(stride); }
  float* record(int i) { return data.data() + size_t(i) * size_t(stride); }
};

// ---- set-up triangles (setup -> bin -> tile) ---------------------------------------------------

// An edge function in sub-pixel fixed point, referenced to pixel (0, 0)'s centre. A pixel
// centre (px, py) is on the inside when at(px, py) > 0 (the fill rule is folded into c).
struct EdgeFunction {
  int64_t c;      // value at pixel (0, 0), fill-rule bias included
  int64_t dcdx;   // step per pixel in x (already scaled by kSubPixelOne), subtracted
  int64_t dcdy;   // step per pixel in y (already scaled by kSubPixelOne), added
  int64_t at(int px, int py) const { return c - dcdx * px + dcdy * py; }
};

// An interpolated quantity: a(px, py) = fma(dady, py, fma(dadx, px, a0)) at pixel centres.
struct Plane {
  float a0, dadx, dady;
};

// A triangle ready for rasterization. Its varying planes live in the pass's plane list.
struct SetupTriangle {
  EdgeFunction edge[3];
  int minX, minY, maxX, maxY;   // inclusive pixel bounds, already inside the framebuffer
  Plane z;                      // window z
  Plane w;                      // 1/w (the position's fourth component)
  float depthOffset;            // polygon offset, added after interpolation
  uint32_t varyingBase;         // index of the first varying Plane in the pass's list
  uint32_t drawIndex;           // which draw of the pass
  bool frontFacing;
};

// A pass's set-up triangles and their varying planes: lists that grow without zeroing
// (util/default_init.h), since the renderer sizes them before its setup chunks write them.
using TriangleList = GrowableList<SetupTriangle>;
using PlaneList = GrowableList<Plane>;

// Where a set-up triangle came from, kept only for pixel history (the renderer's list runs
// beside its triangles): the primitive, instance-major (instance * primitives per
// instance + primitive), with kClippedOrigin set when the clipper cut it into pieces.
constexpr uint32_t kClippedOrigin = 0x80000000u;

// ---- draws and tile work (renderer -> tile) ------------------------------------------------------

// A draw as the tiles need it after binning.
struct DrawRecord {
  std::shared_ptr<const ShaderInstance> shader;
  RasterState state;
  // The shader's answers, asked once per draw rather than once per lane group.
  bool samplesTextures = false;   // shader->samplesTextures()
  int varyingFloats = 0;          // shader->varyingFloats()
  int colorOutputs = 0;           // shader->colorOutputs()
  uint32_t primitivesPerInstance = 0;   // the indices' triangles: SetupTriangle::primitive / this = instance
  bool lanesIndependent = false;        // shader->lanesIndependent()
  bool samplesAroundPixel = false;      // shader->samplesAroundPixel()
};

// The colour outputs a draw writes to a framebuffer: those both its shader and the
// framebuffer have (0: a depth-only draw).
inline int colorOutputsWritten(const DrawRecord& draw, const Framebuffer& framebuffer) {
  return std::min(draw.colorOutputs, int(framebuffer.colors.size()));
}

// One pass's work, as every tile reads it: the set-up triangles, their varying planes and
// draws, and the framebuffer. Each tile also gets its bin: the indices of the triangles
// that touch it, in API order.
struct TileJob {
  const Framebuffer* framebuffer = nullptr;
  std::span<const SetupTriangle> triangles;
  std::span<const Plane> varyingPlanes;
  std::span<const DrawRecord> draws;
  bool timeStages = false;   // read the cycle counter around each stage (raster bench)
  // No colour draw of the pass blends: tiles find each pixel's visible fragment first and
  // shade only those (tile/visible_first.h).
  bool visibilityFirst = false;
  // Tiles no triangle reaches are cleared with streaming stores (merge/clear_avx2.h): where
  // the pass's targets outgrow the threads' own caches, so that what is stored would leave
  // the cache before anything reads it again.
  bool streamUntouchedClears = false;
  // The pass's coarse pixel in pixels (methods.h, `shading`; passShadingRate, shading_rate.h):
  // 1x1 is GL's one shader invocation per pixel, anything larger is walked by
  // tile/coarse_tile.h. Each side divides a 16-row band and a tile.
  int coarseWidth = 1, coarseHeight = 1;
  // Bit k: the framebuffer's colour attachment k is RGBA8 (FragmentOutput::unorm8Outputs).
  unsigned unorm8Outputs = 0;
};

// A tile's pixel rectangle, inclusive, clipped to the framebuffer.
struct TileBounds {
  int x0, y0, x1, y1;
};

// ---- fragments (tile -> shader -> merge) -------------------------------------------------------

template <class F>
struct VertexInput {
  glsl::vec4<F> attribute[limits::kMaxVertexAttributes];   // missing components read (0, 0, 0, 1)
  F gl_InstanceID;                                         // as float lanes: exact for any count used
};

template <class F>
struct FragmentInput {
  glsl::vec4<F> gl_FragCoord;   // (x + 0.5, y + 0.5, z, 1/w) in window coordinates
  bool gl_FrontFacing = true;
};

template <class F>
struct FragmentOutput {
  glsl::vec4<F> color[limits::kMaxColorOutputs];
  // Bit k: colour output k goes to an RGBA8 target, which keeps only each channel's unorm8
  // byte (merge/color_write.h, blended or not), so a port may hand it any value that
  // provably converts to the same byte (merge/unorm8_within.h; docs/porting.md, section 5).
  // 0 where the floats themselves are kept or recorded: float targets, pixel history's traced
  // fragments.
  unsigned unorm8Outputs = 0;
  bool keepsUnorm8Only(int k) const { return (unorm8Outputs >> k & 1u) != 0; }
};

// A lane group that passed its depth test: everything its shader call and its output merge
// need. Lanes outside laneMask are helpers (shaded so dFdx / dFdy see whole quads, never
// written). A group is prepared (its triangle, pixel centres and depth) and interpolated
// (its inputs and varyings) in two steps, so that the in-order walk can leave the second to
// the group shader, which interpolates two groups of one triangle in one operation
// (tile/interpolate.h, group_shader_avx2.h).
template <class F>
struct FragmentGroup {
  const DrawRecord* draw = nullptr;
  unsigned laneMask = 0;     // lanes that passed: the ones whose outputs are written
  int outputs = 0;           // colour outputs both the shader and the framebuffer have
  size_t texel[F::kCount];   // each lane's pixel index in the attachments
  const SetupTriangle* tri = nullptr;
  F px, py, z;               // the lanes' pixel coordinates and window z, as the depth test saw it
  bool interpolated = false;   // whether `in` and `varyings` hold the group's values yet
  FragmentInput<F> in;
  F varyings[limits::kMaxVaryingFloats];
};

// ---- counters ---------------------------------------------------------------------------------

// What happened in the pipeline since the counters were last reset.
struct PipelineCounters {
  uint64_t trianglesIn = 0;        // primitives assembled from indices
  uint64_t trianglesClipped = 0;   // that needed the clipper
  uint64_t trianglesRejected = 0;  // trivially outside one plane
  uint64_t trianglesSetUp = 0;     // that reached the rasterizer (after culling)
  uint64_t tileBinEntries = 0;     // (triangle, tile) pairs binned
  uint64_t depthRangeWalks = 0;    // later triangle ranges of heavy depth-only tiles (tile/depth_ranges.h)
  uint64_t texelPlaneTexels = 0;   // texels of the texel planes made (shader/texel_planes.h)
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

}  // namespace raster
