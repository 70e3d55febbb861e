// ꟻLIP (LDR): a perceptual difference between two sRGB images, per pixel in [0, 1].
//
// Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild, "FLIP: A Difference
// Evaluator for Alternating Images", HPG 2020. PSNR counts 8-bit steps; ꟻLIP asks how
// visible the difference is to a viewer flipping between the two images at a given viewing
// distance: colour differences after the eye's contrast sensitivity has blurred both images,
// raised where edges or points differ. 0 is no visible difference, 1 the largest (pure green
// against pure blue, or a feature where the other image has none).
//
// This is a port of the reference implementation, NVlabs/flip (BSD-3-Clause), src/cpp/FLIP.h
// at commit 1eb247c, LDR path only: same constants, same filters, same float operations in
// the same order, so the error map matches the reference's (flip.cpp cites each step).
// Every pixel's value is computed from the two images alone, so the map is the same bytes
// at any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "backends/backend.h"

namespace compare {

// Pixels per degree of visual angle: the reference's default observer, 0.7 m from a 0.7 m
// wide monitor of 3840 pixels (FLIP.h, Parameters::PPD = calculatePPD(0.7, 3840, 0.7)),
// about 67.02.
float flipDefaultPpd();

// Pixels per degree for a viewer `distance` metres from a monitor `monitorWidth` metres wide
// showing `resolutionX` pixels across (FLIP.h, calculatePPD).
float flipPpd(float distance, float resolutionX, float monitorWidth);

// The ꟻLIP error of each pixel, row-major, top row first as the images are stored; each in
// [0, 1]. `reference` and `test` are RGBA8 sRGB, width * height * 4 bytes; alpha is ignored.
// `threads` (0: every core) split the rows and change no byte of the result.
// Throws std::invalid_argument when a size is not positive, a buffer is not width * height *
// 4 bytes, or ppd is not a positive finite number.
std::vector<float> flipErrorMap(const std::vector<uint8_t>& reference, const std::vector<uint8_t>& test,
                                int width, int height, float ppd = flipDefaultPpd(), int threads = 0);

// The same for two images read back from a backend: both must be RGBA8 (colour) targets of
// the same size, otherwise std::invalid_argument says which requirement failed.
std::vector<float> flipErrorMap(const scenes::ImageData& reference, const scenes::ImageData& test,
                                float ppd = flipDefaultPpd(), int threads = 0);

// The mean of an error map, summed as the reference sums it (in float, in pixel order), so it
// reads as the reference's published means do; 0 for an empty map.
double flipMean(const std::vector<float>& errorMap);

// The mean ꟻLIP error of two RGBA8 images (flipErrorMap, then flipMean).
double flipMean(const scenes::ImageData& reference, const scenes::ImageData& test,
                float ppd = flipDefaultPpd(), int threads = 0);

}  // namespace compare
