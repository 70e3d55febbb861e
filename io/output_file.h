// The one writer of every file the project writes (PNG, OpenEXR, JSON, Markdown, manifests).
//
// A file is written whole or not at all:
//   - the path is checked first: an existing entry there must be a regular file (a symbolic
//     link, FIFO, device or folder is refused, never replaced or opened), its folder must
//     exist, and no name may be longer than the file system allows;
//   - the bytes go to a temporary file in the same folder (".raster-XXXXXX.tmp"), every
//     write and the close are checked, and the temporary file is renamed over the path;
//   - on any failure the temporary file is removed, and so it is when SIGINT, SIGTERM,
//     SIGHUP or SIGXFSZ ends the process meanwhile (a handler removes it and re-raises;
//     the same handler passes the signal on to tracked child processes, below).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace compare {

// A path that cannot be written as a regular file: bad input (the command exits 2).
struct OutputPathError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws OutputPathError when the path, or a name in it, is longer than the file system
// allows (a folder to be made is checked with it too). Touches nothing.
void checkPathLengths(const std::string& path);
// Throws OutputPathError when path names something other than a regular file or nothing,
// has a name too long, or lies in no existing folder. Touches nothing.
void checkOutputPath(const std::string& path);

// Writes bytes to path as above. Throws OutputPathError for a path checkOutputPath refuses,
// and std::runtime_error "cannot write PATH: REASON" when a write, the close or the rename
// fails (a full disk, a file-size limit: the command exits 1).
void writeOutputFile(const std::string& path, std::string_view bytes);

// A temporary folder the run removes itself when it ends (a report being made, a child
// process's dump): tracked here, the folder and all in it are removed too when SIGINT,
// SIGTERM, SIGHUP or SIGXFSZ ends the process first. Returns the slot to untrack it by
// before the folder is renamed into place or removed (-1: not tracked, all slots in use).
int trackTemporaryFolder(const std::string& path);
void untrackTemporaryFolder(int slot);

// A child process this one waits for: when SIGINT, SIGTERM or SIGHUP ends this process, the
// handler sends the child the same signal (SIGXFSZ: SIGTERM) before removing the files, so
// that a signal to this process alone does not leave the child running. Untrack the slot
// once the child has been waited for (its pid may then be reused).
int trackChildProcess(int pid);
void untrackChildProcess(int slot);

}  // namespace compare
