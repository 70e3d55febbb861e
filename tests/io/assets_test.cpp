// The asset loaders (io/assets.h): the deferred scene's real files load as the tutorial
// loads them, and a missing, unreadable or bad file (a bad OBJ here; bad images in
// image_structure_test.cpp) fails with one SceneError line that names the file and says
// what is wrong. Bad files are written into a fresh temporary folder per test.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <stb_image.h>

#include "tests/io/asset_test_support.h"

using namespace asset_test;

TEST_SUITE("assets") {

TEST_CASE("assetPath joins the asset folder and a relative path") {
  scenes::SceneOptions options;
  options.assetDir = "/some/where";
  CHECK(scenes::assetPath(options, "cat/x.obj") == "/some/where/cat/x.obj");
}

TEST_CASE("the cat OBJ loads as upload_cat builds it") {
  const std::string path = realAsset(kCatObj);
  scenes::ObjLoadInfo info;
  const scenes::MeshData mesh = scenes::loadCatMesh(path, &info);
  CHECK(info.sharedIndices);  // PROVENANCE.md: v/vt/vn share one index
  CHECK(info.positions == 6863);
  CHECK(info.texcoords == 6863);
  CHECK(info.normals == 6863);
  CHECK(info.triangles == 11950);
  REQUIRE(mesh.strideFloats == 8);
  REQUIRE(mesh.attributes.size() == 3);
  CHECK((mesh.attributes[0].location == 0 && mesh.attributes[0].components == 3 && mesh.attributes[0].offsetFloats == 0));
  CHECK((mesh.attributes[1].location == 1 && mesh.attributes[1].components == 3 && mesh.attributes[1].offsetFloats == 3));
  CHECK((mesh.attributes[2].location == 2 && mesh.attributes[2].components == 2 && mesh.attributes[2].offsetFloats == 6));
  const size_t count = mesh.vertices.size() / 8;
  CHECK(mesh.vertices.size() == count * 8);
  CHECK(count == 6863);
  CHECK(mesh.indices.size() == 35850);
  CHECK(std::all_of(mesh.indices.begin(), mesh.indices.end(), [&](uint32_t i) { return i < count; }));
  CHECK(std::all_of(mesh.vertices.begin(), mesh.vertices.end(), [](float v) { return std::isfinite(v); }));

  float minY = 1e30f, maxY = -1e30f, minX = 1e30f, maxX = -1e30f, minZ = 1e30f, maxZ = -1e30f;
  for (size_t i = 0; i < count; ++i) {
    minX = std::min(minX, mesh.vertices[i * 8 + 0]);
    maxX = std::max(maxX, mesh.vertices[i * 8 + 0]);
    minY = std::min(minY, mesh.vertices[i * 8 + 1]);
    maxY = std::max(maxY, mesh.vertices[i * 8 + 1]);
    minZ = std::min(minZ, mesh.vertices[i * 8 + 2]);
    maxZ = std::max(maxZ, mesh.vertices[i * 8 + 2]);
  }
  CHECK(minY == 0.0f);
  CHECK(maxY == doctest::Approx(2.2f).epsilon(1e-6));
  CHECK(std::abs(minX + maxX) < 1e-5f);  // centred on x and z
  CHECK(std::abs(minZ + maxZ) < 1e-5f);

  // Vertex 0 is the file's first v / vn / vt, the uv as written (no 1 - v flip); the first
  // face is the first triangle.
  std::istringstream text(readBytes(path));
  std::string line;
  float vt[2] = {0, 0}, vn[3] = {0, 0, 0};
  int f[3] = {0, 0, 0};
  bool haveVt = false, haveVn = false, haveF = false;
  while (std::getline(text, line) && !(haveVt && haveVn && haveF)) {
    if (!haveVt && line.rfind("vt ", 0) == 0) haveVt = std::sscanf(line.c_str(), "vt %f %f", &vt[0], &vt[1]) == 2;
    if (!haveVn && line.rfind("vn ", 0) == 0) haveVn = std::sscanf(line.c_str(), "vn %f %f %f", &vn[0], &vn[1], &vn[2]) == 3;
    if (!haveF && line.rfind("f ", 0) == 0) haveF = std::sscanf(line.c_str(), "f %d/%*d/%*d %d/%*d/%*d %d", &f[0], &f[1], &f[2]) == 3;
  }
  REQUIRE((haveVt && haveVn && haveF));
  CHECK(mesh.vertices[3] == doctest::Approx(vn[0]).epsilon(1e-6));
  CHECK(mesh.vertices[4] == doctest::Approx(vn[1]).epsilon(1e-6));
  CHECK(mesh.vertices[5] == doctest::Approx(vn[2]).epsilon(1e-6));
  CHECK(mesh.vertices[6] == doctest::Approx(vt[0]).epsilon(1e-6));
  CHECK(mesh.vertices[7] == doctest::Approx(vt[1]).epsilon(1e-6));
  CHECK(mesh.indices[0] == uint32_t(f[0] - 1));
  CHECK(mesh.indices[1] == uint32_t(f[1] - 1));
  CHECK(mesh.indices[2] == uint32_t(f[2] - 1));
}

TEST_CASE("the seven JPEGs load at their real sizes, rows as stb_image gives them") {
  std::vector<std::string> paths;
  for (const std::string& j : kJpegs) paths.push_back(realAsset(j));
  const std::vector<scenes::ImageRgba8> images = scenes::loadImagesRgba8(paths);
  REQUIRE(images.size() == 7);
  CHECK(images[0].width == 2048);  // diff_2k
  CHECK(images[0].height == 2048);
  CHECK(images[1].width == 1024);  // nor_gl_1k
  CHECK(images[1].height == 1024);
  CHECK(images[3].width == 1024);  // brick colour
  CHECK(images[3].height == 1024);
  for (const scenes::ImageRgba8& im : images) CHECK(im.pixels.size() == size_t(im.width) * im.height * 4);

  // The parallel loader gives what the one-file loader gives, and that is stbi_load's
  // unflipped rows with 4 channels.
  const scenes::ImageRgba8 one = scenes::loadImageRgba8(paths[3]);
  CHECK(one.pixels == images[3].pixels);
  int w = 0, h = 0, c = 0;
  stbi_set_flip_vertically_on_load_thread(0);
  unsigned char* ref = stbi_load(paths[3].c_str(), &w, &h, &c, 4);
  REQUIRE(ref != nullptr);
  CHECK(std::equal(one.pixels.begin(), one.pixels.end(), ref));
  stbi_image_free(ref);
}

// The test program keeps decoded images for its whole run (tests/main.cpp): a file is
// found by its bytes, not its name, and every check and the memory cap still hold on a hit.
TEST_CASE("decoded images are reused only for the same bytes, and every check still runs") {
  CHECK_THROWS_AS(scenes::ScopedImageCache(), std::logic_error);   // the program's is alive
  TempFolder dir;
  const std::string path = dir.file("image.jpg");
  for (const std::string& j : {kJpegs[3], kJpegs[4], kJpegs[3]}) {   // the same name, new bytes each time
    writeBytes(path, readBytes(realAsset(j)));
    for (int load = 0; load < 2; ++load) {
      INFO(j << ", load " << load);
      const scenes::ImageRgba8 image = scenes::loadImageRgba8(path);
      int w = 0, h = 0, c = 0;
      stbi_set_flip_vertically_on_load_thread(0);
      unsigned char* ref = stbi_load(path.c_str(), &w, &h, &c, 4);
      REQUIRE(ref != nullptr);
      CHECK(image.width == w);
      CHECK(image.height == h);
      REQUIRE(image.pixels.size() == size_t(w) * h * 4);
      CHECK(std::equal(image.pixels.begin(), image.pixels.end(), ref));
      stbi_image_free(ref);
    }
  }
  // A file cut short after its whole self was decoded: refused as before.
  const std::string whole = readBytes(realAsset(kJpegs[3]));
  writeBytes(path, whole.substr(0, whole.size() / 2));
  CHECK(errorOf([&] { scenes::loadImageRgba8(path); }).find("truncated") != std::string::npos);
  // The memory cap: a hit reserves the decoded size as a decoding would.
  writeBytes(path, whole);
  const uint64_t previous = scenes::memory::cap();
  scenes::memory::setCap(scenes::memory::reserved() + 1024);
  const std::string refused = errorOf([&] { scenes::loadImageRgba8(path); });
  scenes::memory::setCap(previous);
  CHECK(refused.find("memory: decoding") != std::string::npos);
}

TEST_CASE("the HDR environment loads as 1024x512 finite non-negative RGB") {
  const scenes::ImageRgbFloat env = scenes::loadHdrRgb(realAsset(kHdr));
  CHECK(env.width == 1024);
  CHECK(env.height == 512);
  REQUIRE(env.pixels.size() == size_t(1024) * 512 * 3);
  CHECK(std::all_of(env.pixels.begin(), env.pixels.end(), [](float v) { return std::isfinite(v) && v >= 0.0f; }));
  CHECK(*std::max_element(env.pixels.begin(), env.pixels.end()) > 1.0f);  // it is HDR
}

TEST_CASE("loading every asset once: time") {
  std::vector<std::string> paths;
  for (const std::string& j : kJpegs) paths.push_back(realAsset(j));
  const std::string obj = realAsset(kCatObj), hdr = realAsset(kHdr);
  using clock = std::chrono::steady_clock;
  auto ms = [](clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  const auto t0 = clock::now();
  const scenes::MeshData mesh = scenes::loadCatMesh(obj);
  const auto t1 = clock::now();
  const auto images = scenes::loadImagesRgba8(paths);
  const auto t2 = clock::now();
  const scenes::ImageRgbFloat env = scenes::loadHdrRgb(hdr);
  const auto t3 = clock::now();
  double sequential = 0;
  for (const std::string& p : paths) {
    const auto a = clock::now();
    (void)scenes::loadImageRgba8(p);
    sequential += ms(clock::now() - a);
  }
  MESSAGE("asset load: OBJ " << ms(t1 - t0) << " ms, 7 JPEGs " << ms(t2 - t1) << " ms in parallel (" << sequential
                             << " ms one after another), HDR " << ms(t3 - t2) << " ms, total " << ms(t3 - t0) << " ms");
  CHECK(images.size() == 7);
  CHECK(env.width == 1024);
  CHECK(!mesh.indices.empty());
}

TEST_CASE("a missing file, a directory, an unreadable file") {
  TempFolder tmp;
  const std::string jpg = tmp.file("nothing.jpg");
  std::string m = errorOf([&] { scenes::loadImageRgba8(jpg); });
  checkOneLine(m, jpg);
  CHECK(contains(m, "no such file"));
  m = errorOf([&] { scenes::loadCatMesh(tmp.file("nothing.obj")); });
  checkOneLine(m, tmp.file("nothing.obj"));
  CHECK(contains(m, "no such file"));
  m = errorOf([&] { scenes::loadHdrRgb(tmp.file("nothing.hdr")); });
  checkOneLine(m, tmp.file("nothing.hdr"));
  CHECK(contains(m, "no such file"));
  const std::string inMissingFolder = tmp.file("no-folder/cat.obj");
  m = errorOf([&] { scenes::loadCatMesh(inMissingFolder); });
  CHECK(contains(m, "no such file (the folder"));

  fs::create_directory(tmp.path / "dir.jpg");
  m = errorOf([&] { scenes::loadImageRgba8(tmp.file("dir.jpg")); });
  CHECK(contains(m, "is a directory"));

  // Permission denied: only meaningful where permissions bind (not as root).
  const std::string locked = tmp.file("locked.jpg");
  writeBytes(locked, readBytes(realAsset(kJpegs[6])));
  fs::permissions(locked, fs::perms::none);
  if (std::FILE* probe = std::fopen(locked.c_str(), "rb")) {
    std::fclose(probe);
    MESSAGE("running with permissions that read a mode-000 file (root?): permission test skipped");
  } else {
    m = errorOf([&] { scenes::loadImageRgba8(locked); });
    checkOneLine(m, locked);
    CHECK(contains(m, "permission denied"));
  }
}

TEST_CASE("OBJ: out-of-range indices, no faces, no vertices, missing attributes") {
  TempFolder tmp;
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n";

  const std::string outOfRange = tmp.file("out-of-range.obj");
  writeBytes(outOfRange, tri + "f 1/1/1 2/2/2 3/3/3\nf 1/1/1 2/2/2 9000/3/3\n");
  std::string m = errorOf([&] { scenes::loadCatMesh(outOfRange); });
  checkOneLine(m, outOfRange);
  CHECK(contains(m, outOfRange + ":11: a face uses vertex 9000 but the file has 3 vertices"));

  const std::string uvOut = tmp.file("uv-out-of-range.obj");
  writeBytes(uvOut, tri + "f 1/1/1 2/7/2 3/3/3\n");
  m = errorOf([&] { scenes::loadCatMesh(uvOut); });
  CHECK(contains(m, ":10: a face uses texture coordinate 7 but the file has 3 texture coordinates"));

  const std::string relative = tmp.file("relative.obj");
  writeBytes(relative, tri + "f -1/1/1 -2/2/2 -5/3/3\n");
  m = errorOf([&] { scenes::loadCatMesh(relative); });
  CHECK(contains(m, ":10: vertex index -5 points before the first vertex"));

  const std::string zero = tmp.file("zero.obj");
  writeBytes(zero, tri + "f 0/1/1 2/2/2 3/3/3\n");
  m = errorOf([&] { scenes::loadCatMesh(zero); });
  checkOneLine(m, zero);
  CHECK(contains(m, ":10: vertex index 0 (OBJ indices start at 1)"));

  const std::string empty = tmp.file("empty.obj");
  writeBytes(empty, "");
  m = errorOf([&] { scenes::loadCatMesh(empty); });
  checkOneLine(m, empty);
  CHECK(contains(m, "empty file"));

  const std::string comments = tmp.file("comments.obj");
  writeBytes(comments, "# nothing here\n\n");
  m = errorOf([&] { scenes::loadCatMesh(comments); });
  checkOneLine(m, comments);
  CHECK(contains(m, "no vertices"));

  const std::string onlyVertices = tmp.file("only-vertices.obj");
  writeBytes(onlyVertices, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  m = errorOf([&] { scenes::loadCatMesh(onlyVertices); });
  checkOneLine(m, onlyVertices);
  CHECK(contains(m, "no triangles"));

  const std::string noNormals = tmp.file("no-normals.obj");
  writeBytes(noNormals, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n");
  m = errorOf([&] { scenes::loadCatMesh(noNormals); });
  checkOneLine(m, noNormals);
  CHECK(contains(m, "no normals"));

  const std::string noUvIndex = tmp.file("no-uv-index.obj");
  writeBytes(noUvIndex, tri + "f 1//1 2//2 3//3\n");
  m = errorOf([&] { scenes::loadCatMesh(noUvIndex); });
  checkOneLine(m, noUvIndex);
  CHECK(contains(m, "face 1 has no texture coordinate index"));

  std::mt19937 rng(7);
  std::string garbage(5000, '\0');
  for (char& b : garbage) b = char(rng() & 0xFF);
  const std::string binary = tmp.file("binary.obj");
  writeBytes(binary, garbage);
  m = errorOf([&] { scenes::loadCatMesh(binary); });
  checkOneLine(m, binary);
}

TEST_CASE("OBJ without shared indices: (v, vt, vn) triples de-duplicated in first-use order") {
  TempFolder tmp;
  const std::string path = tmp.file("quad.obj");
  // A quad (fanned into 2 triangles) whose corners use different v / vt / vn numbers.
  writeBytes(path,
             "v 0 0 0\nv 2 0 0\nv 2 4 0\nv 0 4 0\n"
             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
             "vn 0 0 1\n"
             "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
             "f 1/5/1 3/3/1 4/4/1\n");
  scenes::ObjLoadInfo info;
  const scenes::MeshData mesh = scenes::loadCatMesh(path, &info);
  CHECK_FALSE(info.sharedIndices);
  CHECK(info.faces == 2);
  CHECK(info.triangles == 3);
  REQUIRE(mesh.vertices.size() == 5 * 8);  // 4 corners, then (1, 5, 1) is new
  CHECK(mesh.indices == std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 4, 2, 3});
  // Normalised: height 4 -> 2.2 (s = 0.55), centred on x (0..2 -> -0.55..0.55), min y 0; uv unflipped.
  CHECK(mesh.vertices[0 * 8 + 0] == doctest::Approx(-0.55f));
  CHECK(mesh.vertices[0 * 8 + 1] == 0.0f);
  CHECK(mesh.vertices[2 * 8 + 0] == doctest::Approx(0.55f));
  CHECK(mesh.vertices[2 * 8 + 1] == doctest::Approx(2.2f));
  CHECK(mesh.vertices[3 * 8 + 6] == 0.0f);
  CHECK(mesh.vertices[3 * 8 + 7] == 1.0f);
  CHECK(mesh.vertices[4 * 8 + 6] == 0.5f);
}

}  // TEST_SUITE("assets")
