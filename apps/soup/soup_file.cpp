// The soup reproducer file (soup_file.h).
#include "apps/soup/soup_file.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "apps/common/cli_options.h"

namespace cli {
namespace {

using nlohmann::json;
using scenes::soup::ClosedMesh;
using scenes::soup::Soup;
using scenes::soup::Triangle;

constexpr const char* kFormat = "raster-soup-1";
constexpr uintmax_t kMaxFileBytes = uintmax_t(1) << 30;  // far above any soup worth replaying

std::string bitsOf(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  char text[9];
  std::snprintf(text, sizeof text, "%08x", bits);
  return text;
}

json vec4Json(const glm::vec4& v) { return json::array({bitsOf(v.x), bitsOf(v.y), bitsOf(v.z), bitsOf(v.w)}); }

// Reading: every error names the file and the JSON path of the bad field.
class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw UsageError("--replay " + path_ + ": " + (where.empty() ? "" : where + ": ") + what);
  }

  const json& field(const json& object, const std::string& where, const char* name) const {
    if (!object.is_object()) fail(where, "is not an object");
    const auto it = object.find(name);
    if (it == object.end()) fail(where.empty() ? std::string(name) : where + "." + name, "is missing");
    return *it;
  }

  const json& array(const json& value, const std::string& where) const {
    if (!value.is_array()) fail(where, "is not an array");
    return value;
  }

  int64_t integer(const json& value, const std::string& where, int64_t lo, int64_t hi) const {
    if (!value.is_number_integer()) fail(where, "is not a whole number");
    // Parsed non-negative numbers are unsigned (and may not fit int64), others signed.
    const bool outside = value.is_number_unsigned()
                             ? value.get<uint64_t>() > uint64_t(hi) || int64_t(value.get<uint64_t>()) < lo
                             : value.get<int64_t>() < lo || value.get<int64_t>() > hi;
    if (outside)
      fail(where, value.dump() + " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")");
    return value.get<int64_t>();
  }

  std::string text(const json& value, const std::string& where) const {
    if (!value.is_string()) fail(where, "is not a string");
    return value.get<std::string>();
  }

  float bits(const json& value, const std::string& where) const {
    const std::string s = text(value, where);
    if (s.size() != 8 || s.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
      fail(where, "'" + s + "' is not a float's bit pattern (8 hex digits)");
    const uint32_t b = uint32_t(std::stoul(s, nullptr, 16));
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
  }

  glm::vec4 vec4(const json& value, const std::string& where) const {
    if (!array(value, where).is_array() || value.size() != 4) fail(where, "is not 4 coordinates");
    glm::vec4 v;
    for (int c = 0; c < 4; ++c) v[c] = bits(value[size_t(c)], where + "[" + std::to_string(c) + "]");
    return v;
  }

 private:
  std::string path_;
};

}  // namespace

std::string soupToJson(const Soup& soup, const std::vector<std::string>& differences) {
  json triangles = json::array();
  for (const Triangle& t : soup.triangles)
    triangles.push_back({{"kind", scenes::soup::kindName(t.kind)},
                         {"clip", json::array({vec4Json(t.clip[0]), vec4Json(t.clip[1]), vec4Json(t.clip[2])})}});
  json meshes = json::array();
  for (const ClosedMesh& m : soup.meshes) {
    json clip = json::array();
    for (const glm::vec4& v : m.clip) clip.push_back(vec4Json(v));
    meshes.push_back({{"kind", scenes::soup::meshKindName(m.kind)},
                      {"note", m.note},
                      {"clip", clip},
                      {"indices", m.indices},
                      {"outline", m.outline}});
  }
  json file = {{"format", kFormat},       {"seed", soup.seed},        {"width", soup.width},
               {"height", soup.height},   {"triangles", triangles},   {"meshes", meshes},
               {"differences", differences}};
  return file.dump(1) + "\n";
}

