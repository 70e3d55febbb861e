// The run's memory cap (see memory_budget.h).
#include "io/memory_budget.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "scenes/scene.h"

namespace scenes::memory {
namespace {

std::atomic<uint64_t> capBytes{0};   // 0: not set yet (the default applies)
std::atomic<uint64_t> total{0};

}  // namespace

uint64_t defaultCap() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return uint64_t(1) << 30;
  return uint64_t(pages) * uint64_t(pageSize) / 4 * 3;
}

void setCap(uint64_t bytes) { capBytes = bytes; }

uint64_t cap() {
  const uint64_t set = capBytes.load();
  return set ? set : defaultCap();
}

void reserve(uint64_t bytes, const std::string& what) {
  const uint64_t limit = cap();
  uint64_t before = total.load();
  for (;;) {
    const uint64_t after = before + bytes;
    if (after < before || after > limit)
      throw SceneError(joined({"memory: ", what, " needs ", formatBytes(bytes), ", which would bring this run to ",
                               formatBytes(after < before ? UINT64_MAX : after), ", over the cap of ", formatBytes(limit),
                               " (--max-memory)"}));
    if (total.compare_exchange_weak(before, after)) return;
  }
}

void release(uint64_t bytes) {
  uint64_t before = total.load();
  while (!total.compare_exchange_weak(before, before >= bytes ? before - bytes : 0)) {
  }
}

uint64_t reserved() { return total.load(); }

std::string formatBytes(uint64_t bytes) {
  char text[48];
  const double b = double(bytes);
  if (bytes >= (uint64_t(1) << 30)) std::snprintf(text, sizeof text, "%.2f GiB", b / double(uint64_t(1) << 30));
  else if (bytes >= (uint64_t(1) << 20)) std::snprintf(text, sizeof text, "%.1f MiB", b / double(uint64_t(1) << 20));
  else if (bytes >= 1024) std::snprintf(text, sizeof text, "%.1f KiB", b / 1024.0);
  else std::snprintf(text, sizeof text, "%llu bytes", (unsigned long long)bytes);
  return text;
}

bool parseBytes(const std::string& text, uint64_t& bytes) {
  if (text.empty()) return false;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  double scale = 1;
  const std::string unit = end;
  if (unit == "K" || unit == "k" || unit == "KiB") scale = 1024.0;
  else if (unit == "M" || unit == "m" || unit == "MiB") scale = 1024.0 * 1024.0;
  else if (unit == "G" || unit == "g" || unit == "GiB") scale = 1024.0 * 1024.0 * 1024.0;
  else if (unit == "T" || unit == "t" || unit == "TiB") scale = 1024.0 * 1024.0 * 1024.0 * 1024.0;
  else if (!unit.empty()) return false;
  if (end == text.c_str() || !std::isfinite(value) || value <= 0 || value * scale >= 1.8e19) return false;
  bytes = uint64_t(value * scale);
  return bytes > 0;
}

}  // namespace scenes::memory
