// The scene registry: one row per scene, the only list of scenes in the project.
//
// A scene is its folder in scenes/ (host code, parameters, this row) and its folder in
// shaders_cpp/ (each GLSL file beside its C++ port); builtin_scenes.cpp holds one line per
// scene that adds its row. Everything generic takes the scene list from here: `raster scenes`
// (and `--json`, which the bench/ runners, setup.sh's profile training and
// bench/stability_sweeps.sh read), every command, every test that covers every scene, the
// report. CONTRIBUTING.md walks through adding one.
#pragma once

#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scenes/program_entry.h"
#include "scenes/scene.h"
#include "scenes/scene_params.h"

namespace scenes {

struct SceneEntry {
  std::string name;          // as typed: `raster render NAME`
  std::string description;   // one line: what it draws and what it exercises
  std::string seed;          // the tutorial document it ports (../shared/seeds/)
  std::function<std::unique_ptr<Scene>(const SceneOptions&)> make;
  // Its parameters (--set NAME=VALUE and `raster sweep`), in the order `raster params`
  // lists them; time and size first (scene_params.h has the shared ones).
  std::vector<ParamSpec> params;
  std::vector<ProgramEntry> programs;   // its shader programs (shaders_cpp/NAME/)
  std::vector<std::string> assets;      // files it reads, relative to the asset folder
  // The stability sweeps STABILITY.md charts (bench/stability_sweeps.sh): each as
  // `raster sweep NAME --param` takes it, "PARAM=FROM:TO:STEPS[:log]", optionally followed
  // by further sweep options ("size=1:8192:10:log --no-softpipe").
  std::vector<std::string> sweeps;
  // Where coarse shading fails (STABILITY.md, "Coarse shading"; bench/stability_sweeps.sh):
  // sweeps in the same form, each with the `--methods` it races against llvmpipe
  // ("instances=10:100000:5:log --methods gl,shading=2x2"), charted apart from the ones above.
  std::vector<std::string> coarseSweeps;
};

// Every row, the built-in scenes first in the order `raster scenes` lists them, then any
// registered at run time. A reference to a row stays valid when another is registered.
const std::deque<SceneEntry>& sceneRegistry();
// The row of `name`; SceneError naming the known scenes for an unknown one.
const SceneEntry& sceneEntry(const std::string& name);
std::vector<std::string> sceneNames();
// The scene `name` made by its row's factory (SceneError for an unknown name). Making one
// checks its options (SceneError for values it refuses) and does no other work: it reads no
// asset and touches no backend until setup(), so `raster sweep --check` makes one per value.
std::unique_ptr<Scene> makeScene(const std::string& name, const SceneOptions& options);

// Adds a row at run time, for a program that embeds the library or a test (a scene under a
// second name is one row). SceneError for an empty or taken name, or a row without a
// factory or time/size parameters. Not thread-safe: register before rendering.
void registerScene(SceneEntry entry);
// Shader programs outside every scene (the tests' probes); std::invalid_argument for a
// name already taken.
void registerProgram(ProgramEntry entry);
// Every program: each scene's, then those registered on their own.
std::vector<const ProgramEntry*> programRegistry();
// The program of that name, or null.
const ProgramEntry* findProgram(const std::string& name);

// A port's uniforms must be its GLSL's: every uniform GL reports active (`active`, array
// names with or without "[0]") is one of the port's, and every uniform of the port is
// declared in `glslSource` (both stages' text). Otherwise std::runtime_error naming the
// program, its files and the name: a misspelt name is an error, not an image difference.
// A program with no port in the registry (the GL backend's own tests) is not checked.
void checkPortUniforms(const std::string& program, const ProgramFiles& files, const std::vector<std::string>& active,
                       const std::string& glslSource);

// The built-in rows, one line per scene, and the programs outside every scene (`raster
// soup`'s): scenes/builtin_scenes.cpp. (The fuzz targets, which cannot compile the shader
// ports, link a row of their own instead: fuzz/fuzz_scenes.cpp.)
std::vector<SceneEntry> builtinScenes();
std::vector<ProgramEntry> builtinPrograms();

}  // namespace scenes
