// Image comparison metrics: how far one backend's target is from another's.
//
// The unit of difference depends on what the target stores, so a number means the same
// thing whatever the backend:
//   rgba8: 8-bit steps of any of the four channels;
//   depth: LSBs of the integer depth code (2^bits - 1 is the far plane);
//   half:  half-float ULPs (values read back as floats are exact halves), counted on an
//          integer order of the half bit patterns in which +0 and -0 are one point;
//   float: float32 ULPs, counted the same way (half ULPs would hide one float step).
// compareImages() summarises a whole target; pixelDifference() is the per-pixel measure
// the heat map (io/image_io.h) draws.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "backends/backend.h"

namespace compare {

struct TargetStats {
  std::string name;
  std::string kind;                    // "rgba8", "depth", "half" (RGBA16F), "float" (RGBA32F)
  double maxAbs = 0;                   // rgba8: steps; depth: LSBs; half, float: value
  double rmse = 0;                     // over every channel sample, in the same unit
  double psnr = 0;                     // peak 255, 2^bits - 1 or 1.0; +inf when identical
  double shareDiffering = 0;           // of pixels: any channel differs at all
  double shareOver1 = 0;               // any channel differs by more than 1 unit
  double shareOver4 = 0;               // ... by more than 4 units
  uint64_t depthTexelsDiffering = 0;   // depth only
  uint64_t maxDepthLsb = 0;            // depth only
  double shareBitIdentical = 0;        // of pixels whose every channel has the same bits
  uint64_t maxUlps = 0;                // half and float: ULPs of the target's own float type
  // Float images: pixels with a NaN or infinite channel in either image. Their channels
  // count in the shares and ULPs (NaN = NaN, +inf = +inf), but not in RMSE, PSNR or maxAbs,
  // which are over the finite samples only, so no metric is ever NaN.
  uint64_t nonFinitePixels = 0;
  int width = 0, height = 0;
  // ꟻLIP (compare/flip.h), a perceptual error in [0, 1] beside PSNR: the mean of its map at
  // the reference's default 67 pixels per degree. compareImages() leaves it out (it costs
  // about 60 ms of CPU at 640x480, 0.43 s at 1920x1080, spread over the cores, and most
  // callers, the tests among them, want only the step counts); measureFlip() fills it. flipMeasured: it was asked for;
  // flipMean: set for rgba8 targets only (FLIP measures 8-bit sRGB colour), absent for depth
  // and float targets.
  bool flipMeasured = false;
  std::optional<double> flipMean;

  // A target of floats (RGBA16F or RGBA32F): measured in ULPs and bit identity.
  bool isFloatKind() const { return isFloatKindName(kind); }
  static bool isFloatKindName(const std::string& k) { return k == "half" || k == "float"; }
};

// "rgba8", "depth", "half" or "float"; throws std::invalid_argument for an inconsistent image.
std::string imageKind(const scenes::ImageData& image);

// Throws std::invalid_argument (naming `name`) unless a and b have the same size, kind and
// layout (channel count of float images, bits of depth images).
void checkComparable(const std::string& name, const scenes::ImageData& a,
                     const scenes::ImageData& b);

// Compares two images of the same size, kind and layout (see checkComparable).
TargetStats compareImages(const std::string& name, const scenes::ImageData& a,
                          const scenes::ImageData& b);

// Adds ꟻLIP to stats of `test` against `reference` (the images compareImages measured):
// their mean ꟻLIP error for rgba8 targets (0 without computing it when no pixel differs),
// none for the other kinds.
void measureFlip(TargetStats& stats, const scenes::ImageData& test, const scenes::ImageData& reference);

// The largest difference over the channels of one pixel, in the kind's unit (see above);
// a and b must be comparable.
uint64_t pixelDifference(const scenes::ImageData& a, const scenes::ImageData& b, size_t pixel);

// Half-float helpers: the bit pattern of a float rounded to half (to nearest even), and the
// distance in ULPs between two halves (0 between +0 and -0).
uint16_t halfBits(float value);
uint64_t halfUlpDistance(uint16_t a, uint16_t b);
// The same for float32: its bits with every NaN made one, and the ULP distance.
uint32_t floatBits(float value);
uint64_t floatUlpDistance(uint32_t a, uint32_t b);

// One aligned, human-readable line; depth lines add "texels N" (differing), half lines
// "identical P%  max|d| X" and, when there are any, "nonfinite N"; when ꟻLIP was measured,
// every line ends with "flip M" (the mean, six decimals as the reference prints it) or
// "flip -" (not a colour target). E.g.
//   final            rgba8 640x480    max 3            rmse 0.2827     psnr 59.10   differ  10.119%  >1   2.731%  >4   0.000%
std::string formatStatsLine(const TargetStats& stats);

}  // namespace compare
