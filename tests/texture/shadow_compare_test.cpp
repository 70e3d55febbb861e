// sampler2DShadow lookups (LINEAR, CLAMP_TO_EDGE, LEQUAL) against GL (llvmpipe), with
// shaders_cpp/test/shadow_lookup.{vert,frag,h}: out = (texture(shadow_map, (u, v, ref)), 0, 0, 1).
//
// 1. A 64x48 Depth24 shadow map is rendered by both backends from ~40 random passthrough
//    triangles into a depth-only FBO; the depth codes must be identical.
// 2. Each backend samples its own map: a 128x128 RGBA16F target is tiled with 2x2-pixel
//    squares (each exactly one quad), every square with its own constant (u, v, ref), so
//    interpolation is exact and each lookup is one known input. Inputs include u/v outside
//    [0, 1], on texel centres (i + 0.5)/W and edges i/W (and their float neighbours), refs
//    outside [0, 1], and refs equal to a stored texel value (code * float(1/16777215) and
//    float(code / 16777215.0)) and their float neighbours. Results must be bit-identical.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "raster/methods.h"
#include "raster/texture/format.h"
#include "raster/texture/sampler.h"
#include "tests/gl_compare_helpers.h"

namespace {

using namespace gltest;

constexpr int kMapWidth = 64, kMapHeight = 48;
constexpr int kTarget = 128, kCell = 2;
constexpr int kLookupsPerDraw = (kTarget / kCell) * (kTarget / kCell);

// ~40 random passthrough triangles over (and past) the map, at random depths.
MeshData shadowCasters(std::mt19937& rng) {
  std::vector<Vertex> vertices;
  for (int i = 0; i < 40; ++i) {
    const glm::vec2 c(uniform(rng, -0.2f, 1.2f) * kMapWidth, uniform(rng, -0.2f, 1.2f) * kMapHeight);
    const float radius = uniform(rng, 4.0f, 30.0f);
    for (int v = 0; v < 3; ++v) {
      const glm::vec2 p = c + glm::vec2(uniform(rng, -radius, radius), uniform(rng, -radius, radius));
      vertices.push_back({clipFromWindow(p, uniform(rng, -0.98f, 0.98f), uniform(rng, 0.5f, 3.0f), kMapWidth, kMapHeight),
                          glm::vec4(1.0f)});
    }
  }
  return makeMesh(vertices);
}

// The lookup inputs: (u, v, ref), drawn from the interesting classes in turn.
std::vector<glm::vec3> lookups(std::mt19937& rng, const std::vector<uint32_t>& codes, int count) {
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  auto neighbour = [&](float x) {
    switch (pick(5)) {
      case 0: return std::nextafter(x, -INFINITY);
      case 1: return std::nextafter(x, INFINITY);
      default: return x;
    }
  };
  // A coordinate along an axis of `size` texels.
  auto coordinate = [&](int size) {
    switch (pick(5)) {
      case 0: return uniform(rng, 0.0f, 1.0f);
      case 1: return uniform(rng, -0.6f, 1.6f);                                    // outside [0, 1] too
      case 2: return neighbour((float(pick(size)) + 0.5f) / float(size));          // texel centres
      case 3: return neighbour(float(pick(size + 1)) / float(size));               // texel edges, 0 and 1
      default: return neighbour(float(pick(4 * size + 1)) / float(4 * size));      // quarter texels
    }
  };
  std::vector<glm::vec3> out;
  for (int i = 0; i < count; ++i) {
    const float u = coordinate(kMapWidth), v = coordinate(kMapHeight);
    // The texel nearest (u, v) (clamped): refs equal to its stored value hit the compare's edge.
    const int tx = std::clamp(int(std::floor(u * kMapWidth)), 0, kMapWidth - 1);
    const int ty = std::clamp(int(std::floor(v * kMapHeight)), 0, kMapHeight - 1);
    const uint32_t code = codes[size_t(kMapHeight - 1 - ty) * kMapWidth + size_t(tx)];   // read-back is top row first
    float ref = 0.0f;
    switch (pick(6)) {
      case 0: ref = uniform(rng, 0.0f, 1.0f); break;
      case 1: ref = uniform(rng, -0.5f, 1.5f); break;                                       // outside [0, 1]
      case 2: ref = neighbour(raster::format::depth24ToFloat(code)); break;                 // the texel as sampled
      case 3: ref = neighbour(float(double(code) / 16777215.0)); break;                     // code / (2^24 - 1)
      case 4: ref = neighbour(pick(2) ? 1.0f : 0.0f); break;
      default: ref = neighbour(raster::format::depth24ToFloat(codes[size_t(pick(int(codes.size())))])); break;
    }
    out.emplace_back(u, v, ref);
  }
  return out;
}

}  // namespace

