// Reading and writing read-back images as PNG: previews, RGBA8 targets, difference heat maps.
//
// A target is saved twice when dumped (io/target_dump.h): a PNG anyone can look at, and
// (for depth and float targets) a lossless OpenEXR file another process can load back bit
// for bit (io/exr_io.h); RGBA8 targets are already lossless as PNG. Every file goes
// through io/output_file.h: whole or not at all, never over anything but a regular
// file, and no temporary file left behind.
#pragma once

#include <string>

#include "backends/backend.h"

namespace compare {

// A PNG for looking at: RGBA8 as is; float images clamped to [0,1] and gamma-encoded
// (1/2.2) to 8-bit RGB; depth codes as grey, contrast-stretched between the smallest and
// largest code present (or scaled by 2^bits - 1 when every code is the same).
void writePng(const std::string& path, const scenes::ImageData& image);

// Loads a PNG as RGBA8; throws std::runtime_error naming the file.
scenes::ImageData readPng(const std::string& path);

// A heat map of where a and b differ: per pixel the largest channel difference in the
// kind's unit (compare::pixelDifference), black 0 -> blue 1 -> yellow 4 -> red >= 16
// (interpolated on a log2 scale), so one-step differences stand out.
void writeHeatmapPng(const std::string& path, const scenes::ImageData& a,
                     const scenes::ImageData& b);

}  // namespace compare
