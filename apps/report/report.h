// `raster report SCENE... --out DIR`: one HTML page a person opens in a browser, with what
// the other commands measure, side by side.
//
// DIR/index.html, self-contained (no script, no network; every image a file beside it):
//   - per scene and target: this pipeline's image, llvmpipe's and the difference heat map,
//     with the target's metrics (compare::compareImages, what `raster compare` prints):
//     report_targets.h, which also says how each kind of target is previewed (an RGBA8
//     target opaque, its alpha, which is data, as a grey image of its own);
//   - per scene, every stage view of `raster render --view NAME` (each with its sidecar
//     JSON), the views as their registry lists them (apps/views/stage_views.h);
//   - per scene, the pixel history (`raster trace --json`) of a few pixels: the worst
//     differing pixels of the final image first (apps/common/pixels_to_trace.h);
//   - the tradeoff and sweep charts and their tables, from every tradeoff.json / sweep.json
//     under the --include folders (default: the repository's docs/): report_charts.h.
// Views and traces come from child processes of this program (report_children.h), as
// softpipe's frames do; a child that fails leaves a visible note in its place.
// DIR/report.json holds the numbers the tables show.
//
// Nothing is half-written: everything is checked before the first frame, and the report is
// made beside DIR and moved onto it at the end (report_folder.h).
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
