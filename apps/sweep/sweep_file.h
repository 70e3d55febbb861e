// sweep.json, what `raster sweep` writes and `raster sweep-merge` reads back (its fields are
// in sweep.h): the order of a value's sides, the shard a run renders, and writing the file
// with its table (sweep.md) and chart (sweep.png / .svg, bench/sweep_chart.py).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cli {

constexpr const char* kSweepChartScript = "sweep_chart.py";

// --shard K/N; `sharded` false (1/1) for an empty text. UsageError for anything else.
struct ShardSpec {
  int index = 1, count = 1;
  bool sharded = false;
};
ShardSpec parseShard(const std::string& text);

// The sides of every value, in the order their points are written: llvmpipe, the method
// sets, softpipe.
std::vector<std::string> sweepSides(const nlohmann::json& sweep);

// Writes sweep.json and sweep.md into `folder` (a whole run adds "first_failure" and the
// chart; a shard neither), and says on stdout what it wrote. The folder is made here, with
// its first file, so that a run that fails before it (a render, a shard refused) leaves none.
void writeSweep(nlohmann::json sweep, const std::string& folder);

}  // namespace cli
