// The shadow-map scene, ported from the seed's host code (create_gl_objects, update).
// Deviations decided for the project (seeds/README.md): glm::perspectiveRH_NO replaces the
// tutorial's perspective_rh_opengl; look_at_rh = glm::lookAtRH; ortho_rh = glm::orthoRH_NO;
// compose(t, q, s) = T * R * S; frame N renders at t = N / 60.
#include "scenes/shadow/shadow_scene.h"

#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "shaders_cpp/shadow/main.h"
#include "shaders_cpp/shadow/shadow.h"

namespace scenes {
namespace {

constexpr int SHADOW_DIM = 1024;
constexpr float CUBE_HOVER = 1.5f;
constexpr float PI = 3.14159265358979323846f;

// SceneVertex { pos : float3; normal : float3 }: 6 floats, pos at location 0, normal at 1.
MeshData sceneMesh(std::vector<float> vertices, std::vector<uint32_t> indices) {
  MeshData mesh;
  mesh.vertices = std::move(vertices);
  mesh.strideFloats = 6;
  mesh.attributes = {{0, 3, 0}, {1, 3, 3}};
  mesh.indices = std::move(indices);
  return mesh;
}

// Unit cube, 24 split vertices (one face normal per corner), spanning [-1, 1].
MeshData cubeMesh() {
  return sceneMesh(
      {
          1, 1, 1, 0, 0, 1,    -1, 1, 1, 0, 0, 1,    -1, -1, 1, 0, 0, 1,   1, -1, 1, 0, 0, 1,
          1, 1, 1, 1, 0, 0,    1, -1, 1, 1, 0, 0,    1, -1, -1, 1, 0, 0,   1, 1, -1, 1, 0, 0,
          1, 1, 1, 0, 1, 0,    1, 1, -1, 0, 1, 0,    -1, 1, -1, 0, 1, 0,   -1, 1, 1, 0, 1, 0,
          -1, 1, 1, -1, 0, 0,  -1, 1, -1, -1, 0, 0,  -1, -1, -1, -1, 0, 0, -1, -1, 1, -1, 0, 0,
          -1, -1, -1, 0, -1, 0, 1, -1, -1, 0, -1, 0, 1, -1, 1, 0, -1, 0,   -1, -1, 1, 0, -1, 0,
          1, -1, -1, 0, 0, -1, -1, -1, -1, 0, 0, -1, -1, 1, -1, 0, 0, -1,  1, 1, -1, 0, 0, -1,
      },
      {0, 1, 2, 2, 3, 0, 4, 5, 6, 6, 7, 4, 8, 9, 10, 10, 11, 8,
       12, 13, 14, 14, 15, 12, 16, 17, 18, 18, 19, 16, 20, 21, 22, 22, 23, 20});
}

// Floor quad in the XZ plane at y = 0, normal up, FLOOR_HALF = 5.
MeshData floorMesh() {
  return sceneMesh({-5, 0, -5, 0, 1, 0, 5, 0, -5, 0, 1, 0, 5, 0, 5, 0, 1, 0, -5, 0, 5, 0, 1, 0}, {0, 1, 2, 0, 2, 3});
}

// The cube's model matrix: hover + spin about a tilted axis, scaled to a tidy box.
glm::mat4 cube_model(float t) {
  const glm::quat rot = glm::angleAxis(t * 0.7f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)));
  return glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, CUBE_HOVER, 0.0f)) * glm::mat4_cast(rot) *
         glm::scale(glm::mat4(1.0f), glm::vec3(0.55f));
}

class ShadowScene final : public Scene {
 public:
  explicit ShadowScene(const SceneOptions& options) : options_(options) {}

  std::string name() const override { return "shadow"; }

  void setup(Backend& b) override {
    prog_shadow_ = b.createProgram("shadow/shadow");
    prog_main_ = b.createProgram("shadow/main");
    cube_ = b.createMesh(cubeMesh());
    floor_ = b.createMesh(floorMesh());
    // create_shadow_target: DEPTH_COMPONENT24, LINEAR, CLAMP_TO_EDGE, compare LEQUAL.
    TextureDesc depth;
    depth.width = depth.height = SHADOW_DIM;
    depth.format = TexelFormat::Depth24;
    depth.sampler = {Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, /*compareLequal=*/true};
    shadow_tex_ = b.createTexture(depth);
    b.labelTexture(shadow_tex_, "shadow_map");
    shadow_fbo_ = b.createFramebuffer({{}, shadow_tex_});
    createFinalTarget(b, options_, /*depth=*/true);
  }

