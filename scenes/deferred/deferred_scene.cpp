// "10 - Deferred Shading + MRT" (seed 000_a9faaef907542225.txt), ported from the seed's
// host code (init, setup_targets, create_shadow_target, update): a concrete cat statue on a
// brick floor, rendered in four passes: shadow map, G-buffer (RGBA8 + 2 x RGBA16F + 16-bit
// depth, one draw writes all three), SSAO, and lighting to the default framebuffer.
// Deviations decided for the project (seeds/README.md): glm::perspectiveRH_NO, lookAtRH,
// orthoRH_NO; the 1K normal map and the 1K HDR replace the tutorial's 2K files.
#include "scenes/deferred/deferred_scene.h"

#include <cmath>
#include <filesystem>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include "io/assets.h"
#include "shaders_cpp/deferred/gbuffer.h"
#include "shaders_cpp/deferred/lighting.h"
#include "shaders_cpp/deferred/ssao.h"
#include "shaders_cpp/shadow/shadow.h"

namespace scenes {
namespace {

constexpr int SHADOW_DIM = 1024;
constexpr float PI = 3.14159265358979323846f;

const char* const CAT_OBJ = "cat/concrete_cat_statue.obj";
const char* const CAT_DIFF = "cat/textures/concrete_cat_statue_diff_2k.jpg";
const char* const CAT_NOR = "cat/textures/concrete_cat_statue_nor_gl_1k.jpg";
const char* const CAT_ARM = "cat/textures/concrete_cat_statue_arm_2k.jpg";
const char* const BRICK_COLOR = "brick/Bricks031_1K-JPG_Color.jpg";
const char* const BRICK_NOR = "brick/Bricks031_1K-JPG_NormalGL.jpg";
const char* const BRICK_AO = "brick/Bricks031_1K-JPG_AmbientOcclusion.jpg";
const char* const BRICK_ROUGH = "brick/Bricks031_1K-JPG_Roughness.jpg";
const char* const HDRI = "hdri/cannon_1k.hdr";

// MeshVertex { pos : float3; normal : float3; uv : float2 }.
MeshData meshOf(std::vector<float> vertices, std::vector<uint32_t> indices) {
  MeshData mesh;
  mesh.vertices = std::move(vertices);
  mesh.strideFloats = 8;
  mesh.attributes = {{0, 3, 0}, {1, 3, 3}, {2, 2, 6}};
  mesh.indices = std::move(indices);
  return mesh;
}

MeshData floorMesh() {
  return meshOf({-6, 0, 6, 0, 1, 0, 0, 0, 6, 0, 6, 0, 1, 0, 1, 0, 6, 0, -6, 0, 1, 0, 1, 1, -6, 0, -6, 0, 1, 0, 0, 1},
                {0, 1, 2, 0, 2, 3});
}

// --set uv_scale (unset: the seed's cat) multiplies the cat's texture coordinates: its 2K
// maps (REPEAT) then wrap uv_scale times along each side, and their texels per pixel, the
// texture frequency on screen, rise with it. (The floor's coordinates come from its world
// position in the G-buffer shader, so the cat is the mesh whose uv reaches the lookups.)
void scaleTextureCoordinates(MeshData& mesh, float scale) {
  for (size_t v = 6; v + 1 < mesh.vertices.size(); v += size_t(mesh.strideFloats)) {
    mesh.vertices[v] *= scale;
    mesh.vertices[v + 1] *= scale;
  }
}

// The fullscreen triangle, drawn with glDrawArrays(GL_TRIANGLES, 0, 3).
MeshData quadMesh() { return meshOf({-1, -1, 0, 0, 0, 0, 0, 0, 3, -1, 0, 0, 0, 0, 0, 0, -1, 3, 0, 0, 0, 0, 0, 0}, {0, 1, 2}); }

class DeferredScene final : public Scene {
 public:
  explicit DeferredScene(const SceneOptions& options) : options_(options) {}

  std::string name() const override { return "deferred"; }

