// sampler2D lookups against llvmpipe, bit for bit: RGBA8 (llvmpipe's 8-bit fixed-point
// path) and RGBA16F (its float path), NEAREST and LINEAR, REPEAT and CLAMP_TO_EDGE, at
// random coordinates, coordinates far outside [0, 1], and exactly on texel centres and
// edges. Results are written to an RGBA32F target so every bit of the lookup is compared.
// The RGBA16F textures are uploaded from floats, which also checks the upload conversion
// (Mesa 22.3 truncates toward zero there).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "raster/methods.h"
#include "raster/texture/footprint_strips.h"
#include "raster/texture/format.h"
#include "raster/texture/sampler.h"
#include "tests/gl_compare_helpers.h"
#include "tests/texture/lookup_test_helpers.h"

namespace {

using namespace gltest;

struct TextureCase {
  int width, height;
  TexelFormat format;
  scenes::Filter filter;
  scenes::Wrap wrapS, wrapT;
};

// Random grey bytes (r = g = b, alpha 255) for an upload: the backend keeps a grey copy.
[[maybe_unused]] std::vector<uint8_t> greyBytes(std::mt19937& rng, int w, int h) {
  std::vector<uint8_t> bytes(size_t(w) * size_t(h) * 4);
  for (size_t i = 0; i < bytes.size(); i += 4) {
    bytes[i] = bytes[i + 1] = bytes[i + 2] = uint8_t(rng());
    bytes[i + 3] = 255;
  }
  return bytes;
}

// Renders one lookup per 2x2 cell with both backends and counts cells whose bits differ.
void checkLookups(const TextureCase& c, unsigned seed, bool grey = false) {
  std::mt19937 rng(seed);
  std::vector<uint8_t> bytes(size_t(c.width) * size_t(c.height) * 4);
  std::vector<float> floats(bytes.size());
  for (uint8_t& b : bytes) b = uint8_t(rng());
  if (grey) bytes = greyBytes(rng, c.width, c.height);
  for (float& f : floats) f = uniform(rng, -4.0f, 4.0f);
  scenes::TextureDesc desc;
  desc.width = c.width;
  desc.height = c.height;
  desc.format = c.format;
  desc.sampler = {c.filter, c.wrapS, c.wrapT, false};
  const void* pixels = c.format == TexelFormat::RGBA8 ? static_cast<const void*>(bytes.data()) : floats.data();

  constexpr int kSize = 128, kCell = 2;
  const MeshData mesh = gridMesh(kSize, kSize, kCell, [&](int, int) {
    GridCell cell;
    cell.attribute = glm::vec4(lookupCoordinate(rng, c.width), lookupCoordinate(rng, c.height), 0.0f, 1.0f);
    return cell;
  });

  BackendPair backends;
  ImageData images[2];
  Backend* sides[2] = {backends.raster.get(), backends.gl.get()};
  for (int k = 0; k < 2; ++k) images[k] = drawLookups(*sides[k], sides[k]->createTexture(desc, pixels), mesh, kSize);
  const FloatComparison cmp = compareFloatBits(images[0], images[1]);
  const std::string name = std::to_string(c.width) + "x" + std::to_string(c.height) +
                           (c.format == TexelFormat::RGBA8 ? (grey ? " grey RGBA8" : " RGBA8") : " RGBA16F") +
                           (c.filter == scenes::Filter::Linear ? " linear" : " nearest");
  MESSAGE(name << ": " << cmp.diffs << " of " << kSize * kSize << " pixels differ " << cmp.firstDiff);
  CHECK(cmp.diffs == 0);
}


}  // namespace

