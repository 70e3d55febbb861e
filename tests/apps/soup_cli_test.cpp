// `raster soup`: random triangle soups, this pipeline against llvmpipe (apps/soup/soup.h).
//
// A run of a few hundred seeds must be identical and watertight; the check must be able to
// fail (a hidden flag moves this pipeline's triangles a pixel, and hand-made closed meshes
// with a hole or an overlap are caught); a reproducer holds its soup bit for bit and replays
// to the same verdict; bad arguments and bad reproducers are refused with exit 2.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenes/soup/soup.h"
#include "tests/apps/cli_test_helpers.h"

namespace {

using namespace cli_test;
using nlohmann::json;

int countLines(const std::string& text, const std::string& prefix) {
  int n = 0;
  size_t at = 0;
  while (at < text.size()) {
    const size_t end = text.find('\n', at);
    if (text.compare(at, prefix.size(), prefix) == 0) ++n;
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return n;
}

std::string hexBits(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  char text[9];
  std::snprintf(text, sizeof text, "%08x", bits);
  return text;
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// A replay file with no random triangles and one closed mesh: a strip of 2 x 2 quads whose
// outline is the whole 16x16 viewport (w = 1, clip = NDC), triangles as given.
json stripReplay(const std::vector<uint32_t>& indices) {
  json clip = json::array();
  for (int row = 0; row <= 2; ++row)
    for (int column = 0; column <= 2; ++column)
      clip.push_back({hexBits(float(column) - 1.0f), hexBits(float(row) - 1.0f), hexBits(0.0f), hexBits(1.0f)});
  json mesh = {{"kind", "strip"}, {"note", "hand-made"}, {"clip", clip}, {"indices", indices}, {"outline", {0, 2, 8, 6}}};
  return {{"format", "raster-soup-1"}, {"seed", 0}, {"width", 16}, {"height", 16},
          {"triangles", json::array()}, {"meshes", json::array({mesh})}};
}

// The two triangles of each quad of that strip.
std::vector<uint32_t> stripIndices() {
  std::vector<uint32_t> indices;
  for (uint32_t row = 0; row < 2; ++row)
    for (uint32_t column = 0; column < 2; ++column) {
      const uint32_t a = row * 3 + column, b = a + 1, c = a + 3, d = a + 4;
      indices.insert(indices.end(), {a, b, c, c, b, d});
    }
  return indices;
}

void expectRefused(const std::string& args, const std::string& mentions, const fs::path& cwd) {
  const RunResult result = runCli(cwd, args);
  INFO("raster " << args << "\nstderr: " << result.err);
  CHECK(result.status == 2);
  CHECK(result.err.rfind("raster: ", 0) == 0);
  CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
  CHECK(result.err.find(mentions) != std::string::npos);
  CHECK(result.out.empty());
}

}  // namespace

TEST_SUITE("soup") {
  TEST_CASE("300 seeds at 64x64: every one identical to llvmpipe and watertight, nothing written") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult result = runCli(cwd, "soup --seeds 0:299 --size 64x64 --json ../soup.json");
    INFO("stdout tail: " << result.out.substr(result.out.size() > 2000 ? result.out.size() - 2000 : 0) << "\nstderr: "
                         << result.err);
    CHECK(result.status == 0);
    CHECK(countLines(result.out, "seed ") == 300);
    CHECK(result.out.find("300 seeds (0..299) at 64x64 against llvmpipe: 300 identical and watertight, 0 failed") !=
          std::string::npos);
    CHECK(result.out.find("non-finite triangles drawn apart, not compared") != std::string::npos);
    CHECK(fs::is_empty(cwd));
    // The same for scripts.
    const json summary = json::parse(readText(temp.path / "soup.json"));
    CHECK(summary["seeds"] == json::array({0, 299}));
    CHECK(summary["size"] == json::array({64, 64}));
    CHECK(summary["soups"] == 300);
    CHECK(summary["passed"] == 300);
    CHECK(summary["failed"] == 0);
    CHECK(summary["failed_seeds"].empty());
    CHECK(summary["non_finite_triangles"].get<int>() > 0);
  }

  TEST_CASE("the same seed makes the same soup, with every kind of triangle over a few seeds") {
    const scenes::soup::Soup a = scenes::soup::generate(42, 64, 64, 200);
    const scenes::soup::Soup b = scenes::soup::generate(42, 64, 64, 200);
    REQUIRE(a.triangles.size() == 200);
    CHECK(std::memcmp(a.triangles.data(), b.triangles.data(), sizeof(scenes::soup::Triangle) * 200) == 0);
    CHECK(scenes::soup::generate(43, 64, 64, 200).triangles[0].clip[0] != a.triangles[0].clip[0]);
    std::vector<int> kinds(11, 0);
    for (const auto& t : a.triangles) kinds[size_t(t.kind)]++;
    for (size_t k = 0; k < kinds.size(); ++k) {
      INFO(scenes::soup::kindName(scenes::soup::Kind(k)));
      CHECK(kinds[k] > 0);
    }
    REQUIRE(a.meshes.size() == 2);
    CHECK(a.meshes[0].kind == scenes::soup::MeshKind::Fan);
    CHECK(a.meshes[1].kind == scenes::soup::MeshKind::Strip);
  }

  TEST_CASE("a difference fails the run, names the seed and pixels, and writes a reproducer that replays") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult failing = runCli(cwd, "soup --seeds 4:5 --size 64x64 --out repro --json failing.json --inject-difference");
    INFO("stdout: " << failing.out << "\nstderr: " << failing.err);
    CHECK(failing.status == 1);
    CHECK(failing.out.find("seed 4: ") != std::string::npos);
    CHECK(failing.out.find("DIFFERS from llvmpipe") != std::string::npos);
    CHECK(std::regex_search(failing.out, std::regex("main pass pixel \\(x \\d+, row \\d+ from the top\\): ours "
                                                    "(triangle \\d+ \\([a-z-]+\\)|nothing) depth 0x[0-9a-f]{6}, llvmpipe")));
    CHECK(failing.err.find("failed (seeds 4, 5)") != std::string::npos);
    REQUIRE(fs::is_regular_file(cwd / "repro" / "soup-4.json"));
    REQUIRE(fs::is_regular_file(cwd / "repro" / "soup-5.json"));
    // --json: the same verdicts, each failure with its reproducer.
    const json results = json::parse(readText(cwd / "failing.json"));
    CHECK(results["failed"] == 2);
    CHECK(results["failed_seeds"] == json::array({4, 5}));
    REQUIRE(results["failures"].size() == 2);
    CHECK(results["failures"][0]["seed"] == 4);
    CHECK(results["failures"][0]["identical"] == false);
    CHECK(results["failures"][0]["color_diffs"].get<int>() > 0);
    CHECK(results["failures"][1]["reproducer"] == "repro/soup-5.json");
    CHECK(!results["failures"][0]["first_diffs"].empty());

    // The file holds the generator's soup bit for bit.
    const json file = json::parse(readText(cwd / "repro" / "soup-4.json"));
    const scenes::soup::Soup soup = scenes::soup::generate(4, 64, 64, 64);
    CHECK(file["seed"] == 4);
    REQUIRE(file["triangles"].size() == soup.triangles.size());
    for (size_t i = 0; i < soup.triangles.size(); ++i) {
      CHECK(file["triangles"][i]["kind"] == scenes::soup::kindName(soup.triangles[i].kind));
      for (int v = 0; v < 3; ++v)
        for (int c = 0; c < 4; ++c) CHECK(file["triangles"][i]["clip"][v][c] == hexBits(soup.triangles[i].clip[v][c]));
    }
    REQUIRE(file["meshes"].size() == soup.meshes.size());
    CHECK(file["meshes"][1]["indices"].get<std::vector<uint32_t>>() == soup.meshes[1].indices);
    CHECK(!file["differences"].empty());

    // Replayed as it is, the soup is identical; with the same perturbation, the same verdict.
    const RunResult clean = runCli(cwd, "soup --replay repro/soup-4.json");
    CHECK(clean.status == 0);
    CHECK(clean.out.find("seed 4: ") != std::string::npos);
    CHECK(clean.out.find("identical, watertight") != std::string::npos);
    const RunResult again = runCli(cwd, "soup --replay repro/soup-4.json --inject-difference");
    CHECK(again.status == 1);
    const std::string firstLine = failing.out.substr(0, failing.out.find("\n  reproducer"));
    CHECK(again.out.rfind(firstLine, 0) == 0);
  }

