// The vector samplers against the scalar reference (sample_color.cpp), bit for bit: the
// 8-lane and paired lookups of sample_color_avx2.cpp, and the 16-lane ones in one AVX-512
// register that the ports make inline (sample_half_avx512.h, sample_rgba8_avx512.h,
// sample_nearest_avx512.h), on every wrap, filter, format and filter method.
// (sampler_test.cpp holds the reference to llvmpipe.)
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <utility>

#include "raster/methods.h"
#include "raster/texture/footprint_strips.h"
#include "raster/texture/format.h"
#include "raster/texture/sampler.h"
#include "tests/texture/lookup_test_helpers.h"

using namespace gltest;

TEST_SUITE("texture") {
#if RASTER_AVX2
  TEST_CASE("the 8-lane and paired samplers equal the scalar reference on every wrap, filter, format and filter method") {
    std::mt19937 rng(77);
    long mismatches = 0, lookups = 0;
    for (const raster::FilterMethod method : {raster::FilterMethod::Unorm8, raster::FilterMethod::Float}) {
    raster::MethodSet methods;
    methods.filter = method;
    const raster::ScopedMethods scoped(methods);
    // RGBA8 in rows and kept in strips alone (as uploads are where the 16-lane lookup reads
    // strips, footprint_strips.h), RGBA16F, RGBA32F, and grey RGBA8 (with the one-byte copy
    // the AVX2 sampler reads).
    for (const auto& [format, grey, strips] : {std::tuple{raster::TexelFormat::RGBA8, false, false},
                                               std::tuple{raster::TexelFormat::RGBA8, false, true},
                                               std::tuple{raster::TexelFormat::RGBA16F, false, false},
                                               std::tuple{raster::TexelFormat::RGBA32F, false, false},
                                               std::tuple{raster::TexelFormat::RGBA8, true, false}}) {
      for (const auto& [w, h] : {std::pair{16, 8}, std::pair{13, 7}, std::pair{1, 1}, std::pair{64, 3}, std::pair{3, 1001},
                                 std::pair{16384, 1}}) {
        raster::Texture tex = randomTexture(rng, w, h, format, grey);
        for (raster::Filter filter : {raster::Filter::Nearest, raster::Filter::Linear})
          for (raster::Wrap ws : {raster::Wrap::Repeat, raster::Wrap::ClampToEdge})
            for (raster::Wrap wt : {raster::Wrap::Repeat, raster::Wrap::ClampToEdge}) {
              tex.sampler = {filter, ws, wt, false};
              raster::Texture stripped;   // the strips variant's texture; the reference reads tex's rows
              if (strips) {
                stripped = tex;
                stripped.sampler.filter = raster::Filter::Linear;   // the copy is made for a bilinear filter
                if (raster::makeStripCopy(stripped)) raster::releaseRows(stripped);
                stripped.sampler = tex.sampler;
                REQUIRE((h < 2 || raster::texelsInStripsOnly(stripped)));
              }
              const raster::Texture& sampled = strips ? stripped : tex;
              for (int round = 0; round < 200; ++round) {
                // Lanes 0-7 go to the 8-lane lookups; all 16 to the paired ones (Float8x2).
                alignas(32) float s16[16], t16[16];
                for (int i = 0; i < 16; ++i) {
                  s16[i] = laneCoordinate(rng);
                  t16[i] = laneCoordinate(rng);
                }
                using raster::simd::Float8;
                Float8 out[4];
                // A prefetch of the same lanes first: it must take any coordinate (NaN, huge,
                // far outside) on any texture and change nothing that follows.
                raster::sampling::prefetchColor8(sampled, Float8::load(s16), Float8::load(t16));
                raster::sampling::sampleColor8(sampled, Float8::load(s16), Float8::load(t16), out);
                const Float8 sPair[2] = {Float8::load(s16), Float8::load(s16 + 8)};
                const Float8 tPair[2] = {Float8::load(t16), Float8::load(t16 + 8)};
                Float8 pair[2][4];
                raster::sampling::sampleColor8x2(sampled, sPair, tPair, pair);
                for (int i = 0; i < 16; ++i) {
                  float ref[4], refSampled[4];
                  raster::sampling::sampleColor(tex, s16[i], t16[i], ref);
                  raster::sampling::sampleColor(sampled, s16[i], t16[i], refSampled);   // the scalar reference from strips
                  for (int c = 0; c < 4; ++c) mismatches += !sameLookup(refSampled[c], ref[c]);
                  for (int c = 0; c < 4; ++c) {
                    const float paired = pair[i / 8][c][i % 8];
                    const float single = i < 8 ? out[c][i] : ref[c];
                    for (const float got : {single, paired}) {
                      if (sameLookup(got, ref[c])) continue;
                      if (++mismatches <= 3)
                        MESSAGE("mismatch: format " << int(format) << std::string(grey ? " grey" : "") << std::string(strips ? " strips" : "") << " " << w << "x" << h << " filter " << int(filter)
                                << " wrap " << int(ws) << int(wt) << " at (" << s16[i] << ", " << t16[i] << ") channel " << c
                                << ": SIMD " << got << " scalar " << ref[c]);
                    }
                  }
                  ++lookups;
                }
              }
            }
      }
    }
    }   // filter methods
    MESSAGE(lookups << " lookups, " << mismatches << " channel mismatches");
    CHECK(mismatches == 0);
  }
#endif
#if RASTER_ZMM_PAIRS
  TEST_CASE("Float8x2 lookups in one AVX-512 register equal the scalar reference, at the right edge or not") {
    std::mt19937 rng(79);
    const float specials[] = {-0.0f, 1.0f, 1e30f, -1e30f, 3e9f, std::nanf(""), std::numeric_limits<float>::infinity()};
    long mismatches = 0, lookups = 0, awayFromEdge = 0, repeatInline = 0;
    // RGBA8 under both filter methods (the 16-lane inline lookup is the 8-bit one), grey,
    // and kept in strips alone, as uploaded RGBA8 textures are (footprint_strips.h); depth
    // codes read through sampler2D (NEAREST inline, sample_nearest_avx512.h); RGBA32F.
    struct Variant {
      raster::TexelFormat format;
      bool grey;
      raster::FilterMethod method;
      bool strips = false;
    };
    for (const Variant variant : {Variant{raster::TexelFormat::RGBA16F, false, raster::FilterMethod::Unorm8},
                                  Variant{raster::TexelFormat::RGBA8, false, raster::FilterMethod::Unorm8},
                                  Variant{raster::TexelFormat::RGBA8, false, raster::FilterMethod::Unorm8, true},
                                  Variant{raster::TexelFormat::RGBA8, true, raster::FilterMethod::Unorm8},
                                  Variant{raster::TexelFormat::RGBA8, false, raster::FilterMethod::Float},
                                  Variant{raster::TexelFormat::RGBA8, false, raster::FilterMethod::Float, true},
                                  Variant{raster::TexelFormat::Depth24, false, raster::FilterMethod::Unorm8},
                                  Variant{raster::TexelFormat::Depth16, false, raster::FilterMethod::Unorm8},
                                  Variant{raster::TexelFormat::RGBA32F, false, raster::FilterMethod::Unorm8}}) {
      const raster::TexelFormat format = variant.format;
      raster::MethodSet methods;
      methods.filter = variant.method;
      const raster::ScopedMethods scoped(methods);
      for (const auto& [w, h] : {std::pair{320, 240}, std::pair{13, 7}, std::pair{2, 2}, std::pair{1, 3}, std::pair{16, 8}}) {
        raster::Texture tex = randomTexture(rng, w, h, format, variant.grey);
        for (raster::Filter filter : {raster::Filter::Linear, raster::Filter::Nearest})
          // Both axes alike, and each wrap along s with the other along t (an environment
          // map repeats along s and clamps along t); the ports' inline RGBA16F lookup takes
          // every one, sampleColor8x2 blends CLAMP_TO_EDGE along s in one register.
          for (const auto& [wrap, wrapT] : {std::pair{raster::Wrap::ClampToEdge, raster::Wrap::ClampToEdge},
                                            std::pair{raster::Wrap::Repeat, raster::Wrap::Repeat},
                                            std::pair{raster::Wrap::ClampToEdge, raster::Wrap::Repeat},
                                            std::pair{raster::Wrap::Repeat, raster::Wrap::ClampToEdge}}) {
            tex.sampler = {filter, wrap, wrapT, false};
            // The strip variant samples a copy kept in strips alone, as an upload is
            // (footprint_strips.h), under every sampler state; the reference reads the rows.
            raster::Texture stripped;
            if (variant.strips) {
              stripped = tex;
              stripped.sampler.filter = raster::Filter::Linear;   // the copy is made for a bilinear filter
              if (raster::makeStripCopy(stripped)) raster::releaseRows(stripped);
              stripped.sampler = tex.sampler;
              REQUIRE((h < 2 || raster::texelsInStripsOnly(stripped)));
            }
            const raster::Texture& sampled = variant.strips ? stripped : tex;
            for (int round = 0; round < 300; ++round) {
              // Pixel centres of a post pass's quads (the fast path's case), or anywhere.
              alignas(64) float s16[16], t16[16];
              const float scale = round % 3 == 0 ? 1.0f : round % 3 == 1 ? 2.0f : 0.5f;
              const int px = int(rng() % unsigned(std::max(1.0f, scale * float(w))));
              const int py = int(rng() % unsigned(std::max(1.0f, scale * float(h))));
              // Every other round of anywhere keeps s left of the right edge, so that the
              // one-register path also sees the special values (a NaN s must take the last texel).
              const float sMax = round % 8 == 3 ? (float(w) - 0.75f) / float(w) : 1.5f;
              // Even rounds lay the lanes out as a shaded block's (raster/simd/lane_layout.h:
              // rows 2-3 in lanes 8-15), which the NEAREST lookups of 32-bit texels read as
              // four rows where the block's texels are the texture's, every other one as a
              // window-system buffer's block (its memory rows swapped, so lanes 8-15 read
              // the lower texel rows): a post pass reading a target at its own resolution
              // takes either (blendHalfOwnResolution16). One in four of those reads its rows
              // upside down, as a mirrored lookup would (blendHalfWindow16 then finds its
              // window's corner in other lanes). Odd rounds side by side.
              const bool block = round % 2 == 0, swapped = round % 4 == 2, mirrored = round % 8 == 6;
              for (int i = 0; i < 16; ++i) {
                const int dx = (i % 8 / 4) * 2 + (i & 1) + (block ? 0 : (i / 8) * 4);
                const int blockRow = ((i >> 1) & 1) + (swapped ? 1 - i / 8 : i / 8) * 2;
                const int dy = block ? (mirrored ? 3 - blockRow : blockRow) : ((i >> 1) & 1);
                const bool centre = round % 4 != 3;
                s16[i] = centre ? (float(px + dx) + 0.5f) / (scale * float(w)) : uniform(rng, -0.5f, sMax);
                t16[i] = centre ? (float(py + dy) + 0.5f) / (scale * float(h)) : uniform(rng, -0.5f, 1.5f);
                if (!centre && rng() % 8 == 0) s16[i] = specials[rng() % std::size(specials)];
                if (!centre && rng() % 8 == 0) t16[i] = specials[rng() % std::size(specials)];
              }
              const raster::simd::Float8x2 s = raster::simd::Float8x2::load(s16), t = raster::simd::Float8x2::load(t16);
              raster::simd::Float8x2 planes[4];
              raster::sampling::sampleColor8x2(sampled, s, t, planes);
              // And through the shaders' own entry points (sampler_avx2.h), which take some
              // lookups inline (sample_half_avx512.h) rather than through sampleColor8x2.
              const raster::glsl::vec2<raster::simd::Float8x2> uv{s, t};
              raster::sampling::prefetchColor(sampled, uv);   // any coordinate, and nothing changes
              const auto viaPort = raster::sampling::lookupColor(sampled, uv);
              const raster::simd::Float8x2 port[4] = {viaPort.x, viaPort.y, viaPort.z, viaPort.w};
              bool edge = false;
              for (int i = 0; i < 16; ++i) {
                float ref[4], refSampled[4];
                raster::sampling::sampleColor(tex, s16[i], t16[i], ref);
                raster::sampling::sampleColor(sampled, s16[i], t16[i], refSampled);   // the scalar reference from strips
                for (int c = 0; c < 4; ++c) mismatches += !sameLookup(refSampled[c], ref[c]);
                edge = edge || std::min(s16[i] * float(w), float(w)) - 0.5f >= float(w - 1);
                for (int c = 0; c < 4; ++c) {
                  const float got = planes[c][i], gotPort = port[c][i];
                  if (sameLookup(got, ref[c]) && sameLookup(gotPort, ref[c])) continue;
                  if (++mismatches <= 3)
                    MESSAGE("mismatch: format " << int(format) << std::string(variant.grey ? " grey" : "") << " method "
                                                << int(variant.method) << " " << w << "x" << h << " at (" << s16[i] << ", "
                                                << t16[i] << ") channel " << c << ": SIMD " << got << " (via the port " << gotPort
                                                << ") scalar " << ref[c]);
                }
                ++lookups;
              }
              // The cases the one-register path takes (the others fall back to two halves).
              awayFromEdge += !edge && format == raster::TexelFormat::RGBA16F && filter == raster::Filter::Linear &&
                              wrap == raster::Wrap::ClampToEdge && w >= 2;
              // and with REPEAT along s, where every lane's footprint is inside the texture's
              // columns (s in [1.5, w - 1.5] texels), none split by the seam
              const bool inside = std::all_of(s16, s16 + 16, [&](float v) {
                return v >= 1.5f / float(w) && v <= (float(w) - 1.5f) / float(w);
              });
              repeatInline += inside && format == raster::TexelFormat::RGBA16F && filter == raster::Filter::Linear &&
                              wrap == raster::Wrap::Repeat && w >= 2;
            }
          }
      }
    }
    MESSAGE(lookups << " lookups; on the one-register path " << awayFromEdge << " groups clamping along s, " << repeatInline
                    << " repeating; " << mismatches << " channel mismatches");
    CHECK(awayFromEdge > 200);   // the one-register path ran, not only the fallback
    CHECK(repeatInline > 200);
    CHECK(mismatches == 0);
  }

  TEST_CASE("a REPEAT lookup in a tile that holds only a clear: a NaN or infinite coordinate still blends to NaN") {
    // The inline RGBA16F lookup returns a cleared tile's value without a fetch
    // (cleared_tiles.h), which holds only for finite weights. CLAMP_TO_EDGE's always are;
    // REPEAT's weight for a NaN or infinite coordinate is NaN, and the blend of four equal
    // texels with it is NaN, so a REPEAT lookup must not take that shortcut.
    raster::Texture tex(64, 64, raster::TexelFormat::RGBA16F);
    const float value[4] = {0.25f, 1.5f, -3.0f, 0.75f};
    for (size_t i = 0; i < tex.half.size(); ++i) tex.half[i] = raster::format::halfFromFloatTowardZero(value[i % 4]);
    tex.clearedTiles.tilesX = 1;
    tex.clearedTiles.cleared = {1};
    for (int c = 0; c < 4; ++c) tex.clearedTiles.value[c] = value[c];
    std::mt19937 rng(80);
    long mismatches = 0;
    for (raster::Wrap wrap : {raster::Wrap::Repeat, raster::Wrap::ClampToEdge}) {
      tex.sampler = {raster::Filter::Linear, wrap, wrap, false};
      const float specials[] = {std::nanf(""), std::numeric_limits<float>::infinity(),
                                -std::numeric_limits<float>::infinity(), 0.3f};
      for (int round = 0; round < 64; ++round) {
        alignas(64) float s16[16], t16[16];
        for (int i = 0; i < 16; ++i) {
          s16[i] = rng() % 4 == 0 ? specials[rng() % std::size(specials)] : uniform(rng, 0.1f, 0.4f);
          t16[i] = rng() % 4 == 0 ? specials[rng() % std::size(specials)] : uniform(rng, 0.1f, 0.4f);
        }
        const raster::glsl::vec2<raster::simd::Float8x2> uv{raster::simd::Float8x2::load(s16),
                                                            raster::simd::Float8x2::load(t16)};
        const auto got = raster::sampling::lookupColor(tex, uv);
        const raster::simd::Float8x2 planes[4] = {got.x, got.y, got.z, got.w};
        for (int i = 0; i < 16; ++i) {
          float ref[4];
          raster::sampling::sampleColor(tex, s16[i], t16[i], ref);
          for (int c = 0; c < 4; ++c) mismatches += !sameLookup(planes[c][i], ref[c]);
        }
      }
    }
    CHECK(mismatches == 0);
  }
#endif
}
