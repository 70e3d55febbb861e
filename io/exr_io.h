// Lossless OpenEXR dumps of depth and float targets (OpenEXR 3, Debian libopenexr-dev), and
// their loaders. Another process loads a dump back bit for bit (io/target_dump.h), and
// any OpenEXR tool (exrheader, exrdisplay, an image editor) can open it.
//
// The files, all ZIP-compressed (lossless), one part, scan lines, data window at (0,0):
//   - RGBA16F (and RGB16F) images: HALF channels R, G, B[, A]. The read-back floats of a half
//     target are exact half values, so the half bits are stored as they are (NaN payloads
//     included); a float that is not exactly a half is refused, never rounded.
//   - RGBA32F images: FLOAT channels R, G, B[, A], the bits as they are.
//     (1- to 4-channel float images use the first 1-4 of R, G, B, A.)
//   - Depth images: one FLOAT channel "Z" (OpenEXR's name for depth) holding code / (2^D - 1)
//     for a D-bit code, so that tools show depth in [0, 1] as GL defines it, and an int
//     attribute "depthBits" = D. The mapping is exact both ways for every code of D <= 24
//     bits (depthCodeToFloat says why; tests check every 16- and 24-bit code).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "backends/backend.h"

namespace compare {

// Writes a depth or float image as above, through io/output_file.h (whole or not at
// all). Throws std::invalid_argument for RGBA8 images (dumped as PNG), depth of more than
// 24 bits, and a half image holding a value that is not a half.
void writeExr(const std::string& path, const scenes::ImageData& image);

// Loaders for another process's dump. Each throws std::runtime_error "cannot read PATH:
// WHY" for a file that cannot be opened, is not OpenEXR, is truncated or corrupt, or has
// other channels (or another depth-bit count) than the dump of that kind.
scenes::ImageData readExrDepth(const std::string& path, int depthBits);   // Depth16 / Depth24
// Float images: HALF channels give RGBA16F (RGB16F for exactly R, G, B), FLOAT give RGBA32F.
scenes::ImageData readExrColor(const std::string& path);

// The depth mapping. code / (2^bits - 1), rounded once to float (bits 1..24).
float depthCodeToFloat(uint32_t code, int bits);
// Its inverse: the code whose depthCodeToFloat has exactly value's bits, or nothing.
std::optional<uint32_t> depthCodeFromFloat(float value, int bits);

}  // namespace compare
