// Triangle soups: random draws that push coverage, clipping and depth to their edges, for
// `raster soup` (apps/soup/soup.h), which renders each with this pipeline and with llvmpipe and
// compares coverage and depth exactly.
//
// A soup is plain data in clip space, so a reproducer file can hold it bit for bit:
//   triangles     drawn in one pass (depth test LESS, Z24), each in a flat colour that
//                 encodes its ID (index + 1, see idColor); those with a NaN or infinite
//                 coordinate are drawn in a pass of their own instead, reported and not
//                 compared (GL leaves them undefined);
//   closed meshes fans around a centre and strips tiling a rectangle, each drawn alone with
//                 additive blending of 1/255 per fragment: every pixel whose centre lies
//                 inside the mesh's outline must be hit exactly once (no crack, no double
//                 hit), every pixel outside not at all.
//
// The generator is deterministic per seed on every machine: std::mt19937_64 (its output is
// fixed by the standard), distributions written out here rather than std's (which differ
// between libraries), and only + - * / and powers of two on the way to a coordinate: no libm
// function whose last bit could differ.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace scenes::soup {

// What a triangle was generated to exercise; its name goes into reports and reproducers.
enum class Kind {
  General,       // on screen, random size and perspective w
  Tiny,          // sub-pixel, down to 1/1024 of a pixel
  Sliver,        // two vertices nearly coincident, or three nearly collinear
  PixelGrid,     // vertices exactly on pixel centres and pixel edges
  FarOut,        // vertices far outside the viewport (2^10 .. 2^24 pixels): clipped
  Huge,          // clip coordinates up to 1e30 (the same picture scaled, or one vertex far)
  NearZeroW,     // a vertex with w within 2^-126 .. 2^-10 of zero, either sign
  NegativeW,     // one, two or three vertices behind the eye (w < 0)
  DepthPlanes,   // z across the near or far plane (z beyond +-w)
  Degenerate,    // zero area: a repeated vertex, all three the same, or collinear
  NonFinite,     // a NaN, +inf or -inf coordinate (undefined in GL: drawn apart)
};
const char* kindName(Kind kind);
// Throws std::invalid_argument for a name that is not a kind.
Kind kindFromName(const std::string& name);

struct Triangle {
  Kind kind = Kind::General;
  glm::vec4 clip[3];   // clip-space positions (x, y, z, w), drawn in this order
};

enum class MeshKind { Fan, Strip };
const char* meshKindName(MeshKind kind);
MeshKind meshKindFromName(const std::string& name);

// A closed mesh: triangles sharing vertices by index, tiling a convex outline without
// overlap. `outline` lists vertex indices of the outline in order (counter-clockwise in
// window coordinates); every vertex has w > 0 and |z| < w, so no part of it is clipped
// away in depth and its picture is exactly the outline's inside.
struct ClosedMesh {
  MeshKind kind = MeshKind::Fan;
  std::string note;                 // what variant it is, for reports ("off screen", ...)
  std::vector<glm::vec4> clip;      // clip-space positions
  std::vector<uint32_t> indices;    // triangles
  std::vector<uint32_t> outline;
};

struct Soup {
  uint64_t seed = 0;
  int width = 0, height = 0;
  std::vector<Triangle> triangles;
  std::vector<ClosedMesh> meshes;
};

// The soup of a seed for a width x height viewport with `triangles` triangles (>= 0) and a
// few closed meshes. The same arguments give the same bits everywhere.
Soup generate(uint64_t seed, int width, int height, int triangles);

// True when any coordinate of the triangle is NaN or infinite.
bool nonFinite(const Triangle& triangle);

// The RGBA8 bytes of triangle ID `id` (1 .. 2^24 - 1): R, G, B are its low, middle and high
// bytes, alpha 255. 0 is the clear colour, so "no triangle". As floats, byte / 255, which
// the unorm8 conversion of both pipelines rounds back to the byte.
glm::vec4 idColor(uint32_t id);
constexpr uint32_t kMaxTriangles = (1u << 24) - 2;

}  // namespace scenes::soup
