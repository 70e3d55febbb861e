// The backend interface: what a scene may ask of a renderer.
//
// Each scene is written once against this interface; two implementations run it:
//   RasterBackend (backends/raster_backend.*): this project's pipeline;
//   GlBackend     (backends/gl_backend.*):     real OpenGL 3.3 core through OSMesa
//                                            (llvmpipe by default, softpipe via GALLIUM_DRIVER).
// The interface models only what the scenes use, with GL's meaning: programs are named
// pairs of GLSL files under shaders_cpp/ (the GL backend compiles them; the raster backend
// runs their C++ ports), meshes are indexed interleaved float buffers, render targets are
// framebuffers of textures, and state is passed per draw.
//
// Coordinates: every image read back is in GL orientation flipped to top-row-first
// (row 0 = the top of the picture), so both backends' images compare directly.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "io/memory_budget.h"
#include "raster/contract.h"
#include "raster/texture/texture.h"

namespace scenes {

using Handle = int;                    // 0 means "none" / the default framebuffer
constexpr Handle kDefaultFramebuffer = 0;

// ---- resources ------------------------------------------------------------------------
struct VertexAttribute {
  int location = 0;       // layout(location = N) in the vertex shader
  int components = 3;     // 1..4 floats
  int offsetFloats = 0;   // offset inside one vertex, in floats
};

struct MeshData {
  std::vector<float> vertices;           // interleaved, strideFloats per vertex
  int strideFloats = 0;
  std::vector<VertexAttribute> attributes;
  std::vector<uint32_t> indices;         // GL_TRIANGLES, GL_UNSIGNED_INT
  // Optional per-instance attributes (glVertexAttribDivisor 1), from a second buffer.
  std::vector<float> instances;
  int instanceStrideFloats = 0;
  std::vector<VertexAttribute> instanceAttributes;
};

// Formats, filters, wraps and compare modes are the pipeline's own vocabulary
// (raster/texture/texture.h), which both backends map to what they run.
using raster::Filter;
using raster::SamplerState;
using raster::TexelFormat;
using raster::Wrap;

struct TextureDesc {
  int width = 0;
  int height = 0;
  TexelFormat format = TexelFormat::RGBA8;
  SamplerState sampler;
};

// A framebuffer object: colour attachments (draw buffers 0..n-1, in order) and an
// optional depth attachment. No colour attachment means glDrawBuffer(GL_NONE).
struct FramebufferDesc {
  std::vector<Handle> colorTextures;
  Handle depthTexture = 0;
};

// ---- per-pass and per-draw state --------------------------------------------------------
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;   // GL window coordinates (y up)
};

struct ClearOp {
  bool color = false;
  glm::vec4 colorValue{0.0f};
  bool depth = false;
  float depthValue = 1.0f;
};

using raster::DepthFunc;
enum class CullMode { None, Back };

struct DrawState {
  bool depthTest = true;
  DepthFunc depthFunc = DepthFunc::Less;
  bool depthWrite = true;
  CullMode cull = CullMode::None;        // front faces are counter-clockwise
  bool polygonOffset = false;            // GL_POLYGON_OFFSET_FILL
  float offsetFactor = 0.0f;
  float offsetUnits = 0.0f;
  bool blendAdditive = false;            // glBlendFunc(GL_ONE, GL_ONE)
};

using UniformValue = std::variant<float, int, glm::vec2, glm::vec3, glm::vec4, glm::mat4>;

// ---- read-back ----------------------------------------------------------------------------
// An image read back from a backend, top row first. Exactly one of the payloads is used:
//   rgba8:   width*height*4 bytes (RGBA8 targets)
//   floats:  width*height*channels floats (RGBA16F / RGBA32F targets as exact float values)
//   depth:   width*height integer depth codes (0 .. 2^bits - 1) of a depth attachment
struct ImageData {
  int width = 0;
  int height = 0;
  int channels = 4;
  TexelFormat format = TexelFormat::RGBA8;
  std::vector<uint8_t> rgba8;
  std::vector<float> floats;
  std::vector<uint32_t> depth;
  int depthBits = 0;
  memory::Reservation reserved;   // the payload's share of --max-memory (io/memory_budget.h)
};

// ---- the interface --------------------------------------------------------------------------
class Backend {
 public:
  virtual ~Backend() = default;

  // Short name for reports: "raster", "llvmpipe", "softpipe".
  virtual std::string name() const = 0;

  // The default framebuffer (handle 0): RGBA8 colour + 24-bit depth, width x height.
  virtual void resizeDefaultFramebuffer(int width, int height) = 0;

  // `program` names shaders_cpp/<program>.vert and .frag, e.g. "shadow/main"; a vertex
  // shader shared by several programs is named with '+': "deferred/post+ssao" is
  // shaders_cpp/deferred/post.vert with shaders_cpp/deferred/ssao.frag.
  virtual Handle createProgram(const std::string& program) = 0;
  virtual Handle createMesh(const MeshData& mesh) = 0;
  // Pixels (top row last, as glTexImage2D takes them) may be empty: uninitialised storage.
  // RGBA8 takes 4 bytes a texel; RGBA16F 4 floats and RGB16F 3 floats a texel (rounded to
  // half, to nearest even, on upload); RGBA32F 4 floats.
  virtual Handle createTexture(const TextureDesc& desc, const void* pixels = nullptr) = 0;
  virtual Handle createFramebuffer(const FramebufferDesc& desc) = 0;

  // Names that debugging tools show, as glObjectLabel names a texture and a debug group
  // (glPushDebugGroup) a pass: `raster trace` names targets and passes by them. A scene
  // labels each texture and pass with the name of the target it reads back from it
  // (readTargets). The GL backend ignores them: nothing here reads GL's labels.
  virtual void labelTexture(Handle texture, const std::string& label) {}
  virtual void labelNextPass(const std::string& label) {}

  // glBindFramebuffer + glViewport + glClear.
  virtual void beginPass(Handle framebuffer, const Viewport& viewport, const ClearOp& clear) = 0;
  virtual void setUniform(Handle program, const std::string& name, const UniformValue& value) = 0;
  // Binds a texture to a texture unit (the sampler uniform's value).
  virtual void bindTexture(int unit, Handle texture) = 0;
  // glDrawElements(GL_TRIANGLES, indexCount) of the whole mesh, instanceCount instances.
  virtual void draw(Handle program, Handle mesh, const DrawState& state, int instanceCount = 1) = 0;
  // Everything submitted so far is complete when this returns (glFinish).
  virtual void finish() = 0;

  // Read back a framebuffer's colour attachment (framebuffer 0: the default one).
  virtual ImageData readColor(Handle framebuffer, int attachment = 0) = 0;
  // Read back a framebuffer's depth buffer as integer codes.
  virtual ImageData readDepth(Handle framebuffer) = 0;

  // Named counters of the work done since the last reset (the raster backend's pipeline
  // counters, and per-stage cycles once resetStatistics(true) asked for them; empty for GL,
  // which does not expose them).
  virtual std::vector<std::pair<std::string, double>> statistics() const { return {}; }
  virtual void resetStatistics(bool timeStages = false) {}
};

// Where the GLSL sources live: $RASTER_SOURCE_DIR/shaders_cpp, else the build's source dir.
std::string shaderSourceDir();

// The two GLSL files of a program name (see Backend::createProgram).
struct ProgramFiles {
  std::string vertex;
  std::string fragment;
};
ProgramFiles programFiles(const std::string& program);

}  // namespace scenes
