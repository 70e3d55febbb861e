// Tile rasterization: coverage, early depth, quad shading, output merge (see raster_tile.h).
// Sources: llvmpipe lp_rast_tri_tmp.h (block coverage), lp_bld_interp.c (plane evaluation:
// fmuladd(dady, y, fmuladd(dadx, x, a0)), perspective via an exact 1/w), lp_state_fs.c
// (depth clamp, early depth test), lp_bld_conv.c / lp_bld_blend.c (output conversion).
#include "raster/tile/rasterize_tile.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <type_traits>
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#endif

#include "raster/texture/format.h"
#include "raster/merge/output_merge.h"
#include "raster/util/cycles.h"

namespace raster {
namespace {

constexpr int kBlock = 4;    // 4x4 pixel blocks, as llvmpipe hands them to the shader
constexpr int kRegion = 16;  // 16x16 regions of blocks (llvmpipe's middle level)

// The largest and smallest amounts an edge function rises over a rectangle of pixel
// centres whose far corner is (farX, farY) pixels from its first one: the function is
// linear, so both sit at corners.
void edgeExtremes(const EdgeFunction& e, int farX, int farY, int64_t& high, int64_t& low) {
  const int64_t alongX = -e.dcdx * farX, alongY = e.dcdy * farY;
  high = std::max<int64_t>(alongX, 0) + std::max<int64_t>(alongY, 0);
  low = std::min<int64_t>(alongX, 0) + std::min<int64_t>(alongY, 0);
}

// One edge function as the block walk uses it, set up once per triangle and tile. The
// function is linear, so over a square of pixels it is largest and smallest at fixed
// corners: a square is tested by its first pixel's value plus those two offsets, with no
// corner evaluated. For 4x4 blocks that straddle the edge, `pixel` holds the offset from the
// block's first pixel to each of its 16 (bit row * 4 + col), when those fit 32 bits.
struct WalkEdge {
  EdgeFunction f;
  int64_t blockMax, blockMin;     // over a 4x4 block's pixel centres
  int64_t regionMax, regionMin;   // over a 16x16 region's
  bool smallSteps;                // |dcdx| + |dcdy| < 2^28: pixel offsets below 2^30
#if RASTER_AVX2
  __m256i pixel[2];               // -dcdx * col + dcdy * row: rows 0-1, rows 2-3
#endif
#if RASTER_ZMM_PAIRS
  __m512i pixel16;                // both in one register
#endif
  explicit WalkEdge(const EdgeFunction& e) : f(e) {
    edgeExtremes(e, kBlock - 1, kBlock - 1, blockMax, blockMin);
    edgeExtremes(e, kRegion - 1, kRegion - 1, regionMax, regionMin);
    smallSteps = std::abs(e.dcdx) + std::abs(e.dcdy) < (int64_t(1) << 28);
#if RASTER_AVX2
    if (smallSteps) {
      const __m256i col = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
      const __m256i xTerm = _mm256_mullo_epi32(_mm256_set1_epi32(int32_t(e.dcdx)), col);
      for (int half = 0; half < 2; ++half) {
        const __m256i row = _mm256_add_epi32(_mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1), _mm256_set1_epi32(2 * half));
        pixel[half] = _mm256_sub_epi32(_mm256_mullo_epi32(_mm256_set1_epi32(int32_t(e.dcdy)), row), xTerm);
      }
#if RASTER_ZMM_PAIRS
      pixel16 = _mm512_inserti64x4(_mm512_castsi256_si512(pixel[0]), pixel[1], 1);
#endif
    }
#endif
  }

  // Bits (row * 4 + col) of a straddled block whose first pixel has value c00, set where
  // c00 - dcdx * col + dcdy * row > 0.
  uint32_t straddledCoverage(int64_t c00) const {
#if RASTER_ZMM_PAIRS
    if (smallSteps) return _mm512_cmpgt_epi32_mask(pixel16, _mm512_set1_epi32(int32_t(-c00)));
#endif
#if RASTER_AVX2
    if (smallSteps) {   // straddling: |c00| < 3 * 2^28, so -c00 fits 32 bits too
      const __m256i threshold = _mm256_set1_epi32(int32_t(-c00));
      auto rows = [&](int half) {
        return uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpgt_epi32(pixel[half], threshold))));
      };
      return rows(0) | rows(1) << 8;
    }
#endif
    uint32_t mask = 0;
    for (int row = 0; row < kBlock; ++row)
      for (int col = 0; col < kBlock; ++col)
        if (c00 - f.dcdx * col + f.dcdy * row > 0) mask |= 1u << (row * kBlock + col);
    return mask;
  }
};

// How a square of pixels lies against a triangle: wholly outside one edge, wholly inside
// all three, or across an edge.
enum class Overlap { Outside, Inside, Partial };
Overlap regionOverlap(const WalkEdge (&edges)[3], int x, int y) {
  Overlap result = Overlap::Inside;
  for (const WalkEdge& e : edges) {
    const int64_t c00 = e.f.at(x, y);
    if (c00 + e.regionMax <= 0) return Overlap::Outside;
    if (c00 + e.regionMin <= 0) result = Overlap::Partial;
  }
  return result;
}

// Coverage of one 4x4 block: bit (row * 4 + col) set when that pixel centre is inside.
uint32_t blockCoverage(const WalkEdge (&edges)[3], int blockX, int blockY) {
  uint32_t mask = 0xFFFFu;
  for (const WalkEdge& e : edges) {
    const int64_t c00 = e.f.at(blockX, blockY);
    if (c00 + e.blockMax <= 0) return 0;      // all outside this edge
    if (c00 + e.blockMin > 0) continue;       // all inside this edge
    mask &= e.straddledCoverage(c00);
  }
  return mask;
}

#if RASTER_AVX2
// blockCoverage without a branch, when every edge has small steps: each edge's value at the
// block's first pixel is clamped to +-2^30 and compared with all 16 pixel offsets at once.
// The offsets stay below 3 * 2^28 in size, so beyond the clamp a block lies wholly on one
// side of the edge either way, and every bit is the one blockCoverage gives.
[[gnu::always_inline]] inline uint32_t blockCoverageSmallSteps(const WalkEdge (&edges)[3], int blockX, int blockY) {
  constexpr int64_t kLimit = int64_t(1) << 30;
  uint32_t mask = 0xFFFFu;
  for (const WalkEdge& e : edges) mask &= e.straddledCoverage(std::clamp(e.f.at(blockX, blockY), -kLimit, kLimit));
  return mask;
}
#endif

