// The failure points STABILITY.md names, pinned from both sides: each case sweeps two
// values of a parameter, one where a method still holds and one where it has failed, and
// checks which side fails where (a final image below 30 dB against llvmpipe, or a
// non-finite pixel). If a change moves a method's breaking point, one of these says so.
// They run the built `raster sweep` on small images, so they exercise what a user runs.
#include <doctest/doctest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "tests/apps/cli_test_helpers.h"

namespace {

using namespace cli_test;
using nlohmann::json;

json sweep(const std::string& args) {
  TempFolder temp;
  const RunResult run = runCli(temp.path, "sweep " + args + " --no-softpipe --quiet --out s");
  INFO("raster sweep " << args << "\nstderr: " << run.err);
  REQUIRE(run.status == 0);
  return json::parse(readText(temp.path / "s" / "sweep.json"));
}

// The point of `method` at `value`.
json pointOf(const json& sweep, const std::string& method, double value) {
  for (const json& p : sweep["points"])
    if (p["method"] == method && p["value"].get<double>() == value) return p;
  FAIL("no point of " << method << " at " << value);
  return {};
}

}  // namespace

TEST_SUITE("stability") {
  TEST_CASE("hdr intensity: llvmpipe's truncating half saturates at 65504; round-to-nearest overflows to inf") {
    const json s = sweep("hdr --param intensity=3162.28:10000:2 --methods gl,half=rne --size 96x72");
    for (double value : {3162.28, 10000.0}) {
      CHECK(pointOf(s, "llvmpipe", value)["nonfinite_pixels"] == 0);
      CHECK(pointOf(s, "gl", value)["identical_to_llvmpipe"] == true);
    }
    CHECK(pointOf(s, "half=rne", 3162.28)["fails"] == false);
    CHECK(pointOf(s, "half=rne", 10000.0)["nonfinite_pixels"].get<uint64_t>() > 0);
    CHECK(s["first_failure"]["half=rne"] == 10000.0);
  }

  TEST_CASE("hdr time: past 1e7 s llvmpipe's sin and cos leave their range; libm and fast sin part from them") {
    const json s = sweep("hdr --param time=1e7:1e8:2 --methods gl,fast,math=fast,math=libm --size 96x72");
    for (const char* method : {"math=fast", "math=libm"}) {
      CHECK(pointOf(s, method, 1e7)["fails"] == false);
      CHECK(pointOf(s, method, 1e8)["fails"] == true);
    }
    CHECK(pointOf(s, "gl", 1e8)["identical_to_llvmpipe"] == true);
    // The time reaches only the vertex shader's sin and cos, which the fast preset
    // (math=fast-fragment) leaves llvmpipe's: it follows llvmpipe where math=fast parts.
    const json fast = pointOf(s, "fast", 1e8);
    CHECK((fast["identical_to_llvmpipe"] == true || fast["psnr_vs_llvmpipe_db"].get<double>() > 60.0));
  }

  TEST_CASE("deferred world_offset: precise's rounding of the half-float G-buffer moves SSAO past 30 dB at 100") {
    const json s = sweep("deferred --param world_offset=31.6228:100:2 --methods half=rne --size 160x120");
    CHECK(pointOf(s, "half=rne", 31.6228)["fails"] == false);
    CHECK(pointOf(s, "half=rne", 100.0)["fails"] == true);
  }

  TEST_CASE("deferred world_offset: at 1e5 GL itself makes non-finite pixels, and gl makes exactly as many") {
    const json s = sweep("deferred --param world_offset=31622.8:100000:2 --methods gl --size 320x240");
    CHECK(pointOf(s, "llvmpipe", 31622.8)["nonfinite_pixels"] == 0);
    CHECK(pointOf(s, "gl", 31622.8)["nonfinite_pixels"] == 0);
    // Where positions are this large, SSAO's sample points sit on knife edges: gl stays
    // identical only if it sums p + off in Mesa's reassociated order (ssao.h).
    CHECK(pointOf(s, "gl", 31622.8)["identical_to_llvmpipe"] == true);
    const uint64_t broken = pointOf(s, "llvmpipe", 100000.0)["nonfinite_pixels"].get<uint64_t>();
    CHECK(broken > 0);
    CHECK(pointOf(s, "gl", 100000.0)["nonfinite_pixels"].get<uint64_t>() == broken);
  }

  TEST_CASE("pbr world_offset: llvmpipe's 8-bit filter overflows its fixed-point coordinate past |s| = 8192; filter=float parts there") {
    // The floor's uv is 0.35 x its world position; on its 1024-texel maps iround(s * 1024 * 256)
    // leaves 32 bits at a world x of 23,406 m: between these two values.
    const json s = sweep("pbr --param world_offset=10000:31622.8:2 --methods gl,filter=float --size 96x72");
    for (double value : {10000.0, 31622.8}) CHECK(pointOf(s, "gl", value)["identical_to_llvmpipe"] == true);
    CHECK(pointOf(s, "filter=float", 10000.0)["fails"] == false);
    CHECK(pointOf(s, "filter=float", 31622.8)["fails"] == true);
  }
}

