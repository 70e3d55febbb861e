// NEAREST lookups of RGBA8 and depth textures for Float8x2 lanes held in one 512-bit
// register, sixteen lanes at a time: pbr's SSAO reads its depth texture 65 times a pixel
// through sampler2D, and its blur an RGBA8 target 9 times (a line of taps that share their
// loads: sampleNearest32Line). Inline, so that a port's lookup costs no call and no trip of
// four channel planes through memory, and the shader's compiler drops the channels it never
// reads (both read r only). The wraps and conversions are the 8-lane sampler's
// (sample_rgba8_avx2.h: sampleRgba8; sample_color_avx2.cpp: sampleRgba8Float and its depth
// branch) on 16 lanes at once, so every value is the same:
//   - RGBA8: each channel as unorm8 * float(1/255). The fixed-point path floors before its
//     CLAMP_TO_EDGE clamp and the float path truncates; the clamp to [0, size - 1] makes the
//     two the same index for every float, NaN included, so wrapNearest16 serves both. A grey
//     copy's texels are the rgba8 texels' r, with a = 255, so rows read as it reads.
//   - depth: code * depthCodeScale in r, (0, 0, 1) in gba (sample_color.cpp's
//     depthTexelChannel).
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include <cmath>

#include "raster/simd/intrinsics.h"
#include "raster/simd/prefetch.h"
#include "raster/texture/lane_loads_avx512.h"
#include "raster/texture/lookup_filter.h"
#include "raster/texture/sample_half_avx512.h"
#include "raster/texture/sampler.h"
#include "raster/texture/texture.h"
#include "raster/texture/wrap_avx512.h"
#include "raster/simd/lane_layout.h"

namespace raster::sampling {

// Whether sampleNearest32Pair is this texture's lookup: a depth texture, or an RGBA8 one
// that keeps its rows (a strip copy alone holds an uploaded LINEAR texture's texels; under
// `lookup=nearest` that texture takes sampleColor8x2).
inline bool isNearest32(const Texture& t) {
  if (lookupFilter(t) != Filter::Nearest) return false;
  return t.isDepth() || (t.format == TexelFormat::RGBA8 && !t.rgba8.empty());
}

// Each lane's texel offset from lane 0's where the sixteen lanes read a 4x4 block of texels
// as raster/simd/lane_layout.h lays a block's pixels out (two 8-lane groups, quads of 2x2,
// memory rows upward): what a post pass reads at its own pixel, or at one a whole number of
// texels away, in an offscreen target.
[[gnu::always_inline]] inline __m512i blockOffsets16(int width) {
  struct Lanes {
    alignas(64) int dx[16];
    alignas(64) int dy[16];
  };
  static constexpr Lanes kLanes = [] {
    Lanes lanes{};
    for (int lane = 0; lane < 16; ++lane) {
      lanes.dx[lane] = BlockLanes::column(lane);
      lanes.dy[lane] = BlockLanes::row(lane);
    }
    return lanes;
  }();
  const __m512i dx = _mm512_load_si512(kLanes.dx), dy = _mm512_load_si512(kLanes.dy);
  return _mm512_add_epi32(_mm512_mullo_epi32(dy, _mm512_set1_epi32(width)), dx);
}

// Lane 0's texel index, and the lanes whose index is lane 0's plus their blockOffsets16:
// all sixteen where the lanes read a 4x4 block of texels.
[[gnu::always_inline]] inline __mmask16 lanesInBlock16(__m512i index, int width, int& first) {
  first = _mm_cvtsi128_si32(_mm512_castsi512_si128(index));
  return _mm512_cmpeq_epi32_mask(index, _mm512_add_epi32(_mm512_set1_epi32(first), blockOffsets16(width)));
}

// Two texel rows of four (columns c0..c3) in one half's lane order:
// [top c0, top c1, bottom c0, bottom c1, top c2, top c3, bottom c2, bottom c3].
[[gnu::always_inline]] inline __m256i rowPairHalf(__m128i top, __m128i bottom) {
  return _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_unpacklo_epi64(top, bottom)), _mm_unpackhi_epi64(top, bottom), 1);
}