// Pixels of the block inside the framebuffer.
uint32_t blockBounds(int blockX, int blockY, int width, int height) {
  if (blockX + kBlock <= width && blockY + kBlock <= height) return 0xFFFFu;
  uint32_t mask = 0;
  for (int row = 0; row < kBlock; ++row)
    for (int col = 0; col < kBlock; ++col)
      if (blockX + col < width && blockY + row < height) mask |= 1u << (row * kBlock + col);
  return mask;
}

// Lane layout of a group: quads of 2x2 (lanes TL, TR, BL, BR), quads side by side.
// "Top" is GL's top: on window-system buffers, stored top row first, the quad's rows are
// swapped, so dFdy = bottom - top lanes gives GL's sign. llvmpipe computes the memory-row
// difference and negates it (nir_lower_wpos_ytransform); both are the same exact value.
template <class F>
struct LaneLayout {
  static constexpr int kLanes = F::kCount;
  static constexpr int kQuads = kLanes / 4;
  static constexpr int kGroupsPerBlock = 16 / kLanes;
  int dx[kLanes], dy[kLanes];
  F dxLanes, dyLanes;        // the same offsets as lane values
  size_t texel[kLanes];      // the same offsets in texels of a `width`-wide attachment
  LaneLayout(bool flipY, int width) {
    alignas(32) float fx[kLanes], fy[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      dx[i] = (i / 4) * 2 + (i & 1);
      dy[i] = flipY ? 1 - ((i >> 1) & 1) : (i >> 1) & 1;
      fx[i] = float(dx[i]);
      fy[i] = float(dy[i]);
      texel[i] = size_t(dy[i]) * size_t(width) + size_t(dx[i]);
    }
    dxLanes = F::load(fx);
    dyLanes = F::load(fy);
  }
  // Group g's origin inside the block: 8 lanes cover rows 0-1 then 2-3; 4 lanes one quad.
  static int originX(int g) { return kQuads == 2 ? 0 : (g & 1) * 2; }
  static int originY(int g) { return kQuads == 2 ? g * 2 : (g >> 1) * 2; }
  // Lane mask of group g from the block's coverage (bit row * 4 + col).
  unsigned laneMask(uint32_t coverage, int g) const {
    unsigned mask = 0;
    for (int i = 0; i < kLanes; ++i) {
      const int row = originY(g) + dy[i], col = originX(g) + dx[i];
      mask |= (coverage >> (row * kBlock + col) & 1u) << i;
    }
    return mask;
  }
};

// laneMask() for every pair of block rows at once: a table from the rows' 8 coverage bits
// (upper row in bits 0-3) to the 8 lanes of a group, one per orientation.
struct RowPairLanes {
  uint8_t lanes[2][256];
  RowPairLanes() {
    for (int flip = 0; flip < 2; ++flip) {
      const LaneLayout<simd::Lanes<8>> layout(flip == 1, 0);
      for (unsigned bits = 0; bits < 256; ++bits) lanes[flip][bits] = uint8_t(layout.laneMask(bits, 0));
    }
  }
};
const RowPairLanes kRowPairLanes;

template <class F>
F evaluatePlane(const Plane& p, F px, F py) {
  return simd::fma(F(p.dady), py, simd::fma(F(p.dadx), px, F(p.a0)));
}

// A fragment's window z: the z plane plus the polygon offset (clamped only for the test).
template <class F>
F fragmentDepth(const SetupTriangle& tri, F px, F py) {
  return evaluatePlane(tri.z, px, py) + F(tri.depthOffset);
}

#if RASTER_AVX2
// A depth-only draw over a 16x16 region wholly inside its triangle: no lane is shaded, so
// the depth test runs along memory rows, 8 pixels a step, instead of in 2x2 quads. Each
// pixel gets the arithmetic prepareGroup gives it (z plane, polygon offset, clamp,
// quantization), and a triangle touches each pixel once, so the same bits land.
void depthOnlyRegion(const SetupTriangle& tri, const RasterState& state, Texture& depth, int width, int x, int y) {
  using simd::Float8;
  const Float8 columns(_mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7));
  for (int row = 0; row < kRegion; ++row) {
    const Float8 py(float(y + row));
    uint32_t* dst = depth.depth.data() + size_t(y + row) * size_t(width) + size_t(x);
    for (int column = 0; column < kRegion; column += 8) {
      const Float8 px = Float8(float(x + column)) + columns;
      const Float8 z = fragmentDepth(tri, px, py);
      alignas(32) uint32_t codes[8];
      output_merge::depthCodes(simd::min(simd::max(z, Float8(0.0f)), Float8(1.0f)), depth.format, codes);
      const __m256i code = _mm256_load_si256(reinterpret_cast<const __m256i*>(codes));
      __m256i* stored = reinterpret_cast<__m256i*>(dst + column);
      const __m256i old = _mm256_loadu_si256(stored);
      const __m256i pass = output_merge::depthPasses(code, old, state.depthFunc == DepthFunc::Lequal);
      _mm256_storeu_si256(stored, _mm256_blendv_epi8(old, code, pass));
    }
  }
}
#endif

