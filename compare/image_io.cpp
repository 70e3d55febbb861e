// Image files: PNG previews (stb_image_write), PFM dumps and their loaders, heat maps.
// See image_io.h for the formats and conventions.
#include "compare/image_io.h"

#include "compare/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

#include "compare/metrics.h"

namespace compare {
namespace {

using scenes::ImageData;
using scenes::TexelFormat;

constexpr int kMaxPfmSide = 1 << 16;   // far above any target; keeps size arithmetic safe

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

// A PFM file: channels 1 ("Pf") or 3 ("PF"), rows top first as ImageData keeps them.
struct Pfm {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;
};

std::string encodePfm(const Pfm& pfm) {
  std::string bytes = (pfm.channels == 3 ? "PF\n" : "Pf\n") + std::to_string(pfm.width) + " " +
                      std::to_string(pfm.height) + "\n-1.0\n";
  // Rows bottom first, each float little endian (the negative scale says so).
  const size_t rowFloats = size_t(pfm.width) * pfm.channels;
  for (int y = pfm.height - 1; y >= 0; --y) {
    for (size_t i = 0; i < rowFloats; ++i) {
      uint32_t bits = std::bit_cast<uint32_t>(pfm.values[size_t(y) * rowFloats + i]);
      for (int byte = 0; byte < 4; ++byte, bits >>= 8) bytes.push_back(char(bits & 0xff));
    }
  }
  return bytes;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  if (!in || !(content << in.rdbuf()))
    throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  return content.str();
}

Pfm decodePfm(const std::string& path) {
  const std::string bytes = readFile(path);
  const auto bad = [&](const char* why) {
    return std::runtime_error("cannot read " + path + ": not a PFM file (" + why + ")");
  };
  // Header: magic, width, height, scale, then exactly one whitespace byte.
  std::istringstream header(bytes);
  std::string magic;
  double scale = 0;
  Pfm pfm;
  if (!(header >> magic >> pfm.width >> pfm.height >> scale) || header.get() == EOF)
    throw bad("bad header");
  if (magic != "PF" && magic != "Pf") throw bad("bad magic");
  if (pfm.width <= 0 || pfm.height <= 0 || pfm.width > kMaxPfmSide || pfm.height > kMaxPfmSide)
    throw bad("bad size");
  if (scale == 0 || !std::isfinite(scale)) throw bad("bad scale");
  pfm.channels = magic == "PF" ? 3 : 1;
  const size_t rowFloats = size_t(pfm.width) * pfm.channels;
  const size_t offset = size_t(header.tellg());
  if (bytes.size() - offset != rowFloats * pfm.height * 4) throw bad("wrong data size");

  // Data: rows bottom first, byte order from the scale's sign.
  const bool littleEndian = scale < 0;
  pfm.values.resize(rowFloats * pfm.height);
  for (size_t i = 0; i < pfm.values.size(); ++i) {
    const auto* p = reinterpret_cast<const uint8_t*>(bytes.data() + offset + 4 * i);
    const uint32_t bits = littleEndian ? (p[0] | p[1] << 8 | p[2] << 16 | uint32_t(p[3]) << 24)
                                       : (p[3] | p[2] << 8 | p[1] << 16 | uint32_t(p[0]) << 24);
    const size_t row = pfm.height - 1 - i / rowFloats;
    pfm.values[row * rowFloats + i % rowFloats] = std::bit_cast<float>(bits);
  }
  return pfm;
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

std::string alphaPfmPath(const std::string& pfmPath) {
  const std::string suffix = ".pfm";
  const bool hasSuffix = pfmPath.size() >= suffix.size() &&
                         pfmPath.compare(pfmPath.size() - suffix.size(), suffix.size(), suffix) == 0;
  return (hasSuffix ? pfmPath.substr(0, pfmPath.size() - suffix.size()) : pfmPath) + ".alpha.pfm";
}

void writePfm(const std::string& path, const ImageData& image) {
  const std::string kind = imageKind(image);
  const size_t pixels = size_t(image.width) * size_t(image.height);
  Pfm pfm{image.width, image.height, 1, {}};
  if (kind == "rgba8") throw std::invalid_argument("RGBA8 images are dumped as PNG, not PFM");
  if (kind == "depth") {
    // Integer codes as floats: exact up to 2^24.
    pfm.values.assign(image.depth.begin(), image.depth.end());
    writeOutputFile(path, encodePfm(pfm));
    return;
  }
  if (image.channels == 1) {
    pfm.values = image.floats;
    writeOutputFile(path, encodePfm(pfm));
    return;
  }
  if (image.channels != 3 && image.channels != 4)
    throw std::invalid_argument("PFM dumps take 1, 3 or 4 channels");
  // RGB to the main file; alpha to its own file only when it carries something.
  pfm.channels = 3;
  Pfm alpha{image.width, image.height, 1, {}};
  bool alphaIsOne = true;
  for (size_t i = 0; i < pixels; ++i) {
    const float* texel = &image.floats[i * image.channels];
    pfm.values.insert(pfm.values.end(), texel, texel + 3);
    if (image.channels == 4) {
      alpha.values.push_back(texel[3]);
      alphaIsOne = alphaIsOne && texel[3] == 1.0f;
    }
  }
  writeOutputFile(path, encodePfm(pfm));
  if (image.channels == 4 && !alphaIsOne)
    writeOutputFile(alphaPfmPath(path), encodePfm(alpha));
  else
    std::filesystem::remove(alphaPfmPath(path));   // a stale one would be read back
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

ImageData readPfmDepth(const std::string& path, int depthBits) {
  Pfm pfm = decodePfm(path);
  if (pfm.channels != 1) throw std::runtime_error("cannot read " + path + ": not a depth dump");
  ImageData image;
  image.width = pfm.width;
  image.height = pfm.height;
  image.channels = 1;
  image.format = depthBits == 16 ? TexelFormat::Depth16 : TexelFormat::Depth24;
  image.depthBits = depthBits;
  // Every value must be an integer code within the depth range.
  const double largest = std::ldexp(1.0, depthBits) - 1.0;
  image.depth.reserve(pfm.values.size());
  for (float v : pfm.values) {
    if (!(v >= 0.0f && v <= largest && v == std::floor(v)))
      throw std::runtime_error("cannot read " + path + ": value " + std::to_string(v) +
                               " is not a " + std::to_string(depthBits) + "-bit depth code");
    image.depth.push_back(uint32_t(v));
  }
  return image;
}

ImageData readPfmFloat(const std::string& path) {
  Pfm pfm = decodePfm(path);
  ImageData image;
  image.width = pfm.width;
  image.height = pfm.height;
  image.format = TexelFormat::RGBA16F;
  if (pfm.channels == 1) {
    image.channels = 1;
    image.floats = std::move(pfm.values);
    return image;
  }
  // RGB plus the alpha file if there is one (its absence means alpha 1 everywhere).
  const size_t pixels = size_t(pfm.width) * size_t(pfm.height);
  std::vector<float> alpha(pixels, 1.0f);
  if (std::filesystem::exists(alphaPfmPath(path))) {
    Pfm alphaPfm = decodePfm(alphaPfmPath(path));
    if (alphaPfm.channels != 1 || alphaPfm.width != pfm.width || alphaPfm.height != pfm.height)
      throw std::runtime_error("cannot read " + alphaPfmPath(path) + ": does not match " + path);
    alpha = std::move(alphaPfm.values);
  }
  image.channels = 4;
  image.floats.reserve(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    image.floats.insert(image.floats.end(), &pfm.values[i * 3], &pfm.values[i * 3] + 3);
    image.floats.push_back(alpha[i]);
  }
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
