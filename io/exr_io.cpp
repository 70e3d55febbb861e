// OpenEXR dumps and their loaders (see exr_io.h for the files and their guarantees).
#include "io/exr_io.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <memory>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfVersion.h>
#include <Iex.h>

#include "io/memory_budget.h"
#include "io/output_file.h"
#include "raster/texture/format.h"

namespace compare {
namespace {

using scenes::ImageData;
using scenes::TexelFormat;

constexpr const char* kDepthBitsAttribute = "depthBits";
constexpr const char* kColorNames[] = {"R", "G", "B", "A"};
// Far above any target, and small enough that width * height * 4 channels * 4 bytes cannot
// overflow; a larger header is refused before anything is allocated.
constexpr int kMaxSide = 1 << 16;

// ---- OpenEXR streams over memory: the writer encodes into a string that output_file.h
// writes whole; the reader decodes a file read whole (so "truncated" is one clear check).

class MemoryOStream : public Imf::OStream {
 public:
  explicit MemoryOStream(const std::string& name) : Imf::OStream(name.c_str()) {}
  void write(const char c[], int n) override {
    // OutputFile seeks back to fill in the table of scan-line offsets: overwrite, then append.
    const size_t end = position_ + size_t(n);
    if (end > bytes_.size()) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, size_t(n));
    position_ = end;
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = size_t(pos); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  size_t position_ = 0;
};

class MemoryIStream : public Imf::IStream {
 public:
  MemoryIStream(const std::string& name, const std::string& bytes) : Imf::IStream(name.c_str()), bytes_(bytes) {}
  // As Imf::StdIFStream: true while bytes are left, an exception at a read past the end.
  bool read(char c[], int n) override {
    if (n < 0 || position_ > bytes_.size() || bytes_.size() - position_ < size_t(n))
      throw Iex::InputExc("unexpected end of file");
    std::memcpy(c, bytes_.data() + position_, size_t(n));
    position_ += size_t(n);
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t pos) override { position_ = size_t(std::min<uint64_t>(pos, bytes_.size() + 1)); }

 private:
  const std::string& bytes_;
  size_t position_ = 0;
};

std::runtime_error readError(const std::string& path, const std::string& why) {
  return std::runtime_error("cannot read " + path + ": " + why);
}

std::string readWhole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw readError(path, std::strerror(errno));
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw readError(path, std::strerror(errno));
  return bytes;
}

// The header and pixels of a file, read into the caller's frame buffer: decode() checks the
// magic number, header and size first (before the caller allocates), then readPixels.
class ExrReader {
 public:
  explicit ExrReader(const std::string& path) : path_(path), bytes_(readWhole(path)) {
    if (bytes_.size() < 4 || !Imf::isImfMagic(bytes_.data())) throw readError(path_, "not an OpenEXR file");
    guarded([&] {
      stream_ = std::make_unique<MemoryIStream>(path_, bytes_);
      file_ = std::make_unique<Imf::InputFile>(*stream_);
    });
    const Imath::Box2i window = file_->header().dataWindow();
    const int64_t width = int64_t(window.max.x) - window.min.x + 1;
    const int64_t height = int64_t(window.max.y) - window.min.y + 1;
    if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
      throw readError(path_, "bad data window (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    width_ = int(width);
    height_ = int(height);
  }

  const Imf::Header& header() const { return file_->header(); }
  int width() const { return width_; }
  int height() const { return height_; }
  size_t pixels() const { return size_t(width_) * size_t(height_); }

  int channelCount() const {
    int count = 0;
    for (auto c = header().channels().begin(); c != header().channels().end(); ++c) ++count;
    return count;
  }

  // The channel names in the file's (alphabetical) order, for messages.
  std::string channelNames() const {
    std::string names;
    for (auto c = header().channels().begin(); c != header().channels().end(); ++c)
      names += std::string(names.empty() ? "" : ", ") + c.name();
    return names.empty() ? "none" : names;
  }

  // Reads channel `name` (of `type`, full resolution) into `base`, `stride` bytes a pixel.
  void addSlice(Imf::FrameBuffer& frame, const char* name, Imf::PixelType type, char* base, size_t stride) const {
    const Imf::Channel* channel = header().channels().findChannel(name);
    if (!channel || channel->type != type || channel->xSampling != 1 || channel->ySampling != 1)
      throw readError(path_, std::string("no full-resolution ") + (type == Imf::HALF ? "HALF" : "FLOAT") +
                                 " channel " + name + " (channels: " + channelNames() + ")");
    frame.insert(name, Imf::Slice::Make(type, base, header().dataWindow(), stride, stride * size_t(width_)));
  }

  void readPixels(const Imf::FrameBuffer& frame) {
    guarded([&] {
      file_->setFrameBuffer(frame);
      const Imath::Box2i window = header().dataWindow();
      file_->readPixels(window.min.y, window.max.y);
    });
  }

 private:
  // OpenEXR reports a bad file with Iex exceptions (and std ones for bad allocations).
  template <class F>
  void guarded(F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      throw readError(path_, std::string("truncated or corrupt OpenEXR file (") + e.what() + ")");
    }
  }