// The 32-bit texels at base[index[lane]], in lane order. Where the lanes read a 4x4 block
// (blockOffsets16), four 16-byte row loads and two shuffles a half take the place of
// sixteen loads: the blur's lookups all do, SSAO's own-pixel lookups too. Every texel of
// the block is some lane's, so the row loads stay inside the texture.
[[gnu::always_inline]] inline __m512i loadTexels32(const uint32_t* base, __m512i index, int width) {
  int first;
  if (lanesInBlock16(index, width, first) == 0xFFFF) {
    const uint32_t* block = base + first;
    auto row = [&](int r) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(block + ptrdiff_t(r) * width)); };
    return _mm512_inserti64x4(_mm512_castsi256_si512(rowPairHalf(row(0), row(1))), rowPairHalf(row(2), row(3)), 1);
  }
  alignas(64) int at[16];
  storeLaneIndices16(index, at);
  return loadSixteenLanes32(base, at);
}

// The texels of isNearest32 texture t: depth codes or RGBA8 texels.
[[gnu::always_inline]] inline const uint32_t* texels32(const Texture& t) {
  return t.isDepth() ? t.depth.data() : reinterpret_cast<const uint32_t*>(t.rgba8.data());
}

// Starts loading the lines kPrefetchTexelsAhead texels to the right of `rows` texel rows from
// texel `first` (column x0) on, where the tile stage's next blocks will read them
// (simd::prefetchRowsAhead: a fullscreen pass reads 16 bytes of each row a block at a time,
// short runs a target row apart that the hardware prefetchers do not run ahead of). Only from
// blocks whose column is a multiple of 16: once a 64-byte line along a row, whatever the row's
// alignment; the blocks between would prefetch lines already on their way. Without it pbr's
// blur along x at 1920x1080 waited on its texels for half its time (4.1-4.6 -> 2.3-2.4 ms, 2
// threads); prefetching from every block cost its blur along y at 640x480 about 7%.
[[gnu::always_inline]] inline void prefetchBlockRowsAhead(const Texture& t, size_t first, int x0, int rows) {
  if (x0 % 16 != 0) return;
  // A 32-bit texel is four one-byte channels to prefetchRowsAhead.
  simd::prefetchRowsAhead(reinterpret_cast<const uint8_t*>(texels32(t)), size_t(t.width) * size_t(t.height) - 1, first,
                          size_t(t.width), rows);
}

// How isNearest32 texture t's 32-bit texels become channels: a depth code times its scale,
// or four unorm8 bytes. Read from the texture once, before a lookup's stores: a store of a
// vector may alias anything, so a field read after it is read again from memory.
struct Texel32Format {
  bool depth;
  float depthScale;
};
[[gnu::always_inline]] inline Texel32Format texel32Format(const Texture& t) {
  return {t.isDepth(), t.isDepth() ? depthCodeScale(t) : 0.0f};
}

// Channel c (0-3: r, g, b, a) of a four-channel value: a plane array or a vec4.
[[gnu::always_inline]] inline simd::Float8x2& channelRef(simd::Float8x2* planes, int c) { return planes[c]; }
[[gnu::always_inline]] inline simd::Float8x2& channelRef(glsl::vec4<simd::Float8x2>& v, int c) {
  return c == 0 ? v.x : c == 1 ? v.y : c == 2 ? v.z : v.w;
}

