// Texel planes as a port declares them, and how the pipeline makes them once a draw.
//
// A fragment shader that reads many texels of NEAREST textures and makes one number of each
// repeats that work wherever two lookups land in one texel. Deferred's SSAO is the case: each
// of a pixel's sixteen samples reads a texel of the G-buffer's positions and one of its
// normals and makes of them one view-space depth, and each texel is read by about sixteen
// samples of nearby pixels. A port may name such a number as a function of uv whose only
// use of uv is its texture() lookups:
//
//   struct Uniforms { ...; raster::TexelPlane stored_vz; };   // not in kUniformTable
//   template <class F> static F storedViewZ(const Uniforms& u, vec2<F> uv);
//   static void texelPlanes(raster::TexelPlaneMaker<Uniforms>& make) {
//     make(&Uniforms::stored_vz, {&Uniforms::ssao_g_worldpos, &Uniforms::ssao_g_normal},
//          [](const Uniforms& u, auto uv) { return storedViewZ(u, uv); });
//   }
//
// and read it with textureFromPlane(u.stored_vz, uv, [&](auto uv) { return storedViewZ(u, uv); })
// (texture/sampler.h). Before the draw's fragments, the pipeline evaluates the function at
// every texel's centre into the plane, in parallel; a lookup then reads one float.
//
// The plane holds exactly what the function returns wherever a lookup lands:
//   - every source is NEAREST (as the active methods sample it) with one size and one pair
//     of wraps, so the index nearestIndex computes from uv is each source's texel, and the
//     plane's: the function reads the same texels at uv as at that texel's centre;
//   - the centre, (x + 0.5) / W in float, lands in texel x for every wrap: its two
//     roundings move it by under (x + 0.5) * 2^-23, below half a texel where x < 2^22,
//     and sides are at most 16384 (limits.h);
//   - it is evaluated with the draw's own uniforms, under the method set its fragments run
//     under, in lanes whose every operation gives the bits of every other lane type;
//   - the sources are complete: an earlier pass wrote them (beginPass flushed it), and a
//     source that is an attachment of the draw's own framebuffer, which the pass may still
//     write, gets no plane.
// Where a condition fails the plane is left empty and textureFromPlane calls the function
// at every lookup instead, as the GLSL does: the same bits, without the saving.
#pragma once

#include <algorithm>
#include <initializer_list>
#include <type_traits>
#include <vector>

#include "raster/contract.h"
#include "raster/simd/isa.h"
#include "raster/texture/lookup_filter.h"
#include "raster/texture/sampler.h"
#include "raster/util/parallel.h"

namespace raster {

template <class Uniforms>
class TexelPlaneMaker {
 public:
  // The largest plane made: 64 MiB of floats, beside sources of at least as many bytes each.
  static constexpr size_t kMaxTexels = size_t(4096) * 4096;

  // scalarLanes: evaluate in ScalarLanes, as a `--scalar` draw shades.
  TexelPlaneMaker(Uniforms& uniforms, ThreadPool& pool, const Framebuffer& target, bool scalarLanes)
      : uniforms_(uniforms), pool_(pool), target_(target), scalarLanes_(scalarLanes) {}

  // The texels of the planes made so far.
  size_t texelsMade() const { return texelsMade_; }

  // Fills uniforms.*plane with value(uniforms, uv at each texel's centre), where the sources
  // allow (the file header); otherwise leaves it empty.
  template <class Value>
  void operator()(TexelPlane Uniforms::*plane, std::initializer_list<Sampler2D Uniforms::*> sources, Value value) {
    TexelPlane& out = uniforms_.*plane;
    out.values.clear();
    const Texture* shape = sources.size() ? (uniforms_.*(*sources.begin())).texture : nullptr;
    if (!shape || size_t(shape->width) * size_t(shape->height) > kMaxTexels) return;
    for (Sampler2D Uniforms::*source : sources) {
      const Texture* t = (uniforms_.*source).texture;
      if (!t || sampling::lookupFilter(*t) != Filter::Nearest || t->width != shape->width || t->height != shape->height ||
          t->sampler.wrapS != shape->sampler.wrapS || t->sampler.wrapT != shape->sampler.wrapT || isAttachment(t))
        return;
    }
    out.width = shape->width;
    out.height = shape->height;
    out.wrapS = shape->sampler.wrapS;
    out.wrapT = shape->sampler.wrapT;
    out.values.resize(size_t(out.width) * size_t(out.height));
    texelsMade_ += out.values.size();
    if (scalarLanes_) fill<ScalarLanes>(out, value);
#if RASTER_AVX2
    else fill<PairedLanes>(out, value);
#else
    else fill<FastLanes>(out, value);
#endif
  }

 private:
  bool isAttachment(const Texture* t) const {
    return t == target_.depth || std::find(target_.colors.begin(), target_.colors.end(), t) != target_.colors.end();
  }

  // Rows in bands, one task a band; F::kCount texels a call, the last group of a row padded
  // with its last texel.
  template <class F, class Value>
  void fill(TexelPlane& plane, Value& value) {
    const int width = plane.width, height = plane.height;
    const int padded = (width + F::kCount - 1) / F::kCount * F::kCount;
    std::vector<float> columns(static_cast<size_t>(padded));
    for (int x = 0; x < padded; ++x) columns[size_t(x)] = (float(std::min(x, width - 1)) + 0.5f) / float(width);
    const int bands = std::min(height, 8 * pool_.threads());
    pool_.parallelFor(bands, [&](int band) {
      alignas(64) float lanes[F::kCount];
      for (int y = int(int64_t(height) * band / bands); y < int(int64_t(height) * (band + 1) / bands); ++y) {
        const F t((float(y) + 0.5f) / float(height));
        float* row = plane.values.data() + size_t(y) * size_t(width);
        for (int x = 0; x < width; x += F::kCount) {
          const F v = value(std::as_const(uniforms_), glsl::vec2<F>(F::load(columns.data() + x), t));
          v.store(lanes);
          std::copy_n(lanes, std::min(F::kCount, width - x), row + x);
        }
      }
    });
  }

  Uniforms& uniforms_;
  ThreadPool& pool_;
  const Framebuffer& target_;
  bool scalarLanes_;
  size_t texelsMade_ = 0;
};

// Whether a port declares texel planes (static void texelPlanes(TexelPlaneMaker<Uniforms>&)).
template <class Program>
constexpr bool hasTexelPlanes() {
  return requires(TexelPlaneMaker<typename Program::Uniforms>& make) { Program::texelPlanes(make); };
}

}  // namespace raster
