// Small images built by hand for the comparison and image-file tests: one value everywhere,
// given depth codes, given half-float texels.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "backends/backend.h"

namespace test_images {

// A width x height RGBA8 image, every byte `value`.
inline scenes::ImageData rgba8Image(int width, int height, uint8_t value) {
  scenes::ImageData image;
  image.width = width;
  image.height = height;
  image.format = scenes::TexelFormat::RGBA8;
  image.rgba8.assign(size_t(width) * size_t(height) * 4, value);
  return image;
}

// A width x height depth image of these codes, row by row: 16 or 24 bits.
inline scenes::ImageData depthImage(int width, int height, int bits, std::vector<uint32_t> codes) {
  scenes::ImageData image;
  image.width = width;
  image.height = height;
  image.channels = 1;
  image.format = bits == 16 ? scenes::TexelFormat::Depth16 : scenes::TexelFormat::Depth24;
  image.depthBits = bits;
  image.depth = std::move(codes);
  return image;
}

// A one-row RGBA16F image of these values, four to a pixel (for the float comparisons).
inline scenes::ImageData halfImage(std::vector<float> rgba) {
  scenes::ImageData image;
  image.width = int(rgba.size() / 4);
  image.height = 1;
  image.format = scenes::TexelFormat::RGBA16F;
  image.floats = std::move(rgba);
  return image;
}

}  // namespace test_images
