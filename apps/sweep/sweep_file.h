// sweep.json, what `raster sweep` writes and `raster sweep-merge` reads back (its fields are
// in sweep.h): the values of its range, when a side fails, the order of a value's sides, the
// shard a run renders, and writing the file with its table (sweep.md) and chart (sweep.png /
// .svg, bench/sweep_chart.py). The merge recomputes the first two to check a shard's points.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cli {

constexpr const char* kSweepChartScript = "sweep_chart.py";
constexpr int kMaxSweepSteps = 10000;   // values of a range, and so shards of a sweep

// --param NAME=FROM:TO:STEPS[:log], as sweep.json's "param" and "range" record it.
struct SweepRange {
  std::string name;
  double from = 0, to = 0;
  int steps = 1;
  bool log = false;
};

// The values of the range, evenly spaced (or evenly in log), rounded to 6 significant digits
// (1e-05 rather than 1.0000000000000001e-05: a value a user can type back into --set), the
// last exactly TO; whole numbers for whole-number parameters; repeats after rounding dropped.
std::vector<double> sweepValues(const SweepRange& range, bool integer);

// Why a side fails at a value, or "" where it does not: any non-finite pixel in its targets,
// else a final image below the threshold (`finalPsnrDb` +inf where the final images are
// identical).
std::string sweepFailure(uint64_t nonFinitePixels, double finalPsnrDb, double thresholdDb);

// --shard K/N; `sharded` false (1/1) for an empty text. UsageError for anything else.
struct ShardSpec {
  int index = 1, count = 1;
  bool sharded = false;
};
ShardSpec parseShard(const std::string& text);
// The indexes of the values that shard renders, of `valueCount`: i with i % N == K - 1.
std::vector<size_t> shardValueIndexes(const ShardSpec& shard, size_t valueCount);

// The sides of every value, in the order their points are written: llvmpipe, the method
// sets, softpipe.
std::vector<std::string> sweepSides(const nlohmann::json& sweep);

// The files writeSweep writes: sweep.json and sweep.md, and a whole run's chart, sweep.png
// and sweep.svg (checked in the --out folder before the run: checkOutputFolder).
std::vector<std::string> sweepFiles(bool shard);

// Writes sweep.json and sweep.md into `folder` (a whole run adds "first_failure" and the
// chart; a shard neither), and says on stdout what it wrote. The folder is made here, with
// its first file, so that a run that fails before it (a render, a shard refused) leaves none.
void writeSweep(nlohmann::json sweep, const std::string& folder);

}  // namespace cli
