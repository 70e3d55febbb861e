// Asset loading for the deferred scene: OBJ through tinyobjloader, JPEG/PNG and Radiance HDR
// through stb_image, each checked first so that a bad file fails with one clear line.
//
// Order of checks for every file: it exists and is a regular file, it can be opened (so "no
// such file" and "permission denied" are told apart from bad content), it is not empty; then
// the format's signature; then the file's structure is walked to prove it is complete (the
// HDR header here, JPEG markers, PNG chunks and HDR scanlines in image_structure.h, which
// says why stb_image cannot be left to find out); then the size (at most 16384 a side);
// then stb_image decodes.
#include "io/assets.h"

#include "io/asset_manifest.h"
#include "io/image_structure.h"
#include "io/obj_validate.h"

#include "raster/util/parallel.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <unordered_map>

#include <stb_image.h>
#include <tiny_obj_loader.h>

#include <glm/glm.hpp>

namespace scenes {

std::string assetPath(const SceneOptions& options, const std::string& relative) {
  return assetDirectory(options) + "/" + relative;
}

namespace {

namespace fs = std::filesystem;

constexpr int kMaxImageSide = 16384;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw SceneError("asset " + path + ": " + what);
}

// Text from a library, made safe for a one-line message.
std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

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

}  // namespace

void checkAssetFileExists(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) {
    std::error_code ec2;
    if (fs::is_symlink(fs::symlink_status(path, ec2))) fail(path, "no such file (a symbolic link to a missing file)");
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::exists(parent, ec2) && !ec2)
      fail(path, "no such file (the folder " + parent.string() + " does not exist)");
    fail(path, "no such file");
  }
  if (ec) {
    if (ec == std::errc::permission_denied) fail(path, "permission denied (cannot look into its folder)");
    fail(path, "cannot be examined (" + ec.message() + ")");
  }
  if (fs::is_directory(st)) fail(path, "is a directory, not a file");
  if (!fs::is_regular_file(st)) fail(path, "is not a regular file");
}

namespace {

// The whole file, after checking that it is there, is a file, can be read and is not empty.
std::string readAssetFile(const std::string& path) {
  checkAssetFileExists(path);
  std::error_code ec;
  errno = 0;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    const int e = errno;
    if (e == EACCES || e == EPERM) fail(path, "permission denied");
    fail(path, std::string("cannot be opened (") + std::strerror(e) + ")");
  }
  std::string data;
  const uintmax_t expected = fs::file_size(path, ec);
  if (!ec) data.reserve(static_cast<size_t>(expected));
  char buf[1 << 16];
  size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) data.append(buf, got);
  const bool readError = std::ferror(f) != 0;
  const int e = errno;
  std::fclose(f);
  if (readError) fail(path, std::string("read error (") + std::strerror(e) + ")");
  if (data.empty()) fail(path, "empty file (0 bytes)");
  checkAssetAgainstManifest(path, data);   // a checked asset folder: the listed bytes or an error
  return data;
}

void checkImageSize(const std::string& path, long w, long h) {
  if (w <= 0 || h <= 0)
    fail(path, "not a readable image (it claims a size of " + std::to_string(w) + "x" + std::to_string(h) + ")");
  if (w > kMaxImageSide || h > kMaxImageSide)
    fail(path, "image too large (" + std::to_string(w) + "x" + std::to_string(h) + "; at most " +
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

// ---- OBJ ----------------------------------------------------------------------------------------

struct TripleHash {
  size_t operator()(const std::array<int, 3>& t) const {
    uint64_t h = uint32_t(t[0]);
    h = h * 0x9E3779B97F4A7C15ull ^ uint32_t(t[1]);
    h = h * 0x9E3779B97F4A7C15ull ^ uint32_t(t[2]);
    return size_t(h ^ (h >> 29));
  }
};

void checkFinite(const std::string& path, const std::vector<tinyobj::real_t>& values, int perItem, const char* what) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(static_cast<float>(values[i])))
      fail(path, std::string(what) + " " + std::to_string(i / perItem + 1) + " has a coordinate that is not a finite float");
}

}  // namespace

// ---- the cat mesh ---------------------------------------------------------------------------------

