// Rendering and comparing soups (soup_check.h).
#include "scenes/soup/soup_check.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "shaders_cpp/test/passthrough.h"

namespace scenes::soup {
namespace {

constexpr int kMaxDescribed = 8;   // differing pixels named in a verdict

// One passthrough vertex: clip position, then the colour.
void appendVertex(std::vector<float>& out, const glm::vec4& clip, const glm::vec4& color) {
  for (int c = 0; c < 4; ++c) out.push_back(clip[c]);
  for (int c = 0; c < 4; ++c) out.push_back(color[c]);
}

MeshData passthroughMesh(std::vector<float> vertices, std::vector<uint32_t> indices) {
  MeshData mesh;
  mesh.strideFloats = 8;
  mesh.attributes = {{0, 4, 0}, {1, 4, 4}};
  mesh.vertices = std::move(vertices);
  mesh.indices = std::move(indices);
  return mesh;
}

std::vector<uint32_t> sequence(size_t count) {
  std::vector<uint32_t> indices(count);
  for (size_t i = 0; i < count; ++i) indices[i] = uint32_t(i);
  return indices;
}

ClearOp clearAll() {
  ClearOp clear;
  clear.color = true;
  clear.colorValue = glm::vec4(0.0f);
  clear.depth = true;
  clear.depthValue = 1.0f;
  return clear;
}

std::string where(int x, int row) {
  return "pixel (x " + std::to_string(x) + ", row " + std::to_string(row) + " from the top)";
}

std::string hex24(uint32_t code) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%06x", code);
  return text;
}

void note(Verdict& verdict, const std::string& line) {
  if (int(verdict.firstDiffs.size()) < kMaxDescribed) verdict.firstDiffs.push_back(line);
}

}  // namespace

SoupRenderer::SoupRenderer(Backend& backend, int width, int height)
    : backend_(backend), width_(width), height_(height) {
  FramebufferDesc fb;
  fb.colorTextures = {backend.createTexture({width, height, TexelFormat::RGBA8, {}})};
  fb.depthTexture = backend.createTexture({width, height, TexelFormat::Depth24, {}});
  framebuffer_ = backend.createFramebuffer(fb);
  program_ = backend.createProgram("test/passthrough");
}

void SoupRenderer::pass(const std::vector<float>& vertices, const DrawState& state) {
  backend_.beginPass(framebuffer_, {0, 0, width_, height_}, clearAll());
  if (!vertices.empty()) {
    const Handle mesh = backend_.createMesh(passthroughMesh(vertices, sequence(vertices.size() / 8)));
    backend_.draw(program_, mesh, state);
  }
  backend_.finish();
}

Rendering SoupRenderer::render(const Soup& soup) {
  if (soup.width != width_ || soup.height != height_) throw std::logic_error("soup size differs from the renderer's");
  Rendering r;
  r.backend = backend_.name();

  std::vector<float> finite, nonFiniteVertices;
  for (size_t i = 0; i < soup.triangles.size(); ++i) {
    const Triangle& t = soup.triangles[i];
    std::vector<float>& out = nonFinite(t) ? nonFiniteVertices : finite;
    for (const glm::vec4& v : t.clip) appendVertex(out, v, idColor(uint32_t(i + 1)));
  }

  pass(finite, DrawState{});
  r.color = backend_.readColor(framebuffer_);
  r.depth = backend_.readDepth(framebuffer_);

  if (!nonFiniteVertices.empty()) {
    pass(nonFiniteVertices, DrawState{});
    const ImageData image = backend_.readColor(framebuffer_);
    for (size_t p = 0; p < image.rgba8.size(); p += 4)
      r.nonFiniteCovered += (image.rgba8[p] | image.rgba8[p + 1] | image.rgba8[p + 2] | image.rgba8[p + 3]) != 0;
  }

  DrawState counting;
  counting.depthTest = false;
  counting.depthWrite = false;
  counting.blendAdditive = true;
  for (const ClosedMesh& m : soup.meshes) {
    std::vector<float> vertices;
    for (const glm::vec4& v : m.clip) appendVertex(vertices, v, glm::vec4(1.0f / 255.0f, 0.0f, 0.0f, 0.0f));
    backend_.beginPass(framebuffer_, {0, 0, width_, height_}, clearAll());
    if (!m.indices.empty()) backend_.draw(program_, backend_.createMesh(passthroughMesh(vertices, m.indices)), counting);
    backend_.finish();
    r.counts.push_back(backend_.readColor(framebuffer_));
  }
  return r;
}

