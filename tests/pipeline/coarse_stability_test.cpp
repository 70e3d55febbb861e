// Where coarse shading (--method shading=RATE, tile/coarse_tile.h) fails, pinned from both
// sides as tests/pipeline/stability_test.cpp pins the methods' breaking points: two values
// of a parameter, one where a rate still holds (final image at or above 30 dB against
// llvmpipe) and one where it has failed. STABILITY.md, "Coarse shading", charts the sweeps
// these come from. They run the built `raster sweep` on small images.
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

json pointOf(const json& sweep, const std::string& method, double value) {
  for (const json& p : sweep["points"])
    if (p["method"] == method && p["value"].get<double>() == value) return p;
  FAIL("no point of " << method << " at " << value);
  return {};
}

}  // namespace

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
}
