// `raster bench`: this pipeline and a GL driver render the same frame, alternating in one
// process, and the medians of their frame times are compared.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/common/cli_options.h"

namespace cli {

struct BenchArgs : FrameArgs {
  int frames = 30;                 // timed frames per backend
  int warmup = 3;                  // untimed frames per backend first
  std::string glDriver = "llvmpipe";
  std::string json;                // empty: no JSON file
  bool passes = false;             // also time each pass of both backends
  bool noPin = false;              // leave the process free to run on every core
};

void addBenchOptions(CLI::App& command, BenchArgs& args);
int runBench(const BenchArgs& args);

// The median of frame times (the mean of the middle two for an even count; 0 for none).
double median(std::vector<double> values);

// Restricts the process to `threads` of the cores it may run on, before any backend starts
// a thread; returns how many cores the process is now on (bench.cpp says why).
int pinToCores(int threads);

}  // namespace cli
