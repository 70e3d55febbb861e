// Fuzz target: the command line of `raster render` and `raster compare` (CLI11 parsing, then
// every check of apps/common/cli_options.cpp and of compare's thresholds), with the input
// split into arguments at newlines. A command line parses and validates, or is refused as
// bad input; nothing else may happen.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "apps/common/cli_options.h"
#include "apps/compare/compare.h"
#include "apps/render/render.h"
#include "io/output_file.h"
#include "fuzz/fuzz_common.h"
#include "scenes/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzzSetUpOnce();
  std::vector<std::string> args = {"raster"};
  std::string current;
  for (size_t i = 0; i < size && args.size() < 64; ++i) {
    const char c = char(data[i]);
    if (c == '\n') {
      args.push_back(current);
      current.clear();
    } else if (c != '\0') {
      current += c;
    }
  }
  args.push_back(current);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());

  CLI::App app{"fuzz", "raster"};
  app.require_subcommand(1);
  cli::RenderArgs render;
  cli::CompareArgs compare;
  CLI::App* renderCommand = app.add_subcommand("render");
  cli::addRenderOptions(*renderCommand, render);
  CLI::App* compareCommand = app.add_subcommand("compare");
  cli::addCompareOptions(*compareCommand, compare);
  try {
    app.parse(int(argv.size()), argv.data());
    if (renderCommand->parsed()) {
      cli::validateFrame(render);
      if (!render.out.empty()) cli::checkOutputFile("--out", render.out);
    } else if (compareCommand->parsed()) {
      cli::validateFrame(compare);
      cli::validateThresholds(compare);
    }
  } catch (const CLI::Error&) {
  } catch (const cli::UsageError&) {
  } catch (const scenes::SceneError&) {
  }
  return 0;
}