// Writes the covered lanes of one colour output to an attachment: conversion, then
// blending. unorm8 ONE/ONE blending is a saturating 8-bit add (lp_bld_blend.c); float
// targets blend in float32 (exact destination + source) and convert once, toward zero.
template <class F>
void writeColorOutput(Texture& target, const glsl::vec4<F>& color, const size_t* texel, unsigned laneMask,
                      bool blendAdditive) {
#if RASTER_AVX2
  if constexpr (std::is_same_v<F, simd::Float8>) {
    if (laneMask == 0xFFu) {
      if (target.format == TexelFormat::RGBA8 && !blendAdditive)
        return output_merge::writeRgba8Rows(color, target.rgba8.data(), texel);
      if (target.format == TexelFormat::RGBA16F)
        return output_merge::writeHalfRows(color, target.half.data(), texel, blendAdditive);
    }
  }
#endif
  if (target.format == TexelFormat::RGBA8) {
    uint32_t packed[F::kCount];
    output_merge::packRgba8(color, packed);
    for (int i = 0; i < F::kCount; ++i) {
      if (!(laneMask >> i & 1u)) continue;
      uint8_t* dst = &target.rgba8[texel[i] * 4];
      if (!blendAdditive) {
        std::memcpy(dst, &packed[i], 4);   // bytes r g b a, as packed
        continue;
      }
      for (int c = 0; c < 4; ++c) dst[c] = uint8_t(std::min(255, int(dst[c]) + int(uint8_t(packed[i] >> (8 * c)))));
    }
  } else if (target.format == TexelFormat::RGBA16F) {
    output_merge::writeHalfTexels(color, target.half.data(), texel, laneMask, blendAdditive);
  } else {   // RGBA32F, for tests
    alignas(32) float rgba[4][F::kCount];
    glsl::storePlanes(color, rgba);
    for (int i = 0; i < F::kCount; ++i) {
      if (!(laneMask >> i & 1u)) continue;
      float* dst = &target.f32[texel[i] * 4];
      for (int c = 0; c < 4; ++c) dst[c] = blendAdditive ? dst[c] + rgba[c][i] : rgba[c][i];
    }
  }
}

// A lane group that passed its depth test: everything its shader call needs.
template <class F>
struct ReadyGroup {
  const RecordedDraw* draw = nullptr;
  unsigned laneMask = 0;          // lanes that passed: the ones whose outputs are written
  int outputs = 0;                // colour outputs both the shader and the framebuffer have
  size_t texel[F::kCount];        // each lane's pixel index in the attachments
  FragmentInput<F> in;
  F varyings[kMaxVaryingFloats];
};

// Depth test of one lane group at origin (gx, gy) whose covered lanes are `laneMask`: z
// from its plane plus the polygon offset (returned in z), clamped to [0, 1] (NaN -> 0),
// quantized, tested and written. Returns the lanes that pass.
template <class F>
[[gnu::always_inline]] inline unsigned depthTestGroup(const TileJob& job, const SetupTriangle& tri,
                                                     const RecordedDraw& draw, const LaneLayout<F>& layout, int gx,
                                                     int gy, unsigned laneMask, F& z) {
  constexpr int kLanes = F::kCount;
  const Framebuffer& fb = *job.framebuffer;
  // Pixel coordinates per lane (small integers: the float sums are exact).
  const F px = F(float(gx)) + layout.dxLanes;
  const F py = F(float(gy)) + layout.dyLanes;
  z = fragmentDepth(tri, px, py);
  const RasterState& state = draw.state;
  if (!state.depthTest || !fb.depth) return laneMask;
  uint32_t codes[kLanes];
  output_merge::depthCodes(simd::min(simd::max(z, F(0.0f)), F(1.0f)), fb.depth->format, codes);
#if RASTER_AVX2
  if constexpr (std::is_same_v<F, simd::Float8>) {
    uint32_t* rowTop = fb.depth->depth.data() + size_t(gy) * size_t(fb.width) + size_t(gx);
    // On a last odd row the second row's lanes are all masked off: no pointer past the buffer.
    uint32_t* rowBottom = gy + 1 < fb.height ? rowTop + fb.width : rowTop;
    const bool wholeRows = gx + 4 <= fb.width && gy + 1 < fb.height;
    return output_merge::depthTestRows(codes, rowTop, rowBottom, laneMask, fb.flipY,
                                       state.depthFunc == DepthFunc::Lequal, state.depthWrite, wholeRows);
  }
#endif
  size_t texel[kLanes];
  const size_t origin = size_t(gy) * size_t(fb.width) + size_t(gx);
  for (int i = 0; i < kLanes; ++i) texel[i] = origin + layout.texel[i];
  return output_merge::depthTest<kLanes>(codes, fb.depth->depth.data(), texel, laneMask,
                                         state.depthFunc == DepthFunc::Lequal, state.depthWrite);
}

#if RASTER_ZMM_PAIRS
// Four rows of 4 lanes as one register (row r in lanes 4r..4r + 3), and back.
inline __m512i joinRows(const __m128i (&rows)[4]) {
  const __m512i low = _mm512_inserti32x4(_mm512_castsi128_si512(rows[0]), rows[1], 1);
  return _mm512_inserti32x4(_mm512_inserti32x4(low, rows[2], 2), rows[3], 3);
}
inline void splitRows(__m512i v, __m128i (&rows)[4]) {
  rows[0] = _mm512_castsi512_si128(v);
  rows[1] = _mm512_extracti32x4_epi32(v, 1);
  rows[2] = _mm512_extracti32x4_epi32(v, 2);
  rows[3] = _mm512_extracti32x4_epi32(v, 3);
}

// The depth test of one 4x4 block in memory-row order (lane row * 4 + col) instead of two
// lane groups: each pixel gets the z, clamp and quantization depthTestGroup gives it, is
// tested against its stored code and written where it passes, so the same bits land.
// Returns the pixels that pass (bit row * 4 + col). For the tests that shade nothing and so
// need no quads: the visibility pass's, and depth-only draws'.
[[gnu::always_inline]] inline uint32_t depthTestBlock(const TileJob& job, const SetupTriangle& tri, const RecordedDraw& draw,
                                                    int blockX, int blockY, uint32_t coverage) {
  const Framebuffer& fb = *job.framebuffer;
  const RasterState& state = draw.state;
  if (!state.depthTest || !fb.depth) return coverage;
  using simd::Float8x2;
  const Float8x2 px(_mm512_add_ps(_mm512_set1_ps(float(blockX)), _mm512_setr_ps(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3)));
  const Float8x2 py(_mm512_add_ps(_mm512_set1_ps(float(blockY)), _mm512_setr_ps(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3)));
  const Float8x2 z = simd::min(simd::max(fragmentDepth(tri, px, py), Float8x2(0.0f)), Float8x2(1.0f));
  const __m512i code = output_merge::depthCodes16(z, fb.depth->format);
  // The block's four memory rows. Where the block sticks out of the framebuffer, rows and
  // pixels outside it (never covered) are neither read nor written; otherwise whole rows
  // are read and written back blended, as masked stores are slow.
  const bool whole = blockX + 4 <= fb.width && blockY + 4 <= fb.height;
  uint32_t* rows[4];
  __m128i rowCodes[4];
  for (int r = 0; r < 4; ++r) {
    const __mmask8 covered = __mmask8(coverage >> (4 * r) & 0xFu);
    rows[r] = whole || covered ? fb.depth->depth.data() + size_t(blockY + r) * size_t(fb.width) + size_t(blockX) : nullptr;
    rowCodes[r] = whole ? _mm_loadu_si128(reinterpret_cast<const __m128i*>(rows[r]))
                        : covered ? _mm_maskz_loadu_epi32(covered, rows[r]) : _mm_setzero_si128();
  }
  const __m512i stored = joinRows(rowCodes);
  const __mmask16 pass =
      output_merge::depthPasses16(__mmask16(coverage), code, stored, state.depthFunc == DepthFunc::Lequal);
  if (state.depthWrite && pass) {
    splitRows(_mm512_mask_blend_epi32(pass, stored, code), rowCodes);
    for (int r = 0; r < 4; ++r) {
      if (whole) _mm_storeu_si128(reinterpret_cast<__m128i*>(rows[r]), rowCodes[r]);
      else if (rows[r]) _mm_mask_storeu_epi32(rows[r], __mmask8(pass >> (4 * r) & 0xFu), rowCodes[r]);
    }
  }
  return pass;
}
#endif

