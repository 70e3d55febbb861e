// The numbers behind a stage view (views.h): each pass as one value per pixel (the picture),
// and the figures that go under its cell and into the sidecar JSON.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/view_recorder.h"

namespace cli {

enum class View { Overdraw, DepthKills, Helpers, TileCost, Triangles };

// One value per pixel as num / den, top row first (as the rendered picture reads); den 0:
// nothing to show there. A ratio is kept as its two sums so a scaled-down cell shows the
// ratio of its pixels' sums.
struct Field {
  int width = 0, height = 0;
  std::vector<double> num, den;
};

// The view's value at every pixel of the pass (Triangles: none; the wireframe is drawn).
Field fieldOf(View view, const raster::ViewPass& pass);

// The field scaled to width x height: each cell pixel sums the source pixels under it
// (nearest source pixel when scaling up).
Field resample(const Field& f, int width, int height);

// The sum of a per-pixel count.
uint64_t total(const std::vector<uint32_t>& values);

// "pass 2: label - shadow/main (640x480, window)": the pass, its programs and its size.
std::string passTitle(const raster::ViewPass& pass);

// The pass's figures for the view: its JSON entry, and the line under its cell.
struct PassFigures {
  nlohmann::json json;
  std::string line;
  double scaleMax = 0;   // the largest value the view shows of this pass
};
PassFigures figuresOf(View view, const raster::ViewPass& pass);

// Tick values for a scale [0, max]: 0, max and a round step (1, 2 or 5 times a power of ten,
// whole numbers for counts) between them, at most about six.
std::vector<double> ticksFor(double max, bool whole);

// A tick's label in the view's unit.
std::string tickText(View view, double v);

}  // namespace cli