// Where coarse shading (--method shading=RATE, tile/coarse_tile.h) fails, pinned the same
// way; STABILITY.md's "Coarse shading" charts the sweeps these come from. A suite of its own,
// so ctest runs it beside the one above.
TEST_SUITE("stability_coarse") {
  TEST_CASE("hdr instances (edges): 2x1 holds over 10 cubes and fails at 100, 2x2 fails at 10 already") {
    // The post passes take the rate; the cubes' edges are the detail a coarse bright pass
    // and bloom chain smear, and more cubes make more of them (STABILITY.md).
    const json s = sweep("hdr --param instances=10:100:2 --methods gl,shading=2x1,shading=2x2 --size 160x120 --threads 2");
    CHECK(pointOf(s, "gl", 100.0)["identical_to_llvmpipe"] == true);
    CHECK(pointOf(s, "shading=2x1", 10.0)["fails"] == false);
    CHECK(pointOf(s, "shading=2x1", 100.0)["fails"] == true);
    CHECK(s["first_failure"]["shading=2x1"] == 100.0);
    CHECK(s["first_failure"]["shading=2x2"] == 10.0);
    // A coarser rate is never the more accurate one here.
    for (double value : {10.0, 100.0})
      CHECK(pointOf(s, "shading=2x2", value)["psnr_vs_llvmpipe_db"].get<double>() <
            pointOf(s, "shading=2x1", value)["psnr_vs_llvmpipe_db"].get<double>());
  }

  TEST_CASE("coarse bloom: fast with 2x2-offscreen holds hdr at 30 dB at 640x480 and fails 149 wide; 2x2-smooth (draft) holds at both") {
    // 2x2-offscreen's coarse bright pass samples the HDR target once per 4x4 of its texels and
    // thresholds what it reads, so the bloom aliases; the smaller the image, the more of it
    // each cube's step covers (STABILITY.md, "Coarse bloom"). 2x2-smooth leaves the passes
    // that minify (bright pass, downsamples) at 1x1 and shades only the upsamples coarse.
    const std::string offscreen = "math=fast-fragment+compare=nearest+shading=2x2-offscreen";   // fast with it
    const json s = sweep("hdr --param size=149:640:2 --methods fast," + offscreen + ",draft --threads 2");
    CHECK(pointOf(s, offscreen, 149.0)["fails"] == true);
    CHECK(pointOf(s, offscreen, 640.0)["fails"] == false);
    CHECK(s["first_failure"][offscreen] == 149.0);
    CHECK(s["first_failure"]["draft"] == nullptr);
    CHECK(s["first_failure"]["fast"] == nullptr);
    for (double value : {149.0, 640.0})
      CHECK(pointOf(s, "draft", value)["psnr_vs_llvmpipe_db"].get<double>() > 40.0);
  }
}
