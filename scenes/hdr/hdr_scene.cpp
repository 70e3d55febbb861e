// The HDR + bloom scene, ported from the seed's host code (gen_instances, make_hdr_color,
// create_scene_target, create_bloom_chain, create_gl_objects, update).
//
// Deviations decided for the project (seeds/README.md): glm::perspectiveRH_NO replaces the
// tutorial's perspective_rh_opengl; look_at_rh = glm::lookAtRH; frame N renders at t = N / 60.
// Generalisation: the seed fixes the HDR target at 640x480, the size of its canvas, so the
// composite maps it 1:1 onto the screen. Here the HDR target is the scene's width x height
// (SceneOptions), which keeps that 1:1 mapping at any size; the scene projection's aspect is
// HDR_W / HDR_H as in the seed, and bloom mip i is max(HDR_W >> (i + 1), 1) by
// max(HDR_H >> (i + 1), 1). At the default 640x480 this is exactly the seed.
// The seed's depth renderbuffer (DEPTH_COMPONENT16) is a Depth16 texture here: the backend
// interface attaches textures only; it is never sampled, so nothing else changes.
//
// Targets, and how the bloom mips are seen after each pass without touching the frame:
//   hdr_scene, hdr_depth      the scene pass's RGBA16F colour and 16-bit depth;
//   bloom_down_0..4           mip i as the bright pass (i = 0) or the downsample (i > 0) left
//                             it, before any upsample was blended onto it;
//   bloom_up_0..3             mip i after the upsample of mip i + 1 was blended onto it (mip
//                             4 is never blended onto: its final content is bloom_down_4);
//   final                     the composite, RGBA8, last.
// renderFrame() does exactly the seed's work and nothing else (it is what gets timed). The
// up passes overwrite mips 0-3 in place, so their down results no longer exist when the
// frame ends. readTargets() therefore runs the bright and down passes a second time, with the
// same code (brightAndDownPasses) and the same inputs (the HDR scene target, which nothing
// after pass 1 writes), into a second chain of mips made for this purpose in setup(). Both
// backends are deterministic, so this reproduces the mips' intermediate content exactly, on
// either backend, at the cost of extra work only when targets are read.
#include "scenes/hdr/hdr_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include "shaders_cpp/hdr/bright.h"
#include "shaders_cpp/hdr/composite.h"
#include "shaders_cpp/hdr/down.h"
#include "shaders_cpp/hdr/scene.h"
#include "shaders_cpp/hdr/up.h"

