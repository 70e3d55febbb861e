// Uniform arrays set element by element (scenes/program_registry.h), drawn by both backends:
// a scene uploads a kernel or a light list as `uSamples[i]`, one glUniform call per element,
// and expects what GL does with those names. Three draws of test/uniform_array (a vec3, a
// float and a mat4 array, one element per output channel, no arithmetic) into two RGBA32F
// attachments, with uniforms changed between draws:
//   1. every element set by its own name "u[i]";
//   2. some elements again, an array's plain name (GL: element 0), and names past the end
//      (GL: no location, ignored), the other elements keeping their values;
//   3. the plain name of another array, and a whole matrix element.
// GL's image must hold the values those rules give, and this pipeline's (SIMD and scalar
// lanes) must equal GL's bit for bit, at an odd size.
#include <doctest/doctest.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "tests/gl_compare_helpers.h"

namespace {

using namespace gltest;

constexpr int kWidth = 29, kHeight = 17;
// The three draws cover columns [0, 9), [9, 19), [19, 29) (edges on pixel boundaries).
constexpr int kColumnEdges[4] = {0, 9, 19, 29};

using Setting = std::pair<std::string, UniformValue>;

struct Outputs {
  ImageData vectors, scalars;
};

Outputs drawThree(Backend& b, const std::array<std::vector<Setting>, 3>& settings) {
  const Handle vectors = b.createTexture({kWidth, kHeight, TexelFormat::RGBA32F, {}});
  const Handle scalars = b.createTexture({kWidth, kHeight, TexelFormat::RGBA32F, {}});
  const Handle fb = b.createFramebuffer({{vectors, scalars}, 0});
  const Handle program = b.createProgram("test/uniform_array");
  b.beginPass(fb, {0, 0, kWidth, kHeight}, clearAll());
  DrawState state;
  state.depthTest = false;
  for (int d = 0; d < 3; ++d) {
    for (const auto& [name, value] : settings[size_t(d)]) b.setUniform(program, name, value);
    const float x0 = float(kColumnEdges[d]), x1 = float(kColumnEdges[d + 1]), h = float(kHeight);
    std::vector<Vertex> quad;
    for (const glm::vec2 p : {glm::vec2(x0, 0), glm::vec2(x1, 0), glm::vec2(x1, h), glm::vec2(x0, 0), glm::vec2(x1, h), glm::vec2(x0, h)})
      quad.push_back({clipFromWindow(p, 0.0f, 1.0f, kWidth, kHeight), glm::vec4(1.0f)});
    b.draw(program, b.createMesh(makeMesh(quad)), state);
  }
  b.finish();
  return {b.readColor(fb, 0), b.readColor(fb, 1)};
}

glm::mat4 filledMatrix(float base) {
  glm::mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = base + float(c * 4 + r) * 0.125f;
  return m;
}

}  // namespace

TEST_SUITE("shaders") {
  TEST_CASE("uniform arrays set element by element, by plain name and past the end, equal GL's rules and llvmpipe's bits") {
    std::array<std::vector<Setting>, 3> settings;
    settings[0] = {{"uVectors[0]", glm::vec3(1.5f, 2.5f, 3.5f)}, {"uVectors[1]", glm::vec3(4.25f, 5.25f, 6.25f)},
                   {"uVectors[2]", glm::vec3(7.75f, 8.75f, 9.75f)}, {"uScalars[0]", 0.1f}, {"uScalars[1]", -0.3f},
                   {"uMatrices[0]", filledMatrix(10.0f)}, {"uMatrices[1]", filledMatrix(20.0f)}};
    settings[1] = {{"uVectors[2]", glm::vec3(-1.0f, -2.0f, -3.0f)}, {"uScalars", 42.0f},
                   {"uVectors[3]", glm::vec3(99.0f)}, {"uScalars[2]", 99.0f}, {"uMatrices[2]", filledMatrix(99.0f)},
                   {"uMatrices[1]", filledMatrix(30.0f)}};
    settings[2] = {{"uVectors", glm::vec3(0.5f, 0.75f, 0.875f)}, {"uMatrices", filledMatrix(40.0f)}};
    // What GL's rules give, per draw: (uVectors[0].x, [1].y, [2].z, 1) and
    // (uScalars[0], uScalars[1], uMatrices[0][1].y, uMatrices[1][3].x).
    const glm::vec4 expectedVectors[3] = {{1.5f, 5.25f, 9.75f, 1.0f}, {1.5f, 5.25f, -3.0f, 1.0f}, {0.5f, 5.25f, -3.0f, 1.0f}};
    const glm::vec4 expectedScalars[3] = {{0.1f, -0.3f, filledMatrix(10.0f)[1].y, filledMatrix(20.0f)[3].x},
                                          {42.0f, -0.3f, filledMatrix(10.0f)[1].y, filledMatrix(30.0f)[3].x},
                                          {42.0f, -0.3f, filledMatrix(40.0f)[1].y, filledMatrix(30.0f)[3].x}};

    BackendPair backends;
    const std::unique_ptr<Backend> scalar = scenes::makeRasterBackend(2, /*scalarOnly=*/true);
    const Outputs gl = drawThree(*backends.gl, settings);
    int wrong = 0;
    for (int row = 0; row < kHeight; ++row)
      for (int x = 0; x < kWidth; ++x) {
        const int d = x < kColumnEdges[1] ? 0 : x < kColumnEdges[2] ? 1 : 2;
        const size_t p = (size_t(row) * kWidth + size_t(x)) * 4;
        for (int c = 0; c < 4; ++c) {
          wrong += gl.vectors.floats[p + size_t(c)] != expectedVectors[d][c];
          wrong += gl.scalars.floats[p + size_t(c)] != expectedScalars[d][c];
        }
      }
    CHECK_MESSAGE(wrong == 0, "GL: " << describeFloats(gl.vectors, 10, 3) << " / " << describeFloats(gl.scalars, 10, 3));
    for (Backend* side : {backends.raster.get(), scalar.get()}) {
      CAPTURE(side->name());
      const Outputs ours = drawThree(*side, settings);
      const FloatComparison v = compareFloatBits(ours.vectors, gl.vectors);
      const FloatComparison s = compareFloatBits(ours.scalars, gl.scalars);
      CHECK_MESSAGE(v.diffs == 0, v.firstDiff);
      CHECK_MESSAGE(s.diffs == 0, s.firstDiff);
    }
  }
}
