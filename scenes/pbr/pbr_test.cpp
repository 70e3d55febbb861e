// The pbr scene against llvmpipe, pass by pass (three cascades, four G-buffer attachments
// and depth, SSAO before and after each blur pass, final) at several times and odd sizes;
// the final pass in float; the parameters' checks; and the two GL features it added
// (a uniform array set element by element, a depth texture read through sampler2D), each
// exercised by a target that llvmpipe computes too.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "compare/metrics.h"
#include "scenes/program_registry.h"
#include "scenes/registry.h"
#include "shaders_cpp/pbr/ssao.h"
#include "tests/scene_test_helpers.h"

namespace {

namespace fs = std::filesystem;

// The share of the final pass's RGBA32F pixels bit-identical to llvmpipe's (see the case).
constexpr double kFloatFinalIdenticalAtLeast = 1.0;

void checkAgainstLlvmpipe(float t, int w, int h) {
  for (const compare::TargetStats& s : testing_support::compareWithLlvmpipe("pbr", t, w, h)) {
    INFO(s.name);
    CHECK(s.shareDiffering == 0.0);   // every target bit-identical
  }
}

std::string cli() { return RASTER_CLI_PATH; }

// Runs `raster render pbr ARGS`; returns the exit status and stderr.
std::pair<int, std::string> renderPbr(const std::string& args, const fs::path& out) {
  const fs::path err = fs::temp_directory_path() / ("raster-pbr-err-" + std::to_string(getpid()) + ".txt");
  const std::string command =
      "'" + cli() + "' render pbr " + args + " --out '" + out.string() + "' > /dev/null 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(err);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

}  // namespace

TEST_SUITE("scene_pbr") {
  TEST_CASE("t = 1.0 at 640x480 matches llvmpipe pass by pass") { checkAgainstLlvmpipe(1.0f, 640, 480); }
  TEST_CASE("t = 3.7 at 640x480 matches llvmpipe pass by pass") { checkAgainstLlvmpipe(3.7f, 640, 480); }
  TEST_CASE("t = 2.2 at an odd size, 333x197, matches llvmpipe") { checkAgainstLlvmpipe(2.2f, 333, 197); }
  TEST_CASE("t = 0.5 at 97x61 and at 1x1 match llvmpipe") {
    checkAgainstLlvmpipe(0.5f, 97, 61);
    checkAgainstLlvmpipe(0.5f, 1, 1);
  }

  // SSAO's rangeCheck is the built-in smoothstep, which Mesa multiplies nested to the right
  // (docs/porting.md, row smoothstep): here one SSAO pixel's float lay a rounding from
  // x.5 / 255, and the left-to-right order wrote it one step up.
  TEST_CASE("t = 1.922 at 201x438, where SSAO's smoothstep order shows in a byte, matches llvmpipe") {
    checkAgainstLlvmpipe(1.922f, 201, 438);
  }

  TEST_CASE("the final pass in RGBA32F: how many floats differ from llvmpipe's") {
    for (const auto& [w, h] : {std::pair{640, 480}, std::pair{333, 197}}) {
      const compare::TargetStats s = testing_support::compareFloatFinal("pbr", 1.0f, w, h);
      CHECK(s.kind == "float");
      MESSAGE(compare::formatStatsLine(s));
      CHECK(s.shareBitIdentical >= kFloatFinalIdenticalAtLeast);
    }
  }

  TEST_CASE("a split order that cannot work, or a value out of range, exits 2 with one line and no image") {
    const fs::path out = fs::temp_directory_path() / ("raster-pbr-" + std::to_string(getpid()) + ".png");
    for (const std::string& args : {std::string("--set cascade_split1=12 --set cascade_split2=6"),
                                    std::string("--set cascade_split1=5 --set cascade_split2=5")}) {
      CAPTURE(args);
      const auto [status, err] = renderPbr(args, out);
      CHECK(status == 2);
      CHECK(err.find("cascade splits must rise along view depth") != std::string::npos);
      CHECK_FALSE(fs::exists(out));
    }
    for (const std::string& args : {std::string("--set roughness_floor=2"), std::string("--set ssao_radius=0"),
                                    std::string("--set cascade_split2=40")}) {
      CAPTURE(args);
      const auto [status, err] = renderPbr(args, out);
      CHECK(status == 2);
      CHECK(err.find("--set") != std::string::npos);
      CHECK_FALSE(fs::exists(out));
    }
  }

  TEST_CASE("a uniform array is set element by element, the plain name being element 0, as in GL") {
    auto program = scenes::makeBoundProgram("pbr/post+ssao");
    // Setting through the names GL takes must not throw, and wrong names are ignored as GL does.
    program->setUniform("uSamples[63]", glm::vec3(1.0f, 2.0f, 3.0f));
    program->setUniform("uSamples", glm::vec3(4.0f));
    program->setUniform("uSamples[64]", glm::vec3(5.0f));   // past the end: no location in GL
    program->setUniform("uSamples[x]", glm::vec3(5.0f));
    program->setUniform("uRadius[0]", 9.0f);                // not an array
    CHECK_THROWS(program->setUniform("uSamples[1]", 1.0f));   // the wrong type, as glUniform1f on a vec3
    CHECK(scenes::program_detail::splitElementName("uSamples[12]").index == 12);
    CHECK(scenes::program_detail::splitElementName("uSamples[12]").base == "uSamples");
    CHECK(scenes::program_detail::splitElementName("uSamples").index == scenes::program_detail::kNotAnElement);
    CHECK(scenes::program_detail::splitElementName("uSamples[]").index != 0);
  }
}
