// The numbers behind a stage view (view_figures.h).
#include "apps/views/view_figures.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "apps/common/number_text.h"

namespace cli {
namespace {

using raster::ViewPass;
using Json = nlohmann::json;

// The pass's memory row under picture row y: window buffers are stored top row first,
// framebuffer objects bottom row first.
int memoryRow(const ViewPass& pass, int y) { return pass.window ? y : pass.height - 1 - y; }

// The pass's texel (memory rows) under picture pixel (x, y).
size_t texelAt(const ViewPass& pass, int x, int y) { return size_t(memoryRow(pass, y)) * size_t(pass.width) + size_t(x); }

struct Stats {
  double total = 0, min = 0, max = 0, mean = 0;
};

// A per-pixel count's or per-tile time's total, extremes and mean.
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

Json statsJson(const Stats& s) { return {{"total", s.total}, {"min", s.min}, {"max", s.max}, {"mean", s.mean}}; }

// "shadow/main, shadow/ground" (each program once, in draw order), or "clear only".
std::string programsOf(const ViewPass& pass) {
  std::vector<std::string> names;
  for (const std::string& p : pass.drawPrograms)
    if (std::find(names.begin(), names.end(), p) == names.end()) names.push_back(p.empty() ? "?" : p);
  if (names.empty()) return "clear only";
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

bool depthOnlyPass(const ViewPass& pass) { return pass.colorTargets == 0; }

}  // namespace

Field fieldOf(View view, const ViewPass& pass) {
  Field f{pass.width, pass.height, {}, {}};
  const size_t n = size_t(pass.width) * size_t(pass.height);
  f.num.assign(n, 0.0);
  f.den.assign(n, 1.0);
  const raster::FragmentCounts& c = pass.counts;
  for (int y = 0; y < pass.height; ++y) {
    for (int x = 0; x < pass.width; ++x) {
      const size_t at = size_t(y) * size_t(pass.width) + size_t(x), texel = texelAt(pass, x, y);
      switch (view) {
        case View::Overdraw: f.num[at] = c.shaded[texel]; break;
        case View::DepthKills: f.num[at] = c.depthKills[texel]; break;
        case View::Helpers: {   // the sums of the texel's 2x2 quad (quads start at even texels)
          const int qx = x & ~1, row = memoryRow(pass, y) & ~1;
          double helpers = 0, lanes = 0;
          for (int dy = 0; dy < 2 && row + dy < pass.height; ++dy)
            for (int dx = 0; dx < 2 && qx + dx < pass.width; ++dx) {
              const size_t t = size_t(row + dy) * size_t(pass.width) + size_t(qx + dx);
              helpers += c.helpersUncovered[t] + c.helpersKilled[t];
              lanes += c.helpersUncovered[t] + c.helpersKilled[t] + c.shaded[t];
            }
          f.num[at] = helpers;
          f.den[at] = lanes;
          break;
        }
        case View::TileCost: {
          const size_t tile = size_t(memoryRow(pass, y) / raster::limits::kTileSize) * size_t(pass.tilesX) + size_t(x / raster::limits::kTileSize);
          f.num[at] = double(pass.tileCycles[tile]) / 1000.0;
          break;
        }
        case View::Triangles: break;
      }
    }
  }
  return f;
}

Field resample(const Field& f, int width, int height) {
  if (width == f.width && height == f.height) return f;
  Field out{width, height, std::vector<double>(size_t(width) * size_t(height)), std::vector<double>(size_t(width) * size_t(height))};
  const double sx = double(f.width) / width, sy = double(f.height) / height;
  for (int y = 0; y < height; ++y) {
    const int y0 = std::min(int(y * sy), f.height - 1), y1 = std::clamp(int((y + 1) * sy), y0 + 1, f.height);
    for (int x = 0; x < width; ++x) {
      const int x0 = std::min(int(x * sx), f.width - 1), x1 = std::clamp(int((x + 1) * sx), x0 + 1, f.width);
      double num = 0, den = 0;
      for (int v = y0; v < y1; ++v)
        for (int u = x0; u < x1; ++u) {
          num += f.num[size_t(v) * size_t(f.width) + size_t(u)];
          den += f.den[size_t(v) * size_t(f.width) + size_t(u)];
        }
      out.num[size_t(y) * size_t(width) + size_t(x)] = num;
      out.den[size_t(y) * size_t(width) + size_t(x)] = den;
    }
  }
  return out;
}

uint64_t total(const std::vector<uint32_t>& values) {
  uint64_t total = 0;
  for (uint32_t v : values) total += v;
  return total;
}

std::string passTitle(const ViewPass& pass) {
  return "pass " + std::to_string(pass.index) + ": " + (pass.label.empty() ? "" : pass.label + " - ") + programsOf(pass) + " (" + std::to_string(pass.width) + "x" +
         std::to_string(pass.height) + (pass.window ? ", window" : "") + ")";
}

PassFigures figuresOf(View view, const ViewPass& pass) {
  PassFigures f;
  f.json = {{"index", pass.index},
            {"label", pass.label},
            {"programs", pass.drawPrograms},
            {"width", pass.width},
            {"height", pass.height},
            {"window", pass.window},
            {"color_targets", pass.colorTargets},
            {"depth", pass.depth},
            {"draws", pass.drawPrograms.size()},
            {"triangles", pass.triangles},
            {"pipeline_counters",
             {{"lane_groups_shaded", pass.counters.laneGroupsShaded},
              {"lanes_shaded", pass.counters.lanesShaded},
              {"lanes_covered", pass.counters.lanesCovered}}}};
  const raster::FragmentCounts& c = pass.counts;
  switch (view) {
    case View::Overdraw: {
      const Stats s = statsOf(c.shaded);
      f.json["fragments_shaded"] = statsJson(s);
      f.json["depth_only_fragments"] = total(c.depthOnly);
      f.scaleMax = s.max;
      f.line = depthOnlyPass(pass) ? "depth only, no shader: " + std::to_string(total(c.depthOnly)) + " fragments passed"
                                   : "shaded " + std::to_string(uint64_t(s.total)) + ", max " + sixDigits(s.max) +
                                         ", mean " + fixedDigits(s.mean, 2);
      break;
    }
    case View::DepthKills: {
      const Stats s = statsOf(c.depthKills);
      f.json["depth_kills"] = statsJson(s);
      f.json["early"] = uint64_t(s.total);
      f.json["late"] = 0;
      f.scaleMax = s.max;
      f.line = "rejected " + std::to_string(uint64_t(s.total)) + " (all early), max " + sixDigits(s.max) + ", mean " +
               fixedDigits(s.mean, 2);
      break;
    }
    case View::Helpers: {
      const uint64_t uncovered = total(c.helpersUncovered), killed = total(c.helpersKilled), shaded = total(c.shaded);
      const uint64_t helperLanes = pass.counters.lanesShaded - pass.counters.lanesCovered;
      const double share = pass.counters.lanesShaded ? double(helperLanes) / double(pass.counters.lanesShaded) : 0.0;
      f.json["helpers"] = {{"uncovered", uncovered},
                           {"depth_failed", killed},
                           {"off_framebuffer", helperLanes - uncovered - killed},
                           {"total", helperLanes},
                           {"fragments_shaded", shaded},
                           {"lanes_shaded", pass.counters.lanesShaded},
                           {"share", share}};
      f.scaleMax = 0.75;
      f.line = pass.counters.lanesShaded ? "helpers " + fixedDigits(100.0 * share, 1) + "% of " +
                                               std::to_string(pass.counters.lanesShaded) + " lanes shaded"
                                         : "no lane shaded";
      break;
    }
    case View::TileCost: {
      const Stats s = statsOf(pass.tileCycles);
      f.json["tile_cycles"] = statsJson(s);
      f.json["tiles"] = {pass.tilesX, pass.tilesY};
      f.scaleMax = s.max / 1000.0;
      f.line = std::to_string(pass.tileCycles.size()) + (pass.tileCycles.size() == 1 ? " tile, max " : " tiles, max ") + fixedDigits(s.max / 1000.0, 0) + " kcyc, mean " +
               fixedDigits(s.mean / 1000.0, 0) + " kcyc";
      break;
    }
    case View::Triangles: {
      std::map<std::string, uint64_t> perProgram;
      for (const raster::ViewTriangle& t : pass.triangleList) ++perProgram[pass.drawPrograms[t.drawIndex]];
      f.json["triangles_per_program"] = perProgram;
      f.json["triangles_drawn"] = pass.triangleList.size();
      f.line = std::to_string(pass.triangles) + " triangles, " + std::to_string(pass.drawPrograms.size()) + " draws";
      break;
    }
  }
  return f;
}

std::vector<double> ticksFor(double max, bool whole) {
  std::vector<double> ticks;
  if (!(max > 0)) return {0.0};
  double step = std::pow(10.0, std::floor(std::log10(max / 5.0)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (max / (step * m) <= 6.0) { step *= m; break; }
  if (whole) step = std::max(step, 1.0);
  for (double v = 0; v < max - step * 0.6; v += step) ticks.push_back(v);   // room for max's label
  ticks.push_back(max);
  return ticks;
}

std::string tickText(View view, double v) {
  if (view == View::Helpers) return fixedDigits(100.0 * v, 0) + "%";
  if (view == View::TileCost && v >= 10) return fixedDigits(v, 0);
  return v == std::floor(v) && v < 1e15 ? std::to_string(int64_t(v)) : sixDigits(v);
}

}  // namespace cli