// Sixteen 32-bit texels (an RGBA8 texel or a depth code each) as float channels.
template <class Channels>
[[gnu::always_inline]] inline void texelChannels32(Texel32Format format, __m512i texel, Channels&& out) {
  if (format.depth) {
    channelRef(out, 0) = simd::Float8x2(_mm512_mul_ps(_mm512_cvtepi32_ps(texel), _mm512_set1_ps(format.depthScale)));
    channelRef(out, 1) = channelRef(out, 2) = simd::Float8x2(0.0f);
    channelRef(out, 3) = simd::Float8x2(1.0f);
    return;
  }
  const __m512 kUnorm8 = _mm512_set1_ps(float(1.0 / 255.0));
  for (int c = 0; c < 4; ++c) {
    const __m512i value = _mm512_and_si512(_mm512_srli_epi32(texel, 8 * c), _mm512_set1_epi32(0xFF));
    channelRef(out, c) = simd::Float8x2(_mm512_mul_ps(_mm512_cvtepi32_ps(value), kUnorm8));
  }
}

// One 32-bit texel a lane (an RGBA8 texel or a depth code) as float channels: into planes
// (Float8x2 out[4]) or a vec4.
template <class Channels>
[[gnu::always_inline]] inline void sampleNearest32Pair(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc,
                                                       Channels&& out) {
  const __m512i index = nearestTexelIndex16(s.v, tc.v, t.width, t.height, t.sampler.wrapS, t.sampler.wrapT);
  texelChannels32(texel32Format(t), loadTexels32(texels32(t), index, t.width), out);
}

// A texel plane's values (sampler.h, TexelPlane) at sixteen lanes' NEAREST texels, its index
// as every NEAREST lookup here computes it: one 4-byte load a lane, or four row loads where
// the lanes read a 4x4 block.
[[gnu::always_inline]] inline simd::Float8x2 samplePlanePair(const TexelPlane& plane, simd::Float8x2 s, simd::Float8x2 tc) {
  const __m512i index = nearestTexelIndex16(s.v, tc.v, plane.width, plane.height, plane.wrapS, plane.wrapT);
  const uint32_t* values = reinterpret_cast<const uint32_t*>(plane.values.data());
  return simd::Float8x2(_mm512_castsi512_ps(loadTexels32(values, index, plane.width)));
}

