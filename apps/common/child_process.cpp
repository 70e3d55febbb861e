// Child processes through posix_spawn (child_process.h says why not fork).
#include "apps/common/child_process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include "apps/common/cli_options.h"
#include "io/output_file.h"

extern char** environ;

namespace cli {
namespace {

constexpr std::string_view kErrorPrefix = "raster: ";

// Writes all of `bytes` to stderr. (When stderr is gone, the rest is dropped: a child whose
// stderr is passed on still runs to its end.)
void writeToStderr(std::string_view bytes) {
  for (size_t written = 0; written < bytes.size();) {
    const ssize_t n = write(STDERR_FILENO, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    written += size_t(n);
  }
}

// Copies a child's stderr from `fd` to this process's, piece by piece as it comes (a piece
// ends at a newline or a carriage return, so progress lines keep moving), except the pieces
// that start with "raster: ": returns those, without the prefix and the line end.
std::vector<std::string> passStderrOn(int fd) {
  std::string pending;
  std::vector<std::string> held;
  const auto flush = [&](size_t end) {   // pending[0, end) is one piece, line end included
    std::string_view piece(pending.data(), end);
    if (piece.substr(0, kErrorPrefix.size()) == kErrorPrefix) {
      piece.remove_prefix(kErrorPrefix.size());
      while (!piece.empty() && (piece.back() == '\n' || piece.back() == '\r')) piece.remove_suffix(1);
      held.emplace_back(piece);
    } else {
      writeToStderr(piece);
    }
    pending.erase(0, end);
  };
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(buffer, size_t(n));
    for (size_t end; (end = pending.find_first_of("\n\r")) != std::string::npos;) flush(end + 1);
    // A piece without its line end yet: passed on now unless it may become an error line.
    const size_t compared = std::min(pending.size(), kErrorPrefix.size());
    if (!pending.empty() && pending.compare(0, compared, kErrorPrefix, 0, compared) != 0) flush(pending.size());
  }
  if (!pending.empty()) flush(pending.size());
  return held;
}

}  // namespace

int runChildProcess(const std::vector<std::string>& argv, const std::string& what, const ChildOptions& options) {
  // The environment as it is, with the entries of setEnvironment replaced.
  std::vector<std::string> environment;
  for (char** entry = environ; *entry; ++entry) {
    bool replaced = false;
    for (const std::string& set : options.setEnvironment)
      replaced = replaced || std::strncmp(*entry, set.c_str(), set.find('=') + 1) == 0;
    if (!replaced) environment.emplace_back(*entry);
  }
  environment.insert(environment.end(), options.setEnvironment.begin(), options.setEnvironment.end());
  std::vector<std::string> args = argv;
  const auto pointers = [](std::vector<std::string>& strings) {
    std::vector<char*> result;
    for (std::string& s : strings) result.push_back(s.data());
    result.push_back(nullptr);
    return result;
  };
  std::vector<char*> argvPointers = pointers(args), envPointers = pointers(environment);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  int errorPipe[2] = {-1, -1};
  if (options.errorLines && options.outputPath.empty()) {
    if (pipe2(errorPipe, O_CLOEXEC) != 0) throw std::runtime_error("cannot start " + what + ": " + std::strerror(errno));
    posix_spawn_file_actions_adddup2(&actions, errorPipe[1], STDERR_FILENO);   // dup2 clears O_CLOEXEC
  }
  if (!options.outputPath.empty()) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, options.outputPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  } else if (options.silenceStdout) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid = 0;
  const int error = options.searchPath
                        ? posix_spawnp(&pid, args[0].c_str(), &actions, nullptr, argvPointers.data(), envPointers.data())
                        : posix_spawn(&pid, args[0].c_str(), &actions, nullptr, argvPointers.data(), envPointers.data());
  posix_spawn_file_actions_destroy(&actions);
  if (errorPipe[1] >= 0) close(errorPipe[1]);   // the child's copy is the writer now
  if (error != 0) {
    if (errorPipe[0] >= 0) close(errorPipe[0]);
    throw std::runtime_error("cannot start " + what + ": " + std::strerror(error));
  }
  // Tracked while it runs, so that a signal ending this process ends it too. It is untracked
  // while still a zombie (waited for with WNOWAIT) and reaped after: its pid cannot have been
  // given to another process while the signal handler may still send to it.
  const int slot = compare::trackChildProcess(pid);
  if (errorPipe[0] >= 0) {
    *options.errorLines = passStderrOn(errorPipe[0]);   // until the child closes it, at its end
    close(errorPipe[0]);
  }
  siginfo_t ended{};
  while (waitid(P_PID, id_t(pid), &ended, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
  }
  compare::untrackChildProcess(slot);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("waiting for " + what + ": " + std::strerror(errno));
  if (WIFSIGNALED(status))
    throw std::runtime_error(what + " was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                             strsignal(WTERMSIG(status)) + ")");
  return WEXITSTATUS(status);
}

void runThisProgram(std::vector<std::string> argv, const std::string& what, ChildOptions options) {
  argv.at(0) = "/proc/self/exe";
  std::vector<std::string> errors;   // its "raster: ..." lines; the last is carried by ours
  options.errorLines = &errors;
  const int status = runChildProcess(argv, what, options);
  for (size_t i = 0; i + (status == 0 ? 0 : 1) < errors.size(); ++i) writeToStderr("raster: " + errors[i] + "\n");
  if (status == 0) return;
  const std::string failed =
      what + " failed with exit status " + std::to_string(status) + (errors.empty() ? "" : ": " + errors.back());
  if (status == 2) throw UsageError(failed);
  throw std::runtime_error(failed);
}

}  // namespace cli
