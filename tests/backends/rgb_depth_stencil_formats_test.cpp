// What llvmpipe does with three attachment formats a deferred G-buffer may ask for and this
// pipeline does not have: GL_RGB8 and GL_RGB16F colour, GL_DEPTH24_STENCIL8 depth-stencil
// (seed 004's table). A scene ported from such a table renders RGBA8, RGBA16F and Depth24
// in their place (raster/texture/texture.h has no RGB or stencil formats); these tests pin
// the facts that choice stands on, on llvmpipe itself, at an odd size:
//   - RGB8 and RGB16F are colour-renderable (the framebuffer is complete), and store RGBX:
//     the alpha a shader writes is dropped, alpha reads back 1 (255, 1.0f), and r, g, b
//     hold exactly the texels the RGBA format holds for the same draws. So RGBA written
//     with a constant alpha 1.0 holds the same texels (an interpolated 1 may not: below);
//     this pipeline's RGBA draws are checked against them too.
//   - DEPTH24_STENCIL8 at GL_DEPTH_STENCIL_ATTACHMENT stores the very depth codes
//     DEPTH_COMPONENT24 stores (read as depth, and as the top 24 bits of the packed
//     UNSIGNED_INT_24_8 word, whose stencil byte holds the cleared 0), equal to this
//     pipeline's Depth24 codes.
// The GL objects are made with raw GL calls (backends/gl_entry_points.h) in the context of a
// GlBackend, which has no RGB or depth-stencil formats of its own.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "backends/gl_entry_points.h"
#include "tests/gl_compare_helpers.h"

namespace {

using namespace gltest;

constexpr int kWidth = 37, kHeight = 23;
const glm::vec4 kClearColor(0.2f, 0.4f, 0.6f, 0.25f);

// Random triangles, overlapping at random depths, with colours whose alpha is `alpha`; the
// colours go past 1 and below 0 too (a float target keeps them, RGBA8 clamps).
MeshData coloredTriangles(unsigned seed, float alpha) {
  std::mt19937 rng(seed);
  std::vector<Vertex> vertices;
  for (int i = 0; i < 40; ++i) {
    const glm::vec2 c(uniform(rng, 0.0f, float(kWidth)), uniform(rng, 0.0f, float(kHeight)));
    for (int v = 0; v < 3; ++v) {
      const glm::vec2 p = c + glm::vec2(uniform(rng, -14.0f, 14.0f), uniform(rng, -14.0f, 14.0f));
      const glm::vec4 color(uniform(rng, -0.5f, 3.0f), uniform(rng, 0.0f, 1.0f), uniform(rng, 0.0f, 1.0f), alpha);
      vertices.push_back({clipFromWindow(p, uniform(rng, -0.95f, 0.95f), uniform(rng, 0.6f, 2.0f), kWidth, kHeight), color});
    }
  }
  return makeMesh(vertices);
}

struct RawFormat {
  GLint internal;
  GLenum format, type;
};

struct RawResult {
  GLenum status = 0;
  std::vector<uint8_t> bytes;     // RGBA, top row first
  std::vector<float> floats;      // RGBA, top row first
  std::vector<uint32_t> depth;    // 24-bit codes, top row first
  std::vector<uint32_t> packed;   // UNSIGNED_INT_24_8 words (depth-stencil attachments only)
};

template <class T>
void flipRows(std::vector<T>& v, size_t rowElements) {
  const size_t rows = v.size() / rowElements;
  for (size_t r = 0; r < rows / 2; ++r)
    std::swap_ranges(v.begin() + long(r * rowElements), v.begin() + long((r + 1) * rowElements),
                     v.begin() + long((rows - 1 - r) * rowElements));
}

// Draws `mesh` with test/passthrough, depth test LESS, into a kWidth x kHeight framebuffer
// of `color` and `depth` textures (depth attached at `depthAttachment`) made with raw GL in
// `gl`'s context, after a clear of colour, depth (1.0) and stencil (0); reads back.
RawResult drawRaw(Backend& gl, RawFormat color, RawFormat depth, GLenum depthAttachment, const MeshData& mesh) {
  const GLuint program = GLuint(gl.createProgram("test/passthrough"));
  const GLuint vao = GLuint(gl.createMesh(mesh));
  GLuint textures[2] = {0, 0};
  scenes::glGenTextures(2, textures);
  const RawFormat formats[2] = {color, depth};
  for (int i = 0; i < 2; ++i) {
    scenes::glBindTexture(GL_TEXTURE_2D, textures[i]);
    scenes::glTexImage2D(GL_TEXTURE_2D, 0, formats[i].internal, kWidth, kHeight, 0, formats[i].format, formats[i].type, nullptr);
    scenes::glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    scenes::glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  scenes::glBindTexture(GL_TEXTURE_2D, 0);
  GLuint fb = 0;
  scenes::glGenFramebuffers(1, &fb);
  scenes::glBindFramebuffer(GL_FRAMEBUFFER, fb);
  scenes::glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, textures[0], 0);
  scenes::glFramebufferTexture2D(GL_FRAMEBUFFER, depthAttachment, GL_TEXTURE_2D, textures[1], 0);
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  scenes::glDrawBuffers(1, &drawBuffer);
  scenes::glReadBuffer(GL_COLOR_ATTACHMENT0);
  RawResult r;
  r.status = scenes::glCheckFramebufferStatus(GL_FRAMEBUFFER);
  REQUIRE(scenes::glGetError() == GL_NO_ERROR);
  if (r.status != GL_FRAMEBUFFER_COMPLETE) return r;
  scenes::glViewport(0, 0, kWidth, kHeight);
  scenes::glClearColor(kClearColor.r, kClearColor.g, kClearColor.b, kClearColor.a);
  scenes::glClearDepth(1.0);
  scenes::glDepthMask(GL_TRUE);
  scenes::glEnable(GL_DEPTH_TEST);
  scenes::glDepthFunc(GL_LESS);
  scenes::glDisable(GL_BLEND);
  scenes::glDisable(GL_CULL_FACE);
  scenes::glDisable(GL_POLYGON_OFFSET_FILL);
  scenes::glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  scenes::glUseProgram(program);
  scenes::glBindVertexArray(vao);
  scenes::glDrawElements(GL_TRIANGLES, GLsizei(mesh.indices.size()), GL_UNSIGNED_INT, nullptr);
  scenes::glBindVertexArray(0);
  scenes::glFinish();
  const size_t texels = size_t(kWidth) * kHeight;
  r.bytes.resize(texels * 4);
  r.floats.resize(texels * 4);
  r.depth.resize(texels);
  scenes::glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, r.bytes.data());
  scenes::glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, r.floats.data());
  scenes::glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, r.depth.data());
  for (uint32_t& d : r.depth) d >>= 8;   // Mesa replicates bits: the top 24 are the code
  if (depthAttachment == GL_DEPTH_STENCIL_ATTACHMENT) {
    r.packed.resize(texels);
    scenes::glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, r.packed.data());
    flipRows(r.packed, kWidth);
  }
  REQUIRE(scenes::glGetError() == GL_NO_ERROR);
  flipRows(r.bytes, size_t(kWidth) * 4);
  flipRows(r.floats, size_t(kWidth) * 4);
  flipRows(r.depth, kWidth);
  scenes::glBindFramebuffer(GL_FRAMEBUFFER, 0);
  scenes::glDeleteFramebuffers(1, &fb);
  return r;
}

