// `raster tradeoff`: every method set raced against llvmpipe and scored against it, so
// speed can be charted against accuracy.
//
// The points: every preset (`raster methods` lists them), every single-step change from gl
// (math=fast, div=approx, ...), llvmpipe itself and softpipe. This pipeline's sets share one
// backend and one scene, and their frames interleave with llvmpipe's in this process
// (round after round: each set's frame after one of llvmpipe's), so slow drifts of a shared
// machine hit every point alike; each point's time is the median of its frames. Softpipe needs a
// process of its own (Mesa picks one Gallium driver per process): a child `raster bench
// --gl-driver softpipe` times it against this pipeline's gl set, and the ratio is carried
// over to llvmpipe through gl's time here.
//
// Accuracy: the final image of each point against llvmpipe's (identical, PSNR, mean LDR-FLIP
// error "flip_vs_llvmpipe" (compare/flip.h; null for a final image that is not RGBA8), share
// of pixels off by more than one 8-bit step, largest step) and against the precise preset's
// (PSNR, and FLIP as "flip_vs_precise").
//
// Written into --out: tradeoff.json, tradeoff.md (the table, sorted by speed, Pareto-optimal
// rows marked) and tradeoff.png / .svg (bench/tradeoff_chart.py, matplotlib).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "apps/common/cli_options.h"

namespace cli {

// The frame options (FrameArgs: scene, time, size, threads, assets, memory, instances) with
// `scene` also `all`; the method options are not offered: every set is raced.
struct TradeoffArgs : FrameArgs {
  TradeoffArgs() { threads = 2; }
  int frames = 9;                  // timed rounds
  int warmup = 2;
  int softpipeFrames = 3;          // timed frames of the softpipe child (it is slow)
  bool noSoftpipe = false;
  std::string out;
};

void addTradeoffOptions(CLI::App& command, TradeoffArgs& args);
int runTradeoff(const TradeoffArgs& args);

}  // namespace cli
