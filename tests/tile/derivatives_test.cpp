// dFdx / dFdy against GL (llvmpipe), with shaders_cpp/test/derivatives.{vert,frag,h}:
//   q = v.y * (v.x * v.x + 0.25),  p = v.x * v.y
//   out = (dFdx(q), dFdy(q), dFdx(p), dFdy(p * v.z))  into an RGBA16F target.
// The values must be bit-identical on every pixel, and the derivatives must be the fine
// (per row / per column of the 2x2 quad) ones llvmpipe computes: dFdx on a quad's second
// row is that row's own difference, not the first row's (coarse) one.
//
// Window coordinates: FBO quads pair GL rows (2k, 2k+1); images come back top row first,
// so GL row y is read-back row height - 1 - y.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "tests/gl_compare_helpers.h"

namespace {

using namespace gltest;

constexpr float kClear = 8192.0f;   // a half value no derivative here takes

ClearOp clearTo(float value) {
  ClearOp clear;
  clear.color = true;
  clear.colorValue = glm::vec4(value);
  return clear;
}

// Channel c of pixel (x, GL y) of a top-row-first float image.
float at(const ImageData& image, int x, int glY, int c) {
  const int row = image.height - 1 - glY;
  return image.floats[(size_t(row) * size_t(image.width) + size_t(x)) * 4 + size_t(c)];
}

DrawCall derivativesDraw(std::vector<Vertex> vertices) {
  DrawCall d;
  d.program = "test/derivatives";
  d.mesh = makeMesh(vertices);
  d.state.depthTest = false;
  return d;
}

// The fullscreen triangle with v = (window x * sx, window y * sy, 1, 0) at its corners
// (w = 1): v is then linear in window coordinates, v = (x * sx, y * sy) at the pixel centre.
std::vector<Vertex> screenAlignedTriangle(int width, int height, float sx, float sy) {
  const glm::vec2 ndc[3] = {{-1.0f, -1.0f}, {3.0f, -1.0f}, {-1.0f, 3.0f}};
  std::vector<Vertex> vertices;
  for (const glm::vec2& p : ndc) {
    const float wx = (p.x + 1.0f) * 0.5f * float(width), wy = (p.y + 1.0f) * 0.5f * float(height);
    vertices.push_back({glm::vec4(p.x, p.y, 0.0f, 1.0f), glm::vec4(wx * sx, wy * sy, 1.0f, 0.0f)});
  }
  return vertices;
}

double q(double x, double y) { return y * (x * x + 0.25); }

}  // namespace