// Fragment inputs of lanes at pixels (px, py) with window z: perspective-correct varyings
// and gl_FragCoord, for a group or a pair of groups (the same operations per lane).
template <class F>
[[gnu::always_inline]] inline void interpolateFragment(const TileJob& job, const SetupTriangle& tri,
                                                       const RecordedDraw& draw, F px, F py, F z, FragmentInput<F>& in,
                                                       F* varyings) {
  const Framebuffer& fb = *job.framebuffer;
  // Varyings: a = fma(dady, y, fma(dadx, x, a0)) * (1 / w), w from the 1/w plane.
  const F w = evaluatePlane(tri.w, px, py);
  const F oow = F(1.0f) / w;
  const int varyingCount = draw.varyingFloats;
  for (int v = 0; v < varyingCount; ++v) varyings[v] = evaluatePlane(job.varyingPlanes[tri.varyingBase + v], px, py) * oow;

  // gl_FragCoord.y is GL's (y up): mirrored for window-system buffers (wpos_ytransform).
  const F fragY = fb.flipY ? F(float(fb.height)) - (py + F(0.5f)) : py + F(0.5f);
  in.gl_FragCoord = glsl::vec4<F>(px + F(0.5f), fragY, z, w);
  in.gl_FrontFacing = tri.frontFacing;
}

// Fragment inputs of a lane group at origin (gx, gy) whose lanes `laneMask` passed their
// depth test (z as depthTestGroup computed it): pixel indices, perspective-correct varyings
// (helper lanes too, so dFdx / dFdy see whole quads) and gl_FragCoord.
template <class F>
[[gnu::always_inline]] inline void fillGroup(const TileJob& job, const SetupTriangle& tri, const RecordedDraw& draw,
                                             const LaneLayout<F>& layout, int gx, int gy, unsigned laneMask, F z,
                                             PipelineCounters& counters, ReadyGroup<F>& group) {
  constexpr int kLanes = F::kCount;
  const Framebuffer& fb = *job.framebuffer;
  const F px = F(float(gx)) + layout.dxLanes;
  const F py = F(float(gy)) + layout.dyLanes;
  const size_t origin = size_t(gy) * size_t(fb.width) + size_t(gx);
  for (int i = 0; i < kLanes; ++i) group.texel[i] = origin + layout.texel[i];
  counters.lanesCovered += unsigned(__builtin_popcount(laneMask));
  group.outputs = colorOutputsWritten(draw, *job.framebuffer);
  group.draw = &draw;
  group.laneMask = laneMask;

  interpolateFragment(job, tri, draw, px, py, z, group.in, group.varyings);
}

// Shades one ready group and writes its colour outputs.
template <class F>
void shadeGroup(const TileJob& job, const ReadyGroup<F>& group, PipelineCounters& counters) {
  const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;
  FragmentOutput<F> out;
  group.draw->shader->shadeFragments(group.in, group.varyings, out);
  const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;
  counters.shadeCycles += mergeStart - shadeStart;
  counters.laneGroupsShaded += 1;
  counters.lanesShaded += F::kCount;

  const Framebuffer& fb = *job.framebuffer;
  for (int k = 0; k < group.outputs; ++k)
    writeColorOutput(*fb.colors[k], out.color[k], group.texel, group.laneMask, group.draw->state.blendAdditive);
  if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
}

#if RASTER_AVX2
// Two groups of the same draw and facing can share one shader call. They may cover the same
// pixels (overlapping triangles), but the later group was depth-tested after the earlier
// one's depth write, and a's colours are written before b's, so the framebuffer ends the
// same as shading each alone.
bool canPair(const ReadyGroup<simd::Float8>& a, const ReadyGroup<simd::Float8>& b) {
  return a.draw == b.draw && a.in.gl_FrontFacing == b.in.gl_FrontFacing;
}

// Shades two ready groups in one Float8x2 call, then writes a's outputs and b's.
void shadeGroupPair(const TileJob& job, const ReadyGroup<simd::Float8>& a, const ReadyGroup<simd::Float8>& b,
                    PipelineCounters& counters) {
  using simd::Float8x2;
  const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;
  FragmentInput<Float8x2> in;
  const glsl::vec4<simd::Float8>& ca = a.in.gl_FragCoord;
  const glsl::vec4<simd::Float8>& cb = b.in.gl_FragCoord;
  in.gl_FragCoord = {{ca.x, cb.x}, {ca.y, cb.y}, {ca.z, cb.z}, {ca.w, cb.w}};
  in.gl_FrontFacing = a.in.gl_FrontFacing;
  Float8x2 varyings[kMaxVaryingFloats];
  const int varyingCount = a.draw->varyingFloats;
  for (int v = 0; v < varyingCount; ++v) varyings[v] = {a.varyings[v], b.varyings[v]};
  FragmentOutput<Float8x2> out;
  a.draw->shader->shadeFragments(in, varyings, out);
  const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;
  counters.shadeCycles += mergeStart - shadeStart;
  counters.laneGroupsShaded += 2;
  counters.lanesShaded += Float8x2::kCount;

  const Framebuffer& fb = *job.framebuffer;
  const bool additive = a.draw->state.blendAdditive;
  for (int k = 0; k < a.outputs; ++k) {
    const glsl::vec4<Float8x2>& c = out.color[k];
    writeColorOutput(*fb.colors[k], output_merge::lowGroup(c), a.texel, a.laneMask, additive);
    writeColorOutput(*fb.colors[k], output_merge::highGroup(c), b.texel, b.laneMask, additive);
  }
  if (job.timeStages) counters.mergeCycles += cycleCount() - mergeStart;
}
#endif

