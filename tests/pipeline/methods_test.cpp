// Method sets (raster/methods.h): the names a user types, and each preset's final image
// against llvmpipe at the threshold the preset promises.
//   gl       bit-identical on every target (the default; the scene suites test it at more
//            times and sizes);
//   fast     >= 40 dB PSNR on the final image, every scene;
//   draft    >= 30 dB on the final image, every scene;
//   precise  >= 30 dB on the final image: it moves pixels where llvmpipe's own numerics are
//            approximate (TRADEOFF.md says which), so it is not near llvmpipe by design; it is
//            held closer to llvmpipe than softpipe is, where softpipe differs.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "raster/methods.h"
#include "tests/scene_test_helpers.h"

namespace {

using testing_support::renderScene;
using testing_support::renderWithLlvmpipe;

// Every target of this pipeline's frame at t = 1 under `methods`.
std::vector<scenes::Target> renderWithMethods(const std::string& scene, const raster::MethodSet& methods, int w, int h) {
  const raster::ScopedMethods scoped(methods);
  auto ours = scenes::makeRasterBackend(0);
  return renderScene(*ours, scene, 1.0f, w, h);
}

compare::TargetStats finalAgainstLlvmpipe(const std::string& scene, const raster::MethodSet& methods,
                                          const std::vector<scenes::Target>& gl, int w, int h) {
  const auto mine = renderWithMethods(scene, methods, w, h);
  const compare::TargetStats stats = compare::compareImages("final", mine.back().image, gl.back().image);
  MESSAGE(scene << " " << raster::methodLabel(methods) << ": " << compare::formatStatsLine(stats));
  return stats;
}

std::string errorOf(auto&& call) {
  try {
    call();
  } catch (const raster::MethodError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_SUITE("methods") {
  TEST_CASE("names: presets, overrides, and one-line errors that list the valid names") {
    CHECK(raster::presetMethods("gl") == raster::MethodSet{});
    raster::MethodSet set = raster::presetMethods("gl");
    raster::applyMethodOverrides(set, "math=fast,half=rne");
    CHECK(set.math == raster::MathMethod::Fast);
    CHECK(set.half == raster::HalfMethod::NearestEven);
    CHECK(raster::methodLabel(set) == "math=fast,half=rne");
    CHECK(raster::methodLabel(raster::presetMethods("precise")) == "precise");
    CHECK(raster::methodName(set, "half") == "rne");
    // The vertex stage's view: fast-fragment reads as llvmpipe's math there, every other
    // step and every other math method as set.
    const raster::MethodSet fast = raster::presetMethods("fast");
    CHECK(fast.math == raster::MathMethod::FastFragment);
    raster::MethodSet vertexFast = fast;
    vertexFast.math = raster::MathMethod::Llvmpipe;
    CHECK(raster::vertexStageSet(fast) == vertexFast);
    CHECK(raster::vertexStageSet(set) == set);
    // Every catalog entry round-trips through its name.
    for (const raster::StepInfo& step : raster::methodCatalog())
      for (const raster::MethodInfo& method : step.methods) {
        raster::MethodSet s;
        raster::setMethod(s, step.name, method.name);
        CHECK(raster::methodName(s, step.name) == method.name);
      }
    CHECK(errorOf([] { raster::MethodSet s; raster::applyMethodOverrides(s, "lookup=cubic"); }) ==
          "unknown method 'cubic' for step lookup (methods: linear, nearest)");
    CHECK(errorOf([] { raster::presetMethods("turbo"); }) == "unknown preset 'turbo' (presets: gl, precise, fast, draft)");
    CHECK(errorOf([] { raster::presetPromise("turbo"); }) == "unknown preset 'turbo' (presets: gl, precise, fast, draft)");
    for (const std::string& preset : raster::presetNames()) CHECK(!raster::presetPromise(preset).empty());
    CHECK(errorOf([] { raster::MethodSet s; raster::applyMethodOverrides(s, "math=slow"); }) ==
          "unknown method 'slow' for step math (methods: llvmpipe, libm, fast, fast-fragment)");
    CHECK(errorOf([] { raster::MethodSet s; raster::applyMethodOverrides(s, "blend=fast"); }) ==
          "unknown step 'blend' (steps: math, filter, half, div, interp, lookup, compare, shading)");
    CHECK(!errorOf([] { raster::MethodSet s; raster::applyMethodOverrides(s, "math"); }).empty());
    CHECK(!errorOf([] { raster::MethodSet s; raster::applyMethodOverrides(s, "math=fast,"); }).empty());
    CHECK(errorOf([] { raster::MethodSet s; raster::applyMethodOverrides(s, "shading=2x2-all,math=fast,shading=1x1"); }) ==
          "step shading is given twice");
  }

  TEST_CASE("each preset's final image against llvmpipe, every scene, at its threshold") {
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      const auto gl = renderWithLlvmpipe(scene, 1.0f, 320, 240);
      CHECK(finalAgainstLlvmpipe(scene, raster::presetMethods("gl"), gl, 320, 240).maxAbs == 0);
      CHECK(finalAgainstLlvmpipe(scene, raster::presetMethods("fast"), gl, 320, 240).psnr >= 40.0);
      CHECK(finalAgainstLlvmpipe(scene, raster::presetMethods("precise"), gl, 320, 240).psnr >= 30.0);
      CHECK(finalAgainstLlvmpipe(scene, raster::presetMethods("draft"), gl, 320, 240).psnr >= 30.0);
    }
  }

  TEST_CASE("math=fast-fragment keeps llvmpipe's vertex math: hdr's geometry and its one NaN pixel are llvmpipe's") {
    // At 1920x1080, t = 1, llvmpipe's rim pow takes a negative base at one pixel (a dot of
    // two unit vectors rounds above 1) and its bloom spreads the NaN into a black block of
    // the final image (TRADEOFF.md). math=fast's vertex sin and cos move the cubes by ulps
    // and the pixel with them (18.7 dB); fast-fragment places every vertex as llvmpipe does.
    const int w = 1920, h = 1080;
    const auto gl = renderWithLlvmpipe("hdr", 1.0f, w, h);
    raster::MethodSet fragmentOnly;
    fragmentOnly.math = raster::MathMethod::FastFragment;
    const auto mine = renderWithMethods("hdr", fragmentOnly, w, h);
    REQUIRE(mine.size() == gl.size());
    for (size_t i = 0; i < mine.size(); ++i) {
      const compare::TargetStats stats = compare::compareImages(mine[i].name, mine[i].image, gl[i].image);
      CAPTURE(compare::formatStatsLine(stats));
      if (mine[i].name == "hdr_depth") CHECK(stats.maxAbs == 0);
      if (mine[i].name == "hdr_scene") {
        CHECK(stats.maxUlps <= 1);   // fast pow in the fragment shader: at most one half ulp
        const auto nans = std::count_if(mine[i].image.floats.begin(), mine[i].image.floats.end(),
                                        [](float v) { return std::isnan(v); });
        CHECK(nans > 0);   // llvmpipe's NaN pixel, made the same way
      }
      if (mine[i].name == "final") CHECK(stats.psnr >= 40.0);
    }
  }

  TEST_CASE("every single-step method renders every scene with finite pixels and changes only what it claims") {
    // half=rne touches only half targets: the shadow scene has none, so its image is llvmpipe's.
    const auto gl = renderWithLlvmpipe("shadow", 1.0f, 160, 120);
    raster::MethodSet rne;
    rne.half = raster::HalfMethod::NearestEven;
    CHECK(finalAgainstLlvmpipe("shadow", rne, gl, 160, 120).maxAbs == 0);
    // interp=affine bends the shadow scene's big ground triangles: far from llvmpipe.
    raster::MethodSet affine;
    affine.interp = raster::InterpMethod::Affine;
    const compare::TargetStats bent = finalAgainstLlvmpipe("shadow", affine, gl, 160, 120);
    CHECK(bent.psnr < 30.0);
    CHECK(bent.nonFinitePixels == 0);
    // compare=nearest moves only the shadow's penumbrae, where the PCF taps' footprints
    // straddle a depth edge: a few pixels.
    raster::MethodSet nearest;
    nearest.compare = raster::CompareMethod::Nearest;
    const compare::TargetStats stepped = finalAgainstLlvmpipe("shadow", nearest, gl, 160, 120);
    CHECK(stepped.maxAbs > 0);
    CHECK(stepped.psnr > 45.0);
  }

  TEST_CASE("shading=2x2-offscreen leaves SSAO and the pass into the window at 1x1; 2x2-local only SSAO") {
    // deferred's post passes are SSAO (samples around its pixel) and the lighting (draws the
    // window): -offscreen takes neither, so the frame is gl's bytes; -local takes the
    // lighting, whose G-buffer edges step. pbr's blurs are offscreen and go coarse, which
    // the blur after them smooths (70 dB at 1920x1080, TRADEOFF.md).
    raster::MethodSet offscreen, local;
    offscreen.shading = raster::ShadingMethod::Rate2x2Offscreen;
    local.shading = raster::ShadingMethod::Rate2x2Local;
    const auto deferredGl = renderWithLlvmpipe("deferred", 1.0f, 160, 120);
    CHECK(finalAgainstLlvmpipe("deferred", offscreen, deferredGl, 160, 120).maxAbs == 0);
    CHECK(finalAgainstLlvmpipe("deferred", local, deferredGl, 160, 120).psnr < 30.0);
    const auto pbrGl = renderWithLlvmpipe("pbr", 1.0f, 160, 120);
    const compare::TargetStats pbr = finalAgainstLlvmpipe("pbr", offscreen, pbrGl, 160, 120);
    CHECK(pbr.maxAbs > 0);
    CHECK(pbr.psnr > 40.0);
  }

  TEST_CASE("shading=2x2-smooth: hdr's bright pass and downsamples stay 1x1, its upsamples go coarse; a NaN keeps them 1x1") {
    // The bright pass and the downsamples read a mip larger than their target, so -smooth
    // leaves them at 1x1 and every target up to the last downsample is fast's to the bit;
    // the upsamples read a mip half their size and go coarse.
    const raster::MethodSet fast = raster::presetMethods("fast");
    raster::MethodSet smooth = fast;
    smooth.shading = raster::ShadingMethod::Rate2x2Smooth;
    CHECK(raster::presetMethods("draft") == smooth);
    const auto full = renderWithMethods("hdr", fast, 160, 120);
    const auto coarse = renderWithMethods("hdr", smooth, 160, 120);
    REQUIRE(coarse.size() == full.size());
    for (size_t i = 0; i < coarse.size(); ++i) {
      INFO("target " << coarse[i].name);
      const bool same = coarse[i].image.rgba8 == full[i].image.rgba8 && coarse[i].image.floats == full[i].image.floats &&
                        coarse[i].image.depth == full[i].image.depth;
      CHECK(same == !(coarse[i].name.starts_with("bloom_up") || coarse[i].name == "final"));
    }
    const auto gl = renderWithLlvmpipe("hdr", 1.0f, 160, 120);
    CHECK(finalAgainstLlvmpipe("hdr", smooth, gl, 160, 120).psnr > 35.0);
    // At 1920x1080, t = 1, the HDR target holds llvmpipe's NaN pixel (the case above), which
    // the bright pass and the downsamples spread into the mips the upsamples read: those stay
    // 1x1 too, so draft renders fast's bytes, NaNs included, where a coarse upsample would
    // have redrawn the black block llvmpipe's bloom makes of it (25 dB).
    const auto fastFrame = renderWithMethods("hdr", fast, 1920, 1080);
    const auto draftFrame = renderWithMethods("hdr", smooth, 1920, 1080);
    REQUIRE(draftFrame.size() == fastFrame.size());
    for (size_t i = 0; i < draftFrame.size(); ++i) {
      INFO("target " << draftFrame[i].name);
      const auto& a = draftFrame[i].image;
      const auto& b = fastFrame[i].image;
      CHECK(a.rgba8 == b.rgba8);
      CHECK(a.depth == b.depth);
      REQUIRE(a.floats.size() == b.floats.size());
      // Bytes, not floats: NaN != NaN. (memcmp of an empty vector's null data is undefined.)
      if (!a.floats.empty()) CHECK(std::memcmp(a.floats.data(), b.floats.data(), a.floats.size() * sizeof(float)) == 0);
    }
  }
}