  void setup(Backend& b) override {
    // Assets first: a missing or corrupt file stops here, before anything is rendered.
    MeshData cat = loadCatMesh(assetPath(options_, CAT_OBJ));
    if (const std::optional<float> uvScale = options_.params.get("uv_scale")) scaleTextureCoordinates(cat, *uvScale);
    std::vector<std::string> images;
    for (const char* image : {CAT_DIFF, CAT_NOR, CAT_ARM, BRICK_COLOR, BRICK_NOR, BRICK_AO, BRICK_ROUGH})
      images.push_back(assetPath(options_, image));
    std::vector<ImageRgba8> loaded = loadImagesRgba8(images);   // decoded in parallel
    ImageRgbFloat env = loadHdrRgb(assetPath(options_, HDRI));

    // The seed's shadow_vs / shadow_fs are the shadow-map scene's shaders, word for word.
    prog_shadow_ = b.createProgram("shadow/shadow");
    prog_gbuffer_ = b.createProgram("deferred/gbuffer");
    prog_ssao_ = b.createProgram("deferred/post+ssao");
    prog_light_ = b.createProgram("deferred/post+lighting");
    cat_ = b.createMesh(cat);
    floor_ = b.createMesh(floorMesh());
    quad_ = b.createMesh(quadMesh());

    // load_image_from_file: RGBA8, REPEAT, LINEAR, no mipmaps.
    for (size_t i = 0; i < 7; ++i) {
      const TextureDesc desc{loaded[i].width, loaded[i].height, TexelFormat::RGBA8,
                             {Filter::Linear, Wrap::Repeat, Wrap::Repeat, false}};
      textures_[i] = b.createTexture(desc, loaded[i].pixels.data());
      b.labelTexture(textures_[i], std::filesystem::path(images[i]).filename().string());
      // Both backends copy what they are given: each decoded image goes as soon as it is
      // uploaded, so the 52 MiB of them never sit beside all the textures made from them
      // (docs/notes/2026-12-01-peak-memory.md).
      loaded[i] = ImageRgba8{};
    }
    // load_hdr_texture: RGB16F, REPEAT on s, CLAMP_TO_EDGE on t, LINEAR.
    tex_env_ = b.createTexture({env.width, env.height, TexelFormat::RGB16F, {Filter::Linear, Wrap::Repeat, Wrap::ClampToEdge, false}},
                               env.pixels.data());
    env = ImageRgbFloat{};
    b.labelTexture(tex_env_, std::filesystem::path(assetPath(options_, HDRI)).filename().string());

    // create_shadow_target
    shadow_tex_ = b.createTexture({SHADOW_DIM, SHADOW_DIM, TexelFormat::Depth24,
                                   {Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, true}});
    b.labelTexture(shadow_tex_, "shadow_map");
    shadow_fbo_ = b.createFramebuffer({{}, shadow_tex_});

    // setup_targets(w, h): G-buffer (3 MRT + depth 16) and the SSAO target.
    const int w = options_.width, h = options_.height;
    const SamplerState nearest{Filter::Nearest, Wrap::ClampToEdge, Wrap::ClampToEdge, false};
    const SamplerState linear{Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, false};
    g_albedo_ = b.createTexture({w, h, TexelFormat::RGBA8, nearest});
    g_normal_ = b.createTexture({w, h, TexelFormat::RGBA16F, nearest});
    g_worldpos_ = b.createTexture({w, h, TexelFormat::RGBA16F, nearest});
    g_depth_ = b.createTexture({w, h, TexelFormat::Depth16, nearest});
    b.labelTexture(g_albedo_, "gbuffer_albedo");
    b.labelTexture(g_normal_, "gbuffer_normal");
    b.labelTexture(g_worldpos_, "gbuffer_worldpos");
    b.labelTexture(g_depth_, "gbuffer_depth");
    g_fbo_ = b.createFramebuffer({{g_albedo_, g_normal_, g_worldpos_}, g_depth_});
    ssao_tex_ = b.createTexture({w, h, TexelFormat::RGBA8, linear});
    b.labelTexture(ssao_tex_, "ssao");
    ssao_fbo_ = b.createFramebuffer({{ssao_tex_}, 0});
    createFinalTarget(b, options_, /*depth=*/false);
  }