#if RASTER_AVX2
#if RASTER_AVX2
// Whether a draw's lane groups are shaded two per call (Float8x2): for programs that read
// textures (one group's lookups overlap the other's), and with AVX-512 for every program
// (a pair's arithmetic is one 512-bit operation instead of two 256-bit ones).
bool shadedInPairs(const RecordedDraw& draw) {
#if RASTER_ZMM_PAIRS
  return true;
#else
  return draw.samplesTextures;
#endif
}
#endif

// A tile that one triangle covers whole, the fullscreen triangle of a post-processing pass
// being the common case: no lane is left out and no fragment can fail, so the tile is
// shaded block by block, each 4x4 block's two groups as one pair, straight from the planes.
// That skips the walk's coverage and depth bookkeeping and the ready-group copies. Each
// lane gets the walk's fragmentDepth and interpolateFragment, the pairs are the ones
// GroupShader forms there (a block's upper group, then its lower one), and every pixel is
// written once, so the bits are the same. Returns false (nothing done) for other tiles.
bool shadeCoveredTile(const TileJob& job, int tileX0, int tileY0, int tileX1, int tileY1, std::span<const uint32_t> bin,
                      const LaneLayout<simd::Float8>& layout, PipelineCounters& counters) {
  using simd::Float8;
  using simd::Float8x2;
  if (bin.size() != 1) return false;
  const SetupTriangle& tri = job.triangles[bin.front()];
  const RecordedDraw& draw = job.draws[tri.drawIndex];
  const Framebuffer& fb = *job.framebuffer;
  // Pairs only where GroupShader forms them; a depth test could fail lanes.
  if (!shadedInPairs(draw) || (draw.state.depthTest && fb.depth)) return false;
  if ((tileX1 + 1 - tileX0) % kBlock || (tileY1 + 1 - tileY0) % kBlock) return false;   // partial blocks
  if (!triangleCoversRect(tri, tileX0, tileY0, tileX1 + 1, tileY1 + 1)) return false;

  // Lane offsets of the pair: the block's upper group (rows 0-1), then its lower (rows 2-3).
  const Float8x2 dx(layout.dxLanes, layout.dxLanes), dy(layout.dyLanes, layout.dyLanes + Float8(2.0f));
  const int outputs = colorOutputsWritten(draw, fb);
  const bool additive = draw.state.blendAdditive;
  FragmentInput<Float8x2> in;
  Float8x2 varyings[kMaxVaryingFloats];
  FragmentOutput<Float8x2> out;
  for (int blockY = tileY0; blockY <= tileY1; blockY += kBlock) {
    for (int blockX = tileX0; blockX <= tileX1; blockX += kBlock) {
      const Float8x2 px = Float8x2(float(blockX)) + dx, py = Float8x2(float(blockY)) + dy;
      interpolateFragment(job, tri, draw, px, py, fragmentDepth(tri, px, py), in, varyings);
      const uint64_t shadeStart = job.timeStages ? cycleCount() : 0;   // interpolation counts as rasterization
      draw.shader->shadeFragments(in, varyings, out);
      const uint64_t mergeStart = job.timeStages ? cycleCount() : 0;

      size_t upper[8], lower[8];
      const size_t origin = size_t(blockY) * size_t(fb.width) + size_t(blockX);
      for (int i = 0; i < 8; ++i) {
        upper[i] = origin + layout.texel[i];
        lower[i] = upper[i] + 2 * size_t(fb.width);
      }
      for (int k = 0; k < outputs; ++k) {
        Texture& target = *fb.colors[k];
        const glsl::vec4<Float8x2>& c = out.color[k];
        if (!additive && target.format == TexelFormat::RGBA8) {
          output_merge::writeRgba8RowsPair(c, target.rgba8.data(), upper, lower);
        } else if (target.format == TexelFormat::RGBA16F) {
          output_merge::writeHalfRowsPair(c, target.half.data(), upper, lower, additive);
        } else {
          writeColorOutput(target, output_merge::lowGroup(c), upper, 0xFFu, additive);
          writeColorOutput(target, output_merge::highGroup(c), lower, 0xFFu, additive);
        }
      }
      if (job.timeStages) {
        counters.shadeCycles += mergeStart - shadeStart;
        counters.mergeCycles += cycleCount() - mergeStart;
      }
    }
  }
  const unsigned lanes = unsigned((tileX1 + 1 - tileX0) * (tileY1 + 1 - tileY0));
  counters.lanesCovered += lanes;
  counters.laneGroupsShaded += lanes / 8;
  counters.lanesShaded += lanes;
  return true;
}
#endif

// Shades a tile's ready groups in order, two groups per call (Float8x2) where
// shadedInPairs: a group waits in its slot until the next ready group joins it, or until
// one that cannot join (another draw or facing) or the end of the tile sends it alone.
// Each group passed its depth test before it became ready, and colours are written in the
// order the groups became ready, so the framebuffer ends as if each were shaded alone.
template <class F>
class GroupShader {
 public:
  GroupShader(const TileJob& job, PipelineCounters& counters) : job_(job), counters_(counters) {}
  // Where the next group is prepared: never the waiting group's slot.
  ReadyGroup<F>& next() { return slots_[nextIndex()]; }
  // next() holds a ready group: shade it now, with the waiting one, or let it wait.
  void push() {
    const int index = nextIndex();
    ReadyGroup<F>& ready = slots_[index];
#if RASTER_AVX2
    if constexpr (std::is_same_v<F, simd::Float8>) {
      if (shadedInPairs(*ready.draw)) {
        if (waiting_ >= 0 && canPair(slots_[waiting_], ready)) {
          shadeGroupPair(job_, slots_[waiting_], ready, counters_);
          waiting_ = -1;
          return;
        }
        flush();
        waiting_ = index;
        return;
      }
    }
#endif
    flush();
    shadeGroup(job_, ready, counters_);
  }
  // Shades the waiting group alone.
  void flush() {
    if (waiting_ >= 0) shadeGroup(job_, slots_[waiting_], counters_);
    waiting_ = -1;
  }

