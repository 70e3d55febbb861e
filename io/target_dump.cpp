// A frame's targets as a folder of files, and back (see target_dump.h).
#include "io/target_dump.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/exr_io.h"
#include "io/image_io.h"
#include "io/output_file.h"

namespace compare {
namespace {

namespace fs = std::filesystem;
using scenes::ImageData;
using scenes::Target;
using scenes::TexelFormat;

constexpr const char* kManifest = "targets.txt";

std::string kindTag(const ImageData& image) {
  switch (image.format) {
    case TexelFormat::RGBA8: return "rgba8";
    case TexelFormat::RGBA16F:
    case TexelFormat::RGB16F: return "half";
    case TexelFormat::RGBA32F: return "float";
    case TexelFormat::Depth16:
    case TexelFormat::Depth24: return "depth" + std::to_string(image.depthBits);
  }
  throw std::invalid_argument("a target of an unknown format");
}

}  // namespace

std::vector<std::string> targetDumpFiles(const std::vector<Target>& targets) {
  std::vector<std::string> files;
  for (const Target& target : targets) {
    if (target.name.empty() || target.name.find_first_of("/ \t\n") != std::string::npos)
      throw std::runtime_error("target name '" + target.name + "' cannot be a file name");
    files.push_back(target.name + ".png");
    if (target.image.format != TexelFormat::RGBA8) files.push_back(target.name + ".exr");
  }
  files.push_back(kManifest);
  return files;
}

void writeTargetDump(const std::string& folder, const std::vector<Target>& targets,
                     const std::function<void(const std::string&)>& wrote) {
  const std::vector<std::string> files = targetDumpFiles(targets);
  fs::create_directory(folder);
  for (const std::string& file : files) checkOutputPath((fs::path(folder) / file).string());
  const auto written = [&](const std::string& path) {
    if (wrote) wrote(path);
  };
  std::string manifest;
  for (const Target& target : targets) {
    const std::string base = (fs::path(folder) / target.name).string();
    writePng(base + ".png", target.image);
    written(base + ".png");
    if (target.image.format != TexelFormat::RGBA8) {
      writeExr(base + ".exr", target.image);
      written(base + ".exr");
    }
    manifest += target.name + " " + kindTag(target.image) + "\n";
  }
  const std::string manifestPath = (fs::path(folder) / kManifest).string();
  writeOutputFile(manifestPath, manifest);
  written(manifestPath);
}

std::vector<Target> loadTargetDump(const std::string& folder) {
  const std::string manifestPath = (fs::path(folder) / kManifest).string();
  std::ifstream manifest(manifestPath);
  if (!manifest) throw std::runtime_error("cannot read " + manifestPath);
  std::vector<Target> targets;
  std::string line;
  while (std::getline(manifest, line)) {
    std::istringstream fields(line);
    std::string name, tag, extra;
    if (!(fields >> name >> tag) || (fields >> extra))
      throw std::runtime_error(manifestPath + ": bad line '" + line + "' (want NAME KIND)");
    const std::string base = (fs::path(folder) / name).string();
    if (tag == "rgba8") {
      targets.push_back({name, readPng(base + ".png")});
    } else if (tag == "half" || tag == "float") {
      ImageData image = readExrColor(base + ".exr");
      const bool isHalf = image.format != TexelFormat::RGBA32F;
      if (isHalf != (tag == "half"))
        throw std::runtime_error("cannot read " + base + ".exr: " + (isHalf ? "HALF" : "FLOAT") +
                                 " channels, but " + manifestPath + " says " + tag);
      targets.push_back({name, std::move(image)});
    } else if (tag == "depth16" || tag == "depth24") {
      targets.push_back({name, readExrDepth(base + ".exr", std::stoi(tag.substr(5)))});
    } else {
      throw std::runtime_error(manifestPath + ": unknown target kind '" + tag + "'");
    }
  }
  return targets;
}

}  // namespace compare
