// Whole-or-nothing file writes, and the signal handlers that clean up after them (see
// output_file.h).
#include "io/output_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>

#include "io/utf8.h"

namespace compare {
namespace {

namespace fs = std::filesystem;

// Temporary files being written, for the signal handler: fixed slots it can read without
// allocating. A slot's path is complete before its flag is set.
constexpr int kSlots = 16;
char tempPaths[kSlots][PATH_MAX];
volatile sig_atomic_t tempUsed[kSlots];
std::mutex slotMutex;

constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};

// Temporary folders (a report being made, a child's dump), for the same handler.
char folderPaths[kSlots][PATH_MAX];
volatile sig_atomic_t folderUsed[kSlots];

// Removes `name` under the open folder `dirfd`, and everything below it, with only calls a
// signal handler may make (openat, getdents64, unlinkat, close: nothing allocated). The
// folders it is for are a few levels deep; past kMaxDepth it leaves the rest.
void removeTreeAt(int dirfd, const char* name, int depth) {
  constexpr int kMaxDepth = 8;
  if (unlinkat(dirfd, name, 0) == 0 || errno != EISDIR || depth > kMaxDepth) return;
  const int fd = openat(dirfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  alignas(8) char entries[2048];
  for (long got; (got = getdents64(fd, entries, sizeof entries)) > 0;) {
    for (long at = 0; at < got;) {
      const auto* entry = reinterpret_cast<const struct dirent64*>(entries + at);
      at += entry->d_reclen;
      const char* child = entry->d_name;
      if (!(child[0] == '.' && (child[1] == '\0' || (child[1] == '.' && child[2] == '\0')))) removeTreeAt(fd, child, depth + 1);
    }
  }
  close(fd);
  unlinkat(dirfd, name, AT_REMOVEDIR);
}

// Child processes running (a softpipe side, a report's views), for the same handler: a
// signal sent to this process alone (kill PID, not Ctrl-C to the whole job) would otherwise
// leave them running on after it, writing into folders it removes.
volatile sig_atomic_t childPids[kSlots];

extern "C" void removeTempFilesAndReraise(int signal) {
  // The children first, so that each removes its own temporary files while this one
  // removes the folders; a file-size limit reached here is not theirs, so they are told TERM.
  for (int i = 0; i < kSlots; ++i)
    if (childPids[i] > 0) kill(pid_t(childPids[i]), signal == SIGXFSZ ? SIGTERM : signal);
  for (int i = 0; i < kSlots; ++i)
    if (tempUsed[i]) unlink(tempPaths[i]);
  for (int i = 0; i < kSlots; ++i)
    if (folderUsed[i]) removeTreeAt(AT_FDCWD, folderPaths[i], 0);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// Installs the handler for each cleanup signal that is not ignored (an ignored SIGXFSZ makes
// an over-limit write fail with EFBIG instead, which is reported as an error).
void installHandlersOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signal : kCleanupSignals) {
      struct sigaction current {};
      if (sigaction(signal, nullptr, &current) != 0 || current.sa_handler == SIG_IGN) continue;
      struct sigaction action {};
      action.sa_handler = removeTempFilesAndReraise;
      // One clean-up at a time: a second signal (Ctrl-C's INT, then the parent's TERM)
      // waits until the first has removed everything and ended the process.
      sigemptyset(&action.sa_mask);
      for (int other : kCleanupSignals) sigaddset(&action.sa_mask, other);
      sigaction(signal, &action, nullptr);
    }
  });
}

int claimSlot(const std::string& path) {
  std::lock_guard<std::mutex> lock(slotMutex);
  for (int i = 0; i < kSlots; ++i) {
    if (tempUsed[i]) continue;
    std::strncpy(tempPaths[i], path.c_str(), PATH_MAX - 1);
    tempPaths[i][PATH_MAX - 1] = '\0';
    tempUsed[i] = 1;
    return i;
  }
  return -1;   // more writes at once than slots: the file is still written, just not tracked
}

void releaseSlot(int slot) {
  if (slot < 0) return;
  std::lock_guard<std::mutex> lock(slotMutex);
  tempUsed[slot] = 0;
}

}  // namespace

