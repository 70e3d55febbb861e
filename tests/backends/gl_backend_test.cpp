// Tests of GlBackend (backends/gl_backend.cpp): the OSMesa context, clears and their
// read-back (bytes, half floats, depth codes), orientation of read-back images, program
// loading from $RASTER_SOURCE_DIR/shaders_cpp and its errors.
//
// Backends are created one after another (one GlBackend may exist at a time).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "backends/backends.h"
#include "scenes/program_registry.h"
#include "scenes/registry.h"
#include "shaders_cpp/test/passthrough.h"

namespace {

using namespace scenes;
namespace fs = std::filesystem;

// A pass-through vertex shader and a fragment shader writing a uniform colour.
constexpr const char* kFlatVert = R"(#version 330 core
layout(location = 0) in vec2 position;
void main() { gl_Position = vec4(position, 0.0, 1.0); }
)";
constexpr const char* kFlatFrag = R"(#version 330 core
uniform vec4 color;
layout(location = 0) out vec4 fragColor;
void main() { fragColor = color; }
)";

// A temporary source root with shaders_cpp/test/{flat,broken}.{vert,frag}, and
// RASTER_SOURCE_DIR pointing at it for the object's lifetime (restored after).
class TempShaderRoot {
 public:
  TempShaderRoot() : root_(fs::temp_directory_path() / ("gl_backend_test_" + std::to_string(getpid()))) {
    fs::create_directories(root_ / "shaders_cpp/test");
    write("flat.vert", kFlatVert);
    write("flat.frag", kFlatFrag);
    write("broken.vert", kFlatVert);
    write("broken.frag", "#version 330 core\nvoid main() { undeclared = 1.0; }\n");
    if (const char* old = std::getenv("RASTER_SOURCE_DIR")) previous_ = old;
    setenv("RASTER_SOURCE_DIR", root_.c_str(), 1);
  }
  ~TempShaderRoot() {
    if (previous_) setenv("RASTER_SOURCE_DIR", previous_->c_str(), 1);
    else unsetenv("RASTER_SOURCE_DIR");
    fs::remove_all(root_);
  }

 private:
  void write(const std::string& name, const char* text) { std::ofstream(root_ / "shaders_cpp/test" / name) << text; }
  fs::path root_;
  std::optional<std::string> previous_;
};

// The message of the std::runtime_error `f` throws ("" when it throws none).
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// A triangle covering the upper-left half of the top half of NDC: (-1,0), (1,0), (-1,1).
MeshData topTriangle() {
  MeshData mesh;
  mesh.vertices = {-1.0f, 0.0f, 1.0f, 0.0f, -1.0f, 1.0f};
  mesh.strideFloats = 2;
  mesh.attributes = {{0, 2, 0}};
  mesh.indices = {0, 1, 2};
  return mesh;
}

// RGBA bytes of pixel (x, row) of a top-row-first image.
std::string pixel(const ImageData& image, int x, int row) {
  size_t at = (size_t(row) * size_t(image.width) + size_t(x)) * 4;
  return std::to_string(image.rgba8[at]) + "," + std::to_string(image.rgba8[at + 1]) + "," +
         std::to_string(image.rgba8[at + 2]) + "," + std::to_string(image.rgba8[at + 3]);
}

// Draws topTriangle() in green over a clear of dark blue into `framebuffer` (16 x 16)
// and checks the picture: the triangle is in the first rows, the bottom half is clear.
void checkTopTriangle(Backend& backend, Handle framebuffer) {
  Handle program = backend.createProgram("test/flat");
  Handle mesh = backend.createMesh(topTriangle());
  ClearOp clear;
  clear.color = true;
  clear.colorValue = {0.0f, 0.0f, 0.2f, 1.0f};
  clear.depth = true;
  backend.beginPass(framebuffer, {0, 0, 16, 16}, clear);
  backend.setUniform(program, "color", glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  backend.setUniform(program, "not_a_uniform", 1.0f);  // ignored, as GL does
  DrawState state;
  state.cull = CullMode::Back;  // the triangle is counter-clockwise: front-facing
  backend.draw(program, mesh, state);
  backend.finish();

  ImageData image = backend.readColor(framebuffer);
  REQUIRE(image.width == 16);
  REQUIRE(image.height == 16);
  const std::string green = "0,255,0,255", clearColor = "0,0,51,255";
  CHECK(pixel(image, 0, 0) == green);        // top-left corner: inside
  CHECK(pixel(image, 0, 7) == green);        // just above the middle, left edge
  CHECK(pixel(image, 15, 0) == clearColor);  // top-right corner: above the hypotenuse
  for (int row = 8; row < 16; ++row)
    for (int x = 0; x < 16; ++x) CHECK(pixel(image, x, row) == clearColor);
}

}  // namespace

