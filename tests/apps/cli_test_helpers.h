// Running the built `raster` program (RASTER_CLI_PATH) from tests, in a temporary folder.
#pragma once

#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "backends/backend.h"
#include "tests/temp_folder.h"

namespace cli_test {

namespace fs = std::filesystem;

// A working folder for one run of the program (tests/temp_folder.h).
struct TempFolder : testing_support::TempFolder {
  TempFolder() : testing_support::TempFolder("raster-cli-test") {}
};

struct RunResult {
  int status = -1;   // the exit status, or -1 when a signal ended it (then `signal` says which)
  int signal = 0;
  std::string out, err;
};

inline std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

inline std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs a shell script with the working folder `cwd`, where "$RASTER" is the program; its
// output is kept outside that folder, in a temporary folder of its own: test processes run
// side by side (ctest -j), and output files shared between them (the parent of `cwd`, /tmp
// for a TempFolder) let one process read another's stderr.
inline RunResult runShell(const fs::path& cwd, const std::string& script) {
  const TempFolder logFolder;
  const fs::path& logs = logFolder.path;
  const std::string command = "cd " + shellQuote(cwd.string()) + " && RASTER=" + shellQuote(RASTER_CLI_PATH) +
                              " bash -c " + shellQuote(script) + " >" + shellQuote((logs / "out.txt").string()) +
                              " 2>" + shellQuote((logs / "err.txt").string());
  const int raw = std::system(command.c_str());
  RunResult result;
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  if (result.status > 128) {   // bash reports a child killed by signal N as 128 + N
    result.signal = result.status - 128;
    result.status = -1;
  }
  result.out = readText(logs / "out.txt");
  result.err = readText(logs / "err.txt");
  return result;
}

// Runs `raster ARGS` with the working folder `cwd`.
inline RunResult runCli(const fs::path& cwd, const std::string& args) {
  return runShell(cwd, "exec \"$RASTER\" " + args);
}

// Runs a command that must be refused as bad input, in an empty folder, and checks how it is
// refused: exit status 2, one "raster: ..." line on stderr that contains `mentions`, and
// nothing written.
inline void expectRefused(const std::string& args, const std::string& mentions = "") {
  TempFolder temp;
  const fs::path cwd = temp.path / "cwd";
  fs::create_directory(cwd);
  const RunResult result = runCli(cwd, args);
  INFO("raster " << args << "\nstderr: " << result.err);
  CHECK(result.status == 2);
  CHECK(result.err.rfind("raster: ", 0) == 0);
  CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
  CHECK(result.err.find(mentions) != std::string::npos);
  CHECK(fs::is_empty(cwd));
}

}  // namespace cli_test
