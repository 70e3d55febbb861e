// The size of a core's own cache (L2), for choices that only change speed: whether data a
// pass writes would still be in cache when it is next read.
#pragma once

#include <cstddef>

#include <unistd.h>

namespace raster {

// sysconf's L2 size (glibc reads it from cpuid); 1 MiB where the system does not say.
inline size_t privateCacheBytesPerCore() {
  static const size_t bytes = [] {
    const long reported = sysconf(_SC_LEVEL2_CACHE_SIZE);
    return reported > 0 ? size_t(reported) : size_t(1) << 20;
  }();
  return bytes;
}

}  // namespace raster
