// The stage views' canvas (view_canvas.h).
#include "apps/views/view_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstring>

// stb_easy_font is a header of static functions, some of which this file does not call.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace cli {

Rgb rampColor(double t) {
  // viridis at nine even stops, linearly interpolated between them
  static constexpr uint8_t kStops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},  {44, 113, 142}, {33, 144, 141},
                                          {39, 173, 129}, {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  if (!(t > 0.0)) t = 0.0;   // NaN too
  if (t > 1.0) t = 1.0;
  const double at = t * 8.0;
  const int i = std::min(int(at), 7);
  const double f = at - double(i);
  auto mix = [&](int c) { return uint8_t(std::lround(double(kStops[i][c]) * (1.0 - f) + double(kStops[i + 1][c]) * f)); };
  return {mix(0), mix(1), mix(2)};
}

Rgb categoryColor(size_t i) {
  static constexpr Rgb kTab10[10] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
                                     {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
  return kTab10[i % 10];
}

Canvas::Canvas(int width, int height, Rgb background)
    : width_(width), height_(height), pixels_(size_t(width) * size_t(height), background) {}

void Canvas::fill(int x, int y, int w, int h, Rgb c) {
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = std::min(x + w, width_), y1 = std::min(y + h, height_);
  if (x1 <= x0) return;
  for (int row = y0; row < y1; ++row)
    std::fill(pixels_.begin() + long(size_t(row) * size_t(width_) + size_t(x0)),
              pixels_.begin() + long(size_t(row) * size_t(width_) + size_t(x1)), c);
}

void Canvas::line(double x0, double y0, double x1, double y1, Rgb c, int clipX0, int clipY0, int clipX1, int clipY1) {
  // Liang-Barsky against the clip box, so a far-off end costs nothing.
  double t0 = 0.0, t1 = 1.0;
  const double dx = x1 - x0, dy = y1 - y0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x0 - clipX0, double(clipX1) - x0, y0 - clipY0, double(clipY1) - y0};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0.0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    if (t0 > t1) return;
  }
  const double ax = x0 + t0 * dx, ay = y0 + t0 * dy, bx = x0 + t1 * dx, by = y0 + t1 * dy;
  const int steps = int(std::ceil(std::max(std::fabs(bx - ax), std::fabs(by - ay)))) + 1;
  for (int s = 0; s <= steps; ++s) {
    const double f = double(s) / double(steps);
    const int x = int(std::floor(ax + (bx - ax) * f)), y = int(std::floor(ay + (by - ay) * f));
    if (x >= clipX0 && x < clipX1 && y >= clipY0 && y < clipY1) set(x, y, c);
  }
}

namespace {
std::string printable(const std::string& text) {
  std::string out = text;
  for (char& ch : out)
    if (ch < 32 || ch > 126) ch = '?';
  return out;
}
}  // namespace

int Canvas::text(int x, int y, const std::string& text, Rgb c, int scale) {
  std::string line = printable(text);
  // 4 vertices of 16 bytes per quad; a character is at most a dozen quads.
  std::vector<char> buffer(line.size() * 16 * 64 + 64);
  const int quads = stb_easy_font_print(0.0f, 0.0f, line.data(), nullptr, buffer.data(), int(buffer.size()));
  for (int q = 0; q < quads; ++q) {
    float minX = 1e9f, minY = 1e9f, maxX = -1e9f, maxY = -1e9f;
    for (int v = 0; v < 4; ++v) {
      float vertex[2];   // x, y of a 16-byte vertex (then z and a colour)
      std::memcpy(vertex, buffer.data() + (q * 4 + v) * 16, sizeof vertex);
      minX = std::min(minX, vertex[0]);
      maxX = std::max(maxX, vertex[0]);
      minY = std::min(minY, vertex[1]);
      maxY = std::max(maxY, vertex[1]);
    }
    fill(x + int(std::lround(minX)) * scale, y + int(std::lround(minY)) * scale,
         int(std::lround(maxX - minX)) * scale, int(std::lround(maxY - minY)) * scale, c);
  }
  return textWidth(line, scale);
}

int Canvas::textWidth(const std::string& text, int scale) {
  std::string line = printable(text);
  return stb_easy_font_width(line.data()) * scale;
}

scenes::ImageData Canvas::image() const {
  scenes::ImageData image;
  image.width = width_;
  image.height = height_;
  image.channels = 4;
  image.rgba8.reserve(pixels_.size() * 4);
  for (const Rgb& p : pixels_) image.rgba8.insert(image.rgba8.end(), {p.r, p.g, p.b, 255});
  return image;
}

std::vector<std::string> wrapText(const std::string& text, int width, int scale) {
  std::vector<std::string> lines;
  std::string line;
  size_t at = 0;
  while (at < text.size()) {
    size_t end = text.find(' ', at);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(at, end - at);
    const std::string joined = line.empty() ? word : line + " " + word;
    if (!line.empty() && Canvas::textWidth(joined, scale) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = joined;
    }
    at = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace cli
