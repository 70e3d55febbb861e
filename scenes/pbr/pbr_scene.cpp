// "Deferred PBR with cascaded shadow maps" (seed 004_c2461eff6b055266.txt), the host side of
// the seed's listings: a concrete cat statue on a brick floor in seven passes, three shadow
// cascades, the G-buffer, SSAO, its blur along x and along y, and lighting to the window.
//
// The seed's G-buffer table asks RGB8 / RGB16F / RGB8 / RGBA16F colour and DEPTH24_STENCIL8.
// This pipeline's formats are RGBA8, RGBA16F and Depth24 (raster/texture/texture.h), and each
// is what llvmpipe stores for the seed's format where the seed's shader writes only rgb: GL
// renders an RGB8 or RGB16F attachment as RGBX (the alpha the shader writes is dropped and
// reads back as 1), so the RGBA attachments here are written with alpha 1 and hold the same
// texels; DEPTH24_STENCIL8's depth is 24-bit unorm like DEPTH_COMPONENT24's, and no pass
// uses stencil. So: RGBA8, RGBA16F, RGBA8, RGBA16F, Depth24, all read with NEAREST.
// Deviations decided for the project: glm::perspectiveRH_NO, lookAtRH, orthoRH_NO, as the
// other scenes; the SSAO kernel and noise come from a fixed generator (below), not
// std::default_random_engine, whose sequence differs between standard libraries.
#include "scenes/pbr/pbr_scene.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <sstream>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "io/assets.h"
#include "shaders_cpp/pbr/blur.h"
#include "shaders_cpp/pbr/gbuffer.h"
#include "shaders_cpp/pbr/lighting.h"
#include "shaders_cpp/pbr/ssao.h"
#include "shaders_cpp/shadow/shadow.h"

namespace scenes {
namespace {

constexpr int NUM_CASCADES = 3;
constexpr int CASCADE_DIM = 1024;
constexpr int KERNEL_SIZE = 64;
constexpr float PI = 3.14159265358979323846f;
constexpr float NEAR_PLANE = 0.1f, FAR_PLANE = 30.0f;
// The seed's defaults for what the registry row lets a sweep move.
constexpr float SPLIT1 = 4.0f, SPLIT2 = 10.0f, SSAO_RADIUS = 0.5f, SSAO_BIAS = 0.025f, ROUGHNESS_FLOOR = 0.04f;

const char* const CAT_OBJ = "cat/concrete_cat_statue.obj";
const char* const CAT_DIFF = "cat/textures/concrete_cat_statue_diff_2k.jpg";
const char* const CAT_NOR = "cat/textures/concrete_cat_statue_nor_gl_1k.jpg";
const char* const CAT_ARM = "cat/textures/concrete_cat_statue_arm_2k.jpg";
const char* const BRICK_COLOR = "brick/Bricks031_1K-JPG_Color.jpg";
const char* const BRICK_NOR = "brick/Bricks031_1K-JPG_NormalGL.jpg";
const char* const BRICK_ROUGH = "brick/Bricks031_1K-JPG_Roughness.jpg";
const char* const BRICK_AO = "brick/Bricks031_1K-JPG_AmbientOcclusion.jpg";

// MeshVertex { pos : float3; normal : float3; uv : float2 }.
MeshData meshOf(std::vector<float> vertices, std::vector<uint32_t> indices) {
  MeshData mesh;
  mesh.vertices = std::move(vertices);
  mesh.strideFloats = 8;
  mesh.attributes = {{0, 3, 0}, {1, 3, 3}, {2, 2, 6}};
  mesh.indices = std::move(indices);
  return mesh;
}

// A 24 m square of bricks: the cascades have room to split along view depth.
MeshData floorMesh() {
  const float s = 12.0f;
  return meshOf({-s, 0, s, 0, 1, 0, 0, 0, s, 0, s, 0, 1, 0, 1, 0, s, 0, -s, 0, 1, 0, 1, 1, -s, 0, -s, 0, 1, 0, 0, 1},
                {0, 1, 2, 0, 2, 3});
}

// The seed's fullscreen triangle (post.vert), drawn with glDrawArrays(GL_TRIANGLES, 0, 3).
MeshData triangleMesh() { return meshOf({-1, -1, 0, 0, 0, 0, 0, 0, 3, -1, 0, 0, 0, 0, 0, 0, -1, 3, 0, 0, 0, 0, 0, 0}, {0, 1, 2}); }

// The SSAO kernel's and noise's random numbers: a 32-bit xorshift (Marsaglia 2003) with a
// fixed seed, its top 24 bits as a float in [0, 1). The same on every machine and standard
// library, so both backends, every run, get the same kernel.
class FixedRandom {
 public:
  float next() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 17;
    state_ ^= state_ << 5;
    return float(state_ >> 8) * (1.0f / 16777216.0f);
  }