  void renderFrame(Backend& b, float t) override {
    // --set NAME=VALUE (the parameters of this scene's row); unset, the seed's own value.
    const SceneParams& p = options_.params;
    const std::optional<float> worldOffset = p.get("world_offset"), lightElevation = p.get("light_elevation"), nearPlane = p.get("near"), offsetScale = p.get("offset_scale");
    // world_offset moves every model and both eyes by (d, d, d); unset, nothing is touched.
    auto moved = [&](glm::vec3 v) { return worldOffset ? v + glm::vec3(*worldOffset) : v; };
    auto placed = [&](const glm::mat4& model) {
      return worldOffset ? glm::translate(glm::mat4(1.0f), glm::vec3(*worldOffset)) * model : model;
    };
    const int display_w = options_.width, display_h = options_.height;
    const int h = std::max(display_h, 1);
    const float aspect = float(display_w) / float(h);

    // Directional light orbits in XZ, tilted up, so the cube's shadow sweeps the floor.
    const float sun_yaw = t * 0.6f;
    const glm::vec3 light_dir = lightElevation ? lightAtElevation(sun_yaw, *lightElevation)
                                                 : glm::normalize(glm::vec3(std::cos(sun_yaw), 1.4f, std::sin(sun_yaw)));
    const glm::vec3 light_eye = light_dir * 8.0f;
    const glm::mat4 light_view = glm::lookAtRH(moved(light_eye), moved(glm::vec3(0.0f)), glm::vec3(0, 1, 0));
    const glm::mat4 light_proj = glm::orthoRH_NO(-4.0f, 4.0f, -4.0f, 4.0f, 0.1f, 20.0f);
    const glm::mat4 u_light_vp = light_proj * light_view;

    // Camera orbits the scene, slightly elevated.
    const float cam_angle = t * 0.35f;
    const glm::vec3 cam_pos = moved(glm::vec3(std::cos(cam_angle) * 5.0f, 3.2f, std::sin(cam_angle) * 5.0f));
    const glm::mat4 u_view = glm::lookAtRH(cam_pos, moved(glm::vec3(0.0f, CUBE_HOVER * 0.5f, 0.0f)), glm::vec3(0, 1, 0));
    const glm::mat4 u_proj = glm::perspectiveRH_NO(50.0f * PI / 180.0f, aspect, nearPlane.value_or(0.1f), 50.0f);

    // Pass 1: shadow map from the light's point of view, with slope-scaled depth bias.
    ClearOp clearDepth;
    clearDepth.depth = true;
    b.labelNextPass("shadow_map");
    b.beginPass(shadow_fbo_, {0, 0, SHADOW_DIM, SHADOW_DIM}, clearDepth);
    DrawState shadowState;
    shadowState.polygonOffset = true;
    shadowState.offsetFactor = offsetScale ? 2.0f * *offsetScale : 2.0f;
    shadowState.offsetUnits = offsetScale ? 4.0f * *offsetScale : 4.0f;
    b.setUniform(prog_shadow_, "u_light_vp", u_light_vp);
    b.setUniform(prog_shadow_, "u_model", placed(cube_model(t)));
    b.draw(prog_shadow_, cube_, shadowState);
    b.setUniform(prog_shadow_, "u_model", placed(glm::mat4(1.0f)));
    b.draw(prog_shadow_, floor_, shadowState);

    // Pass 2: main scene from the camera, sampling the shadow map on unit 0.
    ClearOp clearAll;
    clearAll.color = true;
    clearAll.colorValue = glm::vec4(0.04f, 0.05f, 0.09f, 1.0f);
    clearAll.depth = true;
    b.labelNextPass("final");
    b.beginPass(final_, {0, 0, display_w, display_h}, clearAll);
    const DrawState mainState;
    b.bindTexture(0, shadow_tex_);
    b.setUniform(prog_main_, "shadow_map", 0);
    b.setUniform(prog_main_, "u_light_vp", u_light_vp);
    b.setUniform(prog_main_, "u_view", u_view);
    b.setUniform(prog_main_, "u_proj", u_proj);
    b.setUniform(prog_main_, "u_light_dir", light_dir);
    b.setUniform(prog_main_, "u_cam_pos", cam_pos);
    b.setUniform(prog_main_, "u_model", placed(cube_model(t)));
    b.setUniform(prog_main_, "u_is_floor", 0.0f);
    b.draw(prog_main_, cube_, mainState);
    b.setUniform(prog_main_, "u_model", placed(glm::mat4(1.0f)));
    b.setUniform(prog_main_, "u_is_floor", 1.0f);
    b.draw(prog_main_, floor_, mainState);
  }

  std::vector<Target> readTargets(Backend& b) override {
    b.finish();
    // Appended one by one: a braced list would copy every image (its elements are const).
    std::vector<Target> targets;
    targets.push_back({"shadow_map", b.readDepth(shadow_fbo_)});
    targets.push_back({"depth", b.readDepth(final_)});
    targets.push_back({"final", b.readColor(final_)});
    return targets;
  }

 private:
  SceneOptions options_;
  Handle prog_shadow_ = 0, prog_main_ = 0, cube_ = 0, floor_ = 0, shadow_tex_ = 0, shadow_fbo_ = 0;
};

}  // namespace

SceneEntry shadowScene() {
  return {
      .name = "shadow",
      .description = "\"08 - The Shadow Map\": depth-only pass with polygon offset, 1024x1024 Z24 shadow map, sampler2DShadow 3x3 PCF, clipping",
      .seed = "001_e52e56bd2ca24dc3.txt",
      .make = [](const SceneOptions& options) -> std::unique_ptr<Scene> { return std::make_unique<ShadowScene>(options); },
      // light_dir = normalize(cos, 1.4, sin): atan(1.4) above the ground
      .params = {param::time(), param::size(), param::lightElevation("54.46"), param::offsetScale(), param::nearPlane(),
                 param::worldOffset()},
      .programs = {shaders::shadow::shadowProgram(), shaders::shadow::mainProgram()},
      .assets = {},
      .sweeps = {"light_elevation=1:80:12:log",
                 "offset_scale=0:4:9",
                 "near=0.1:1e-6:11:log",
                 "world_offset=1:1e7:15:log",
                 "time=1:1e10:11:log",
                 "size=1:8192:10:log --no-softpipe"},
      .coarseSweeps = {},   // no post pass: a coarse rate changes nothing here
  };
}

}  // namespace scenes
