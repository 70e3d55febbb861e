// The OBJ checks (see obj_validate.h).
#include "io/obj_validate.h"

#include <charconv>
#include <initializer_list>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace scenes {
namespace {

// Concatenates message parts (building messages with std::string's operator+ trips GCC 12's
// false -Wrestrict warning, GCC bug 105651).
std::string message(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view part : parts) out.append(part);
  return out;
}

struct Counts {
  int64_t positions = 0, texcoords = 0, normals = 0;
};

class LineChecker {
 public:
  LineChecker(const std::string& path, size_t line) : path_(path), line_(line) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw SceneError(message({"asset ", path_, ":", std::to_string(line_), ": ", what}));
  }

  // A float as tinyobjloader would read it, but refused unless it is a finite number
  // within the coordinate limit.
  void number(std::string_view token, const char* what) const {
    const std::string text(token);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0') fail(message({what, " '", text, "' is not a number"}));
    if (!std::isfinite(value) || !std::isfinite(float(value))) fail(message({what, " '", text, "' is not a finite float"}));
    if (std::fabs(value) > kMaxObjCoordinate)
      fail(message({what, " ", text, " is beyond the limit of 1e6 (io/obj_validate.h says why)"}));
  }

  // One corner index: non-zero, and (negative) relative to the elements defined so far.
  // Positive indices are checked against the whole file's counts at the end.
  int64_t index(std::string_view token, int64_t definedSoFar, const char* what) const {
    int64_t value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
      fail(message({what, " index '", token, "' is not an integer"}));
    if (value == 0) fail(message({what, " index 0 (OBJ indices start at 1)"}));
    if (value < 0 && -value > definedSoFar) fail(message({what, " index ", token, " points before the first ", what}));
    return value > 0 ? value : definedSoFar + value + 1;
  }

 private:
  const std::string& path_;
  size_t line_;
};

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

}  // namespace

void validateObj(const std::string& path, std::string_view text) {
  if (!text.empty() && text.back() != '\n')
    throw SceneError(message({"asset ", path, ": truncated (its last line has no end of line)"}));
  Counts counts;
  // The largest positive index of each kind, and the line it is on, checked at the end.
  int64_t maxIndex[3] = {0, 0, 0};
  size_t maxLine[3] = {0, 0, 0};
  size_t lineNumber = 0;
  for (size_t start = 0; start < text.size();) {
    const size_t end = text.find('\n', start);
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++lineNumber;
    const std::vector<std::string_view> t = tokens(line);
    if (t.empty() || t[0][0] == '#') continue;
    const LineChecker check(path, lineNumber);
    const std::string_view key = t[0];
    const size_t values = t.size() - 1;
    if (key == "v") {
      if (values != 3 && values != 4)
        check.fail(message({"a vertex needs 3 coordinates (x y z, optionally w), this has ", std::to_string(values)}));
      for (size_t i = 1; i < t.size(); ++i) check.number(t[i], "coordinate");
      ++counts.positions;
    } else if (key == "vt") {
      if (values < 2 || values > 3)
        check.fail(message({"a texture coordinate needs 2 numbers (u v, optionally w), this has ", std::to_string(values)}));
      for (size_t i = 1; i < t.size(); ++i) check.number(t[i], "texture coordinate");
      ++counts.texcoords;
    } else if (key == "vn") {
      if (values != 3) check.fail(message({"a normal needs 3 numbers, this has ", std::to_string(values)}));
      for (size_t i = 1; i < t.size(); ++i) check.number(t[i], "normal component");
      ++counts.normals;
    } else if (key == "f") {
      if (values < 3)
        check.fail(message({"a face of ", std::to_string(values), values == 1 ? " corner" : " corners", " (a face needs at least 3)"}));
      if (values > size_t(kMaxObjFaceCorners))
        check.fail(message({"a face of ", std::to_string(values), " corners (at most ", std::to_string(kMaxObjFaceCorners),
                            ": the OBJ reader counts corners in a byte)"}));
      for (size_t i = 1; i < t.size(); ++i) {
        const std::string_view corner = t[i];
        const size_t slash1 = corner.find('/');
        const size_t slash2 = slash1 == std::string_view::npos ? slash1 : corner.find('/', slash1 + 1);
        const std::string_view parts[3] = {
            corner.substr(0, slash1),
            slash1 == std::string_view::npos ? std::string_view() : corner.substr(slash1 + 1, slash2 == std::string_view::npos ? std::string_view::npos : slash2 - slash1 - 1),
            slash2 == std::string_view::npos ? std::string_view() : corner.substr(slash2 + 1)};
        const int64_t defined[3] = {counts.positions, counts.texcoords, counts.normals};
        const char* names[3] = {"vertex", "texture coordinate", "normal"};
        if (parts[0].empty()) check.fail(message({"face corner '", corner, "' has no vertex index"}));
        for (int k = 0; k < 3; ++k) {
          if (parts[k].empty()) continue;
          const int64_t resolved = check.index(parts[k], defined[k], names[k]);
          if (resolved > maxIndex[k]) {
            maxIndex[k] = resolved;
            maxLine[k] = lineNumber;
          }
        }
      }
    } else if (key != "o" && key != "g" && key != "s" && key != "usemtl" && key != "mtllib" && key != "l" && key != "p") {
      check.fail(message({"unknown keyword '", key.substr(0, 40), "'"}));
    }
  }
  const int64_t totals[3] = {counts.positions, counts.texcoords, counts.normals};
  const char* plural[3] = {"vertices ('v' lines)", "texture coordinates ('vt' lines)", "normals ('vn' lines)"};
  const char* names[3] = {"vertex", "texture coordinate", "normal"};
  for (int k = 0; k < 3; ++k)
    if (maxIndex[k] > totals[k])
      LineChecker(path, maxLine[k]).fail(message({"a face uses ", names[k], " ", std::to_string(maxIndex[k]),
                                                  " but the file has ", std::to_string(totals[k]), " ", plural[k]}));
}

}  // namespace scenes
