// The lossless dumps: OpenEXR files of depth and float images (io/exr_io.h) and the
// folder of a frame's targets (io/target_dump.h). What is written must load back with
// the same bits, every depth code and every half included; a file that is not such a dump
// must be refused with an error naming it, never read as something else.
#include <doctest/doctest.h>

#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>

#include "backends/backends.h"
#include "io/exr_io.h"
#include "io/image_io.h"
#include "io/target_dump.h"
#include "raster/texture/format.h"
#include "tests/compare/test_images.h"
#include "tests/scene_test_helpers.h"
#include "tests/temp_folder.h"

namespace {

namespace fs = std::filesystem;
using scenes::ImageData;
using scenes::Target;
using scenes::TexelFormat;
using test_images::depthImage;

using testing_support::readBytes;
using testing_support::writeBytes;

struct ImageTempFolder : testing_support::TempFolder {
  ImageTempFolder() : testing_support::TempFolder("raster-image-io-test") {}
};

// Whether two images are the same, field by field and payload byte by payload byte.
bool sameImage(const ImageData& a, const ImageData& b) {
  const auto sameBytes = [](const auto& x, const auto& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof x[0]) == 0);
  };
  return a.width == b.width && a.height == b.height && a.channels == b.channels && a.format == b.format &&
         a.depthBits == b.depthBits && sameBytes(a.rgba8, b.rgba8) && sameBytes(a.floats, b.floats) &&
         sameBytes(a.depth, b.depth);
}

ImageData floatImage(int width, int height, TexelFormat format, std::vector<float> values) {
  ImageData image;
  image.width = width;
  image.height = height;
  image.channels = int(values.size() / (size_t(width) * size_t(height)));
  image.format = format;
  image.floats = std::move(values);
  return image;
}

// Writes an EXR with the given channels (all `type`, values 0) and optional depthBits, for
// files this project would never write.
void writeForeignExr(const std::string& path, const std::vector<std::string>& names, Imf::PixelType type,
                     int depthBits = 0, float value = 0.0f, int xSampling = 1) {
  const int width = 4, height = 2;
  Imf::Header header(width, height);
  std::vector<uint32_t> storage(size_t(width) * height * names.size());
  if (type == Imf::FLOAT) std::fill(storage.begin(), storage.end(), std::bit_cast<uint32_t>(value));
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < names.size(); ++c) {
    header.channels().insert(names[c], Imf::Channel(type, xSampling, 1));
    frame.insert(names[c], Imf::Slice(type, reinterpret_cast<char*>(storage.data() + c), 4 * names.size(),
                                      4 * names.size() * width, xSampling, 1));
  }
  if (depthBits) header.insert("depthBits", Imf::IntAttribute(depthBits));
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(height);
}

}  // namespace

