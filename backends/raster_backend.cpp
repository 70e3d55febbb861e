// The Backend implemented by this project's pipeline (raster::Renderer).
//
// Resources are plain raster::Texture objects; the default framebuffer is an RGBA8 colour
// texture and a 24-bit depth texture stored top row first (flipY), as llvmpipe stores
// window-system buffers. Read-back flips FBO images (row 0 = GL's bottom) to top row first.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends/backends.h"
#include "io/memory_budget.h"
#include "raster/renderer.h"
#include "raster/texture/footprint_strips.h"
#include "raster/texture/format.h"
#include "scenes/program_registry.h"

namespace scenes {
namespace {

struct Mesh {
  MeshData data;
  raster::VertexStream stream;
};

class RasterBackend final : public Backend {
 public:
  RasterBackend(int threads, bool scalarOnly, bool visibilityFirst) : renderer_(threads, scalarOnly) {
    renderer_.setVisibilityFirst(visibilityFirst);
    textures_.emplace_back();     // handle 0: no texture
    framebuffers_.emplace_back(); // handle 0: the default framebuffer
    meshes_.emplace_back();
    programs_.emplace_back();
    // The smallest window until the scene sizes it: a memory cap (--max-memory) is then met
    // or missed at the size asked for, not at a default nobody asked for.
    resizeDefaultFramebuffer(1, 1);
  }

  ~RasterBackend() override { memory::release(reserved_); }

  std::string name() const override { return "raster"; }

  void resizeDefaultFramebuffer(int width, int height) override {
    renderer_.flush();
    const uint64_t before = raster::textureStorageBytes(defaultColor_.width, defaultColor_.height, TexelFormat::RGBA8) * 2;
    defaultColor_ = raster::Texture();   // freed before the new size is reserved
    defaultDepth_ = raster::Texture();
    unreserve(before);
    reserve(raster::textureStorageBytes(width, height, TexelFormat::RGBA8) * 2,
            memory::joined({"the ", std::to_string(width), "x", std::to_string(height), " window (RGBA8 colour, 24-bit depth)"}));
    defaultColor_ = raster::Texture(width, height, TexelFormat::RGBA8);
    defaultDepth_ = raster::Texture(width, height, TexelFormat::Depth24);
    defaultColor_.label = "final";   // the names the scenes' targets give the window's buffers
    defaultDepth_.label = "depth";
    raster::Framebuffer& fb = framebuffers_[kDefaultFramebuffer];
    fb.colors = {&defaultColor_};
    fb.depth = &defaultDepth_;
    fb.width = width;
    fb.height = height;
    fb.flipY = true;
  }

  Handle createProgram(const std::string& program) override {
    programs_.push_back(makeBoundProgram(program));
    return Handle(programs_.size() - 1);
  }

  Handle createMesh(const MeshData& mesh) override {
    // The mesh's copy, and the shaded vertex records of every (instance, vertex): 8 floats of
    // positions plus the program's varyings (at most kMaxVaryingFloats).
    const uint64_t vertices = mesh.strideFloats > 0 ? mesh.vertices.size() / size_t(mesh.strideFloats) : 0;
    const uint64_t instances = mesh.instanceStrideFloats > 0 ? std::max<uint64_t>(mesh.instances.size() / size_t(mesh.instanceStrideFloats), 1) : 1;
    reserve((mesh.vertices.size() + mesh.instances.size() + mesh.indices.size()) * 4 +
                vertices * instances * (8 + raster::limits::kMaxVaryingFloats) * 4,
            memory::joined({"a mesh of ", std::to_string(vertices), " vertices x ", std::to_string(instances), " instances"}));
    auto m = std::make_unique<Mesh>();
    m->data = mesh;
    m->stream.vertices = m->data.vertices.data();
    m->stream.strideFloats = mesh.strideFloats;
    m->stream.vertexCount = mesh.strideFloats > 0 ? int(mesh.vertices.size() / size_t(mesh.strideFloats)) : 0;
    for (const VertexAttribute& a : mesh.attributes) m->stream.attributes.push_back({a.location, a.components, a.offsetFloats});
    if (!m->data.instances.empty()) {
      m->stream.instances = m->data.instances.data();
      m->stream.instanceStrideFloats = mesh.instanceStrideFloats;
      for (const VertexAttribute& a : mesh.instanceAttributes)
        m->stream.instanceAttributes.push_back({a.location, a.components, a.offsetFloats});
    }
    meshes_.push_back(std::move(m));
    return Handle(meshes_.size() - 1);
  }

