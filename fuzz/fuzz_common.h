// What every fuzz target shares: a low memory cap, so an input that claims a huge image is
// refused from its header (as --max-memory would) instead of exhausting libFuzzer's RSS limit.
#pragma once

#include "io/memory_budget.h"

inline void fuzzSetUpOnce() {
  static const bool done = [] {
    scenes::memory::setCap(uint64_t(256) << 20);
    return true;
  }();
  (void)done;
}
