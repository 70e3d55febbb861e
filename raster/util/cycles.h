// A cheap clock for the pipeline's per-stage breakdown: the CPU's time-stamp counter.
// Read a few times per lane group, it costs far less than the work it measures; its
// units are converted to milliseconds by whoever reports them (raster bench).
#pragma once

#include <cstdint>
#include <x86intrin.h>

namespace raster {

inline uint64_t cycleCount() { return __rdtsc(); }

}  // namespace raster
