// The `raster` program's options and their validation (see cli_options.h).
#include "apps/common/cli_options.h"

#include "io/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <tuple>

#include "io/memory_budget.h"
#include "scenes/registry.h"

namespace cli {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxInstances = 200000;

}  // namespace

void addFrameOptions(CLI::App& command, FrameArgs& args) {
  std::string names;
  for (const auto& name : scenes::sceneNames()) names += (names.empty() ? "" : ", ") + name;
  command.add_option("scene", args.scene, "Scene: " + names)->required()->type_name("SCENE");
  command.add_option("--time", args.time, "Time in seconds (frame N is N/60)")
      ->type_name("T")->capture_default_str();
  command.add_option("--size", args.size, "Final image size")->type_name("WxH")->capture_default_str();
  command.add_option("--threads", args.threads,
                     "Threads of this pipeline and llvmpipe (LP_NUM_THREADS), 0..1024; 0: every core")
      ->type_name("N")->capture_default_str();
  command.add_option("--instances", args.instances, "Cubes in the hdr scene (1..200000)")->capture_default_str();
  command.add_flag("--scalar", args.scalar, "This pipeline with every SIMD fast path off (same bytes, slower)");
  command.add_option("--max-memory", args.maxMemory,
                     "Refuse (exit 2) a run whose images, textures and targets would take more than SIZE, "
                     "e.g. 8G or 512M (default: 3/4 of this machine's memory)")
      ->type_name("SIZE");
  command.add_option("--assets", args.assets, "Asset folder (default: $RASTER_ASSETS, else the repository's assets/)")
      ->type_name("DIR");
  addMethodOptions(command, args.preset, args.method);
  addSetOption(command, args.sets);
  addQuietOption(command, args.quiet);
  command.add_flag("--float-final", args.floatFinal,
                   "Draw the final pass into an RGBA32F target instead of the RGBA8 window: the shaders' "
                   "outputs before 8-bit rounding, compared bit for bit");
}

namespace {

// A non-negative decimal integer that fits in uint64_t.
std::optional<uint64_t> parseUnsigned(const std::string& text) {
  uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

// compare::checkOutputPath (the writer's own rules: a regular file or nothing), its refusal
// bad input named by the option that gave the path.
void checkOutputPathOf(const std::string& option, const std::string& path) {
  try {
    compare::checkOutputPath(path);
  } catch (const compare::OutputPathError& e) {
    throw UsageError(option + ": " + e.what());
  }
}

}  // namespace

// Whether this process can make a file in `folder`, tried rather than predicted: for root,
// access(W_OK) says yes of folders nobody can write into (/proc, /sys), and the run would
// then fail at its end, after the work, with exit 1. A probe file is made and removed.
bool writableFolder(const std::filesystem::path& folder) {
  std::error_code error;
  if (!fs::is_directory(folder, error) || access(folder.c_str(), W_OK | X_OK) != 0) return false;
  for (int attempt = 0; attempt < 8; ++attempt) {
    const fs::path probe = folder / (".raster-write-probe-" + std::to_string(getpid()) + "-" + std::to_string(attempt));
    const int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd >= 0) {
      close(fd);
      unlink(probe.c_str());
      return true;
    }
    if (errno != EEXIST) return false;
  }
  return false;
}

void addMethodOptions(CLI::App& command, std::string& preset, std::string& method) {
  std::string presets;
  for (const std::string& name : raster::presetNames()) presets.append(presets.empty() ? "" : "|").append(name);
  command.add_option("--preset", preset,
                     "This pipeline's method set: gl (llvmpipe's numerics, bit-exact), precise, fast (>= 40 dB), draft (>= 30 dB) "
                     "(raster methods lists them and where each promise holds)")
      ->type_name(presets)->capture_default_str();
  command.add_option("--method", method, "Override steps of the preset, e.g. math=fast,half=rne")
      ->type_name("STEP=NAME[,...]");
}

void addSetOption(CLI::App& command, std::vector<std::string>& sets) {
  command.add_option("--set", sets,
                     "Set a scene parameter (repeatable; `raster params SCENE` lists them), e.g. --set near=0.001")
      ->type_name("NAME=VALUE")->take_all()->allow_extra_args(false);
}

void addQuietOption(CLI::App& command, bool& quiet) {
  command.add_flag("--quiet", quiet, "No progress or announcements on stderr (errors still go there)");
}

scenes::SceneOptions sceneOptions(const Frame& frame) {
  scenes::SceneOptions options{frame.time, frame.width, frame.height, frame.assets, frame.instances, frame.params};
  options.floatFinal = frame.floatFinal;
  return options;
}

