// A folder under $TMPDIR for one run's scratch files (a child process's dump, a timing's
// JSON): removed with all in it when the object goes, and by io/output_file.h's signal
// handler when SIGINT, SIGTERM, SIGHUP or SIGXFSZ ends the run first.
#pragma once

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "apps/common/cli_options.h"
#include "io/output_file.h"

namespace cli {

struct TemporaryFolder {
  std::string path;

  // UsageError naming TMPDIR where no folder can be made there (TMPDIR is the user's input).
  TemporaryFolder() {
    namespace fs = std::filesystem;
    const char* tmpdir = std::getenv("TMPDIR");
    const std::string where = tmpdir && *tmpdir ? std::string("TMPDIR=") + tmpdir : "/tmp";
    std::error_code error;
    const fs::path base = fs::temp_directory_path(error);
    if (error) throw UsageError(where + ": cannot make a temporary folder there (" + error.message() + ")");
    std::string pattern = (base / "raster-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw UsageError(where + ": cannot make a temporary folder there (" + std::strerror(errno) + ")");
    path = pattern;
    slot_ = compare::trackTemporaryFolder(path);
  }
  ~TemporaryFolder() {
    compare::untrackTemporaryFolder(slot_);
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace cli
