// The GLSL transcendentals of raster/simd/gl_math.h against llvmpipe, bit for bit.
//
// 1. Through real GL: shaders_cpp/test/math_probe.{vert,frag,h} evaluates one built-in
//    (picked by the uniform u_func) per pixel of an RGBA32F target, on arguments carried by
//    varyings that are constant over each 1x1-pixel quad (so they interpolate exactly; the
//    probe writes them back out and the test checks they arrived unchanged; the arguments,
//    special values and each function's ranges are in math_probe_args.h). The same
//    draws run on this pipeline (its 8-wide AVX2 path and its Lanes<8> path) and on
//    llvmpipe, and every result must have the same bits, NaN payloads included.
//    Measured on this machine kind (AVX2/FMA x86-64, Mesa 22.3.6 llvmpipe): every function
//    here matched on every argument tried, so the test demands all of them; beyond these
//    draws, a standalone GL probe swept all 2^32 arguments of sin, cos and atan(x) and
//    every 4th bit pattern of exp2, log2, acos and pow(x, 48 | 2.2 | 0.4545), and 31
//    million random arguments of each function, with no difference.
// 2. Without GL (gl_math_lanes_test.cpp): the Float8 and Float8x2 (AVX2), Lanes<8> and
//    float instantiations agree bit for bit on millions of random arguments.
//
// Denormal arguments: llvmpipe's shaders run with DAZ/FTZ, so a denormal argument is a zero
// there, while this pipeline delivers it unchanged and the functions flush it themselves;
// their echo is checked against the flushed value on the GL side. llvmpipe's thread keeps
// denormals from a half-float draw's first block that fails its depth test on (simd/
// gl_math.h, the top), and this pipeline's renderer from its first depth-tested half-float
// pass: a second case draws the probe after an hdr frame, with denormal arguments a third of
// the time, and demands the same bits and the arguments unflushed; a third follows the rule
// draw by draw.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "backends/backends.h"
#include "scenes/registry.h"
#include "raster/simd/glsl.h"
#include "shaders_cpp/test/math_probe.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/simd/math_probe_args.h"

