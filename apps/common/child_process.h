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
};

// Runs argv[0] with argv and waits. Returns its exit status; throws std::runtime_error,
// naming `what`, when it cannot start or is killed by a signal.
int runChildProcess(const std::vector<std::string>& argv, const std::string& what, const ChildOptions& options = {});

}  // namespace cli
