// Hostile environment and values: a Gallium driver or thread count Mesa cannot use, a time
// that overflows a float, images with NaN and infinite pixels in a comparison.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "compare/metrics.h"
#include "tests/apps/cli_test_helpers.h"

namespace {

using namespace cli_test;

void expectBadInput(const std::string& script, const std::string& needle) {
  TempFolder temp;
  const fs::path cwd = temp.path / "cwd";
  fs::create_directory(cwd);
  const RunResult r = runShell(cwd, script);
  INFO(script << "\nstderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.err.rfind("raster: ", 0) == 0);
  CHECK(r.err.find(needle) != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(fs::is_empty(cwd));
}

}  // namespace

TEST_SUITE("hostile") {
  // An unknown GALLIUM_DRIVER crashed inside Mesa (SIGSEGV, no message).
  TEST_CASE("environment: GALLIUM_DRIVER and LP_NUM_THREADS are checked before Mesa starts") {
    expectBadInput("GALLIUM_DRIVER=nosuchdriver exec \"$RASTER\" render shadow --backend gl --size 32x32 --out x.png",
                   "GALLIUM_DRIVER='nosuchdriver'");
    expectBadInput("LP_NUM_THREADS=many exec \"$RASTER\" render shadow --backend gl --size 32x32 --out x.png",
                   "LP_NUM_THREADS='many'");
    expectBadInput("LP_NUM_THREADS=-3 exec \"$RASTER\" compare shadow --size 32x32 --out cmp",
                   "LP_NUM_THREADS='-3'");
  }

  // 1e39 passed as a double but became +inf as the scene's float; the message said "out of range".
  TEST_CASE("values: a time that overflows a float says so") {
    expectBadInput("exec \"$RASTER\" render shadow --time 1e39", "overflows a float");
    expectBadInput("exec \"$RASTER\" render shadow --time -1", "is negative");
  }

  // Identical NaN pixels made RMSE and PSNR NaN ("psnr nan").
  TEST_CASE("compare: non-finite pixels are counted apart, and no metric is ever NaN") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const auto a = halfImage({nan, 0.5f, 0.25f, 1.0f, 0.5f, 0.5f, 0.5f, 1.0f, inf, 0, 0, 1});
    compare::TargetStats same = compare::compareImages("hdr", a, a);
    CHECK(same.nonFinitePixels == 2);
    CHECK(same.rmse == 0.0);
    CHECK(std::isinf(same.psnr));
    CHECK(same.shareBitIdentical == 1.0);
    const std::string line = compare::formatStatsLine(same);
    INFO(line);
    CHECK(line.find("nan") == std::string::npos);
    CHECK(line.find("nonfinite 2") != std::string::npos);

    // NaN against a number: a differing pixel, but RMSE only over the finite samples.
    const auto b = halfImage({0.0f, 0.5f, 0.25f, 1.0f, 0.5f, 0.5f, 0.75f, 1.0f, inf, 0, 0, 1});
    const compare::TargetStats differ = compare::compareImages("hdr", a, b);
    CHECK(differ.nonFinitePixels == 2);
    CHECK(std::isfinite(differ.rmse));
    CHECK(differ.rmse > 0.0);
    CHECK(std::isfinite(differ.psnr));
    CHECK(differ.shareDiffering == doctest::Approx(2.0 / 3.0));
    CHECK(compare::formatStatsLine(differ).find("nan") == std::string::npos);
  }
}