namespace scenes {
namespace {

constexpr int BLOOM_MIPS = 5;
constexpr float PI = 3.14159265358979323846f;

// Vertex { xyz : float3; normal : float3 }: faceted unit cube (half-extent 0.5), per-face
// normals, 24 vertices / 36 indices, counter-clockwise from outside (correct under GL_BACK).
// Instance { offset : float3; color : float3; phase : float; emissive : float } at
// locations 2-5, divisor 1.
MeshData cubeMesh(std::vector<float> instances) {
  MeshData mesh;
  mesh.vertices = {
      0.5f, 0.5f, 0.5f, 0, 0, 1,     -0.5f, 0.5f, 0.5f, 0, 0, 1,    -0.5f, -0.5f, 0.5f, 0, 0, 1,   0.5f, -0.5f, 0.5f, 0, 0, 1,
      0.5f, 0.5f, 0.5f, 1, 0, 0,     0.5f, -0.5f, 0.5f, 1, 0, 0,    0.5f, -0.5f, -0.5f, 1, 0, 0,   0.5f, 0.5f, -0.5f, 1, 0, 0,
      0.5f, 0.5f, 0.5f, 0, 1, 0,     0.5f, 0.5f, -0.5f, 0, 1, 0,    -0.5f, 0.5f, -0.5f, 0, 1, 0,   -0.5f, 0.5f, 0.5f, 0, 1, 0,
      -0.5f, 0.5f, 0.5f, -1, 0, 0,   -0.5f, 0.5f, -0.5f, -1, 0, 0,  -0.5f, -0.5f, -0.5f, -1, 0, 0, -0.5f, -0.5f, 0.5f, -1, 0, 0,
      -0.5f, -0.5f, -0.5f, 0, -1, 0, 0.5f, -0.5f, -0.5f, 0, -1, 0,  0.5f, -0.5f, 0.5f, 0, -1, 0,   -0.5f, -0.5f, 0.5f, 0, -1, 0,
      0.5f, -0.5f, -0.5f, 0, 0, -1,  -0.5f, -0.5f, -0.5f, 0, 0, -1, -0.5f, 0.5f, -0.5f, 0, 0, -1,  0.5f, 0.5f, -0.5f, 0, 0, -1,
  };
  mesh.strideFloats = 6;
  mesh.attributes = {{0, 3, 0}, {1, 3, 3}};
  mesh.indices = {0, 1, 2, 2, 3, 0, 4, 5, 6, 6, 7, 4, 8, 9, 10, 10, 11, 8,
                  12, 13, 14, 14, 15, 12, 16, 17, 18, 18, 19, 16, 20, 21, 22, 22, 23, 20};
  mesh.instances = std::move(instances);
  mesh.instanceStrideFloats = 8;
  mesh.instanceAttributes = {{2, 3, 0}, {3, 3, 3}, {4, 1, 6}, {5, 1, 7}};
  return mesh;
}

// QuadVertex { xy : float2 }: the fullscreen triangle, drawn as indices 0 1 2 (the seed's
// glDrawArrays(GL_TRIANGLES, 0, 3)).
MeshData quadMesh() {
  MeshData mesh;
  mesh.vertices = {-1, -1, 3, -1, -1, 3};
  mesh.strideFloats = 2;
  mesh.attributes = {{0, 2, 0}};
  mesh.indices = {0, 1, 2};
  return mesh;
}

// gen_instances: n rows on a 3D Lissajous curve (7 azimuthal vs 3 elevation lobes vs radial
// breathing); hue cycles three times; phase sweeps [0, 1); every 9th cube is emissive.
// All in float, left to right as the seed writes it, with PI as a float.
// world_offset adds (d, d, d) to every offset and intensity scales every colour (params,
// when set; unset, the seed's values are untouched).
std::vector<float> gen_instances(int n, const SceneParams& params) {
  const std::optional<float> worldOffset = params.get("world_offset"), intensity = params.get("intensity");
  std::vector<float> result;
  result.reserve(size_t(n) * 8);
  for (int i = 0; i < n; ++i) {
    const float fi = float(i) / float(n);
    const float theta = fi * 2.0f * PI * 7.0f;
    const float phi = fi * 2.0f * PI * 3.0f;
    const float r = 5.0f + 1.5f * std::sin(fi * 2.0f * PI * 5.0f);
    const float x = r * std::cos(theta) * std::cos(phi * 0.5f);
    const float y = r * std::sin(phi);
    const float z = r * std::sin(theta) * std::cos(phi * 0.5f);
    const float hue = fi * 6.0f * PI;
    const float cr = 0.5f + 0.5f * std::cos(hue);
    const float cg = 0.5f + 0.5f * std::cos(hue + 2.0944f);
    const float cb = 0.5f + 0.5f * std::cos(hue + 4.1888f);
    const float emissive = (i % 9 == 0) ? 1.0f : 0.0f;
    const float d = worldOffset.value_or(0.0f), k = intensity.value_or(1.0f);
    if (worldOffset || intensity) result.insert(result.end(), {x + d, y + d, z + d, cr * k, cg * k, cb * k, fi, emissive});
    else result.insert(result.end(), {x, y, z, cr, cg, cb, fi, emissive});
  }
  return result;
}

// One bloom chain: BLOOM_MIPS RGBA16F textures, each with its framebuffer.
struct BloomChain {
  std::array<Handle, BLOOM_MIPS> tex{};
  std::array<Handle, BLOOM_MIPS> fbo{};
};

class HdrScene final : public Scene {
 public:
  explicit HdrScene(const SceneOptions& options)
      : HDR_W(std::max(options.width, 1)), HDR_H(std::max(options.height, 1)), N_INSTANCES(options.instances),
        options_(options) {
    // bloom mip chain: mip i lives at (HDR >> (i+1)) -- mip 0 is half res, then halving.
    for (int i = 0; i < BLOOM_MIPS; ++i) {
      bloom_w_[size_t(i)] = std::max(HDR_W >> (i + 1), 1);
      bloom_h_[size_t(i)] = std::max(HDR_H >> (i + 1), 1);
    }
  }

