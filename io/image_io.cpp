// PNG files (stb_image_write, stb_image): previews, RGBA8 images, heat maps.
// See image_io.h for the formats and conventions.
#include "io/image_io.h"

#include "io/output_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

#include "compare/metrics.h"

namespace compare {
namespace {

using scenes::ImageData;
using scenes::TexelFormat;

// Encodes 8-bit pixels (top row first, `components` per pixel) as PNG bytes.
std::string encodePng(int width, int height, int components, const std::vector<uint8_t>& pixels) {
  std::string bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, width, height, components, pixels.data(),
                              width * components))
    throw std::runtime_error("PNG encoding failed");
  return bytes;
}

uint8_t toByte(double unit) {   // [0,1] -> 0..255, rounded
  return uint8_t(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0));
}

// Heat-map colour of a difference: black 0, blue 1, yellow 4, red >= 16 (log2 steps).
std::array<uint8_t, 3> heatColour(uint64_t difference) {
  if (difference == 0) return {0, 0, 0};
  const double t = std::min(std::log2(double(difference)), 4.0);   // 0 at 1, 2 at 4, 4 at 16
  if (t <= 2.0) {
    const double s = t / 2.0;                                      // blue -> yellow
    return {toByte(s), toByte(s), toByte(1.0 - s)};
  }
  const double s = (t - 2.0) / 2.0;                                // yellow -> red
  return {255, toByte(1.0 - s), 0};
}

}  // namespace

void writePng(const std::string& path, const ImageData& image) {
  const std::string kind = imageKind(image);
  const size_t pixels = size_t(image.width) * size_t(image.height);
  if (kind == "rgba8") {
    writeOutputFile(path, encodePng(image.width, image.height, 4, image.rgba8));
    return;
  }
  if (kind == "depth") {
    // Grey: contrast-stretched between the codes present, else scaled by the full range.
    const auto [lo, hi] = std::minmax_element(image.depth.begin(), image.depth.end());
    const double low = lo == image.depth.end() || *lo == *hi ? 0.0 : double(*lo);
    const double range = lo == image.depth.end() || *lo == *hi
                             ? std::ldexp(1.0, image.depthBits) - 1.0
                             : double(*hi) - double(*lo);
    std::vector<uint8_t> grey(pixels);
    for (size_t i = 0; i < pixels; ++i) grey[i] = toByte((double(image.depth[i]) - low) / range);
    writeOutputFile(path, encodePng(image.width, image.height, 1, grey));
    return;
  }
  // Float: clamp, gamma 1/2.2, opaque (alpha of an intermediate buffer would hide colour).
  const int channels = image.channels;
  const int components = channels >= 3 ? 3 : 1;
  std::vector<uint8_t> preview(pixels * components);
  for (size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < components; ++c) {
      const double v = std::clamp(double(image.floats[i * channels + c]), 0.0, 1.0);
      preview[i * components + c] = toByte(std::pow(v, 1.0 / 2.2));
    }
  writeOutputFile(path, encodePng(image.width, image.height, components, preview));
}

ImageData readPng(const std::string& path) {
  int width = 0, height = 0, components = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &components, 4);
  if (!pixels) throw std::runtime_error("cannot read " + path + ": " + stbi_failure_reason());
  ImageData image;
  image.width = width;
  image.height = height;
  image.format = TexelFormat::RGBA8;
  image.rgba8.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
  stbi_image_free(pixels);
  return image;
}

void writeHeatmapPng(const std::string& path, const ImageData& a, const ImageData& b) {
  checkComparable(path, a, b);
  const size_t pixels = size_t(a.width) * size_t(a.height);
  std::vector<uint8_t> rgb(pixels * 3);
  for (size_t i = 0; i < pixels; ++i) {
    const auto colour = heatColour(pixelDifference(a, b, i));
    std::copy(colour.begin(), colour.end(), &rgb[i * 3]);
  }
  writeOutputFile(path, encodePng(a.width, a.height, 3, rgb));
}

}  // namespace compare
