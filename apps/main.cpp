// raster: the command-line program.
//   raster render SCENE ...   one frame with this pipeline or GL; the final image as PNG,
//                             and with --dump every target (PNG preview + lossless dump);
//   raster compare SCENE ...  one frame with a test and a reference backend; per target a
//                             stats line and ours / gl / heat-map PNGs; optional thresholds.
// Options and their checks live in cli_options.*; everything is validated before rendering.
//
// Mesa picks one Gallium driver per process, so a softpipe side of a comparison is rendered
// by a child process (this executable: `render --backend gl --dump TMP` under
// GALLIUM_DRIVER=softpipe) whose lossless dump, listed in TMP/targets.txt, is loaded back.
//
// Exit status: 0 success; 1 internal failure or a compare threshold exceeded; 2 bad input.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/bench.h"
#include "apps/cli_options.h"
#include "compare/image_io.h"
#include "compare/metrics.h"
#include "compare/output_file.h"
#include "scenes/backends.h"
#include "scenes/memory_budget.h"
#include "scenes/scene.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using cli::Frame;
using cli::UsageError;
using scenes::Target;

constexpr const char* kManifest = "targets.txt";   // "NAME rgba8|half|depth<bits>" per line

// The targets of one rendered frame and the name of the backend that made them.
struct Side {
  std::string backend;
  std::vector<Target> targets;
};

// "640x480, t=1.000"
std::string sizeAndTime(const Frame& frame) {
  char text[64];
  std::snprintf(text, sizeof text, "%dx%d, t=%.3f", frame.width, frame.height, frame.time);
  return text;
}

// Renders one frame with a backend made in this process ("raster" or "gl"), and reads back
// every target, or only the final image when `finalOnly` (a render without --dump).
Side renderInProcess(const Frame& frame, const std::string& backendKind, bool finalOnly = false) {
  const scenes::SceneOptions options{frame.time, frame.width, frame.height, frame.assets, frame.instances};
  std::unique_ptr<scenes::Scene> scene = scenes::makeScene(frame.scene, options);
  std::unique_ptr<scenes::Backend> backend;
  if (backendKind == "raster") {
    backend = scenes::makeRasterBackend(frame.threads, frame.scalar);
  } else {
    if (frame.threads > 0) setenv("LP_NUM_THREADS", std::to_string(frame.threads).c_str(), 1);
    backend = scenes::makeGlBackend();
  }
  std::cerr << "rendering " << frame.scene << " with " << backend->name() << " at "
            << sizeAndTime(frame) << " ..." << std::endl;
  backend->resizeDefaultFramebuffer(frame.width, frame.height);
  scene->setup(*backend);
  scene->renderFrame(*backend, frame.time);
  Side side{backend->name(), {}};
  if (finalOnly) side.targets.push_back(scene->readFinal(*backend));
  else side.targets = scene->readTargets(*backend);
  if (side.targets.empty()) throw std::runtime_error("scene " + frame.scene + " exposed no targets");
  return side;
}

std::string manifestTag(const scenes::ImageData& image) {
  const std::string kind = compare::imageKind(image);
  return kind == "depth" ? kind + std::to_string(image.depthBits) : kind;
}

// Writes every target as NAME.png (+ NAME.pfm for depth / float) and the manifest.
void dumpTargets(const std::string& folder, const std::vector<Target>& targets) {
  fs::create_directory(folder);
  std::string manifest;
  for (const Target& target : targets) {
    if (target.name.empty() || target.name.find_first_of("/ \t\n") != std::string::npos)
      throw std::runtime_error("target name '" + target.name + "' cannot be a file name");
    const std::string base = (fs::path(folder) / target.name).string();
    compare::writePng(base + ".png", target.image);
    std::cout << "wrote " << base << ".png" << std::endl;
    if (compare::imageKind(target.image) != "rgba8") {
      compare::writePfm(base + ".pfm", target.image);
      std::cout << "wrote " << base << ".pfm" << std::endl;
      if (fs::exists(compare::alphaPfmPath(base + ".pfm")))
        std::cout << "wrote " << compare::alphaPfmPath(base + ".pfm") << std::endl;
    }
    manifest += target.name + " " + manifestTag(target.image) + "\n";
  }
  const std::string manifestPath = (fs::path(folder) / kManifest).string();
  compare::writeOutputFile(manifestPath, manifest);
  std::cout << "wrote " << manifestPath << std::endl;
}

// Loads a folder written by dumpTargets, in the same order.
std::vector<Target> loadDump(const std::string& folder) {
  const std::string manifestPath = (fs::path(folder) / kManifest).string();
  std::ifstream manifest(manifestPath);
  if (!manifest) throw std::runtime_error("cannot read " + manifestPath);
  std::vector<Target> targets;
  std::string name, tag;
  while (manifest >> name >> tag) {
    const std::string base = (fs::path(folder) / name).string();
    if (tag == "rgba8")
      targets.push_back({name, compare::readPng(base + ".png")});
    else if (tag == "half")
      targets.push_back({name, compare::readPfmFloat(base + ".pfm")});
    else if (tag.rfind("depth", 0) == 0)
      targets.push_back({name, compare::readPfmDepth(base + ".pfm", std::stoi(tag.substr(5)))});
    else
      throw std::runtime_error(manifestPath + ": unknown target kind '" + tag + "'");
  }
  return targets;
}

