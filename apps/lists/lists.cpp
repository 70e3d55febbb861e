// The listings (lists.h).
#include "apps/lists/lists.h"

#include <cstdio>
#include <iostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/common/number_text.h"
#include "apps/views/stage_views.h"
#include "raster/methods.h"
#include "scenes/registry.h"

namespace cli {
namespace {

nlohmann::json paramsJson(const std::vector<scenes::ParamSpec>& specs) {
  nlohmann::json list = nlohmann::json::array();
  for (const scenes::ParamSpec& p : specs)
    list.push_back({{"name", p.name}, {"min", p.min}, {"max", p.max}, {"integer", p.integer}, {"unit", p.unit},
                    {"default", p.byDefault}, {"meaning", p.meaning}});
  return list;
}

}  // namespace

void addMethodsOptions(CLI::App& command, MethodsArgs& args) {
  command.add_flag("--json", args.json, "As JSON: each step's methods (the default first) and each preset's methods and promise");
}

// `raster methods`: every step, its methods (the default first) and what each trades; then
// the presets as step=method lists, each with what it promises and where. With --json the
// same as one object, which bench/goal_runs.py reads its preset names from.
int listMethods(const MethodsArgs& args) {
  if (args.json) {
    nlohmann::json steps = nlohmann::json::array(), presets = nlohmann::json::array();
    for (const raster::StepInfo& step : raster::methodCatalog()) {
      nlohmann::json methods = nlohmann::json::array();
      for (size_t i = 0; i < step.methods.size(); ++i)
        methods.push_back({{"name", step.methods[i].name}, {"trade", step.methods[i].trade}, {"default", i == 0}});
      steps.push_back({{"name", step.name}, {"what", step.what}, {"methods", methods}});
    }
    for (const std::string& preset : raster::presetNames()) {
      nlohmann::json methods = nlohmann::json::object();
      for (const auto& [step, method] : raster::methodNames(raster::presetMethods(preset))) methods[step] = method;
      presets.push_back({{"name", preset}, {"methods", methods}, {"promise", raster::presetPromise(preset)}});
    }
    std::cout << nlohmann::json{{"steps", steps}, {"presets", presets}}.dump(2) << "\n";
    return 0;
  }
  for (const raster::StepInfo& step : raster::methodCatalog()) {
    std::cout << step.name << ": " << step.what << "\n";
    for (size_t i = 0; i < step.methods.size(); ++i)
      std::cout << "  " << step.name << "=" << step.methods[i].name << (i == 0 ? " (default)" : "") << "  "
                << step.methods[i].trade << "\n";
  }
  std::cout << "presets:\n";
  for (const std::string& preset : raster::presetNames()) {
    std::cout << "  " << preset << " ";
    for (const auto& [step, method] : raster::methodNames(raster::presetMethods(preset)))
      std::cout << " " << step << "=" << method;
    std::cout << "\n    promise: " << raster::presetPromise(preset) << "\n";
  }
  return 0;
}

void addParamsOptions(CLI::App& command, ParamsArgs& args) {
  command.add_option("scene", args.scene, "Scene")->required()->type_name("SCENE");
  command.add_flag("--json", args.json, "As JSON");
}

// `raster params SCENE`: one line per parameter, its range, default and meaning; with
// --json the same as a list of objects.
int listParams(const ParamsArgs& args) {
  const std::vector<scenes::ParamSpec>& specs = scenes::sceneEntry(args.scene).params;   // SceneError: exit 2
  if (args.json) {
    std::cout << paramsJson(specs).dump(2) << "\n";
    return 0;
  }
  std::cout << "parameters of " << args.scene << " (set with --set NAME=VALUE on render, compare, bench, tradeoff, sweep):\n";
  for (const scenes::ParamSpec& p : specs) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-16s %-16s default %-8s ", p.name.c_str(),
                  (sixDigits(p.min) + ".." + sixDigits(p.max) + (p.unit.empty() ? "" : " " + p.unit)).c_str(), p.byDefault.c_str());
    std::cout << line << p.meaning << "\n";
  }
  return 0;
}

void addScenesOptions(CLI::App& command, ScenesArgs& args) {
  command.add_flag("--json", args.json, "Every scene's row as JSON: description, seed, parameters, programs, assets, sweeps");
}

// `raster scenes`: the registry's names, one a line; with --json every row (name,
// description, seed, parameters, programs, assets, stability sweeps), which the bench/
// runners, setup.sh and bench/stability_sweeps.sh read.
int listScenes(const ScenesArgs& args) {
  if (!args.json) {
    for (const std::string& name : scenes::sceneNames()) std::cout << name << "\n";
    return 0;
  }
  nlohmann::json rows = nlohmann::json::array();
  for (const scenes::SceneEntry& row : scenes::sceneRegistry()) {
    nlohmann::json programs = nlohmann::json::array();
    for (const scenes::ProgramEntry& program : row.programs) programs.push_back(program.name);
    rows.push_back({{"name", row.name}, {"description", row.description}, {"seed", row.seed},
                    {"params", paramsJson(row.params)}, {"programs", programs}, {"assets", row.assets},
                    {"sweeps", row.sweeps}, {"coarse_sweeps", row.coarseSweeps}});
  }
  std::cout << rows.dump(2) << "\n";
  return 0;
}

// `raster views`: each stage view's name and what it shows, one a line.
int listViews() {
  for (const StageView& view : stageViews()) {
    char name[32];
    std::snprintf(name, sizeof name, "%-12s ", view.name);
    std::cout << name << view.shows << "\n";
  }
  return 0;
}

}  // namespace cli
