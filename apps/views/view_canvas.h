// Drawing the stage views' images (view_sheet.h, view_painters.h): an RGB canvas with
// filled rectangles, clipped lines, text in stb_easy_font's built-in bitmap font (Debian's
// libstb-dev, already the project's PNG library) and a colour ramp, so a view's PNG carries
// its own legend with no plotting tool at run time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "backends/backend.h"

namespace cli {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
};

// The views' colour ramp for t in [0, 1] (clamped): viridis, dark blue-purple at 0 through
// green to yellow at 1, perceptually even and readable by most colour-blind eyes.
Rgb rampColor(double t);

// A distinct colour for category i (matplotlib's tab10, cycled).
Rgb categoryColor(size_t i);

class Canvas {
 public:
  static constexpr int kLineHeight = 12;   // stb_easy_font's line advance at scale 1

  Canvas(int width, int height, Rgb background);
  int width() const { return width_; }
  int height() const { return height_; }

  void set(int x, int y, Rgb c) {
    if (x >= 0 && y >= 0 && x < width_ && y < height_) pixels_[size_t(y) * size_t(width_) + size_t(x)] = c;
  }
  void fill(int x, int y, int w, int h, Rgb c);
  // A one-pixel line from (x0, y0) to (x1, y1), clipped first to the pixels [clipX0, clipX1)
  // x [clipY0, clipY1) (its ends may lie anywhere, far outside included).
  void line(double x0, double y0, double x1, double y1, Rgb c, int clipX0, int clipY0, int clipX1, int clipY1);
  // Text with its top-left corner at (x, y), each font pixel scale x scale; characters
  // outside printable ASCII show as '?'. Returns the width drawn.
  int text(int x, int y, const std::string& text, Rgb c, int scale = 1);
  static int textWidth(const std::string& text, int scale = 1);

  // As an RGBA8 image for compare::writePng.
  scenes::ImageData image() const;

 private:
  int width_, height_;
  std::vector<Rgb> pixels_;
};

// `text` broken at spaces into lines no wider than `width` pixels at `scale`.
std::vector<std::string> wrapText(const std::string& text, int width, int scale = 1);

}  // namespace cli
