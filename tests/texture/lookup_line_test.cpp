// textureLine (a separable filter's taps along x or y, as pbr's SSAO blur makes them), 8 and
// 16 lanes, against the lone scalar lookup of every tap: blocks of a target's pixels whose
// taps land one texel apart (the 16-lane shared path, along x and along y), blocks at the
// texture's edges where the taps clamp or wrap, steps that are not one texel, diagonal
// lines, scattered lanes, and every format and filter (the others take the lone lookups).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <random>

#include "raster/texture/sampler.h"
#include "raster/simd/lane_layout.h"
#include "tests/gl_compare_helpers.h"
#include "tests/texture/lookup_test_helpers.h"

using namespace gltest;

TEST_SUITE("texture") {
#if RASTER_AVX2
  // What lineTapsAgainstScalar saw: taps, channel mismatches, and lines the 16-lane shared
  // path took, by axis.
  struct LineCounts {
    long taps = 0, mismatches = 0, sharedAlongX = 0, sharedAlongY = 0;
  };

  // Every tap of textureLine<R> for `Lanes` (Float8, or Float8x2 with its 16-lane path)
  // against its lone scalar lookup at uv + step * float(i) or uv - step * float(i).
  template <class Lanes, int R>
  LineCounts lineTapsAgainstScalar(std::mt19937& rng) {
    constexpr int kLanes = int(sizeof(Lanes) / sizeof(float)), N = 2 * R + 1;
    const raster::LaneLayout<raster::simd::Float8> layout(false, 0);   // a block's lanes, as the pipeline lays them out
    LineCounts counts;
    const raster::TexelFormat formats[] = {raster::TexelFormat::RGBA8, raster::TexelFormat::Depth24,
                                           raster::TexelFormat::Depth16, raster::TexelFormat::RGBA16F};
    for (raster::TexelFormat format : formats) {
      for (const auto& [w, h] : {std::pair{128, 96}, std::pair{13, 7}, std::pair{16, 16}, std::pair{4, 4}, std::pair{2, 1}}) {
        const raster::Texture base = randomTexture(rng, w, h, format);
        for (raster::Wrap wrap : {raster::Wrap::ClampToEdge, raster::Wrap::Repeat})
          for (raster::Filter filter : {raster::Filter::Nearest, raster::Filter::Linear}) {
            if (filter == raster::Filter::Linear && base.isDepth()) continue;   // a sampler2D of depth: NEAREST in the scenes
            raster::Texture tex = base;
            tex.sampler = {filter, wrap, wrap, false};
            for (int round = 0; round < 120; ++round) {
              // Most rounds: one 4x4 block of a target the texture's size, laid out as the
              // pipeline lays out a block's lanes, at the first, the last or any block of a
              // row and column (so taps clamp or wrap at the edges). Some rounds scatter the
              // lanes anywhere, special values among them.
              alignas(64) float s16[16], t16[16];
              auto blockAt = [&](int size) {
                const int blocks = (size + 3) / 4;
                const unsigned pick = rng() % 3;
                return 4 * (pick == 0 ? 0 : pick == 1 ? blocks - 1 : int(rng() % unsigned(blocks)));
              };
              const int blockX = blockAt(w), blockY = blockAt(h);
              const bool scattered = round % 7 == 6;
              for (int i = 0; i < 16; ++i) {
                const int group = i / 8, lane = i % 8;
                const int x = std::min(blockX + layout.originX(group) + layout.dx[lane], w - 1);
                const int y = std::min(blockY + layout.originY(group) + layout.dy[lane], h - 1);
                s16[i] = scattered ? laneCoordinate(rng) : (float(x) + 0.5f) / float(w);
                t16[i] = scattered ? laneCoordinate(rng) : (float(y) + 0.5f) / float(h);
              }
              // The blur's steps (one texel along x, along y; either way round, and with a
              // zero of either sign), two texels, and a diagonal.
              const glm::vec2 steps[] = {{1.0f / float(w), 0.0f},  {0.0f, 1.0f / float(h)},  {-1.0f / float(w), -0.0f},
                                         {-0.0f, -1.0f / float(h)}, {2.0f / float(w), 0.0f}, {1.0f / float(w), 1.0f / float(h)}};
              const glm::vec2 step = steps[round % std::size(steps)];
              raster::Sampler2D sampler;
              sampler.texture = &tex;
              for (int first = 0; first < 16; first += kLanes) {
                const auto uv = raster::glsl::vec2<Lanes>(Lanes::load(s16 + first), Lanes::load(t16 + first));
                raster::glsl::vec4<Lanes> taps[N];
                raster::textureLine<R>(sampler, uv, step, taps);
#if RASTER_ZMM_PAIRS
                if constexpr (kLanes == 16) {
                  raster::glsl::vec4<raster::simd::Float8x2> planes[N];
                  const bool shared = raster::sampling::isNearest32(tex) &&
                                      raster::sampling::sampleNearest32Line(tex, uv.x, uv.y, step, planes);
                  counts.sharedAlongX += shared && step.y == 0.0f;
                  counts.sharedAlongY += shared && step.x == 0.0f;
                }
#endif
                for (int k = 0; k < N; ++k) {
                  alignas(64) float got[4][kLanes];
                  taps[k].x.store(got[0]), taps[k].y.store(got[1]), taps[k].z.store(got[2]), taps[k].w.store(got[3]);
                  const int i = k - R;   // the tap's place on the line, as the shader computes it
                  const float along = float(i < 0 ? -i : i);
                  for (int lane = 0; lane < kLanes; ++lane) {
                    const float s = s16[first + lane], t = t16[first + lane];
                    float ref[4];
                    if (i == 0) raster::sampling::sampleColor(tex, s, t, ref);
                    else if (i > 0) raster::sampling::sampleColor(tex, s + step.x * along, t + step.y * along, ref);
                    else raster::sampling::sampleColor(tex, s - step.x * along, t - step.y * along, ref);
                    for (int c = 0; c < 4; ++c) counts.mismatches += !sameLookup(got[c][lane], ref[c]);
                    ++counts.taps;
                  }
                }
              }
            }
          }
      }
    }
    return counts;
  }

  TEST_CASE("lookup lines: every tap equals its lone scalar lookup (8 lanes, the reference's order)") {
    std::mt19937 rng(2026);
    const LineCounts counts = lineTapsAgainstScalar<raster::simd::Float8, 4>(rng);
    MESSAGE(counts.taps << " line taps, " << counts.mismatches << " channel mismatches");
    CHECK(counts.taps == 5L * 120 * 9 * 16 * (2 * 2 * 2 + 2 * 2 * 1));   // colour formats with both filters, depth nearest
    CHECK(counts.mismatches == 0);
  }
#if RASTER_ZMM_PAIRS
  TEST_CASE("lookup lines on 16 lanes (Float8x2): every tap equals its lone scalar lookup, shared texels or not") {
    std::mt19937 rng(2027);
    for (const int r : {4, 2, 6}) {
      CAPTURE(r);
      const LineCounts counts = r == 4   ? lineTapsAgainstScalar<raster::simd::Float8x2, 4>(rng)
                                : r == 2 ? lineTapsAgainstScalar<raster::simd::Float8x2, 2>(rng)
                                         : lineTapsAgainstScalar<raster::simd::Float8x2, 6>(rng);
      MESSAGE(counts.taps << " line taps of " << 2 * r + 1 << ", " << counts.mismatches << " channel mismatches, "
                          << counts.sharedAlongX << " lines shared along x, " << counts.sharedAlongY << " along y");
      CHECK(counts.sharedAlongX > 20);   // the shared path ran, each way
      CHECK(counts.sharedAlongY > 20);
      CHECK(counts.mismatches == 0);
    }
  }

  // tapsApartByMargin16 skips the comparison of each tap's texel where a margin proves it: for
  // every lane it accepts, tap +-i must truncate to the centre's texel +-i. Coordinates near
  // texel boundaries (fractions at and around the margin), sizes up to 16384 and steps off
  // one texel by up to 1e-3 put the bound to the test; every tap is computed as the line
  // computes it (fl(fl(u +- fl(s * i)) * W)).
  TEST_CASE("lookup lines on 16 lanes: a lane the margin accepts has every tap one texel apart") {
    std::mt19937 rng(2028);
    long accepted = 0, rejected = 0, wrong = 0;
    for (int round = 0; round < 20000; ++round) {
      const int size = std::array{16, 640, 1080, 4096, 16384}[size_t(round % 5)];
      const int r = std::array{2, 4, 6}[size_t(round / 5 % 3)];
      const float etaWanted = std::array{0.0f, 1e-7f, -1e-7f, 1e-5f, -3e-5f, 1e-3f}[size_t(rng() % 6)];
      const float stride = (1.0f + etaWanted) / float(size);
      alignas(64) float u[16];
      for (float& lane : u) {
        const int c = r + int(rng() % unsigned(size - 2 * r));   // inside the end test
        // A fraction anywhere, or within 0.02 of a boundary, where the margin decides.
        const float f = rng() % 2 ? float(rng() % 100000) / 100000.0f : float(rng() % 20000) / 1e6f;
        lane = (float(c) + (rng() % 2 ? f : 1.0f - f)) / float(size);
      }
      const uint32_t lanes = raster::sampling::tapsApartByMargin16(raster::simd::Float8x2::load(u).v, size, stride, r);
      for (int lane = 0; lane < 16; ++lane) {
        const float a0 = u[lane] * float(size);
        const int c = int(a0);
        if (!(lanes >> lane & 1) || c < r || c > size - 1 - r) {
          ++rejected;
          continue;
        }
        ++accepted;
        for (int i = 1; i <= r; ++i) {
          const float offset = stride * float(i);
          wrong += int((u[lane] + offset) * float(size)) != c + i;
          wrong += int((u[lane] - offset) * float(size)) != c - i;
        }
      }
    }
    MESSAGE(accepted << " lanes accepted, " << rejected << " left to the comparisons");
    CHECK(wrong == 0);
    CHECK(accepted > 100000);
    CHECK(rejected > 10000);
  }
#endif
#endif
}
