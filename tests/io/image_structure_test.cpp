// The image loaders' refusals (io/image_structure.h, io/assets.h): a truncated,
// corrupt or oversized JPEG, PNG or Radiance HDR fails with one SceneError line that names
// the file and says what is wrong, before stb_image decodes it.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <stb_image_write.h>

#include "tests/io/asset_test_support.h"

using namespace asset_test;

TEST_SUITE("assets") {

TEST_CASE("a truncated JPEG") {
  TempFolder tmp;
  const std::string real = readBytes(realAsset(kJpegs[3]));
  const std::string half = tmp.file("half.jpg");
  writeBytes(half, real.substr(0, real.size() / 2));
  std::string m = errorOf([&] { scenes::loadImageRgba8(half); });
  checkOneLine(m, half);
  CHECK(contains(m, "truncated"));
  CHECK(contains(m, "end-of-image marker"));

  // Only the final FF D9 missing (stb_image 2.27 alone says just "expected marker").
  const std::string noEoi = tmp.file("no-eoi.jpg");
  REQUIRE(real.size() > 2);
  REQUIRE((uint8_t(real[real.size() - 2]) == 0xFF && uint8_t(real[real.size() - 1]) == 0xD9));
  writeBytes(noEoi, real.substr(0, real.size() - 2));
  m = errorOf([&] { scenes::loadImageRgba8(noEoi); });
  CHECK(contains(m, "truncated"));

  // Only the headers.
  const std::string headers = tmp.file("headers.jpg");
  writeBytes(headers, real.substr(0, 200));
  m = errorOf([&] { scenes::loadImageRgba8(headers); });
  CHECK(contains(m, "truncated"));
}

TEST_CASE("a JPEG of random bytes, and an empty one") {
  TempFolder tmp;
  std::mt19937 rng(12345);
  std::string bytes(100000, '\0');
  for (char& b : bytes) b = char(rng() & 0xFF);
  bytes[0] = 0x3C;  // whatever the generator says, not FF D8 or 89 'P'
  const std::string path = tmp.file("random.jpg");
  writeBytes(path, bytes);
  std::string m = errorOf([&] { scenes::loadImageRgba8(path); });
  checkOneLine(m, path);
  CHECK(contains(m, "not a readable JPEG/PNG image"));
  CHECK(contains(m, "neither a JPEG nor a PNG signature"));

  // A JPEG signature followed by garbage: complete as far as markers go, stb_image refuses it.
  const std::string sigThenJunk = tmp.file("sig-junk.jpg");
  std::string junk = bytes;
  junk[0] = char(0xFF);
  junk[1] = char(0xD8);
  junk[2] = char(0xFF);
  junk[3] = char(0xE0);
  junk[4] = 0;
  junk[5] = 16;
  junk += std::string("\xFF\xD9", 2);
  writeBytes(sigThenJunk, junk);
  m = errorOf([&] { scenes::loadImageRgba8(sigThenJunk); });
  checkOneLine(m, sigThenJunk);
  CHECK((contains(m, "not a readable JPEG image (stb_image:") || contains(m, "truncated") || contains(m, "segment")));

  // Complete, but its frame header asks for 12-bit samples: stb_image's reason is passed on.
  std::string twelveBit = readBytes(realAsset(kJpegs[3]));
  const size_t sof = twelveBit.find("\xFF\xC0");
  REQUIRE(sof != std::string::npos);
  twelveBit[sof + 4] = 12;
  const std::string twelveBitPath = tmp.file("twelve-bit.jpg");
  writeBytes(twelveBitPath, twelveBit);
  m = errorOf([&] { scenes::loadImageRgba8(twelveBitPath); });
  checkOneLine(m, twelveBitPath);
  CHECK(contains(m, "not a readable JPEG image (stb_image: "));

  const std::string empty = tmp.file("empty.jpg");
  writeBytes(empty, "");
  m = errorOf([&] { scenes::loadImageRgba8(empty); });
  checkOneLine(m, empty);
  CHECK(contains(m, "empty file"));
}

TEST_CASE("PNG: loads, and a truncated or oversized one is refused") {
  TempFolder tmp;
  const int w = 5, h = 3;
  std::vector<uint8_t> rgba(w * h * 4);
  for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = uint8_t(i * 7);
  const std::string png = tmp.file("small.png");
  REQUIRE(stbi_write_png(png.c_str(), w, h, 4, rgba.data(), w * 4) != 0);
  const scenes::ImageRgba8 im = scenes::loadImageRgba8(png);
  CHECK(im.width == w);
  CHECK(im.height == h);
  CHECK(im.pixels == rgba);  // row 0 is the file's first row

  const std::string bytes = readBytes(png);
  const std::string cut = tmp.file("cut.png");
  writeBytes(cut, bytes.substr(0, bytes.size() - 12));  // IEND gone
  std::string m = errorOf([&] { scenes::loadImageRgba8(cut); });
  checkOneLine(m, cut);
  CHECK(contains(m, "truncated"));
  CHECK(contains(m, "IEND"));
  const std::string noCrc = tmp.file("no-crc.png");   // only IEND's 4-byte CRC missing
  writeBytes(noCrc, bytes.substr(0, bytes.size() - 4));
  m = errorOf([&] { scenes::loadImageRgba8(noCrc); });
  checkOneLine(m, noCrc);
  CHECK(contains(m, "inside its IEND chunk"));

  // A well-formed PNG whose header claims 20000 x 10.
  std::string big = bytes;
  const uint32_t claimed = 20000;
  big[16] = char(claimed >> 24);
  big[17] = char(claimed >> 16);
  big[18] = char(claimed >> 8);
  big[19] = char(claimed);
  const std::string bigPath = tmp.file("big.png");
  writeBytes(bigPath, big);
  m = errorOf([&] { scenes::loadImageRgba8(bigPath); });
  checkOneLine(m, bigPath);
  CHECK(contains(m, "image too large (20000x3"));

  // The chunk after IHDR with a type of control bytes, claiming more than the file holds:
  // the message names the chunk with its unprintable bytes as '?', never the bytes.
  std::string odd = bytes;
  const size_t chunk = 8 + 25;   // after the signature and IHDR (length, type, 13 bytes, CRC)
  const char header[8] = {0, 0x10, 0, 0, '\x01', 'I', 'D', '\x7f'};
  odd.replace(chunk, 8, header, 8);
  const std::string oddPath = tmp.file("odd.png");
  writeBytes(oddPath, odd);
  m = errorOf([&] { scenes::loadImageRgba8(oddPath); });
  checkOneLine(m, oddPath);
  CHECK(contains(m, "inside its ?ID? chunk"));
  CHECK(std::none_of(m.begin(), m.end(), [](char c) { return static_cast<unsigned char>(c) < 32; }));
}

TEST_CASE("HDR: corrupt header lines and truncation") {
  TempFolder tmp;
  const std::string real = readBytes(realAsset(kHdr));

  auto withReplaced = [&](const std::string& from, const std::string& to) {
    std::string s = real;
    const size_t at = s.find(from);
    REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
  };

  const std::string badSig = tmp.file("bad-signature.hdr");
  writeBytes(badSig, withReplaced("#?RADIANCE", "#?RADIUNCE"));
  std::string m = errorOf([&] { scenes::loadHdrRgb(badSig); });
  checkOneLine(m, badSig);
  CHECK(contains(m, "not a Radiance HDR file"));
  CHECK(contains(m, "#?RADIUNCE"));

  const std::string badFormat = tmp.file("bad-format.hdr");
  writeBytes(badFormat, withReplaced("FORMAT=32-bit_rle_rgbe", "FORMAT=32-bit_rle_xyze"));
  m = errorOf([&] { scenes::loadHdrRgb(badFormat); });
  checkOneLine(m, badFormat);
  CHECK(contains(m, "FORMAT is '32-bit_rle_xyze', expected 32-bit_rle_rgbe"));

  const std::string badLayout = tmp.file("bad-layout.hdr");
  writeBytes(badLayout, withReplaced("-Y 512 +X 1024", "+Y 512 +X 1024"));
  m = errorOf([&] { scenes::loadHdrRgb(badLayout); });
  checkOneLine(m, badLayout);
  CHECK(contains(m, "resolution line '+Y 512 +X 1024' is not '-Y <height> +X <width>'"));

  const std::string huge = tmp.file("huge.hdr");
  writeBytes(huge, withReplaced("-Y 512 +X 1024", "-Y 512 +X 99999"));
  m = errorOf([&] { scenes::loadHdrRgb(huge); });
  CHECK(contains(m, "image too large (99999x512"));

  // stb_image 2.27 alone never returns on this one (zero-length dumps read past the end).
  const std::string half = tmp.file("half.hdr");
  writeBytes(half, real.substr(0, real.size() / 2));
  m = errorOf([&] { scenes::loadHdrRgb(half); });
  checkOneLine(m, half);
  CHECK(contains(m, "truncated (the file ends in scanline"));

  const std::string headerOnly = tmp.file("header-only.hdr");
  writeBytes(headerOnly, real.substr(0, 20));
  m = errorOf([&] { scenes::loadHdrRgb(headerOnly); });
  CHECK(contains(m, "truncated"));

  // An 8-wide scanline whose R run is 9 long: refused by our check, in its words (stb_image's
  // own would say only "corrupt").
  std::string rle = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n";
  rle += std::string("\x02\x02\x00\x08", 4) + "\x89\x10";
  for (int k = 0; k < 3; ++k) rle += "\x88\x10";
  const std::string overrun = tmp.file("overrun.hdr");
  writeBytes(overrun, rle);
  m = errorOf([&] { scenes::loadHdrRgb(overrun); });
  checkOneLine(m, overrun);
  CHECK(contains(m, "bad run-length data in scanline 1"));
  // A JPEG is not an HDR even though stbi_loadf would convert it.
  const std::string jpegAsHdr = tmp.file("photo.hdr");
  writeBytes(jpegAsHdr, readBytes(realAsset(kJpegs[6])));
  m = errorOf([&] { scenes::loadHdrRgb(jpegAsHdr); });
  CHECK(contains(m, "not a Radiance HDR file"));
}

}  // TEST_SUITE("assets")