TEST_SUITE("image_io") {
  TEST_CASE("every 16-bit and every 24-bit depth code maps to one float and back") {
    for (int bits : {16, 24}) {
      const uint32_t largest = (uint32_t(1) << bits) - 1;
      float previous = -1.0f;
      for (uint32_t code = 0; code <= largest; ++code) {
        const float value = compare::depthCodeToFloat(code, bits);
        // Increasing, so no two codes share a float; and each float gives its code back.
        if (!(value > previous) || compare::depthCodeFromFloat(value, bits) != code)
          FAIL(bits << "-bit code " << code << " -> " << value);
        previous = value;
      }
      CHECK(compare::depthCodeToFloat(0, bits) == 0.0f);
      CHECK(compare::depthCodeToFloat(largest, bits) == 1.0f);
    }
    // Floats that are no code's float are refused.
    CHECK_FALSE(compare::depthCodeFromFloat(std::nextafter(compare::depthCodeToFloat(1000, 16), 1.0f), 16));
    CHECK_FALSE(compare::depthCodeFromFloat(0.5f, 16));   // 32767.5: between two codes
    CHECK_FALSE(compare::depthCodeFromFloat(-0.0f, 24));
    CHECK_FALSE(compare::depthCodeFromFloat(std::nextafter(1.0f, 2.0f), 24));
    CHECK_FALSE(compare::depthCodeFromFloat(std::numeric_limits<float>::quiet_NaN(), 24));
    CHECK_FALSE(compare::depthCodeFromFloat(-1e-30f, 24));
  }

  TEST_CASE("depth dumps: every 16-bit and every 24-bit code, through a file") {
    ImageTempFolder temp;
    std::vector<uint32_t> codes(1 << 16);
    for (uint32_t i = 0; i < codes.size(); ++i) codes[i] = i;
    const ImageData depth16 = depthImage(256, 256, 16, codes);
    compare::writeExr(temp.file("d16.exr"), depth16);
    CHECK(sameImage(compare::readExrDepth(temp.file("d16.exr"), 16), depth16));

    // Every 24-bit code, in a 4096x4096 image.
    codes.resize(1 << 24);
    for (uint32_t i = 0; i < codes.size(); ++i) codes[i] = i;
    const ImageData depth24 = depthImage(4096, 4096, 24, std::move(codes));
    compare::writeExr(temp.file("d24.exr"), depth24);
    CHECK(sameImage(compare::readExrDepth(temp.file("d24.exr"), 24), depth24));
  }

  TEST_CASE("half dumps keep every half bit pattern, NaN payloads included") {
    ImageTempFolder temp;
    std::vector<float> values(1 << 16);
    for (uint32_t bits = 0; bits < values.size(); ++bits) values[bits] = raster::format::floatFromHalf(uint16_t(bits));
    const ImageData half = floatImage(128, 128, TexelFormat::RGBA16F, values);   // 4 channels
    compare::writeExr(temp.file("half.exr"), half);
    CHECK(sameImage(compare::readExrColor(temp.file("half.exr")), half));

    // Three channels read back as RGB16F.
    values.resize(3 * 5);
    const ImageData rgb = floatImage(5, 1, TexelFormat::RGB16F, values);
    compare::writeExr(temp.file("rgb.exr"), rgb);
    CHECK(sameImage(compare::readExrColor(temp.file("rgb.exr")), rgb));
  }

  TEST_CASE("images that cannot be dumped exactly are refused, and nothing is written") {
    ImageTempFolder temp;
    const ImageData half = floatImage(2, 1, TexelFormat::RGBA16F, {0, 0, 0, 1, 0.1f, 0, 0, 1});
    CHECK_THROWS_WITH_AS(compare::writeExr(temp.file("h.exr"), half),
                         doctest::Contains("h.exr: value 0.100000 at pixel (1, 0) of a half image is not a half"),
                         std::invalid_argument);
    CHECK(fs::is_empty(temp.path));
    CHECK_THROWS_AS(compare::writeExr(temp.file("x.exr"), depthImage(1, 1, 16, {70000})), std::invalid_argument);
    CHECK_THROWS_AS(compare::writeExr(temp.file("x.exr"), depthImage(0, 0, 16, {})), std::invalid_argument);
    CHECK_THROWS_AS(compare::writeExr(temp.file("x.exr"), floatImage(1, 1, TexelFormat::RGBA8, {0})), std::invalid_argument);
    CHECK(fs::is_empty(temp.path));
  }

  TEST_CASE("RGBA32F dumps keep every float's bits") {
    ImageTempFolder temp;
    std::mt19937 random(7);
    std::vector<float> values(64 * 32 * 4);
    for (float& v : values) v = std::bit_cast<float>(uint32_t(random()));
    // And the special ones: signed zeros, subnormals, infinities, a signalling NaN.
    const uint32_t specials[] = {0x00000000, 0x80000000, 0x00000001, 0x807fffff, 0x7f800000,
                                 0xff800000, 0x7f800001, 0x7fc00000, 0xffffffff, 0x7f7fffff};
    for (size_t i = 0; i < std::size(specials); ++i) values[i] = std::bit_cast<float>(specials[i]);
    const ImageData image = floatImage(64, 32, TexelFormat::RGBA32F, values);
    compare::writeExr(temp.file("f.exr"), image);
    CHECK(sameImage(compare::readExrColor(temp.file("f.exr")), image));
  }

  TEST_CASE("files that are not such dumps are refused, naming the file and the problem") {
    ImageTempFolder temp;
    const ImageData depth = depthImage(3, 2, 24, {0, 1, 16777215, 12345678, 42, 8388608});
    const std::string good = temp.file("good.exr");
    compare::writeExr(good, depth);
    const std::string bytes = readBytes(good);
    const auto refused = [&](const std::string& path, const std::string& why, bool asDepth = true) {
      INFO(path << ": " << why);
      const std::string expected = "cannot read " + path + ": " + why;
      if (asDepth) CHECK_THROWS_WITH_AS(compare::readExrDepth(path, 24), doctest::Contains(expected.c_str()), std::runtime_error);
      else CHECK_THROWS_WITH_AS(compare::readExrColor(path), doctest::Contains(expected.c_str()), std::runtime_error);
    };

    refused(temp.file("missing.exr"), "No such file or directory");
    writeBytes(temp.file("empty.exr"), "");
    refused(temp.file("empty.exr"), "not an OpenEXR file");
    writeBytes(temp.file("text.exr"), "PF\n1 1\n-1.0\n\0\0\0\0");
    refused(temp.file("text.exr"), "not an OpenEXR file");
    compare::writePng(temp.file("image.png"), depth);
    refused(temp.file("image.png"), "not an OpenEXR file", false);

    // Cut short anywhere: the header, the offset table, the compressed rows.
    for (size_t length = 4; length < bytes.size(); ++length) {
      writeBytes(temp.file("cut.exr"), bytes.substr(0, length));
      refused(temp.file("cut.exr"), "truncated or corrupt OpenEXR file");
    }

    // The wrong channels, types, sampling, attribute or values.
    refused(good, "a float dump has HALF or FLOAT channels R[, G[, B[, A]]], not Z", false);
    CHECK_THROWS_WITH_AS(compare::readExrDepth(good, 16), doctest::Contains("holds 24-bit depth codes, not 16-bit ones"),
                         std::runtime_error);
    compare::writeExr(temp.file("half.exr"), floatImage(1, 1, TexelFormat::RGBA16F, {1, 2, 3, 4}));
    refused(temp.file("half.exr"), "a depth dump has one channel Z, not A, B, G, R");
    writeForeignExr(temp.file("uint.exr"), {"Z"}, Imf::UINT, 24);
    refused(temp.file("uint.exr"), "no full-resolution FLOAT channel Z (channels: Z)");
    writeForeignExr(temp.file("nobits.exr"), {"Z"}, Imf::FLOAT);
    refused(temp.file("nobits.exr"), "no int attribute depthBits");
    writeForeignExr(temp.file("sub.exr"), {"Z"}, Imf::FLOAT, 24, 0.0f, 2);
    refused(temp.file("sub.exr"), "no full-resolution FLOAT channel Z");
    writeForeignExr(temp.file("far.exr"), {"Z"}, Imf::FLOAT, 24, 1.5f);
    refused(temp.file("far.exr"), "Z value 1.5 at pixel (0, 0) is not a 24-bit depth code");
    writeForeignExr(temp.file("between.exr"), {"Z"}, Imf::FLOAT, 16, 0.5f);
    CHECK_THROWS_WITH_AS(compare::readExrDepth(temp.file("between.exr"), 16),
                         doctest::Contains("Z value 0.5 at pixel (0, 0) is not a 16-bit depth code"), std::runtime_error);
    writeForeignExr(temp.file("gb.exr"), {"G", "B"}, Imf::FLOAT);
    refused(temp.file("gb.exr"), "a float dump has HALF or FLOAT channels R[, G[, B[, A]]], not B, G", false);
    writeForeignExr(temp.file("rgbz.exr"), {"R", "G", "B", "Z"}, Imf::FLOAT);
    refused(temp.file("rgbz.exr"), "a float dump has HALF or FLOAT channels R[, G[, B[, A]]], not B, G, R, Z", false);
    writeForeignExr(temp.file("uintrgb.exr"), {"R", "G", "B"}, Imf::UINT);
    refused(temp.file("uintrgb.exr"), "a float dump has HALF or FLOAT channels R[, G[, B[, A]]], not B, G, R", false);
  }

  TEST_CASE("a rendered frame's dump loads back bit for bit: depth, half and float targets") {
    // hdr: RGBA16F targets and a depth buffer; deferred: Z16, RGBA16F G-buffer, and more.
    auto backend = scenes::makeRasterBackend(0);
    std::vector<Target> targets = testing_support::renderScene(*backend, "hdr", 0.7f, 96, 64);
    for (Target& t : testing_support::renderScene(*backend, "deferred", 0.7f, 96, 64))
      targets.push_back({"deferred_" + t.name, std::move(t.image)});
    // No scene renders to RGBA32F: one made up, with bits of every kind.
    std::vector<float> values(7 * 3 * 4);
    for (size_t i = 0; i < values.size(); ++i) values[i] = std::bit_cast<float>(uint32_t(0x9e3779b9u * (i + 1)));
    targets.push_back({"float32", floatImage(7, 3, TexelFormat::RGBA32F, values)});

    std::set<std::string> kinds;
    for (const Target& t : targets)
      kinds.insert(t.image.format == TexelFormat::Depth16 ? "depth16" : t.image.format == TexelFormat::Depth24 ? "depth24"
                   : t.image.format == TexelFormat::RGBA16F ? "half" : t.image.format == TexelFormat::RGBA32F ? "float" : "rgba8");
    CHECK(kinds == std::set<std::string>{"depth16", "depth24", "half", "float", "rgba8"});

    ImageTempFolder temp;
    const std::string folder = temp.file("dump");
    std::vector<std::string> written;
    compare::writeTargetDump(folder, targets, [&](const std::string& path) { written.push_back(path); });
    std::vector<std::string> expected;
    for (const Target& t : targets) {
      expected.push_back(folder + "/" + t.name + ".png");
      if (t.image.format != TexelFormat::RGBA8) expected.push_back(folder + "/" + t.name + ".exr");
    }
    expected.push_back(folder + "/targets.txt");
    CHECK(written == expected);
    const std::vector<Target> loaded = compare::loadTargetDump(folder);
    REQUIRE(loaded.size() == targets.size());
    for (size_t i = 0; i < targets.size(); ++i) {
      INFO(targets[i].name);
      CHECK(loaded[i].name == targets[i].name);
      CHECK(sameImage(loaded[i].image, targets[i].image));
      const bool exr = targets[i].image.format != TexelFormat::RGBA8;
      CHECK(fs::exists(folder + "/" + targets[i].name + ".png"));
      CHECK(fs::exists(folder + "/" + targets[i].name + ".exr") == exr);
    }

    // A manifest that disagrees with a file is refused, naming both.
    std::string manifest = readBytes(folder + "/targets.txt");
    const size_t at = manifest.find("float32 float");
    REQUIRE(at != std::string::npos);
    writeBytes(folder + "/targets.txt", manifest.replace(at, 13, "float32 half"));
    CHECK_THROWS_WITH_AS(compare::loadTargetDump(folder),
                         doctest::Contains(("float32.exr: FLOAT channels, but " + folder + "/targets.txt says half").c_str()),
                         std::runtime_error);
  }
}
