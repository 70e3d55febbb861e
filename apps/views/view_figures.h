// The numbers every stage view (stage_views.h) builds its own from: a pass as one value per
// pixel (Field), the statistics of a per-pixel count or per-tile time, the figures every
// pass's sidecar entry starts with, and the ticks of a colour scale.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/view_recorder.h"

namespace cli {

// One value per pixel as num / den, top row first (as the rendered picture reads); den 0:
// nothing to show there. A ratio is kept as its two sums so a scaled-down cell shows the
// ratio of its pixels' sums.
struct Field {
  int width = 0, height = 0;
  std::vector<double> num, den;
};

// The field scaled to width x height: each cell pixel sums the source pixels under it
// (nearest source pixel when scaling up).
Field resample(const Field& f, int width, int height);

// The pass's memory row under picture row y: window buffers are stored top row first,
// framebuffer objects bottom row first.
inline int memoryRow(const raster::ViewPass& pass, int y) { return pass.window ? y : pass.height - 1 - y; }

// The pass's texel (memory rows) under picture pixel (x, y).
inline size_t texelAt(const raster::ViewPass& pass, int x, int y) {
  return size_t(memoryRow(pass, y)) * size_t(pass.width) + size_t(x);
}

// A per-pixel count of the pass (one of its FragmentCounts) as a field: the count over 1.
Field countField(const raster::ViewPass& pass, const std::vector<uint32_t>& counts);
// The same for a fractional count (FragmentCounts::invocations).
Field countField(const raster::ViewPass& pass, const std::vector<float>& counts);

// The sum of a per-pixel count.
uint64_t total(const std::vector<uint32_t>& values);

// A per-pixel count's or per-tile time's total, extremes and mean.
struct Stats {
  double total = 0, min = 0, max = 0, mean = 0;
};
template <class T>
Stats statsOf(const std::vector<T>& values) {
  Stats s;
  if (values.empty()) return s;
  s.min = double(*std::min_element(values.begin(), values.end()));
  s.max = double(*std::max_element(values.begin(), values.end()));
  for (T v : values) s.total += double(v);
  s.mean = s.total / double(values.size());
  return s;
}
nlohmann::json statsJson(const Stats& s);

// "pass 2: label - shadow/main (640x480, window)": the pass, its programs and its size.
std::string passTitle(const raster::ViewPass& pass);

// A pass's figures for a view: its sidecar entry, the line under its cell, and the largest
// value the view shows of it (the colour scale's top is the largest of the passes shown).
struct PassFigures {
  nlohmann::json json;
  std::string line;
  double scaleMax = 0;
};

// What every view's entry for a pass starts with: its index, label, programs, size,
// targets, draws, triangles and tile-stage counters.
PassFigures passFigures(const raster::ViewPass& pass);

// Tick values for a scale [0, max]: 0, max and a round step (1, 2 or 5 times a power of ten,
// whole numbers for counts) between them, at most about six.
std::vector<double> ticksFor(double max, bool whole);

// A tick's label as a plain number: whole numbers as integers, others to 6 digits.
std::string plainTickText(double v);

}  // namespace cli