TEST_SUITE("texture") {
  using scenes::Filter;
  using scenes::Wrap;
  TEST_CASE("RGBA8 bilinear, repeat and clamp, power-of-two and odd sizes, equals llvmpipe") {
    checkLookups({16, 8, TexelFormat::RGBA8, Filter::Linear, Wrap::Repeat, Wrap::Repeat}, 1);
    checkLookups({16, 16, TexelFormat::RGBA8, Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge}, 2);
    checkLookups({13, 7, TexelFormat::RGBA8, Filter::Linear, Wrap::Repeat, Wrap::ClampToEdge}, 3);
    checkLookups({13, 7, TexelFormat::RGBA8, Filter::Linear, Wrap::ClampToEdge, Wrap::Repeat}, 4);
  }
  TEST_CASE("RGBA8 nearest equals llvmpipe") {
    checkLookups({16, 8, TexelFormat::RGBA8, Filter::Nearest, Wrap::Repeat, Wrap::ClampToEdge}, 5);
    checkLookups({13, 7, TexelFormat::RGBA8, Filter::Nearest, Wrap::ClampToEdge, Wrap::Repeat}, 6);
  }
  TEST_CASE("grey RGBA8 textures, sampled through their one-byte copy, equal llvmpipe") {
    checkLookups({16, 8, TexelFormat::RGBA8, Filter::Linear, Wrap::Repeat, Wrap::Repeat}, 21, true);
    checkLookups({13, 7, TexelFormat::RGBA8, Filter::Linear, Wrap::ClampToEdge, Wrap::Repeat}, 22, true);
    checkLookups({3, 1001, TexelFormat::RGBA8, Filter::Linear, Wrap::Repeat, Wrap::ClampToEdge}, 23, true);
    checkLookups({16384, 1, TexelFormat::RGBA8, Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge}, 24, true);
    checkLookups({1, 1, TexelFormat::RGBA8, Filter::Linear, Wrap::Repeat, Wrap::Repeat}, 25, true);
    checkLookups({13, 7, TexelFormat::RGBA8, Filter::Nearest, Wrap::Repeat, Wrap::ClampToEdge}, 26, true);
    checkLookups({16384, 1, TexelFormat::RGBA8, Filter::Nearest, Wrap::Repeat, Wrap::Repeat}, 27, true);
  }
  // Uploads `bytes` (w x h RGBA8, bilinear, REPEAT along s) to both backends, makes the
  // texture a render target, runs a pass over it with `clear` (drawing nothing), then draws
  // one lookup of it per 2x2 cell of a 64x64 grid at random coordinates; returns how many
  // cells' bits differ between the two backends.
  long cellsDifferingAfterPass(const std::vector<uint8_t>& bytes, int w, int h, Wrap wrapT, const ClearOp& clear,
                               std::mt19937& rng) {
    constexpr int kSize = 64;
    const MeshData mesh = gridMesh(kSize, kSize, 2, [&](int, int) {
      GridCell cell;
      cell.attribute = glm::vec4(uniform(rng, -1.0f, 2.0f), uniform(rng, -1.0f, 2.0f), 0.0f, 1.0f);
      return cell;
    });
    BackendPair backends;
    ImageData images[2];
    Backend* sides[2] = {backends.raster.get(), backends.gl.get()};
    for (int k = 0; k < 2; ++k) {
      Backend& b = *sides[k];
      scenes::TextureDesc desc;
      desc.width = w;
      desc.height = h;
      desc.format = TexelFormat::RGBA8;
      desc.sampler = {Filter::Linear, Wrap::Repeat, wrapT, false};
      const Handle texture = b.createTexture(desc, bytes.data());
      const Handle textureFb = b.createFramebuffer({{texture}, 0});
      b.beginPass(textureFb, {0, 0, w, h}, clear);
      images[k] = drawLookups(b, texture, mesh, kSize);
    }
    const FloatComparison cmp = compareFloatBits(images[0], images[1]);
    MESSAGE(w << "x" << h << ": " << cmp.diffs << " of " << kSize * kSize << " pixels differ " << cmp.firstDiff);
    return cmp.diffs;
  }
  TEST_CASE("a grey texture drawn into is sampled as drawn: its one-byte copy is gone") {
    // A grey texture becomes a render target and is cleared to a colour that is not grey;
    // then it is sampled. A stale copy would return the old greys.
    std::mt19937 rng(31);
    ClearOp tint;
    tint.color = true;
    tint.colorValue = glm::vec4(0.8f, 0.3f, 0.1f, 0.5f);
    CHECK(cellsDifferingAfterPass(greyBytes(rng, 37, 37), 37, 37, Wrap::Repeat, tint, rng) == 0);
  }
  TEST_CASE("a texture kept in strips and then drawn into gets its rows back: sampled after a pass, it equals llvmpipe") {
    // An uploaded bilinear RGBA8 texture is kept in strips alone (footprint_strips.h). As a
    // render target it needs rows: the pass clears nothing and draws nothing, so what is
    // sampled after it is the upload, through the rows made back from the strips.
    std::mt19937 rng(37);
    for (const auto& [w, h] : {std::pair{37, 37}, std::pair{13, 7}, std::pair{5, 4}}) {
      std::vector<uint8_t> bytes(size_t(w) * size_t(h) * 4);
      for (uint8_t& b : bytes) b = uint8_t(rng());
      CHECK(cellsDifferingAfterPass(bytes, w, h, Wrap::ClampToEdge, ClearOp{}, rng) == 0);
    }
  }
  TEST_CASE("textures one texel wide or high, and 16384 wide, equal llvmpipe") {
    checkLookups({3, 1001, TexelFormat::RGBA8, Filter::Linear, Wrap::Repeat, Wrap::ClampToEdge}, 31);
    checkLookups({16384, 1, TexelFormat::RGBA8, Filter::Linear, Wrap::Repeat, Wrap::Repeat}, 32);
    checkLookups({1, 1, TexelFormat::RGBA8, Filter::Nearest, Wrap::ClampToEdge, Wrap::Repeat}, 33);
    checkLookups({3, 1001, TexelFormat::RGBA16F, Filter::Linear, Wrap::ClampToEdge, Wrap::Repeat}, 34);
    checkLookups({16384, 1, TexelFormat::RGBA16F, Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge}, 35);
    checkLookups({1, 1, TexelFormat::RGBA16F, Filter::Linear, Wrap::Repeat, Wrap::Repeat}, 36);
  }
  TEST_CASE("RGBA16F bilinear and nearest equal llvmpipe") {
    checkLookups({16, 8, TexelFormat::RGBA16F, Filter::Linear, Wrap::Repeat, Wrap::ClampToEdge}, 7);
    checkLookups({13, 7, TexelFormat::RGBA16F, Filter::Linear, Wrap::ClampToEdge, Wrap::Repeat}, 8);
    checkLookups({16, 16, TexelFormat::RGBA16F, Filter::Nearest, Wrap::Repeat, Wrap::Repeat}, 9);
    checkLookups({13, 7, TexelFormat::RGBA16F, Filter::Nearest, Wrap::ClampToEdge, Wrap::ClampToEdge}, 10);
  }

  TEST_CASE("lookup=nearest: a LINEAR texture reads as NEAREST, its footprint's texel of largest weight, on every lookup path") {
    // The method's whole promise: the value is the one texel the coordinate lands in (the
    // footprint texel of largest bilinear weight), so the same as the texture set to
    // NEAREST under gl, and the 8-lane, paired and grid lookups agree with the scalar one.
    std::mt19937 rng(81);
    raster::MethodSet nearestSet;
    nearestSet.lookup = raster::LookupMethod::Nearest;
    long mismatches = 0, differsFromLinear = 0, lookups = 0;
    for (const auto& [format, grey, strips] : {std::tuple{raster::TexelFormat::RGBA8, false, false},
                                               std::tuple{raster::TexelFormat::RGBA8, false, true},
                                               std::tuple{raster::TexelFormat::RGBA16F, false, false},
                                               std::tuple{raster::TexelFormat::RGBA8, true, false}}) {
      for (const auto& [w, h] : {std::pair{16, 8}, std::pair{13, 7}, std::pair{64, 3}, std::pair{1, 1}}) {
        raster::Texture tex = randomTexture(rng, w, h, format, grey);
        for (raster::Wrap wrap : {raster::Wrap::Repeat, raster::Wrap::ClampToEdge}) {
          tex.sampler = {raster::Filter::Linear, wrap, wrap, false};
          raster::Texture sampled = tex;   // LINEAR, in strips alone where the variant says so
          if (strips && raster::makeStripCopy(sampled)) raster::releaseRows(sampled);
          raster::Texture nearestTex = tex;
          nearestTex.sampler.filter = raster::Filter::Nearest;
          for (int round = 0; round < 100; ++round) {
            alignas(64) float s16[16], t16[16];
            for (int i = 0; i < 16; ++i) s16[i] = lookupCoordinate(rng, w), t16[i] = lookupCoordinate(rng, h);
            float want[16][4], linear[16][4], got[16][4];
            for (int i = 0; i < 16; ++i) {
              raster::sampling::sampleColor(nearestTex, s16[i], t16[i], want[i]);   // under gl
              raster::sampling::sampleColor(sampled, s16[i], t16[i], linear[i]);
            }
            const raster::ScopedMethods scoped(nearestSet);
            for (int i = 0; i < 16; ++i) {
              raster::sampling::sampleColor(sampled, s16[i], t16[i], got[i]);
              for (int c = 0; c < 4; ++c) {
                mismatches += !sameLookup(got[i][c], want[i][c]);
                differsFromLinear += !sameLookup(got[i][c], linear[i][c]);
              }
              ++lookups;
            }
#if RASTER_AVX2
            using raster::simd::Float8;
            using raster::simd::Float8x2;
            const raster::Sampler2D sampler{0, &sampled};
            const auto one = raster::texture(sampler, raster::glsl::vec2<Float8>(Float8::load(s16), Float8::load(t16)));
            const auto pair = raster::texture(sampler, raster::glsl::vec2<Float8x2>(Float8x2(Float8::load(s16), Float8::load(s16 + 8)),
                                                                                    Float8x2(Float8::load(t16), Float8::load(t16 + 8))));
            raster::glsl::vec4<Float8x2> grid[3][3];   // the centre tap is the lookup at uv
            raster::textureGrid3x3(sampler, raster::glsl::vec2<Float8x2>(Float8x2(Float8::load(s16), Float8::load(s16 + 8)),
                                                                         Float8x2(Float8::load(t16), Float8::load(t16 + 8))),
                                   glm::vec2(1.0f / float(w), 1.0f / float(h)), grid);
            alignas(64) float planes[3][4][16];
            for (int c = 0; c < 4; ++c) {
              (c == 0 ? one.x : c == 1 ? one.y : c == 2 ? one.z : one.w).store(planes[0][c]);
              (c == 0 ? pair.x : c == 1 ? pair.y : c == 2 ? pair.z : pair.w).store(planes[1][c]);
              const auto& centre = grid[1][1];
              (c == 0 ? centre.x : c == 1 ? centre.y : c == 2 ? centre.z : centre.w).store(planes[2][c]);
            }
            for (int i = 0; i < 16; ++i)
              for (int c = 0; c < 4; ++c) {
                if (i < 8) mismatches += !sameLookup(planes[0][c][i], want[i][c]);
                mismatches += !sameLookup(planes[1][c][i], want[i][c]);
                mismatches += !sameLookup(planes[2][c][i], want[i][c]);
              }
#endif
          }
        }
      }
    }
    MESSAGE(lookups << " lookups, " << mismatches << " mismatches, " << differsFromLinear << " channels unlike LINEAR");
    CHECK(mismatches == 0);
    CHECK(differsFromLinear > lookups);   // the method does change what a LINEAR lookup reads
  }

  // The property the 16-lane lookup's strip path stands on (footprint_strips.h): for every
  // footprint's first row y <= height - 2 and every column x, the copy holds texel (x, y) at
  // stripUnit and (x, y + 1) in the unit after it; and only a bilinear, non-grey RGBA8
  // texture of two rows or more takes a copy, of the size reserved for it.
  TEST_CASE("strip copies hold each footprint column's two texels side by side") {
    std::mt19937 rng(83);
    long checked = 0, wrong = 0;
    for (const auto& [w, h] : {std::pair{1, 2}, std::pair{2, 2}, std::pair{4, 4}, std::pair{5, 3}, std::pair{13, 7},
                               std::pair{17, 10}, std::pair{3, 1001}}) {
      raster::Texture tex = randomTexture(rng, w, h, raster::TexelFormat::RGBA8);
      tex.sampler = {raster::Filter::Linear, raster::Wrap::Repeat, raster::Wrap::Repeat, false};
      REQUIRE(raster::makeStripCopy(tex));
      CHECK(tex.strips8.size() == raster::stripCopyBytes(tex));
      for (int y = 0; y + 1 < h; ++y)
        for (int x = 0; x < w; ++x) {
          const size_t unit = raster::stripUnit(w, x, y);
          wrong += std::memcmp(&tex.strips8[unit * 4], &tex.rgba8[(size_t(y) * size_t(w) + size_t(x)) * 4], 4) != 0;
          wrong += std::memcmp(&tex.strips8[(unit + 1) * 4], &tex.rgba8[(size_t(y + 1) * size_t(w) + size_t(x)) * 4], 4) != 0;
          checked += 2;
        }
    }
    MESSAGE(checked << " texels checked, " << wrong << " wrong");
    CHECK(checked > 0);
    CHECK(wrong == 0);
    // Kept in strips alone, every texel is still found (rgba8Texel), a sampler state change
    // keeps the strips, and the rows come back byte for byte for a texture drawn into.
    for (const auto& [w, h] : {std::pair{1, 2}, std::pair{2, 3}, std::pair{4, 4}, std::pair{5, 5}, std::pair{13, 7},
                               std::pair{3, 1001}}) {
      raster::Texture tex = randomTexture(rng, w, h, raster::TexelFormat::RGBA8);
      tex.sampler = {raster::Filter::Linear, raster::Wrap::Repeat, raster::Wrap::Repeat, false};
      const auto rows = tex.rgba8;
      REQUIRE(raster::makeStripCopy(tex));
      CHECK(raster::releaseRows(tex) == rows.size());
      REQUIRE(raster::texelsInStripsOnly(tex));
      CHECK(raster::makeStripCopy(tex));   // the strips are the texels now: kept, not remade
      long missed = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          missed += std::memcmp(raster::rgba8Texel(tex, x, y), &rows[(size_t(y) * size_t(w) + size_t(x)) * 4], 4) != 0;
      CHECK(missed == 0);
      raster::restoreRows(tex);
      CHECK_FALSE(tex.hasStripCopy());
      CHECK((tex.rgba8.size() == rows.size() && std::equal(rows.begin(), rows.end(), tex.rgba8.begin())));
    }
    raster::Texture oneRow = randomTexture(rng, 16384, 1, raster::TexelFormat::RGBA8);
    CHECK_FALSE(raster::makeStripCopy(oneRow));   // no footprint of two rows
    raster::Texture nearest = randomTexture(rng, 13, 7, raster::TexelFormat::RGBA8);
    nearest.sampler = {raster::Filter::Nearest, raster::Wrap::Repeat, raster::Wrap::Repeat, false};
    CHECK_FALSE(raster::makeStripCopy(nearest));
    raster::Texture grey = randomTexture(rng, 13, 7, raster::TexelFormat::RGBA8, true);
    grey.sampler = {raster::Filter::Linear, raster::Wrap::Repeat, raster::Wrap::Repeat, false};
    CHECK_FALSE(raster::makeStripCopy(grey));   // its grey copy is smaller still
  }

  TEST_CASE("filter=float: RGBA8 bilinear within float rounding of the exact bilinear, and within 2/255 of llvmpipe's 8-bit lerps") {
    std::mt19937 rng(1234);
    raster::Texture tex = randomTexture(rng, 13, 7, raster::TexelFormat::RGBA8);
    tex.sampler = {raster::Filter::Linear, raster::Wrap::ClampToEdge, raster::Wrap::ClampToEdge, false};
    raster::MethodSet floatFilter;
    floatFilter.filter = raster::FilterMethod::Float;
    double worstExact = 0, worst8bit = 0;
    for (int i = 0; i < 200000; ++i) {
      const float s = uniform(rng, -0.1f, 1.1f), t = uniform(rng, -0.1f, 1.1f);
      float eight[4], full[4];
      raster::sampling::sampleColor(tex, s, t, eight);
      {
        const raster::ScopedMethods scoped(floatFilter);
        raster::sampling::sampleColor(tex, s, t, full);
      }
      // The exact bilinear in double, on the same taps (CLAMP_TO_EDGE: c = clamp(s W, 0, W) - 0.5).
      auto taps = [](float coord, int size, int& i0, int& i1, double& w) {
        const double c = std::max(std::min(double(coord) * size, double(size)) - 0.5, 0.0);
        i0 = int(std::floor(c));
        i1 = std::min(i0 + 1, size - 1);
        w = c - i0;
      };
      int x0, x1, y0, y1;
      double wx, wy;
      taps(s, tex.width, x0, x1, wx);
      taps(t, tex.height, y0, y1, wy);
      for (int c = 0; c < 4; ++c) {
        auto texel = [&](int x, int y) { return tex.rgba8[(size_t(y) * size_t(tex.width) + size_t(x)) * 4 + size_t(c)] / 255.0; };
        const double row0 = texel(x0, y0) + wx * (texel(x1, y0) - texel(x0, y0));
        const double row1 = texel(x0, y1) + wx * (texel(x1, y1) - texel(x0, y1));
        const double exact = row0 + wy * (row1 - row0);
        worstExact = std::max(worstExact, std::fabs(full[c] - exact));
        worst8bit = std::max(worst8bit, std::fabs(double(full[c]) - eight[c]));
      }
    }
    MESSAGE("float filter vs exact bilinear: " << worstExact << "; vs llvmpipe's 8-bit: " << worst8bit * 255 << " steps");
    CHECK(worstExact < 1e-6);              // float32 rounding of a few operations on values <= 1
    CHECK(worst8bit * 255.0 <= 2.0);
    CHECK(worst8bit > 0.0);                // the methods really differ
  }
}
