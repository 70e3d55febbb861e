// Lookups of tiles that hold only a clear (raster/texture/cleared_tiles.h), against
// llvmpipe bit for bit: the samplers read no texels there, and must still return what a
// fetch would, before and after the tiles are drawn into.
#include <doctest/doctest.h>

#include <random>
#include <string>
#include <vector>

#include "tests/gl_compare_helpers.h"
#include "tests/texture/lookup_test_helpers.h"

namespace {

using namespace gltest;
using scenes::Filter;
using scenes::Wrap;

}  // namespace

TEST_SUITE("texture") {
  TEST_CASE("a float target's tiles that hold only a clear are sampled as cleared, and as drawn once drawn into") {
    // The samplers skip the fetch where every footprint of a lane group lies in a tile that
    // holds only the target's last clear (texture/cleared_tiles.h). A 200x150 RGBA16F target
    // (tiles of 64: 4 x 3, the last column and row partial) goes through passes that clear
    // it, draw into some tiles, draw into more without a clear, and clear it to values the
    // shortcut must not take (-0, which a blend turns into +0; no plain value at all when
    // every tile is drawn). After each pass it is sampled, on a lattice of nearby
    // coordinates (lane groups whose footprints share a tile) and anywhere, against llvmpipe.
    constexpr int kW = 200, kH = 150, kSize = 128;
    auto rect = [](float x0, float y0, float x1, float y1, glm::vec4 color) {   // window coordinates
      std::vector<Vertex> v;
      for (glm::vec2 p : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y0), glm::vec2(x1, y1),
                          glm::vec2(x0, y1)})
        v.push_back({clipFromWindow(p, 0.0f, 1.0f, kW, kH), color});
      return v;
    };
    auto clearTo = [](glm::vec4 value) {
      ClearOp op;
      op.color = true;
      op.colorValue = value;
      return op;
    };
    struct Pass {
      ClearOp clear;
      std::vector<Vertex> drawn;
    };
    const glm::vec4 plain(0.25f, 1.5f, -3.0f, 0.75f), red(2.0f, -1.0f, 0.5f, 1.0f);
    std::vector<Pass> passes;
    passes.push_back({clearTo(plain), rect(64, 64, 100, 90, red)});   // tile (1, 1) drawn, from its corner
    std::vector<Vertex> more = rect(3, 5, 20, 40, glm::vec4(-5.0f, 4.0f, 3.0f, 0.5f));     // tile (0, 0)
    for (const Vertex& v : rect(150, 120, 199, 149, glm::vec4(7.0f, 0.125f, -1.0f, 1.0f))) more.push_back(v);   // (3, 2)
    passes.push_back({ClearOp{}, more});                                                    // no clear: drawn into
    passes.push_back({clearTo(glm::vec4(-0.0f, 0.5f, 0.5f, 1.0f)), {}});                      // -0: not plain
    passes.push_back({clearTo(plain), {}});                                                 // every tile cleared
    passes.push_back({clearTo(plain), rect(0, 0, kW, kH, red)});                            // every tile drawn

    std::mt19937 rng(97);
    std::vector<MeshData> lookups;
    for (int k = 0; k < 2; ++k) {
      const float jitter = uniform(rng, -0.4f, 0.4f);
      lookups.push_back(gridMesh(kSize, kSize, 2, [&](int column, int row) {   // 64 x 64 cells over the texture
        GridCell cell;
        cell.attribute = glm::vec4((float(column) * kW / 64.0f + 0.5f + jitter) / kW,
                                   (float(row) * kH / 64.0f + 0.5f + jitter) / kH, 0.0f, 1.0f);
        return cell;
      }));
    }
    lookups.push_back(gridMesh(kSize, kSize, 2, [&](int, int) {
      GridCell cell;
      cell.attribute = glm::vec4(lookupCoordinate(rng, kW), lookupCoordinate(rng, kH), 0.0f, 1.0f);
      return cell;
    }));

    BackendPair backends;
    Backend* sides[2] = {backends.raster.get(), backends.gl.get()};
    std::vector<ImageData> images[2];
    for (int k = 0; k < 2; ++k) {
      Backend& b = *sides[k];
      scenes::TextureDesc desc;
      desc.width = kW;
      desc.height = kH;
      desc.format = TexelFormat::RGBA16F;
      desc.sampler = {Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, false};
      const Handle texture = b.createTexture(desc);
      const Handle textureFb = b.createFramebuffer({{texture}, 0});
      const Handle program = b.createProgram("test/passthrough");
      for (const Pass& pass : passes) {
        b.beginPass(textureFb, {0, 0, kW, kH}, pass.clear);
        if (!pass.drawn.empty()) {
          DrawState state;
          state.depthTest = false;
          b.draw(program, b.createMesh(makeMesh(pass.drawn)), state);
        }
        for (const MeshData& mesh : lookups) images[k].push_back(drawLookups(b, texture, mesh, kSize));
      }
    }
    for (size_t i = 0; i < images[0].size(); ++i) {
      const FloatComparison cmp = compareFloatBits(images[0][i], images[1][i]);
      MESSAGE("pass " << i / lookups.size() << ", lookups " << i % lookups.size() << ": " << cmp.diffs << " of "
                      << kSize * kSize << " pixels differ " << cmp.firstDiff);
      CHECK(cmp.diffs == 0);
    }
  }
}