  Handle createTexture(const TextureDesc& desc, const void* pixels) override {
    reserve(raster::textureStorageBytes(desc.width, desc.height, desc.format),
            memory::joined({"a ", std::to_string(desc.width), "x", std::to_string(desc.height), " texture"}));
    auto t = std::make_unique<raster::Texture>(desc.width, desc.height, desc.format);
    t->sampler = desc.sampler;
    if (pixels) upload(*t, pixels, desc.format == TexelFormat::RGB16F ? 3 : 4);
    else if (desc.format == TexelFormat::RGB16F) upload(*t, nullptr, 3);
    // A grey texture also gets the samplers' one-byte-a-texel copy (texture.h).
    if (pixels && raster::makeGreyCopy(*t))
      reserve(t->grey8.size(), memory::joined({"the grey copy of a ", std::to_string(desc.width), "x",
                                               std::to_string(desc.height), " texture"}));
    // Another RGBA8 texture sampled bilinearly is kept in the 16-lane sampler's strips
    // instead of rows (footprint_strips.h), where this build has that sampler: 4/3 of the
    // rows, reserved before they are made; the rows are then freed.
    if (pixels && raster::kSamplersReadStrips && raster::wantsStripCopy(*t)) {
      reserve(raster::stripCopyBytes(*t), memory::joined({"the strips of a ", std::to_string(desc.width), "x",
                                                          std::to_string(desc.height), " texture"}));
      raster::makeStripCopy(*t);
      unreserve(raster::releaseRows(*t));
    }
    textures_.push_back(std::move(t));
    return Handle(textures_.size() - 1);
  }

  Handle createFramebuffer(const FramebufferDesc& desc) override {
    raster::Framebuffer fb;
    auto attach = [&](Handle h) {
      raster::Texture* t = texture(h);
      // Drawing writes rows only: a sampler's copy would go stale, so a render target has
      // none, and a texture kept in strips gets its rows back first.
      if (raster::texelsInStripsOnly(*t))
        reserve(raster::textureStorageBytes(t->width, t->height, t->format),
                memory::joined({"the rows of a ", std::to_string(t->width), "x", std::to_string(t->height),
                                " texture drawn into"}));
      const uint64_t copies = t->grey8.size() + t->strips8.size();
      raster::dropGreyCopy(*t);
      raster::restoreRows(*t);
      unreserve(copies);
      if (fb.width == 0) { fb.width = t->width; fb.height = t->height; }
      if (t->width != fb.width || t->height != fb.height) throw std::runtime_error("framebuffer attachments differ in size");
      return t;
    };
    for (Handle h : desc.colorTextures) fb.colors.push_back(attach(h));
    if (desc.depthTexture) fb.depth = attach(desc.depthTexture);
    if (fb.width == 0) throw std::runtime_error("framebuffer without attachments");
    framebuffers_.push_back(fb);
    return Handle(framebuffers_.size() - 1);
  }

  void beginPass(Handle framebuffer, const Viewport& viewport, const ClearOp& clear) override {
    raster::ClearValues values;
    values.color = clear.color;
    for (int c = 0; c < 4; ++c) values.colorValue[c] = clear.colorValue[c];
    values.depth = clear.depth;
    values.depthValue = clear.depthValue;
    renderer_.beginPass(framebufferAt(framebuffer), {viewport.x, viewport.y, viewport.width, viewport.height}, values);
    if (history_ && !history_->passes.empty()) history_->passes.back().label = nextPassLabel_;
    if (recorder_) recorder_->labelNextPass(nextPassLabel_);
    nextPassLabel_.clear();
  }

  void labelTexture(Handle texture, const std::string& label) override { this->texture(texture)->label = label; }
  void labelNextPass(const std::string& label) override { nextPassLabel_ = label; }
  void setPixelHistory(raster::PixelHistory* history) {
    renderer_.flush();
    history_ = history;
    renderer_.setPixelHistory(history);
  }
  void setViewRecorder(raster::ViewRecorder* recorder) {
    renderer_.flush();
    recorder_ = recorder;
    renderer_.setViewRecorder(recorder);
  }

  void setUniform(Handle program, const std::string& name, const UniformValue& value) override {
    programAt(program).setUniform(name, value);
  }

  void bindTexture(int unit, Handle t) override {
    if (unit < 0 || unit >= kTextureUnits) throw std::runtime_error("texture unit out of range");
    units_[size_t(unit)] = t ? texture(t) : nullptr;
  }