const RawFormat kRgba8{GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE}, kRgb8{GL_RGB8, GL_RGB, GL_UNSIGNED_BYTE};
const RawFormat kRgba16f{GL_RGBA16F, GL_RGBA, GL_FLOAT}, kRgb16f{GL_RGB16F, GL_RGB, GL_FLOAT};
const RawFormat kDepth24{GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT};
const RawFormat kDepth24Stencil8{GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};

// This pipeline's draw of the same triangles with alpha 1, into `color` + Depth24, cleared
// to kClearColor with alpha 1: what a scene renders in place of the RGB format.
Rendered drawOurs(Backend& raster, TexelFormat color, const MeshData& opaque) {
  ClearOp clear = clearAll();
  clear.colorValue = glm::vec4(glm::vec3(kClearColor), 1.0f);
  return render(raster, {kWidth, kHeight, color, TexelFormat::Depth24}, {{"test/passthrough", opaque, DrawState{}, {}}}, clear);
}

}  // namespace

TEST_SUITE("gl_backend") {
  TEST_CASE("RGB8 and RGB16F attachments on llvmpipe: complete, RGBX (alpha reads back 1), the RGBA format's r, g, b") {
    BackendPair backends;
    const MeshData translucent = coloredTriangles(601, 0.3f), opaque = coloredTriangles(601, 1.0f);
    const size_t texels = size_t(kWidth) * kHeight;

    const RawResult rgba8 = drawRaw(*backends.gl, kRgba8, kDepth24, GL_DEPTH_ATTACHMENT, translucent);
    const RawResult rgb8 = drawRaw(*backends.gl, kRgb8, kDepth24, GL_DEPTH_ATTACHMENT, translucent);
    REQUIRE(rgba8.status == GL_FRAMEBUFFER_COMPLETE);
    CHECK(rgb8.status == GL_FRAMEBUFFER_COMPLETE);
    if (rgb8.status == GL_FRAMEBUFFER_COMPLETE) {
      int alphaNot1 = 0, rgbDiffer = 0, rgbaAlpha = 0;
      for (size_t p = 0; p < texels; ++p) {
        alphaNot1 += rgb8.bytes[p * 4 + 3] != 255;
        rgbDiffer += std::memcmp(&rgb8.bytes[p * 4], &rgba8.bytes[p * 4], 3) != 0;
        rgbaAlpha += rgba8.bytes[p * 4 + 3] != 255;   // the RGBA target keeps the 0.3 / 0.25 written
      }
      MESSAGE("RGB8: " << alphaNot1 << " texels with alpha != 255, " << rgbDiffer << " whose r, g, b differ from RGBA8's");
      CHECK(alphaNot1 == 0);
      CHECK(rgbDiffer == 0);
      CHECK(rgbaAlpha == int(texels));   // so the alpha really was written, and dropped by RGB8
      const Rendered ours = drawOurs(*backends.raster, TexelFormat::RGBA8, opaque);
      CHECK(ours.color->rgba8 == rgb8.bytes);   // RGBA8 with alpha 1: RGB8's bytes, alpha included
    }

    const RawResult rgba16f = drawRaw(*backends.gl, kRgba16f, kDepth24, GL_DEPTH_ATTACHMENT, translucent);
    const RawResult rgb16f = drawRaw(*backends.gl, kRgb16f, kDepth24, GL_DEPTH_ATTACHMENT, translucent);
    REQUIRE(rgba16f.status == GL_FRAMEBUFFER_COMPLETE);
    // GL 3.3 does not require RGB16F to be colour-renderable; llvmpipe makes it so.
    CHECK(rgb16f.status == GL_FRAMEBUFFER_COMPLETE);
    if (rgb16f.status == GL_FRAMEBUFFER_COMPLETE) {
      int alphaNot1 = 0, rgbDiffer = 0;
      for (size_t p = 0; p < texels; ++p) {
        alphaNot1 += rgb16f.floats[p * 4 + 3] != 1.0f;
        for (int c = 0; c < 3; ++c) rgbDiffer += bitsOf(rgb16f.floats[p * 4 + size_t(c)]) != bitsOf(rgba16f.floats[p * 4 + size_t(c)]);
      }
      MESSAGE("RGB16F: " << alphaNot1 << " texels with alpha != 1, " << rgbDiffer << " channels differing from RGBA16F's");
      CHECK(alphaNot1 == 0);
      CHECK(rgbDiffer == 0);
      // This pipeline's RGBA16F: RGB16F's r, g, b. Its alpha is what the shader writes, and
      // here that is an interpolated 1: perspective leaves it at 0.99999994, which the
      // conversion to half truncates to 0.999512 (llvmpipe's RGBA16F does the same). An RGB
      // target reads exactly 1 there, so a scene in its place writes a constant 1.0.
      const Rendered ours = drawOurs(*backends.raster, TexelFormat::RGBA16F, opaque);
      int rgbOursDiffer = 0, alphaBelow1 = 0;
      for (size_t p = 0; p < texels; ++p) {
        for (int c = 0; c < 3; ++c) rgbOursDiffer += bitsOf(ours.color->floats[p * 4 + size_t(c)]) != bitsOf(rgb16f.floats[p * 4 + size_t(c)]);
        alphaBelow1 += ours.color->floats[p * 4 + 3] != 1.0f;
      }
      MESSAGE("RGBA16F here, alpha 1 interpolated: " << rgbOursDiffer << " r, g, b channels differ from RGB16F's; " << alphaBelow1
                                                     << " alphas read below 1");
      CHECK(rgbOursDiffer == 0);
      CHECK(alphaBelow1 > 0);   // why the constant matters
    }
  }

  TEST_CASE("DEPTH24_STENCIL8 on llvmpipe: complete, its depth codes DEPTH_COMPONENT24's, packed as code << 8 | stencil") {
    BackendPair backends;
    const MeshData mesh = coloredTriangles(602, 1.0f);
    const RawResult depth24 = drawRaw(*backends.gl, kRgba8, kDepth24, GL_DEPTH_ATTACHMENT, mesh);
    const RawResult packed = drawRaw(*backends.gl, kRgba8, kDepth24Stencil8, GL_DEPTH_STENCIL_ATTACHMENT, mesh);
    REQUIRE(depth24.status == GL_FRAMEBUFFER_COMPLETE);
    REQUIRE(packed.status == GL_FRAMEBUFFER_COMPLETE);
    CHECK(packed.depth == depth24.depth);
    CHECK(packed.bytes == depth24.bytes);   // the depth test decided the same
    int codeDiffers = 0, stencilNot0 = 0, cleared = 0;
    for (size_t p = 0; p < packed.packed.size(); ++p) {
      codeDiffers += (packed.packed[p] >> 8) != depth24.depth[p];
      stencilNot0 += (packed.packed[p] & 0xFFu) != 0;
      cleared += depth24.depth[p] == 0xFFFFFFu;
    }
    MESSAGE("DEPTH24_STENCIL8: " << codeDiffers << " packed words whose top 24 bits differ from DEPTH_COMPONENT24's code, "
                                 << stencilNot0 << " stencil bytes not 0; " << cleared << " texels hold the clear");
    CHECK(codeDiffers == 0);
    CHECK(stencilNot0 == 0);
    CHECK(cleared > 0);
    CHECK(cleared < int(packed.depth.size()));
    const Rendered ours = drawOurs(*backends.raster, TexelFormat::RGBA8, mesh);
    CHECK(ours.depth->depth == packed.depth);
  }
}
