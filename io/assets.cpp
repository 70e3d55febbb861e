// The scenes' image assets: JPEG/PNG and Radiance HDR through stb_image, each checked first
// so that a bad file fails with one clear line (the cat mesh is io/cat_mesh.cpp's).
//
// Order of checks for every file: it exists and is a regular file, it can be opened (so "no
// such file" and "permission denied" are told apart from bad content), it is not empty
// (io/asset_file.h); then the format's signature; then the file's structure is walked to
// prove it is complete (the HDR header here, JPEG markers, PNG chunks and HDR scanlines in
// image_structure.h, which says why stb_image cannot be left to find out); then the size (at
// most 16384 a side); then stb_image decodes.
#include "io/assets.h"

#include "io/asset_file.h"
#include "io/image_structure.h"

#include "raster/util/parallel.h"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <unordered_map>

#include <stb_image.h>

namespace scenes {

std::string assetPath(const SceneOptions& options, const std::string& relative) {
  return assetDirectory(options) + "/" + relative;
}

namespace {

constexpr int kMaxImageSide = 16384;

// ScopedImageCache's store: decoded images by the file's bytes (the key is the whole file,
// so a changed or cut file is a different key and goes through stb_image again). Images are
// decoded on several threads at once (loadImagesRgba8), hence the lock; the decoding itself
// runs outside it.
template <class T>
struct Decoded {
  int width = 0, height = 0;
  SharedPixels<T> pixels;
};
template <class T>
using DecodedByBytes = std::unordered_map<std::string, Decoded<T>>;
struct DecodedImages {
  std::mutex lock;
  DecodedByBytes<uint8_t> rgba8;
  DecodedByBytes<float> rgbFloat;
};
std::unique_ptr<DecodedImages> decodedImages;

// The image a ScopedImageCache holds for these bytes, holding this load's reservation (taken
// from `reserved` only on a hit); none when no cache is alive or it has no such image.
template <class Image, class T>
std::optional<Image> cachedImage(DecodedByBytes<T> DecodedImages::*map, const std::string& data,
                                 memory::Reservation& reserved) {
  if (!decodedImages) return std::nullopt;
  const std::lock_guard<std::mutex> held(decodedImages->lock);
  const DecodedByBytes<T>& images = (*decodedImages).*map;
  const auto found = images.find(data);
  if (found == images.end()) return std::nullopt;
  Image image;
  image.width = found->second.width;
  image.height = found->second.height;
  image.reserved = std::move(reserved);
  image.pixels = found->second.pixels;
  return image;
}

template <class T>
void keepImage(DecodedByBytes<T> DecodedImages::*map, const std::string& data, int width, int height,
               const SharedPixels<T>& pixels) {
  if (!decodedImages) return;
  const std::lock_guard<std::mutex> held(decodedImages->lock);
  ((*decodedImages).*map).emplace(data, Decoded<T>{width, height, pixels});
}

std::string hexBytes(const std::string& data, size_t count) {
  std::string out;
  char buf[4];
  for (size_t i = 0; i < count && i < data.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%02x", static_cast<unsigned>(static_cast<uint8_t>(data[i])));
    if (i) out += ' ';
    out += buf;
  }
  return out;
}

void checkImageSize(const std::string& path, long w, long h) {
  if (w <= 0 || h <= 0)
    failAsset(path, "not a readable image (it claims a size of " + std::to_string(w) + "x" + std::to_string(h) + ")");
  if (w > kMaxImageSide || h > kMaxImageSide)
    failAsset(path, "image too large (" + std::to_string(w) + "x" + std::to_string(h) + "; at most " +
                   std::to_string(kMaxImageSide) + " texels a side)");
}

std::string stbReason() {
  const char* r = stbi_failure_reason();
  return std::string("stb_image: ") + (r ? r : "unknown error");
}

// ---- Radiance HDR ---------------------------------------------------------------------------

// One header line as stb_image's stbi__hdr_gettoken reads it (up to '\n' or the end).
bool hdrLine(const std::string& d, size_t& pos, std::string& line) {
  if (pos >= d.size()) return false;
  const size_t nl = d.find('\n', pos);
  if (nl == std::string::npos) {
    line = d.substr(pos);
    pos = d.size();
  } else {
    line = d.substr(pos, nl - pos);
    pos = nl + 1;
  }
  return true;
}

std::string quoteForMessage(const std::string& s) {
  std::string out;
  for (char c : s.substr(0, 60)) out += (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) ? '?' : c;
  return "'" + out + (s.size() > 60 ? "...'" : "'");
}

bool looksLikeText(const std::string& s) {
  if (s.empty() || s.size() > 200) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) >= 32 && static_cast<unsigned char>(c) < 127; });
}

}  // namespace