  void draw(Handle program, Handle mesh, const DrawState& state, int instanceCount) override {
    if (mesh <= 0 || size_t(mesh) >= meshes_.size()) throw std::runtime_error("unknown mesh handle");
    const Mesh& m = *meshes_[size_t(mesh)];
    raster::RasterState rs;
    rs.depthTest = state.depthTest;
    rs.depthFunc = state.depthFunc;
    rs.depthWrite = state.depthWrite;
    rs.cullBack = state.cull == CullMode::Back;
    rs.polygonOffset = state.polygonOffset;
    rs.offsetFactor = state.offsetFactor;
    rs.offsetUnits = state.offsetUnits;
    rs.blendAdditive = state.blendAdditive;
    renderer_.draw(programAt(program).instantiate(units_), m.stream, m.data.indices, rs, instanceCount);
  }

  void finish() override { renderer_.flush(); }

  ImageData readColor(Handle framebuffer, int attachment) override {
    renderer_.flush();
    const raster::Framebuffer& fb = framebufferAt(framebuffer);
    if (attachment < 0 || attachment >= int(fb.colors.size())) throw std::runtime_error("no such colour attachment");
    const raster::Texture& t = *fb.colors[size_t(attachment)];
    ImageData image = imageHeader(t);
    image.reserved = readBackReservation(t);
    for (int row = 0; row < t.height; ++row) {
      const size_t src = size_t(fb.flipY ? row : t.height - 1 - row) * size_t(t.width) * 4;
      if (t.format == TexelFormat::RGBA8) {
        image.rgba8.insert(image.rgba8.end(), t.rgba8.begin() + long(src), t.rgba8.begin() + long(src + size_t(t.width) * 4));
      } else if (t.format == TexelFormat::RGBA32F) {
        image.floats.insert(image.floats.end(), t.f32.begin() + long(src), t.f32.begin() + long(src + size_t(t.width) * 4));
      } else {
        for (size_t i = 0; i < size_t(t.width) * 4; ++i) image.floats.push_back(raster::format::floatFromHalf(t.half[src + i]));
      }
    }
    return image;
  }

  ImageData readDepth(Handle framebuffer) override {
    renderer_.flush();
    const raster::Framebuffer& fb = framebufferAt(framebuffer);
    if (!fb.depth) throw std::runtime_error("framebuffer has no depth buffer");
    const raster::Texture& t = *fb.depth;
    ImageData image = imageHeader(t);
    image.reserved = readBackReservation(t);
    for (int row = 0; row < t.height; ++row) {
      const size_t src = size_t(fb.flipY ? row : t.height - 1 - row) * size_t(t.width);
      image.depth.insert(image.depth.end(), t.depth.begin() + long(src), t.depth.begin() + long(src + size_t(t.width)));
    }
    return image;
  }

  std::vector<std::pair<std::string, double>> statistics() const override {
    const raster::PipelineCounters& c = renderer_.counters();
    return {{"triangles_in", double(c.trianglesIn)},         {"triangles_clipped", double(c.trianglesClipped)},
            {"triangles_rejected", double(c.trianglesRejected)}, {"triangles_set_up", double(c.trianglesSetUp)},
            {"tile_bin_entries", double(c.tileBinEntries)},    {"depth_range_walks", double(c.depthRangeWalks)},
            {"texel_plane_texels", double(c.texelPlaneTexels)},
            {"lane_groups_shaded", double(c.laneGroupsShaded)},
            {"lanes_shaded", double(c.lanesShaded)},           {"lanes_covered", double(c.lanesCovered)},
            {"cycles_vertex", double(c.vertexCycles)},         {"cycles_clip_setup", double(c.setupCycles)},
            {"cycles_bin", double(c.binCycles)},               {"cycles_raster", double(c.rasterCycles)},
            {"cycles_fragment_shading", double(c.shadeCycles)}, {"cycles_output_merge", double(c.mergeCycles)}};
  }
  void resetStatistics(bool timeStages) override {
    renderer_.resetCounters();
    renderer_.setStageTiming(timeStages);
  }

 private:
  void reserve(uint64_t bytes, const std::string& what) {
    memory::reserve(bytes, what);
    reserved_ += bytes;
  }
  void unreserve(uint64_t bytes) {
    bytes = std::min(reserved_, bytes);
    memory::release(bytes);
    reserved_ -= bytes;
  }

