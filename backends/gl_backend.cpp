// GlBackend: the Backend interface (backends/backend.h) on real OpenGL 3.3 core through
// OSMesa, i.e. Mesa's Gallium software drivers (llvmpipe, or softpipe via GALLIUM_DRIVER).
//
// It is the reference the raster backend is compared against, so every call is the plain
// GL call the tutorial makes (OpenGL 3.3 core specification; Mesa's OSMesa API in
// GL/osmesa.h). Handles are the GL object names themselves.
//
// One GlBackend may exist at a time in a process (a second one throws): OSMesa has one
// current context per thread, and this backend makes its context current only when it is
// created or resized, never before each call. Backends may be created one after another. Mesa reads GALLIUM_DRIVER and LP_NUM_THREADS when the
// first context of the process is created.
#include "backends/gl_entry_points.h"   // GL and OSMesa, loaded when the first backend is made

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "backends/backends.h"
#include "io/memory_budget.h"
#include "scenes/registry.h"
#include "scenes/scene.h"

namespace scenes {
namespace {

// Throws if the GL error flag is set after `call`. (Each gl* name here is a pointer into
// libOSMesa, gl_entry_points.h; libOSMesa exports every GL 3.3 core entry point, so no
// GetProcAddress is needed.)
void checkGl(const char* call) {
  GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  std::ostringstream message;
  message << "GL backend: " << call << " failed with GL error 0x" << std::hex << error;
  throw std::runtime_error(message.str());
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("GL backend: cannot read shader file " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Reverses the row order of a width x rows image with `rowElements` values a row:
// glReadPixels returns the bottom row first, the interface wants the top row first.
template <typename T>
void flipRows(std::vector<T>& pixels, size_t rowElements) {
  size_t rows = rowElements == 0 ? 0 : pixels.size() / rowElements;
  for (size_t top = 0; top < rows / 2; ++top)
    std::swap_ranges(pixels.begin() + top * rowElements, pixels.begin() + (top + 1) * rowElements,
                     pixels.begin() + (rows - 1 - top) * rowElements);
}

int liveBackends = 0;  // enforces one GlBackend at a time
int backendsMade = 0;  // glBackendsMade()

class GlBackend : public Backend {
 public:
  GlBackend() {
    if (liveBackends > 0)
      throw std::runtime_error("GL backend: only one GlBackend may exist at a time");
    checkGalliumEnvironment();
    loadGlEntryPoints();
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 24,
                              OSMESA_STENCIL_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr)
      throw std::runtime_error(
          "GL backend: OSMesaCreateContextAttribs failed (no OpenGL 3.3 core context; "
          "check GALLIUM_DRIVER is llvmpipe or softpipe)");
    ++liveBackends;
    ++backendsMade;
    // The smallest window until the scene sizes it: a memory cap (--max-memory) is then met
    // or missed at the size asked for, not at a default nobody asked for.
    resizeDefaultFramebuffer(1, 1);

    // The driver name is the first word of GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    name_ = renderer != nullptr ? renderer : "unknown";
    for (const char* driver : {"llvmpipe", "softpipe"})
      if (name_.find(driver) != std::string::npos) name_ = driver;
  }

  ~GlBackend() override {
    memory::release(reserved_);
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
    --liveBackends;
  }

  std::string name() const override { return name_; }

  void resizeDefaultFramebuffer(int width, int height) override {
    // Our RGBA8 buffer, Mesa's own colour buffer and its 24-bit depth buffer: 12 bytes a pixel.
    const uint64_t bytes = uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0)) * 12;
    reserve(bytes, memory::joined({"the ", std::to_string(width), "x", std::to_string(height), " window in GL"}));
    memory::release(windowBytes_);
    reserved_ -= std::min(reserved_, windowBytes_);
    windowBytes_ = bytes;
    // The old buffer stays alive until the context is bound to the new one (Mesa may
    // flush pending rendering into the old buffer while switching).
    std::vector<uint8_t> buffer(size_t(width) * size_t(height) * 4, 0);
    if (!OSMesaMakeCurrent(context_, buffer.data(), GL_UNSIGNED_BYTE, width, height))
      throw std::runtime_error("GL backend: OSMesaMakeCurrent failed for " +
                               std::to_string(width) + "x" + std::to_string(height));
    colorBuffer_ = std::move(buffer);
    width_ = width;
    height_ = height;
  }