 private:
  uint32_t state_ = 0x9E3779B9u;
};

// GenerateSSAOKernel(64) of the seed, with FixedRandom for its distribution and engine.
std::array<glm::vec3, KERNEL_SIZE> generateSsaoKernel(FixedRandom& rng) {
  std::array<glm::vec3, KERNEL_SIZE> kernel{};
  for (int i = 0; i < KERNEL_SIZE; ++i) {
    glm::vec3 s;
    s.x = rng.next() * 2.0f - 1.0f;
    s.y = rng.next() * 2.0f - 1.0f;
    s.z = rng.next();   // hemisphere: z in [0,1]
    s = glm::normalize(s);
    // Accelerate toward origin with lerp
    float scale = float(i) / float(KERNEL_SIZE);
    scale = glm::mix(0.1f, 1.0f, scale * scale);
    kernel[size_t(i)] = s * scale;
  }
  return kernel;
}

// The 4x4 rotation vectors: random in the tangent plane (z = 0), RGBA32F texels.
std::vector<float> generateSsaoNoise(FixedRandom& rng) {
  std::vector<float> noise;
  for (int i = 0; i < 16; ++i) {
    const float x = rng.next() * 2.0f - 1.0f, y = rng.next() * 2.0f - 1.0f;
    noise.insert(noise.end(), {x, y, 0.0f, 1.0f});
  }
  return noise;
}

float paramOr(const SceneOptions& options, const char* name, float byDefault) {
  return options.params.get(name).value_or(byDefault);
}

// The cascade splits must rise from the near plane to the far plane: each cascade covers
// [near, split1], [split1, split2], [split2, far] of view depth, and GetCascadeIndex picks
// the first split above a pixel's depth. Any other order leaves a cascade empty or inverted.
void checkSplits(float split1, float split2) {
  if (split1 > NEAR_PLANE && split1 < split2 && split2 < FAR_PLANE) return;
  std::ostringstream message;
  message << "pbr: the cascade splits must rise along view depth, near " << NEAR_PLANE << " < cascade_split1 ("
          << split1 << ") < cascade_split2 (" << split2 << ") < far " << FAR_PLANE;
  throw SceneError(message.str());
}

// A cascade's light matrix: the view frustum between view depths `nearZ` and `farZ`, its
// eight corners' bounding sphere, seen along the sun from outside it by an orthographic box.
glm::mat4 cascadeMatrix(const glm::mat4& view, float fovY, float aspect, float nearZ, float farZ, glm::vec3 sunDir) {
  const glm::mat4 inverse = glm::inverse(glm::perspectiveRH_NO(fovY, aspect, nearZ, farZ) * view);
  glm::vec3 corners[8];
  glm::vec3 center(0.0f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = inverse * glm::vec4((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f);
    corners[i] = glm::vec3(c) / c.w;
    center += corners[i] / 8.0f;
  }
  float radius = 0.0f;
  for (const glm::vec3& c : corners) radius = std::max(radius, glm::length(c - center));
  const float pullBack = radius + 20.0f;   // casters up to 20 m beyond the slice, toward the sun
  const glm::mat4 lightView = glm::lookAtRH(center + sunDir * pullBack, center, glm::vec3(0, 1, 0));
  return glm::orthoRH_NO(-radius, radius, -radius, radius, 0.1f, pullBack + radius) * lightView;
}

class PbrScene final : public Scene {
 public:
  explicit PbrScene(const SceneOptions& options) : options_(options) {
    checkSplits(paramOr(options, "cascade_split1", SPLIT1), paramOr(options, "cascade_split2", SPLIT2));
  }

  std::string name() const override { return "pbr"; }

  void setup(Backend& b) override {
    // Assets first: a missing or corrupt file stops here, before anything is rendered.
    const MeshData cat = loadCatMesh(assetPath(options_, CAT_OBJ));
    std::vector<std::string> images;
    for (const char* image : {CAT_DIFF, CAT_NOR, CAT_ARM, BRICK_COLOR, BRICK_NOR, BRICK_ROUGH, BRICK_AO})
      images.push_back(assetPath(options_, image));
    std::vector<ImageRgba8> loaded = loadImagesRgba8(images);   // decoded in parallel

    prog_shadow_ = b.createProgram("shadow/shadow");   // depth only: the shadow scene's program
    prog_gbuffer_ = b.createProgram("pbr/gbuffer");
    prog_ssao_ = b.createProgram("pbr/post+ssao");
    prog_blur_ = b.createProgram("pbr/post+blur");
    prog_light_ = b.createProgram("pbr/post+lighting");
    cat_ = b.createMesh(cat);
    floor_ = b.createMesh(floorMesh());
    triangle_ = b.createMesh(triangleMesh());

    // The material maps: RGBA8, REPEAT, LINEAR, no mipmaps.
    for (size_t i = 0; i < maps_.size(); ++i) {
      const TextureDesc desc{loaded[i].width, loaded[i].height, TexelFormat::RGBA8,
                             {Filter::Linear, Wrap::Repeat, Wrap::Repeat, false}};
      maps_[i] = b.createTexture(desc, loaded[i].pixels.data());
      b.labelTexture(maps_[i], std::filesystem::path(images[i]).filename().string());
      loaded[i] = ImageRgba8{};   // each decoded image goes once uploaded (both backends copy)
    }

    // The SSAO kernel (a uniform array) and the 4x4 noise (REPEAT, NEAREST), once.
    FixedRandom rng;
    kernel_ = generateSsaoKernel(rng);
    const std::vector<float> noise = generateSsaoNoise(rng);
    noise_ = b.createTexture({4, 4, TexelFormat::RGBA32F, {Filter::Nearest, Wrap::Repeat, Wrap::Repeat, false}}, noise.data());
    b.labelTexture(noise_, "ssao_noise");

    // Three cascades, each its own depth texture, LINEAR with compare (sampler2DShadow).
    for (int c = 0; c < NUM_CASCADES; ++c) {
      cascade_tex_[c] = b.createTexture({CASCADE_DIM, CASCADE_DIM, TexelFormat::Depth24,
                                         {Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, true}});
      b.labelTexture(cascade_tex_[c], "shadow_cascade" + std::to_string(c));
      cascade_fbo_[c] = b.createFramebuffer({{}, cascade_tex_[c]});
    }

    // The G-buffer (see the top of this file for the formats), NEAREST, and the SSAO targets.
    const int w = std::max(options_.width, 1), h = std::max(options_.height, 1);
    const SamplerState nearest{Filter::Nearest, Wrap::ClampToEdge, Wrap::ClampToEdge, false};
    const TexelFormat formats[4] = {TexelFormat::RGBA8, TexelFormat::RGBA16F, TexelFormat::RGBA8, TexelFormat::RGBA16F};
    const char* const labels[4] = {"gbuffer_albedo", "gbuffer_normal", "gbuffer_mra", "gbuffer_emissive"};
    for (int i = 0; i < 4; ++i) {
      g_tex_[i] = b.createTexture({w, h, formats[i], nearest});
      b.labelTexture(g_tex_[i], labels[i]);
    }
    g_depth_ = b.createTexture({w, h, TexelFormat::Depth24, nearest});
    b.labelTexture(g_depth_, "gbuffer_depth");
    g_fbo_ = b.createFramebuffer({{g_tex_[0], g_tex_[1], g_tex_[2], g_tex_[3]}, g_depth_});
    const char* const ssaoLabels[3] = {"ssao", "ssao_blur_h", "ssao_blur"};
    for (int i = 0; i < 3; ++i) {
      ssao_tex_[i] = b.createTexture({w, h, TexelFormat::RGBA8, nearest});
      b.labelTexture(ssao_tex_[i], ssaoLabels[i]);
      ssao_fbo_[i] = b.createFramebuffer({{ssao_tex_[i]}, 0});
    }
    createFinalTarget(b, options_, /*depth=*/false);
  }

  void renderFrame(Backend& b, float t) override {
    const int w = std::max(options_.width, 1), h = std::max(options_.height, 1);
    const float split1 = paramOr(options_, "cascade_split1", SPLIT1), split2 = paramOr(options_, "cascade_split2", SPLIT2);
    // world_offset moves the models, the eye, its target and the point lights by (d, d, d);
    // unset, nothing is touched (the seed's bytes).
    const std::optional<float> worldOffset = options_.params.get("world_offset");
    auto moved = [&](glm::vec3 v) { return worldOffset ? v + glm::vec3(*worldOffset) : v; };
    const float cam_angle = t * 0.3f;
    const glm::vec3 cam = moved(glm::vec3(std::cos(cam_angle) * 4.6f, 2.3f, std::sin(cam_angle) * 4.6f));
    const glm::mat4 view = glm::lookAtRH(cam, moved(glm::vec3(0.0f, 1.0f, 0.0f)), glm::vec3(0, 1, 0));
    const float fovY = 50.0f * PI / 180.0f, aspect = float(w) / float(h);
    const glm::mat4 proj = glm::perspectiveRH_NO(fovY, aspect, NEAR_PLANE, FAR_PLANE);
    const float sun_yaw = t * 0.25f;
    const glm::vec3 sunDir = glm::normalize(glm::vec3(std::cos(sun_yaw) * 0.6f, 1.05f, std::sin(sun_yaw) * 0.6f));
    const float bounds[NUM_CASCADES + 1] = {NEAR_PLANE, split1, split2, FAR_PLANE};
    std::array<glm::mat4, NUM_CASCADES> lightVP;
    for (int c = 0; c < NUM_CASCADES; ++c) lightVP[size_t(c)] = cascadeMatrix(view, fovY, aspect, bounds[c], bounds[c + 1], sunDir);
    const glm::mat4 model = worldOffset ? glm::translate(glm::mat4(1.0f), glm::vec3(*worldOffset)) : glm::mat4(1.0f);

    // Passes 1-3: the cascades from the sun, with slope-scaled depth bias.
    ClearOp clearDepth;
    clearDepth.depth = true;
    DrawState shadowState;
    shadowState.polygonOffset = true;
    shadowState.offsetFactor = 2.0f;
    shadowState.offsetUnits = 4.0f;
    for (int c = 0; c < NUM_CASCADES; ++c) {
      b.labelNextPass("shadow_cascade" + std::to_string(c));
      b.beginPass(cascade_fbo_[c], {0, 0, CASCADE_DIM, CASCADE_DIM}, clearDepth);
      b.setUniform(prog_shadow_, "u_light_vp", lightVP[size_t(c)]);
      b.setUniform(prog_shadow_, "u_model", model);
      b.draw(prog_shadow_, floor_, shadowState);
      b.draw(prog_shadow_, cat_, shadowState);
    }

    // Pass 4: the G-buffer, floor then cat, the seven maps on units 0-6.
    ClearOp clearAll;
    clearAll.color = true;
    clearAll.colorValue = glm::vec4(0.0f);
    clearAll.depth = true;
    b.labelNextPass("gbuffer");
    b.beginPass(g_fbo_, {0, 0, w, h}, clearAll);
    const char* const samplers[7] = {"uAlbedoMap", "uNormalMap", "uMRAMap", "uFloorAlbedoMap",
                                     "uFloorNormalMap", "uFloorRoughnessMap", "uFloorAOMap"};
    for (int i = 0; i < 7; ++i) {
      b.bindTexture(i, maps_[size_t(i)]);
      b.setUniform(prog_gbuffer_, samplers[i], i);
    }
    b.setUniform(prog_gbuffer_, "u_view", view);
    b.setUniform(prog_gbuffer_, "u_proj", proj);
    b.setUniform(prog_gbuffer_, "u_model", model);
    b.setUniform(prog_gbuffer_, "uMaterial", 1.0f);
    b.draw(prog_gbuffer_, floor_, DrawState{});
    b.setUniform(prog_gbuffer_, "uMaterial", 0.0f);
    b.draw(prog_gbuffer_, cat_, DrawState{});

    // Pass 5: SSAO, no depth test.
    DrawState fullscreen;
    fullscreen.depthTest = false;
    b.labelNextPass("ssao");
    b.beginPass(ssao_fbo_[0], {0, 0, w, h}, ClearOp{});
    b.bindTexture(0, g_depth_);
    b.bindTexture(1, g_tex_[1]);
    b.bindTexture(2, noise_);
    b.setUniform(prog_ssao_, "uDepth", 0);
    b.setUniform(prog_ssao_, "uNormal", 1);
    b.setUniform(prog_ssao_, "uNoise", 2);
    for (int i = 0; i < KERNEL_SIZE; ++i)
      b.setUniform(prog_ssao_, "uSamples[" + std::to_string(i) + "]", kernel_[size_t(i)]);
    b.setUniform(prog_ssao_, "uProjection", proj);
    b.setUniform(prog_ssao_, "uInvProjection", glm::inverse(proj));
    b.setUniform(prog_ssao_, "uView", view);
    b.setUniform(prog_ssao_, "noiseScale", glm::vec2(float(w) / 4.0f, float(h) / 4.0f));
    b.setUniform(prog_ssao_, "uRadius", paramOr(options_, "ssao_radius", SSAO_RADIUS));
    b.setUniform(prog_ssao_, "uBias", paramOr(options_, "ssao_bias", SSAO_BIAS));
    b.draw(prog_ssao_, triangle_, fullscreen);

    // Passes 6-7: the separable Gaussian blur, along x then along y.
    for (int pass = 0; pass < 2; ++pass) {
      b.labelNextPass(pass == 0 ? "ssao_blur_h" : "ssao_blur");
      b.beginPass(ssao_fbo_[pass + 1], {0, 0, w, h}, ClearOp{});
      b.bindTexture(0, ssao_tex_[pass]);
      b.setUniform(prog_blur_, "uInput", 0);
      b.setUniform(prog_blur_, "uDirection", pass == 0 ? glm::vec2(1.0f / float(w), 0.0f) : glm::vec2(0.0f, 1.0f / float(h)));
      b.draw(prog_blur_, triangle_, fullscreen);
    }

    // Pass 8: lighting, tone mapping and gamma to the window.
    ClearOp clearScreen;
    clearScreen.color = true;
    clearScreen.colorValue = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    b.labelNextPass("final");
    b.beginPass(final_, {0, 0, w, h}, clearScreen);
    const Handle inputs[9] = {g_tex_[0], g_tex_[1], g_tex_[2], g_tex_[3], g_depth_, ssao_tex_[2],
                              cascade_tex_[0], cascade_tex_[1], cascade_tex_[2]};
    const char* const inputNames[9] = {"gAlbedo", "gNormal", "gMRA", "gEmissive", "gDepth", "uSSAO",
                                       "uShadowMap0", "uShadowMap1", "uShadowMap2"};
    for (int i = 0; i < 9; ++i) {
      b.bindTexture(i, inputs[i]);
      b.setUniform(prog_light_, inputNames[i], i);
    }
    for (int c = 0; c < NUM_CASCADES; ++c) b.setUniform(prog_light_, "uLightVP[" + std::to_string(c) + "]", lightVP[size_t(c)]);
    b.setUniform(prog_light_, "cascadeSplits[0]", split1);
    b.setUniform(prog_light_, "cascadeSplits[1]", split2);
    b.setUniform(prog_light_, "uInvViewProj", glm::inverse(proj * view));
    b.setUniform(prog_light_, "uView", view);
    b.setUniform(prog_light_, "uCamPos", cam);
    b.setUniform(prog_light_, "uSunDir", sunDir);
    b.setUniform(prog_light_, "uSunColor", glm::vec3(3.2f, 2.9f, 2.5f));
    // Three point lights orbiting the cat, from t.
    const glm::vec3 colours[3] = {{6.0f, 2.2f, 1.0f}, {1.0f, 2.5f, 6.0f}, {1.5f, 5.0f, 1.5f}};
    for (int i = 0; i < 3; ++i) {
      const float fi = float(i), ang = t * 0.7f + fi * 2.0944f;
      const glm::vec3 pos = moved(glm::vec3(std::cos(ang) * 2.2f, 0.6f + 0.4f * std::sin(t + fi), std::sin(ang) * 2.2f));
      b.setUniform(prog_light_, "uPointPos[" + std::to_string(i) + "]", pos);
      b.setUniform(prog_light_, "uPointColor[" + std::to_string(i) + "]", colours[i]);
    }
    b.setUniform(prog_light_, "uRoughnessFloor", paramOr(options_, "roughness_floor", ROUGHNESS_FLOOR));
    b.setUniform(prog_light_, "uExposure", 1.0f);
    b.draw(prog_light_, triangle_, fullscreen);
  }

  std::vector<Target> readTargets(Backend& b) override {
    b.finish();
    std::vector<Target> targets;   // appended one by one: a braced list would copy every image
    for (int c = 0; c < NUM_CASCADES; ++c) targets.push_back({"shadow_cascade" + std::to_string(c), b.readDepth(cascade_fbo_[c])});
    targets.push_back({"gbuffer_albedo", b.readColor(g_fbo_, 0)});
    targets.push_back({"gbuffer_normal", b.readColor(g_fbo_, 1)});
    targets.push_back({"gbuffer_mra", b.readColor(g_fbo_, 2)});
    targets.push_back({"gbuffer_emissive", b.readColor(g_fbo_, 3)});
    targets.push_back({"gbuffer_depth", b.readDepth(g_fbo_)});
    targets.push_back({"ssao", b.readColor(ssao_fbo_[0], 0)});
    targets.push_back({"ssao_blur_h", b.readColor(ssao_fbo_[1], 0)});
    targets.push_back({"ssao_blur", b.readColor(ssao_fbo_[2], 0)});
    targets.push_back({"final", b.readColor(final_)});
    return targets;
  }

 private:
  SceneOptions options_;
  Handle prog_shadow_ = 0, prog_gbuffer_ = 0, prog_ssao_ = 0, prog_blur_ = 0, prog_light_ = 0;
  Handle cat_ = 0, floor_ = 0, triangle_ = 0, noise_ = 0;
  std::array<Handle, 7> maps_{};
  std::array<glm::vec3, KERNEL_SIZE> kernel_{};
  Handle cascade_tex_[NUM_CASCADES] = {}, cascade_fbo_[NUM_CASCADES] = {};
  Handle g_tex_[4] = {}, g_depth_ = 0, g_fbo_ = 0;
  Handle ssao_tex_[3] = {}, ssao_fbo_[3] = {};
};

}  // namespace

SceneEntry pbrScene() {
  return {
      .name = "pbr",
      .description = "deferred PBR: real assets (OBJ, 2K JPEGs), 4-attachment G-buffer, three cascaded shadow maps with 5x5 PCF, "
                     "64-sample SSAO and a separable blur, Cook-Torrance GGX, ACES tone mapping",
      .seed = "004_c2461eff6b055266.txt",
      .make = [](const SceneOptions& options) -> std::unique_ptr<Scene> { return std::make_unique<PbrScene>(options); },
      .params = {param::time(), param::size(),
                 {"cascade_split1", 0.2, 29.9, false, "m", "4",
                  "view depth where cascade 0 ends and 1 begins; must stay below cascade_split2 (a seam moves with it)"},
                 {"cascade_split2", 0.2, 29.9, false, "m", "10",
                  "view depth where cascade 1 ends and 2 begins; the last cascade reaches the far plane (30 m)"},
                 {"ssao_radius", 0.001, 100, false, "m", "0.5",
                  "SSAO hemisphere radius in view space; large radii reach across depth edges"},
                 {"ssao_bias", 0, 10, false, "m", "0.025", "SSAO depth bias; toward 0, self-occlusion (acne) on flat surfaces"},
                 {"roughness_floor", 0, 1, false, "", "0.04",
                  "lowest GGX roughness, max(map, floor): toward 0 the lobe would become a spike (a2 -> 0), but the maps seen at t = 1 "
                  "go no lower than 0.16, so below that it changes nothing"},
                 param::worldOffset()},
      .programs = {shaders::shadow::shadowProgram(), shaders::pbr::gbufferProgram(), shaders::pbr::ssaoProgram(),
                   shaders::pbr::blurProgram(), shaders::pbr::lightingProgram()},
      .assets = {CAT_OBJ, CAT_DIFF, CAT_NOR, CAT_ARM, BRICK_COLOR, BRICK_NOR, BRICK_ROUGH, BRICK_AO},
      .sweeps = {"roughness_floor=0.5:0.0001:9:log",
                 "cascade_split1=0.5:9:7",
                 "ssao_radius=0.05:5:7:log",
                 "time=1:1e10:11:log",
                 "world_offset=1:1e6:13:log",
                 "size=1:8192:10:log --no-softpipe"},
      .coarseSweeps = {},   // its SSAO noise tile under coarse rates: measured with compare (STABILITY.md)
  };
}

}  // namespace scenes