  // Read-backs hold RGBA8 as 4 bytes a pixel, depth codes as 4, float formats as 4 floats.
  static memory::Reservation readBackReservation(const raster::Texture& t) {
    const uint64_t perPixel = t.format == TexelFormat::RGBA8 || t.isDepth() ? 4 : 16;
    return memory::Reservation(uint64_t(t.width) * uint64_t(t.height) * perPixel,
                               memory::joined({"reading back a ", std::to_string(t.width), "x", std::to_string(t.height), " target"}));
  }

  static ImageData imageHeader(const raster::Texture& t) {
    ImageData image;
    image.width = t.width;
    image.height = t.height;
    image.channels = t.isDepth() ? 1 : 4;
    image.depthBits = t.depthBits();
    image.format = t.format;   // a Texture never holds RGB16F (it stores RGBA16F)
    return image;
  }

  // glTexImage2D: rows as given (row 0 = t = 0). float -> half TRUNCATES toward zero, as
  // measured against Mesa 22.3's texture upload (tests/texture/sampler_test.cpp), though the
  // reference notes expected round-to-nearest-even. Three-channel float uploads get
  // alpha 1 (null pixels: undefined in GL, zero here).
  static void upload(raster::Texture& t, const void* pixels, int channels) {
    const size_t texels = size_t(t.width) * size_t(t.height);
    t.clearedTiles.forget();   // new texels: no tile is known to hold a clear
    if (t.format == TexelFormat::RGBA8) {
      const auto* src = static_cast<const uint8_t*>(pixels);
      if (src) t.rgba8.assign(src, src + texels * 4);
    } else if (t.format == TexelFormat::RGBA16F) {
      const auto* src = static_cast<const float*>(pixels);
      for (size_t i = 0; i < texels; ++i)
        for (int c = 0; c < 4; ++c)
          t.half[i * 4 + size_t(c)] = c < channels ? (src ? raster::format::halfFromFloatTowardZero(src[i * size_t(channels) + size_t(c)]) : 0)
                                                   : raster::format::halfFromFloatTowardZero(1.0f);
    } else if (t.format == TexelFormat::RGBA32F) {
      const auto* src = static_cast<const float*>(pixels);
      if (src) t.f32.assign(src, src + texels * 4);
    } else {
      throw std::runtime_error("depth textures are not uploaded from the CPU in these scenes");
    }
  }

  raster::Texture* texture(Handle h) {
    if (h <= 0 || size_t(h) >= textures_.size()) throw std::runtime_error("unknown texture handle");
    return textures_[size_t(h)].get();
  }
  raster::Framebuffer& framebufferAt(Handle h) {
    if (h < 0 || size_t(h) >= framebuffers_.size()) throw std::runtime_error("unknown framebuffer handle");
    return framebuffers_[size_t(h)];
  }
  BoundProgram& programAt(Handle h) {
    if (h <= 0 || size_t(h) >= programs_.size()) throw std::runtime_error("unknown program handle");
    return *programs_[size_t(h)];
  }

  raster::Renderer renderer_;
  raster::Texture defaultColor_, defaultDepth_;
  uint64_t reserved_ = 0;   // this backend's share of the run's memory (io/memory_budget.h)
  std::vector<std::unique_ptr<raster::Texture>> textures_;
  std::vector<raster::Framebuffer> framebuffers_;
  std::vector<std::unique_ptr<Mesh>> meshes_;
  std::vector<std::unique_ptr<BoundProgram>> programs_;
  TextureUnits units_{};
  raster::PixelHistory* history_ = nullptr;   // pixel history, when a trace asked for it
  std::string nextPassLabel_;                 // labelNextPass, for the next beginPass
  raster::ViewRecorder* recorder_ = nullptr;  // stage views, when a view asked for them
};

}  // namespace

void setPixelHistory(Backend& rasterBackend, raster::PixelHistory* history) {
  auto* backend = dynamic_cast<RasterBackend*>(&rasterBackend);
  if (!backend) throw std::invalid_argument("pixel history needs this pipeline's backend, not " + rasterBackend.name());
  backend->setPixelHistory(history);
}

void setViewRecorder(Backend& rasterBackend, raster::ViewRecorder* recorder) {
  auto* backend = dynamic_cast<RasterBackend*>(&rasterBackend);
  if (!backend) throw std::invalid_argument("stage views need this pipeline's backend, not " + rasterBackend.name());
  backend->setViewRecorder(recorder);
}

std::unique_ptr<Backend> makeRasterBackend(int threads, bool scalarOnly, bool visibilityFirst) {
  return std::make_unique<RasterBackend>(threads, scalarOnly, visibilityFirst);
}

}  // namespace scenes
