// Hostile OBJ files: every one is refused with "asset PATH:LINE: PROBLEM" (a SceneError, exit 2
// from the program), never read as something else. Before io/obj_validate.h each of
// these crashed, over-read, or rendered a silently wrong mesh (in brackets).
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "io/assets.h"
#include "scenes/scene.h"
#include "tests/apps/cli_test_helpers.h"

namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";   // lines 1-7

// The error loading `text` as the cat mesh; fails the test unless it is a SceneError naming
// the file (and, when line > 0, that line).
std::string refusal(const std::string& text, int line) {
  cli_test::TempFolder temp;
  const std::string path = (temp.path / "mesh.obj").string();
  std::ofstream(path, std::ios::binary) << text;
  try {
    scenes::loadCatMesh(path);
  } catch (const scenes::SceneError& e) {
    const std::string message = e.what();
    std::string where = "asset ";
    where.append(path).append(line > 0 ? ":" + std::to_string(line) : std::string()).append(": ");
    INFO(message);
    CHECK(message.rfind(where, 0) == 0);
    return message.substr(std::min(message.size(), where.size()));
  } catch (const std::exception& e) {
    FAIL("threw something other than SceneError: " << e.what());
  }
  FAIL("loaded without an error");
  return "";
}

std::string face(int corners) {
  std::string f = "f";
  for (int i = 0; i < corners; ++i) f.append(" ").append(std::to_string(1 + i % 3)).append("/1/1");
  return f.append("\n");
}

}  // namespace

TEST_SUITE("hostile") {
  TEST_CASE("OBJ: faces of 256 and more corners are refused (tinyobjloader counts them in a byte)") {
    CHECK(refusal(kTriangle + face(256), 8).find("a face of 256 corners (at most 255") == 0);   // [heap over-read]
    CHECK(refusal(kTriangle + face(300), 8).find("a face of 300 corners") == 0);                 // [a 44-triangle fan]
    // 255 corners is still read, and fanned into 253 triangles.
    cli_test::TempFolder temp;
    const std::string path = (temp.path / "fan.obj").string();
    std::ofstream(path) << kTriangle + face(255);
    scenes::ObjLoadInfo info;
    scenes::loadCatMesh(path, &info);
    CHECK(info.triangles == 253);
  }

  TEST_CASE("OBJ: faces of fewer than three corners are refused") {
    CHECK(refusal(kTriangle + "f 1/1/1\n", 8) == "a face of 1 corner (a face needs at least 3)");       // [dropped]
    CHECK(refusal(kTriangle + "f 1/1/1 2/2/1\n", 8) == "a face of 2 corners (a face needs at least 3)");
  }

  TEST_CASE("OBJ: coordinates that are not finite numbers, or beyond the limit, are refused") {
    // [each read as 0]
    CHECK(refusal("v 0 0 0\nv abc 0 0\n", 2) == "coordinate 'abc' is not a number");
    CHECK(refusal("v 0 0 0\nv nan 0 0\n", 2) == "coordinate 'nan' is not a finite float");
    CHECK(refusal("v inf 0 0\n", 1) == "coordinate 'inf' is not a finite float");
    CHECK(refusal("v 0 0 1e39\n", 1) == "coordinate '1e39' is not a finite float");   // overflows float
    CHECK(refusal("v 0 0 0\nvt 0.5 x\n", 2) == "texture coordinate 'x' is not a number");
    CHECK(refusal("vn 0 0 -nan\n", 1) == "normal component '-nan' is not a finite float");
    CHECK(refusal("v 1.5e3x 0 0\n", 1) == "coordinate '1.5e3x' is not a number");
    // [the mesh vanished: scaled to a point]
    CHECK(refusal("v 0 0 0\nv 1e30 0 0\n", 2).find("coordinate 1e30 is beyond the limit") == 0);
    CHECK(refusal("v 0 0\n", 1).find("a vertex needs 3 coordinates") == 0);
  }

  TEST_CASE("OBJ: a file cut short, indices out of range, unknown keywords") {
    CHECK(refusal(kTriangle + "f 1/1/1 2/2/1 3/3", 0) == "truncated (its last line has no end of line)");   // [rendered the part read]
    CHECK(refusal(kTriangle + "f 1/1/1 2/2/1 4/3/1\n", 8) == "a face uses vertex 4 but the file has 3 vertices ('v' lines)");
    CHECK(refusal(kTriangle + "f 1/1/1 2/2/2 3/3/1\n", 8) == "a face uses normal 2 but the file has 1 normals ('vn' lines)");
    CHECK(refusal(kTriangle + "f 1/1/1 2/2/1 -4/3/1\n", 8) == "vertex index -4 points before the first vertex");
    CHECK(refusal(kTriangle + "f 1/1/1 2/2/1 x/3/1\n", 8) == "vertex index 'x' is not an integer");
    CHECK(refusal(kTriangle + "bogus 1 2 3\n", 8) == "unknown keyword 'bogus'");
  }
}
