// What the microbenchmarks share: the 16-lane type the paired shading uses, textures of the
// scenes' sizes and formats, the two coordinate patterns, and the per-item counters.
//
// Coordinates model how a fragment shader asks: 16 lanes are two 8-lane groups of a 4x4
// pixel block (lane_layout.h: two 2x2 quads side by side, rows 0-1 then 2-3), and
//   coherent   blocks in the tile walk's order (64x64 tiles, 4x4 blocks row by row inside
//              each) over a 640x480 screen, uv = pixel centre * texels per pixel / size:
//              neighbouring lanes and neighbouring calls share cache lines;
//   scattered  every lane jumps by its own irrational step (mod 1) on each call: no two
//              consecutive lookups share a line, and the whole texture is the working set.
// Both are computed in registers from a few scalars, so their cost is a handful of vector
// adds beside a lookup of a hundred or more instructions, and they never repeat.
#pragma once

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

#include "raster/simd/isa.h"
#include "raster/texture/format.h"
#include "raster/texture/texture.h"

namespace micro {

#if RASTER_AVX2
using Lanes16 = raster::PairedLanes;   // what paired shading hands a lookup (Float8x2)
#else
using Lanes16 = raster::simd::Lanes<16>;
#endif

// A small deterministic generator for texel contents (splitmix64).
struct Random {
  uint64_t state;
  explicit Random(uint64_t seed) : state(seed) {}
  uint64_t next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float unit() { return float(next() >> 40) * (1.0f / 16777216.0f); }   // [0, 1)
};

// The deferred scene's 2K JPEGs: RGBA8, LINEAR, REPEAT (deferred_scene.cpp).
inline const raster::Texture& rgba8Texture2048() {
  static const raster::Texture texture = [] {
    raster::Texture t(2048, 2048, raster::TexelFormat::RGBA8);
    t.sampler = {raster::Filter::Linear, raster::Wrap::Repeat, raster::Wrap::Repeat, false};
    Random random(1);
    for (uint8_t& byte : t.rgba8) byte = uint8_t(random.next());
    return t;
  }();
  return texture;
}

// An hdr colour target / bloom level: RGBA16F, LINEAR, CLAMP_TO_EDGE (hdr_scene.cpp).
inline const raster::Texture& rgba16fTexture1024() {
  static const raster::Texture texture = [] {
    raster::Texture t(1024, 1024, raster::TexelFormat::RGBA16F);
    t.sampler = {raster::Filter::Linear, raster::Wrap::ClampToEdge, raster::Wrap::ClampToEdge, false};
    Random random(2);
    for (uint16_t& half : t.half) half = raster::format::halfFromFloatTowardZero(4.0f * random.unit());
    return t;
  }();
  return texture;
}

// The shadow scenes' map: 1024x1024 Depth24, LINEAR with compare, CLAMP_TO_EDGE. Its depths
// vary smoothly with a little noise, so a reference of 0.5 passes on some texels only.
inline const raster::Texture& depth24Texture1024() {
  static const raster::Texture texture = [] {
    raster::Texture t(1024, 1024, raster::TexelFormat::Depth24);
    t.sampler = {raster::Filter::Linear, raster::Wrap::ClampToEdge, raster::Wrap::ClampToEdge, true};
    Random random(3);
    for (int y = 0; y < t.height; ++y)
      for (int x = 0; x < t.width; ++x) {
        const float z = 0.3f + 0.4f * float(x + y) / float(t.width + t.height) + 0.02f * random.unit();
        t.depth[size_t(y) * size_t(t.width) + size_t(x)] = raster::format::depth24FromFloat(z);
      }
    return t;
  }();
  return texture;
}

// Lane i's pixel offset inside the 4x4 block (two 8-lane groups of lane_layout.h).
inline Lanes16 laneOffset(bool y) {
  alignas(64) float offset[16];
  for (int i = 0; i < 16; ++i) {
    const int group = i / 8, lane = i % 8;
    offset[i] = y ? float(group * 2 + ((lane >> 1) & 1)) : float((lane / 4) * 2 + (lane & 1));
  }
  return Lanes16::load(offset);
}

// 4x4 blocks in the tile walk's order over a screen, as texture coordinates.
class CoherentWalk {
 public:
  // texelsPerPixel > 1 minifies (the deferred floor reads its 2K textures about 2:1).
  CoherentWalk(int textureWidth, int textureHeight, float texelsPerPixel, int screenWidth = 640, int screenHeight = 480)
      : screenW_(screenWidth), screenH_(screenHeight), scaleS_(texelsPerPixel / float(textureWidth)),
        scaleT_(texelsPerPixel / float(textureHeight)), dx_(laneOffset(false) + Lanes16(0.5f)),
        dy_(laneOffset(true) + Lanes16(0.5f)) {}
  // The next block's 16 coordinates.
  void next(Lanes16& s, Lanes16& t) {
    s = (Lanes16(float(tileX_ + bx_)) + dx_) * Lanes16(scaleS_);
    t = (Lanes16(float(tileY_ + by_)) + dy_) * Lanes16(scaleT_);
    advance();
  }

 private:
  void advance() {
    do {
      if ((bx_ += 4) < 64) continue;
      bx_ = 0;
      if ((by_ += 4) < 64) continue;
      by_ = 0;
      if ((tileX_ += 64) < screenW_) continue;
      tileX_ = 0;
      if ((tileY_ += 64) < screenH_) continue;
      tileY_ = 0;
    } while (tileX_ + bx_ >= screenW_ || tileY_ + by_ >= screenH_);   // skip blocks off a partial tile
  }
  int screenW_, screenH_;
  float scaleS_, scaleT_;
  Lanes16 dx_, dy_;
  int tileX_ = 0, tileY_ = 0, bx_ = 0, by_ = 0;
};

// Each lane's coordinates step by their own fractional part of a square root (mod 1).
class ScatteredWalk {
 public:
  ScatteredWalk() {
    alignas(64) float stepS[16], stepT[16], start[16];
    Random random(4);
    for (int i = 0; i < 16; ++i) {
      stepS[i] = float(std::fmod(std::sqrt(double(2 * i + 2)) * 7.0, 1.0));
      stepT[i] = float(std::fmod(std::sqrt(double(2 * i + 3)) * 5.0, 1.0));
      start[i] = random.unit();
    }
    stepS_ = Lanes16::load(stepS);
    stepT_ = Lanes16::load(stepT);
    s_ = Lanes16::load(start);
    t_ = Lanes16(1.0f) - s_;
  }
  void next(Lanes16& s, Lanes16& t) {
    s_ = fract(s_ + stepS_);
    t_ = fract(t_ + stepT_);
    s = s_;
    t = t_;
  }

 private:
  static Lanes16 fract(Lanes16 x) { return x - floor(x); }
  Lanes16 stepS_, stepT_, s_, t_;
};

// items/s counts `items` per iteration; ns_per_item is its inverse in nanoseconds
// (a rate of items * 1e-9 per second is items per nanosecond; inverted, ns per item).
inline void countItems(benchmark::State& state, int64_t itemsPerIteration, const char* perItemName) {
  const int64_t items = int64_t(state.iterations()) * itemsPerIteration;
  state.SetItemsProcessed(items);
  state.counters[perItemName] =
      benchmark::Counter(double(items) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace micro
