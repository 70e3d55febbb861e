// The numbers the stage views share (view_figures.h).
#include "apps/views/view_figures.h"

#include <cmath>

#include "apps/common/number_text.h"

namespace cli {
namespace {

using raster::ViewPass;
using Json = nlohmann::json;

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

}  // namespace

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

namespace {

template <class Count>
Field countFieldOf(const ViewPass& pass, const std::vector<Count>& counts) {
  Field f{pass.width, pass.height, {}, {}};
  const size_t n = size_t(pass.width) * size_t(pass.height);
  f.num.assign(n, 0.0);
  f.den.assign(n, 1.0);
  for (int y = 0; y < pass.height; ++y)
    for (int x = 0; x < pass.width; ++x) f.num[size_t(y) * size_t(pass.width) + size_t(x)] = counts[texelAt(pass, x, y)];
  return f;
}

}  // namespace

Field countField(const ViewPass& pass, const std::vector<uint32_t>& counts) { return countFieldOf(pass, counts); }
Field countField(const ViewPass& pass, const std::vector<float>& counts) { return countFieldOf(pass, counts); }

uint64_t total(const std::vector<uint32_t>& values) {
  uint64_t total = 0;
  for (uint32_t v : values) total += v;
  return total;
}

Json statsJson(const Stats& s) { return {{"total", s.total}, {"min", s.min}, {"max", s.max}, {"mean", s.mean}}; }

std::string passTitle(const ViewPass& pass) {
  return "pass " + std::to_string(pass.index) + ": " + (pass.label.empty() ? "" : pass.label + " - ") + programsOf(pass) +
         " (" + std::to_string(pass.width) + "x" + std::to_string(pass.height) + (pass.window ? ", window" : "") + ")";
}

PassFigures passFigures(const ViewPass& pass) {
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

std::string plainTickText(double v) {
  return v == std::floor(v) && v < 1e15 ? std::to_string(int64_t(v)) : sixDigits(v);
}

}  // namespace cli
