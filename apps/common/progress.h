// Progress of a long run on stderr: a bar redrawn in place when stderr is a terminal, else
// one plain line each time another tenth is done (so logs stay short); nothing at all when
// quiet (--quiet). Never on stdout, which carries results.
#pragma once

#include <chrono>
#include <string>

namespace cli {

class Progress {
 public:
  Progress(std::string label, int total, bool quiet);
  ~Progress();   // ends the bar's line
  // `done` of `total` steps finished; `detail` says what runs next (or what just finished).
  void update(int done, const std::string& detail);

 private:
  std::string label_;
  int total_;
  bool quiet_, terminal_;
  int lastTenth_ = -1;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace cli
