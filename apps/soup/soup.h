// `raster soup`: random triangle soups through this pipeline and llvmpipe, compared exactly.
//
//   raster soup --seeds A:B [--size WxH] [--triangles N] [--out DIR] [--json FILE] [--threads N] [--scalar]
//   raster soup --replay FILE [--json FILE] [--threads N] [--scalar]
//
// Seeds A through B (inclusive; "--seeds 7" is seed 7 alone) each make a soup
// (scenes/soup/soup.h: tiny, sliver, pixel-grid, far-out, huge, near-zero-w, negative-w,
// depth-plane, degenerate and non-finite triangles, and closed fans and strips), rendered by
// both pipelines (scenes/soup/soup_check.h). The visible triangle's ID and the depth code of
// every pixel must be identical, and so must every closed mesh's fragment counts, which on
// this pipeline must also be watertight (each pixel inside hit exactly once); llvmpipe
// failing that is reported as a note. Non-finite triangles are drawn apart and reported,
// never compared: GL leaves them undefined.
//
// A line per seed on stdout, a summary at the end; progress on stderr every few seconds
// once a run takes longer than that. A seed that differs is named with its first
// differing pixels (the triangle IDs and depth codes of both sides), and its soup is written
// to DIR/soup-SEED.json (apps/soup/soup_file.h; --out, default the current folder), which
// `raster soup --replay` renders again with the same comparison. --json FILE: the same results
// for scripts (the run, its counts, every failing seed, and the first failures in full).
//
// Exit status: 0 every seed identical and watertight; 1 any difference; 2 bad input.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace cli {

struct SoupArgs {
  std::string seeds;
  std::string replay;
  std::string size = "128x128";
  std::string triangles = "64";
  std::string out = ".";
  std::string json;                // empty: no JSON
  int threads = 0;
  bool scalar = false;             // this pipeline with every SIMD fast path off
  bool injectDifference = false;   // hidden: this pipeline's triangles one pixel right
};

void addSoupOptions(CLI::App& command, SoupArgs& args);
int runSoup(const SoupArgs& args);

}  // namespace cli