// The lanes of a CLAMP_TO_EDGE line (sampleNearest32Line) whose R taps either way are
// proven to land i texels from the centre by a margin, without computing them: tap +-i's
// texel is trunc(fl(fl(u +- fl(s * i)) * W)) for the coordinate u, the step s > 0 and the
// size W, and the centre's c = trunc(a0), a0 = fl(u * W), with R <= c <= W - 1 - R (the
// caller's end test, which also makes u >= 1 / W and t = u W just below W). Writing
// s W = 1 + eta (exact in double) and each rounding to nearest as (1 + e), |e| <= 2^-24
// (every value here is a normal float; an s too small for that makes |eta| about 1, which
// fails below):
//   tap value = (t +- i (1 + eta)(1 + e1)) (1 + e2)(1 + e3),
// which differs from t +- i by at most i |eta| + i (1 + |eta|) 2^-24 + (t + i (1 + |eta|)
// (1 + 2^-24)) (2^-23 + 2^-48) < delta = R |eta| + (W + 4R (1 + |eta|)) 2^-22; and |a0 - t|
// <= W 2^-24 <= delta / 4. So where a0 - c (exact: Sterbenz, a0 < c + 1 <= 2c) lies in
// [2 delta, 1 - 2 delta], every tap value lies strictly inside (c +- i, c +- i + 1),
// positive, and truncates to c +- i: the index the tap's own comparison would accept. Other
// lanes (near a texel boundary, or a step that is not one texel) are left to those
// comparisons; delta < 0.25 also bounds W below 2^20.
[[gnu::always_inline]] inline __mmask16 tapsApartByMargin16(__m512 along, int size, float stride, int R) {
  if (!(stride > 0.0f)) return 0;
  const double eta = std::fabs(double(stride) * double(size) - 1.0);
  const double delta = double(R) * eta + (double(size) + 4.0 * double(R) * (1.0 + eta)) * 0x1p-22;
  if (!(delta < 0.25)) return 0;
  const __m512 a0 = _mm512_mul_ps(along, _mm512_set1_ps(float(size)));
  const __m512 fraction = _mm512_sub_ps(a0, _mm512_roundscale_ps(a0, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
  // The bounds as floats, moved inward by more than a float's rounding (2^-24 of each).
  const float low = float(2.0 * delta * (1.0 + 0x1p-22)), high = float((1.0 - 2.0 * delta) * (1.0 - 0x1p-22));
  return _mm512_cmp_ps_mask(fraction, _mm512_set1_ps(low), _CMP_GE_OQ) &
         _mm512_cmp_ps_mask(fraction, _mm512_set1_ps(high), _CMP_LE_OQ);
}

// textureLine's N = 2R + 1 taps (sampler.h) where sampleNearest32Pair is the lookup, the
// line runs along x or along y (step.y or step.x is zero, as a separable filter's passes
// are), and the sixteen lanes are a 4x4 block (blockOffsets16) whose tap i lands i texels
// up the axis: out[i + R] = sampleNearest32Pair at uv + float(i) * step, bit for bit, and
// true.
// False, with nothing written, where the lanes or the line are otherwise.
//
// Every tap's index is still computed as the lone lookup computes it; only the loads are
// shared. Along x the taps read one window of 4 + 2R texels in each of the block's 4 rows,
// along y one 4-texel row in each of 4 + 2R rows, so a tap costs two permutes or one insert
// instead of four row loads and five shuffles. The offset along the other axis, 0 * i, adds
// +0 or -0: the coordinate itself, or a zero of the other sign, which wraps to the same
// texel (floor(0 * size) = 0 in every wrap), so that axis's index is computed once.
template <int N>
[[gnu::always_inline]] inline bool sampleNearest32Line(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc,
                                                       glm::vec2 step, glsl::vec4<simd::Float8x2> (&out)[N]) {
  constexpr int R = N / 2;
  static_assert(N % 2 == 1 && N <= 13, "a window of 4 + 2R texels fits one 512-bit register");
  const bool alongX = step.y == 0.0f, alongY = step.x == 0.0f;
  if (alongX == alongY) return false;   // a diagonal line, or no step at all
  const __m512 along = alongX ? s.v : tc.v;
  const float stride = alongX ? step.x : step.y;
  const int size = alongX ? t.width : t.height;
  const Wrap wrap = alongX ? t.sampler.wrapS : t.sampler.wrapT;
  // The coordinates along the line exactly as the lone lookups compute them: uv + step * i,
  // uv - step * i; `apart`: the lanes where each tap lands i texels from the centre's.
  const __m512i centreIndex = wrapNearest16(along, size, wrap);
  __mmask16 apart = 0xFFFF;
  if (wrap == Wrap::ClampToEdge) {
    // There a tap's texel is its truncated coordinate clamped to [0, size - 1]. Where the
    // truncation is the centre's plus i and every tap's texel lies inside (the centre at
    // least R from either end), the clamp changes nothing: the truncations alone are
    // compared, and the ends tested once.
    const __m512 sizeF = _mm512_set1_ps(float(size));
    apart = _mm512_cmpge_epi32_mask(centreIndex, _mm512_set1_epi32(R)) &
            _mm512_cmple_epi32_mask(centreIndex, _mm512_set1_epi32(size - 1 - R));
    // A block of a target's own pixels lies mid-texel: a margin proves every tap there.
    if ((apart & tapsApartByMargin16(along, size, stride, R)) != 0xFFFF) {
      for (int i = 1; i <= R; ++i) {
        const __m512 offset = _mm512_set1_ps(stride * float(i));
        const __m512i ahead = _mm512_cvttps_epi32(_mm512_mul_ps(_mm512_add_ps(along, offset), sizeF));
        const __m512i behind = _mm512_cvttps_epi32(_mm512_mul_ps(_mm512_sub_ps(along, offset), sizeF));
        apart &= _mm512_cmpeq_epi32_mask(ahead, _mm512_add_epi32(centreIndex, _mm512_set1_epi32(i)));
        apart &= _mm512_cmpeq_epi32_mask(behind, _mm512_sub_epi32(centreIndex, _mm512_set1_epi32(i)));
      }
    }
  } else {
    for (int i = 1; i <= R; ++i) {
      const __m512 offset = _mm512_set1_ps(stride * float(i));
      apart &= _mm512_cmpeq_epi32_mask(wrapNearest16(_mm512_add_ps(along, offset), size, wrap),
                                       _mm512_add_epi32(centreIndex, _mm512_set1_epi32(i)));
      apart &= _mm512_cmpeq_epi32_mask(wrapNearest16(_mm512_sub_ps(along, offset), size, wrap),
                                       _mm512_sub_epi32(centreIndex, _mm512_set1_epi32(i)));
    }
  }
  const __m512i across = alongX ? wrapNearest16(tc.v, t.height, t.sampler.wrapT) : wrapNearest16(s.v, t.width, t.sampler.wrapS);
  const __m512i x = alongX ? centreIndex : across, y = alongX ? across : centreIndex;
  const __m512i index = _mm512_add_epi32(_mm512_mullo_epi32(y, _mm512_set1_epi32(t.width)), x);
  int first;
  if ((apart & lanesInBlock16(index, t.width, first)) != 0xFFFF) return false;
  // From here every texel read is some tap's: the block's 4x4 texels moved by -R..R.
  const uint32_t* centre = texels32(t) + first;
  const Texel32Format format = texel32Format(t);
  // The rows the line reads: the block's 4, and along y R more above and below.
  prefetchBlockRowsAhead(t, size_t(first - (alongX ? 0 : R * t.width)), _mm_cvtsi128_si32(_mm512_castsi512_si128(x)),
                         alongX ? 4 : 4 + 2 * R);
  if (alongX) {
    // rows[r]: texels -R .. 3 + R of the block's row r (a masked load reads no further).
    constexpr __mmask16 kWindow = __mmask16((1u << (4 + 2 * R)) - 1);
    __m512i rows[4];
    for (int r = 0; r < 4; ++r) rows[r] = _mm512_maskz_loadu_epi32(kWindow, centre + ptrdiff_t(r) * t.width - R);
    for (int i = -R; i <= R; ++i) {
      // A half's lanes from rows r and r + 1: [r c0, r c1, r+1 c0, r+1 c1, r c2, r c3, r+1 c2, r+1 c3].
      const int c = i + R;
      const __m512i pick = _mm512_setr_epi32(c, c + 1, 16 + c, 17 + c, c + 2, c + 3, 18 + c, 19 + c, 0, 0, 0, 0, 0, 0, 0, 0);
      const __m512i low = _mm512_permutex2var_epi32(rows[0], pick, rows[1]);
      const __m512i high = _mm512_permutex2var_epi32(rows[2], pick, rows[3]);
      texelChannels32(format, _mm512_inserti64x4(low, _mm512_castsi512_si256(high), 1), out[i + R]);
    }
    return true;
  }
  // halves[k]: rows k - R and k - R + 1 of the block's 4 columns, in a half's lane order.
  __m256i halves[N + 2];
  __m128i row = _mm_loadu_si128(reinterpret_cast<const __m128i*>(centre - ptrdiff_t(R) * t.width));
  for (int k = 0; k < N + 2; ++k) {
    const __m128i next = _mm_loadu_si128(reinterpret_cast<const __m128i*>(centre + ptrdiff_t(k + 1 - R) * t.width));
    halves[k] = rowPairHalf(row, next);
    row = next;
  }
  for (int i = -R; i <= R; ++i)
    texelChannels32(format, _mm512_inserti64x4(_mm512_castsi256_si512(halves[i + R]), halves[i + R + 2], 1), out[i + R]);
  return true;
}

}  // namespace raster::sampling
#endif