std::vector<std::string> childFrameOptions(const Frame& frame) {
  char time[32];
  std::snprintf(time, sizeof time, "%.9g", frame.time);
  std::vector<std::string> options = {"--size", std::to_string(frame.width) + "x" + std::to_string(frame.height),
                                      "--time", time, "--instances", std::to_string(frame.instances)};
  if (!frame.assets.empty()) options.insert(options.end(), {"--assets", frame.assets});
  for (const std::string& set : frame.sets) {
    const std::string name = set.substr(0, set.find('='));
    if (!scenes::isFrameOption(name)) options.insert(options.end(), {"--set", set});
  }
  return options;
}

std::vector<std::string> childMethodOptions(const FrameArgs& args) {
  std::vector<std::string> options;
  if (args.preset != FrameArgs{}.preset) options.insert(options.end(), {"--preset", args.preset});
  if (!args.method.empty()) options.insert(options.end(), {"--method", args.method});
  return options;
}

raster::MethodSet validateMethods(const std::string& preset, const std::string& overrides) {
  try {
    raster::MethodSet set = raster::presetMethods(preset);
    raster::applyMethodOverrides(set, overrides);
    return set;
  } catch (const raster::MethodError& e) {
    throw UsageError(std::string(overrides.empty() ? "--preset: " : "--preset/--method: ") + e.what());
  }
}

Frame validateFrame(const FrameArgs& args) {
  Frame frame;
  // The scene must be one the library knows.
  const auto names = scenes::sceneNames();
  if (std::find(names.begin(), names.end(), args.scene) == names.end()) {
    std::string known;
    for (const auto& name : names) known += (known.empty() ? "" : ", ") + name;
    throw UsageError("unknown scene '" + args.scene + "' (known scenes: " + known + ")");
  }
  frame.scene = args.scene;

  std::tie(frame.width, frame.height) = parseSize("--size", args.size);

  // --time: the scene parameter `time`, read and range-checked as --set time= reads it.
  try {
    frame.time = float(scenes::parseParamValue(frame.scene, "time", args.time));
  } catch (const scenes::ParamError& e) {
    throw UsageError(std::string("--") + e.what());   // "--time: ..."
  }

  if (args.threads < 0 || args.threads > kMaxThreads)
    throw UsageError("--threads: " + std::to_string(args.threads) + " is out of range (0.." +
                     std::to_string(kMaxThreads) + ")");
  frame.threads = args.threads;
  frame.scalar = args.scalar;
  frame.methods = validateMethods(args.preset, args.method);
  // 200,000 cubes shade 4.8M vertices a frame (about 0.3 GB of vertex data): past that a
  // frame would need gigabytes for no further insight.
  if (args.instances < 1 || args.instances > kMaxInstances)
    throw UsageError("--instances: " + std::to_string(args.instances) + " is out of range (1.." +
                     std::to_string(kMaxInstances) + ")");
  frame.instances = args.instances;

  if (!args.assets.empty()) requireFolder("--assets", args.assets);
  frame.assets = args.assets;

  // --set NAME=VALUE, after the options whose defaults it may replace (time, size,
  // instances: given both ways, the command line refuses them, refuseParameterGivenTwice);
  // a name set twice is ambiguous, not "the last wins".
  std::vector<std::string> namesSet;
  for (const std::string& set : args.sets) {
    const size_t equals = set.find('=');
    if (equals == std::string::npos || equals == 0)
      throw UsageError("--set: '" + set + "' is not NAME=VALUE (raster params " + frame.scene + " lists the names)");
    const std::string name = set.substr(0, equals), value = set.substr(equals + 1);
    if (std::find(namesSet.begin(), namesSet.end(), name) != namesSet.end())
      throw UsageError("--set: " + name + " is given twice");
    namesSet.push_back(name);
    try {
      if (name == "size") {
        scenes::findParam(frame.scene, name);
        if (!scenes::parseSizeValue(value, frame.width, frame.height))
          throw scenes::ParamError("size: '" + value + "' is not WxH or a width, each side 1..16384");
        continue;
      }
      const double number = scenes::parseParamValue(frame.scene, name, value);
      if (name == "time") frame.time = float(number);
      else if (name == "instances") frame.instances = int(number);
      else scenes::applyParam(frame.params, name, number);
    } catch (const scenes::ParamError& e) {
      throw UsageError(std::string("--set: ") + e.what());
    }
  }
  frame.sets = args.sets;
  frame.quiet = args.quiet;
  frame.floatFinal = args.floatFinal;

  if (!args.maxMemory.empty()) {
    uint64_t bytes = 0;
    if (!scenes::memory::parseBytes(args.maxMemory, bytes))
      throw UsageError("--max-memory: '" + args.maxMemory + "' is not a size (a number of bytes above 0, or of K, M, G or T, e.g. 8G; below 16 EiB)");
    scenes::memory::setCap(bytes);
  }
  return frame;
}