 private:
  int nextIndex() const { return waiting_ == 0 ? 1 : 0; }
  const TileJob& job_;
  PipelineCounters& counters_;
  ReadyGroup<F> slots_[2];
  int waiting_ = -1;   // the slot of the group waiting for a partner, or -1
};

// The 4x4 blocks of one triangle inside one tile, in walk order: visitBlock(blockX, blockY,
// coverage) for every block with a covered pixel (bit row * 4 + col). Depth-only draws fill
// the 16x16 regions wholly inside the triangle themselves (depthOnlyRegion) and visit only
// the rest.
template <class F, class VisitBlock>
void walkTriangleBlocks(const TileJob& job, const SetupTriangle& tri, const RecordedDraw& draw, int tileX0, int tileY0,
                        int tileX1, int tileY1, VisitBlock&& visitBlock) {
  const Framebuffer& fb = *job.framebuffer;
  const int x0 = std::max(tileX0, tri.minX), x1 = std::min(tileX1, tri.maxX);
  const int y0 = std::max(tileY0, tri.minY), y1 = std::min(tileY1, tri.maxY);
  const WalkEdge edges[3] = {WalkEdge(tri.edge[0]), WalkEdge(tri.edge[1]), WalkEdge(tri.edge[2])};
  const bool smallSteps = edges[0].smallSteps && edges[1].smallSteps && edges[2].smallSteps;
  // Depth test and write, and no colour the shader writes is kept.
  const bool depthOnly =
      draw.state.depthTest && draw.state.depthWrite && fb.depth && colorOutputsWritten(draw, fb) == 0;
  // 16x16 regions first (llvmpipe's middle level): a region wholly inside needs no edge
  // tests per block, one wholly outside no blocks at all. Blocks are still walked a whole
  // row of the triangle's extent at a time, so texture reads run along long rows.
  const int firstRegionX = x0 & ~(kRegion - 1);
  for (int regionY = y0 & ~(kRegion - 1); regionY <= y1; regionY += kRegion) {
    Overlap overlap[kTileSize / kRegion + 1];
    for (int regionX = firstRegionX; regionX <= x1; regionX += kRegion)
      overlap[(regionX - firstRegionX) / kRegion] = regionOverlap(edges, regionX, regionY);
#if RASTER_AVX2
    // Depth-only draws fill whole inside regions row by row; the blocks then skip them.
    if (std::is_same_v<F, simd::Float8> && depthOnly && regionY >= y0 && regionY + kRegion - 1 <= y1) {
      for (int regionX = firstRegionX; regionX <= x1; regionX += kRegion) {
        Overlap& region = overlap[(regionX - firstRegionX) / kRegion];
        if (region != Overlap::Inside || regionX < x0 || regionX + kRegion - 1 > x1) continue;
        depthOnlyRegion(tri, draw.state, *fb.depth, fb.width, regionX, regionY);
        region = Overlap::Outside;
      }
    }
#endif
    const int bandY1 = std::min(y1, regionY + kRegion - 1);
    for (int blockY = std::max(y0, regionY) & ~(kBlock - 1); blockY <= bandY1; blockY += kBlock) {
      for (int blockX = x0 & ~(kBlock - 1); blockX <= x1; blockX += kBlock) {
        const Overlap region = overlap[(blockX - firstRegionX) / kRegion];
        if (region == Overlap::Outside) {   // on to the next region's first block
          blockX = (blockX | (kRegion - 1)) - (kBlock - 1);
          continue;
        }
        const uint32_t inside = region == Overlap::Inside ? 0xFFFFu
#if RASTER_AVX2
                                : smallSteps ? blockCoverageSmallSteps(edges, blockX, blockY)
#endif
                                             : blockCoverage(edges, blockX, blockY);
        const uint32_t coverage = inside & blockBounds(blockX, blockY, fb.width, fb.height);
        if (coverage) visitBlock(blockX, blockY, coverage);
      }
    }
  }
}

// The lane groups of one triangle inside one tile, in walk order: visit(gx, gy, laneMask)
// for every group with a covered lane.
template <class F, class Visit>
void walkTriangle(const TileJob& job, const SetupTriangle& tri, const RecordedDraw& draw, const LaneLayout<F>& layout,
                  int tileX0, int tileY0, int tileX1, int tileY1, Visit&& visit) {
  const bool flipY = job.framebuffer->flipY;
  walkTriangleBlocks<F>(job, tri, draw, tileX0, tileY0, tileX1, tileY1, [&](int blockX, int blockY, uint32_t coverage) {
    for (int g = 0; g < LaneLayout<F>::kGroupsPerBlock; ++g) {
      const int gx = blockX + LaneLayout<F>::originX(g), gy = blockY + LaneLayout<F>::originY(g);
      const unsigned laneMask = F::kCount == 8 ? kRowPairLanes.lanes[flipY][(coverage >> (8 * g)) & 0xFFu]
                                               : layout.laneMask(coverage, g);
      if (laneMask) visit(gx, gy, laneMask);
    }
  });
}

// Walks the bin's triangles in order through the depth test, calling
// passed(index, tri, draw, gx, gy, laneMask, z) for every lane group of a colour-writing
// draw with lanes left (depth-only draws stop at the test and its write).
template <class F, class Passed>
[[gnu::always_inline]] inline void depthTestBin(const TileJob& job, int tileX0, int tileY0, int tileX1, int tileY1,
                                                std::span<const uint32_t> bin, const LaneLayout<F>& layout,
                                                Passed&& passed) {
  for (uint32_t index : bin) {
    const SetupTriangle& tri = job.triangles[index];
    const RecordedDraw& draw = job.draws[tri.drawIndex];
    const bool writesColor = colorOutputsWritten(draw, *job.framebuffer) > 0;
#if RASTER_ZMM_PAIRS
    if constexpr (std::is_same_v<F, simd::Float8>) {
      if (!writesColor) {   // depth only: no quads needed
        walkTriangleBlocks<F>(job, tri, draw, tileX0, tileY0, tileX1, tileY1, [&](int blockX, int blockY, uint32_t coverage) {
          depthTestBlock(job, tri, draw, blockX, blockY, coverage);
        });
        continue;
      }
    }
#endif
    walkTriangle<F>(job, tri, draw, layout, tileX0, tileY0, tileX1, tileY1, [&](int gx, int gy, unsigned laneMask) {
      F z;
      const unsigned lanes = depthTestGroup(job, tri, draw, layout, gx, gy, laneMask, z);
      if (lanes && writesColor) passed(index, tri, draw, gx, gy, lanes, z);
    });
  }
}