int trackTemporaryFolder(const std::string& path) {
  installHandlersOnce();
  const std::string absolute = fs::absolute(path).string();   // the handler has no cwd to trust
  std::lock_guard<std::mutex> lock(slotMutex);
  for (int i = 0; i < kSlots; ++i) {
    if (folderUsed[i] || absolute.size() >= PATH_MAX) continue;
    std::memcpy(folderPaths[i], absolute.c_str(), absolute.size() + 1);
    folderUsed[i] = 1;
    return i;
  }
  return -1;   // more folders at once than slots: still removed at the end, just not on a signal
}

void untrackTemporaryFolder(int slot) {
  if (slot < 0) return;
  std::lock_guard<std::mutex> lock(slotMutex);
  folderUsed[slot] = 0;
}

int trackChildProcess(int pid) {
  installHandlersOnce();
  std::lock_guard<std::mutex> lock(slotMutex);
  for (int i = 0; i < kSlots; ++i) {
    if (childPids[i] > 0) continue;
    childPids[i] = pid;
    return i;
  }
  return -1;   // more children at once than slots: they still end with the job, not alone
}

void untrackChildProcess(int slot) {
  if (slot < 0) return;
  std::lock_guard<std::mutex> lock(slotMutex);
  childPids[slot] = 0;
}

namespace {

// The first `bytes` bytes of text at most, cut between UTF-8 characters (a message quotes it).
std::string headOf(std::string_view text, size_t bytes) {
  if (text.size() <= bytes) return std::string(text);
  return std::string(text.substr(0, utf8CharacterStart(text, bytes)));
}

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  const std::string shown = path.size() > 120 ? headOf(path, 100) + "..." : path;
  throw OutputPathError("cannot write " + shown + ": " + why);
}

const char* kindOf(mode_t mode) {
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

void checkPathLengths(const std::string& path) {
  if (path.size() >= PATH_MAX) refuse(path, "the path is longer than " + std::to_string(PATH_MAX - 1) + " bytes");
  for (const fs::path& part : fs::path(path))
    if (part.native().size() > NAME_MAX)
      refuse(path, "the name '" + headOf(part.native(), 40) + "...' is longer than " + std::to_string(NAME_MAX) + " bytes");
}

void checkOutputPath(const std::string& path) {
  if (path.empty()) refuse(path, "no file name");
  checkPathLengths(path);
  struct stat info {};
  if (lstat(path.c_str(), &info) == 0) {
    if (!S_ISREG(info.st_mode)) refuse(path, std::string("it is ") + kindOf(info.st_mode) + ", not a regular file");
  } else if (errno != ENOENT) {
    refuse(path, std::strerror(errno));
  }
  const fs::path folder = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  struct stat folderInfo {};
  if (stat(folder.c_str(), &folderInfo) != 0 || !S_ISDIR(folderInfo.st_mode)) refuse(path, "no such folder " + folder.string());
}

void writeOutputFile(const std::string& path, std::string_view bytes) {
  checkOutputPath(path);
  installHandlersOnce();
  const fs::path folder = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  std::string temp = (folder / ".raster-XXXXXX.tmp").string();
  const int fd = mkostemps(temp.data(), 4, O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  const int slot = claimSlot(temp);
  const auto fail = [&](int error) {
    unlink(temp.c_str());
    releaseSlot(slot);
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(error));
  };
  fchmod(fd, 0644);
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      close(fd);
      fail(error);
    }
    done += size_t(n);
  }
  if (close(fd) != 0) fail(errno);
  // Test hook (tests/apps/output_file_test.cpp): hold the finished temporary file this many
  // milliseconds before the rename, so a test can deliver a signal while it exists.
  if (const char* stall = std::getenv("RASTER_TEST_STALL_BEFORE_RENAME")) usleep(useconds_t(std::atoi(stall)) * 1000u);
  // The path may have become something else meanwhile: rename replaces only what lstat saw
  // as a regular file (or nothing), so check again right before.
  struct stat info {};
  if (lstat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
    unlink(temp.c_str());
    releaseSlot(slot);
    refuse(path, std::string("it is ") + kindOf(info.st_mode) + ", not a regular file");
  }
  if (rename(temp.c_str(), path.c_str()) != 0) fail(errno);
  releaseSlot(slot);
}

}  // namespace compare