// A temporary folder, removed with everything in it when this goes out of scope.
struct TempFolder {
  std::string path;
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "raster-compare-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw std::runtime_error("cannot create a temporary folder: " + std::string(std::strerror(errno)));
    path = pattern;
  }
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

// Renders one frame with GL under another Gallium driver, in a child process of this program.
Side renderInChild(const Frame& frame, const std::string& driver) {
  TempFolder dump;
  char time[32];
  std::snprintf(time, sizeof time, "%.9g", frame.time);   // 9 digits: the same float back
  std::vector<std::string> args = {"raster", "render", frame.scene, "--backend", "gl",
                                   "--size", std::to_string(frame.width) + "x" + std::to_string(frame.height),
                                   "--time", time, "--threads", std::to_string(frame.threads),
                                   "--dump", dump.path, "--out", dump.path + "/out.png"};
  if (!frame.assets.empty()) args.insert(args.end(), {"--assets", frame.assets});
  // The child gets what this process has left of the cap (its targets are loaded back here).
  const uint64_t left = scenes::memory::cap() - std::min(scenes::memory::cap(), scenes::memory::reserved());
  args.insert(args.end(), {"--max-memory", std::to_string(std::max<uint64_t>(left / 2, 1))});
  args.insert(args.end(), {"--instances", std::to_string(frame.instances)});

  // The environment as it is, with GALLIUM_DRIVER replaced.
  std::vector<std::string> environment;
  for (char** entry = environ; *entry; ++entry)
    if (std::strncmp(*entry, "GALLIUM_DRIVER=", 15) != 0) environment.emplace_back(*entry);
  environment.push_back("GALLIUM_DRIVER=" + driver);
  const auto pointers = [](std::vector<std::string>& strings) {
    std::vector<char*> result;
    for (auto& s : strings) result.push_back(s.data());
    result.push_back(nullptr);
    return result;
  };
  std::vector<char*> argv = pointers(args), envp = pointers(environment);

  // Run it with stdout (its "wrote" lines) silenced; its progress and errors go to stderr.
  std::cerr << "starting a child process for " << driver << " (GALLIUM_DRIVER=" << driver << ") ..."
            << std::endl;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0)
    throw std::runtime_error("cannot start the " + driver + " child process: " + std::strerror(error));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("waiting for the child: " + std::string(std::strerror(errno)));

  // Its failure is ours: bad input stays bad input (2), anything else is internal (1).
  const std::string what = "the " + driver + " render (child process) ";
  if (WIFSIGNALED(status))
    throw std::runtime_error(what + "was killed by signal " + std::to_string(WTERMSIG(status)) +
                             " (" + strsignal(WTERMSIG(status)) + ")");
  if (WEXITSTATUS(status) == 2) throw UsageError(what + "failed with exit status 2");
  if (WEXITSTATUS(status) != 0)
    throw std::runtime_error(what + "failed with exit status " + std::to_string(WEXITSTATUS(status)));
  return {driver, loadDump(dump.path)};
}

// One side of a comparison: "raster" or "llvmpipe" in this process, "softpipe" in a child.
Side renderSide(const Frame& frame, const std::string& which) {
  if (which == "softpipe") return renderInChild(frame, which);
  if (which == "llvmpipe") setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  return renderInProcess(frame, which == "raster" ? "raster" : "gl");
}

