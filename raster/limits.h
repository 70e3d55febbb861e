// Every limit of the pipeline, in one place, each with the reason for its value.
//
// A limit here is a number some stage relies on: a size a buffer is laid out for, a bound an
// integer budget is worked out from, or a count GL lets an implementation cap. Tuning knobs
// that change only speed (chunk sizes, thresholds for a fast path) stay beside the code they
// tune; they never change a bit of the output.
#pragma once

#include <cstddef>
#include <cstdint>

namespace raster::limits {

// ---- framebuffer and tiles ------------------------------------------------------------------

// Largest framebuffer side: llvmpipe's GL_MAX_TEXTURE_SIZE / GL_MAX_RENDERBUFFER_SIZE. With
// 8 sub-pixel bits a window coordinate then needs 14 + 8 = 22 bits, so an edge function
// (a product of two 23-bit differences) stays below 2^46 and int64 holds it exactly.
constexpr int kMaxFramebufferSide = 16384;

// Tiles are 64x64 pixels: llvmpipe's TILE_ORDER 6. A tile is the unit of parallel work and
// of binning; its depth and colour rows (64 * 16 bytes at most) stay in L1/L2 while its
// triangles are walked.
constexpr int kTileSize = 64;

// Inside a tile, coverage is decided for 16x16 regions, then 4x4 blocks (llvmpipe's 64 ->
// 16 -> 4 hierarchy, LP_RASTER_BLOCK_SIZE 4): a 4x4 block is what its shader is handed.
constexpr int kRegionSize = 16;
constexpr int kBlockSize = 4;

// ---- fixed point ---------------------------------------------------------------------------

// Window x and y are snapped to 8 sub-pixel bits (llvmpipe's FIXED_ORDER), which decides
// coverage: the same snapping gives the same pixels as llvmpipe.
constexpr int kSubPixelBits = 8;
constexpr int kSubPixelOne = 1 << kSubPixelBits;

// Setup drops a triangle with a window coordinate beyond +-2^21 pixels, or not a number.
// Clipping bounds every finite vertex to the viewport, so only NaN positions (which pass the
// clip tests: ordered compares are false) or a caller that skips clipping get here; GL
// leaves them undefined. Below the bound, snapped coordinates need 30 bits and every edge
// product of setup fits int64 with room to spare.
constexpr float kMaxWindowCoordinate = float(1 << 21);

// ---- shader interface ----------------------------------------------------------------------

// Vertex attribute locations 0..7: GL 3.3 guarantees 16; the scenes use at most 6, and every
// unused location costs a (0, 0, 0, 1) plane per vertex group.
constexpr int kMaxVertexAttributes = 8;

// Interpolated floats per vertex: GL 3.3 guarantees 64 components; the scenes use at most 10.
// A fragment group carries this many lane values on the stack.
constexpr int kMaxVaryingFloats = 32;

// Colour attachments written at once: GL 3.3 guarantees 8 draw buffers; pbr's
// G-buffer writes 4, deferred's 3.
constexpr int kMaxColorOutputs = 4;

// ---- clipping ------------------------------------------------------------------------------

// One triangle clipped by the six frustum planes has at most 3 + 6 vertices, and Mesa's
// draw module reserves 2 * 6 + 1 (MAX_CLIPPED_VERTICES): the clipper keeps that bound.
constexpr int kClipPlanes = 6;
constexpr int kMaxClippedVertices = 2 * kClipPlanes + 1;

// ---- buffers -------------------------------------------------------------------------------

// The vertex stage gathers attributes with 32-bit float offsets, so a vertex buffer holds at
// most 2^31 - 1 floats; larger draws are refused with an error.
constexpr size_t kMaxVertexBufferFloats = size_t(INT32_MAX);

}  // namespace raster::limits
