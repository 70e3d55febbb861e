// `raster compare SCENE`: one frame with a test and a reference backend; per target a stats
// line (compare/metrics.h) and the ours / gl / heat-map PNGs, then compare.json beside them
// (every target's numbers, apps/common/target_stats_json.h, and the thresholds exceeded); a
// threshold exceeded fails the run (exit 1).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "apps/common/cli_options.h"

namespace cli {

struct CompareArgs : FrameArgs {
  std::string out;             // empty: compare-SCENE
  std::string reference = "llvmpipe";
  std::string test = "raster";
  std::string maxRmse, minPsnr, maxShareOver1, maxDepthLsb;   // empty: no threshold
  bool exact = false;          // every target must match, whatever its kind
};

// Limits the compare thresholds set; absent ones are not checked.
struct Thresholds {
  std::optional<double> maxRmse, minPsnr, maxShareOver1;
  std::optional<uint64_t> maxDepthLsb;
  bool exact = false;
};

// compare_options.cpp, apart so that the command-line fuzz target (fuzz/cli_fuzz.cpp) links
// the options and their checks without what renders.
void addCompareOptions(CLI::App& command, CompareArgs& args);
Thresholds validateThresholds(const CompareArgs& args);

int runCompare(const CompareArgs& args);

}  // namespace cli