int runRender(const cli::RenderArgs& args) {
  const Frame frame = cli::validateFrame(args);
  if (args.backend != "raster" && args.backend != "gl")
    throw UsageError("--backend: '" + args.backend + "' is neither raster nor gl");
  const std::string out = args.out.empty() ? frame.scene + ".png" : args.out;
  cli::checkOutputFile("--out", out);
  if (!args.dump.empty()) cli::checkOutputFolder("--dump", args.dump);
  if (args.backend == "gl") scenes::checkGalliumEnvironment();

  const Side side = renderInProcess(frame, args.backend, /*finalOnly=*/args.dump.empty());
  compare::writePng(out, side.targets.back().image);
  std::cout << "wrote " << out << std::endl;
  if (!args.dump.empty()) dumpTargets(args.dump, side.targets);
  return 0;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// The thresholds a target exceeds, one message each (colour ones for rgba8, depth for depth).
std::vector<std::string> exceeded(const compare::TargetStats& s, const cli::Thresholds& limits) {
  std::vector<std::string> failures;
  if (s.kind == "rgba8") {
    if (limits.maxRmse && s.rmse > *limits.maxRmse)
      failures.push_back(s.name + ": rmse " + number(s.rmse) + " exceeds --max-rmse " + number(*limits.maxRmse));
    if (limits.minPsnr && s.psnr < *limits.minPsnr)
      failures.push_back(s.name + ": psnr " + number(s.psnr) + " is below --min-psnr " + number(*limits.minPsnr));
    if (limits.maxShareOver1 && s.shareOver1 > *limits.maxShareOver1)
      failures.push_back(s.name + ": share of pixels off by more than 1 step " + number(s.shareOver1) +
                         " exceeds --max-share-over1 " + number(*limits.maxShareOver1));
  }
  if (s.kind == "depth" && limits.maxDepthLsb && s.maxDepthLsb > *limits.maxDepthLsb)
    failures.push_back(s.name + ": depth differs by up to " + std::to_string(s.maxDepthLsb) +
                       " LSBs, over --max-depth-lsb " + std::to_string(*limits.maxDepthLsb));
  return failures;
}

int runCompare(const cli::CompareArgs& args) {
  const Frame frame = cli::validateFrame(args);
  if (args.test != "raster" && args.test != "softpipe")
    throw UsageError("--test: '" + args.test + "' is neither raster nor softpipe");
  if (args.reference != "llvmpipe" && args.reference != "softpipe")
    throw UsageError("--reference: '" + args.reference + "' is neither llvmpipe nor softpipe");
  const cli::Thresholds limits = cli::validateThresholds(args);
  const std::string outFolder = args.out.empty() ? "compare-" + frame.scene : args.out;
  cli::checkOutputFolder("--out", outFolder);
  scenes::checkGalliumEnvironment();

  // Render both sides; they must expose the same targets in the same order.
  const Side test = renderSide(frame, args.test);
  const Side reference = renderSide(frame, args.reference);
  const auto names = [](const Side& side) {
    std::string list;
    for (const Target& t : side.targets) list += (list.empty() ? "" : ",") + t.name;
    return list;
  };
  if (names(test) != names(reference))
    throw std::runtime_error("the sides expose different targets: " + test.backend + " {" + names(test) +
                             "}, " + reference.backend + " {" + names(reference) + "}");

  // Per target: three images, one stats line, and the thresholds it exceeds.
  fs::create_directory(outFolder);
  std::cout << "test: " << test.backend << "  reference: " << reference.backend << "  scene: "
            << frame.scene << " at " << sizeAndTime(frame) << std::endl;
  std::vector<std::string> failures;
  for (size_t i = 0; i < test.targets.size(); ++i) {
    const Target& ours = test.targets[i];
    const Target& theirs = reference.targets[i];
    const compare::TargetStats stats = compare::compareImages(ours.name, ours.image, theirs.image);
    const std::string base = (fs::path(outFolder) / ours.name).string();
    compare::writePng(base + "_ours.png", ours.image);
    compare::writePng(base + "_gl.png", theirs.image);
    compare::writeHeatmapPng(base + "_diff.png", ours.image, theirs.image);
    std::cout << compare::formatStatsLine(stats) << std::endl;
    for (const std::string& failure : exceeded(stats, limits)) failures.push_back(failure);
  }
  std::cout << "images: " << outFolder << "/NAME_{ours,gl,diff}.png" << std::endl;
  for (const std::string& failure : failures) std::cerr << "raster: " << failure << std::endl;
  return failures.empty() ? 0 : 1;
}

// One line, as the single error line demands.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n') c = ' ';
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"A CPU software rasterizer for GL 3.3 scenes, checked against real OpenGL (OSMesa)",
               "raster"};
  app.require_subcommand(1);
  cli::RenderArgs renderArgs;
  cli::CompareArgs compareArgs;
  CLI::App* render = cli::addRenderCommand(app, renderArgs);
  cli::BenchArgs benchArgs;
  cli::addCompareCommand(app, compareArgs);
  CLI::App* bench = cli::addBenchCommand(app, benchArgs);
  CLI::App* list = app.add_subcommand("scenes", "List the scenes, one a line");
  app.footer("Run 'raster COMMAND --help' for a command's options (render, compare, bench, scenes).");

  // Parse: --help prints and exits 0; a malformed command line is bad input.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "raster: " << oneLine(e.what()) << " (see raster --help)" << std::endl;
    return 2;
  }

  // Run: bad input and scene problems exit 2, anything else is an internal failure (1).
  try {
    if (list->parsed()) {
      for (const std::string& name : scenes::sceneNames()) std::cout << name << "\n";
      return 0;
    }
    if (bench->parsed()) return cli::runBench(benchArgs);
    return render->parsed() ? runRender(renderArgs) : runCompare(compareArgs);
  } catch (const UsageError& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 2;
  } catch (const scenes::SceneError& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 2;
  } catch (const compare::OutputPathError& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 1;
  }
}
