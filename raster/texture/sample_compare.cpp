// Depth-compare sampling (sampler2DShadow), LINEAR + CLAMP_TO_EDGE, as llvmpipe does it, and
// the compare=nearest method (methods.h): the reference, one lookup at a time
// (sample_compare_avx2.cpp: 8 lanes and PCF grids at once; sample_compare_avx512.cpp: the
// grids of a Float8x2 pair in one register).
// Sources: lp_bld_sample_soa.c (lp_build_sample_wrap_linear, lp_build_sample_image_linear,
// lp_build_sample_comparefunc, lp_build_masklerp2d); lp_bld_conv.c (unorm -> float).
#include <algorithm>
#include <cmath>

#include "raster/methods.h"
#include "raster/texture/format.h"
#include "raster/texture/sample_trace.h"
#include "raster/texture/sampler.h"

namespace raster::sampling {
namespace {

struct LinearTaps {
  int i0, i1;      // texel indices along one axis
  float weight;    // weight of i1
};

// lp_build_sample_wrap_linear, CLAMP_TO_EDGE with normalized coordinates.
LinearTaps wrapLinearClampToEdge(float coord, int size) {
  const float sizeF = float(size);
  float c = coord * sizeF;
  c = (c < sizeF) ? c : sizeF;          // min(c, size); NaN returns the non-NaN size
  c = c - 0.5f;
  c = (c > 0.0f) ? c : 0.0f;            // max(c, 0)
  const float floorC = std::floor(c);
  LinearTaps taps;
  taps.i0 = int(floorC);
  taps.weight = c - floorC;
  taps.i1 = std::min(taps.i0 + 1, size - 1);
  return taps;
}

float texelAsFloat(const Texture& t, int x, int y) {
  const uint32_t code = t.depth[size_t(y) * size_t(t.width) + size_t(x)];
  return t.format == TexelFormat::Depth24 ? format::depth24ToFloat(code) : format::depth16ToFloat(code);
}

// The texel a coordinate lands in, CLAMP_TO_EDGE: floor(clamp(coord * size, 0, size - 1)),
// NaN -> 0. Clamped first, so the truncation is the floor and no value overflows.
int nearestTexel(float coord, int size) {
  float c = coord * float(size);
  c = (c > 0.0f) ? c : 0.0f;
  c = (c < float(size - 1)) ? c : float(size - 1);
  return int(c);
}

float clampRef(float ref) {
  ref = (ref > 0.0f) ? ref : 0.0f;      // clamp to [0, 1], NaN -> 0
  return (ref < 1.0f) ? ref : 1.0f;
}

// (m1 ? w : 0) + (m0 ? 1 - w : 0)
float maskLerp(float w, bool m0, bool m1) { return (m1 ? w : 0.0f) + (m0 ? 1.0f - w : 0.0f); }

}  // namespace

float compareLinearClamp(const Texture& depth, float s, float t, float ref) {
  ref = clampRef(ref);
  const LinearTaps x = wrapLinearClampToEdge(s, depth.width);
  const LinearTaps y = wrapLinearClampToEdge(t, depth.height);
  const bool m00 = ref <= texelAsFloat(depth, x.i0, y.i0);
  const bool m01 = ref <= texelAsFloat(depth, x.i1, y.i0);
  const bool m10 = ref <= texelAsFloat(depth, x.i0, y.i1);
  const bool m11 = ref <= texelAsFloat(depth, x.i1, y.i1);
  const float row0 = maskLerp(x.weight, m00, m01);
  const float row1 = maskLerp(x.weight, m10, m11);
  return std::fma(y.weight, row1 - row0, row0);
}

float compareNearestClamp(const Texture& depth, float s, float t, float ref) {
  return clampRef(ref) <= texelAsFloat(depth, nearestTexel(s, depth.width), nearestTexel(t, depth.height)) ? 1.0f : 0.0f;
}

float compareClamp(const Texture& depth, float s, float t, float ref) {
  return methods::nearestCompare(methods::active().compare) ? compareNearestClamp(depth, s, t, ref)
                                                                : compareLinearClamp(depth, s, t, ref);
}

// The footprint of compareClamp, for pixel history (sample_trace.h).
void explainCompare(const Texture& depth, SampleRecord& record) {
  const float ref = clampRef(record.ref);
  record.explained[0] = compareClamp(depth, record.s, record.t, record.ref);
  if (methods::nearestCompare(methods::active().compare)) {
    record.filter = "compare (LEQUAL) of the texel the coordinate lands in (compare=nearest)";
    record.texelCount = 1;
    FootprintTexel& texel = record.texels[0];
    texel.x = nearestTexel(record.s, depth.width);
    texel.y = nearestTexel(record.t, depth.height);
    texel.weight = 1.0f;
    texel.value[0] = texelAsFloat(depth, texel.x, texel.y);
    texel.compare = ref <= texel.value[0] ? 1 : 0;
    return;
  }
  const LinearTaps x = wrapLinearClampToEdge(record.s, depth.width);
  const LinearTaps y = wrapLinearClampToEdge(record.t, depth.height);
  record.filter = "compare (LEQUAL per texel, results weighted bilinearly)";
  record.weightS = x.weight;
  record.weightT = y.weight;
  record.texelCount = 4;
  const int xs[4] = {x.i0, x.i1, x.i0, x.i1}, ys[4] = {y.i0, y.i0, y.i1, y.i1};
  const float weights[4] = {(1 - x.weight) * (1 - y.weight), x.weight * (1 - y.weight), (1 - x.weight) * y.weight,
                            x.weight * y.weight};
  for (int k = 0; k < 4; ++k) {
    FootprintTexel& texel = record.texels[k];
    texel.x = xs[k];
    texel.y = ys[k];
    texel.weight = weights[k];
    texel.value[0] = texelAsFloat(depth, xs[k], ys[k]);
    texel.compare = ref <= texel.value[0] ? 1 : 0;
  }
}

}  // namespace raster::sampling
