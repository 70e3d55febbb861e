// The cat mesh of the deferred and pbr scenes: an OBJ file checked line by line
// (io/obj_validate.h), read by tinyobjloader, then checked again as a mesh (counts, finite
// coordinates, every corner's indices), interleaved and fanned as the tutorial's upload_cat
// does (io/assets.h).
#include "io/assets.h"

#include "io/asset_file.h"
#include "io/obj_validate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <tiny_obj_loader.h>

#include <glm/glm.hpp>

namespace scenes {

namespace {

// Text from a library, made safe for a one-line message.
std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// A corner's (v, vt, vn) indices as a key: interleaveAndFan makes one vertex per distinct triple.
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
      failAsset(path, std::string(what) + " " + std::to_string(i / perItem + 1) + " has a coordinate that is not a finite float");
}

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
    failAsset(path, "not a readable OBJ file (tinyobjloader: " + oneLine(err) + ")");
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
  if (P == 0) failAsset(path, "no vertices (no 'v' lines): not an OBJ mesh");
  if (info.triangles == 0)
    failAsset(path, "no triangles (" + std::to_string(P) + " vertices but no faces, 'f' lines)");
  if (N == 0) failAsset(path, "no normals ('vn' lines); the scene needs a position, normal and uv per vertex");
  if (T == 0) failAsset(path, "no texture coordinates ('vt' lines); the scene needs a position, normal and uv per vertex");
  if (P > UINT32_MAX / 2) failAsset(path, "too many vertices (" + std::to_string(P) + ")");
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
      failAsset(path, "face " + std::to_string(face) + " has no " + what + " index (every corner must be v/vt/vn)");
    if (idx < 0)
      failAsset(path, "face " + std::to_string(face) + " uses a relative " + what + " index that points before the first " + what);
    if (size_t(idx) >= count)
      failAsset(path, "face " + std::to_string(face) + " uses " + what + " " + std::to_string(size_t(idx) + 1) +
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

}  // namespace scenes
