// The options the `raster` commands share (a frame: scene, size, time, threads, methods,
// --set ...), and the checks that turn raw text into validated values before any work
// starts. Each command's own options live in its folder (apps/NAME/).
//
// Every check throws UsageError with one line naming the option and the problem; main()
// prints it as "raster: <line>" and exits with status 2. Output locations are checked here
// too (their folder exists and is writable), so a bad path fails in milliseconds rather
// than after a render, and nothing is written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "raster/methods.h"
#include "scenes/scene.h"

namespace cli {

// Limits every command that takes the option checks against.
constexpr int kMaxSide = 16384;      // --size, each side: GL_MAX_TEXTURE_SIZE of llvmpipe
constexpr int kMaxThreads = 1024;    // --threads: far above any machine this runs on

// Something the user asked for that cannot be done as asked (exit status 2).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Options of the commands that render a frame, as typed on the command line.
struct FrameArgs {
  std::string scene;
  std::string time = "1";
  std::string size = "640x480";
  int threads = 0;             // 0: every core
  bool scalar = false;         // this pipeline with every SIMD fast path off
  int instances = 1000;        // the hdr scene's cube count
  std::string assets;          // empty: the scene library's default
  std::string maxMemory;       // empty: scenes::memory::defaultCap()
  std::string preset = "gl";   // this pipeline's method set (raster/methods.h)
  std::string method;          // STEP=NAME[,STEP=NAME]: overrides of the preset's steps
  std::vector<std::string> sets;   // --set NAME=VALUE, in order (scenes/scene_params.h)
  bool quiet = false;          // no progress or announcements on stderr
  bool floatFinal = false;     // the final pass into RGBA32F (scenes::SceneOptions::floatFinal)
};

// The validated frame: what to render, where, and when.
struct Frame {
  std::string scene;
  float time = 1.0f;
  int width = 0, height = 0;
  int threads = 0;
  bool scalar = false;
  int instances = 1000;
  std::string assets;
  raster::MethodSet methods;   // --preset with --method applied
  scenes::SceneParams params;  // --set, beyond time, size and instances
  std::vector<std::string> sets;   // the --set texts, for a child process to get the same frame
  bool quiet = false;
  bool floatFinal = false;
};

// The scene options of a validated frame.
scenes::SceneOptions sceneOptions(const Frame& frame);

// The options that make a child process (`raster render`, `bench`, `trace`) render this
// frame: --size, --time (9 digits: the same float back), --instances, --assets, and a --set of
// each scene setting. Time, size and instances go as their own options only, whether they
// came from them or from --set: both at once is refused as ambiguous.
std::vector<std::string> childFrameOptions(const Frame& frame);

// The options that give a child process the same method set: --preset unless it is the
// default, and --method when it was given.
std::vector<std::string> childMethodOptions(const FrameArgs& args);

// Adds the options every frame command shares (the scene, --time, --size, --threads,
// --preset, --set, ...) to a command.
void addFrameOptions(CLI::App& command, FrameArgs& args);

// Checks the shared options: a known scene, WxH within 1..16384, a time within 0..1e30 (as --set time=),
// threads within 0..1024, an existing asset folder, a memory cap (which it sets: the run
// allocates nothing before this).
Frame validateFrame(const FrameArgs& args);

// WxH with each side 1..16384; UsageError naming the option otherwise.
std::pair<int, int> parseSize(const std::string& option, const std::string& text);
// A non-negative decimal integer, the whole text, that fits in 64 bits; nullopt otherwise.
std::optional<uint64_t> parseWholeNumber(const std::string& text);
// A finite decimal number, the whole text (scenes::parseDecimal); UsageError naming the option otherwise.
double parseFiniteNumber(const std::string& option, const std::string& text);

// The method set of --preset and --method; UsageError naming the valid names otherwise.
raster::MethodSet validateMethods(const std::string& preset, const std::string& overrides);
// Adds --set NAME=VALUE (repeatable) to a command.
void addSetOption(CLI::App& command, std::vector<std::string>& sets);
// Adds --quiet (no progress on stderr) to a command.
void addQuietOption(CLI::App& command, bool& quiet);
// Adds --preset and --method to a command.
void addMethodOptions(CLI::App& command, std::string& preset, std::string& method);

// This pipeline's own options (--preset, --method, --scalar) given to a GL side are refused,
// not ignored: GL has its own numerics and none of our SIMD paths. `side` names the GL side
// as the command line chose it ("--backend gl", "--test softpipe").
void refuseOwnOptionsOnGl(const Frame& frame, const std::string& side);

// Whether this process can make a file in `folder`, tried with a probe file rather than
// predicted (root's access(W_OK) says yes of /proc and /sys, which take no files).
bool writableFolder(const std::filesystem::path& folder);
// Checks that `path` can be created or replaced: its folder exists and is writable.
void checkOutputFile(const std::string& option, const std::string& path);
// checkOutputFile for a PNG: the name must also end in .png, so that a y.jpg is not given PNG
// bytes under another format's name.
void checkOutputPng(const std::string& option, const std::string& path);
// Checks that `path` is an existing folder (or a link to one): else UsageError, "OPTION: no
// such folder: PATH", or the reason its status cannot be read.
void requireFolder(const std::string& option, const std::string& path);
// Checks that `path` is a writable folder, or can be made in an existing writable folder.
void checkOutputFolder(const std::string& option, const std::string& path);
// checkOutputFolder, then, where the folder exists, each of `files` in it as the writer will
// check it (a regular file or nothing): a folder or link that took one of the names is found
// before the work (a sweep, a race, two renders), not after it with half the files written.
void checkOutputFolder(const std::string& option, const std::string& path, const std::vector<std::string>& files);

}  // namespace cli