// Per-pixel triangle indices of one tile for rasterizeVisibleFirst, kept per lane group:
// a group's entries are valid once it is marked (bit: group column, per pair of rows).
template <class F>
class TileTriangles {
 public:
  static constexpr int kLanes = F::kCount;
  static constexpr int kGroupWidth = 2 * LaneLayout<F>::kQuads;   // 4 (8 lanes) or 2 (4 lanes)
  static constexpr uint32_t kNone = ~0u;

  explicit TileTriangles(bool flipY) : local_(flipY) {}
  // Forgets every mark (a new tile).
  void reset() { std::fill(std::begin(marked_), std::end(marked_), 0u); }

  // Lanes `passed` of the group at tile offset (lx, ly) now show triangle `index`.
  void mark(int lx, int ly, unsigned passed, uint32_t index) {
    uint32_t* at = entries_ + ly * kTileSize + lx;
    uint32_t& rowBits = marked_[ly / 2];
    const uint32_t bit = 1u << (lx / kGroupWidth);
    const bool first = !(rowBits & bit);
    rowBits |= bit;
#if RASTER_AVX2
    if constexpr (kLanes == 8) {
      // The group's two rows of four, read (or kNone when first marked), blended, written.
      __m128i* top = reinterpret_cast<__m128i*>(at);
      __m128i* bottom = reinterpret_cast<__m128i*>(at + kTileSize);
      const __m256i old = first ? _mm256_set1_epi32(-1) : _mm256_setr_m128i(_mm_loadu_si128(top), _mm_loadu_si128(bottom));
      const __m256i lanes = _mm256_castps_si256(simd::Mask8::fromBits(passed).v);
      const __m256i rows = _mm256_permutevar8x32_epi32(lanes, local_.toRows);
      const __m256i merged = _mm256_blendv_epi8(old, _mm256_set1_epi32(int(index)), rows);
      _mm_storeu_si128(top, _mm256_castsi256_si128(merged));
      _mm_storeu_si128(bottom, _mm256_extracti128_si256(merged, 1));
      return;
    }
#endif
    if (first)
      for (int i = 0; i < kLanes; ++i) at[local_.texel[i]] = kNone;
    for (; passed; passed &= passed - 1) at[local_.texel[__builtin_ctz(passed)]] = index;
  }

#if RASTER_ZMM_PAIRS
  // Pixels `passed` (bit row * 4 + col) of the 4x4 block at tile offset (lx, ly) now show
  // triangle `index`: mark() for the block's upper group and its lower one, in memory rows.
  void markBlock(int lx, int ly, uint32_t passed, uint32_t index) {
    for (int half = 0; half < 2; ++half) {
      const uint32_t bits = passed >> (8 * half) & 0xFFu;
      if (!bits) continue;
      uint32_t& rowBits = marked_[ly / 2 + half];
      const uint32_t bit = 1u << (lx / kGroupWidth);
      const bool first = !(rowBits & bit);
      rowBits |= bit;
      for (int r = 0; r < 2; ++r) {
        uint32_t* at = entries_ + (ly + 2 * half + r) * kTileSize + lx;
        const __mmask8 row = __mmask8(bits >> (4 * r) & 0xFu);
        // A row the tile owns whole: read, blended and written back (masked stores are slow).
        const __m128i before = first ? _mm_set1_epi32(-1) : _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(at), _mm_mask_blend_epi32(row, before, _mm_set1_epi32(int(index))));
      }
    }
  }
#endif

  // Calls shade(lx, ly, index, laneMask) once per triangle that marked group (lx, ly).
  template <class Shade>
  void forEachVisible(Shade&& shade) const {
    for (int row = 0; row < kTileSize / 2; ++row) {
      for (uint32_t bits = marked_[row]; bits; bits &= bits - 1) {
        const int lx = __builtin_ctz(bits) * kGroupWidth, ly = row * 2;
        const uint32_t* at = entries_ + ly * kTileSize + lx;
        alignas(32) uint32_t lanes[kLanes];
#if RASTER_AVX2
        if constexpr (kLanes == 8) {
          const __m256i rows = _mm256_setr_m128i(_mm_loadu_si128(reinterpret_cast<const __m128i*>(at)),
                                                 _mm_loadu_si128(reinterpret_cast<const __m128i*>(at + kTileSize)));
          const __m256i v = _mm256_permutevar8x32_epi32(rows, local_.toLanes);
          _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), v);
          const __m256i none = _mm256_cmpeq_epi32(v, _mm256_set1_epi32(-1));
          unsigned remaining = ~unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(none))) & 0xFFu;
          while (remaining) {
            const uint32_t index = lanes[__builtin_ctz(remaining)];
            const __m256i same = _mm256_cmpeq_epi32(v, _mm256_set1_epi32(int(index)));
            const unsigned laneMask = unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(same)));
            remaining &= ~laneMask;
            shade(lx, ly, index, laneMask);
          }
          continue;
        }
#endif
        unsigned remaining = 0;
        for (int i = 0; i < kLanes; ++i) {
          lanes[i] = at[local_.texel[i]];
          if (lanes[i] != kNone) remaining |= 1u << i;
        }
        while (remaining) {
          const uint32_t index = lanes[__builtin_ctz(remaining)];
          unsigned laneMask = 0;
          for (int i = 0; i < kLanes; ++i)
            if (lanes[i] == index) laneMask |= 1u << i;
          remaining &= ~laneMask;
          shade(lx, ly, index, laneMask);
        }
      }
    }
  }

 private:
  struct Local : LaneLayout<F> {   // lane offsets within the tile, and lanes <-> rows orders
#if RASTER_AVX2
    __m256i toRows, toLanes;
#endif
    explicit Local(bool flipY) : LaneLayout<F>(flipY, kTileSize) {
#if RASTER_AVX2
      toRows = output_merge::quadLanesToRows(flipY);
      toLanes = output_merge::rowsToQuadLanes(flipY);
#endif
    }
  };
  const Local local_;
  alignas(32) uint32_t entries_[kTileSize * kTileSize];
  uint32_t marked_[kTileSize / 2] = {};
};

