// The listings of what this build offers, each read from its registry:
//   raster methods [--json]       the methods of each pipeline step, and the presets (raster/methods.h);
//   raster scenes [--json]        the scenes, one a line; --json: every registry row (scenes/registry.h);
//   raster params SCENE [--json]  a scene's parameters, set with --set NAME=VALUE;
//   raster views                  the stage views of `render --view` (apps/views/stage_views.h).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace cli {

struct ScenesArgs {
  bool json = false;
};
void addScenesOptions(CLI::App& command, ScenesArgs& args);
int listScenes(const ScenesArgs& args);

struct ParamsArgs {
  std::string scene;
  bool json = false;
};
void addParamsOptions(CLI::App& command, ParamsArgs& args);
int listParams(const ParamsArgs& args);

struct MethodsArgs {
  bool json = false;
};
void addMethodsOptions(CLI::App& command, MethodsArgs& args);
int listMethods(const MethodsArgs& args);

int listViews();

}  // namespace cli