TEST_SUITE("derivatives") {
  TEST_CASE("screen-aligned: fine dFdx/dFdy of x*x*y, bit-identical to GL, per row and per column") {
    BackendPair backends;
    constexpr int kSize = 64;
    constexpr float kScale = 1.0f / 8.0f;   // v = window position / 8
    const TargetDesc target{kSize, kSize, TexelFormat::RGBA16F, std::nullopt};
    const BothRendered r = renderBoth(backends, target, {derivativesDraw(screenAlignedTriangle(kSize, kSize, kScale, kScale))},
                                      clearTo(kClear));
    const FloatComparison cmp = compareFloatBits(*r.raster.color, *r.gl.color);
    MESSAGE("screen-aligned derivatives: " << cmp.diffs << " of " << kSize * kSize << " pixels differ from GL");
    CAPTURE(cmp.firstDiff);
    CHECK(cmp.diffs == 0);

    const ImageData& image = *r.raster.color;
    int rowsAlike = 0, columnsAlike = 0, offModel = 0, quadsBroken = 0;
    std::string firstOffModel;
    for (int y0 = 0; y0 < kSize; y0 += 2) {
      for (int x0 = 0; x0 < kSize; x0 += 2) {
        // Within a quad: dFdx is shared along each row, dFdy along each column.
        for (int d = 0; d < 2; ++d) {
          quadsBroken += at(image, x0, y0 + d, 0) != at(image, x0 + 1, y0 + d, 0);
          quadsBroken += at(image, x0 + d, y0, 1) != at(image, x0 + d, y0 + 1, 1);
        }
        // Fine: the second row's dFdx is its own, the second column's dFdy too.
        rowsAlike += at(image, x0, y0, 0) == at(image, x0, y0 + 1, 0);
        columnsAlike += at(image, x0, y0, 1) == at(image, x0 + 1, y0, 1);
        // Against the exact differences of q at the pixel centres, row by row / column by column.
        const double xa = (x0 + 0.5) * kScale, xb = (x0 + 1.5) * kScale;
        const double ya = (y0 + 0.5) * kScale, yb = (y0 + 1.5) * kScale;
        const double expect[4] = {q(xb, ya) - q(xa, ya), q(xb, yb) - q(xa, yb), q(xa, yb) - q(xa, ya), q(xb, yb) - q(xb, ya)};
        const float got[4] = {at(image, x0, y0, 0), at(image, x0, y0 + 1, 0), at(image, x0, y0, 1), at(image, x0 + 1, y0, 1)};
        for (int k = 0; k < 4; ++k) {
          if (std::fabs(double(got[k]) - expect[k]) > 2e-3 * std::fabs(expect[k]) + 1e-5) {
            if (offModel++ == 0)
              firstOffModel = "quad at (" + std::to_string(x0) + ", " + std::to_string(y0) + ") value " + std::to_string(k) +
                              ": " + std::to_string(got[k]) + " vs " + std::to_string(expect[k]);
          }
        }
      }
    }
    MESSAGE("quads whose two rows share dFdx: " << rowsAlike << ", whose two columns share dFdy: " << columnsAlike
                                               << ", values off the fine model: " << offModel);
    CAPTURE(firstOffModel);
    CHECK(quadsBroken == 0);
    CHECK(rowsAlike == 0);      // per-row dFdx (coarse would make every quad alike)
    CHECK(columnsAlike == 0);   // per-column dFdy
    CHECK(offModel == 0);
    // GL orientation in an FBO: q grows with window y, so dFdy(q) > 0 everywhere.
    int negativeDy = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) negativeDy += !(at(image, x, y, 1) > 0.0f);
    CHECK(negativeDy == 0);
  }

  TEST_CASE("random perspective triangles: derivatives bit-identical to GL on every pixel") {
    BackendPair backends;
    std::mt19937 rng(6006);
    for (const auto& size : {std::pair{64, 64}, std::pair{45, 38}}) {
      const int width = size.first, height = size.second;
      std::vector<Vertex> vertices;
      for (int i = 0; i < 60; ++i) {
        const glm::vec2 c(uniform(rng, 0.0f, float(width)), uniform(rng, 0.0f, float(height)));
        const float radius = uniform(rng, 3.0f, 40.0f);
        for (int v = 0; v < 3; ++v) {
          const glm::vec2 p = c + glm::vec2(uniform(rng, -radius, radius), uniform(rng, -radius, radius));
          const glm::vec4 value(uniform(rng, -2.0f, 2.0f), uniform(rng, -2.0f, 2.0f), uniform(rng, -2.0f, 2.0f), 0.0f);
          vertices.push_back({clipFromWindow(p, 0.0f, uniform(rng, 0.5f, 3.0f), width, height), value});
        }
      }
      const TargetDesc target{width, height, TexelFormat::RGBA16F, std::nullopt};
      const BothRendered r = renderBoth(backends, target, {derivativesDraw(vertices)}, clearTo(kClear));
      const FloatComparison cmp = compareFloatBits(*r.raster.color, *r.gl.color);
      int covered = 0;
      for (size_t i = 0; i < r.gl.color->floats.size(); i += 4) covered += r.gl.color->floats[i] != kClear;
      MESSAGE("random perspective derivatives " << width << "x" << height << ": " << covered << " covered pixels, "
                                                << cmp.diffs << " differ from GL");
      CAPTURE(cmp.firstDiff);
      CHECK(covered > width * height / 2);
      CHECK(cmp.diffs == 0);
    }
  }

  TEST_CASE("window-system framebuffer: dFdy keeps GL's sign (y up)") {
    // The default framebuffer is stored top row first, like llvmpipe's window-system
    // buffers; GL's dFdy must still be the derivative along window y (up). v.y grows with
    // window y, so dFdy(q) and dFdy(p * v.z) are positive and land inside (0, 1).
    BackendPair backends;
    constexpr int kWidth = 32, kHeight = 24;
    const TargetDesc target{kWidth, kHeight, std::nullopt, std::nullopt, true};
    ClearOp clear;
    clear.color = true;
    const BothRendered r = renderBoth(
        backends, target, {derivativesDraw(screenAlignedTriangle(kWidth, kHeight, 1.0f / kWidth, 0.25f))}, clear);
    const uint8_t clearBytes[4] = {0, 0, 0, 0};
    const Rgba8Comparison cmp = compareRgba8(*r.raster.color, *r.gl.color, clearBytes);
    MESSAGE("default framebuffer derivatives: " << cmp.coverageDiffs + cmp.colorDiffs << " of " << kWidth * kHeight
                                                << " pixels differ from GL (max step " << cmp.maxStep << ")");
    CAPTURE(cmp.firstCoverageDiff);
    CAPTURE(cmp.firstColorDiff);
    // Fails today on every pixel: the pipeline's dFdy is quadDdy of memory rows whatever the
    // framebuffer's orientation, so on this top-row-first buffer it is -dFdy (channels 1 and
    // 3 come out 0 where GL has the positive value). llvmpipe negates it for Y_0_TOP
    // framebuffers (nir_lower_wpos_ytransform, lower_fddy).
    CHECK(cmp.coverageDiffs + cmp.colorDiffs == 0);
    int glPositive = 0;
    for (size_t i = 0; i < r.gl.color->rgba8.size(); i += 4) glPositive += r.gl.color->rgba8[i + 1] > 0;
    CHECK(glPositive == kWidth * kHeight);   // the reference's own sign, for the record
  }
}
