// The structure walks of image_structure.h: each reads a whole file's bytes and says what is
// wrong with them, or "" when the decoder can be trusted with them.
#include "io/image_structure.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace scenes {
namespace {

// A chunk type from the file, made safe for a one-line message.
std::string printable(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return s;
}

std::string jpegTruncated(size_t n, const char* where) {
  return "truncated (the JPEG ends after " + std::to_string(n) + " bytes, " + where +
         ", without the end-of-image marker FF D9)";
}

}  // namespace

bool isJpeg(const std::string& d) {
  return d.size() >= 3 && uint8_t(d[0]) == 0xFF && uint8_t(d[1]) == 0xD8 && uint8_t(d[2]) == 0xFF;
}

bool isPng(const std::string& d) {
  static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  return d.size() >= 8 && std::memcmp(d.data(), sig, 8) == 0;
}

// Walks the JPEG's segments and entropy-coded scans up to the end-of-image marker. Returns
// "" when it is reached, else what is wrong; *w and *h get the first frame header's size
// (left alone if there is none). Lenient where decoders are (fill bytes, stray bytes
// between segments, data after EOI); strict only about running out of file.
std::string jpegStructureProblem(const std::string& s, long* w, long* h) {
  const uint8_t* d = bytesOf(s);
  const size_t n = s.size();
  size_t pos = 2;  // after SOI
  bool sawScan = false;
  for (;;) {
    while (pos < n && d[pos] != 0xFF) ++pos;  // stray bytes (libjpeg skips them too)
    while (pos < n && d[pos] == 0xFF) ++pos;  // fill bytes
    if (pos >= n) return jpegTruncated(n, sawScan ? "after its image data" : "inside its headers");
    const uint8_t marker = d[pos++];
    if (marker == 0xD9) return "";                                         // EOI
    if (marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) continue;  // no length
    if (pos + 2 > n) return jpegTruncated(n, "inside a segment header");
    const size_t len = (size_t(d[pos]) << 8) | d[pos + 1];
    if (len < 2) {
      char m[8];
      std::snprintf(m, sizeof m, "%02X", marker);
      return "not a readable JPEG image (segment FF " + std::string(m) + " at byte " + std::to_string(pos - 2) +
             " has length " + std::to_string(len) + ")";
    }
    if (pos + len > n) {
      char m[8];
      std::snprintf(m, sizeof m, "%02X", marker);
      return "truncated or corrupt (segment FF " + std::string(m) + " at byte " + std::to_string(pos - 2) +
             " claims " + std::to_string(len) + " bytes, but the file ends " + std::to_string(n - pos) +
             " bytes later, without the end-of-image marker FF D9)";
    }
    const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof && len >= 7 && *w < 0) {
      *h = (long(d[pos + 3]) << 8) | d[pos + 4];
      *w = (long(d[pos + 5]) << 8) | d[pos + 6];
    }
    pos += len;
    if (marker != 0xDA) continue;
    // SOS: entropy-coded data runs to the next marker that is not a stuffed 00, a restart
    // marker or a fill byte.
    sawScan = true;
    for (;;) {
      const void* ff = std::memchr(d + pos, 0xFF, n - pos);
      if (!ff) return jpegTruncated(n, "inside its image data");
      pos = size_t(static_cast<const uint8_t*>(ff) - d);
      if (pos + 1 >= n) return jpegTruncated(n, "inside its image data");
      const uint8_t b = d[pos + 1];
      if (b == 0x00 || (b >= 0xD0 && b <= 0xD7)) {
        pos += 2;
      } else if (b == 0xFF) {
        pos += 1;
      } else {
        break;  // a real marker at pos
      }
    }
  }
}

// Walks the PNG's chunks up to IEND; *w and *h get the IHDR size when it comes first.
std::string pngStructureProblem(const std::string& s, long* w, long* h) {
  const uint8_t* d = bytesOf(s);
  const size_t n = s.size();
  auto be32 = [&](size_t at) {
    return (uint32_t(d[at]) << 24) | (uint32_t(d[at + 1]) << 16) | (uint32_t(d[at + 2]) << 8) | d[at + 3];
  };
  if (n >= 24 && std::memcmp(d + 12, "IHDR", 4) == 0) {
    *w = long(be32(16));
    *h = long(be32(20));
  }
  size_t pos = 8;
  for (;;) {
    if (pos + 8 > n)
      return "truncated (the PNG ends after " + std::to_string(n) + " bytes without its IEND chunk)";
    const uint32_t len = (uint32_t(d[pos]) << 24) | (uint32_t(d[pos + 1]) << 16) | (uint32_t(d[pos + 2]) << 8) | d[pos + 3];
    const std::string type(reinterpret_cast<const char*>(d + pos + 4), 4);
    if (len > 0x7FFFFFFFu)
      return "not a readable PNG image (chunk at byte " + std::to_string(pos) + " has length " + std::to_string(len) + ")";
    if (pos + 12 + size_t(len) > n)
      return "truncated (the PNG ends after " + std::to_string(n) + " bytes, inside its " + printable(type) +
             " chunk, without its IEND chunk)";
    if (type == "IEND") return "";
    pos += 12 + size_t(len);
  }
}

// Checks the pixel data exactly as stb_image 2.27's stbi__hdr_load will consume it, so that
// the decode never reads past the end (where it would loop forever on zero-length dumps).
std::string hdrDataProblem(const std::string& s, size_t pos, int w, int h) {
  const uint8_t* d = bytesOf(s);
  const size_t n = s.size();
  const size_t flatBytes = size_t(w) * size_t(h) * 4;
  auto truncatedAt = [&](size_t row) {
    return "truncated (the file ends in scanline " + std::to_string(row + 1) + " of " + std::to_string(h) + ")";
  };
  auto flatFrom = [&](size_t start) -> std::string {
    if (n - start >= flatBytes) return "";
    return truncatedAt((n - start) / (size_t(w) * 4));
  };
  if (w < 8 || w >= 32768) return flatFrom(pos);
  for (int j = 0; j < h; ++j) {
    if (pos + 3 > n) return truncatedAt(j);
    const uint8_t c1 = d[pos], c2 = d[pos + 1], lenHi = d[pos + 2];
    if (c1 != 2 || c2 != 2 || (lenHi & 0x80)) return flatFrom(pos);  // stb: the rest is flat
    if (pos + 4 > n) return truncatedAt(j);
    const int len = (int(lenHi) << 8) | d[pos + 3];
    pos += 4;
    if (len != w)
      return "not a readable Radiance HDR file (scanline " + std::to_string(j + 1) + " holds " + std::to_string(len) +
             " pixels; the image is " + std::to_string(w) + " wide)";
    for (int k = 0; k < 4; ++k) {
      int i = 0;
      while (i < w) {
        if (pos >= n) return truncatedAt(j);
        int count = d[pos++];
        if (count > 128) {
          if (pos >= n) return truncatedAt(j);
          ++pos;
          count -= 128;
          if (count > w - i)
            return "not a readable Radiance HDR file (bad run-length data in scanline " + std::to_string(j + 1) + ")";
          i += count;
        } else {
          if (count > w - i)
            return "not a readable Radiance HDR file (bad run-length data in scanline " + std::to_string(j + 1) + ")";
          if (pos + size_t(count) > n) return truncatedAt(j);
          pos += size_t(count);
          i += count;
        }
      }
    }
  }
  return "";
}

}  // namespace scenes