  TEST_CASE("a closed mesh with a hole or an overlap is caught, on both sides") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    writeText(cwd / "whole.json", stripReplay(stripIndices()).dump());
    const RunResult whole = runCli(cwd, "soup --replay whole.json");
    CHECK(whole.status == 0);
    CHECK(whole.out.find("256 px counted") != std::string::npos);

    std::vector<uint32_t> holed = stripIndices();
    holed.erase(holed.begin() + 3, holed.begin() + 6);   // the first quad's second triangle
    writeText(cwd / "holed.json", stripReplay(holed).dump());
    const RunResult hole = runCli(cwd, "soup --replay holed.json");
    INFO("holed: " << hole.out);
    CHECK(hole.status == 1);
    CHECK(hole.out.find("NOT WATERTIGHT") != std::string::npos);
    CHECK(std::regex_search(hole.out, std::regex("on ours: [1-9]\\d* cracks, 0 double hits")));
    CHECK(hole.out.find("note: closed mesh 0 (strip, hand-made) on llvmpipe itself") != std::string::npos);

    std::vector<uint32_t> doubled = stripIndices();
    doubled.insert(doubled.end(), {0, 1, 3});
    writeText(cwd / "doubled.json", stripReplay(doubled).dump());
    const RunResult overlap = runCli(cwd, "soup --replay doubled.json");
    INFO("doubled: " << overlap.out);
    CHECK(overlap.status == 1);
    CHECK(std::regex_search(overlap.out, std::regex("on ours: 0 cracks, [1-9]\\d* double hits")));
  }

  TEST_CASE("bad arguments and bad reproducers: exit 2, one line, nothing written") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    expectRefused("soup --seeds 5:2", "--seeds: 5:2 runs backwards", cwd);
    expectRefused("soup --seeds 1:99999999999999", "is more than 1000000 seeds", cwd);
    expectRefused("soup --seeds 0:1000000", "is more than 1000000 seeds", cwd);
    expectRefused("soup --seeds x:3", "--seeds: 'x:3' is not A:B", cwd);
    expectRefused("soup --seeds 1:", "--seeds", cwd);
    expectRefused("soup --seeds 0:3 --size 0x0", "--size: 0x0 is out of range", cwd);
    expectRefused("soup --seeds 0:3 --size 64", "--size: '64' is not WxH", cwd);
    expectRefused("soup --seeds 0:3 --triangles -1", "--triangles", cwd);
    expectRefused("soup --seeds 0:3 --json /nonexistent/soup.json", "--json", cwd);
    expectRefused("soup --seeds 0:3 --triangles 2000000", "--triangles: '2000000' is not a whole number 0..1000000", cwd);
    expectRefused("soup --seeds 0:3 --threads -1", "--threads", cwd);
    expectRefused("soup", "give --seeds A:B or --replay FILE", cwd);
    expectRefused("soup --seeds 0:1 --out no/such/folder", "--out: cannot create no/such/folder", cwd);
    expectRefused("soup --replay missing.json", "--replay missing.json: cannot read", cwd);
    CHECK(fs::is_empty(cwd));

    const fs::path replays = temp.path / "replays";
    fs::create_directory(replays);
    writeText(replays / "both.json", stripReplay(stripIndices()).dump());
    expectRefused("soup --seeds 0:1 --replay ../replays/both.json", "exactly one", cwd);
    writeText(replays / "broken.json", "{\"format\": \"raster-soup-1\", ");
    expectRefused("soup --replay ../replays/broken.json", "--replay ../replays/broken.json: not JSON", cwd);
    writeText(replays / "empty.json", "");
    expectRefused("soup --replay ../replays/empty.json", "not JSON", cwd);
    expectRefused("soup --replay ../replays", "is a folder", cwd);

    json bad = stripReplay(stripIndices());
    bad["meshes"][0]["clip"][2][1] = "3f80";
    writeText(replays / "bits.json", bad.dump());
    expectRefused("soup --replay ../replays/bits.json", "meshes[0].clip[2][1]: '3f80' is not a float's bit pattern", cwd);
    bad = stripReplay(stripIndices());
    bad["meshes"][0]["indices"][4] = 9;
    writeText(replays / "index.json", bad.dump());
    expectRefused("soup --replay ../replays/index.json", "meshes[0].indices[4]: 9 is out of range (0..8)", cwd);
    bad = stripReplay(stripIndices());
    bad["triangles"] = json::array({{{"kind", "wobbly"}, {"clip", json::array()}}});
    writeText(replays / "kind.json", bad.dump());
    expectRefused("soup --replay ../replays/kind.json", "triangles[0].kind: unknown triangle kind 'wobbly'", cwd);
    bad = stripReplay(stripIndices());
    bad.erase("width");
    writeText(replays / "width.json", bad.dump());
    expectRefused("soup --replay ../replays/width.json", "width: is missing", cwd);
    bad = stripReplay(stripIndices());
    bad["height"] = 0;
    writeText(replays / "height.json", bad.dump());
    expectRefused("soup --replay ../replays/height.json", "height: 0 is out of range (1..16384)", cwd);
    CHECK(fs::is_empty(cwd));
  }

  TEST_CASE("non-finite triangles are drawn apart and reported, never compared, and crash neither side") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    json replay = stripReplay(stripIndices());
    const float corners[][4] = {{nan, 0.0f, 0.0f, 1.0f}, {-1.0f, -1.0f, 0.0f, 1.0f}, {1.0f, -1.0f, 0.0f, 1.0f},
                                {-1.0f, -1.0f, 0.0f, inf}, {1.0f, inf, 0.0f, 1.0f}, {-inf, 1.0f, 0.0f, 1.0f}};
    for (int t = 0; t < 2; ++t) {
      json clip = json::array();
      for (int v = 0; v < 3; ++v) {
        const float* c = corners[t * 3 + v];
        clip.push_back({hexBits(c[0]), hexBits(c[1]), hexBits(c[2]), hexBits(c[3])});
      }
      replay["triangles"].push_back({{"kind", "non-finite"}, {"clip", clip}});
    }
    writeText(cwd / "nonfinite.json", replay.dump());
    const RunResult result = runCli(cwd, "soup --replay nonfinite.json");
    INFO(result.out << result.err);
    CHECK(result.status == 0);
    CHECK(result.out.find("2 non-finite (not compared: ours covered") != std::string::npos);
  }
}
