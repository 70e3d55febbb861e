// Progress lines and bars (progress.h).
#include "apps/common/progress.h"

#include <unistd.h>

#include <cstdio>

namespace cli {

Progress::Progress(std::string label, int total, bool quiet)
    : label_(std::move(label)), total_(total > 0 ? total : 1), quiet_(quiet), terminal_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  if (drawn_ && terminal_) std::fputc('\n', stderr);
}

void Progress::update(int done, const std::string& detail) {
  if (quiet_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double share = double(done) / double(total_);
  // The time left, from the pace so far, once there is a pace to go by.
  char left[48] = "";
  if (done > 0 && done < total_) std::snprintf(left, sizeof left, ", about %.0f s left", elapsed / share - elapsed);
  if (terminal_) {
    constexpr int kWidth = 28;
    const int filled = int(share * kWidth);
    std::string bar(size_t(filled), '#');
    bar.append(size_t(kWidth - filled), '.');
    std::fprintf(stderr, "\r\033[K%s [%s] %d/%d%s  %s", label_.c_str(), bar.c_str(), done, total_, left, detail.c_str());
    std::fflush(stderr);
    drawn_ = true;
    return;
  }
  const int tenth = int(share * 10);
  if (tenth == lastTenth_) return;
  lastTenth_ = tenth;
  std::fprintf(stderr, "%s: %d/%d (%.0f s%s)  %s\n", label_.c_str(), done, total_, elapsed, left, detail.c_str());
}

}  // namespace cli
