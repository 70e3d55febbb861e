// Running another program (this one, or Python) as a child process and waiting for it.
//
// posix_spawn, not fork + exec: this process has worker threads (the pipeline's pool,
// llvmpipe's), and a forked copy may only call async-signal-safe functions before exec;
// redirecting stdout with freopen there could deadlock on a lock another thread held.
#pragma once

#include <string>
#include <vector>

namespace cli {

struct ChildOptions {
  bool searchPath = false;             // look `argv[0]` up in PATH (python3), else a path
  bool silenceStdout = true;           // the child's stdout to /dev/null; stderr stays ours
  std::vector<std::string> setEnvironment;   // NAME=VALUE entries replacing this process's
  std::string outputPath;              // non-empty: the child's stdout and stderr both into this file
  // Non-null (and no outputPath): the child's stderr passes through this process, which
  // holds back its lines that start with "raster: " (this program's error lines) and leaves
  // them here, without the prefix. The caller's own error line can then carry the child's
  // reason, and a refused child still ends in one "raster: ..." line (docs/errors.md). Its
  // progress lines pass on as they come.
  std::vector<std::string>* errorLines = nullptr;
};

// Runs argv[0] with argv and waits. Returns its exit status; throws std::runtime_error,
// naming `what`, when it cannot start or is killed by a signal.
int runChildProcess(const std::vector<std::string>& argv, const std::string& what, const ChildOptions& options = {});

// Runs this program (argv[0] is replaced by /proc/self/exe) as a child with `options`, its
// error lines held (ChildOptions::errorLines), and returns when it succeeds (any lines held
// then go to stderr as they were). Otherwise throws, naming `what`, its status and its last
// error line (those before it go to stderr first): cli::UsageError for status 2 (bad input
// stays bad input), std::runtime_error for any other.
void runThisProgram(std::vector<std::string> argv, const std::string& what, ChildOptions options = {});

}  // namespace cli