// ---- images ---------------------------------------------------------------------------------------

ImageRgba8 loadImageRgba8(const std::string& path) { return decodeImageRgba8(path, readAssetFile(path)); }

ImageRgba8 decodeImageRgba8(const std::string& path, const std::string& data) {
  const bool jpeg = isJpeg(data), png = isPng(data);
  if (!jpeg && !png) {
    int w, h, c;
    std::string why = "stb_image: unknown image type";
    if (data.size() <= size_t(INT_MAX) && !stbi_info_from_memory(bytesOf(data), int(data.size()), &w, &h, &c))
      why = stbReason();
    failAsset(path, "not a readable JPEG/PNG image (it starts with bytes " + hexBytes(data, 4) +
                   ", which is neither a JPEG nor a PNG signature; " + why + ")");
  }
  const char* kind = jpeg ? "JPEG" : "PNG";
  if (data.size() > size_t(INT_MAX)) failAsset(path, "file too large for stb_image");
  long headerW = -1, headerH = -1;
  const std::string problem =
      jpeg ? jpegStructureProblem(data, &headerW, &headerH) : pngStructureProblem(data, &headerW, &headerH);
  if (!problem.empty()) failAsset(path, problem);
  // Refuse an absurd size before decoding (a zero JPEG height is stb_image's to refuse).
  if (headerW > kMaxImageSide || headerH > kMaxImageSide) checkImageSize(path, headerW, headerH);

  // The decoded size, from the header, reserved before stb_image allocates it (and held for
  // as long as the pixels are).
  memory::Reservation reserved;
  if (headerW > 0 && headerH > 0)
    reserved = memory::Reservation(uint64_t(headerW) * uint64_t(headerH) * 4,
                                   memory::joined({"decoding ", path, " (", std::to_string(headerW), "x", std::to_string(headerH), ")"}));
  if (auto cached = cachedImage<ImageRgba8>(&DecodedImages::rgba8, data, reserved)) return std::move(*cached);
  int w = 0, h = 0, c = 0;
  stbi_set_flip_vertically_on_load_thread(0);  // the tutorial's loader: rows as in the file
  stbi_uc* pixels = stbi_load_from_memory(bytesOf(data), int(data.size()), &w, &h, &c, 4);
  if (!pixels) failAsset(path, std::string("not a readable ") + kind + " image (" + stbReason() + ")");
  if (w <= 0 || h <= 0 || w > kMaxImageSide || h > kMaxImageSide) {
    stbi_image_free(pixels);
    checkImageSize(path, w, h);
  }
  ImageRgba8 image;
  image.width = w;
  image.height = h;
  image.reserved = std::move(reserved);
  image.pixels = SharedPixels<uint8_t>(std::vector<uint8_t>(pixels, pixels + size_t(w) * size_t(h) * 4));
  stbi_image_free(pixels);
  keepImage(&DecodedImages::rgba8, data, w, h, image.pixels);
  return image;
}

