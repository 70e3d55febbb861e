// textureGrid3x3 (the bloom passes' 3x3 grids of bilinear lookups), 8 and 16 lanes, against
// the lone scalar lookup of every tap: shared texels, textures small enough that every tap
// clamps, and, on 16 lanes, each form of the grid that picks texels at a texture's edge.
#include <doctest/doctest.h>

#include <algorithm>
#include <iterator>
#include <random>

#include "raster/texture/sampler.h"
#include "raster/simd/lane_layout.h"
#include "tests/gl_compare_helpers.h"
#include "tests/texture/lookup_test_helpers.h"

using namespace gltest;

TEST_SUITE("texture") {
#if RASTER_AVX2
  // What gridTapsAgainstScalar saw: taps and channel mismatches, grids that took the 16-lane
  // shared path, and those of them whose taps some edge piled onto the same texels, by the
  // axes that were not in place (only down the rows, only along them, or both).
  struct GridCounts {
    long taps = 0, mismatches = 0, shared16 = 0;
    long pickedRows = 0, pickedColumns = 0, pickedBoth = 0;
    long separable = 0;   // grids whose coordinates follow the block's columns and rows
    long strided = 0;     // and those whose columns lie two texels apart (a downsample's)
  };

  // Every tap of textureGrid3x3 for `Lanes` (Float8, or Float8x2 with its 16-lane path)
  // against its lone scalar lookup.
  template <class Lanes>
  GridCounts gridTapsAgainstScalar() {
    constexpr int kLanes = int(sizeof(Lanes) / sizeof(float));
    std::mt19937 rng(78);
    const raster::LaneLayout<raster::simd::Float8> layout(false, 0);   // a block's lanes, as the pipeline lays them out
    GridCounts counts;
    for (raster::TexelFormat format : {raster::TexelFormat::RGBA16F, raster::TexelFormat::RGBA8}) {
      for (const auto& [w, h] : {std::pair{320, 240}, std::pair{13, 7}, std::pair{4, 4}, std::pair{2, 1}}) {
        raster::Texture tex = randomTexture(rng, w, h, format);
        // Some infinite and negative-zero texels: a tap that takes the wrong neighbour with
        // a zero weight still gives the same value for finite texels, but not next to these.
        const uint16_t specials[] = {0x7C00, 0xFC00, 0x8000};
        for (uint16_t& v : tex.half)
          if (rng() % 16 == 0) v = specials[rng() % std::size(specials)];
        for (raster::Wrap wrap : {raster::Wrap::ClampToEdge, raster::Wrap::Repeat}) {
          tex.sampler = {raster::Filter::Linear, wrap, wrap, false};
          for (int round = 0; round < 300; ++round) {
            alignas(64) float s16[kLanes], t16[kLanes];
            // Pixel centres of a target twice the size (as the bloom upsample reads) or half
            // (the downsample), or anywhere; in most rounds every lane, so that the vector
            // forms' shared paths (which need all lanes one texel apart) are taken.
            // Every third round the lanes are one 4x4 block of that target, laid out as the
            // pipeline lays out a block's lanes (lane_layout.h): a block on one edge of the
            // texture has its taps in place along the other axis, as the bloom passes' border
            // blocks do. Such a block of a target twice the size (or the same size) is what
            // the separable 16-lane path takes: each tap the same down a block column.
            const int scale = round % 4 == 3 ? 1 : 2;
            const int cols = round % 2 ? scale * w : std::max(w / scale, 1);
            const int rows = round % 2 ? scale * h : std::max(h / scale, 1);
            const bool asBlock = round % 3 == 0;
            // The block's column and row of blocks: the first, the last or any, so that
            // blocks on one edge and in a corner are both common. A block of a target half the
            // size away from the edges is what the strided 16-lane path takes.
            auto blockAt = [&](int size) {
              const int blocks = (size + 3) / 4;
              const unsigned pick = rng() % 3;
              return 4 * (pick == 0 ? 0 : pick == 1 ? blocks - 1 : int(rng() % unsigned(blocks)));
            };
            const int blockX = blockAt(cols), blockY = blockAt(rows);
            for (int i = 0; i < kLanes; ++i) {
              if (asBlock) {
                const int group = (i % 16) / 8, lane = i % 8;
                const int x = std::min(blockX + layout.originX(group) + layout.dx[lane], cols - 1);
                const int y = std::min(blockY + layout.originY(group) + layout.dy[lane], rows - 1);
                s16[i] = (float(x) + 0.5f) / float(cols);
                t16[i] = (float(y) + 0.5f) / float(rows);
                continue;
              }
              const bool centre = round % 5 != 4 || i % 3 != 0;
              s16[i] = centre ? (float(rng() % unsigned(cols)) + 0.5f) / float(cols) : uniform(rng, -0.2f, 1.2f);
              t16[i] = centre ? (float(rng() % unsigned(rows)) + 0.5f) / float(rows) : uniform(rng, -0.2f, 1.2f);
            }
            // One texel (the bloom passes' step), a step that is not one texel, and none.
            const glm::vec2 steps[3] = {{1.0f / float(w), 1.0f / float(h)}, {0.37f / float(w), 1.9f / float(h)}, {0.0f, 0.0f}};
            const glm::vec2 step = steps[round % 3];
            raster::Sampler2D sampler;
            sampler.texture = &tex;
            raster::glsl::vec4<Lanes> grid[3][3];
            raster::textureGrid3x3(sampler, raster::glsl::vec2<Lanes>(Lanes::load(s16), Lanes::load(t16)), step, grid);
#if RASTER_ZMM_PAIRS
            if constexpr (kLanes == 16) {
              raster::simd::Float8x2 planes[9][4];
              const auto s = Lanes::load(s16).v, t = Lanes::load(t16).v;
              raster::sampling::LinearTaps16 x[3], y[3];
              raster::sampling::bloomGridTaps16(tex, s, t, step.x, step.y, x, y);
              const bool shared = raster::sampling::isHalfBilinearClamp(tex) &&
                                  raster::sampling::blendHalfGrid16(tex, x, y, planes);
              const bool inPlaceX = raster::sampling::axisTapsAreConsecutive16(x, 3);
              const bool inPlaceY = raster::sampling::axisTapsAreConsecutive16(y, 3);
              counts.shared16 += shared;
              counts.pickedRows += shared && inPlaceX && !inPlaceY;      // a top or bottom edge
              counts.pickedColumns += shared && !inPlaceX && inPlaceY;   // a left or right edge
              counts.pickedBoth += shared && !inPlaceX && !inPlaceY;
              raster::simd::Float8x2 separablePlanes[9][4];
              counts.separable += shared && raster::sampling::mayBeSeparable16(tex, s, t) &&
                                  raster::sampling::blendHalfGridSeparable16(tex, s, t, step.x, step.y, separablePlanes);
              counts.strided += shared && raster::sampling::blendHalfGridStrided16(tex, s, t, step.x, step.y, separablePlanes);
            }
#endif
            for (int j = 0; j < 3; ++j)
              for (int k = 0; k < 3; ++k) {
                alignas(64) float got[4][kLanes];
                grid[j][k].x.store(got[0]), grid[j][k].y.store(got[1]);
                grid[j][k].z.store(got[2]), grid[j][k].w.store(got[3]);
                for (int i = 0; i < kLanes; ++i) {
                  float ref[4];
                  const float s = s16[i] + float(k - 1) * step.x, t = t16[i] + float(j - 1) * step.y;
                  raster::sampling::sampleColor(tex, s, t, ref);
                  for (int c = 0; c < 4; ++c) counts.mismatches += bitsOf(got[c][i]) != bitsOf(ref[c]);
                  ++counts.taps;
                }
              }
          }
        }
      }
    }
    return counts;
  }

  TEST_CASE("3x3 lookup grids: every tap equals its lone scalar lookup, shared texels or not") {
    const GridCounts counts = gridTapsAgainstScalar<raster::simd::Float8>();
    MESSAGE(counts.taps << " grid taps, " << counts.mismatches << " channel mismatches");
    CHECK(counts.taps == 2 * 4 * 2 * 300 * 9 * 8);
    CHECK(counts.mismatches == 0);
  }
#if RASTER_ZMM_PAIRS
  TEST_CASE("3x3 lookup grids on 16 lanes (Float8x2): every tap equals its lone scalar lookup") {
    const GridCounts counts = gridTapsAgainstScalar<raster::simd::Float8x2>();
    MESSAGE(counts.taps << " grid taps, " << counts.mismatches << " channel mismatches, " << counts.shared16
                        << " grids on the 16-lane path, picking texels at an edge: " << counts.pickedRows
                        << " down the rows only, " << counts.pickedColumns << " along them only, " << counts.pickedBoth
                        << " both, " << counts.separable << " separable, " << counts.strided << " strided");
    CHECK(counts.taps == 2 * 4 * 2 * 300 * 9 * 16);
    CHECK(counts.shared16 > 20);   // the 16-lane path ran, not only the 8-lane fallback
    // and each of its edge forms
    CHECK(counts.pickedRows > 10);
    CHECK(counts.pickedColumns > 10);
    CHECK(counts.pickedBoth > 10);
    CHECK(counts.separable > 10);
    CHECK(counts.strided > 5);
    CHECK(counts.mismatches == 0);
  }
#endif
#endif
}