namespace {

using namespace gl_math_test;   // the probe's arguments (math_probe_args.h)

// Distance in units in the last place (on the ordered integer line of float bit patterns).
int64_t ulpDistance(float a, float b) {
  auto ordered = [](float f) {
    const int64_t i = int32_t(bitsOf(f));
    return i < 0 ? int64_t(INT32_MIN) - i : i;
  };
  return std::llabs(ordered(a) - ordered(b));
}

// ---- rendering ----------------------------------------------------------------------------
constexpr int kWidth = 256;
constexpr int kHeight = 128;

// One 1x1-pixel quad (two triangles, own vertices) per argument pair, row by row from the
// top of the read-back image: vertex = clip position (vec4), a_x (vec4), a_y (vec4).
scenes::MeshData probeMesh(const std::vector<Args>& args) {
  scenes::MeshData mesh;
  mesh.strideFloats = 12;
  mesh.attributes = {{0, 4, 0}, {1, 4, 4}, {2, 4, 8}};
  for (size_t i = 0; i < args.size(); ++i) {
    const int column = int(i % kWidth), row = int(i / kWidth);
    const float x0 = float(column), x1 = float(column + 1);
    const float y1 = float(kHeight - row), y0 = y1 - 1.0f;   // GL window y, up
    const auto base = uint32_t(mesh.vertices.size() / 12);
    for (const auto& [wx, wy] : {std::pair{x0, y0}, std::pair{x1, y0}, std::pair{x1, y1}, std::pair{x0, y1}}) {
      const float v[12] = {wx / kWidth * 2.0f - 1.0f, wy / kHeight * 2.0f - 1.0f, 0.0f, 1.0f,
                           args[i].x.value, args[i].x.scale, args[i].x.scale2, 0.0f,
                           args[i].y.value, args[i].y.scale, args[i].y.scale2, 0.0f};
      mesh.vertices.insert(mesh.vertices.end(), v, v + 12);
    }
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return mesh;
}

// Runs the probe for `func` over `args` (at most kWidth * kHeight) on a backend; returns the
// RGBA32F image, top row first.
scenes::ImageData runProbe(scenes::Backend& backend, int func, const std::vector<Args>& args) {
  const scenes::Handle target = backend.createTexture({kWidth, kHeight, scenes::TexelFormat::RGBA32F, {}});
  const scenes::Handle framebuffer = backend.createFramebuffer({{target}, 0});
  const scenes::Handle program = backend.createProgram(MathProbe::kName);
  const scenes::Handle mesh = backend.createMesh(probeMesh(args));
  scenes::ClearOp clear;
  clear.color = true;
  clear.colorValue = glm::vec4(-7.0f);
  backend.beginPass(framebuffer, {0, 0, kWidth, kHeight}, clear);
  backend.setUniform(program, "u_func", func);
  scenes::DrawState state;
  state.depthTest = false;
  state.depthWrite = false;
  backend.draw(program, mesh, state);
  backend.finish();
  return backend.readColor(framebuffer);
}

std::string functionName(int func) {
  static const char* names[] = {"exp2(x)",       "log2(x)",         "pow(x, y)",      "pow(x, 48.0)",
                                "pow(x, 2.2)",   "pow(x, 0.4545)",  "pow(x, 2.0)",    "pow(x, 4.0)",
                                "sin(x)",        "cos(x)",          "atan(x, y)",     "acos(x)",
                                "asin(x)",       "atan(x)",         "pow(vec3, vec3(2.2))", "pow(vec3, vec3 e)"};
  return names[func];
}

struct Agreement {
  size_t exact = 0, total = 0, echoBroken = 0;
  int64_t maxUlp = 0;
  std::string firstDiff, firstEchoBroken;
};

// Channel 0 (the result) bit for bit; channels 1-2 (the arguments) must equal the
// arguments sent, except denormals where llvmpipe flushes them on the way in (glFlushes).
Agreement compare(const scenes::ImageData& ours, const scenes::ImageData& gl, const std::vector<Args>& args, bool checkEcho,
                  bool glFlushes = true) {
  Agreement a;
  for (size_t i = 0; i < args.size(); ++i) {
    const float* o = &ours.floats[i * 4];
    const float* g = &gl.floats[i * 4];
    ++a.total;
    const float x = args[i].x.effective(), y = args[i].y.effective();
    if (bitsOf(o[0]) == bitsOf(g[0])) {
      ++a.exact;
    } else {
      a.maxUlp = std::max(a.maxUlp, ulpDistance(o[0], g[0]));
      if (a.firstDiff.empty()) {
        std::ostringstream s;
        s.precision(9);
        s << "x = " << x << " (0x" << std::hex << bitsOf(x) << "), y = " << std::dec << y << " (0x" << std::hex << bitsOf(y)
          << "): ours " << std::dec << o[0] << " (0x" << std::hex << bitsOf(o[0]) << "), gl " << std::dec << g[0] << " (0x"
          << std::hex << bitsOf(g[0]) << ")";
        a.firstDiff = s.str();
      }
    }
    if (!checkEcho) continue;
    for (int c = 1; c <= 2; ++c) {
      const float sent = c == 1 ? x : y;
      for (const float* image : {o, g}) {
        const bool flushedByGl = glFlushes && image == g && isDenormal(sent);
        const float expected = flushedByGl ? std::copysign(0.0f, sent) : sent;
        if (bitsOf(image[c]) != bitsOf(expected) && a.echoBroken++ == 0) {
          const Arg& arg = c == 1 ? args[i].x : args[i].y;
          std::ostringstream s;
          s.precision(9);
          s << (image == g ? "gl" : "ours") << " echoed argument " << c << " = (" << arg.value << " * " << arg.scale << ") * "
            << arg.scale2 << " as 0x" << std::hex << bitsOf(image[c]) << ", expected 0x" << bitsOf(expected);
          a.firstEchoBroken = s.str();
        }
      }
    }
  }
  return a;
}

// The probe for `func` over `args` on llvmpipe and on this pipeline's two lane paths (`fast`,
// the vector lanes; `reference`, Lanes<8>): both must give llvmpipe's bits, and the fast
// path's echo the arguments as llvmpipe received them (denormals flushed where `glFlushes`).
// `label` opens the message. Returns llvmpipe's image.
scenes::ImageData checkAgainstGl(scenes::Backend& gl, scenes::Backend& fast, scenes::Backend& reference, int func,
                                 const std::vector<Args>& args, bool glFlushes, const std::string& label) {
  const scenes::ImageData glImage = runProbe(gl, func, args);
  const scenes::ImageData fastImage = runProbe(fast, func, args);
  const scenes::ImageData referenceImage = runProbe(reference, func, args);
  REQUIRE(glImage.floats.size() == size_t(kWidth) * kHeight * 4);
  REQUIRE(fastImage.floats.size() == glImage.floats.size());
  REQUIRE(referenceImage.floats.size() == glImage.floats.size());
  const Agreement a = compare(fastImage, glImage, args, true, glFlushes);
  const Agreement r = compare(referenceImage, glImage, args, false);
  MESSAGE(label << ": " << a.exact << " of " << a.total << " results bit-identical to llvmpipe (max " << a.maxUlp
                << " ulp); Lanes<8> path " << r.exact << " of " << r.total);
  CAPTURE(a.firstDiff);
  CAPTURE(r.firstDiff);
  CAPTURE(a.firstEchoBroken);
  CHECK(a.echoBroken == 0);
  CHECK(a.exact == a.total);
  CHECK(r.exact == r.total);
  return glImage;
}

// Draws test/mrt's full-screen quad at depth 0 `times` times in one pass into a new target of
// `format`, with a Depth16 target and the depth test (LESS) where `depthTested`: from the
// second time on, every fragment fails its depth test.
void drawQuads(scenes::Backend& backend, scenes::TexelFormat format, bool depthTested, int times) {
  const scenes::Handle color = backend.createTexture({kWidth, kHeight, format, {}});
  const scenes::Handle depth = depthTested ? backend.createTexture({kWidth, kHeight, scenes::TexelFormat::Depth16, {}}) : 0;
  const scenes::Handle framebuffer = backend.createFramebuffer({{color}, depth});
  scenes::MeshData mesh;
  mesh.strideFloats = 8;
  mesh.attributes = {{0, 4, 0}, {1, 4, 4}};
  for (const auto& [x, y] : {std::pair{-1.0f, -1.0f}, std::pair{1.0f, -1.0f}, std::pair{1.0f, 1.0f}, std::pair{-1.0f, 1.0f}})
    mesh.vertices.insert(mesh.vertices.end(), {x, y, 0.0f, 1.0f, 0.5f, 0.25f, 0.125f, 1.0f});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  const scenes::Handle program = backend.createProgram("test/mrt");
  const scenes::Handle quad = backend.createMesh(mesh);
  scenes::ClearOp clear;
  clear.color = true;
  clear.depth = depthTested;
  backend.beginPass(framebuffer, {0, 0, kWidth, kHeight}, clear);
  scenes::DrawState state;
  state.depthTest = state.depthWrite = depthTested;
  for (int i = 0; i < times; ++i) backend.draw(program, quad, state);
  backend.finish();
}

}  // namespace

// The case's name, also its filter when it reruns itself: a filter that matched no case
// would pass with nothing run.
constexpr const char* kThroughGl = "every transcendental is bit-identical to llvmpipe through real GL";
constexpr const char* kKeptDenormals = "after an hdr frame every transcendental keeps denormals as llvmpipe does";
constexpr const char* kWhenKept = "llvmpipe keeps denormals after a half-float draw's block fails its depth test";

// Runs the test case `name` again in a fresh process of this binary, `environment` (shell
// assignments) before it, and checks that it passed and that its output holds `ranMarker`,
// a text its messages print: a filter that matched no case would pass with nothing run.
namespace {
void runInFreshProcess(const char* name, const std::string& environment, const std::string& ranMarker) {
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const cli_test::RunResult fresh =
      cli_test::runShell(std::filesystem::current_path(), environment + "exec " + cli_test::shellQuote(self) +
                                                              " --no-intro --test-case=" + cli_test::shellQuote(name));
  INFO("the case in a fresh process:\n" << fresh.out << fresh.err);
  CHECK(fresh.status == 0);
  CHECK(fresh.out.find(ranMarker) != std::string::npos);
}

// Whether the case `name` runs in this process: one with a single llvmpipe rasterizer thread
// (LP_NUM_THREADS=1), whose denormal mode only this process's draws have set, as no GL
// backend was made before. Otherwise it runs the case in such a process and says no.
bool runsHereWithOneLlvmpipeThread(const char* name, const std::string& ranMarker) {
  const char* lpThreads = std::getenv("LP_NUM_THREADS");
  if (scenes::glBackendsMade() == 0 && lpThreads != nullptr && std::string(lpThreads) == "1") return true;
  runInFreshProcess(name, "LP_NUM_THREADS=1 ", ranMarker);
  return false;
}
}  // namespace

TEST_SUITE("gl_math") {
  TEST_CASE(kThroughGl) {
    // The denormal echoes need llvmpipe's threads as they start, flushing denormals; after
    // an earlier GL test's draw into a half-float target some of them may not (see
    // scenes::glBackendsMade). ctest runs each suite in its own process; the whole test
    // binary run at once runs this case again in a fresh process of its own.
    if (scenes::glBackendsMade() > 0) {
      runInFreshProcess(kThroughGl, "", "results bit-identical to llvmpipe");
      return;
    }
    auto gl = scenes::makeGlBackend();
    auto fast = scenes::makeRasterBackend(0);
    auto reference = scenes::makeRasterBackend(0, true);   // the Lanes<8> path
    for (int func = 0; func < MathProbe::kFunctionCount; ++func) {
      CAPTURE(functionName(func));
      const std::vector<Args> args = argumentsFor(func, size_t(kWidth) * kHeight, 4242u + uint32_t(func));
      checkAgainstGl(*gl, *fast, *reference, func, args, true, functionName(func));
    }
  }

  TEST_CASE(kKeptDenormals) {
    // llvmpipe's rasterizer thread keeps denormals from a half-float draw's first block that
    // fails its depth test on (simd/gl_math.h, the top; the next case), as hdr's scene pass
    // has many. So the case draws an hdr frame first, with one llvmpipe thread; this
    // pipeline's renderer keeps denormals from that pass on.
    if (!runsHereWithOneLlvmpipeThread(kKeptDenormals, "denormal results from llvmpipe")) return;
    auto gl = scenes::makeGlBackend();
    auto fast = scenes::makeRasterBackend(0);
    auto reference = scenes::makeRasterBackend(0, true);   // the Lanes<8> path
    scenes::SceneOptions small;
    small.width = 64;
    small.height = 48;
    for (scenes::Backend* backend : {gl.get(), fast.get(), reference.get()}) {
      const auto hdr = scenes::makeScene("hdr", small);
      hdr->setup(*backend);
      hdr->renderFrame(*backend, 1.0f);
      backend->finish();
    }
    // A quarter of the first case's arguments: the suite's seconds are budgeted (tests/suites.cmake).
    const size_t count = size_t(kWidth) * kHeight / 4;
    size_t denormalArguments = 0, denormalResults = 0;
    for (int func = 0; func < MathProbe::kFunctionCount; ++func) {
      CAPTURE(functionName(func));
      const std::vector<Args> args = keptDenormalArguments(func, count, 977u + uint32_t(func));
      // The echo unflushed: llvmpipe delivered the denormal arguments, it kept them.
      const scenes::ImageData glImage =
          checkAgainstGl(*gl, *fast, *reference, func, args, false, functionName(func) + ", denormals kept");
      for (size_t i = 0; i < count; ++i) {
        denormalArguments += isDenormal(args[i].x.effective()) || isDenormal(args[i].y.effective());
        denormalResults += isDenormal(glImage.floats[i * 4]);
      }
    }
    // The mode is the one meant: denormals reached the functions and came out of some.
    MESSAGE(denormalArguments << " denormal arguments, " << denormalResults << " denormal results from llvmpipe");
    CHECK(denormalArguments > size_t(MathProbe::kFunctionCount) * count / 4);
    CHECK(denormalResults > 1000);
  }

  TEST_CASE(kWhenKept) {
    // The rule the renderer's model of llvmpipe's denormal mode follows (raster/renderer.h),
    // draw by draw: llvmpipe's blend code of a half-float target turns FTZ/DAZ off around its
    // conversion and restores it, but not in a block whose fragments the depth test has all
    // killed (the cause in the JIT code was not traced); the thread keeps denormals from
    // there on. After each draw below, the probe's sin over denormal arguments (every third)
    // on llvmpipe (one thread, a fresh process) and on this pipeline: llvmpipe keeps them
    // only at the end, and this pipeline gives its bits at every step but one, which it does
    // not draw (a depth-tested half-float pass where no block fails: this renderer cannot
    // know that none did, and keeps denormals from such a pass on).
    if (!runsHereWithOneLlvmpipeThread(kWhenKept, "denormals kept by llvmpipe")) return;
    auto gl = scenes::makeGlBackend();
    auto ours = scenes::makeRasterBackend(0);
    const std::vector<Args> args = keptDenormalArguments(MathProbe::kSin, size_t(kWidth) * kHeight / 4, 31u);
    const auto expect = [&](const std::string& after, bool kept, bool compared) {
      const scenes::ImageData glImage = runProbe(*gl, MathProbe::kSin, args);
      size_t denormals = 0, keptCount = 0;
      for (size_t i = 0; i < args.size(); ++i) {
        const float sent = args[i].x.effective();
        if (!isDenormal(sent)) continue;
        ++denormals;
        keptCount += bitsOf(glImage.floats[i * 4 + 1]) == bitsOf(sent);
      }
      MESSAGE("after " << after << ": " << keptCount << " of " << denormals << " denormals kept by llvmpipe");
      CAPTURE(after);
      CHECK(denormals > 1000);
      CHECK(keptCount == (kept ? denormals : 0u));
      if (!compared) return;
      const Agreement a = compare(runProbe(*ours, MathProbe::kSin, args), glImage, args, true, !kept);
      CAPTURE(a.firstDiff);
      CAPTURE(a.firstEchoBroken);
      CHECK(a.exact == a.total);
      CHECK(a.echoBroken == 0);
    };
    const auto both = [&](scenes::TexelFormat format, bool depthTested, int times) {
      for (scenes::Backend* backend : {gl.get(), ours.get()}) drawQuads(*backend, format, depthTested, times);
    };
    using scenes::TexelFormat;
    expect("nothing", false, true);
    both(TexelFormat::RGBA32F, true, 2);
    expect("a depth-tested quad twice into RGBA32F (the second failing everywhere)", false, true);
    both(TexelFormat::RGBA16F, false, 2);
    expect("a quad twice into RGBA16F without the depth test", false, true);
    drawQuads(*gl, TexelFormat::RGBA16F, true, 1);
    expect("a depth-tested quad once into RGBA16F, every fragment passing (llvmpipe alone)", false, false);
    both(TexelFormat::RGBA16F, true, 2);
    expect("a depth-tested quad twice into RGBA16F (the second failing everywhere)", true, true);
  }

  TEST_CASE("edge cases follow llvmpipe, not the C library") {
    using namespace raster::glsl;
    // lp_build_pow: pow(0, y) = 0 for every y (x == 0, or NaN, selects 0).
    CHECK(bitsOf(pow(0.0f, -1.0f)) == bitsOf(0.0f));
    CHECK(bitsOf(pow(0.0f, 0.0f)) == bitsOf(0.0f));
    CHECK(bitsOf(pow(kNaN, 2.0f)) == bitsOf(0.0f));
    CHECK(std::isnan(pow(-2.0f, 2.0f)));        // log2 of a negative number is NaN
    CHECK(pow<2.0f>(-2.0f) == 4.0f);            // but the literal exponent 2 is folded to x * x
    CHECK(pow<4.0f>(-2.0f) == 16.0f);
    CHECK(pow<1.0f>(-2.0f) == -2.0f);
    CHECK(std::isnan(pow<3.0f>(-2.0f)));
    CHECK(exp2(128.0f) == kInf);
    CHECK(exp2(-127.0f) == 0.0f);               // never a denormal: 2^ipart is 0 at -127
    CHECK(exp2(0.0f) == 1.0f);
    CHECK(log2(0.0f) == -kInf);
    CHECK(log2(1e-40f) == -kInf);               // DAZ
    CHECK(log2(kInf) == kInf);
    CHECK(std::isnan(log2(-1.0f)));
    CHECK(std::isnan(sin(kInf)));
    CHECK(std::isnan(cos(kNaN)));
    CHECK(bitsOf(sin(-0.0f)) == bitsOf(-0.0f));
    CHECK(cos(0.0f) == 1.0f);
    CHECK(bitsOf(atan(kNaN)) == bitsOf(0.0f));      // fsign(NaN) = 0 (unordered compare)
    CHECK(atan(1.0f, -1.0f) > 2.35f);
  }
}
