// The scene registry (registry.h): one line per built-in scene, each row written in the
// scene's own folder; and the rows and programs added at run time.
#include "scenes/registry.h"

#include <algorithm>
#include <deque>
#include <stdexcept>

#include "scenes/deferred/deferred_scene.h"
#include "scenes/hdr/hdr_scene.h"
#include "scenes/shadow/shadow_scene.h"
#include "scenes/soup/soup_check.h"

namespace scenes {
namespace {

// A deque: a row registered later leaves the references to the others valid.
std::deque<SceneEntry>& rows() {
  static std::deque<SceneEntry> table = {
      shadowScene(),     // scenes/shadow/
      deferredScene(),   // scenes/deferred/
      hdrScene(),        // scenes/hdr/
  };
  return table;
}

// Programs outside every scene: `raster soup`'s, then any registered at run time.
std::deque<ProgramEntry>& standalonePrograms() {
  static std::deque<ProgramEntry> programs = [] {
    const std::vector<ProgramEntry> soup = soup::programs();
    return std::deque<ProgramEntry>(soup.begin(), soup.end());
  }();
  return programs;
}

std::string knownScenes() {
  std::string known;
  for (const SceneEntry& row : rows()) known += (known.empty() ? "" : ", ") + row.name;
  return known;
}

bool declares(const SceneEntry& row, const std::string& param) {
  return std::any_of(row.params.begin(), row.params.end(), [&](const ParamSpec& p) { return p.name == param; });
}

}  // namespace

const std::deque<SceneEntry>& sceneRegistry() { return rows(); }

const SceneEntry& sceneEntry(const std::string& name) {
  for (const SceneEntry& row : rows())
    if (row.name == name) return row;
  throw SceneError("unknown scene '" + name + "' (known scenes: " + knownScenes() + ")");
}

std::vector<std::string> sceneNames() {
  std::vector<std::string> names;
  for (const SceneEntry& row : rows()) names.push_back(row.name);
  return names;
}

std::unique_ptr<Scene> makeScene(const std::string& name, const SceneOptions& options) {
  return sceneEntry(name).make(options);
}

void registerScene(SceneEntry entry) {
  // A name is typed on command lines and used as a folder name by the runners.
  const bool plain = !entry.name.empty() && std::all_of(entry.name.begin(), entry.name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
  if (!plain) throw SceneError("scene name '" + entry.name + "' is not lower-case letters, digits, - and _");
  if (std::any_of(rows().begin(), rows().end(), [&](const SceneEntry& row) { return row.name == entry.name; }))
    throw SceneError("scene '" + entry.name + "' is registered already (known scenes: " + knownScenes() + ")");
  if (!entry.make) throw SceneError("scene '" + entry.name + "' has no factory");
  if (!declares(entry, "time") || !declares(entry, "size"))
    throw SceneError("scene '" + entry.name + "' does not declare the time and size parameters every scene has");
  rows().push_back(std::move(entry));
}

void registerProgram(ProgramEntry entry) {
  for (const ProgramEntry* known : programRegistry())
    if (known->name == entry.name) throw std::invalid_argument("shader program " + entry.name + " is registered already");
  standalonePrograms().push_back(std::move(entry));
}

std::vector<const ProgramEntry*> programRegistry() {
  // A program two scenes share (deferred draws shadow's shadow/shadow) is listed once.
  std::vector<const ProgramEntry*> all;
  auto add = [&](const ProgramEntry& p) {
    if (std::none_of(all.begin(), all.end(), [&](const ProgramEntry* q) { return q->name == p.name; })) all.push_back(&p);
  };
  for (const SceneEntry& row : rows())
    for (const ProgramEntry& p : row.programs) add(p);
  for (const ProgramEntry& p : standalonePrograms()) add(p);
  return all;
}

}  // namespace scenes
