// Image comparison metrics (see metrics.h for the units of each kind).
#include "compare/metrics.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "compare/flip.h"

namespace compare {
namespace {

using scenes::ImageData;
using scenes::TexelFormat;

enum class Kind { Rgba8, Depth, Half, Float };

Kind kindOf(const ImageData& image) {
  const size_t pixels = size_t(image.width) * size_t(image.height);
  switch (image.format) {
    case TexelFormat::RGBA8:
      if (image.rgba8.size() == pixels * 4) return Kind::Rgba8;
      break;
    case TexelFormat::Depth16:
    case TexelFormat::Depth24:
      if (image.depth.size() == pixels && image.depthBits > 0 && image.depthBits <= 32)
        return Kind::Depth;
      break;
    case TexelFormat::RGBA16F:
    case TexelFormat::RGB16F:
    case TexelFormat::RGBA32F:
      if (image.channels > 0 && image.floats.size() == pixels * size_t(image.channels))
        return image.format == TexelFormat::RGBA32F ? Kind::Float : Kind::Half;
      break;
  }
  throw std::invalid_argument("image payload does not match its format and size");
}

int channelsOf(Kind kind, const ImageData& image) {
  return kind == Kind::Rgba8 ? 4 : kind == Kind::Depth ? 1 : image.channels;
}

// One channel sample of both images: the difference in the kind's unit, the signed
// difference in value (for RMSE), and whether the stored bits are the same.
struct SampleDiff {
  uint64_t units;
  double value;
  bool sameBits;
};

SampleDiff sampleDiff(Kind kind, const ImageData& a, const ImageData& b, size_t i) {
  switch (kind) {
    case Kind::Rgba8: {
      const int d = int(a.rgba8[i]) - int(b.rgba8[i]);
      return {uint64_t(std::abs(d)), double(d), d == 0};
    }
    case Kind::Depth: {
      const double d = double(a.depth[i]) - double(b.depth[i]);
      return {uint64_t(std::fabs(d)), d, d == 0};
    }
    case Kind::Half: {
      const uint16_t ha = halfBits(a.floats[i]), hb = halfBits(b.floats[i]);
      return {halfUlpDistance(ha, hb), double(a.floats[i]) - double(b.floats[i]), ha == hb};
    }
    case Kind::Float: {
      const uint32_t fa = floatBits(a.floats[i]), fb = floatBits(b.floats[i]);
      return {floatUlpDistance(fa, fb), double(a.floats[i]) - double(b.floats[i]), fa == fb};
    }
  }
  return {0, 0, true};
}

double peakOf(Kind kind, const ImageData& image) {
  if (kind == Kind::Rgba8) return 255.0;
  if (kind == Kind::Depth) return std::ldexp(1.0, image.depthBits) - 1.0;
  return 1.0;
}

// Signed integer order of half bit patterns: negatives mirrored below zero, -0 == +0.
int32_t halfOrder(uint16_t bits) {
  const int32_t magnitude = bits & 0x7fff;
  return (bits & 0x8000) ? -magnitude : magnitude;
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%8.3f%%", share * 100.0);
  return text;
}

}  // namespace

std::string imageKind(const ImageData& image) {
  switch (kindOf(image)) {
    case Kind::Rgba8: return "rgba8";
    case Kind::Depth: return "depth";
    case Kind::Half: return "half";
    case Kind::Float: return "float";
  }
  return "";
}

uint32_t floatBits(float value) {
  const uint32_t bits = std::bit_cast<uint32_t>(value);
  return (bits & 0x7fffffff) > 0x7f800000 ? (bits & 0x80000000) | 0x7fc00000 : bits;   // one NaN
}

uint64_t floatUlpDistance(uint32_t a, uint32_t b) {
  // Signed order of the patterns: negatives mirrored below zero, -0 == +0.
  auto order = [](uint32_t bits) { return (bits & 0x80000000) ? -int64_t(bits & 0x7fffffff) : int64_t(bits); };
  return uint64_t(std::abs(order(a) - order(b)));
}

uint16_t halfBits(float value) {
  const uint32_t bits = std::bit_cast<uint32_t>(value);
  const uint16_t sign = uint16_t((bits >> 16) & 0x8000);
  const uint32_t magnitude = bits & 0x7fffffff;
  if (magnitude > 0x7f800000) return sign | 0x7e00;      // NaN stays a (quiet) NaN
  if (magnitude >= 0x477ff000) return sign | 0x7c00;     // >= 65520 rounds to infinity
  if (magnitude < 0x38800000) {                          // below 2^-14: half subnormal
    // Scaling by 2^24 is exact; nearbyint rounds to nearest even in the default mode.
    const float scaled = std::bit_cast<float>(magnitude) * 16777216.0f;
    return sign | uint16_t(std::nearbyint(scaled));
  }
  // Normal: rebias the exponent (127 -> 15), round 23 mantissa bits to 10, ties to even.
  const uint32_t rebased = magnitude - ((127u - 15u) << 23);
  return sign | uint16_t((rebased + 0xfff + ((rebased >> 13) & 1)) >> 13);
}

uint64_t halfUlpDistance(uint16_t a, uint16_t b) {
  return uint64_t(std::abs(int64_t(halfOrder(a)) - int64_t(halfOrder(b))));
}

uint64_t pixelDifference(const ImageData& a, const ImageData& b, size_t pixel) {
  const Kind kind = kindOf(a);
  const int channels = channelsOf(kind, a);
  uint64_t largest = 0;
  for (int c = 0; c < channels; ++c)
    largest = std::max(largest, sampleDiff(kind, a, b, pixel * channels + c).units);
  return largest;
}

void checkComparable(const std::string& name, const ImageData& a, const ImageData& b) {
  const Kind kind = kindOf(a);
  if (kindOf(b) != kind || a.format != b.format)
    throw std::invalid_argument(name + ": the two images are of different kinds");
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument(name + ": the two images differ in size");
  if (((kind == Kind::Half || kind == Kind::Float) && a.channels != b.channels) ||
      (kind == Kind::Depth && a.depthBits != b.depthBits))
    throw std::invalid_argument(name + ": the two images differ in layout");
}

TargetStats compareImages(const std::string& name, const ImageData& a, const ImageData& b) {
  checkComparable(name, a, b);
  const Kind kind = kindOf(a);

  TargetStats stats;
  stats.name = name;
  stats.kind = imageKind(a);
  stats.width = a.width;
  stats.height = a.height;

  // Walk every pixel once: per-pixel maxima for the shares, per-sample sums for RMSE.
  const size_t pixels = size_t(a.width) * size_t(a.height);
  const int channels = channelsOf(kind, a);
  uint64_t differing = 0, over1 = 0, over4 = 0, identical = 0, maxUnits = 0, nonFinite = 0, finiteSamples = 0;
  double sumSquares = 0, maxValue = 0;
  for (size_t p = 0; p < pixels; ++p) {
    uint64_t pixelUnits = 0;
    bool sameBits = true, finitePixel = true;
    for (int c = 0; c < channels; ++c) {
      const size_t i = p * channels + c;
      const SampleDiff d = sampleDiff(kind, a, b, i);
      pixelUnits = std::max(pixelUnits, d.units);
      sameBits = sameBits && d.sameBits;
      if ((kind == Kind::Half || kind == Kind::Float) && !(std::isfinite(a.floats[i]) && std::isfinite(b.floats[i]))) {
        finitePixel = false;   // NaN - NaN or inf - inf is no distance: kept out of RMSE
        continue;
      }
      sumSquares += d.value * d.value;
      maxValue = std::max(maxValue, std::fabs(d.value));
      ++finiteSamples;
    }
    nonFinite += !finitePixel;
    maxUnits = std::max(maxUnits, pixelUnits);
    differing += pixelUnits > 0;
    over1 += pixelUnits > 1;
    over4 += pixelUnits > 4;
    identical += sameBits;
  }

  // Turn the counts into shares and the sums into RMSE / PSNR.
  const double pixelCount = pixels ? double(pixels) : 1.0;
  const double samples = finiteSamples ? double(finiteSamples) : 1.0;
  stats.shareDiffering = double(differing) / pixelCount;
  stats.shareOver1 = double(over1) / pixelCount;
  stats.shareOver4 = double(over4) / pixelCount;
  stats.shareBitIdentical = double(identical) / pixelCount;
  stats.rmse = std::sqrt(sumSquares / samples);
  stats.psnr = stats.rmse == 0 ? std::numeric_limits<double>::infinity()
                               : 20.0 * std::log10(peakOf(kind, a) / stats.rmse);
  stats.maxAbs = kind == Kind::Half || kind == Kind::Float ? maxValue : double(maxUnits);
  if (kind == Kind::Depth) {
    stats.depthTexelsDiffering = differing;
    stats.maxDepthLsb = maxUnits;
  }
  if (kind == Kind::Half || kind == Kind::Float) stats.maxUlps = maxUnits;
  stats.nonFinitePixels = nonFinite;
  return stats;
}

void measureFlip(TargetStats& stats, const ImageData& test, const ImageData& reference) {
  stats.flipMeasured = true;
  if (stats.kind != "rgba8") {
    stats.flipMean.reset();
    return;
  }
  // Identical images have a map of zeros (every step of FLIP is a difference of the two).
  stats.flipMean = stats.shareDiffering == 0 ? 0.0 : flipMean(reference, test);
}

std::string formatStatsLine(const TargetStats& s) {
  // The largest difference, in the kind's own unit.
  char largest[48];
  if (s.kind == "depth")
    std::snprintf(largest, sizeof largest, "%llu lsb", (unsigned long long)s.maxDepthLsb);
  else if (s.isFloatKind())
    std::snprintf(largest, sizeof largest, "%llu ulp", (unsigned long long)s.maxUlps);
  else
    std::snprintf(largest, sizeof largest, "%.0f", s.maxAbs);

  char psnr[32];
  if (std::isinf(s.psnr))
    std::snprintf(psnr, sizeof psnr, "inf");
  else
    std::snprintf(psnr, sizeof psnr, "%.2f", s.psnr);

  char size[32];
  std::snprintf(size, sizeof size, "%dx%d", s.width, s.height);

  // Columns shared by every kind, then what only one kind has.
  char line[320];
  std::snprintf(line, sizeof line, "%-16s %-5s %-10s max %-12s rmse %-10.4g psnr %-7s differ%s  >1%s  >4%s",
                s.name.c_str(), s.kind.c_str(), size, largest, s.rmse, psnr,
                percent(s.shareDiffering).c_str(), percent(s.shareOver1).c_str(),
                percent(s.shareOver4).c_str());
  std::string text = line;
  if (s.kind == "depth")
    text += "  texels " + std::to_string(s.depthTexelsDiffering);
  if (s.isFloatKind()) {
    std::snprintf(line, sizeof line, "  identical%s  max|d| %.4g",
                  percent(s.shareBitIdentical).c_str(), s.maxAbs);
    text += line;
    if (s.nonFinitePixels > 0) text += "  nonfinite " + std::to_string(s.nonFinitePixels);
  }
  if (s.flipMeasured) {
    if (s.flipMean) {
      std::snprintf(line, sizeof line, "  flip %.6f", *s.flipMean);
      text += line;
    } else {
      text += "  flip -";
    }
  }
  return text;
}

}  // namespace compare
