// Reading and writing read-back images: PNG previews, lossless PFM dumps, difference heat maps.
//
// A target is saved twice when dumped: a PNG anyone can look at, and (for depth and float
// targets) a lossless PFM another process can load back bit for bit; RGBA8 targets are
// already lossless as PNG. Every file goes through compare/output_file.h: whole or not at
// all, never over anything but a regular file, and no temporary file left behind.
//
// PFM ("Portable Float Map"): a text header "PF" (RGB) or "Pf" (grey), "W H", a scale whose
// sign gives the byte order (negative: little endian), then 32-bit floats, BOTTOM row first.
// ImageData is top row first; the functions here flip rows on the way in and out.
#pragma once

#include <string>

#include "scenes/backend.h"

namespace compare {

// A PNG for looking at: RGBA8 as is; float images clamped to [0,1] and gamma-encoded
// (1/2.2) to 8-bit RGB; depth codes as grey, contrast-stretched between the smallest and
// largest code present (or scaled by 2^bits - 1 when every code is the same).
void writePng(const std::string& path, const scenes::ImageData& image);

// A lossless PFM dump of a depth or float image (throws std::invalid_argument for RGBA8).
// Depth: "Pf" holding the integer codes as floats (exact below 2^24). Float images: "PF"
// with R, G, B (1-channel images as "Pf"); for 4 channels, the alpha goes to
// alphaPfmPath(path) as "Pf" when any alpha differs from 1 (otherwise that file is removed).
void writePfm(const std::string& path, const scenes::ImageData& image);
// "dir/name.pfm" -> "dir/name.alpha.pfm".
std::string alphaPfmPath(const std::string& pfmPath);

// Loaders for another process's dump; each throws std::runtime_error naming the file.
scenes::ImageData readPng(const std::string& path);                   // as RGBA8
scenes::ImageData readPfmDepth(const std::string& path, int depthBits);
scenes::ImageData readPfmFloat(const std::string& path);   // "PF": 4 channels (alpha from
                                                           // the .alpha.pfm, else 1)

// A heat map of where a and b differ: per pixel the largest channel difference in the
// kind's unit (compare::pixelDifference), black 0 -> blue 1 -> yellow 4 -> red >= 16
// (interpolated on a log2 scale), so one-step differences stand out.
void writeHeatmapPng(const std::string& path, const scenes::ImageData& a,
                     const scenes::ImageData& b);

}  // namespace compare
