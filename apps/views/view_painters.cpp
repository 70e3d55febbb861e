// The stage views' painters (view_painters.h).
#include "apps/views/view_painters.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "apps/views/stage_views.h"

namespace cli {
namespace {

using raster::ViewPass;
using Json = nlohmann::json;

class HeatMapPainter final : public ViewPainter {
 public:
  HeatMapPainter(const StageView& view, const SheetLayout& layout, const SheetPasses& passes)
      : heat_(view.heatMap), layout_(layout) {
    // One scale for every cell: its top from the largest value of the passes shown.
    double largest = 0;
    for (const ViewPass* p : passes.shown) largest = std::max(largest, passes.figures[size_t(p->index)].scaleMax);
    top_ = heat_.top(largest);
    scaleLines_ = wrapText(std::string("colour scale: ") + heat_.quantity +
                               (layout.native ? "" : "; scaled-down cells show the mean of the pixels under them"),
                           layout.textWidth, layout.textScale);
  }

  int legendHeight() const override { return layout_.line * (int(scaleLines_.size()) + 3) + layout_.margin; }

  void drawPass(Canvas& canvas, const ViewPass& pass, int x, int y, int width, int height) const override {
    const Field field = resample(heat_.field(pass), width, height);
    for (int v = 0; v < height; ++v)
      for (int u = 0; u < width; ++u) {
        const size_t at = size_t(v) * size_t(width) + size_t(u);
        canvas.set(x + u, y + v, field.den[at] > 0 ? rampColor(position(field.num[at] / field.den[at])) : kNoData);
      }
  }

  // The scale's text, the ramp as a bar, its ticks and their labels, and the no-data swatch.
  Json drawLegend(Canvas& canvas, int y) const override {
    const int scale = layout_.textScale, line = layout_.line, margin = layout_.margin;
    for (size_t i = 0; i < scaleLines_.size(); ++i) canvas.text(margin, y + int(i) * line, scaleLines_[i], kInk, scale);
    const int barX = margin, barY = y + int(scaleLines_.size()) * line + scale * 2;
    const int barWidth = std::min(layout_.textWidth - 100 * scale, 400 * scale);
    for (int u = 0; u < barWidth; ++u) canvas.fill(barX + u, barY, 1, line, rampColor(double(u) / (barWidth - 1)));
    const std::vector<double> ticks = tickValues();
    for (double t : ticks) {
      const int tx = barX + int(std::lround(position(t) * (barWidth - 1)));
      canvas.fill(tx, barY + line, scale, scale * 3, kInk);
      const std::string label = heat_.tickText(t);
      const int labelWidth = Canvas::textWidth(label, scale);
      canvas.text(std::clamp(tx - labelWidth / 2, 0, layout_.width - labelWidth), barY + line + scale * 4, label, kInk, scale);
    }
    if (heat_.noData) {
      canvas.fill(barX + barWidth + 2 * margin, barY, line, line, kNoData);
      canvas.text(barX + barWidth + 3 * margin + line, barY + scale, heat_.noData, kInk, scale);
    }
    Json legend = {{"quantity", heat_.quantity}, {"min", 0},          {"max", top_},
                   {"ticks", ticks},             {"ramp", "viridis"}, {"scale", heat_.logarithmic ? "log10(1 + value)" : "linear"}};
    if (heat_.noDataNote) legend["no_data_colour"] = heat_.noDataNote;
    return legend;
  }

 private:
  // Where a value sits on the ramp, 0..1.
  double position(double v) const {
    return heat_.logarithmic ? std::log10(1.0 + std::max(v, 0.0)) / std::log10(1.0 + top_) : v / top_;
  }

  // A logarithmic scale is ticked at 0, then each power of ten that leaves room before the
  // top; a linear one at round steps.
  std::vector<double> tickValues() const {
    if (!heat_.logarithmic) return ticksFor(top_, heat_.wholeTicks);
    std::vector<double> ticks = {0.0};
    for (double decade = 1; decade * 3 < top_; decade *= 10) ticks.push_back(decade);
    ticks.push_back(top_);
    return ticks;
  }

  const HeatMap& heat_;
  SheetLayout layout_;
  double top_ = 1;
  std::vector<std::string> scaleLines_;
};

class WireframePainter final : public ViewPainter {
 public:
  WireframePainter(const SheetLayout& layout, const SheetPasses& passes) : layout_(layout) {
    // The programs in order of first appearance among the passes shown, a colour each.
    for (const ViewPass* p : passes.shown)
      for (const raster::ViewTriangle& t : p->triangleList) {
        const std::string& name = p->drawPrograms[t.drawIndex];
        if (!triangles_.count(name)) programs_.push_back(name);
        ++triangles_[name];
      }
  }

  int legendHeight() const override { return layout_.line * (int(programs_.size()) + 1) + layout_.margin; }

  // Each triangle's edges on black, scaled from the pass's pixels to the box; y flipped
  // for framebuffer objects, whose memory rows run bottom up.
  void drawPass(Canvas& canvas, const ViewPass& pass, int x, int y, int width, int height) const override {
    canvas.fill(x, y, width, height, Rgb{0, 0, 0});
    const double sx = double(width) / pass.width, sy = double(height) / pass.height;
    const auto px = [&](float vx) { return x + double(vx) * sx; };
    const auto py = [&](float vy) { return y + (pass.window ? double(vy) : double(pass.height) - double(vy)) * sy; };
    for (const raster::ViewTriangle& t : pass.triangleList) {
      const Rgb colour = categoryColor(programIndex(pass.drawPrograms[t.drawIndex]));
      for (int e = 0; e < 3; ++e) {
        const int f = (e + 1) % 3;
        canvas.line(px(t.x[e]), py(t.y[e]), px(t.x[f]), py(t.y[f]), colour, x, y, x + width, y + height);
      }
    }
  }

  // A swatch per program with its triangle count.
  Json drawLegend(Canvas& canvas, int y) const override {
    const int scale = layout_.textScale, line = layout_.line, margin = layout_.margin;
    Json legend;
    canvas.text(margin, y, "colour: the draw's program (triangles in the passes shown)", kInk, scale);
    for (size_t i = 0; i < programs_.size(); ++i) {
      y += line;
      const std::string& program = programs_[i];
      const uint64_t count = triangles_.at(program);
      canvas.fill(margin, y, line - 2, line - 2, categoryColor(i));
      canvas.text(margin + line + margin / 2, y + scale,
                  (program.empty() ? "?" : program) + ": " + std::to_string(count) + " triangles", kInk, scale);
      legend["programs"].push_back({{"program", program}, {"triangles", count}});
    }
    legend["background"] = "black";
    return legend;
  }

 private:
  size_t programIndex(const std::string& program) const {
    return size_t(std::find(programs_.begin(), programs_.end(), program) - programs_.begin());
  }

  SheetLayout layout_;
  std::vector<std::string> programs_;
  std::map<std::string, uint64_t> triangles_;   // per program, over the passes shown
};

}  // namespace

std::unique_ptr<ViewPainter> heatMapPainter(const StageView& view, const SheetLayout& layout, const SheetPasses& passes) {
  return std::make_unique<HeatMapPainter>(view, layout, passes);
}

std::unique_ptr<ViewPainter> wireframePainter(const StageView&, const SheetLayout& layout, const SheetPasses& passes) {
  return std::make_unique<WireframePainter>(layout, passes);
}

}  // namespace cli