MeshCheck checkWatertight(const ClosedMesh& mesh, const ImageData& counts, int width, int height) {
  // The outline in window coordinates (GL, y up), as the viewport transform places it.
  std::vector<glm::dvec2> outline;
  double extent = std::max(width, height);
  for (uint32_t index : mesh.outline) {
    const glm::dvec4 v(mesh.clip.at(index));
    const glm::dvec2 p((v.x / v.w + 1.0) * 0.5 * width, (v.y / v.w + 1.0) * 0.5 * height);
    outline.push_back(p);
    extent = std::max({extent, std::fabs(p.x), std::fabs(p.y)});
  }
  double area = 0.0;
  for (size_t i = 0; i < outline.size(); ++i) {
    const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
    area += a.x * b.y - a.y * b.x;
  }
  const double orientation = area < 0.0 ? -1.0 : 1.0;
  // Snapping moves a vertex by up to 1/512 of a pixel and float window coordinates by a few
  // ulps of their size; past this margin a pixel centre is inside or outside for sure.
  const double margin = 1.0 / 32.0 + std::ldexp(extent, -19);

  MeshCheck check;
  for (int row = 0; row < height; ++row) {
    for (int x = 0; x < width; ++x) {
      const glm::dvec2 centre(x + 0.5, height - 1 - row + 0.5);
      bool inside = outline.size() >= 3 && area != 0.0, outside = false;
      for (size_t i = 0; i < outline.size(); ++i) {
        const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        const glm::dvec2 edge = b - a;
        const double length = std::sqrt(edge.x * edge.x + edge.y * edge.y);
        if (length == 0.0) continue;
        const double distance = orientation * (edge.x * (centre.y - a.y) - edge.y * (centre.x - a.x)) / length;
        if (distance <= margin) inside = false;
        if (distance < -margin) outside = true;
      }
      const size_t at = (size_t(row) * size_t(width) + size_t(x)) * 4;
      const int count = counts.rgba8.at(at);
      auto fail = [&](int& counter, const char* what) {
        if (counter++ == 0 && check.first.empty())
          check.first = where(x, row) + ": " + what + " (counted " + std::to_string(count) + ")";
      };
      if (inside) ++check.inside;
      if (count >= 2) fail(check.doubleHits, "hit more than once");
      else if (inside && count == 0) fail(check.cracks, "inside the outline, never hit");
      else if (outside && count > 0) fail(check.strays, "outside the outline, hit");
    }
  }
  return check;
}

bool Verdict::oursWatertight() const {
  return std::all_of(ours.begin(), ours.end(), [](const MeshCheck& m) { return m.watertight(); });
}
bool Verdict::referenceWatertight() const {
  return std::all_of(reference.begin(), reference.end(), [](const MeshCheck& m) { return m.watertight(); });
}

std::string describeId(const Soup& soup, const uint8_t rgba[4]) {
  const uint32_t id = uint32_t(rgba[0]) | uint32_t(rgba[1]) << 8 | uint32_t(rgba[2]) << 16;
  if (id == 0 && rgba[3] == 0) return "nothing";
  if (rgba[3] == 255 && id >= 1 && id <= soup.triangles.size())
    return "triangle " + std::to_string(id - 1) + " (" + kindName(soup.triangles[id - 1].kind) + ")";
  return "colour " + std::to_string(rgba[0]) + "," + std::to_string(rgba[1]) + "," + std::to_string(rgba[2]) + "," +
         std::to_string(rgba[3]) + " (no triangle's ID)";
}