  std::string name() const override { return "hdr"; }

  void setup(Backend& b) override {
    prog_scene_ = b.createProgram("hdr/scene");
    prog_bright_ = b.createProgram("hdr/post+bright");
    prog_down_ = b.createProgram("hdr/post+down");
    prog_up_ = b.createProgram("hdr/post+up");
    prog_composite_ = b.createProgram("hdr/post+composite");
    scene_mesh_ = b.createMesh(cubeMesh(gen_instances(N_INSTANCES, options_.params)));
    quad_ = b.createMesh(quadMesh());

    // create_scene_target: RGBA16F colour (LINEAR, CLAMP_TO_EDGE) + 16-bit depth.
    hdr_color_ = makeHdrColor(b, HDR_W, HDR_H);
    hdr_depth_ = b.createTexture({HDR_W, HDR_H, TexelFormat::Depth16, {Filter::Nearest, Wrap::ClampToEdge, Wrap::ClampToEdge, false}});
    b.labelTexture(hdr_color_, "hdr_scene");
    b.labelTexture(hdr_depth_, "hdr_depth");
    hdr_fbo_ = b.createFramebuffer({{hdr_color_}, hdr_depth_});
    // create_bloom_chain, and the chain readTargets() re-runs the down passes into.
    bloom_ = makeBloomChain(b, "bloom_mip_");
    capture_ = makeBloomChain(b, "bloom_capture_");
    createFinalTarget(b, options_, /*depth=*/false);
  }

  void renderFrame(Backend& b, float t) override {
    const int display_w = HDR_W, display_h = HDR_H;

    // camera orbits the swarm with a gentle vertical sway; scene projection uses the
    // HDR aspect since the scene renders into the HDR_W x HDR_H target.
    const float camera_angle = t * 0.3f;
    const float camera_r = 14.0f;
    glm::vec3 cam_pos(camera_r * std::cos(camera_angle), std::sin(camera_angle * 2.0f) * 2.0f,
                      camera_r * std::sin(camera_angle));
    glm::vec3 target(0, 0, 0);
    // --set NAME=VALUE (the parameters of this scene's row); unset, the seed's own value.
    const SceneParams& p = options_.params;
    const std::optional<float> worldOffset = p.get("world_offset"), nearPlane = p.get("near");
    if (worldOffset) cam_pos += glm::vec3(*worldOffset), target += glm::vec3(*worldOffset);
    const glm::mat4 u_view = glm::lookAtRH(cam_pos, target, glm::vec3(0, 1, 0));
    const glm::mat4 u_proj = glm::perspectiveRH_NO(60.0f * PI / 180.0f, float(HDR_W) / float(HDR_H),
                                                   nearPlane.value_or(0.1f), 60.0f);

    // ===== Pass 1: scene into the HDR float target =====
    ClearOp clearScene;
    clearScene.color = true;
    clearScene.colorValue = glm::vec4(0.01f, 0.0f, 0.03f, 1.0f);
    clearScene.depth = true;
    b.labelNextPass("hdr_scene");
    b.beginPass(hdr_fbo_, {0, 0, HDR_W, HDR_H}, clearScene);
    DrawState sceneState;
    sceneState.depthTest = true;
    sceneState.depthFunc = DepthFunc::Lequal;
    sceneState.cull = CullMode::Back;
    b.setUniform(prog_scene_, "u_view", u_view);
    b.setUniform(prog_scene_, "u_proj", u_proj);
    b.setUniform(prog_scene_, "u_cam_pos", cam_pos);
    b.setUniform(prog_scene_, "u_time", t);
    b.draw(prog_scene_, scene_mesh_, sceneState, N_INSTANCES);

    // ===== Passes 2 and 3: bright pass into mip 0, downsample mip 0 -> 1 -> 2 -> 3 -> 4 =====
    brightAndDownPasses(b, bloom_);

    // ===== Pass 4: upsample mip 4 -> 3 -> 2 -> 1 -> 0, additively blended =====
    DrawState blendState = postState();
    blendState.blendAdditive = true;
    for (int k = 0; k < BLOOM_MIPS - 1; ++k) {
      const int i = BLOOM_MIPS - 1 - k;   // i = 4, 3, 2, 1; writes onto mip i-1
      b.labelNextPass("bloom_up_" + std::to_string(i - 1));   // the target it reads back as
      b.beginPass(bloom_.fbo[size_t(i - 1)], {0, 0, bloom_w_[size_t(i - 1)], bloom_h_[size_t(i - 1)]}, ClearOp{});
      b.bindTexture(0, bloom_.tex[size_t(i)]);
      b.setUniform(prog_up_, "src0", 0);
      b.setUniform(prog_up_, "u_src_rcp", srcRcp(i));
      b.draw(prog_up_, quad_, blendState);
    }

    // ===== Pass 5: composite HDR scene + bloom -> ACES tonemap -> gamma -> screen =====
    ClearOp clearScreen;
    clearScreen.color = true;
    clearScreen.colorValue = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    b.labelNextPass("final");
    b.beginPass(final_, {0, 0, display_w, display_h}, clearScreen);
    b.bindTexture(0, hdr_color_);
    b.bindTexture(1, bloom_.tex[0]);
    b.setUniform(prog_composite_, "src0", 0);
    b.setUniform(prog_composite_, "src_bloom", 1);
    b.setUniform(prog_composite_, "u_bloom_intensity", 0.7f);
    b.draw(prog_composite_, quad_, postState());
  }

