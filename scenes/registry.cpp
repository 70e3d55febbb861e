// The scene registry (registry.h): the built-in rows (builtin_scenes.cpp), the rows and
// programs added at run time, and the lookups.
#include "scenes/registry.h"

#include <algorithm>
#include <cctype>
#include <deque>
#include <iterator>
#include <stdexcept>


namespace scenes {
namespace {

// A deque: a row registered later leaves the references to the others valid.
std::deque<SceneEntry>& rows() {
  static std::deque<SceneEntry> table = [] {
    std::vector<SceneEntry> builtin = builtinScenes();
    return std::deque<SceneEntry>(std::make_move_iterator(builtin.begin()), std::make_move_iterator(builtin.end()));
  }();
  return table;
}

// Programs outside every scene: `raster soup`'s, then any registered at run time.
std::deque<ProgramEntry>& standalonePrograms() {
  static std::deque<ProgramEntry> programs = [] {
    std::vector<ProgramEntry> builtin = builtinPrograms();
    return std::deque<ProgramEntry>(std::make_move_iterator(builtin.begin()), std::make_move_iterator(builtin.end()));
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

const ProgramEntry* findProgram(const std::string& name) {
  for (const ProgramEntry* entry : programRegistry())
    if (entry->name == name) return entry;
  return nullptr;
}

namespace {

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether text[at, at + length) is a whole word: no identifier character on either side.
bool wholeWordAt(const std::string& text, size_t at, size_t length) {
  return (at == 0 || !isWordChar(text[at - 1])) && (at + length >= text.size() || !isWordChar(text[at + length]));
}

// Whether some `uniform ...;` statement of the GLSL source names `name` as a whole word.
// (A plain scan rather than std::regex, which costs this file a minute to compile under
// the sanitizers.)
bool declaresUniform(const std::string& source, const std::string& name) {
  const std::string keyword = "uniform";
  for (size_t at = source.find(keyword); at != std::string::npos; at = source.find(keyword, at + 1)) {
    if (!wholeWordAt(source, at, keyword.size())) continue;
    const size_t begin = at + keyword.size();
    const std::string statement = source.substr(begin, source.find(';', begin) - begin);
    for (size_t n = statement.find(name); n != std::string::npos; n = statement.find(name, n + 1))
      if (wholeWordAt(statement, n, name.size())) return true;
  }
  return false;
}

}  // namespace

void checkPortUniforms(const std::string& program, const ProgramFiles& files, const std::vector<std::string>& active,
                       const std::string& glslSource) {
  const ProgramEntry* port = findProgram(program);
  if (!port) return;
  const std::string where = "program " + program + " (" + files.vertex + ", " + files.fragment + ")";
  for (std::string name : active) {
    if (const size_t bracket = name.find('['); bracket != std::string::npos) name.resize(bracket);   // arrays
    if (std::find(port->uniforms.begin(), port->uniforms.end(), name) != port->uniforms.end()) continue;
    std::string portNames;
    for (const std::string& n : port->uniforms) portNames += (portNames.empty() ? "" : ", ") + n;
    throw std::runtime_error(where + ": uniform '" + name +
                             "' is active in the GLSL, but the C++ port has no uniform of that name (its uniforms: " +
                             portNames + ")");
  }
  for (const std::string& name : port->uniforms)
    if (!declaresUniform(glslSource, name))
      throw std::runtime_error(where + ": the C++ port's uniform '" + name + "' is not a uniform of the GLSL");
}

}  // namespace scenes