  void renderFrame(Backend& b, float t) override {
    // --set NAME=VALUE (the parameters of this scene's row); unset, the seed's own value.
    const SceneParams& p = options_.params;
    const std::optional<float> worldOffset = p.get("world_offset"), lightElevation = p.get("light_elevation"), nearPlane = p.get("near"), offsetScale = p.get("offset_scale");
    // world_offset moves every model and both eyes by (d, d, d); unset, nothing is touched.
    auto moved = [&](glm::vec3 v) { return worldOffset ? v + glm::vec3(*worldOffset) : v; };
    const int w = std::max(options_.width, 1), h = std::max(options_.height, 1);
    const float cam_angle = t * 0.3f;
    const glm::vec3 cam = moved(glm::vec3(std::cos(cam_angle) * 4.6f, 2.3f, std::sin(cam_angle) * 4.6f));
    const glm::mat4 u_view = glm::lookAtRH(cam, moved(glm::vec3(0.0f, 1.0f, 0.0f)), glm::vec3(0, 1, 0));
    const glm::mat4 u_proj =
        glm::perspectiveRH_NO(50.0f * PI / 180.0f, float(w) / float(h), nearPlane.value_or(0.1f), 60.0f);
    const float sun_yaw = t * 0.25f;
    const glm::vec3 light_dir = lightElevation ? lightAtElevation(sun_yaw, *lightElevation)
                                                 : glm::normalize(glm::vec3(std::cos(sun_yaw) * 0.6f, 1.05f, std::sin(sun_yaw) * 0.6f));
    const glm::mat4 u_light_vp = glm::orthoRH_NO(-4.0f, 4.0f, -4.0f, 4.0f, 0.1f, 20.0f) *
                                 glm::lookAtRH(moved(light_dir * 8.0f), moved(glm::vec3(0.0f, 0.8f, 0.0f)), glm::vec3(0, 1, 0));
    const glm::mat4 model = worldOffset ? glm::translate(glm::mat4(1.0f), glm::vec3(*worldOffset)) : glm::mat4(1.0f);

    // Pass 1: shadow map from the sun's POV, with slope-scaled depth bias.
    ClearOp clearDepth;
    clearDepth.depth = true;
    b.labelNextPass("shadow_map");
    b.beginPass(shadow_fbo_, {0, 0, SHADOW_DIM, SHADOW_DIM}, clearDepth);
    DrawState shadowState;
    shadowState.polygonOffset = true;
    shadowState.offsetFactor = offsetScale ? 2.0f * *offsetScale : 2.0f;
    shadowState.offsetUnits = offsetScale ? 4.0f * *offsetScale : 4.0f;
    b.setUniform(prog_shadow_, "u_light_vp", u_light_vp);
    b.setUniform(prog_shadow_, "u_model", model);
    b.draw(prog_shadow_, floor_, shadowState);
    b.draw(prog_shadow_, cat_, shadowState);

    // Pass 2: geometry -> G-buffer (MRT): floor then cat, the seven maps on units 0-6.
    ClearOp clearAll;
    clearAll.color = true;
    clearAll.colorValue = glm::vec4(0.0f);
    clearAll.depth = true;
    b.labelNextPass("gbuffer");
    b.beginPass(g_fbo_, {0, 0, w, h}, clearAll);
    const char* const samplers[7] = {"cat_albedo", "cat_normal", "cat_arm", "floor_albedo",
                                     "floor_normal", "floor_ao", "floor_roughness"};
    for (int i = 0; i < 7; ++i) {
      b.bindTexture(i, textures_[size_t(i)]);
      b.setUniform(prog_gbuffer_, samplers[i], i);
    }
    b.setUniform(prog_gbuffer_, "u_view", u_view);
    b.setUniform(prog_gbuffer_, "u_proj", u_proj);
    b.setUniform(prog_gbuffer_, "u_model", model);
    b.setUniform(prog_gbuffer_, "u_material", 1.0f);
    b.draw(prog_gbuffer_, floor_, DrawState{});
    b.setUniform(prog_gbuffer_, "u_material", 0.0f);
    b.draw(prog_gbuffer_, cat_, DrawState{});

    // Pass 3: SSAO into its own target, no depth test.
    DrawState fullscreen;
    fullscreen.depthTest = false;
    b.labelNextPass("ssao");
    b.beginPass(ssao_fbo_, {0, 0, w, h}, ClearOp{});
    b.bindTexture(0, g_normal_);
    b.bindTexture(1, g_worldpos_);
    b.setUniform(prog_ssao_, "ssao_g_normal", 0);
    b.setUniform(prog_ssao_, "ssao_g_worldpos", 1);
    b.setUniform(prog_ssao_, "u_view", u_view);
    b.setUniform(prog_ssao_, "u_proj", u_proj);
    b.draw(prog_ssao_, quad_, fullscreen);

    // Pass 4: deferred lighting to the screen.
    ClearOp clearScreen;
    clearScreen.color = true;
    clearScreen.colorValue = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    b.labelNextPass("final");
    b.beginPass(final_, {0, 0, w, h}, clearScreen);
    const Handle lightingInputs[6] = {g_albedo_, g_normal_, g_worldpos_, ssao_tex_, shadow_tex_, tex_env_};
    const char* const lightingSamplers[6] = {"lit_albedo", "lit_normal", "lit_worldpos", "lit_ssao", "shadow_map", "env_map"};
    for (int i = 0; i < 6; ++i) {
      b.bindTexture(i, lightingInputs[i]);
      b.setUniform(prog_light_, lightingSamplers[i], i);
    }
    b.setUniform(prog_light_, "u_cam_pos", cam);
    b.setUniform(prog_light_, "u_light_dir", light_dir);
    b.setUniform(prog_light_, "u_light_vp", u_light_vp);
    b.setUniform(prog_light_, "u_time", t);
    b.draw(prog_light_, quad_, fullscreen);
  }