  std::vector<Target> readTargets(Backend& b) override {
    b.finish();
    std::vector<Target> targets;
    targets.push_back({"hdr_scene", b.readColor(hdr_fbo_)});
    targets.push_back({"hdr_depth", b.readDepth(hdr_fbo_)});
    // The final mips first, then the down results re-made in the capture chain (see the
    // file header); listed in pass order: down 0..4, then up 0..3.
    std::vector<Target> up;
    for (int i = 0; i < BLOOM_MIPS - 1; ++i) up.push_back({"bloom_up_" + std::to_string(i), b.readColor(bloom_.fbo[size_t(i)])});
    brightAndDownPasses(b, capture_);
    b.finish();
    for (int i = 0; i < BLOOM_MIPS; ++i)
      targets.push_back({"bloom_down_" + std::to_string(i), b.readColor(capture_.fbo[size_t(i)])});
    for (Target& t : up) targets.push_back(std::move(t));
    targets.push_back({"final", b.readColor(final_)});
    return targets;
  }

 private:
  // make_hdr_color: RGBA16F, LINEAR + CLAMP_TO_EDGE so the down/up taps filter and never wrap.
  static Handle makeHdrColor(Backend& b, int w, int h) {
    return b.createTexture({w, h, TexelFormat::RGBA16F, {Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, false}});
  }

  BloomChain makeBloomChain(Backend& b, const std::string& label) const {
    BloomChain chain;
    for (int i = 0; i < BLOOM_MIPS; ++i) {
      chain.tex[size_t(i)] = makeHdrColor(b, bloom_w_[size_t(i)], bloom_h_[size_t(i)]);
      b.labelTexture(chain.tex[size_t(i)], label + std::to_string(i));
      chain.fbo[size_t(i)] = b.createFramebuffer({{chain.tex[size_t(i)]}, 0});
    }
    return chain;
  }

  // The post passes are 2D: no depth test, no culling, no blending.
  static DrawState postState() {
    DrawState s;
    s.depthTest = false;
    s.depthWrite = false;
    s.cull = CullMode::None;
    return s;
  }