Verdict compare(const Soup& soup, const Rendering& ours, const Rendering& reference) {
  const int width = soup.width, height = soup.height;
  const size_t pixels = size_t(width) * size_t(height);
  auto sized = [&](const ImageData& image, size_t perPixel, size_t have) {
    if (image.width != width || image.height != height || have != pixels * perPixel)
      throw std::runtime_error("soup: a read-back image has the wrong size");
  };
  sized(ours.color, 4, ours.color.rgba8.size());
  sized(reference.color, 4, reference.color.rgba8.size());
  sized(ours.depth, 1, ours.depth.depth.size());
  sized(reference.depth, 1, reference.depth.depth.size());
  if (ours.counts.size() != soup.meshes.size() || reference.counts.size() != soup.meshes.size())
    throw std::runtime_error("soup: a closed mesh was not rendered");

  Verdict v;
  for (const Triangle& t : soup.triangles) (nonFinite(t) ? v.nonFiniteTriangles : v.finiteTriangles)++;
  v.nonFiniteCoveredOurs = ours.nonFiniteCovered;
  v.nonFiniteCoveredReference = reference.nonFiniteCovered;

  for (int row = 0; row < height; ++row) {
    for (int x = 0; x < width; ++x) {
      const size_t p = size_t(row) * size_t(width) + size_t(x);
      const uint8_t* a = &ours.color.rgba8[p * 4];
      const uint8_t* b = &reference.color.rgba8[p * 4];
      v.covered += (b[0] | b[1] | b[2] | b[3]) != 0;
      const bool colorDiffers = std::memcmp(a, b, 4) != 0;
      const bool depthDiffers = ours.depth.depth[p] != reference.depth.depth[p];
      v.colorDiffs += colorDiffers;
      v.depthDiffs += depthDiffers;
      if (colorDiffers || depthDiffers)
        note(v, "main pass " + where(x, row) + ": ours " + describeId(soup, a) + " depth " + hex24(ours.depth.depth[p]) +
                    ", " + reference.backend + " " + describeId(soup, b) + " depth " + hex24(reference.depth.depth[p]));
    }
  }

  for (size_t m = 0; m < soup.meshes.size(); ++m) {
    const ImageData& a = ours.counts[m];
    const ImageData& b = reference.counts[m];
    sized(a, 4, a.rgba8.size());
    sized(b, 4, b.rgba8.size());
    for (size_t p = 0; p < pixels; ++p) {
      v.countedPixels += b.rgba8[p * 4] != 0;
      if (std::memcmp(&a.rgba8[p * 4], &b.rgba8[p * 4], 4) != 0) {
        ++v.countDiffs;
        note(v, "closed mesh " + std::to_string(m) + " (" + meshKindName(soup.meshes[m].kind) + ", " +
                    soup.meshes[m].note + ") " + where(int(p % size_t(width)), int(p / size_t(width))) +
                    ": ours counted " + std::to_string(a.rgba8[p * 4]) + ", " + reference.backend + " " +
                    std::to_string(b.rgba8[p * 4]));
      }
    }
    v.ours.push_back(checkWatertight(soup.meshes[m], a, width, height));
    v.reference.push_back(checkWatertight(soup.meshes[m], b, width, height));
  }
  return v;
}

Soup shiftedOnePixel(const Soup& soup) {
  Soup shifted = soup;
  for (Triangle& t : shifted.triangles) {
    if (nonFinite(t)) continue;
    for (glm::vec4& v : t.clip) v.x += 2.0f / float(soup.width) * v.w;
  }
  return shifted;
}

std::vector<ProgramEntry> programs() { return {programEntry<shaders::test::Passthrough>()}; }

}  // namespace scenes::soup