namespace {

// What tinyobjloader reads of an OBJ file: the element arrays and the faces of each shape.
struct ObjFile {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
};

// Every line checked first (validateObj): tinyobjloader only sees what it handles right.
ObjFile readObj(const std::string& path, const std::string& text) {
  validateObj(path, text);
  std::istringstream in(text);
  ObjFile obj;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  // No triangulation by the loader (it would reorder quads by edge length and read vertex
  // data through unchecked indices): faces are fanned by interleaveAndFan, in file order.
  if (!tinyobj::LoadObj(&obj.attrib, &obj.shapes, &materials, &warn, &err, &in, nullptr, /*triangulate=*/false,
                        /*default_vcols_fallback=*/false))
    fail(path, "not a readable OBJ file (tinyobjloader: " + oneLine(err) + ")");
  return obj;
}

// The element and face counts, refused unless the file has positions, normals, texture
// coordinates and triangles, every coordinate finite.
ObjLoadInfo countElements(const std::string& path, const ObjFile& obj) {
  ObjLoadInfo info;
  info.positions = obj.attrib.vertices.size() / 3;
  info.texcoords = obj.attrib.texcoords.size() / 2;
  info.normals = obj.attrib.normals.size() / 3;
  for (const tinyobj::shape_t& shape : obj.shapes) {
    info.faces += shape.mesh.num_face_vertices.size();
    for (unsigned char nv : shape.mesh.num_face_vertices) info.triangles += nv >= 3 ? nv - 2 : 0;
  }
  const size_t P = info.positions, T = info.texcoords, N = info.normals;
  if (P == 0) fail(path, "no vertices (no 'v' lines): not an OBJ mesh");
  if (info.triangles == 0)
    fail(path, "no triangles (" + std::to_string(P) + " vertices but no faces, 'f' lines)");
  if (N == 0) fail(path, "no normals ('vn' lines); the scene needs a position, normal and uv per vertex");
  if (T == 0) fail(path, "no texture coordinates ('vt' lines); the scene needs a position, normal and uv per vertex");
  if (P > UINT32_MAX / 2) fail(path, "too many vertices (" + std::to_string(P) + ")");
  checkFinite(path, obj.attrib.vertices, 3, "vertex");
  checkFinite(path, obj.attrib.normals, 3, "normal");
  checkFinite(path, obj.attrib.texcoords, 2, "texture coordinate");
  return info;
}

// Validates every face corner's v, vt and vn index against the counts; returns whether
// v/vt/vn share one index throughout (ObjLoadInfo::sharedIndices).
bool checkCorners(const std::string& path, const ObjFile& obj, const ObjLoadInfo& info) {
  const size_t P = info.positions, T = info.texcoords, N = info.normals;
  bool shared = (P == T && P == N);
  size_t face = 0;
  // tinyobjloader gives -1 for an absent vt or vn index (a v index is never absent).
  auto checkIndex = [&](int idx, size_t count, const char* what, const char* countWhat, bool mayBeAbsent) {
    if (idx == -1 && mayBeAbsent)
      fail(path, "face " + std::to_string(face) + " has no " + what + " index (every corner must be v/vt/vn)");
    if (idx < 0)
      fail(path, "face " + std::to_string(face) + " uses a relative " + what + " index that points before the first " + what);
    if (size_t(idx) >= count)
      fail(path, "face " + std::to_string(face) + " uses " + what + " " + std::to_string(size_t(idx) + 1) +
                     " but the file has " + std::to_string(count) + " " + countWhat);
  };
  for (const tinyobj::shape_t& shape : obj.shapes) {
    size_t corner = 0;
    for (unsigned char nv : shape.mesh.num_face_vertices) {
      ++face;
      for (unsigned c = 0; c < nv; ++c, ++corner) {
        const tinyobj::index_t& ix = shape.mesh.indices[corner];
        checkIndex(ix.vertex_index, P, "vertex", "vertices", false);
        checkIndex(ix.texcoord_index, T, "texture coordinate", "texture coordinates ('vt' lines)", true);
        checkIndex(ix.normal_index, N, "normal", "normals ('vn' lines)", true);
        if (ix.vertex_index != ix.texcoord_index || ix.vertex_index != ix.normal_index) shared = false;
      }
    }
  }
  return shared;
}

// Interleaved pos(3) normal(3) uv(2) vertices: with shared indices vertex i is (v i, vt i,
// vn i), else each (v, vt, vn) triple once, in first-use order. Faces are fanned
// (0, k, k + 1) in file order.
MeshData interleaveAndFan(const ObjFile& obj, const ObjLoadInfo& info) {
  const tinyobj::attrib_t& attrib = obj.attrib;
  MeshData mesh;
  mesh.strideFloats = 8;
  mesh.attributes = {{0, 3, 0}, {1, 3, 3}, {2, 2, 6}};
  mesh.indices.reserve(info.triangles * 3);

  auto pushVertex = [&](int v, int vt, int vn) {
    mesh.vertices.push_back(static_cast<float>(attrib.vertices[3 * size_t(v) + 0]));
    mesh.vertices.push_back(static_cast<float>(attrib.vertices[3 * size_t(v) + 1]));
    mesh.vertices.push_back(static_cast<float>(attrib.vertices[3 * size_t(v) + 2]));
    mesh.vertices.push_back(static_cast<float>(attrib.normals[3 * size_t(vn) + 0]));
    mesh.vertices.push_back(static_cast<float>(attrib.normals[3 * size_t(vn) + 1]));
    mesh.vertices.push_back(static_cast<float>(attrib.normals[3 * size_t(vn) + 2]));
    mesh.vertices.push_back(static_cast<float>(attrib.texcoords[2 * size_t(vt) + 0]));
    mesh.vertices.push_back(static_cast<float>(attrib.texcoords[2 * size_t(vt) + 1]));
  };

  // Per corner, the output vertex index; then faces are fanned (0, k, k + 1) in file order.
  const bool shared = info.sharedIndices;
  std::vector<uint32_t> cornerVertex;
  if (shared) {
    mesh.vertices.reserve(info.positions * 8);
    for (size_t i = 0; i < info.positions; ++i) pushVertex(int(i), int(i), int(i));
  }
  std::unordered_map<std::array<int, 3>, uint32_t, TripleHash> seen;
  for (const tinyobj::shape_t& shape : obj.shapes) {
    cornerVertex.clear();
    for (const tinyobj::index_t& ix : shape.mesh.indices) {
      if (shared) {
        cornerVertex.push_back(uint32_t(ix.vertex_index));
        continue;
      }
      const std::array<int, 3> key{ix.vertex_index, ix.texcoord_index, ix.normal_index};
      auto [it, inserted] = seen.try_emplace(key, uint32_t(mesh.vertices.size() / 8));
      if (inserted) pushVertex(ix.vertex_index, ix.texcoord_index, ix.normal_index);
      cornerVertex.push_back(it->second);
    }
    size_t corner = 0;
    for (unsigned char nv : shape.mesh.num_face_vertices) {
      for (unsigned k = 1; k + 1 < nv; ++k) {
        mesh.indices.push_back(cornerVertex[corner]);
        mesh.indices.push_back(cornerVertex[corner + k]);
        mesh.indices.push_back(cornerVertex[corner + k + 1]);
      }
      corner += nv;
    }
  }
  return mesh;
}

// upload_cat's normalisation, in float: centre x/z, min y at 0, height 2.2.
void normaliseLikeUploadCat(MeshData& mesh) {
  const size_t count = mesh.vertices.size() / 8;
  glm::vec3 bmin(1.0e30f), bmax(-1.0e30f);
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 p(mesh.vertices[i * 8 + 0], mesh.vertices[i * 8 + 1], mesh.vertices[i * 8 + 2]);
    bmin = glm::min(bmin, p);
    bmax = glm::max(bmax, p);
  }
  const glm::vec3 center = (bmin + bmax) * 0.5f;
  const float s = 2.2f / std::max(bmax.y - bmin.y, 0.001f);
  for (size_t i = 0; i < count; ++i) {
    float* v = &mesh.vertices[i * 8];
    v[0] = (v[0] - center.x) * s;
    v[1] = (v[1] - bmin.y) * s;
    v[2] = (v[2] - center.z) * s;
  }
}

}  // namespace