TEST_SUITE("shadow_compare") {
  TEST_CASE("shadow lookups of a rendered Depth24 map are bit-identical to GL") {
    std::mt19937 rng(7007);
    const MeshData casters = shadowCasters(rng);
    const int kDraws = 3;
    std::vector<std::vector<glm::vec3>> inputs(kDraws);

    // Each backend renders its map and samples it; the inputs are chosen from the GL map
    // (identical to ours once the first check passes), so GL runs first.
    struct Result {
      ImageData depth;
      std::vector<ImageData> lookups;
    };
    auto run = [&](Backend& backend) {
      Result result;
      scenes::TextureDesc mapDesc{kMapWidth, kMapHeight, TexelFormat::Depth24, {}};
      mapDesc.sampler.filter = scenes::Filter::Linear;
      mapDesc.sampler.wrapS = mapDesc.sampler.wrapT = scenes::Wrap::ClampToEdge;
      mapDesc.sampler.compareLequal = true;
      const Handle map = backend.createTexture(mapDesc);
      scenes::FramebufferDesc depthOnly;
      depthOnly.depthTexture = map;
      const Handle mapFb = backend.createFramebuffer(depthOnly);
      ClearOp clearDepth;
      clearDepth.depth = true;
      clearDepth.depthValue = 1.0f;
      backend.beginPass(mapFb, {0, 0, kMapWidth, kMapHeight}, clearDepth);
      backend.draw(backend.createProgram("test/passthrough"), backend.createMesh(casters), DrawState{});
      backend.finish();
      result.depth = backend.readDepth(mapFb);
      if (inputs[0].empty())
        for (auto& in : inputs) in = lookups(rng, result.depth.depth, kLookupsPerDraw);

      const Handle program = backend.createProgram("test/shadow_lookup");
      backend.bindTexture(0, map);
      backend.setUniform(program, "shadow_map", 0);
      scenes::FramebufferDesc colorOnly;
      colorOnly.colorTextures = {backend.createTexture({kTarget, kTarget, TexelFormat::RGBA16F, {}})};
      const Handle target = backend.createFramebuffer(colorOnly);
      for (const auto& in : inputs) {
        const MeshData grid = gridMesh(kTarget, kTarget, kCell, [&](int column, int row) {
          const glm::vec3& l = in[size_t(row) * (kTarget / kCell) + size_t(column)];
          return GridCell{glm::vec4(l, 0.0f), 0.0f};
        });
        ClearOp clear;
        clear.color = true;
        clear.colorValue = glm::vec4(-1.0f);
        backend.beginPass(target, {0, 0, kTarget, kTarget}, clear);
        DrawState state;
        state.depthTest = false;
        backend.draw(program, backend.createMesh(grid), state);
        backend.finish();
        result.lookups.push_back(backend.readColor(target));
      }
      return result;
    };
    Result gl, ours;
    {
      auto backend = scenes::makeGlBackend();
      gl = run(*backend);
    }
    {
      auto backend = scenes::makeRasterBackend(0);
      ours = run(*backend);
    }

    const DepthComparison depth = compareDepth(ours.depth, gl.depth);
    int cleared = 0;
    for (uint32_t code : gl.depth.depth) cleared += code == 0xFFFFFFu;
    MESSAGE("shadow map: " << kMapWidth * kMapHeight - cleared << " texels drawn, " << depth.diffs << " differ (max "
                           << depth.maxDiff << " LSB)");
    CAPTURE(depth.firstDiff);
    REQUIRE(depth.diffs == 0);
    CHECK(cleared > 0);
    CHECK(cleared < kMapWidth * kMapHeight / 2);

    int diffs = 0, partial = 0, zeros = 0, ones = 0;
    std::string firstDiff;
    for (int d = 0; d < kDraws; ++d) {
      const FloatComparison cmp = compareFloatBits(ours.lookups[size_t(d)], gl.lookups[size_t(d)]);
      diffs += cmp.diffs;
      if (firstDiff.empty() && cmp.diffs) firstDiff = "draw " + std::to_string(d) + ", " + cmp.firstDiff;
      const std::vector<float>& f = gl.lookups[size_t(d)].floats;
      for (size_t i = 0; i < f.size(); i += 4) {
        zeros += f[i] == 0.0f;
        ones += f[i] == 1.0f;
        partial += f[i] > 0.0f && f[i] < 1.0f;
      }
    }
    // Every lookup covers 4 pixels; count lookups.
    MESSAGE("shadow lookups: " << kDraws * kLookupsPerDraw << " inputs (" << zeros / 4 << " give 0, " << ones / 4
                               << " give 1, " << partial / 4 << " in between); pixels differing from GL: " << diffs);
    CAPTURE(firstDiff);
    CHECK(diffs == 0);
    CHECK(zeros + ones + partial == kDraws * kTarget * kTarget);   // every pixel written
    CHECK(partial > kDraws * kLookupsPerDraw / 20);                // the filter's fractions are exercised
  }
#if RASTER_AVX2
  TEST_CASE("PCF grids, lone and paired: every tap equals its lone lookup, shared texels or not, either compare method") {
    using raster::simd::Float8;
    std::mt19937 rng(8008);
    long lanesCompared = 0;
#if RASTER_ZMM_PAIRS
    long edgeGrids16 = 0;   // paired grids made on 16 lanes where an edge piles taps together
#endif
    using raster::CompareMethod, raster::TexelFormat;
    const std::pair<CompareMethod, TexelFormat> cases[] = {{CompareMethod::Bilinear, TexelFormat::Depth24},
                                                           {CompareMethod::Bilinear, TexelFormat::Depth16},
                                                           {CompareMethod::Nearest, TexelFormat::Depth24},
                                                           {CompareMethod::Nearest, TexelFormat::Depth16}};
    for (const auto& [method, format] : cases) {
      raster::MethodSet methods;
      methods.compare = method;
      const raster::ScopedMethods scoped(methods);
      CAPTURE(raster::methodName(methods, "compare"));
      for (const auto& [width, height] : {std::pair{1024, 1024}, std::pair{37, 29}, std::pair{6, 7}}) {
        raster::Texture map(width, height, format);
        const uint32_t maxCode = format == raster::TexelFormat::Depth24 ? 0xFFFFFFu : 0xFFFFu;
        // Codes around one depth, so the references fall on both sides of neighbouring texels.
        for (uint32_t& code : map.depth) code = maxCode / 2 + rng() % (maxCode / 64);
        raster::Sampler2DShadow sampler;
        sampler.texture = &map;
        std::uniform_real_distribution<float> unit(-0.05f, 1.05f), jitter(-2e-7f, 2e-7f);
        for (int round = 0; round < 600; ++round) {
          alignas(32) float s[8], t[8], ref[8];
          for (int l = 0; l < 8; ++l) {
            // Half the lanes on texel centres and edges (rounding), half anywhere (clamping).
            const bool onGrid = (round + l) % 2 == 0;
            s[l] = onGrid ? (float(rng() % unsigned(width)) + 0.5f * float(rng() % 2)) / float(width) + jitter(rng) : unit(rng);
            t[l] = onGrid ? (float(rng() % unsigned(height)) + 0.5f * float(rng() % 2)) / float(height) + jitter(rng) : unit(rng);
            ref[l] = (float(maxCode / 2) + float(rng() % (maxCode / 64))) / float(maxCode) + (round % 7 == 0 ? unit(rng) : 0.0f);
            // Every lane's window passing whole (ref clamped to 0) or failing whole (to 1):
            // the grids' shortcut for uniform windows, both ways in one group.
            if (round % 7 == 3) ref[l] = l % 3 == 0 ? 1.25f : -0.25f;
          }
          // The seeds' step (one texel), a step that is not one texel, and no step at all.
          const float steps[3] = {1.0f / float(width), 1.0f / 1000.0f, 0.0f};
          const float step = steps[round % 3];
          // The seeds' uv arrives as ndc * 0.5 and the constant 0.5 (textureCompareGrid);
          // half the rounds take that form, half a plain uv.
          const float origin = round % 4 < 2 ? 0.5f : 0.0f;
          for (int l = 0; l < 8; ++l) s[l] -= origin, t[l] -= origin;
          // A second lane group for the paired (Float8x2) grids: the same lanes reversed.
          alignas(32) float sr[8], tr[8], refr[8];
          for (int l = 0; l < 8; ++l) sr[l] = s[7 - l], tr[l] = t[7 - l], refr[l] = ref[7 - l];
          // Every tap of a group (lanes at ls, lt, lref) equals its lone scalar lookup.
          auto check = [&](auto tapLanes, int radius, const float* ls, const float* lt, const float* lref) {
            const int n = 2 * radius + 1;
            for (int j = 0; j < n; ++j) {
              for (int i = 0; i < n; ++i) {
                alignas(32) float got[8];
                tapLanes(j, i).store(got);
                for (int l = 0; l < 8; ++l) {
                  const float lone = raster::sampling::compareClamp(
                      map, (origin + float(i - radius) * step) + ls[l], (origin + float(j - radius) * step) + lt[l], lref[l]);
                  CHECK(std::memcmp(&got[l], &lone, sizeof lone) == 0);
                  ++lanesCompared;
                }
              }
            }
          };
          const raster::glsl::vec2<Float8> uv(Float8::load(s), Float8::load(t));
          Float8 taps3[3][3], taps5[5][5];
          raster::textureCompareGrid<1>(sampler, uv, origin, step, Float8::load(ref), taps3);
          raster::textureCompareGrid<2>(sampler, uv, origin, step, Float8::load(ref), taps5);
          check([&](int j, int i) { return taps3[j][i]; }, 1, s, t, ref);
          check([&](int j, int i) { return taps5[j][i]; }, 2, s, t, ref);

          using raster::simd::Float8x2;
          const raster::glsl::vec2<Float8x2> uvPair(Float8x2{Float8::load(s), Float8::load(sr)},
                                                    Float8x2{Float8::load(t), Float8::load(tr)});
          const Float8x2 refPair{Float8::load(ref), Float8::load(refr)};
          Float8x2 pair3[3][3], pair5[5][5];
          raster::textureCompareGrid<1>(sampler, uvPair, origin, step, refPair, pair3);
          raster::textureCompareGrid<2>(sampler, uvPair, origin, step, refPair, pair5);
          check([&](int j, int i) { return pair3[j][i].low(); }, 1, s, t, ref);
          check([&](int j, int i) { return pair3[j][i].high(); }, 1, sr, tr, refr);
          check([&](int j, int i) { return pair5[j][i].low(); }, 2, s, t, ref);
          check([&](int j, int i) { return pair5[j][i].high(); }, 2, sr, tr, refr);
#if RASTER_ZMM_PAIRS
          if (method == CompareMethod::Bilinear) {   // did the pair's 3x3 grid take its 16-lane edge form?
            raster::sampling::LinearTaps16 x[3], y[3];
            raster::sampling::compareGridTaps16<1>(map, uvPair.x.v, uvPair.y.v, origin, step, x, y);
            Float8x2 direct[9];
            edgeGrids16 += !raster::sampling::tapsAreConsecutive16(x, y, 3) &&
                           raster::sampling::compareGrid16<1>(map, uvPair.x, uvPair.y, origin, step, refPair, direct);
          }
#endif
        }
      }
    }
    CHECK(lanesCompared == 2 * 2 * 3 * 600 * 8 * 3 * (9 + 25));   // methods, formats, maps; lone, paired low, paired high
#if RASTER_ZMM_PAIRS
    MESSAGE(edgeGrids16 << " paired 3x3 grids made on 16 lanes with taps piled together at an edge");
    CHECK(edgeGrids16 > 50);   // the 16-lane grid's edge form ran, not only the 8-lane fallback
#endif
  }

  // The grids read each lane's window once and, where every lane's window passes or fails
  // the compare whole, give taps of 1 or +0 without blending them. Here the map steps from
  // one depth to another along a column (and then a row), the reference lies between, and
  // lanes sit so that their windows lie on one side with taps one texel apart, cross it, or
  // reach it with taps two texels apart (no window holds those, so the lone lookups decide).
  // Every tap equals its lone lookup either way; a uniform test that left out a window
  // column, or a window that did not hold every tap, fails it.
  TEST_CASE("PCF grids beside a depth step: uniform windows, and taps that reach past any window") {
    using raster::simd::Float8;
    using raster::simd::Float8x2;
    constexpr int kSize = 64, kStep = 32;
    constexpr uint32_t kNear = 0x400000, kFar = 0xC00000;
    const float ref = 0.5f;   // between kNear and kFar as depths
    long lanesCompared = 0, passed = 0, failed = 0;
    for (const bool alongX : {true, false}) {
      raster::Texture map(kSize, kSize, raster::TexelFormat::Depth24);
      for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) map.depth[size_t(y) * kSize + size_t(x)] = (alongX ? x : y) < kStep ? kNear : kFar;
      raster::Sampler2DShadow sampler;
      sampler.texture = &map;
      // Both grids of one pair of lane groups, lane l at (s[l], t[l]), every tap against its
      // lone lookup.
      auto checkGrids = [&](const float (&s)[16], const float (&t)[16], float step) {
        alignas(64) float refs[16];
        std::fill(std::begin(refs), std::end(refs), ref);
        const raster::glsl::vec2<Float8x2> uv(Float8x2{Float8::load(s), Float8::load(s + 8)},
                                              Float8x2{Float8::load(t), Float8::load(t + 8)});
        const Float8x2 refPair{Float8::load(refs), Float8::load(refs + 8)};
        Float8x2 grid3[3][3], grid5[5][5];
        raster::textureCompareGrid<1>(sampler, uv, 0.0f, step, refPair, grid3);
        raster::textureCompareGrid<2>(sampler, uv, 0.0f, step, refPair, grid5);
        auto check = [&](auto tap, int radius) {
          const int n = 2 * radius + 1;
          for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
              alignas(64) float got[16];
              tap(j, i).low().store(got);
              tap(j, i).high().store(got + 8);
              for (int l = 0; l < 16; ++l) {
                const float lone = raster::sampling::compareClamp(map, float(i - radius) * step + s[l],
                                                                  float(j - radius) * step + t[l], refs[l]);
                CHECK(std::memcmp(&got[l], &lone, sizeof lone) == 0);
                passed += lone == 1.0f;
                failed += lone == 0.0f;
                ++lanesCompared;
              }
            }
        };
        check([&](int j, int i) { return grid3[j][i]; }, 1);
        check([&](int j, int i) { return grid5[j][i]; }, 2);
      };
      // Lane l at texel `along[l]` (plus `within`) along the step's axis, row or column 8 + l
      // across it.
      auto place = [&](const int (&along)[16], float within, float (&s)[16], float (&t)[16]) {
        for (int l = 0; l < 16; ++l) {
          const float a = (float(along[l]) + within) / float(kSize), across = (float(8 + l) + 0.5f) / float(kSize);
          s[l] = alongX ? a : across;
          t[l] = alongX ? across : a;
        }
      };
      for (const float stepTexels : {1.0f, 2.0f}) {
        const float step = stepTexels / float(kSize);
        // Lanes from 8 texels before the step to 8 after it, 16 at a time: the first pairs'
        // windows lie before the step, the last ones' after it. On a texel centre each tap's
        // second texel has weight 0; a quarter past it, every texel of the window counts.
        for (int lanePlace = 0; lanePlace < 2 * 17; ++lanePlace) {
          int along[16];
          std::fill(std::begin(along), std::end(along), kStep - 8 + lanePlace % 17);
          alignas(64) float s[16], t[16];
          place(along, lanePlace < 17 ? 0.5f : 0.75f, s, t);
          checkGrids(s, t, step);
        }
      }
      // One lane's window across the step, every other lane's on one side of it: the pair is
      // uniform but for that lane, so a uniform test that mixed up lanes, or read some lane's
      // window short, fails here.
      for (const int side : {kStep - 8, kStep + 4})
        for (int lone = 0; lone < 16; ++lone) {
          int along[16];
          std::fill(std::begin(along), std::end(along), side);
          along[lone] = kStep - 1;
          alignas(64) float s[16], t[16];
          place(along, 0.5f, s, t);
          checkGrids(s, t, 1.0f / float(kSize));
        }
      // Every lane's window on one side of the step, the sides in a pattern that no shift of
      // the lanes keeps: the pair is uniform, and a test that gave a lane another lane's
      // result fails here.
      for (const unsigned farLanes : {0x0001u, 0x8000u, 0x00FFu, 0x0F0Fu, 0x3333u, 0x5555u, 0xA5C3u, 0x1248u}) {
        int along[16];
        for (int l = 0; l < 16; ++l) along[l] = (farLanes >> l) & 1u ? kStep + 4 : kStep - 8;
        alignas(64) float s[16], t[16];
        place(along, 0.5f, s, t);
        checkGrids(s, t, 1.0f / float(kSize));
      }
    }
    CHECK(lanesCompared == 2 * (2 * 2 * 17 + 2 * 16 + 8) * 16 * (9 + 25));
    CHECK(passed > lanesCompared / 4);   // both sides of the step are sampled whole
    CHECK(failed > lanesCompared / 4);
  }