  std::string path_;
  std::string bytes_;
  std::unique_ptr<MemoryIStream> stream_;
  std::unique_ptr<Imf::InputFile> file_;
  int width_ = 0, height_ = 0;
};

// The half whose exact float value has f's bits, if there is one: NaN payloads are kept
// (the low 13 bits of a float NaN from a half are zero), never quieted or rounded.
std::optional<uint16_t> exactHalf(float f) {
  const uint32_t bits = std::bit_cast<uint32_t>(f);
  const uint32_t magnitude = bits & 0x7fffffffu;
  const uint16_t candidate =
      magnitude > 0x7f800000u ? uint16_t(((bits >> 16) & 0x8000u) | 0x7c00u | ((magnitude >> 13) & 0x3ffu))
                              : raster::format::halfFromFloatTowardZero(f);
  if (std::bit_cast<uint32_t>(raster::format::floatFromHalf(candidate)) != bits) return std::nullopt;
  return candidate;
}

void writeExrBytes(const std::string& path, const Imf::Header& header, const Imf::FrameBuffer& frame, int height) {
  MemoryOStream stream(path);
  try {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
  } catch (const std::exception& e) {   // (leaving the block, ~OutputFile writes the offset table)
    throw std::runtime_error("cannot encode " + path + " as OpenEXR: " + e.what());
  }
  writeOutputFile(path, stream.bytes());
}

Imf::Header headerFor(const ImageData& image) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;   // lossless, and the same bytes on every run
  return header;
}

}  // namespace

// Why this is exact for D <= 24: let N = 2^D - 1 and x = code / N in [0, 1]. The double
// quotient is within 2^-54 of x, and rounding it to float moves it at most half a float ulp
// (2^-25 in [0.5, 1), less below), so |v - x| <= 2^-25 + 2^-54 and |v * N - code| <=
// N * (2^-25 + 2^-54) < 0.5. v * N is exact in double (24 bits times 24 bits), so rounding
// it to the nearest integer gives the code back. depthCodeFromFloat also re-encodes, so it
// accepts only the one float each code maps to.
float depthCodeToFloat(uint32_t code, int bits) {
  return float(double(code) / (std::ldexp(1.0, bits) - 1.0));
}

std::optional<uint32_t> depthCodeFromFloat(float value, int bits) {
  const double largest = std::ldexp(1.0, bits) - 1.0;
  if (!(value >= 0.0f && value <= 1.0f)) return std::nullopt;   // NaN too
  const double code = std::nearbyint(double(value) * largest);
  if (code < 0.0 || code > largest) return std::nullopt;
  if (std::bit_cast<uint32_t>(depthCodeToFloat(uint32_t(code), bits)) != std::bit_cast<uint32_t>(value))
    return std::nullopt;
  return uint32_t(code);
}

void writeExr(const std::string& path, const ImageData& image) {
  const std::string where = path + ": ";
  const size_t pixels = size_t(image.width) * size_t(image.height);
  if (image.format == TexelFormat::RGBA8) throw std::invalid_argument(where + "RGBA8 images are dumped as PNG, not OpenEXR");
  if (image.width < 1 || image.height < 1 || image.width > kMaxSide || image.height > kMaxSide)
    throw std::invalid_argument(where + "an image of " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " cannot be dumped");
  Imf::Header header = headerFor(image);
  Imf::FrameBuffer frame;

  if (image.format == TexelFormat::Depth16 || image.format == TexelFormat::Depth24) {
    if (image.depthBits < 1 || image.depthBits > 24 || image.depth.size() != pixels)
      throw std::invalid_argument(where + "a depth image of " + std::to_string(image.depthBits) +
                                  " bits and the wrong size cannot be dumped");
    std::vector<float> values(pixels);
    for (size_t i = 0; i < pixels; ++i) {
      if (image.depth[i] > (uint32_t(1) << image.depthBits) - 1)
        throw std::invalid_argument(where + "depth code " + std::to_string(image.depth[i]) + " does not fit " +
                                    std::to_string(image.depthBits) + " bits");
      values[i] = depthCodeToFloat(image.depth[i], image.depthBits);
    }
    header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
    header.insert(kDepthBitsAttribute, Imf::IntAttribute(image.depthBits));
    frame.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                 sizeof(float) * size_t(image.width)));
    writeExrBytes(path, header, frame, image.height);
    return;
  }

  const int channels = image.channels;
  if (channels < 1 || channels > 4 || image.floats.size() != pixels * size_t(channels))
    throw std::invalid_argument(where + "float images of 1 to 4 channels, of the image's size, are dumped");
  if (image.format == TexelFormat::RGBA32F) {
    for (int c = 0; c < channels; ++c) {
      header.channels().insert(kColorNames[c], Imf::Channel(Imf::FLOAT));
      auto* base = const_cast<char*>(reinterpret_cast<const char*>(image.floats.data() + c));
      frame.insert(kColorNames[c], Imf::Slice(Imf::FLOAT, base, sizeof(float) * size_t(channels),
                                              sizeof(float) * size_t(channels) * size_t(image.width)));
    }
    writeExrBytes(path, header, frame, image.height);
    return;
  }
  // Half: the exact half bits of every value.
  std::vector<uint16_t> halves(image.floats.size());
  for (size_t i = 0; i < halves.size(); ++i) {
    const std::optional<uint16_t> half = exactHalf(image.floats[i]);
    if (!half) {
      const size_t pixel = i / size_t(channels);
      throw std::invalid_argument(where + "value " + std::to_string(image.floats[i]) + " at pixel (" +
                                  std::to_string(pixel % size_t(image.width)) + ", " +
                                  std::to_string(pixel / size_t(image.width)) + ") of a half image is not a half");
    }
    halves[i] = *half;
  }
  for (int c = 0; c < channels; ++c) {
    header.channels().insert(kColorNames[c], Imf::Channel(Imf::HALF));
    frame.insert(kColorNames[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves.data() + c),
                                            sizeof(uint16_t) * size_t(channels),
                                            sizeof(uint16_t) * size_t(channels) * size_t(image.width)));
  }
  writeExrBytes(path, header, frame, image.height);
}

