// `raster report SCENE... --out DIR`: one HTML page a person opens in a browser, with what
// the other commands measure, side by side.
//
// DIR/index.html, self-contained (no script, no network; every image a file beside it):
//   - per scene and target: this pipeline's image, llvmpipe's and the difference heat map,
//     with the target's metrics (compare::compareImages, what `raster compare` prints). RGBA8
//     targets are PNGs as they are; float, half and depth targets get a PNG preview
//     (compare::writePng: floats clamped to [0,1] and gamma 1/2.2, depth contrast-stretched)
//     and their lossless OpenEXR files as the data (compare/exr_io.h), linked;
//   - per scene, the stage views of `raster render --view NAME` (each with its sidecar JSON),
//     the list of views as that command gives it;
//   - per scene, the pixel history (`raster trace --json`) of a few pixels: the worst
//     differing pixels of the final image first (report_pixels.h);
//   - the tradeoff and sweep charts and their tables, from every tradeoff.json / sweep.json
//     under the --include folders (default: the repository's docs/).
// Views and traces come from child processes of this program, as softpipe's frames do; a
// build without `render --view` or `trace` gets a visible note in their place.
// DIR/report.json holds the numbers the tables show.
//
// Nothing is half-written: everything is checked before the first frame, the report is made
// in a temporary folder beside DIR and renamed onto it at the end (a DIR that exists must be
// empty or a previous report, which is then replaced).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/common/cli_options.h"

namespace cli {

struct ReportArgs : FrameArgs {
  std::vector<std::string> scenes;     // names, or "all"
  std::string out;
  std::vector<std::string> include;    // folders searched for tradeoff.json / sweep.json
  bool noDefaultInclude = false;
  int pixels = 3;
};

void addReportOptions(CLI::App& command, ReportArgs& args);
int runReport(const ReportArgs& args);

}  // namespace cli