  // u_src_rcp for source mip i: 1 / its size, in float.
  glm::vec2 srcRcp(int i) const {
    return glm::vec2(1.0f / float(bloom_w_[size_t(i)]), 1.0f / float(bloom_h_[size_t(i)]));
  }

  // Pass 2 (bright pass from the HDR scene into mip 0) and pass 3 (5-tap downsamples
  // mip i -> i + 1), into `chain`. Neither clears: each fullscreen triangle covers its mip.
  void brightAndDownPasses(Backend& b, const BloomChain& chain) {
    b.labelNextPass("bloom_down_0");
    b.beginPass(chain.fbo[0], {0, 0, bloom_w_[0], bloom_h_[0]}, ClearOp{});
    b.bindTexture(0, hdr_color_);
    b.setUniform(prog_bright_, "src0", 0);
    b.setUniform(prog_bright_, "u_threshold", 1.0f);
    b.setUniform(prog_bright_, "u_soft_knee", 0.6f);
    b.draw(prog_bright_, quad_, postState());

    for (int i = 0; i < BLOOM_MIPS - 1; ++i) {
      b.labelNextPass("bloom_down_" + std::to_string(i + 1));
      b.beginPass(chain.fbo[size_t(i + 1)], {0, 0, bloom_w_[size_t(i + 1)], bloom_h_[size_t(i + 1)]}, ClearOp{});
      b.bindTexture(0, chain.tex[size_t(i)]);
      b.setUniform(prog_down_, "src0", 0);
      b.setUniform(prog_down_, "u_src_rcp", srcRcp(i));
      b.draw(prog_down_, quad_, postState());
    }
  }

  const int HDR_W, HDR_H;   // the HDR target: the scene's width x height (see the file header)
  const int N_INSTANCES;    // 1000 in the seed; --instances scales the swarm for benchmarks
  const SceneOptions options_;  // options_.params: --set (scene_params.h)
  std::array<int, BLOOM_MIPS> bloom_w_{}, bloom_h_{};
  Handle prog_scene_ = 0, prog_bright_ = 0, prog_down_ = 0, prog_up_ = 0, prog_composite_ = 0;
  Handle scene_mesh_ = 0, quad_ = 0;
  Handle hdr_color_ = 0, hdr_depth_ = 0, hdr_fbo_ = 0;
  BloomChain bloom_, capture_;
};

}  // namespace

SceneEntry hdrScene() {
  return {
      .name = "hdr",
      .description = "\"11 - HDR + Bloom\": 1000 instanced cubes, back-face culling, LEQUAL, RGBA16F targets, a 5-level bloom chain with additive blending, ACES",
      .seed = "002_2011f151d1707bfd.txt",
      .make = [](const SceneOptions& options) -> std::unique_ptr<Scene> { return std::make_unique<HdrScene>(options); },
      .params = {param::time(), param::size(),
                 {"instances", 1, 200000, true, "", "1000", "cubes in the swarm: many small triangles, deep overdraw"},
                 {"intensity", 0, 1e10, false, "", "1",
                  "scale on every cube's colour; past about 65504 the half-float scene target overflows to inf"},
                 param::nearPlane(), param::worldOffset()},
      .programs = {shaders::hdr::sceneProgram(), shaders::hdr::brightProgram(),
                   shaders::hdr::downProgram(), shaders::hdr::upProgram(),
                   shaders::hdr::compositeProgram()},
      .assets = {},
      .sweeps = {"intensity=1:1e6:13:log",
                 "instances=1:200000:10:log",
                 "near=0.1:1e-6:11:log",
                 "world_offset=1:1e7:15:log",
                 "time=1:1e10:11:log",
                 "size=1:8192:10:log --no-softpipe"},
      // Edges: the cubes' silhouettes under a coarse bright pass and bloom chain.
      .coarseSweeps = {"instances=10:100000:5:log --methods gl,shading=2x1,shading=1x2,shading=2x2"},
  };
}

}  // namespace scenes