ImageData readExrDepth(const std::string& path, int depthBits) {
  if (depthBits != 16 && depthBits != 24) throw std::invalid_argument(path + ": depth dumps hold 16 or 24 bits");
  ExrReader file(path);
  if (file.channelCount() != 1)
    throw readError(path, "a depth dump has one channel Z, not " + file.channelNames());
  const auto* bits = file.header().findTypedAttribute<Imf::IntAttribute>(kDepthBitsAttribute);
  if (!bits) throw readError(path, "no int attribute depthBits (not a depth dump)");
  if (bits->value() != depthBits)
    throw readError(path, "holds " + std::to_string(bits->value()) + "-bit depth codes, not " +
                              std::to_string(depthBits) + "-bit ones");

  ImageData image;
  image.width = file.width();
  image.height = file.height();
  image.channels = 1;
  image.format = depthBits == 16 ? TexelFormat::Depth16 : TexelFormat::Depth24;
  image.depthBits = depthBits;
  // The floats and the codes, reserved before either is allocated.
  const scenes::memory::Reservation decoding(file.pixels() * 4, "reading " + path);
  image.reserved = scenes::memory::Reservation(file.pixels() * 4, "reading " + path);
  std::vector<float> values(file.pixels());
  Imf::FrameBuffer frame;
  file.addSlice(frame, "Z", Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float));
  file.readPixels(frame);

  image.depth.resize(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    const std::optional<uint32_t> code = depthCodeFromFloat(values[i], depthBits);
    if (!code) {
      char text[32];
      std::snprintf(text, sizeof text, "%.9g", double(values[i]));
      throw readError(path, std::string("Z value ") + text + " at pixel (" + std::to_string(i % size_t(image.width)) +
                                ", " + std::to_string(i / size_t(image.width)) + ") is not a " +
                                std::to_string(depthBits) + "-bit depth code");
    }
    image.depth[i] = *code;
  }
  return image;
}

ImageData readExrColor(const std::string& path) {
  ExrReader file(path);
  // The channels must be R, or R G, or R G B, or R G B A, all HALF or all FLOAT.
  const Imf::ChannelList& list = file.header().channels();
  const int count = file.channelCount();
  const Imf::Channel* red = list.findChannel("R");
  bool prefix = count >= 1 && count <= 4 && red;
  for (int c = 0; prefix && c < count; ++c) {
    const Imf::Channel* channel = list.findChannel(kColorNames[c]);
    prefix = channel && channel->type == red->type;
  }
  if (!prefix || (red->type != Imf::HALF && red->type != Imf::FLOAT))
    throw readError(path, "a float dump has HALF or FLOAT channels R[, G[, B[, A]]], not " + file.channelNames());
  const int channels = count;
  const bool half = red->type == Imf::HALF;

  ImageData image;
  image.width = file.width();
  image.height = file.height();
  image.channels = channels;
  image.format = half ? (channels == 3 ? TexelFormat::RGB16F : TexelFormat::RGBA16F) : TexelFormat::RGBA32F;
  const size_t values = file.pixels() * size_t(channels);
  image.reserved = scenes::memory::Reservation(values * 4, "reading " + path);
  Imf::FrameBuffer frame;
  if (!half) {
    image.floats.resize(values);
    for (int c = 0; c < channels; ++c)
      file.addSlice(frame, kColorNames[c], Imf::FLOAT, reinterpret_cast<char*>(image.floats.data() + c),
                    sizeof(float) * size_t(channels));
    file.readPixels(frame);
    return image;
  }
  // Half bits, widened exactly (raster's conversion, the one read-back uses).
  const scenes::memory::Reservation decoding(values * 2, "reading " + path);
  std::vector<uint16_t> halves(values);
  for (int c = 0; c < channels; ++c)
    file.addSlice(frame, kColorNames[c], Imf::HALF, reinterpret_cast<char*>(halves.data() + c),
                  sizeof(uint16_t) * size_t(channels));
  file.readPixels(frame);
  image.floats.resize(values);
  std::transform(halves.begin(), halves.end(), image.floats.begin(), raster::format::floatFromHalf);
  return image;
}

}  // namespace compare