MeshData loadCatMesh(const std::string& path, ObjLoadInfo* infoOut) { return parseCatMesh(path, readAssetFile(path), infoOut); }

MeshData parseCatMesh(const std::string& path, const std::string& text, ObjLoadInfo* infoOut) {
  const ObjFile obj = readObj(path, text);
  ObjLoadInfo info = countElements(path, obj);
  info.sharedIndices = checkCorners(path, obj, info);
  MeshData mesh = interleaveAndFan(obj, info);
  normaliseLikeUploadCat(mesh);
  if (infoOut) *infoOut = info;
  return mesh;
}

// ---- images ---------------------------------------------------------------------------------------

ImageRgba8 loadImageRgba8(const std::string& path) { return decodeImageRgba8(path, readAssetFile(path)); }

ImageRgba8 decodeImageRgba8(const std::string& path, const std::string& data) {
  const bool jpeg = isJpeg(data), png = isPng(data);
  if (!jpeg && !png) {
    int w, h, c;
    std::string why = "stb_image: unknown image type";
    if (data.size() <= size_t(INT_MAX) && !stbi_info_from_memory(bytesOf(data), int(data.size()), &w, &h, &c))
      why = stbReason();
    fail(path, "not a readable JPEG/PNG image (it starts with bytes " + hexBytes(data, 4) +
                   ", which is neither a JPEG nor a PNG signature; " + why + ")");
  }
  const char* kind = jpeg ? "JPEG" : "PNG";
  if (data.size() > size_t(INT_MAX)) fail(path, "file too large for stb_image");
  long headerW = -1, headerH = -1;
  const std::string problem =
      jpeg ? jpegStructureProblem(data, &headerW, &headerH) : pngStructureProblem(data, &headerW, &headerH);
  if (!problem.empty()) fail(path, problem);
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
  if (!pixels) fail(path, std::string("not a readable ") + kind + " image (" + stbReason() + ")");
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
    fail(path, "not a Radiance HDR file (it does not start with the line #?RADIANCE; it starts with " +
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
  if (!endOfHeader) fail(path, "truncated (the file ends inside its header, before the blank line and the resolution line)");
  if (!formatOk)
    fail(path, otherFormat.empty()
                   ? "not a Radiance HDR file stb_image can read (its header has no FORMAT=32-bit_rle_rgbe line)"
                   : "not a Radiance HDR file stb_image can read (FORMAT is " + quoteForMessage(otherFormat) +
                         ", expected 32-bit_rle_rgbe)");
  if (!hdrLine(data, pos, line)) fail(path, "truncated (the file ends before its resolution line)");
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
    fail(path, "not a Radiance HDR file stb_image can read (resolution line " + quoteForMessage(line) +
                   " is not '-Y <height> +X <width>')");
  if (w <= 0 || h <= 0)
    fail(path, "not a readable Radiance HDR file (resolution line " + quoteForMessage(line) + " gives a size of " +
                   std::to_string(w) + "x" + std::to_string(h) + ")");
  checkImageSize(path, w, h);
  const std::string problem = hdrDataProblem(data, pos, int(w), int(h));
  if (!problem.empty()) fail(path, problem);
  if (data.size() > size_t(INT_MAX)) fail(path, "file too large for stb_image");

  // Decoded as 3 floats a texel: reserved from the header before stb_image allocates it.
  memory::Reservation reserved(uint64_t(w) * uint64_t(h) * 12,
                               memory::joined({"decoding ", path, " (", std::to_string(w), "x", std::to_string(h), ")"}));
  if (auto cached = cachedImage<ImageRgbFloat>(&DecodedImages::rgbFloat, data, reserved)) return std::move(*cached);
  stbi_set_flip_vertically_on_load_thread(0);
  int x = 0, y = 0, comp = 0;
  float* pixels = stbi_loadf_from_memory(bytesOf(data), int(data.size()), &x, &y, &comp, 3);
  if (!pixels) fail(path, "not a readable Radiance HDR file (" + stbReason() + ")");
  if (x != w || y != h) {
    stbi_image_free(pixels);
    fail(path, "not a readable Radiance HDR file (stb_image decoded " + std::to_string(x) + "x" + std::to_string(y) +
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
