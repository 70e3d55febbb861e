// A cheap clock for the pipeline's per-stage breakdown: the CPU's time-stamp counter.
// Read a few times per lane group, it costs far less than the work it measures; its
// units are converted to milliseconds by whoever reports them (raster bench), at the rate
// they measure against the wall clock.
#pragma once

#include <cstdint>
#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#else
#include <chrono>
#endif

namespace raster {

#if defined(__x86_64__) || defined(__i386__)
inline uint64_t cycleCount() { return __rdtsc(); }
#else
// Without a time-stamp counter (another architecture), the steady clock's nanoseconds.
inline uint64_t cycleCount() { return uint64_t(std::chrono::steady_clock::now().time_since_epoch().count()); }
#endif

}  // namespace raster