// Visibility first, for passes whose colour draws do not blend (TileJob::visibilityFirst).
// Pass 1 walks every triangle of the bin in order with the depth test alone, and records per
// pixel the last colour-writing triangle whose fragment passed: the fragment whose colour
// the pixel would end with. Pass 2 shades, group by group, only those fragments: for each
// triangle a group's pixels name, the group exactly as the in-order walk prepares it (same
// origin, planes and helper lanes, so the same bits), with only that triangle's pixels
// written. Each pixel is written once, so no order is needed between the groups.
template <class F>
void rasterizeVisibleFirst(const TileJob& job, int tileX0, int tileY0, int tileX1, int tileY1,
                           std::span<const uint32_t> bin, const LaneLayout<F>& layout, PipelineCounters& counters,
                           GroupShader<F>& shader) {
  thread_local TileTriangles<F> visibleFlip(true), visible(false);
  TileTriangles<F>& shown = job.framebuffer->flipY ? visibleFlip : visible;
  shown.reset();
#if RASTER_ZMM_PAIRS
  if constexpr (std::is_same_v<F, simd::Float8>) {
    // The visibility pass needs no quads: its depth tests run a whole block at a time.
    for (uint32_t index : bin) {
      const SetupTriangle& tri = job.triangles[index];
      const RecordedDraw& draw = job.draws[tri.drawIndex];
      const bool writesColor = colorOutputsWritten(draw, *job.framebuffer) > 0;
      walkTriangleBlocks<F>(job, tri, draw, tileX0, tileY0, tileX1, tileY1, [&](int blockX, int blockY, uint32_t coverage) {
        const uint32_t passed = depthTestBlock(job, tri, draw, blockX, blockY, coverage);
        if (passed && writesColor) shown.markBlock(blockX - tileX0, blockY - tileY0, passed, index);
      });
    }
  } else
#endif
  depthTestBin<F>(job, tileX0, tileY0, tileX1, tileY1, bin, layout,
                  [&](uint32_t index, const SetupTriangle&, const RecordedDraw&, int gx, int gy, unsigned passed, F) {
                    shown.mark(gx - tileX0, gy - tileY0, passed, index);
                  });
  shown.forEachVisible([&](int lx, int ly, uint32_t index, unsigned laneMask) {
    const SetupTriangle& tri = job.triangles[index];
    const int gx = tileX0 + lx, gy = tileY0 + ly;
    const F px = F(float(gx)) + layout.dxLanes, py = F(float(gy)) + layout.dyLanes;
    const F z = fragmentDepth(tri, px, py);
    fillGroup(job, tri, job.draws[tri.drawIndex], layout, gx, gy, laneMask, z, counters, shader.next());
    shader.push();
  });
}

}  // namespace

bool triangleCoversRect(const SetupTriangle& tri, int x0, int y0, int x1, int y1) {
  if (x1 <= x0 || y1 <= y0) return false;
  // The walk visits only the bounds (which hold every covered pixel centre anyway).
  if (tri.minX > x0 || tri.maxX < x1 - 1 || tri.minY > y0 || tri.maxY < y1 - 1) return false;
  for (const EdgeFunction& e : tri.edge) {
    int64_t high, low;
    edgeExtremes(e, x1 - 1 - x0, y1 - 1 - y0, high, low);
    if (e.at(x0, y0) + low <= 0) return false;   // some pixel centre outside this edge
  }
  return true;
}

bool firstTriangleOverwritesColor(const TileJob& job, std::span<const uint32_t> bin, int x0, int y0, int x1, int y1) {
  if (bin.empty()) return false;
  const SetupTriangle& tri = job.triangles[bin.front()];
  const RecordedDraw& draw = job.draws[tri.drawIndex];
  const Framebuffer& fb = *job.framebuffer;
  if (draw.state.blendAdditive || (draw.state.depthTest && fb.depth) ||
      colorOutputsWritten(draw, fb) != int(fb.colors.size()))
    return false;
  return triangleCoversRect(tri, x0, y0, x1, y1);
}

constexpr size_t kVisibilityFirstMinTriangles = 16;

template <class F>
void rasterizeTile(const TileJob& job, int tileX, int tileY, std::span<const uint32_t> bin, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  const int tileX0 = tileX * kTileSize, tileY0 = tileY * kTileSize;
  const int tileX1 = std::min(tileX0 + kTileSize, fb.width) - 1;
  const int tileY1 = std::min(tileY0 + kTileSize, fb.height) - 1;
  const uint64_t tileStart = job.timeStages ? cycleCount() : 0;
  const uint64_t shadeBefore = counters.shadeCycles, mergeBefore = counters.mergeCycles;

  auto shadeTile = [&] {
#if RASTER_AVX2
    if constexpr (std::is_same_v<F, simd::Float8>)
      if (shadeCoveredTile(job, tileX0, tileY0, tileX1, tileY1, bin, layout, counters)) return;
#endif
    GroupShader<F> shader(job, counters);
    // A tile crossed by a few triangles has little overdraw to save (a floor, a cube's
    // faces), and the visibility pass would cost more than it saves.
    if (job.visibilityFirst && bin.size() >= kVisibilityFirstMinTriangles) {
      rasterizeVisibleFirst<F>(job, tileX0, tileY0, tileX1, tileY1, bin, layout, counters, shader);
    } else {   // in order: each group is shaded as soon as it passes its depth test
      depthTestBin<F>(job, tileX0, tileY0, tileX1, tileY1, bin, layout,
                      [&](uint32_t, const SetupTriangle& tri, const RecordedDraw& draw, int gx, int gy, unsigned passed, F z) {
                        fillGroup(job, tri, draw, layout, gx, gy, passed, z, counters, shader.next());
                        shader.push();
                      });
    }
    shader.flush();
  };
  shadeTile();
  if (job.timeStages)
    counters.rasterCycles += (cycleCount() - tileStart) - (counters.shadeCycles - shadeBefore) - (counters.mergeCycles - mergeBefore);
}

template void rasterizeTile<FastLanes>(const TileJob&, int, int, std::span<const uint32_t>, PipelineCounters&);
template void rasterizeTile<ScalarLanes>(const TileJob&, int, int, std::span<const uint32_t>, PipelineCounters&);

}  // namespace raster