  Handle createProgram(const std::string& program) override {
    const ProgramFiles files = programFiles(program);
    GLuint vertex = compileShader(GL_VERTEX_SHADER, files.vertex);
    GLuint fragment = compileShader(GL_FRAGMENT_SHADER, files.fragment);
    GLuint id = glCreateProgram();
    glAttachShader(id, vertex);
    glAttachShader(id, fragment);
    glLinkProgram(id);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint linked = GL_FALSE;
    glGetProgramiv(id, GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
      std::string log = infoLog(id, glGetProgramiv, glGetProgramInfoLog);
      glDeleteProgram(id);
      throw std::runtime_error("GL backend: linking " + files.vertex + " and " + files.fragment + " failed:\n" + log);
    }
    checkGl("createProgram");
    checkPortUniforms(program, files, id);
    return Handle(id);
  }

  Handle createMesh(const MeshData& mesh) override {
    // The VAO records the attribute layout and the element buffer binding.
    Mesh m;
    m.indexCount = GLsizei(mesh.indices.size());
    glGenVertexArrays(1, &m.vao);
    glBindVertexArray(m.vao);
    glGenBuffers(1, &m.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(float)),
                 mesh.vertices.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &m.ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    for (const VertexAttribute& a : mesh.attributes) {
      glEnableVertexAttribArray(GLuint(a.location));
      glVertexAttribPointer(GLuint(a.location), a.components, GL_FLOAT, GL_FALSE,
                            GLsizei(mesh.strideFloats * sizeof(float)),
                            reinterpret_cast<const void*>(size_t(a.offsetFloats) * sizeof(float)));
    }
    // Per-instance attributes: a second buffer, advanced once per instance.
    if (!mesh.instances.empty()) {
      glGenBuffers(1, &m.instanceVbo);
      glBindBuffer(GL_ARRAY_BUFFER, m.instanceVbo);
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.instances.size() * sizeof(float)), mesh.instances.data(),
                   GL_STATIC_DRAW);
      for (const VertexAttribute& a : mesh.instanceAttributes) {
        glEnableVertexAttribArray(GLuint(a.location));
        glVertexAttribPointer(GLuint(a.location), a.components, GL_FLOAT, GL_FALSE,
                              GLsizei(mesh.instanceStrideFloats * sizeof(float)),
                              reinterpret_cast<const void*>(size_t(a.offsetFloats) * sizeof(float)));
        glVertexAttribDivisor(GLuint(a.location), 1);
      }
    }
    glBindVertexArray(0);
    checkGl("createMesh");
    meshes_[Handle(m.vao)] = m;
    return Handle(m.vao);
  }

  Handle createTexture(const TextureDesc& desc, const void* pixels) override {
    // llvmpipe stores the texture (RGB16F padded like RGBA16F, Z16 in 2 bytes at most: counted as raster does).
    reserve(raster::textureStorageBytes(desc.width, desc.height, desc.format),
            memory::joined({"a ", std::to_string(desc.width), "x", std::to_string(desc.height), " texture in GL"}));
    // Upload formats per TexelFormat: {internal format, format, type}.
    GLint internal = GL_RGBA8;
    GLenum format = GL_RGBA, type = GL_UNSIGNED_BYTE;
    switch (desc.format) {
      case TexelFormat::Depth24: internal = GL_DEPTH_COMPONENT24; format = GL_DEPTH_COMPONENT; type = GL_UNSIGNED_INT; break;
      case TexelFormat::Depth16: internal = GL_DEPTH_COMPONENT16; format = GL_DEPTH_COMPONENT; type = GL_UNSIGNED_INT; break;
      case TexelFormat::RGBA8: break;
      case TexelFormat::RGBA16F: internal = GL_RGBA16F; type = GL_FLOAT; break;
      case TexelFormat::RGB16F: internal = GL_RGB16F; format = GL_RGB; type = GL_FLOAT; break;
      case TexelFormat::RGBA32F: internal = GL_RGBA32F; type = GL_FLOAT; break;
    }
    // Create through the active unit, leaving its binding as it was.
    GLint previous = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glTexImage2D(GL_TEXTURE_2D, 0, internal, desc.width, desc.height, 0, format, type, pixels);
    checkGl("glTexImage2D");

    // Sampler state: one filter for min and mag (no mipmaps), wrap, optional depth compare.
    const SamplerState& s = desc.sampler;
    GLint filter = s.filter == Filter::Linear ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, s.wrapS == Wrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, s.wrapT == Wrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    if (s.compareLequal) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }
    glBindTexture(GL_TEXTURE_2D, GLuint(previous));
    checkGl("createTexture");
    textures_[Handle(id)] = desc;
    return Handle(id);
  }

  Handle createFramebuffer(const FramebufferDesc& desc) override {
    // Built bound to both draw and read (glReadBuffer applies to the read binding);
    // the previous bindings are restored after.
    GLint previousDraw = 0, previousRead = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousDraw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    glBindFramebuffer(GL_FRAMEBUFFER, id);
    std::vector<GLenum> drawBuffers;
    for (size_t i = 0; i < desc.colorTextures.size(); ++i) {
      drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
      glFramebufferTexture2D(GL_FRAMEBUFFER, drawBuffers.back(), GL_TEXTURE_2D,
                             GLuint(desc.colorTextures[i]), 0);
    }
    if (desc.depthTexture != 0)
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                             GLuint(desc.depthTexture), 0);
    if (drawBuffers.empty()) {
      glDrawBuffer(GL_NONE);
      glReadBuffer(GL_NONE);
    } else {
      glDrawBuffers(GLsizei(drawBuffers.size()), drawBuffers.data());
    }
    checkGl("createFramebuffer");
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previousDraw));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previousRead));
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      glDeleteFramebuffers(1, &id);
      std::ostringstream message;
      message << "GL backend: framebuffer incomplete, status 0x" << std::hex << status;
      throw std::runtime_error(message.str());
    }
    framebuffers_[Handle(id)] = desc;
    return Handle(id);
  }

  void beginPass(Handle framebuffer, const Viewport& viewport, const ClearOp& clear) override {
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer));
    glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
    GLbitfield mask = 0;
    if (clear.color) {
      glClearColor(clear.colorValue.r, clear.colorValue.g, clear.colorValue.b, clear.colorValue.a);
      mask |= GL_COLOR_BUFFER_BIT;
    }
    if (clear.depth) {
      glDepthMask(GL_TRUE);  // glClear honours the depth write mask
      glClearDepth(clear.depthValue);
      mask |= GL_DEPTH_BUFFER_BIT;
    }
    if (mask != 0) glClear(mask);
    checkGl("beginPass");
  }

  void setUniform(Handle program, const std::string& name, const UniformValue& value) override {
    // Names that are not active uniforms (location -1) are ignored, as GL does.
    auto key = std::make_pair(program, name);
    auto found = uniformLocations_.find(key);
    if (found == uniformLocations_.end())
      found = uniformLocations_.emplace(key, glGetUniformLocation(GLuint(program), name.c_str())).first;
    GLint location = found->second;
    glUseProgram(GLuint(program));
    std::visit([location](const auto& v) {
      using T = std::decay_t<decltype(v)>;
      if constexpr (std::is_same_v<T, float>) glUniform1f(location, v);
      else if constexpr (std::is_same_v<T, int>) glUniform1i(location, v);
      else if constexpr (std::is_same_v<T, glm::vec2>) glUniform2fv(location, 1, glm::value_ptr(v));
      else if constexpr (std::is_same_v<T, glm::vec3>) glUniform3fv(location, 1, glm::value_ptr(v));
      else if constexpr (std::is_same_v<T, glm::vec4>) glUniform4fv(location, 1, glm::value_ptr(v));
      else glUniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(v));
    }, value);
    // A type that does not match the GLSL declaration is a scene bug: report it.
    checkGl(("glUniform for uniform '" + name + "'").c_str());
  }

  void bindTexture(int unit, Handle texture) override {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, GLuint(texture));
    checkGl("bindTexture");
  }

  void draw(Handle program, Handle mesh, const DrawState& state, int instanceCount) override {
    auto found = meshes_.find(mesh);
    if (found == meshes_.end()) throw std::runtime_error("GL backend: draw of an unknown mesh");
    glUseProgram(GLuint(program));
    glBindVertexArray(found->second.vao);

    // Fixed-function state, all of it set on every draw.
    enable(GL_DEPTH_TEST, state.depthTest);
    glDepthFunc(state.depthFunc == DepthFunc::Less ? GL_LESS : GL_LEQUAL);
    glDepthMask(state.depthWrite ? GL_TRUE : GL_FALSE);
    enable(GL_CULL_FACE, state.cull == CullMode::Back);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    enable(GL_POLYGON_OFFSET_FILL, state.polygonOffset);
    glPolygonOffset(state.offsetFactor, state.offsetUnits);
    enable(GL_BLEND, state.blendAdditive);
    glBlendFunc(GL_ONE, GL_ONE);

    GLsizei count = found->second.indexCount;
    if (instanceCount == 1)
      glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
    else
      glDrawElementsInstanced(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr, instanceCount);
    checkGl("draw");
  }

  void finish() override { glFinish(); }

  ImageData readColor(Handle framebuffer, int attachment) override {
    // The default framebuffer is RGBA8; an FBO attachment has its texture's format.
    ImageData image;
    image.format = TexelFormat::RGBA8;
    image.width = width_;
    image.height = height_;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(framebuffer));
    if (framebuffer != kDefaultFramebuffer) {
      const FramebufferDesc& fb = framebufferDesc(framebuffer);
      if (attachment < 0 || size_t(attachment) >= fb.colorTextures.size())
        throw std::runtime_error("GL backend: readColor of a missing colour attachment");
      const TextureDesc& tex = textures_.at(fb.colorTextures[size_t(attachment)]);
      image.format = tex.format;
      image.width = tex.width;
      image.height = tex.height;
      glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + attachment));
    }
    size_t rowElements = size_t(image.width) * 4;
    const bool floats = image.format == TexelFormat::RGBA16F || image.format == TexelFormat::RGBA32F;
    image.reserved = memory::Reservation(uint64_t(image.width) * uint64_t(image.height) * (floats ? 16 : 4),
                                         memory::joined({"reading back a ", std::to_string(image.width), "x",
                                                         std::to_string(image.height), " target from GL"}));
    if (floats) {
      image.floats.resize(rowElements * size_t(image.height));
      glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, image.floats.data());
      flipRows(image.floats, rowElements);
    } else {
      image.rgba8.resize(rowElements * size_t(image.height));
      glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba8.data());
      flipRows(image.rgba8, rowElements);
    }
    checkGl("readColor");
    return image;
  }

  ImageData readDepth(Handle framebuffer) override {
    ImageData image;
    image.format = TexelFormat::Depth24;
    image.width = width_;
    image.height = height_;
    if (framebuffer != kDefaultFramebuffer) {
      Handle depth = framebufferDesc(framebuffer).depthTexture;
      if (depth == 0) throw std::runtime_error("GL backend: readDepth of a framebuffer without depth");
      const TextureDesc& tex = textures_.at(depth);
      image.format = tex.format;
      image.width = tex.width;
      image.height = tex.height;
    }
    image.depthBits = image.format == TexelFormat::Depth16 ? 16 : 24;
    image.channels = 1;

    // Mesa packs an n-bit depth code d into GL_UNSIGNED_INT by bit replication
    // (d << (32 - n) | d >> (2n - 32)), so the top n bits are exactly the code.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(framebuffer));
    image.reserved = memory::Reservation(uint64_t(image.width) * uint64_t(image.height) * 4,
                                         memory::joined({"reading back a ", std::to_string(image.width), "x",
                                                         std::to_string(image.height), " depth target from GL"}));
    image.depth.resize(size_t(image.width) * size_t(image.height));
    glReadPixels(0, 0, image.width, image.height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, image.depth.data());
    checkGl("readDepth");
    for (uint32_t& d : image.depth) d >>= 32 - image.depthBits;
    flipRows(image.depth, size_t(image.width));
    return image;
  }

 private:
  struct Mesh {
    GLuint vao = 0, vbo = 0, ebo = 0, instanceVbo = 0;
    GLsizei indexCount = 0;
  };

  static void enable(GLenum capability, bool on) { on ? glEnable(capability) : glDisable(capability); }

  template <typename GetIv, typename GetLog>
  static std::string infoLog(GLuint object, GetIv getIv, GetLog getLog) {
    GLint length = 0;
    getIv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(length > 0 ? length : 1), '\0');
    getLog(object, GLsizei(log.size()), nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
  }

  // The program's C++ port must declare what its GLSL does (checkPortUniforms,
  // scenes/registry.h): given the uniforms GL reports active and the GLSL source.
  static void checkPortUniforms(const std::string& program, const ProgramFiles& files, GLuint id) {
    GLint count = 0;
    glGetProgramiv(id, GL_ACTIVE_UNIFORMS, &count);
    std::vector<std::string> active;
    for (GLint i = 0; i < count; ++i) {
      char name[256];
      GLsizei length = 0;
      GLint size = 0;
      GLenum type = 0;
      glGetActiveUniform(id, GLuint(i), sizeof name, &length, &size, &type, name);
      active.emplace_back(name, size_t(std::max(length, 0)));
    }
    scenes::checkPortUniforms(program, files, active, readFile(files.vertex) + "\n" + readFile(files.fragment));
  }

  static GLuint compileShader(GLenum stage, const std::string& path) {
    std::string source = readFile(path);
    const char* text = source.c_str();
    GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    if (compiled != GL_TRUE) {
      std::string log = infoLog(shader, glGetShaderiv, glGetShaderInfoLog);
      glDeleteShader(shader);
      throw std::runtime_error("GL backend: compiling " + path + " failed:\n" + log);
    }
    return shader;
  }

  const FramebufferDesc& framebufferDesc(Handle framebuffer) const {
    auto found = framebuffers_.find(framebuffer);
    if (found == framebuffers_.end()) throw std::runtime_error("GL backend: unknown framebuffer");
    return found->second;
  }

  OSMesaContext context_ = nullptr;
  std::vector<uint8_t> colorBuffer_;  // the default framebuffer's colour, owned here
  uint64_t reserved_ = 0;             // this backend's share of the run's memory (io/memory_budget.h)
  uint64_t windowBytes_ = 0;

  void reserve(uint64_t bytes, const std::string& what) {
    memory::reserve(bytes, what);
    reserved_ += bytes;
  }
  int width_ = 0, height_ = 0;
  std::string name_;
  std::map<Handle, Mesh> meshes_;
  std::map<Handle, TextureDesc> textures_;
  std::map<Handle, FramebufferDesc> framebuffers_;
  std::map<std::pair<Handle, std::string>, GLint> uniformLocations_;
};

}  // namespace

// Mesa reads GALLIUM_DRIVER and LP_NUM_THREADS when the first context is made, and an
// unknown driver name makes OSMesa 22.3 crash inside Mesa with no message. Both are checked
// here first: bad values are bad input (SceneError: the program exits 2).
void checkGalliumEnvironment() {
  if (const char* driver = std::getenv("GALLIUM_DRIVER")) {
    const std::string name = driver;
    if (name != "llvmpipe" && name != "softpipe")
      throw SceneError("GALLIUM_DRIVER='" + name.substr(0, 40) +
                       "' is not a driver the GL reference can use (llvmpipe or softpipe; unset means llvmpipe)");
  }
  if (const char* threads = std::getenv("LP_NUM_THREADS")) {
    const std::string text = threads;
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value < 0 || value > 1024)
      throw SceneError("LP_NUM_THREADS='" + text.substr(0, 40) +
                       "' is not a thread count (a whole number 0..1024; llvmpipe uses at most 32)");
  }
}

std::unique_ptr<Backend> makeGlBackend() { return std::make_unique<GlBackend>(); }

int glBackendsMade() { return backendsMade; }

}  // namespace scenes