std::vector<ImageRgba8> loadImagesRgba8(const std::vector<std::string>& paths) {
  std::vector<ImageRgba8> images(paths.size());
  std::vector<std::exception_ptr> errors(paths.size());
  raster::ThreadPool(0).parallelFor(int(paths.size()), [&](int index) {
    const size_t i = size_t(index);
    try {
      images[i] = loadImageRgba8(paths[i]);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return images;
}

ScopedImageCache::ScopedImageCache() {
  if (decodedImages) throw std::logic_error("ScopedImageCache: one is already alive");
  decodedImages = std::make_unique<DecodedImages>();
}
ScopedImageCache::~ScopedImageCache() { decodedImages.reset(); }

ImageRgbFloat loadHdrRgb(const std::string& path) { return decodeHdrRgb(path, readAssetFile(path)); }

ImageRgbFloat decodeHdrRgb(const std::string& path, const std::string& data) {
  size_t pos = 0;
  std::string line;
  hdrLine(data, pos, line);
  const bool terminated = pos <= data.size() && pos > 0 && data[pos - 1] == '\n';
  if (!terminated || (line != "#?RADIANCE" && line != "#?RGBE"))
    failAsset(path, "not a Radiance HDR file (it does not start with the line #?RADIANCE; it starts with " +
                   (looksLikeText(line) ? quoteForMessage(line) : "bytes " + hexBytes(data, 4)) + ")");
  bool formatOk = false, endOfHeader = false;
  std::string otherFormat;
  while (hdrLine(data, pos, line)) {
    if (line.empty()) {
      endOfHeader = true;
      break;
    }
    if (line == "FORMAT=32-bit_rle_rgbe") formatOk = true;
    else if (line.rfind("FORMAT=", 0) == 0) otherFormat = line.substr(7);
  }
  if (!endOfHeader) failAsset(path, "truncated (the file ends inside its header, before the blank line and the resolution line)");
  if (!formatOk)
    failAsset(path, otherFormat.empty()
                   ? "not a Radiance HDR file stb_image can read (its header has no FORMAT=32-bit_rle_rgbe line)"
                   : "not a Radiance HDR file stb_image can read (FORMAT is " + quoteForMessage(otherFormat) +
                         ", expected 32-bit_rle_rgbe)");
  if (!hdrLine(data, pos, line)) failAsset(path, "truncated (the file ends before its resolution line)");
  // As stb_image parses it: "-Y <height> +X <width>".
  const char* t = line.c_str();
  char* end = nullptr;
  long h = -1, w = -1;
  bool layoutOk = std::strncmp(t, "-Y ", 3) == 0;
  if (layoutOk) {
    h = std::strtol(t + 3, &end, 10);
    while (*end == ' ') ++end;
    layoutOk = std::strncmp(end, "+X ", 3) == 0;
    if (layoutOk) w = std::strtol(end + 3, nullptr, 10);
  }
  if (!layoutOk)
    failAsset(path, "not a Radiance HDR file stb_image can read (resolution line " + quoteForMessage(line) +
                   " is not '-Y <height> +X <width>')");
  if (w <= 0 || h <= 0)
    failAsset(path, "not a readable Radiance HDR file (resolution line " + quoteForMessage(line) + " gives a size of " +
                   std::to_string(w) + "x" + std::to_string(h) + ")");
  checkImageSize(path, w, h);
  const std::string problem = hdrDataProblem(data, pos, int(w), int(h));
  if (!problem.empty()) failAsset(path, problem);
  if (data.size() > size_t(INT_MAX)) failAsset(path, "file too large for stb_image");

  // Decoded as 3 floats a texel: reserved from the header before stb_image allocates it.
  memory::Reservation reserved(uint64_t(w) * uint64_t(h) * 12,
                               memory::joined({"decoding ", path, " (", std::to_string(w), "x", std::to_string(h), ")"}));
  if (auto cached = cachedImage<ImageRgbFloat>(&DecodedImages::rgbFloat, data, reserved)) return std::move(*cached);
  stbi_set_flip_vertically_on_load_thread(0);
  int x = 0, y = 0, comp = 0;
  float* pixels = stbi_loadf_from_memory(bytesOf(data), int(data.size()), &x, &y, &comp, 3);
  if (!pixels) failAsset(path, "not a readable Radiance HDR file (" + stbReason() + ")");
  if (x != w || y != h) {
    stbi_image_free(pixels);
    failAsset(path, "not a readable Radiance HDR file (stb_image decoded " + std::to_string(x) + "x" + std::to_string(y) +
                   ", the header says " + std::to_string(w) + "x" + std::to_string(h) + ")");
  }
  ImageRgbFloat image;
  image.width = x;
  image.height = y;
  image.reserved = std::move(reserved);
  image.pixels = SharedPixels<float>(std::vector<float>(pixels, pixels + size_t(x) * size_t(y) * 3));
  stbi_image_free(pixels);
  keepImage(&DecodedImages::rgbFloat, data, x, y, image.pixels);
  return image;
}

}  // namespace scenes
