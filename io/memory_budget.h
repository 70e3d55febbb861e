// A cap on the memory one run of the program may take for images: decoded assets, textures
// and render targets in either backend, and read-backs. Each is reserved here, from its size,
// before it is allocated (an image's size is read from its header before it is decoded), and
// a reservation that would pass the cap throws SceneError naming what was being allocated,
// its size, the total and the cap; the program exits 2, having allocated at most the cap.
//
// The cap is --max-memory, by default three quarters of the machine's physical memory (the
// rest is left to the program's own code, Mesa's, and the system). Buffers of a few
// kilobytes per draw (vertex records, bins) are not counted, nor a draw's texel planes
// (raster/shader/texel_planes.h: one float a texel of a texture already counted, 64 MiB at most).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

namespace scenes::memory {

// Three quarters of the physical memory (sysconf), or 1 GiB if that cannot be read.
uint64_t defaultCap();
void setCap(uint64_t bytes);
uint64_t cap();

// Adds bytes to the run's total; throws SceneError("memory: WHAT needs SIZE, which would
// bring this run to TOTAL, over the cap of CAP (--max-memory)") first when it would pass the
// cap. Thread-safe.
void reserve(uint64_t bytes, const std::string& what);
// Gives back bytes reserved earlier (a buffer freed).
void release(uint64_t bytes);
uint64_t reserved();

// A reservation given back when it is destroyed: held by a buffer that is freed with it. A
// copy (of the buffer) reserves the same bytes again.
class Reservation {
 public:
  Reservation() = default;
  Reservation(uint64_t bytes, const std::string& what) : bytes_(bytes) { reserve(bytes, what); }
  Reservation(const Reservation& other) : bytes_(other.bytes_) { reserve(bytes_, "a copy of an image"); }
  Reservation& operator=(const Reservation& other) {
    if (this != &other) *this = Reservation(other);
    return *this;
  }
  Reservation(Reservation&& other) noexcept : bytes_(other.bytes_) { other.bytes_ = 0; }
  Reservation& operator=(Reservation&& other) noexcept {
    if (this != &other) {
      release(bytes_);
      bytes_ = other.bytes_;
      other.bytes_ = 0;
    }
    return *this;
  }
  ~Reservation() { release(bytes_); }

 private:
  uint64_t bytes_ = 0;
};

// The parts of a message, joined (std::string's operator+ chains trip GCC 12's false
// -Wrestrict warning, GCC bug 105651).
inline std::string joined(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view part : parts) out.append(part);
  return out;
}

// "1.50 GiB", "12.0 MiB", "640 bytes".
std::string formatBytes(uint64_t bytes);
// Parses "8G", "512M", "64K", "1.5G" or a byte count (binary units; G = 2^30). Returns
// false for anything else, zero included.
bool parseBytes(const std::string& text, uint64_t& bytes);

}  // namespace scenes::memory
