// Loading the scenes' asset files (deferred's and pbr's): the cat OBJ, the JPEG texture sets, the HDR environment.
//
// Each loader reproduces what the tutorial's host code does with the file (seed
// 000_a9faaef907542225.txt: upload_cat, load_image_from_file, load_hdr_texture; deviations in
// ../shared/seeds/README.md), and checks the file first so that a bad asset fails with one
// clear line instead of a crash, a hang or a silently wrong picture. Every failure throws
// SceneError("asset <path>: <what is wrong>"), for example
//   asset /a/b.jpg: no such file
//   asset /a/b.jpg: truncated (the JPEG ends after 1684449 bytes, inside its image data, without the end-of-image marker FF D9)
//   asset /a/cat.obj: face 12 uses vertex 9000 but the file has 6863 vertices
//   asset /a/env.hdr: not a Radiance HDR file (FORMAT is '...', expected 32-bit_rle_rgbe)
#pragma once

#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "io/memory_budget.h"
#include "scenes/scene.h"

namespace scenes {

// assetDirectory(options) + "/" + relative.
std::string assetPath(const SceneOptions& options, const std::string& relative);

// Every loader below reads its file through io/asset_file.h's readAssetFile (there, too, the
// existence check alone, for a caller that must know up front).

// ---- the cat mesh -------------------------------------------------------------------------

// What the OBJ held, for tests and reports.
struct ObjLoadInfo {
  size_t positions = 0;       // v lines
  size_t texcoords = 0;       // vt lines
  size_t normals = 0;         // vn lines
  size_t faces = 0;           // f lines (polygons, before triangulation)
  size_t triangles = 0;
  // True when every face corner uses one index for v, vt and vn and the three counts are
  // equal: vertex i is then (v i, vt i, vn i), in file order. False: (v, vt, vn) triples
  // were de-duplicated in first-use order.
  bool sharedIndices = false;
};

// The seed's upload_cat: interleaved pos(3) normal(3) uv(2), strideFloats 8, attributes
// {0: 3 @0, 1: 3 @3, 2: 2 @6}; uv as in the file (no 1 - v flip); faces fan-triangulated in
// file order; positions normalised as upload_cat does (centre x/z, min y at 0, height 2.2).
MeshData loadCatMesh(const std::string& objPath, ObjLoadInfo* info = nullptr);
// The same for a file's content already read (path names it in messages): for the fuzz targets.
MeshData parseCatMesh(const std::string& path, const std::string& text, ObjLoadInfo* info = nullptr);

// ---- images -----------------------------------------------------------------------------------

// Decoded texels: read-only once decoded, and shared by copies (ScopedImageCache hands out
// the pixels it keeps without copying them). Reads like the std::vector it holds.
template <class T>
class SharedPixels {
 public:
  SharedPixels() = default;
  explicit SharedPixels(std::vector<T> values) : values_(std::make_shared<const std::vector<T>>(std::move(values))) {}
  const T* data() const { return values_ ? values_->data() : nullptr; }
  size_t size() const { return values_ ? values_->size() : 0; }
  bool empty() const { return size() == 0; }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size(); }
  const T& operator[](size_t i) const { return (*values_)[i]; }
  friend bool operator==(const SharedPixels& a, const SharedPixels& b) { return std::equal(a.begin(), a.end(), b.begin(), b.end()); }
  friend bool operator==(const SharedPixels& a, const std::vector<T>& b) { return std::equal(a.begin(), a.end(), b.begin(), b.end()); }

 private:
  std::shared_ptr<const std::vector<T>> values_;
};

// 8-bit RGBA, rows exactly as stb_image returns them (the file's first row first, no flip):
// they are glTexImage2D's rows, so row 0 is t = 0.
struct ImageRgba8 {
  int width = 0;
  int height = 0;
  SharedPixels<uint8_t> pixels;   // width * height * 4
  memory::Reservation reserved;  // the pixels' share of --max-memory, reserved before decoding
};

// A JPEG or PNG through stb_image with 4 channels requested (the tutorial's loader).
// Checks that the file is complete (JPEG: the end-of-image marker after the last scan;
// PNG: the IEND chunk) and at most 16384 texels on a side, and reserves the decoded size
// (io/memory_budget.h) from the header before decoding.
ImageRgba8 loadImageRgba8(const std::string& path);
ImageRgba8 decodeImageRgba8(const std::string& path, const std::string& data);   // content already read

// Several images decoded in parallel (the 2K JPEGs take tens of milliseconds each), in the
// order given. If any fails, the error of the first failing path (in that order) is thrown.
std::vector<ImageRgba8> loadImagesRgba8(const std::vector<std::string>& paths);

// While one of these is alive, an image file whose bytes equal those of one decoded before
// is not decoded again: it shares the first decoding's pixels (every check and the
// --max-memory reservation still run on each load; only stb_image's decoding is skipped,
// which is the larger part of setting up a scene with 2K JPEGs). For a program that sets the
// same scenes up many times (the test program: each renders a scene at several sizes,
// thread counts and methods); the decoded pixels are held until it ends. One at a time.
class ScopedImageCache {
 public:
  ScopedImageCache();
  ~ScopedImageCache();
  ScopedImageCache(const ScopedImageCache&) = delete;
  ScopedImageCache& operator=(const ScopedImageCache&) = delete;
};

// Linear RGB floats, rows as stb_image returns them (no flip).
struct ImageRgbFloat {
  int width = 0;
  int height = 0;
  SharedPixels<float> pixels;     // width * height * 3
  memory::Reservation reserved;  // as ImageRgba8's
};

// A Radiance RGBE (.hdr) file through stbi_loadf with 3 channels (load_hdr_texture).
// The header and every scanline are checked before decoding (stb_image would loop forever
// on some truncated run-length data).
ImageRgbFloat loadHdrRgb(const std::string& path);
ImageRgbFloat decodeHdrRgb(const std::string& path, const std::string& data);   // content already read

}  // namespace scenes