  std::vector<Target> readTargets(Backend& b) override {
    b.finish();
    // Appended one by one: a braced list would copy every image (its elements are const).
    std::vector<Target> targets;
    targets.push_back({"shadow_map", b.readDepth(shadow_fbo_)});
    targets.push_back({"gbuffer_albedo", b.readColor(g_fbo_, 0)});
    targets.push_back({"gbuffer_normal", b.readColor(g_fbo_, 1)});
    targets.push_back({"gbuffer_worldpos", b.readColor(g_fbo_, 2)});
    targets.push_back({"gbuffer_depth", b.readDepth(g_fbo_)});
    targets.push_back({"ssao", b.readColor(ssao_fbo_, 0)});
    targets.push_back({"final", b.readColor(final_)});
    return targets;
  }

 private:
  SceneOptions options_;
  Handle prog_shadow_ = 0, prog_gbuffer_ = 0, prog_ssao_ = 0, prog_light_ = 0;
  Handle cat_ = 0, floor_ = 0, quad_ = 0;
  Handle textures_[7] = {};
  Handle tex_env_ = 0, shadow_tex_ = 0, shadow_fbo_ = 0;
  Handle g_albedo_ = 0, g_normal_ = 0, g_worldpos_ = 0, g_depth_ = 0, g_fbo_ = 0, ssao_tex_ = 0, ssao_fbo_ = 0;
};

}  // namespace

SceneEntry deferredScene() {
  return {
      .name = "deferred",
      .description = "\"10 - Deferred Shading + MRT\": real assets (OBJ, 2K JPEGs, HDR), MRT G-buffer (RGBA8 + 2 x RGBA16F + Z16), derivative normal mapping, SSAO, 5x5 PCF, point lights, equirectangular IBL",
      .seed = "000_a9faaef907542225.txt",
      .make = [](const SceneOptions& options) -> std::unique_ptr<Scene> { return std::make_unique<DeferredScene>(options); },
      // light_dir = normalize(0.6 cos, 1.05, 0.6 sin): atan(1.05 / 0.6) above the ground
      .params = {param::time(), param::size(), param::lightElevation("60.26"), param::offsetScale(), param::nearPlane(),
                 param::worldOffset(),
                 {"uv_scale", 1.0 / 64, 1024, false, "", "1",
                  "the cat's texture coordinates times this: its texels per pixel rise with it, toward aliasing, and a "
                  "coarse-shaded G-buffer (--method shading=2x2-all) samples them at a quarter of the rate"}},
      .programs = {shaders::shadow::shadowProgram(), shaders::deferred::gbufferProgram(),
                   shaders::deferred::ssaoProgram(), shaders::deferred::lightingProgram()},
      .assets = {CAT_OBJ, CAT_DIFF, CAT_NOR, CAT_ARM, BRICK_COLOR, BRICK_NOR, BRICK_AO, BRICK_ROUGH, HDRI},
      .sweeps = {"light_elevation=1:80:10:log",
                 "near=0.1:1e-6:11:log",
                 "world_offset=1:1e6:13:log",
                 "time=1:1e10:11:log",
                 "size=1:8192:10:log --no-softpipe"},
      // Texture frequency: the cat's and the floor's maps under a coarse G-buffer.
      .coarseSweeps = {"uv_scale=0.25:64:5:log --methods gl,shading=2x2,shading=2x2-all"},
  };
}

}  // namespace scenes