Soup readSoupFile(const std::string& path) {
  const Reader r(path);
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) r.fail("", "is a folder, not a file");
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) r.fail("", "cannot read (" + error.message() + ")");
  if (size > kMaxFileBytes) r.fail("", "is " + std::to_string(size) + " bytes, over the 1 GiB a reproducer may take");
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  if (!in) r.fail("", std::string("cannot read (") + std::strerror(errno) + ")");

  json file;
  try {
    file = json::parse(bytes.str());
  } catch (const json::parse_error& e) {
    r.fail("", std::string("not JSON: ") + e.what());
  }
  const std::string format = r.text(r.field(file, "", "format"), "format");
  if (format != kFormat) r.fail("format", "'" + format + "' is not " + kFormat);

  Soup soup;
  const json& seed = r.field(file, "", "seed");
  if (!seed.is_number_unsigned() && !(seed.is_number_integer() && seed.get<int64_t>() >= 0))
    r.fail("seed", "is not a whole number >= 0");
  soup.seed = seed.get<uint64_t>();
  soup.width = int(r.integer(r.field(file, "", "width"), "width", 1, kMaxSide));
  soup.height = int(r.integer(r.field(file, "", "height"), "height", 1, kMaxSide));

  const json& triangles = r.array(r.field(file, "", "triangles"), "triangles");
  if (triangles.size() > scenes::soup::kMaxTriangles)
    r.fail("triangles", "more than " + std::to_string(scenes::soup::kMaxTriangles) + " (IDs are 24-bit colours)");
  for (size_t i = 0; i < triangles.size(); ++i) {
    const std::string where = "triangles[" + std::to_string(i) + "]";
    Triangle t;
    const std::string kind = r.text(r.field(triangles[i], where, "kind"), where + ".kind");
    try {
      t.kind = scenes::soup::kindFromName(kind);
    } catch (const std::invalid_argument& e) {
      r.fail(where + ".kind", e.what());
    }
    const json& clip = r.array(r.field(triangles[i], where, "clip"), where + ".clip");
    if (clip.size() != 3) r.fail(where + ".clip", "has " + std::to_string(clip.size()) + " vertices, not 3");
    for (int v = 0; v < 3; ++v) t.clip[v] = r.vec4(clip[size_t(v)], where + ".clip[" + std::to_string(v) + "]");
    soup.triangles.push_back(t);
  }

  const json& meshes = r.array(r.field(file, "", "meshes"), "meshes");
  for (size_t i = 0; i < meshes.size(); ++i) {
    const std::string where = "meshes[" + std::to_string(i) + "]";
    ClosedMesh m;
    try {
      m.kind = scenes::soup::meshKindFromName(r.text(r.field(meshes[i], where, "kind"), where + ".kind"));
    } catch (const std::invalid_argument& e) {
      r.fail(where + ".kind", e.what());
    }
    m.note = r.text(r.field(meshes[i], where, "note"), where + ".note");
    const json& clip = r.array(r.field(meshes[i], where, "clip"), where + ".clip");
    for (size_t v = 0; v < clip.size(); ++v) m.clip.push_back(r.vec4(clip[v], where + ".clip[" + std::to_string(v) + "]"));
    const int64_t last = int64_t(m.clip.size()) - 1;
    auto indexList = [&](const char* name, size_t multiple) {
      const std::string at = where + "." + name;
      const json& list = r.array(r.field(meshes[i], where, name), at);
      if (list.size() % multiple != 0) r.fail(at, "has " + std::to_string(list.size()) + " entries, not a multiple of 3");
      std::vector<uint32_t> out;
      for (size_t k = 0; k < list.size(); ++k) {
        if (last < 0) r.fail(at, "refers to vertices, but the mesh has none");
        out.push_back(uint32_t(r.integer(list[k], at + "[" + std::to_string(k) + "]", 0, last)));
      }
      return out;
    };
    m.indices = indexList("indices", 3);
    m.outline = indexList("outline", 1);
    soup.meshes.push_back(std::move(m));
  }
  return soup;
}

}  // namespace cli