TEST_SUITE("gl_backend") {
  TEST_CASE("the OSMesa context comes up on llvmpipe (or the GALLIUM_DRIVER asked for)") {
    const char* driver = std::getenv("GALLIUM_DRIVER");
    auto backend = makeGlBackend();
    CHECK(backend->name() == std::string(driver != nullptr ? driver : "llvmpipe"));
  }

  TEST_CASE("clear colours read back exactly") {
    auto backend = makeGlBackend();
    ClearOp clear;
    clear.color = true;
    clear.colorValue = {1.0f, 0.5f, 0.0f, 0.2f};  // bytes: round(x * 255)

    SUBCASE("default framebuffer") {
      backend->resizeDefaultFramebuffer(8, 4);
      backend->beginPass(kDefaultFramebuffer, {0, 0, 8, 4}, clear);
      ImageData image = backend->readColor(kDefaultFramebuffer);
      REQUIRE(image.width == 8);
      REQUIRE(image.height == 4);
      CHECK(image.format == TexelFormat::RGBA8);
      for (int i = 0; i < 8 * 4; ++i) CHECK(pixel(image, i % 8, i / 8) == "255,128,0,51");
    }
    SUBCASE("RGBA16F attachment: exact half values, unclamped") {
      TextureDesc desc{4, 4, TexelFormat::RGBA16F, {}};
      FramebufferDesc fbDesc;
      fbDesc.colorTextures = {backend->createTexture(desc)};
      Handle fb = backend->createFramebuffer(fbDesc);
      clear.colorValue = {0.1f, -2.0f, 1000.0f, 0.5f};
      backend->beginPass(fb, {0, 0, 4, 4}, clear);
      ImageData image = backend->readColor(fb);
      REQUIRE(image.floats.size() == 4 * 4 * 4);
      CHECK(image.format == TexelFormat::RGBA16F);
      // 0.1 rounds to the half 1638 / 16384; the others are exact halves.
      for (int i = 0; i < 16; ++i) {
        CHECK(image.floats[size_t(i) * 4 + 0] == 1638.0f / 16384.0f);
        CHECK(image.floats[size_t(i) * 4 + 1] == -2.0f);
        CHECK(image.floats[size_t(i) * 4 + 2] == 1000.0f);
        CHECK(image.floats[size_t(i) * 4 + 3] == 0.5f);
      }
    }
  }

  TEST_CASE("depth clears read back as round(z * (2^bits - 1))") {
    // Mesa clears to the nearest code of the double z: 0.3f -> 5033164.7 -> 5033165
    // (not 5033164, which a float product 5033164.5 rounded half-to-even would give).
    auto backend = makeGlBackend();
    ClearOp clear;
    clear.depth = true;
    for (float z : {0.3f, 0.0f, 1.0f, 0.123456f}) {
      for (TexelFormat format : {TexelFormat::Depth24, TexelFormat::Depth16}) {
        int bits = format == TexelFormat::Depth24 ? 24 : 16;
        CAPTURE(z);
        CAPTURE(bits);
        TextureDesc desc{5, 3, format, {}};
        FramebufferDesc fbDesc;
        fbDesc.depthTexture = backend->createTexture(desc);
        Handle fb = backend->createFramebuffer(fbDesc);
        clear.depthValue = z;
        backend->beginPass(fb, {0, 0, 5, 3}, clear);
        ImageData image = backend->readDepth(fb);
        CHECK(image.depthBits == bits);
        REQUIRE(image.depth.size() == 5 * 3);
        auto expected = uint32_t(std::lround(double(z) * (std::ldexp(1.0, bits) - 1.0)));
        for (uint32_t code : image.depth) CHECK(code == expected);
      }
    }
    CHECK(uint32_t(std::lround(double(0.3f) * 16777215.0)) == 5033165u);

    // The default framebuffer has 24-bit depth.
    clear.depthValue = 0.3f;
    backend->resizeDefaultFramebuffer(4, 4);
    backend->beginPass(kDefaultFramebuffer, {0, 0, 4, 4}, clear);
    ImageData image = backend->readDepth(kDefaultFramebuffer);
    CHECK(image.depthBits == 24);
    for (uint32_t code : image.depth) CHECK(code == 5033165u);
  }

  TEST_CASE("a triangle in the top half of NDC is in the first rows read back") {
    TempShaderRoot shaders;
    auto backend = makeGlBackend();
    SUBCASE("RGBA8 framebuffer object") {
      TextureDesc color{16, 16, TexelFormat::RGBA8, {}};
      TextureDesc depth{16, 16, TexelFormat::Depth24, {}};
      FramebufferDesc fbDesc;
      fbDesc.colorTextures = {backend->createTexture(color)};
      fbDesc.depthTexture = backend->createTexture(depth);
      checkTopTriangle(*backend, backend->createFramebuffer(fbDesc));
    }
    SUBCASE("default framebuffer") {
      backend->resizeDefaultFramebuffer(16, 16);
      checkTopTriangle(*backend, kDefaultFramebuffer);
    }
  }

  TEST_CASE("two instances with additive blending add up; a mistyped uniform throws") {
    TempShaderRoot shaders;
    auto backend = makeGlBackend();
    TextureDesc color{16, 16, TexelFormat::RGBA8, {}};
    FramebufferDesc fbDesc;
    fbDesc.colorTextures = {backend->createTexture(color)};
    Handle fb = backend->createFramebuffer(fbDesc);
    Handle program = backend->createProgram("test/flat");
    Handle mesh = backend->createMesh(topTriangle());
    ClearOp clear;
    clear.color = true;
    backend->beginPass(fb, {0, 0, 16, 16}, clear);
    backend->setUniform(program, "color", glm::vec4(0.25f));
    DrawState state;
    state.depthTest = false;
    state.blendAdditive = true;
    backend->draw(program, mesh, state, 2);
    ImageData image = backend->readColor(fb);
    CHECK(pixel(image, 0, 0) == "128,128,128,128");  // 2 x round(0.25 * 255)
    CHECK(pixel(image, 0, 15) == "0,0,0,0");
    CHECK_THROWS_AS(backend->setUniform(program, "color", 1.0f), std::runtime_error);
  }

  TEST_CASE("program errors name the file") {
    TempShaderRoot shaders;
    auto backend = makeGlBackend();
    std::string missing = errorOf([&] { backend->createProgram("test/no_such_program"); });
    CHECK(missing.find("test/no_such_program.vert") != std::string::npos);
    std::string broken = errorOf([&] { backend->createProgram("test/broken"); });
    CHECK(broken.find("test/broken.frag") != std::string::npos);
    CHECK(broken.find("undeclared") != std::string::npos);  // the GL info log
  }

  // A port's uniforms must be the GLSL's: test/flat's GLSL has `color`; one port spells
  // it `colour` (a name the GLSL lacks, and `color` never set), one adds `gain`.
  TEST_CASE("a program whose C++ port's uniform names differ from its GLSL's is refused, naming both") {
    TempShaderRoot shaders;
    auto writeFlat = [](const std::string& name) {
      const fs::path folder = fs::path(std::getenv("RASTER_SOURCE_DIR")) / "shaders_cpp/test";
      std::ofstream(folder / (name + ".vert")) << kFlatVert;
      std::ofstream(folder / (name + ".frag")) << kFlatFrag;
    };
    writeFlat("flat_misspelt");
    writeFlat("flat_extra");
    scenes::ProgramEntry misspelt = scenes::programEntry<shaders::test::Passthrough>();
    misspelt.name = "test/flat_misspelt";
    misspelt.uniforms = {"colour"};
    scenes::registerProgram(misspelt);
    scenes::ProgramEntry extra = misspelt;
    extra.name = "test/flat_extra";
    extra.uniforms = {"color", "gain"};
    scenes::registerProgram(extra);
    auto backend = makeGlBackend();
    const std::string notInPort = errorOf([&] { backend->createProgram("test/flat_misspelt"); });
    CHECK(notInPort.find("program test/flat_misspelt") != std::string::npos);
    CHECK(notInPort.find("uniform 'color' is active in the GLSL, but the C++ port has no uniform of that name (its uniforms: colour)") !=
          std::string::npos);
    const std::string notInGlsl = errorOf([&] { backend->createProgram("test/flat_extra"); });
    CHECK(notInGlsl.find("the C++ port's uniform 'gain' is not a uniform of the GLSL") != std::string::npos);
    CHECK(notInGlsl.find("flat_extra.frag") != std::string::npos);
  }

  TEST_CASE("a second live GlBackend is refused") {
    auto backend = makeGlBackend();
    CHECK_THROWS_AS(makeGlBackend(), std::runtime_error);
  }
}
