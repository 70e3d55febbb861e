// Child processes through posix_spawn (child_process.h says why not fork).
#include "apps/common/child_process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "io/output_file.h"

extern char** environ;

namespace cli {

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
  if (error != 0) throw std::runtime_error("cannot start " + what + ": " + std::strerror(error));
  // Tracked while it runs, so that a signal ending this process ends it too. It is untracked
  // while still a zombie (waited for with WNOWAIT) and reaped after: its pid cannot have been
  // given to another process while the signal handler may still send to it.
  const int slot = compare::trackChildProcess(pid);
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

}  // namespace cli