#endif

  // compare=nearest (raster/methods.h) against its definition and its stated bound: each
  // lookup is the compare of the texel floor(clamp(coord * size, 0, size - 1)) lands in, 0 or
  // 1; that texel has the largest bilinear weight, so the lookup equals llvmpipe's wherever
  // that one is 0 or 1 and is within 0.75 of it everywhere. Edge values included.
  TEST_CASE("compare=nearest: the compare of the texel the coordinate lands in, within 0.75 of bilinear") {
    std::mt19937 rng(4242);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float specials[] = {0.0f, -0.0f, 1e-45f, -1e-45f, 1.0f, 1.0000001f, 0.99999994f, -1.0f, 1e30f, -1e30f, inf, -inf, nan};
    long lookups = 0, differing = 0;
    for (raster::TexelFormat format : {raster::TexelFormat::Depth24, raster::TexelFormat::Depth16}) {
      for (const auto& [width, height] : {std::pair{1024, 1024}, std::pair{37, 29}, std::pair{1, 1}, std::pair{3, 1001}}) {
        raster::Texture map(width, height, format);
        const uint32_t maxCode = format == raster::TexelFormat::Depth24 ? 0xFFFFFFu : 0xFFFFu;
        for (uint32_t& code : map.depth) code = maxCode / 2 + rng() % (maxCode / 64);
        auto texelOf = [](float coord, int size) {   // the definition, written out apart
          const float c = coord * float(size);
          if (std::isnan(c) || c <= 0.0f) return 0;
          return int(std::floor(std::min(c, float(size - 1))));
        };
        std::uniform_real_distribution<float> unit(-0.1f, 1.1f);
        for (int k = 0; k < 20000; ++k) {
          const float s = k % 10 == 0 ? specials[rng() % std::size(specials)] : unit(rng);
          const float t = k % 10 == 1 ? specials[rng() % std::size(specials)] : unit(rng);
          float ref = (float(maxCode / 2) + float(rng() % (maxCode / 64))) / float(maxCode);
          if (k % 10 == 2) ref = specials[rng() % std::size(specials)];
          const float nearest = raster::sampling::compareNearestClamp(map, s, t, ref);
          const float clampedRef = std::isnan(ref) ? 0.0f : std::clamp(ref, 0.0f, 1.0f);
          const uint32_t code = map.depth[size_t(texelOf(t, height)) * size_t(width) + size_t(texelOf(s, width))];
          const float texel = format == raster::TexelFormat::Depth24 ? raster::format::depth24ToFloat(code)
                                                                     : raster::format::depth16ToFloat(code);
          CAPTURE(s);
          CAPTURE(t);
          CAPTURE(ref);
          CHECK(nearest == (clampedRef <= texel ? 1.0f : 0.0f));
          // NaN coordinates clamp to opposite texels in the two methods (0 here, size - 1 in
          // llvmpipe's linear wrap): the bound is for coordinates.
          if (std::isnan(s) || std::isnan(t)) continue;
          const float bilinear = raster::sampling::compareLinearClamp(map, s, t, ref);
          CHECK(std::fabs(nearest - bilinear) <= 0.75f);
          if (bilinear == 0.0f || bilinear == 1.0f) CHECK(nearest == bilinear);
          differing += nearest != bilinear;
          ++lookups;
        }
#if RASTER_AVX2
        // The 8-lane lookup, lane for lane the scalar one, specials included.
        for (int k = 0; k < 2000; ++k) {
          alignas(32) float s[8], t[8], ref[8], got[8];
          for (int l = 0; l < 8; ++l) {
            s[l] = (k + l) % 5 == 0 ? specials[rng() % std::size(specials)] : unit(rng);
            t[l] = (k + l) % 5 == 1 ? specials[rng() % std::size(specials)] : unit(rng);
            ref[l] = (k + l) % 5 == 2 ? specials[rng() % std::size(specials)] : unit(rng);
          }
          using raster::simd::Float8;
          raster::sampling::compareNearestClamp8(map, Float8::load(s), Float8::load(t), Float8::load(ref)).store(got);
          for (int l = 0; l < 8; ++l) CHECK(got[l] == raster::sampling::compareNearestClamp(map, s[l], t[l], ref[l]));
        }
#endif
      }
    }
    MESSAGE("compare=nearest: " << differing << " of " << lookups << " lookups differ from bilinear");
    CHECK(differing > lookups / 20);   // the inputs reach the penumbrae
  }
}