std::pair<int, int> parseSize(const std::string& option, const std::string& text) {
  const size_t x = text.find('x');
  const auto width = parseUnsigned(text.substr(0, x));
  const auto height = x == std::string::npos ? std::nullopt : parseUnsigned(text.substr(x + 1));
  if (!width || !height)
    throw UsageError(option + ": '" + text + "' is not WxH (e.g. 640x480)");
  if (*width < 1 || *height < 1 || *width > kMaxSide || *height > kMaxSide)
    throw UsageError(option + ": " + text + " is out of range (each side 1.." + std::to_string(kMaxSide) + ")");
  return {int(*width), int(*height)};
}

std::optional<uint64_t> parseWholeNumber(const std::string& text) { return parseUnsigned(text); }

double parseFiniteNumber(const std::string& option, const std::string& text) {
  const std::optional<double> value = scenes::parseDecimal(text);
  if (!value) throw UsageError(option + ": '" + text + "' is not a finite number");
  return *value;
}

void refuseOwnOptionsOnGl(const Frame& frame, const std::string& side) {
  if (!(frame.methods == raster::MethodSet{}))
    throw UsageError("--preset/--method choose this pipeline's methods; " + side + " renders with GL's own");
  if (frame.scalar) throw UsageError("--scalar turns off this pipeline's SIMD paths; " + side + " is GL");
}

void checkOutputFile(const std::string& option, const std::string& path) {
  const fs::path file(path);
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  if (path.empty() || !file.has_filename())
    throw UsageError(option + ": '" + path + "' names no file");
  checkOutputPathOf(option, path);
  if (!writableFolder(folder))
    throw UsageError(option + ": cannot write into " + folder.string() +
                     " (no such folder, or not writable)");
}

void checkOutputPng(const std::string& option, const std::string& path) {
  checkOutputFile(option, path);   // first: a device, FIFO or folder is named as such
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".png")
    throw UsageError(option + ": " + path + " is written as PNG; give it a name ending in .png");
}

void requireFolder(const std::string& option, const std::string& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) return;
  // A status that cannot be read (a link that loops, a folder on the way this user may not
  // enter) is named with its reason, not thrown as a bare filesystem error.
  const bool missing = !error || error == std::errc::no_such_file_or_directory || error == std::errc::not_a_directory;
  throw UsageError(option + (missing ? ": no such folder: " + path : ": " + path + ": " + error.message()));
}

void checkOutputFolder(const std::string& option, const std::string& path) {
  if (path.empty()) throw UsageError(option + ": names no folder");
  try {
    compare::checkPathLengths(path);   // a name too long was "filesystem error" at the end (exit 1)
  } catch (const compare::OutputPathError& e) {
    throw UsageError(option + ": " + e.what());
  }
  fs::path folder = fs::path(path).lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();   // "out/" -> "out"
  std::error_code error;
  if (fs::exists(folder, error)) {
    if (!fs::is_directory(folder, error)) throw UsageError(option + ": " + path + " is a file, not a folder");
    if (!writableFolder(folder))
      throw UsageError(option + ": " + path + " is not a writable folder");
    return;
  }
  // Not there, or its status unreadable (a link that loops): a name that cannot be made.
  if (error) throw UsageError(option + ": " + path + ": " + error.message());
  if (fs::is_symlink(fs::symlink_status(folder, error)))
    throw UsageError(option + ": " + path + " is a symbolic link to nothing; name a folder");
  const fs::path parent = folder.has_parent_path() ? folder.parent_path() : fs::path(".");
  if (!writableFolder(parent))
    throw UsageError(option + ": cannot create " + path + " (" + parent.string() +
                     " does not exist or is not writable)");
}

void checkOutputFolder(const std::string& option, const std::string& path, const std::vector<std::string>& files) {
  checkOutputFolder(option, path);
  std::error_code error;
  if (!fs::is_directory(path, error)) return;   // to be made: nothing in it yet
  for (const std::string& file : files) checkOutputPathOf(option, (fs::path(path) / file).string());
}

}  // namespace cli
