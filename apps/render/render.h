// `raster render SCENE`: one frame with this pipeline or GL; the final image as PNG, and with
// --dump every target (a PNG preview each, and a lossless dump of depth and float ones).
// With --view NAME it draws a stage view of the frame instead (apps/views/view_render.h).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "apps/common/cli_options.h"

namespace cli {

struct RenderArgs : FrameArgs {
  std::string backend = "raster";
  std::string out;             // empty: SCENE.png
  std::string dump;            // empty: no dump
  std::string view;            // empty: the image; else a stage view (apps/views/stage_views.h)
  std::string pass;            // the view's pass: a number, or empty / "all" for every pass
};

// render_options.cpp, apart so that the command-line fuzz target (fuzz/cli_fuzz.cpp) links
// the options without what renders.
void addRenderOptions(CLI::App& command, RenderArgs& args);

int runRender(const RenderArgs& args);

}  // namespace cli
