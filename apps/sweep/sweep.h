// `raster sweep`: one scene parameter moved step by step toward where methods fail, every
// method set (and softpipe, GL against GL) scored against llvmpipe at every step; and
// `raster sweep-merge`, which joins the shards of a sweep run apart.
//
// A point is one value of the parameter rendered by one side. Per value, llvmpipe renders
// the reference in this process; each method set of this pipeline renders in this process
// too; softpipe renders in a child (Mesa picks one Gallium driver per process). Each side is
// compared with llvmpipe on every target: the final image gives the PSNR, its ꟻLIP, the share of
// pixels off by more than one 8-bit step and the largest step; the worst target is the one
// with the lowest PSNR in its own unit (compare/metrics.h). A side fails at a value when its
// final image is below the threshold (30 dB unless --threshold says otherwise) or any of its
// targets holds a non-finite pixel. llvmpipe's own row reports only its non-finite pixels:
// where GL itself breaks.
//
// Written into --out: sweep.json (below), sweep.md (the table, and the first failing value
// of each side) and sweep.png / .svg (bench/sweep_chart.py, matplotlib). sweep.json holds
// no timing, so a merged run is the unsharded run byte for byte:
//   {"scene", "param", "range": {"from", "to", "steps", "log"}, "size": [w, h], "time",
//    "instances", "sets", "threshold_db", "methods": [...], "softpipe",
//    "points": [{"value", "value_index", "method", "identical_to_llvmpipe",
//                "psnr_vs_llvmpipe_db" (null when identical), "flip_vs_llvmpipe" (the final
//                image's mean LDR-FLIP error, compare/flip.h; the final image is the
//                RGBA8 window's, a sweep having no --float-final),
//                "share_over1_vs_llvmpipe",
//                "max_diff_vs_llvmpipe", "nonfinite_pixels", "worst_target",
//                "worst_target_psnr_db", "fails", "failure"}],
//    "first_failure": {side: value or null}}
// A shard (--shard K/N) renders the values whose index i has i % N == K - 1, and its
// sweep.json says so ("shard": "K/N", "shard_values": the indexes it rendered, no
// "first_failure"); it writes no chart.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/common/cli_options.h"

namespace cli {

struct SweepArgs : FrameArgs {
  SweepArgs() {
    size = "320x240";
    threads = 2;
  }
  std::string param;             // NAME=FROM:TO:STEPS[:log]
  std::string methods = "gl,fast";
  std::string shard;             // K/N; empty: every value
  std::string out;
  std::string threshold = "30";  // dB of the final image against llvmpipe
  bool noSoftpipe = false;
  bool check = false;            // check every option, render nothing, exit 0
};

struct SweepMergeArgs {
  std::vector<std::string> shards;   // folders written by `raster sweep --shard K/N`
  std::string out;
};

void addSweepOptions(CLI::App& command, SweepArgs& args);
int runSweep(const SweepArgs& args);
void addSweepMergeOptions(CLI::App& command, SweepMergeArgs& args);
int runSweepMerge(const SweepMergeArgs& args);

}  // namespace cli
